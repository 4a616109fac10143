//! Index shuffling: Burley's "shuffled scrambled Sobol'" (2020) permutes the point indices by
//! a nested (Owen) scramble of their bits, so that two sequences with different shuffle
//! seeds are decorrelated while each keeps its stratification.
//!
//! `shuffle(i) = reverse(hash(reverse(i)))` restricted to `m` bits: output bit `j` of the
//! index depends only on input bits `>= j`, so the first `2^m` shuffled indices are a
//! permutation of one aligned block of `2^m` indices, and every aligned block of a
//! (t, s)-sequence in base 2 is a (t, m, s)-net.

use crate::bits::reverse_bits;
use crate::error::{Error, Result};
use crate::hash::vegdahl;
use crate::sampler::{FULL_RANGE, Sampler};

/// The shuffle of `index` among `2^m` indices (`index < 2^m`, `m <= 32`) for `seed`: a
/// bijection of `[0, 2^m)`. `const`.
///
/// ```
/// use qmckit::randomize::shuffle::shuffle;
/// let mut seen = [false; 64];
/// for i in 0..64 { seen[shuffle(i, 6, 42) as usize] = true; }
/// assert!(seen.iter().all(|&s| s));
/// ```
#[inline]
pub const fn shuffle(index: u32, m: u32, seed: u32) -> u32 {
    let mask = if m >= 32 { u32::MAX } else { (1 << m) - 1 };
    // reverse(index) holds the m index bits at the top; the hash's top m bits are a nested
    // bijection of them, and they come back as the low m bits.
    reverse_bits(vegdahl(reverse_bits(index & mask), seed)) & mask
}

/// A sampler whose indices are shuffled: point `i` is the sampler's point `shuffle(i)`.
/// Dimensions are shuffled in groups of `group` consecutive dimensions, each group with its
/// own seed (all dimensions share one shuffle when `group` is 0 or at least `dims`).
///
/// The sampler's length must be a power of two (or 2^32, a sequence).
///
/// ```
/// use qmckit::randomize::{FastOwen, Scrambled, shuffle::Shuffled};
/// use qmckit::{Sampler, Sobol};
/// // Burley 2020: shuffled, Owen-scrambled Sobol'.
/// let s = Shuffled::new(Scrambled::new(Sobol::new(4)?, FastOwen::new(1)), 2, 0)?;
/// let _p = s.sample(10, 3)?;
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shuffled<S> {
    sampler: S,
    seed: u64,
    group: usize,
    m: u32,
}

impl<S: Sampler> Shuffled<S> {
    /// `sampler` with shuffled indices.
    ///
    /// # Errors
    /// [`Error::NotPowerOfTwo`] if the sampler's length is not a power of two.
    pub fn new(sampler: S, seed: u64, group: usize) -> Result<Self> {
        let n = sampler.len();
        if !n.is_power_of_two() || n > FULL_RANGE {
            return Err(Error::NotPowerOfTwo { n });
        }
        Ok(Shuffled {
            sampler,
            seed,
            group,
            m: n.trailing_zeros(),
        })
    }

    /// The shuffled index of point `index` in dimension `dim`.
    #[inline]
    pub fn index(&self, index: u32, dim: usize) -> u32 {
        let g = dim.checked_div(self.group).unwrap_or(0);
        shuffle(index, self.m, super::dimension_seed(self.seed ^ 0x5F, g))
    }
}

impl<S: Sampler> Sampler for Shuffled<S> {
    fn dims(&self) -> usize {
        self.sampler.dims()
    }

    fn len(&self) -> u64 {
        self.sampler.len()
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        if index as u64 >= self.len() {
            return Err(Error::IndexOutOfRange {
                index: index as u64,
                len: self.len(),
            });
        }
        self.sampler.sample(self.index(index, dim), dim)
    }
}
