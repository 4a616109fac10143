//! Higher-order digital nets: Dick's digit interlacing of Sobol' (Dick 2008, "Walsh spaces
//! containing smooth functions and quasi-Monte Carlo rules of arbitrary high order", SIAM
//! J. Numer. Anal. 46).
//!
//! # Construction
//!
//! For interlacing factor `alpha`, coordinate `j` of point `i` interleaves the binary digits
//! of Sobol' coordinates `j alpha, .., j alpha + alpha - 1`:
//!
//! ```text
//! x_j = sum_(a >= 1) sum_(k < alpha) y_(j alpha + k, a) 2^-(k + (a - 1) alpha + 1)
//! ```
//!
//! (`y_(c, a)` the `a`-th binary digit of Sobol' coordinate `c`). The result is again a
//! digital net (its generator matrices are the rows of the `alpha` Sobol' matrices
//! interleaved), of order `alpha`: for integrands with square-integrable mixed derivatives
//! of order `alpha` in each variable the error is `O(N^-alpha (log N)^(alpha s))`, against
//! Sobol's `O(N^-1 (log N)^s)` (Owen-scrambled: RMSE `O(N^-3/2)`). Being base-2 digital,
//! [`Interlaced`] takes the digital shift and LMS (which keep the order); Owen scrambling
//! also applies but gives back only `O(N^-3/2)`.
//!
//! In 0.32 fixed point each of the `alpha` inputs contributes its top `ceil(32 / alpha)`
//! bits (16 for `alpha = 2`, 11 for `alpha = 3`), enough for `N <= 2^16` (resp. `2^11`)
//! points to keep the full structure. Cost per value: `alpha` Sobol' values and 32 bit moves.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::digital::sobol::interlaced::Interlaced;
//! let h = Interlaced::new(1, 2)?; // Sobol' dimensions 0 and 1 interleaved
//! // Point 1 of 2D Sobol' is (1/2, 1/2): bits 1 and 1, so x = 0.11b = 3/4.
//! assert_eq!(h.sample(1, 0)?, 0xC000_0000);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::Sobol;
use crate::error::{Error, Result};
use crate::sampler::{Base2Digital, Sampler, check};

/// Dick's interlaced net of order `alpha` (2 or 3) in `dims` dimensions, from `alpha dims`
/// dimensions of `S` (Sobol' by default; [`Interlaced::over`] takes any sampler, e.g. an
/// LMS-scrambled Sobol', which is Dick's randomization: scramble each component, then
/// interlace).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Interlaced<S = Sobol> {
    sobol: S,
    dims: usize,
    alpha: u32,
}

/// `alpha` 0.32 fractions interleaved digit by digit (the first most significant).
#[inline]
pub fn interlace(parts: &[u32]) -> u32 {
    let alpha = parts.len() as u32;
    if alpha == 0 {
        return 0;
    }
    let mut out = 0u32;
    for bit in 0..32u32 {
        // Output digit `bit` (0 = the most significant) is digit bit / alpha of part
        // bit % alpha.
        let part = parts.get((bit % alpha) as usize).copied().unwrap_or(0);
        let digit = (part >> (31 - bit / alpha)) & 1;
        out |= digit << (31 - bit);
    }
    out
}

/// Checks `alpha` and `dims`; returns `alpha dims`.
fn inner_dims(dims: usize, alpha: u32) -> Result<usize> {
    if !(2..=3).contains(&alpha) {
        return Err(Error::InvalidParameter {
            what: "the interlacing factor must be 2 or 3",
        });
    }
    if dims == 0 {
        return Err(Error::ZeroDimensions);
    }
    dims.checked_mul(alpha as usize)
        .ok_or(Error::DimensionOutOfRange {
            dim: usize::MAX,
            dims: crate::SOBOL_MAX_DIMS,
        })
}

impl Interlaced {
    /// The order-`alpha` interlaced Sobol' net in `dims` dimensions.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] unless `alpha` is 2 or 3; [`Error::ZeroDimensions`];
    /// [`Error::DimensionOutOfRange`] when `alpha dims` passes the Sobol' table.
    pub fn new(dims: usize, alpha: u32) -> Result<Self> {
        let inner = inner_dims(dims, alpha)?;
        Ok(Interlaced {
            sobol: Sobol::new(inner)?,
            dims,
            alpha,
        })
    }
}

impl<S: Sampler> Interlaced<S> {
    /// Interlaces the `sampler.dims()` coordinates of `sampler` by `alpha` (the dimension
    /// count must be a multiple of `alpha`).
    ///
    /// # Errors
    /// As [`Interlaced::new`]; [`Error::InvalidParameter`] when `alpha` does not divide the
    /// sampler's dimensions.
    pub fn over(sampler: S, alpha: u32) -> Result<Self> {
        let inner = sampler.dims();
        let dims = inner / alpha.max(1) as usize;
        if inner_dims(dims, alpha)? != inner {
            return Err(Error::InvalidParameter {
                what: "the interlacing factor must divide the sampler's dimensions",
            });
        }
        Ok(Interlaced {
            sobol: sampler,
            dims,
            alpha,
        })
    }

    /// The interlacing factor.
    pub const fn alpha(&self) -> u32 {
        self.alpha
    }
}

impl<S: Sampler> Sampler for Interlaced<S> {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        self.sobol.len()
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        check(index, self.sobol.len(), dim, self.dims)?;
        let mut parts = [0u32; 3];
        let a = self.alpha as usize;
        for (k, p) in parts.iter_mut().take(a).enumerate() {
            *p = self.sobol.sample(index, dim * a + k)?;
        }
        Ok(interlace(parts.get(..a).unwrap_or(&[])))
    }
}

/// Interlacing digital nets gives a digital net: the base-2 digital randomizations apply.
impl<S: Base2Digital> Base2Digital for Interlaced<S> {}
