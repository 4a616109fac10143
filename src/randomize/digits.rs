//! Digit scrambling in base `b` for the radical inverse (Halton, Hammersley, van der Corput
//! in any base): `phi'_b(i) = sum_j sigma_j(d_j) b^-j`.
//!
//! * [`DigitScramble::Permutations`]: an independent random permutation `sigma_j` of the
//!   digits `0..b` for every digit position `j`, applied to all `K` positions including the
//!   index's leading zeros (as SciPy's scrambled Halton and pbrt-v4's
//!   `PermutationDigitsSampler` do), so every point becomes uniform.
//! * [`DigitScramble::Faure`]: Faure's deterministic permutation of `0..b` (Faure 1992),
//!   the same at every position; it maps 0 to 0, so no trailing digits appear.
//! * [`DigitScramble::Owen`]: nested uniform scrambling in base `b`: the permutation of
//!   digit `j` depends on the `j - 1` digits below it in the index (Owen 1995).
//!
//! Random permutations are evaluated one digit at a time by a keyed bijection
//! ([`crate::hash::permute`]); nothing is stored. The output is exact for the `K`-digit
//! expansion behind [`crate::RadicalInverse`] (`b^-K <= 2^-32`): digits past `K` would change
//! the result by less than one unit of the last place.

use crate::hash::{hash3, permute};

/// A digit scrambling of the radical inverse.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum DigitScramble {
    /// No scrambling.
    #[default]
    None,
    /// Random permutations per digit position, from a seed.
    Permutations(u64),
    /// Faure's permutations.
    Faure,
    /// Owen (nested uniform) scrambling in base `b`, from a seed.
    Owen(u64),
}

impl DigitScramble {
    /// The image of `digit` at position `position` (1 = the most significant digit of the
    /// radical inverse) in dimension `dim`, where `prefix` is the index modulo
    /// `b^(position - 1)` (its digits below `position`; used by Owen scrambling).
    #[inline]
    pub const fn digit(
        &self,
        base: u32,
        dim: usize,
        position: u32,
        prefix: u64,
        digit: u32,
    ) -> u32 {
        match *self {
            DigitScramble::None => digit,
            DigitScramble::Faure => faure(base, digit),
            DigitScramble::Permutations(seed) => {
                let key = hash3(seed, dim as u64, position as u64);
                permute(digit, base as u64, key)
            }
            DigitScramble::Owen(seed) => {
                let node = hash3(seed ^ position as u64, dim as u64, prefix);
                permute(digit, base as u64, node)
            }
        }
    }

    /// True for [`DigitScramble::None`].
    pub const fn is_none(&self) -> bool {
        matches!(self, DigitScramble::None)
    }
}

/// Faure's permutation of `0..base`, evaluated at `digit` (`digit < base`, `base >= 2`).
///
/// Defined recursively: `sigma_2 = (0, 1)`; for `b = 2c`, `sigma_b(j) = 2 sigma_c(j)` for
/// `j < c` and `2 sigma_c(j - c) + 1` otherwise; for `b = 2c + 1`, `sigma_b` is `sigma_2c` with
/// values `>= c` raised by one and `c` inserted in the middle. Depth `O(log b)`.
///
/// ```
/// use qmckit::randomize::digits::faure;
/// let s7: Vec<u32> = (0..7).map(|j| faure(7, j)).collect();
/// assert_eq!(s7, [0, 2, 5, 3, 1, 4, 6]);
/// ```
pub const fn faure(base: u32, digit: u32) -> u32 {
    if base <= 2 || digit >= base {
        return digit;
    }
    let c = base / 2;
    if base.is_multiple_of(2) {
        if digit < c {
            2 * faure(c, digit)
        } else {
            2 * faure(c, digit - c) + 1
        }
    } else if digit == c {
        c
    } else {
        let j = if digit < c { digit } else { digit - 1 };
        let v = faure(2 * c, j);
        if v >= c { v + 1 } else { v }
    }
}
