//! Kronecker sequences (additive recurrences) `x_i = frac(i alpha)`, by default Roberts'
//! generalized golden ratio `R_d`.
//!
//! # The sequence
//!
//! For `alpha = (alpha_1, .., alpha_s)` with `1, alpha_1, .., alpha_s` linearly independent
//! over the rationals, `x_i = frac(i alpha)` is uniformly distributed (Weyl 1916); for
//! badly approximable `alpha` its discrepancy is `O((log N)^s / N)`-like. `R_d` (Roberts
//! 2018) takes `phi_d`, the real root above 1 of `x^(d+1) = x + 1` (the golden ratio for
//! `d = 1`, the plastic number 1.3247... for `d = 2`), and `alpha_j = phi_d^-j`.
//!
//! # Fixed point
//!
//! Each `alpha_j` is stored as the 0.32 fraction `a_j = floor(alpha_j 2^32)` (R2:
//! `0xC13FA9A9, 0x91E10DA5`), and `x_i = i a_j mod 2^32`, one wrapping multiply, exact
//! for every `i < 2^32` (with 32 bits `alpha` is the rank-1 lattice `z = a`, `n = 2^32`).
//! `phi_d^-1` is found by bisection on `a^d (1 + a) = 1` in 0.64 fixed point
//! (`u128` products, 64 steps of `O(log d)`), and `alpha_j = (phi_d^-1)^j` by squaring:
//! integer-only, the same bits on every target. A random shift is
//! [`crate::randomize::CranleyPatterson`] (or [`crate::randomize::Shift`]).
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::lattice::kronecker::Kronecker;
//! let r2 = Kronecker::r_d(2)?;
//! assert_eq!([r2.sample(1, 0)?, r2.sample(1, 1)?], [0xC13F_A9A9, 0x91E1_0DA5]);
//! assert_eq!(r2.sample(2, 0)?, 0xC13F_A9A9u32.wrapping_mul(2));
//! # Ok::<(), qmckit::Error>(())
//! ```

use crate::error::{Error, Result};
use crate::sampler::{FULL_RANGE, Sampler, check, check_fill};

/// Most dimensions of [`Kronecker::r_d`] (a bound that keeps the bisection meaningful:
/// `alpha_j` for `j` up to it stays well above `2^-32`).
pub const R_D_MAX_DIMS: usize = 1 << 16;

/// Columns [`Kronecker`]'s fill prepares at a time (256 bytes of stack).
const GROUP: usize = 64;

/// `a b` in 0.64 fixed point, truncated.
#[inline]
const fn mul64(a: u64, b: u64) -> u64 {
    ((a as u128 * b as u128) >> 64) as u64
}

/// `a^k` in 0.64 fixed point (`a^0` is `u64::MAX`, one less than 1), by squaring.
const fn pow64(a: u64, mut k: u64) -> u64 {
    let mut result = u64::MAX;
    let mut base = a;
    while k > 0 {
        if k & 1 == 1 {
            result = mul64(result, base);
        }
        base = mul64(base, base);
        k >>= 1;
    }
    result
}

/// `phi_d^-1` in 0.64 fixed point: the largest `a` with `a^d + a^(d+1) <= 1` (computed
/// with truncated products), by bisection. `d >= 1`.
pub const fn inverse_phi(d: u64) -> u64 {
    let (mut lo, mut hi) = (1u64 << 63, u64::MAX); // 1/2 < phi_d^-1 < 1
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        let p = pow64(mid, d);
        let sum = p as u128 + mul64(p, mid) as u128;
        if sum <= u64::MAX as u128 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// `floor(alpha_j 2^32)` of `R_d`'s component `j` (1-based) from `phi_d^-1` in 0.64.
#[inline]
const fn r_d_component(inv_phi: u64, j: u64) -> u32 {
    (pow64(inv_phi, j) >> 32) as u32
}

/// Where the `alpha` of a [`Kronecker`] sequence comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Alpha<A> {
    /// `R_d`: `phi_d^-1` in 0.64 fixed point.
    Rd(u64),
    /// Given 0.32 fractions.
    Given(A),
}

/// The Kronecker sequence `x_i = frac(i alpha)` in 0.32 fixed point, for every `u32`
/// index. Cost: one wrapping multiply a value (given `alpha`); `R_d` computes `alpha_j`
/// by `O(log j)` 128-bit products per `sample`, once per column in `fill`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Kronecker<A = [u32; 0]> {
    alpha: Alpha<A>,
    dims: usize,
}

impl Kronecker {
    /// `R_d` in `dims` dimensions: `alpha_j = phi_d^-j`, `phi_d^(d+1) = phi_d + 1`.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`]; [`Error::DimensionOutOfRange`] past [`R_D_MAX_DIMS`].
    pub const fn r_d(dims: usize) -> Result<Self> {
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if dims > R_D_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: dims - 1,
                dims: R_D_MAX_DIMS,
            });
        }
        Ok(Kronecker {
            alpha: Alpha::Rd(inverse_phi(dims as u64)),
            dims,
        })
    }
}

impl<A: AsRef<[u32]>> Kronecker<A> {
    /// The sequence with `alpha_j = alpha[j] / 2^32` (e.g. Richtmyer's `frac(sqrt(p_j))`
    /// rounded to 32 bits).
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`] for an empty `alpha`.
    pub fn with_alpha(alpha: A) -> Result<Self> {
        let dims = alpha.as_ref().len();
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        Ok(Kronecker {
            alpha: Alpha::Given(alpha),
            dims,
        })
    }

    /// `floor(alpha_dim 2^32)`, or `None` past the dimensions.
    pub fn alpha(&self, dim: usize) -> Option<u32> {
        if dim >= self.dims {
            return None;
        }
        match &self.alpha {
            Alpha::Rd(inv) => Some(r_d_component(*inv, dim as u64 + 1)),
            Alpha::Given(a) => a.as_ref().get(dim).copied(),
        }
    }
}

impl<A: AsRef<[u32]>> Sampler for Kronecker<A> {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        FULL_RANGE
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        check(index, FULL_RANGE, dim, self.dims)?;
        Ok(index.wrapping_mul(self.alpha(dim).unwrap_or(0)))
    }

    /// `alpha` prepared for 64 columns at a time, then one multiply a value. Same
    /// values as [`sample`](Sampler::sample).
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        check_fill(self, start, out.len())?;
        let dims = self.dims;
        let mut alpha = [0u32; GROUP];
        for first in (0..dims).step_by(GROUP) {
            let width = GROUP.min(dims - first);
            for (k, a) in alpha.iter_mut().take(width).enumerate() {
                *a = self.alpha(first + k).unwrap_or(0);
            }
            let alpha = alpha.get(..width).unwrap_or(&[]);
            for (k, row) in out.chunks_exact_mut(dims).enumerate() {
                let index = start.wrapping_add(k as u32);
                if let Some(part) = row.get_mut(first..first + width) {
                    for (x, &a) in part.iter_mut().zip(alpha) {
                        *x = index.wrapping_mul(a);
                    }
                }
            }
        }
        Ok(())
    }
}
