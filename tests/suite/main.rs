//! qmckit's integration tests, one binary (one link) with a module per concern: goldens
//! from SciPy, mpmath and exact rationals, peer crates, properties, warps, analysis, and the
//! command line (its contract and hostile input).

mod common;

mod cli;
mod cli_analysis;
mod cli_hostile;
mod conversions;
mod fixed_warps;
mod golden_discrepancy;
mod golden_scipy;
mod golden_sobol;
mod integrands;
mod nets;
mod peers;
mod pixel;
mod pmj;
mod randomize;
mod samplers;
mod spectrum;
mod star_discrepancy;
mod star_lower;
mod thiemard;
mod tvalue;
mod warps;
