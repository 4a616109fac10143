//! qmckit's integration tests, one binary (one link) with a module per concern: goldens
//! from SciPy, mpmath and exact rationals, peer crates, properties, warps, analysis, and the
//! command line (its contract and hostile input).

mod common;

mod blue_noise;
mod catalog;
mod cli;
mod cli_analysis;
mod cli_hostile;
mod cli_reference;
mod conversions;
mod digital;
mod fixed_warps;
mod golden_discrepancy;
mod golden_scipy;
mod golden_sobol;
mod hostile;
mod integrands;
mod integrate;
mod lattice;
mod mask;
mod nets;
mod pcf;
mod peers;
mod pixel;
mod plot;
mod pmj;
mod randomize;
mod report;
mod samplers;
mod scene;
mod spectrum;
mod star_discrepancy;
mod star_lower;
mod thiemard;
mod tvalue;
mod variance;
mod warps;
