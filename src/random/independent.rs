//! Independent uniform random points (plain Monte Carlo), the baseline every other sampler
//! is measured against: error `O(N^-1/2)`, `D*` about `0.15` for 64 points in 2D.
//!
//! [`Independent`] is random access: coordinate `(i, k)` is a hash of `(seed, i, k)`.
//! Under the `rand_core` feature, [`Independent::from_rng`] draws the seed from any
//! `RngCore`, and [`fill_from_rng`] fills a buffer straight from a generator.
// Without `rand_core` the generator functions are absent and their links above are text.
#![cfg_attr(not(feature = "rand_core"), allow(rustdoc::broken_intra_doc_links))]

use crate::error::{Error, Result};
use crate::hash::uniform;
use crate::sampler::{FULL_RANGE, Sampler, check};

/// Independent uniform points in `dims` dimensions, indexed by `u32`.
///
/// ```
/// use qmckit::{Independent, Sampler};
/// let a = Independent::new(2, 1)?;
/// assert_eq!(a.sample(5, 1)?, a.sample(5, 1)?); // a pure function
/// assert_ne!(a.sample(5, 1)?, Independent::new(2, 2)?.sample(5, 1)?);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Independent {
    dims: usize,
    seed: u64,
}

impl Independent {
    /// `dims >= 1` dimensions from `seed`.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`].
    pub const fn new(dims: usize, seed: u64) -> Result<Self> {
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        Ok(Independent { dims, seed })
    }

    /// `dims` dimensions with the seed drawn from `rng`.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`].
    #[cfg(feature = "rand_core")]
    pub fn from_rng<R: rand_core::Rng + ?Sized>(dims: usize, rng: &mut R) -> Result<Self> {
        Self::new(dims, rng.next_u64())
    }

    /// Coordinate `dim` of point `index`. `const`.
    ///
    /// # Errors
    /// [`Error::DimensionOutOfRange`].
    #[inline]
    pub const fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        if let Err(e) = check(index, FULL_RANGE, dim, self.dims) {
            return Err(e);
        }
        Ok(uniform(self.seed, index, dim as u64))
    }
}

impl Sampler for Independent {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        FULL_RANGE
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        Independent::sample(self, index, dim)
    }
}

/// Fills `out` with independent uniform 0.32 fractions straight from `rng`
/// (`next_u32` each).
#[cfg(feature = "rand_core")]
pub fn fill_from_rng<R: rand_core::Rng + ?Sized>(rng: &mut R, out: &mut [u32]) {
    for slot in out {
        *slot = rng.next_u32();
    }
}
