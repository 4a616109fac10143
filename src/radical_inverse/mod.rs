//! The radical inverse in any base `b >= 2`, exact to the last bit, and its inverse; with
//! the constructions made of it: [`van_der_corput`] (one base), [`halton`] (one prime base a
//! dimension) and [`hammersley`] (`i / N` beside Halton).
//!
//! For an index `i = sum_{j>=1} d_j b^(j-1)` with base-`b` digits `d_j`, the radical inverse
//! mirrors the digits around the radix point:
//!
//! ```text
//! phi_b(i) = sum_{j>=1} d_j b^(-j)          e.g. phi_2(6) = 0.011b = 0.375
//! ```
//!
//! qmckit returns `floor(phi_b(i) * 2^32)` as a `u32`, **exactly** (no floating point), for
//! every `u32` index, so `phi_3(1000) = 760/2187` comes out as `floor(760 * 2^32 / 2187)`.
//!
//! # How it stays exact and fast
//!
//! Let `K` be a digit count with `B = b^K >= 2^32` (the smallest one, rounded up to a
//! multiple of the chunk size `c` below); every `u32` index has at most `K` digits and
//! `phi_b(i) = N / B` with the integer `N = sum_j d_j b^(K-j) < B < 2^64`.
//!
//! Random access ([`RadicalInverse::sample`]) peels the index a chunk of `c` digits at a
//! time: it divides by `b^c` with a precomputed multiply-high (Lemire, Kaser & Kurz 2019,
//! "Faster remainder by direct computation") and reverses the chunk's digits with a
//! 256-entry-at-most table (`c = 5, 3, 2, 2, 2` for bases 3, 5, 7, 11, 13; `c = 1`, no table,
//! otherwise). Short indices (up to three chunks, `b^c <= 2^16`) then fold the chunks from
//! the top by nested floors, `F <- floor((rev(C) 2^32 + F) / b^c)`, one exact multiply-high
//! each, which lands on `floor(phi_b(i) 2^32)` with no rounding step (on 64-bit targets, two
//! chunks for `b^c <= 256` and three for `b^c <= 40` take a single exact multiply-high by
//! `ceil(2^64 / b^(2c))` or `ceil(2^64 / b^(3c))` instead). Longer indices build
//! `N = sum_j rev(C_j) b^(K-c(j+1))` from the quotients `floor(i / b^(cj))`, all computed
//! at once by multiply-highs with precomputed magics (so no chunk waits on the previous
//! one; for `c = 1` the digits need not even be formed, see `numerator_wide`), and round
//! `N * 2^32 / B` down with a precomputed reciprocal and one correction step (Granlund &
//! Montgomery 1994). Base 2 is a single bit reversal.
//!
//! Sequential access keeps `phi_b(i) * 2^32` as an integer part and an exact remainder over
//! `B`. The iterator ([`RadicalInverse::iter_from`]) adds a cached step: when `i + 1` ends in
//! `t` zero digits, `phi_b` changes by `b^(-t) + b^(-t-1) - 1`, which is `b^(-1)` in the
//! common case `t = 0`. The batch fill ([`RadicalInverse::fill`]) goes by runs of the lowest
//! digit, `phi_b(hb + d) = phi_b(hb) + d/b`, adding a tabled `d/b` to the run's base, so
//! consecutive values do not wait on each other. All paths return the same bits (tested
//! against each other and against a `u128` rational oracle).

use crate::bits::{FromFraction, div_u32, div_u64, rem_u32, rem_u64, reverse_bits};
use crate::error::{Error, Result};
use crate::randomize::digits::DigitScramble;

mod fill;
pub mod halton;
pub mod hammersley;
#[cfg(feature = "std")]
mod permuted;
mod random_access;
mod sequential;
mod tables;
#[cfg(test)]
mod tests;
pub mod van_der_corput;

#[cfg(target_pointer_width = "64")]
pub(crate) use fill::RunFill;
pub(crate) use fill::check_range;
pub use sequential::RadicalInverseIter;
use sequential::Sequential;
use tables::*;

/// 2^32 as `u64`.
const TWO_32: u64 = 1 << 32;

/// Number of carry steps cached by the sequential paths; longer carries (probability
/// `b^-STEPS`) are computed on the spot.
const STEPS: usize = 8;

/// Longest run (a power of the base) whose digit fractions the sequential fill tables, and
/// so the largest base it handles by runs (on the stack: 5 bytes an entry, 1280 bytes).
const RUN_TABLE: usize = 256;

/// Largest chunk `b^c` for which [`RadicalInverse::sample`] takes the nested-floor path
/// (exact up to `2^16`, see `nest`); larger bases build the exact numerator.
const NESTED_CHUNK_MAX: u32 = 1 << 16;

/// A validated base with its precomputed constants: the radical inverse `phi_b` as a cheap,
/// infallible, `const`-callable function of the index.
///
/// 104 bytes on 64-bit targets, 48 on 32-bit ones (plus the 707-byte shared digit-reversal
/// tables, linked with any run-time use).
/// Build it once (a `const`, or a table like [`crate::radical_inverse::halton::HALTON_BASES`]).
///
/// ```
/// use qmckit::RadicalInverse;
/// const PHI3: RadicalInverse = match RadicalInverse::new(3) { Ok(r) => r, Err(_) => panic!() };
/// // phi_3(1000) = 760/2187 exactly; the u32 is floor(760 * 2^32 / 2187).
/// const X: u32 = PHI3.sample(1000);
/// assert_eq!(X as u64, (760u64 << 32) / 2187);
/// assert_eq!(PHI3.inverse(X, 7), Ok(1000)); // 3^7 = 2187 > 1000
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RadicalInverse {
    base: u32,
    /// `K`: digit places of the outputs, `B = b^K >= 2^32`, a multiple of the chunk's digits.
    digits: u8,
    /// `b^c`: random access peels `c` digits of the index at a time.
    chunk: u32,
    /// [`REVERSAL`] table for the chunk (0: `c = 1`, no table needed).
    table: u8,
    /// Trailing zero bits of `chunk` (its power-of-two factor).
    chunk_shift: u8,
    /// `ceil(2^64 / chunk)`: `n / chunk == mulhi(n, chunk_magic)` for every `u32` `n`.
    chunk_magic: u64,
    /// `ceil(2^64 / chunk^j)` for `j = 2, 3, 4` while `j` is below the chunk count, else 0:
    /// the quotients `floor(n / chunk^j)` of a `u32` index by one multiply-high each.
    #[cfg(target_pointer_width = "64")]
    power_magic: [u64; 3],
    /// Inverse of the odd part of `chunk` modulo 2^64 (exact division by multiplication).
    #[cfg(not(target_pointer_width = "64"))]
    chunk_inv: u64,
    /// `min(chunk^3, 2^32) - 1` for chunks up to `NESTED_CHUNK_MAX`, else 0: indices up to
    /// it take the nested floors (at most three chunks).
    short_max: u32,
    /// The coefficients `(A, A', A'')` of the flat three-digit formula (zero for the
    /// two-digit one) and the flat path's last index, all below 2^16; all zero where it does
    /// not apply (see `flat`).
    #[cfg(target_pointer_width = "64")]
    flat: [u16; 4],
    /// `chunk^(m-1-j)` for the `m = K / c <= WIDE` chunks of the wide numerator (0 past `m`),
    /// all below 2^32; all zero when `m > WIDE` (the serial numerator serves those bases).
    #[cfg(target_pointer_width = "64")]
    weight: [u32; WIDE],
    /// `B = base^K`, the common denominator of all outputs.
    big: u64,
    /// `floor((2^96 - 1) / B)`: reciprocal for rounding `N * 2^32 / B` down.
    recip: u64,
}

// The sizes the documentation states (they set the Halton table's flash cost), checked
// at compile time on every target.
#[cfg(target_pointer_width = "64")]
const _: () = assert!(core::mem::size_of::<RadicalInverse>() == 104);
#[cfg(not(target_pointer_width = "64"))]
const _: () = assert!(core::mem::size_of::<RadicalInverse>() == 48);

impl RadicalInverse {
    /// Validates `base >= 2` and precomputes its constants (a few `u128` divisions: do it
    /// once, or in a `const`).
    ///
    /// # Errors
    /// [`Error::BaseTooSmall`] for bases 0 and 1. Any `base >= 2` is accepted (it need not be
    /// prime: the radical inverse is defined for every base).
    pub const fn new(base: u32) -> Result<Self> {
        if base < 2 {
            return Err(Error::BaseTooSmall { base });
        }
        let (table, c) = reversal_for(base);
        let b = base as u64;
        let mut chunk = 1u64;
        let mut k = 0;
        while k < c {
            chunk *= b;
            k += 1;
        }
        // Smallest multiple K of c with b^K >= 2^32 (b^K < 2^40 for the tabled bases,
        // < b 2^32 <= 2^64 otherwise).
        let mut big = 1u64;
        let mut digits = 0u32;
        while big < TWO_32 {
            big *= chunk;
            digits += c;
        }
        let chunk_shift = chunk.trailing_zeros();
        Ok(RadicalInverse {
            base,
            digits: digits as u8,
            chunk: chunk as u32,
            table,
            chunk_shift: chunk_shift as u8,
            chunk_magic: div_u64(u64::MAX, chunk) + 1,
            #[cfg(target_pointer_width = "64")]
            power_magic: power_magics(chunk, digits / c),
            #[cfg(not(target_pointer_width = "64"))]
            chunk_inv: inverse_mod_2_64(chunk >> chunk_shift),
            short_max: {
                let cube = chunk as u128 * chunk as u128 * chunk as u128; // no overflow
                if chunk > NESTED_CHUNK_MAX as u64 {
                    0 // index 0 is 0 by any path
                } else if cube >= TWO_32 as u128 {
                    u32::MAX
                } else {
                    (cube - 1) as u32
                }
            },
            #[cfg(target_pointer_width = "64")]
            flat: flat_coefficients(table, chunk),
            #[cfg(target_pointer_width = "64")]
            weight: wide_weights(chunk, digits / c),
            big,
            recip: match (u128::MAX >> 32).checked_div(big as u128) {
                Some(r) => r as u64,
                None => 0,
            },
        })
    }

    /// The base `b`.
    #[inline]
    pub const fn base(&self) -> u32 {
        self.base
    }

    /// `K`, the number of base-`b` digit places behind the outputs: every output is a
    /// multiple of `b^-K` rounded down, and `b^K >= 2^32`, so every `u32` index has at most
    /// `K` digits. `K` is the smallest such count, rounded up to a multiple of the digits
    /// random access peels at once (5 for base 3, so 25 rather than 21).
    #[inline]
    pub const fn digits(&self) -> u32 {
        self.digits as u32
    }
}
