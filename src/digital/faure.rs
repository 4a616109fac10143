//! Faure's generator matrices: powers of the Pascal matrix modulo a prime.

#[cfg(feature = "std")]
use super::DigitalNetB;
use super::output_digits;
use crate::error::{Error, Result};

/// Fills `out` with Faure's matrices in base `base` for `dims` dimensions, `K x K` each
/// (`K` the first value of [`output_digits`]`(base)`), in [`DigitalNetB`]'s layout:
/// `C_j[r][c] = C(c, r) j^(c - r) mod b` for `c >= r`, else 0 (`C_0` the identity).
/// `O(dims K^2)`; no allocation.
///
/// # Errors
/// [`Error::InvalidParameter`] when `dims > base` (Faure needs `b >= s`), or a base that
/// [`DigitalNetB::new`] refuses; [`Error::BufferLength`] unless `out` holds
/// `dims x K x K` entries.
pub fn faure_matrices(base: u32, dims: usize, out: &mut [u16]) -> Result<()> {
    if base < 2 {
        return Err(Error::BaseTooSmall { base });
    }
    if base > super::MAX_BASE || !super::is_prime(base) {
        return Err(Error::InvalidParameter {
            what: "Faure's base must be a prime of at most 65521",
        });
    }
    if dims as u64 > base as u64 {
        return Err(Error::InvalidParameter {
            what: "Faure's sequence needs a base at least the dimension (b >= s)",
        });
    }
    let (k, _) = output_digits(base)?;
    let expected = dims * k * k;
    if out.len() != expected {
        return Err(Error::BufferLength {
            expected,
            got: out.len(),
        });
    }
    let b = base as u64;
    // Pascal's triangle modulo b: binom[c][r] = C(c, r) mod b.
    let mut binom = [[0u64; super::MAX_DIGITS]; super::MAX_DIGITS];
    for c in 0..k {
        for r in 0..=c {
            let v = if r == 0 || r == c {
                1
            } else {
                let up = binom.get(c - 1).copied().unwrap_or_default();
                (up.get(r - 1).copied().unwrap_or(0) + up.get(r).copied().unwrap_or(0)) % b
            };
            if let Some(slot) = binom.get_mut(c).and_then(|row| row.get_mut(r)) {
                *slot = v % b;
            }
        }
    }
    for (j, matrix) in out.chunks_exact_mut(k * k).enumerate() {
        let j = j as u64 % b;
        for (r, row) in matrix.chunks_exact_mut(k).enumerate() {
            for (c, entry) in row.iter_mut().enumerate() {
                *entry = if c < r {
                    0
                } else {
                    let mut power = 1u64;
                    for _ in 0..c - r {
                        power = power * j % b;
                    }
                    let choose = binom
                        .get(c)
                        .and_then(|row| row.get(r))
                        .copied()
                        .unwrap_or(0);
                    // Both factors are below b <= 65521, so the product fits and the
                    // residue is a u16.
                    (choose * power % b) as u16
                };
            }
        }
    }
    Ok(())
}

#[cfg(feature = "std")]
impl DigitalNetB<Vec<u16>> {
    /// Faure's `(0, s)`-sequence in prime base `base >= dims`, `2^32` points (every
    /// aligned block of `b^m` points a `(0, m, s)`-net).
    ///
    /// # Errors
    /// As [`faure_matrices`]; [`Error::ZeroDimensions`].
    pub fn faure(base: u32, dims: usize) -> Result<Self> {
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if base < 2 {
            return Err(Error::BaseTooSmall { base });
        }
        if dims as u64 > base as u64 {
            return Err(Error::InvalidParameter {
                what: "Faure's sequence needs a base at least the dimension (b >= s)",
            });
        }
        let (k, _) = output_digits(base)?;
        let mut m = crate::size::vec_zeroed(crate::size::coordinates(dims as u64, k * k)?)?;
        faure_matrices(base, dims, &mut m)?;
        DigitalNetB::new(base, dims, k, m)
    }
}
