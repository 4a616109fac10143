//! Latin hypercube sampling (McKay, Beckman & Conover 1979): `N` points such that each of
//! the `N` equal slabs of every axis holds exactly one point.
//!
//! Coordinate `k` of point `i` is `(pi_k(i) + u) / N` with `pi_k` a random permutation of
//! `0..N` (a keyed bijection, [`crate::hash::permute`], so no table is stored) and `u`
//! uniform in `[0, 1)`. Random access, `O(1)` memory, any number of dimensions.

use crate::bits::in_cell;
use crate::error::Result;
use crate::hash::{hash3, permute, uniform};
use crate::sampler::{Sampler, check, check_set};

/// `n` Latin-hypercube points in `dims` dimensions from `seed`.
///
/// ```
/// use qmckit::{LatinHypercube, Sampler};
/// let lhs = LatinHypercube::new(10, 3, 42)?;
/// let mut slabs = [false; 10];
/// for i in 0..10 {
///     slabs[(lhs.sample(i, 2)? as u64 * 10 >> 32) as usize] = true;
/// }
/// assert!(slabs.iter().all(|&s| s)); // one point per slab
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LatinHypercube {
    n: u64,
    dims: usize,
    seed: u64,
}

impl LatinHypercube {
    /// `n` points (`1..=2^32`) in `dims >= 1` dimensions.
    ///
    /// # Errors
    /// [`crate::Error::ZeroPoints`], [`crate::Error::TooManyPoints`], [`crate::Error::ZeroDimensions`].
    pub const fn new(n: u64, dims: usize, seed: u64) -> Result<Self> {
        if let Err(e) = check_set(n, dims) {
            return Err(e);
        }
        Ok(LatinHypercube { n, dims, seed })
    }

    /// Coordinate `dim` of point `index`. `const`.
    ///
    /// # Errors
    /// [`crate::Error::IndexOutOfRange`], [`crate::Error::DimensionOutOfRange`].
    pub const fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        if let Err(e) = check(index, self.n, dim, self.dims) {
            return Err(e);
        }
        let key = hash3(self.seed, dim as u64, 0x4C48_5300); // "LHS"
        let slab = permute(index, self.n, key);
        Ok(in_cell(
            slab as u64,
            self.n,
            uniform(self.seed, index, dim as u64),
        ))
    }
}

impl Sampler for LatinHypercube {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        self.n
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        LatinHypercube::sample(self, index, dim)
    }
}
