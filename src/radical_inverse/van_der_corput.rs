//! The van der Corput sequence: the one-dimensional radical inverse `x_i = phi_b(i)`
//! (van der Corput 1935), base 2 by default.
//!
//! Its first `b^m` points are exactly the multiples of `b^-m`; `D*_N = O(log N / N)`, the
//! best possible order for a 1D sequence.

use crate::error::Result;
use crate::radical_inverse::RadicalInverse;
use crate::randomize::digits::DigitScramble;
use crate::sampler::{FULL_RANGE, Sampler, check};

/// The van der Corput sequence in base `b`.
///
/// ```
/// use qmckit::{VanDerCorput, Sampler};
/// let v = VanDerCorput::new(2)?;
/// let xs: Vec<f64> = (0..8).map(|i| qmckit::bits::to_f64(v.value(i))).collect();
/// assert_eq!(xs, [0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875]); // phi_2(0..8)
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct VanDerCorput {
    ri: RadicalInverse,
    scramble: DigitScramble,
}

impl VanDerCorput {
    /// The sequence in base `base`.
    ///
    /// # Errors
    /// [`crate::Error::BaseTooSmall`] for bases below 2.
    pub const fn new(base: u32) -> Result<Self> {
        match RadicalInverse::new(base) {
            Ok(ri) => Ok(VanDerCorput {
                ri,
                scramble: DigitScramble::None,
            }),
            Err(e) => Err(e),
        }
    }

    /// The sequence in base `base` with its digits scrambled (see [`DigitScramble`]).
    ///
    /// # Errors
    /// [`crate::Error::BaseTooSmall`] for bases below 2.
    pub const fn with_scramble(base: u32, scramble: DigitScramble) -> Result<Self> {
        match Self::new(base) {
            Ok(v) => Ok(VanDerCorput { scramble, ..v }),
            Err(e) => Err(e),
        }
    }

    /// The `index`-th value, `floor(phi_b(index) 2^32)` (digit-scrambled if so built):
    /// infallible.
    #[inline]
    pub const fn value(&self, index: u32) -> u32 {
        self.ri.sample_scrambled(index, &self.scramble, 0)
    }

    /// The radical inverse behind it (for sequential iteration and inversion).
    pub const fn radical_inverse(&self) -> &RadicalInverse {
        &self.ri
    }
}

impl Sampler for VanDerCorput {
    fn dims(&self) -> usize {
        1
    }

    fn len(&self) -> u64 {
        FULL_RANGE
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        check(index, FULL_RANGE, dim, 1)?;
        Ok(self.value(index))
    }

    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        if self.scramble.is_none() {
            return self.ri.fill(start, out);
        }
        crate::sampler::check_fill(self, start, out.len())?;
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = self.value(start + k as u32);
        }
        Ok(())
    }
}
