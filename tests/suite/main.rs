//! qmckit's integration tests, one binary (one link) with a module per concern: goldens
//! from SciPy, mpmath and exact rationals, peer crates, properties, warps and analysis. The
//! command line (its contract and hostile input) is tested by its own package, cli/.

mod common;

#[cfg(feature = "analysis")]
mod aa;
#[cfg(feature = "analysis")]
mod art;
mod blue_noise;
#[cfg(feature = "analysis")]
mod bnot;
mod cascaded;
mod catalog;
mod cmj;
mod conversions;
#[cfg(feature = "analysis")]
mod digital;
mod fixed_warps;
#[cfg(feature = "analysis")]
mod forced_random;
mod golden_discrepancy;
mod golden_scipy;
mod golden_sobol;
mod integrands;
#[cfg(feature = "analysis")]
mod integrate;
mod kde_density;
mod lattice;
#[cfg(feature = "analysis")]
mod ldbn;
mod mask;
mod nets;
mod pcf;
mod peers;
mod pixel;
mod pmj;
#[cfg(feature = "analysis")]
mod projective;
mod randomize;
#[cfg(feature = "analysis")]
mod relaxation;
mod samplers;
mod spectral;
mod spectrum;
mod star_discrepancy;
mod star_lower;
mod thiemard;
mod tiles;
#[cfg(feature = "analysis")]
mod transport;
mod tvalue;
mod variance;
#[cfg(feature = "analysis")]
mod voronoi3;
mod warps;
