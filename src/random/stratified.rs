//! Stratified (jittered) sampling: `[0, 1)^d` cut into `s_1 x ... x s_d` equal cells, one
//! point a cell, placed uniformly at random inside it (jittered) or at its center.
//!
//! Jittered sampling of a smooth integrand has variance `O(N^(-1 - 2/d))` against Monte
//! Carlo's `O(1/N)`; 8x8 jittered points have `D*` about 0.08 against about 0.15
//! for independent ones. Random access: point `i` is cell `i` in mixed radix (dimension 0
//! fastest), and its jitter is a hash of `(seed, i, dim)`.

use crate::bits::{div_u32, in_cell, rem_u32};
use crate::error::{Error, Result};
use crate::hash::uniform;
use crate::sampler::{FULL_RANGE, Sampler, check};

/// Most dimensions a [`Stratified`] sampler takes (a grid with 2 or more strata a
/// dimension cannot have more than 32 and still fit 2^32 points).
pub const STRATIFIED_MAX_DIMS: usize = 32;

/// Where a point sits inside its cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Jitter {
    /// Uniformly at random, from this seed (jittered sampling).
    Random(u64),
    /// At the cell's center (a regular grid).
    Center,
}

/// A stratified grid of `s_1 x ... x s_d` cells with one point each.
///
/// ```
/// use qmckit::{Stratified, Jitter, Sampler};
/// let s = Stratified::new(&[4, 2], Jitter::Random(7))?;
/// assert_eq!(s.len(), 8);
/// // Point 5 lies in cell (1, 1): x in [1/4, 2/4), y in [1/2, 1).
/// let (x, y) = (s.sample(5, 0)?, s.sample(5, 1)?);
/// assert!((1 << 30..2 << 30).contains(&x) && y >= 1 << 31);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Stratified {
    strata: [u32; STRATIFIED_MAX_DIMS],
    dims: usize,
    n: u64,
    jitter: Jitter,
}

impl Stratified {
    /// A grid with `strata[k]` cells along dimension `k`.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`], [`Error::DimensionOutOfRange`] (more than
    /// [`STRATIFIED_MAX_DIMS`]), [`Error::ZeroStrata`], [`Error::TooManyPoints`] (product
    /// above 2^32).
    pub const fn new(strata: &[u32], jitter: Jitter) -> Result<Self> {
        if strata.is_empty() {
            return Err(Error::ZeroDimensions);
        }
        if strata.len() > STRATIFIED_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: strata.len() - 1,
                dims: STRATIFIED_MAX_DIMS,
            });
        }
        let mut table = [1u32; STRATIFIED_MAX_DIMS];
        let mut n = 1u64;
        let mut k = 0;
        while k < strata.len() {
            if strata[k] == 0 {
                return Err(Error::ZeroStrata { dim: k });
            }
            n = n.saturating_mul(strata[k] as u64);
            if n > FULL_RANGE {
                return Err(Error::TooManyPoints {
                    requested: n,
                    max: FULL_RANGE,
                });
            }
            table[k] = strata[k];
            k += 1;
        }
        Ok(Stratified {
            strata: table,
            dims: strata.len(),
            n,
            jitter,
        })
    }

    /// The same number of strata `per_dim` in each of `dims` dimensions (`per_dim^dims`
    /// points).
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub const fn uniform(per_dim: u32, dims: usize, jitter: Jitter) -> Result<Self> {
        if dims > STRATIFIED_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: dims - 1,
                dims: STRATIFIED_MAX_DIMS,
            });
        }
        let table = [per_dim; STRATIFIED_MAX_DIMS];
        let (strata, _) = table.split_at(dims);
        Self::new(strata, jitter)
    }

    /// Cells along each dimension.
    pub fn strata(&self) -> &[u32] {
        &self.strata[..self.dims]
    }

    /// Coordinate `dim` of point `index`. `const`; the result lies in its cell exactly.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::DimensionOutOfRange`].
    pub const fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        if let Err(e) = check(index, self.n, dim, self.dims) {
            return Err(e);
        }
        if dim >= STRATIFIED_MAX_DIMS {
            // Unreachable (dims <= STRATIFIED_MAX_DIMS); keeps indexing free of panic paths.
            return Err(Error::DimensionOutOfRange {
                dim,
                dims: self.dims,
            });
        }
        let mut cell = index;
        let mut k = 0;
        while k < dim {
            cell = div_u32(cell, self.strata[k]);
            k += 1;
        }
        let s = self.strata[dim];
        let u = match self.jitter {
            Jitter::Random(seed) => uniform(seed, index, dim as u64),
            Jitter::Center => 1 << 31,
        };
        Ok(in_cell(rem_u32(cell, s) as u64, s as u64, u))
    }
}

impl Sampler for Stratified {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        self.n
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        Stratified::sample(self, index, dim)
    }
}
