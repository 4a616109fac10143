//! The Hammersley point set: `x_i = (i / N, phi_2(i), phi_3(i), ...)` for `i < N`
//! (Hammersley 1960).
//!
//! A finite set: knowing `N` in advance buys one dimension, so `D*_N = O((log N)^(d-1) / N)`,
//! slightly below Halton's. In 2D with `N = 2^m` it is a (0, m, 2)-net in base 2 (its
//! generator matrices are the reversed identity and the identity), with the exact star
//! discrepancy `N D* = m/3 + 13/9 - (-1)^m 4/(9 2^m)` (De Clerck 1986).

use crate::error::{Error, Result};
use crate::radical_inverse::halton::{HALTON_BASES, HALTON_MAX_DIMS};
use crate::randomize::digits::DigitScramble;
use crate::sampler::{Sampler, check, check_set};

/// `N` Hammersley points in `dims` dimensions; dimension 0 is `i / N`, dimension `k >= 1`
/// the radical inverse in the `k`-th prime (Halton's dimension `k - 1`).
///
/// ```
/// use qmckit::Hammersley;
/// let h = Hammersley::new(8, 2)?;
/// assert_eq!(h.sample(3, 0)?, 3 << 29); // 3/8
/// assert_eq!(h.sample(3, 1)?, 0xC000_0000); // phi_2(3) = 3/4
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Hammersley {
    n: u64,
    /// `m` when `n = 2^m` (first coordinate is a shift).
    log2: Option<u32>,
    dims: usize,
    scramble: DigitScramble,
}

impl Hammersley {
    /// `n` points (`1 <= n <= 2^32`) in `dims` dimensions (`1 <= dims <= 1 + HALTON_MAX_DIMS`).
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::ZeroDimensions`],
    /// [`Error::DimensionOutOfRange`].
    pub const fn new(n: u64, dims: usize) -> Result<Self> {
        if let Err(e) = check_set(n, dims) {
            return Err(e);
        }
        if dims > HALTON_MAX_DIMS + 1 {
            return Err(Error::DimensionOutOfRange {
                dim: dims - 1,
                dims: HALTON_MAX_DIMS + 1,
            });
        }
        let log2 = if n.is_power_of_two() {
            Some(n.trailing_zeros())
        } else {
            None
        };
        Ok(Hammersley {
            n,
            log2,
            dims,
            scramble: DigitScramble::None,
        })
    }

    /// `n` points whose radical-inverse dimensions (1 and up) have their digits scrambled;
    /// dimension 0 stays `i / N`.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub const fn with_scramble(n: u64, dims: usize, scramble: DigitScramble) -> Result<Self> {
        match Self::new(n, dims) {
            Ok(h) => Ok(Hammersley { scramble, ..h }),
            Err(e) => Err(e),
        }
    }

    /// The `2^m`-point set (`m <= 32`), a (0, m, 2)-net in its first two dimensions.
    ///
    /// # Errors
    /// [`Error::MTooLarge`] for `m > 32`, and those of [`new`](Self::new).
    pub const fn with_m(m: u32, dims: usize) -> Result<Self> {
        if m > 32 {
            return Err(Error::MTooLarge { m, max: 32 });
        }
        Self::new(1 << m, dims)
    }

    /// Coordinate `dim` of point `index`. `const`; exact.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::DimensionOutOfRange`].
    #[inline]
    pub const fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        if let Err(e) = check(index, self.n, dim, self.dims) {
            return Err(e);
        }
        Ok(if dim == 0 {
            match self.log2 {
                Some(0) => 0,
                Some(m) => index << (32 - m),
                None => crate::bits::fraction(index as u64, self.n),
            }
        } else {
            let k = dim - 1;
            if k >= HALTON_MAX_DIMS {
                // Unreachable (validated); keeps the indexing free of a panic path.
                return Err(Error::DimensionOutOfRange {
                    dim,
                    dims: self.dims,
                });
            }
            HALTON_BASES[k].sample_scrambled(index, &self.scramble, dim)
        })
    }
}

impl Sampler for Hammersley {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        self.n
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        Hammersley::sample(self, index, dim)
    }

    /// Sequential fast path: the radical-inverse columns use their iterators.
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        let rows = crate::sampler::check_fill(self, start, out.len())?;
        if rows == 0 || self.dims == 0 {
            return Ok(());
        }
        if !self.scramble.is_none() {
            for (k, row) in out.chunks_exact_mut(self.dims).enumerate() {
                self.point(start + k as u32, row)?;
            }
            return Ok(());
        }
        for (k, row) in out.chunks_exact_mut(self.dims).enumerate() {
            if let Some(x) = row.first_mut() {
                *x = Hammersley::sample(self, start + k as u32, 0)?;
            }
        }
        for (dim, ri) in HALTON_BASES.iter().take(self.dims - 1).enumerate() {
            if let Some(column) = out.get_mut(dim + 1..) {
                ri.fill_strided(start, column, self.dims)?;
            }
        }
        Ok(())
    }
}
