//! The common imports: `use qmckit::prelude::*;` brings the [`Sampler`] trait and the traits
//! its methods and the randomizations need, the main samplers and randomizations, and
//! [`Error`]/[`Result`].
//!
//! ```
//! use qmckit::prelude::*;
//! let s = Scrambled::new(Sobol::new(2)?, FastOwen::new(7));
//! let mut p = [0.0f64; 2 * 16];
//! s.fill_as(0, &mut p)?;
//! assert!(p.iter().all(|x| (0.0..1.0).contains(x)));
//! let h = Halton::new(3)?;
//! assert_eq!(h.sample(1, 0)?, 0x8000_0000); // 1/2
//! # Ok::<(), Error>(())
//! ```

pub use crate::bits::FromFraction;
pub use crate::error::{Error, Result};
pub use crate::sampler::{Base2Digital, Sampler};

pub use crate::digital::lp::LarcherPillichshammer;
pub use crate::digital::sobol::{OwenSobol, Sobol};
pub use crate::lattice::Rank1Lattice;
pub use crate::lattice::kronecker::Kronecker;
pub use crate::radical_inverse::RadicalInverse;
pub use crate::radical_inverse::halton::Halton;
pub use crate::radical_inverse::hammersley::Hammersley;
pub use crate::radical_inverse::van_der_corput::VanDerCorput;
pub use crate::random::independent::Independent;
pub use crate::random::latin_hypercube::LatinHypercube;
pub use crate::random::stratified::{Jitter, Stratified};

pub use crate::randomize::{
    CranleyPatterson, DigitalShift, ExactOwen, FastOwen, Randomizer, Randomizes, Scrambled,
    Scrambler,
};
