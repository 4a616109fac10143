//! The radical inverse in any base `b >= 2`, exact to the last bit, and its inverse.
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

/// Most chunks the wide numerator handles (every prime base: at most 8 chunks, for 17, 19
/// and 23; the composite bases 4 to 15 without a reversal table have more and take the
/// serial numerator).
#[cfg(target_pointer_width = "64")]
const WIDE: usize = 8;

/// [`RadicalInverse::power_magic`] for chunk `q` and `m` chunks.
#[cfg(target_pointer_width = "64")]
const fn power_magics(q: u64, m: u32) -> [u64; 3] {
    let mut magic = [0u64; 3];
    let mut p = q * q;
    let mut j = 2;
    while j <= 4 && j < m {
        // q^j <= q^(m-1) < 2^32: no overflow, and the magic is exact for u32 numerators.
        magic[j as usize - 2] = div_u64(u64::MAX, p) + 1;
        p *= q;
        j += 1;
    }
    magic
}

/// [`RadicalInverse::weight`] for chunk `q` and `m` chunks.
#[cfg(target_pointer_width = "64")]
const fn wide_weights(q: u64, m: u32) -> [u32; WIDE] {
    let mut weight = [0u32; WIDE];
    if m as usize <= WIDE {
        let mut w = 1u64;
        let mut j = m as usize;
        while j > 0 {
            j -= 1;
            weight[j] = w as u32; // q^(m-1-j) <= q^(m-1) < 2^32
            w *= q;
        }
    }
    weight
}

/// Largest chunk `q` (of one digit, `q = b`) whose indices below `q^3` take the flat
/// three-digit formula, and largest whose indices below `q^2` take the two-digit one
/// (exactness: `q^6 <= 2^32`, resp. `q^4 + q^3 < 2^32` or `q` a power of 2; see `flat`).
#[cfg(target_pointer_width = "64")]
const FLAT3_MAX: u64 = 40;
#[cfg(target_pointer_width = "64")]
const FLAT2_MAX: u64 = 256;

/// [`RadicalInverse::flat`] for the reversal table id and chunk `q`: bases without a table
/// (`c = 1`) up to [`FLAT3_MAX`]: `(q^2, q^3 - q, q^2 - 1)` up to index `q^3 - 1`; up to
/// [`FLAT2_MAX`]: `(0, 0, 0)` (the two-digit path needs no coefficients; `A'' = 0` selects
/// it) up to `q^2 - 1` (all below 2^16); else zeros.
#[cfg(target_pointer_width = "64")]
const fn flat_coefficients(table: u8, q: u64) -> [u16; 4] {
    if table != 0 {
        [0; 4]
    } else if q <= FLAT3_MAX {
        [
            (q * q) as u16,
            (q * q * q - q) as u16,
            (q * q - 1) as u16,
            (q * q * q - 1) as u16,
        ]
    } else if q <= FLAT2_MAX {
        [0, 0, 0, (q * q - 1) as u16]
    } else {
        [0; 4]
    }
}

/// `floor(m x / 2^64)`.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
const fn mul_hi(m: u64, x: u32) -> u32 {
    ((m as u128 * x as u128) >> 64) as u32
}

/// `floor(m x / 2^64)` as a `u32` (the caller knows it fits).
#[cfg(target_pointer_width = "64")]
#[inline(always)]
const fn mul_hi_64(m: u64, x: u64) -> u32 {
    ((m as u128 * x as u128) >> 64) as u32
}

/// `rev(lo - q hi) w`: chunk `lo - q hi` of the wide numerator, reversed and weighted.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
const fn rev_weighted(table: &[u8], q: u32, hi: u32, lo: u32, w: u32) -> u64 {
    reverse_in(table, lo.wrapping_sub(hi.wrapping_mul(q))) as u64 * w as u64
}

/// Digit-reversal tables for the small prime bases: entry `r` is the `c`-digit reversal of
/// `r < b^c`, with `b^c <= 256` so entries fit a byte. They let random access consume `c`
/// digits per step (5 for base 3). 707 bytes in all.
static REVERSAL: [&[u8]; 6] = [
    &[],
    &reversal_table::<243>(3),
    &reversal_table::<125>(5),
    &reversal_table::<49>(7),
    &reversal_table::<121>(11),
    &reversal_table::<169>(13),
];

/// `table[r]`, or `r` itself past the table's end (an empty table: `c = 1`, no reversal).
#[inline(always)]
const fn reverse_in(table: &[u8], r: u32) -> u32 {
    if (r as usize) < table.len() {
        table[r as usize] as u32
    } else {
        r
    }
}

/// `[rev_c(r) for r < N]` for `N = b^c`.
const fn reversal_table<const N: usize>(base: u32) -> [u8; N] {
    let mut table = [0u8; N];
    let mut r = 0;
    while r < N {
        let (mut n, mut rev, mut len) = (r as u32, 0u32, 1usize);
        while len < N {
            rev = rev * base + n % base;
            n /= base;
            len *= base as usize;
        }
        table[r] = rev as u8;
        r += 1;
    }
    table
}

/// Which [`REVERSAL`] table serves `base` (0: none) and its chunk of digits `c`.
const fn reversal_for(base: u32) -> (u8, u32) {
    match base {
        3 => (1, 5),
        5 => (2, 3),
        7 => (3, 2),
        11 => (4, 2),
        13 => (5, 2),
        _ => (0, 1),
    }
}

/// A validated base with its precomputed constants: the radical inverse `phi_b` as a cheap,
/// infallible, `const`-callable function of the index.
///
/// 104 bytes on 64-bit targets, 48 on 32-bit ones (plus the 707-byte shared digit-reversal
/// tables, linked with any run-time use).
/// Build it once (a `const`, or a table like [`crate::halton::HALTON_BASES`]).
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

    /// `floor(phi_b(index) * 2^32)`, exact. Defined for every `u32` index.
    ///
    /// On 64-bit targets, short indices of bases without a reversal table (`b <= 256`:
    /// below `b^3` for `b <= 40`, below `b^2` up to 256) take one branch-free formula (two
    /// multiplications for two digits, six for three; see `flat`). Otherwise indices of up
    /// to three chunks of `c` digits (`c = 5, 3, 2, 2, 2` for bases 3, 5, 7, 11, 13; 1
    /// otherwise), for `b^c <= 2^16`, go by nested floors (see `nest`): three
    /// multiplications per chunk, one for the last. Longer indices (and bases above 2^16)
    /// build the exact numerator `N` over `B = b^K` from all chunk quotients at once (see
    /// `numerator_wide`: about 16 multiplications, none waiting on another, no branch) and
    /// scale it once (two more); that is on 64-bit targets, inline, except for the composite
    /// bases 4 to 15 (more than 8 chunks). 32-bit targets build `N` chunk by chunk (four
    /// multiplications per chunk), out of line, for flash. Base 2 is one bit reversal.
    #[inline(always)]
    pub const fn sample(&self, index: u32) -> u32 {
        #[cfg(target_pointer_width = "64")]
        if index <= self.flat[3] as u32 {
            return self.flat(index);
        }
        if self.base == 2 {
            return reverse_bits(index);
        }
        let q = self.chunk;
        if index <= self.short_max {
            // index < q^3: up to three chunks by nested floors, unrolled.
            if index < q {
                return self.nest(index, 0) as u32;
            }
            let (n1, r0) = self.peel(index);
            if n1 < q {
                return self.two_chunks(r0, n1);
            }
            let (n2, r1) = self.peel(n1);
            return self.three_chunks(r0, r1, n2);
        }
        self.sample_long(index)
    }

    /// `floor(phi_b(i) 2^32)` for a short index of a base without a reversal table
    /// (`c = 1`, `q = b`), branch-free. With `Q_1 = floor(i / q)`, `Q_2 = floor(i / q^2)` the
    /// digits are `i - q Q_1`, `Q_1 - q Q_2`, `Q_2`, so for `i < q^3`
    ///
    /// ```text
    /// phi_b(i) = X / q^3,  X = (i - q Q_1) q^2 + (Q_1 - q Q_2) q + Q_2
    ///                        = i q^2 - (q^3 - q) Q_1 - (q^2 - 1) Q_2
    /// ```
    ///
    /// and for `i < q^2` (`Q_2 = 0`) `phi_b(i) = X / q^2` with `X = i q - (q^2 - 1) Q_1`; one-
    /// and two-digit indices need no branch (their high digits are 0), and index 0 gives 0
    /// for every base (all coefficients are 0 where the formula does not apply).
    ///
    /// Every product is a single 64-bit multiplication (the integer multiplier, not the
    /// number of instructions, bounds this loop): `Q_1 = floor(i M / 2^32)` with
    /// `M = floor(chunk_magic / 2^32) + 1 = (2^32 + e) / q`, `0 < e <= q`, errs by
    /// `i e / (q 2^32) < 1 / q` (as `i q < 2^32` here), less than the gap from `i / q` up to
    /// an integer, so it is exact; `Q_2` likewise from `ceil(2^64 / q^2)`. The result is
    /// `floor(X M' / 2^32)` for `M' = ceil(2^64 / q^3)` (`q <= 40`), exact as in
    /// [`three_chunks`](Self::three_chunks), and `X M' < 2^64` (`X < q^3`,
    /// `M' < 2^64 / q^3 + 1`), so the low product suffices. Cost: six multiplications.
    ///
    /// Two digits (`40 < q <= 256`, `i < q^2`) take one widening multiplication instead:
    /// with `R = ceil(2^64 / q) = (2^64 + e) / q`, `0 <= e < q`, the product
    /// `i R = 2^64 Q_1 + L` gives `Q_1` as its high half and `L = 2^64 d_0 / q + i e / q` as
    /// its low half (`d_0 = i - q Q_1`), so with `R_2 = ceil(2^64 / q^2) = (2^64 + e') / q^2`
    ///
    /// ```text
    /// S = L + Q_1 R_2 = 2^64 (d_0 q + Q_1) / q^2 + E,   E = i e / q + Q_1 e' / q^2 < q^2 + q,
    /// ```
    ///
    /// and `floor(S / 2^32) = floor(2^32 X / q^2)` because `E / 2^32 < 1 / q^2` (the gap of
    /// `2^32 X / q^2` below the next integer) whenever `q^4 + q^3 < 2^32`, i.e. `q <= 255`
    /// (`q = 256` has `e = e' = 0`); `S < 2^64`, so wrapping addition is exact. Cost: one
    /// widening multiplication and one 64-bit one (the integer multiplier bounds this loop).
    #[cfg(target_pointer_width = "64")]
    #[inline(always)]
    const fn flat(&self, index: u32) -> u32 {
        let i = index as u64;
        let [a, a1, a2, _] = self.flat;
        if a2 == 0 {
            // Two digits, one widening multiplication and one more: see above.
            let p = i as u128 * self.chunk_magic as u128;
            let (q1, low) = ((p >> 64) as u64, p as u64);
            return (low.wrapping_add(q1 * self.power_magic[0]) >> 32) as u32;
        }
        let q1 = (i * ((self.chunk_magic >> 32) + 1)) >> 32;
        let x = (i * a as u64).wrapping_sub(q1 * a1 as u64);
        let q2 = (i * ((self.power_magic[0] >> 32) + 1)) >> 32;
        let x = x.wrapping_sub(q2 * a2 as u64);
        (x.wrapping_mul(self.power_magic[1]) >> 32) as u32 // X / q^3
    }

    /// `floor(phi_b(i) 2^32)` for an index of two chunks `r0 + q r1` (`q = b^c <= 2^16`).
    ///
    /// On 64-bit targets with `q <= 256`, in one division: `phi_b(i) = X / q^2` with
    /// `X = rev(r0) q + rev(r1) < q^2`, and the multiply-high of `X 2^32` by
    /// `ceil(2^64 / q^2) = (2^64 + e) / q^2` (`e < q^2`) errs by less than `q^2 / 2^32 <=
    /// 1 / q^2`, the smallest gap from `X 2^32 / q^2` up to an integer, so the floor is
    /// exact. Otherwise two nested floors.
    #[inline(always)]
    const fn two_chunks(&self, r0: u32, r1: u32) -> u32 {
        #[cfg(target_pointer_width = "64")]
        if self.chunk <= 256 {
            let x = self.reverse_chunk(r0) * self.chunk + self.reverse_chunk(r1);
            return mul_hi_64(self.power_magic[0], (x as u64) << 32);
        }
        self.nest(r0, self.nest(r1, 0)) as u32
    }

    /// `floor(phi_b(i) 2^32)` for an index of three chunks `r0 + q r1 + q^2 r2`
    /// (`q = b^c <= 2^16`): as [`two_chunks`](Self::two_chunks) with `X < q^3` over `q^3`,
    /// exact for `q^6 <= 2^32`, i.e. `q <= 40` (on 64-bit targets); otherwise nested floors.
    #[inline(always)]
    const fn three_chunks(&self, r0: u32, r1: u32, r2: u32) -> u32 {
        #[cfg(target_pointer_width = "64")]
        if self.chunk <= 40 {
            let q = self.chunk;
            let x =
                (self.reverse_chunk(r0) * q + self.reverse_chunk(r1)) * q + self.reverse_chunk(r2);
            return mul_hi_64(self.power_magic[1], (x as u64) << 32);
        }
        self.nest(r0, self.nest(r1, self.nest(r2, 0))) as u32
    }

    /// [`sample`](Self::sample) for indices of four or more chunks, and for all indices
    /// when `b^c > 2^16`: the exact numerator, then one scaling. Inline on 64-bit targets
    /// (the branch-free wide numerator overlaps neighbouring calls' work); out of line on
    /// 32-bit ones, where flash is dear and the serial numerator serves.
    #[cfg_attr(target_pointer_width = "64", inline(always))]
    #[cfg_attr(not(target_pointer_width = "64"), inline(never))]
    const fn sample_long(&self, index: u32) -> u32 {
        self.scale(self.numerator(index)).0
    }

    /// `(n / b^c, n mod b^c)` by a multiply-high (exact for every `u32` `n`).
    #[inline(always)]
    const fn peel(&self, n: u32) -> (u32, u32) {
        let q = ((self.chunk_magic as u128 * n as u128) >> 64) as u32;
        (q, n - q * self.chunk)
    }

    /// One nested-floor step `floor((rev(r) 2^32 + f) / b^c)` for a chunk `r < b^c`,
    /// `f < 2^32` and `b^c <= 2^16`.
    ///
    /// With the index's chunks `C_0, ..., C_m` (`c` digits each, lowest first) and `rev` the
    /// `c`-digit reversal, `phi_b(i) = (rev(C_0) + (rev(C_1) + ... ) / b^c) / b^c`, and
    /// because `floor((a + floor(y)) / q) = floor((a + y) / q)` for integers `a`, `q > 0`,
    ///
    /// ```text
    /// F_m = floor(rev(C_m) 2^32 / b^c),   F_j = floor((rev(C_j) 2^32 + F_(j+1)) / b^c),
    /// floor(phi_b(i) 2^32) = F_0.
    /// ```
    ///
    /// Each step divides `t = rev 2^32 + F < b^c 2^32` by `b^c` with one multiply-high by
    /// `ceil(2^64 / b^c) = (2^64 + e) / b^c`, `0 <= e < b^c`: the error `t e / (b^c 2^64)` is
    /// below `1 / b^c` (the smallest gap from `t / b^c` up to an integer) as `b^c <= 2^16`, so
    /// the floor is exact. No final scaling is needed.
    #[inline(always)]
    const fn nest(&self, r: u32, f: u64) -> u64 {
        let t = ((self.reverse_chunk(r) as u64) << 32) | f;
        ((self.chunk_magic as u128 * t as u128) >> 64) as u64
    }

    /// The `c`-digit reversal of a chunk `r < b^c` (the chunk itself when `c = 1`).
    #[inline(always)]
    const fn reverse_chunk(&self, r: u32) -> u32 {
        if self.table == 0 {
            return r;
        }
        reverse_in(self.reversal_table(), r)
    }

    /// This base's digit-reversal table (empty when `c = 1`).
    #[inline(always)]
    const fn reversal_table(&self) -> &'static [u8] {
        // Guarded indexing (no panic path): an unknown id means no table.
        let id = self.table as usize;
        if id < REVERSAL.len() {
            REVERSAL[id]
        } else {
            &[]
        }
    }

    /// `floor(phi'_b(index) 2^32)` for the digit-scrambled radical inverse
    /// `phi'_b(i) = sum_(j=1..K) sigma_j(d_j) b^-j` (see [`DigitScramble`]), exact for that
    /// `K`-digit sum. `dim` keys the random permutations. `const`.
    ///
    /// Cost: `K` digit steps (all digit places, since scrambled leading zeros are not zero),
    /// each a division and, for the random kinds, a keyed permutation.
    ///
    /// ```
    /// use qmckit::RadicalInverse;
    /// use qmckit::randomize::digits::DigitScramble;
    /// let phi5 = RadicalInverse::new(5)?;
    /// assert_eq!(phi5.sample_scrambled(123, &DigitScramble::None, 0), phi5.sample(123));
    /// // Faure's sigma_5 = (0, 3, 2, 1, 4): phi'_5(1) = 3/5.
    /// assert_eq!(phi5.sample_scrambled(1, &DigitScramble::Faure, 0) as u64, (3u64 << 32) / 5);
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub const fn sample_scrambled(&self, index: u32, scramble: &DigitScramble, dim: usize) -> u32 {
        if scramble.is_none() {
            return self.sample(index);
        }
        self.scale(self.exact_scrambled(index, scramble, dim)).0
    }

    /// The exact numerator `N` of the (scrambled) radical inverse over
    /// [`denominator`](Self::denominator): `phi'_b(index) = N / B`. For users who need the
    /// value beyond 32 bits (e.g. an `f64` with 53) or exact arithmetic.
    ///
    /// ```
    /// use qmckit::{RadicalInverse, randomize::digits::DigitScramble};
    /// let phi3 = RadicalInverse::new(3)?;
    /// let n = phi3.exact_scrambled(1000, &DigitScramble::None, 0);
    /// assert_eq!(n as u128 * 2187, 760 * phi3.denominator() as u128); // 760/2187
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub const fn exact_scrambled(&self, index: u32, scramble: &DigitScramble, dim: usize) -> u64 {
        if scramble.is_none() {
            return self.numerator(index);
        }
        let b = self.base as u64;
        let mut n = index as u64;
        let mut weight = div_u64(self.big, b); // b^(K-1)
        let (mut prefix, mut place) = (0u64, 1u64); // index mod b^(j-1), and b^(j-1)
        let mut acc = 0u64;
        let mut j = 1;
        while j <= self.digits as u32 {
            let d = rem_u64(n, b) as u32;
            n = div_u64(n, b);
            let s = scramble.digit(self.base, dim, j, prefix, d);
            acc += s as u64 * weight; // < B
            prefix += d as u64 * place;
            place = place.wrapping_mul(b);
            weight = div_u64(weight, b);
            j += 1;
        }
        acc
    }

    /// `B = b^K`, the denominator of [`exact_scrambled`](Self::exact_scrambled).
    pub const fn denominator(&self) -> u64 {
        self.big
    }

    /// `N` with `phi_b(index) = N / B`: the digits of `index` reversed into `K` places.
    /// 64-bit targets build it from all chunk quotients at once (for at most `WIDE` chunks,
    /// every prime base); 32-bit targets (microcontrollers without a 64-bit multiplier,
    /// where that code would cost a kilobyte of flash) chunk by chunk. Same value.
    #[inline(always)]
    const fn numerator(&self, index: u32) -> u64 {
        #[cfg(target_pointer_width = "64")]
        if self.weight[0] != 0 {
            return self.numerator_wide(index);
        }
        self.numerator_serial(index)
    }

    /// [`numerator`](Self::numerator) with all chunk quotients at once, for `m <= WIDE`
    /// chunks of `c` digits (`q = b^c`, `W_j = q^(m-1-j)`).
    ///
    /// The quotients `Q_j = floor(n / q^j)` do not wait on each other: `Q_1 .. Q_4` are one
    /// multiply-high of `n` each, `Q_5 .. Q_7` one of `Q_4` (`floor(floor(n/a)/b) =
    /// floor(n/(ab))`); each magic `ceil(2^64/d)` is exact for numerators below 2^32 and
    /// `d < 2^32`, and is 0 where `q^j >= 2^32` (then `Q_j = 0` indeed). Chunk `j` is
    /// `Q_j - q Q_(j+1)`, so
    ///
    /// ```text
    /// N = sum_(j<6) rev(Q_j - q Q_(j+1)) W_j                   (reversal table, c > 1)
    /// N = W_0 n - (b^2 - 1) sum_(j>=1) W_j Q_j  (mod 2^64)    (c = 1, rev = identity)
    /// ```
    ///
    /// the second because `b W_j = W_(j-1)`, so in `sum_j (Q_j - b Q_(j+1)) W_j` the
    /// coefficient of `Q_j` (`j >= 1`) is `W_j - W_(j-2) = (1 - b^2) W_j` (`W_(-1) = b^m`).
    /// Wrapping arithmetic is exact as `N < 2^64`. Cost: 7 multiply-highs
    /// and 8 (c = 1) or 12 (tabled) multiplications, no loop and one branch (table or
    /// not), so the work of one index overlaps the next one's.
    #[cfg(target_pointer_width = "64")]
    #[inline(always)]
    const fn numerator_wide(&self, n: u32) -> u64 {
        let [m2, m3, m4] = self.power_magic;
        let q1 = mul_hi(self.chunk_magic, n);
        let q2 = mul_hi(m2, n);
        let q3 = mul_hi(m3, n);
        let q4 = mul_hi(m4, n);
        let q5 = mul_hi(self.chunk_magic, q4);
        let q6 = mul_hi(m2, q4);
        let q7 = mul_hi(m3, q4);
        let w = &self.weight;
        if self.table == 0 {
            let s = (w[1] as u64 * q1 as u64)
                .wrapping_add(w[2] as u64 * q2 as u64)
                .wrapping_add(w[3] as u64 * q3 as u64)
                .wrapping_add(w[4] as u64 * q4 as u64)
                .wrapping_add(w[5] as u64 * q5 as u64)
                .wrapping_add(w[6] as u64 * q6 as u64)
                .wrapping_add(w[7] as u64 * q7 as u64);
            let b = self.base as u64;
            return (w[0] as u64 * n as u64).wrapping_sub((b * b - 1).wrapping_mul(s));
        }
        // The tabled bases have at most 6 chunks (49^6 >= 2^32 for base 7; 5 for the
        // others): chunks 6 and 7 are zero.
        let (t, q) = (self.reversal_table(), self.chunk);
        rev_weighted(t, q, q1, n, w[0])
            + rev_weighted(t, q, q2, q1, w[1])
            + rev_weighted(t, q, q3, q2, w[2])
            + rev_weighted(t, q, q4, q3, w[3])
            + rev_weighted(t, q, q5, q4, w[4])
            + rev_weighted(t, q, q6, q5, w[5])
    }

    /// [`numerator`](Self::numerator) chunk by chunk (on 64-bit targets only for the bases
    /// with more than `WIDE` chunks, the composites 4 to 15): each chunk weighted by
    /// `b^(K-c)`, `b^(K-2c)`, ..., the weight stepped down by the inverse of `b^c` modulo
    /// 2^64 (an exact division). Four multiplications a chunk, each waiting on the last.
    #[inline(never)]
    const fn numerator_serial(&self, index: u32) -> u64 {
        #[cfg(target_pointer_width = "64")]
        let inv = inverse_mod_2_64((self.chunk >> self.chunk_shift) as u64);
        #[cfg(not(target_pointer_width = "64"))]
        let inv = self.chunk_inv;
        let shift = self.chunk_shift;
        let (mut n, mut acc) = (index, 0u64);
        let mut weight = (self.big >> shift).wrapping_mul(inv); // b^(K-c)
        let table = self.reversal_table(); // looked up once, not per chunk
        loop {
            let (q, r) = self.peel(n);
            // The chunk's c digits reversed (with c = 1 there is no table: r itself).
            acc += reverse_in(table, r) as u64 * weight; // sum < B: no overflow
            if q == 0 {
                return acc;
            }
            weight = (weight >> shift).wrapping_mul(inv); // exact: weight / b^c
            n = q;
        }
    }

    /// `(q, r)` with `n * 2^32 = q * B + r`, `0 <= r < B`, for `n < B` (so `q < 2^32`).
    #[inline]
    const fn scale(&self, n: u64) -> (u32, u64) {
        // q0 <= q and q0 > n 2^32 / B - 1, so q is q0 or q0 + 1.
        let q0 = ((n as u128 * self.recip as u128) >> 64) as u64;
        if self.big <= 1 << 63 {
            // r0 = n 2^32 - q0 B lies in [0, 2B) within 2^64: wrapping arithmetic is exact.
            let r0 = (n << 32).wrapping_sub(q0.wrapping_mul(self.big));
            if r0 >= self.big {
                ((q0 + 1) as u32, r0 - self.big)
            } else {
                (q0 as u32, r0)
            }
        } else {
            let r0 = ((n as u128) << 32) - q0 as u128 * self.big as u128;
            if r0 >= self.big as u128 {
                ((q0 + 1) as u32, (r0 - self.big as u128) as u64)
            } else {
                (q0 as u32, r0 as u64)
            }
        }
    }

    /// `2^32 b^-j` modulo 2^32 as `(q, r)` over `B`, for `1 <= j <= K`.
    const fn power(&self, j: u32) -> (u32, u64) {
        let inv = inverse_mod_2_64((self.base >> self.base.trailing_zeros()) as u64);
        let shift = self.base.trailing_zeros();
        let mut w = self.big;
        let mut k = 0;
        while k < j {
            w = (w >> shift).wrapping_mul(inv); // exact: b^(K-k) / b
            k += 1;
        }
        self.scale(w)
    }

    /// The exact change of `phi_b(i) * 2^32` (mod 2^32) from `i` to `i + 1` when `i + 1` ends
    /// in `t` zero digits: `2^32 (b^-t + b^-(t+1))` mod 2^32, for `t < K`.
    const fn step(&self, t: u32) -> (u32, u64) {
        let hi = self.power(t + 1);
        if t == 0 {
            return hi;
        }
        add_exact(hi, self.power(t), self.big)
    }

    /// The steps for `t = 0 .. STEPS` (those with `t < K`).
    const fn steps(&self) -> [(u32, u64); STEPS] {
        let mut steps = [(0u32, 0u64); STEPS];
        if self.base != 2 {
            let mut t = 0;
            while t < STEPS {
                if (t as u32) < self.digits as u32 {
                    steps[t] = self.step(t as u32);
                }
                t += 1;
            }
        }
        steps
    }

    /// Number of trailing zero base-`b` digits of `m > 0`.
    const fn trailing_zero_digits(&self, mut m: u32) -> u32 {
        let mut t = 0;
        while m != 0 && rem_u32(m, self.base) == 0 {
            m = div_u32(m, self.base);
            t += 1;
        }
        t
    }

    /// Inverse of [`sample`](Self::sample) on indices with at most `digits` base-`b` digits:
    /// the `i < b^digits` whose radical inverse rounds down to `value`.
    ///
    /// For a `value` that is not such an output, returns the `i < b^digits` with the
    /// smallest `phi_b(i) >= value / 2^32` (modulo `b^digits`). Cost: `digits` divisions.
    ///
    /// # Errors
    /// [`Error::TooManyDigits`] when `b^digits > 2^32` (outputs of longer indices can
    /// collide in 32 bits, so they cannot be inverted).
    pub const fn inverse(&self, value: u32, digits: u32) -> Result<u32> {
        let b = self.base as u64;
        let mut bk = 1u64;
        let mut k = 0;
        while k < digits {
            bk *= b;
            k += 1;
            if bk > TWO_32 {
                // The largest m with b^m <= 2^32 is k - 1.
                return Err(Error::TooManyDigits { digits, max: k - 1 });
            }
        }
        // value = floor(a 2^32 / b^k) for the reversed-digit integer a, so
        // a = ceil(value b^k / 2^32); value * b^k + 2^32 - 1 < 2^64.
        let mut a = rem_u64((value as u64 * bk + (TWO_32 - 1)) >> 32, bk);
        let mut index = 0u64;
        k = 0;
        while k < digits {
            index = index * b + rem_u64(a, b);
            a = div_u64(a, b);
            k += 1;
        }
        Ok(index as u32)
    }

    /// A sequential iterator over `sample(start)`, `sample(start + 1)`, ... up to index
    /// `u32::MAX`: the same bits as [`sample`](Self::sample), a few cycles per value.
    pub const fn iter_from(&self, start: u32) -> RadicalInverseIter {
        RadicalInverseIter::new(*self, start)
    }

    /// Fills `out[k] = sample(start + k)`.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] if `start + out.len()` passes 2^32.
    pub fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        self.fill_strided(start, out, 1)
    }

    /// Fills every `stride`-th element of `out`, starting with `out[0]`, with consecutive
    /// samples from `start` on: the column of a row-major point buffer.
    ///
    /// The sequential fast path: the exact value is kept as an integer part and a remainder
    /// over `B` in registers, and each index adds a cached step (one add, compare and
    /// conditional subtract while the lowest digit does not wrap).
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] if the indices pass 2^32; [`Error::BufferLength`] for a
    /// zero stride.
    pub fn fill_strided(&self, start: u32, out: &mut [u32], stride: usize) -> Result<()> {
        self.fill_strided_as(start, out, stride)
    }

    /// [`fill_strided`](Self::fill_strided) into any coordinate type (`f64`, `f32`, ...),
    /// converted as each value is stored ([`FromFraction`]): the same values as converting
    /// the `u32` fill afterwards, without a second pass.
    ///
    /// ```
    /// use qmckit::RadicalInverse;
    /// let phi3 = RadicalInverse::new(3)?;
    /// let mut x = [0f64; 4];
    /// phi3.fill_strided_as(1, &mut x, 1)?;
    /// assert_eq!(x[1], qmckit::bits::to_f64(phi3.sample(2))); // 2/3, 32 bits
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`fill_strided`](Self::fill_strided).
    pub fn fill_strided_as<T: FromFraction>(
        &self,
        start: u32,
        out: &mut [T],
        stride: usize,
    ) -> Result<()> {
        if stride == 0 {
            return Err(Error::BufferLength {
                expected: 1,
                got: 0,
            });
        }
        let count = out.len().div_ceil(stride) as u64;
        check_range(start, count)?;
        if self.base == 2 {
            fill_base_2(start, out, stride);
            return Ok(());
        }
        if self.by_runs() {
            self.fill_runs(start, out, stride);
            return Ok(());
        }
        let seq = Sequential::new(self, start);
        let (mut index, mut low, mut q, mut r) = (seq.index, seq.low, seq.q, seq.r);
        let mut slots = out.iter_mut().step_by(stride);
        if let Some(first) = slots.next() {
            *first = T::from_fraction(q);
        }
        for slot in slots {
            (index, low, q, r) = advance(self, &seq.steps, index, low, q, r);
            *slot = T::from_fraction(q);
        }
        Ok(())
    }

    /// Whether the sequential fill goes by runs ([`RunFill`]): `2 <= b <= RUN_TABLE` (and
    /// `B <= 2^63`, true for these bases: `B < b 2^32`).
    #[inline]
    pub(crate) const fn by_runs(&self) -> bool {
        self.base >= 2 && self.base as usize <= RUN_TABLE && self.big <= 1 << 63
    }

    /// Sequential fill for bases `2 ..= RUN_TABLE`, by runs of the lowest `k` digits, with
    /// `L = b^k` the largest power of `b` up to [`RUN_TABLE`] (256, 243, 125, 49, 121, 169
    /// for bases 2, 3, 5, 7, 11, 13; `L = b` for the primes from 17 on). Needs `B <= 2^63`.
    ///
    /// Within a run, `phi_b(h L + e) = phi_b(h L) + n_e / L` exactly, where `n_e` is `e`
    /// with its `k` digits reversed. The table holds `2^32 n_e / L = P_e + s_e / L`
    /// (`P_e = floor`, `0 <= s_e < L`, built by a chain of exact additions of `2^32 / L`),
    /// and the run base is `q + r / B`. As `L` divides `B` (`k <= K`), with `U = B / L`,
    ///
    /// ```text
    /// floor(2^32 phi_b(h L + e)) = q + P_e + [r + s_e U >= B] = q + P_e + [s_e >= ceil((B - r) / U)]
    /// ```
    ///
    /// so each value is two table loads, a 32-bit compare against the run's threshold and
    /// two adds (no 64-bit work, no chain from value to value). Per run of `L` values: the
    /// run base steps by the last entry plus the carry step for the `t >= k` trailing zero
    /// digits of `(h + 1) L` (counted only when the next digit above the run wraps,
    /// probability `1/b`; cached for `t = k, k + 1`), and the threshold takes one multiply-high and one correction.
    /// Stack: `RUN_TABLE` `u32`s and as many bytes (1280 bytes).
    fn fill_runs<T: FromFraction>(&self, start: u32, out: &mut [T], stride: usize) {
        let count = out.len().div_ceil(stride);
        RunFill::new(self, start).write(out, stride, count);
    }
}

/// The resumable state of [`RadicalInverse::fill_runs`] (see there for the math): the
/// tables of one base and the current run, so that a caller can fill a column block by
/// block (the Halton fill interleaves several dimensions this way). About 1.5 KiB.
pub(crate) struct RunFill {
    pq: [u32; RUN_TABLE],
    ps: [u8; RUN_TABLE],
    ri: RadicalInverse,
    /// `L = b^k`, `k`, and `L` as a table length.
    len: u32,
    k: u32,
    l: usize,
    /// `U = B / L` and `floor((2^64 - 1) / U)`.
    unit: u64,
    unit_magic: u64,
    /// `2^32 (L - 1) / L` as `(P, s U)`: the last entry, exact over `B`.
    last: (u32, u64),
    /// The carry steps for `t = k` and `t = k + 1` trailing zero digits (longer carries,
    /// probability `b^-2` a run, are computed on the spot).
    steps: [(u32, u64); 2],
    /// The current run: its first index `h L`, the lowest digit of `h`, its base
    /// `q + r / B`, its carry threshold, and the offset of the next value in it.
    run_index: u32,
    next_digit: u32,
    base_q: u32,
    base_r: u64,
    thr: u32,
    d0: usize,
}

impl RunFill {
    /// The state at index `start`, for `2 <= base <= RUN_TABLE` and `B <= 2^63`.
    pub(crate) fn new(ri: &RadicalInverse, start: u32) -> Self {
        // The caller guarantees 2 <= base <= RUN_TABLE; the clamps are no-ops that let the
        // compiler see every table index below in bounds (no panic path survives
        // inlining; tests/firmware/panic_proof.sh checks this at link time).
        let b = ri.base.clamp(2, RUN_TABLE as u32);
        let (mut len, mut k) = (b, 1u32);
        while len * b <= RUN_TABLE as u32 {
            len *= b;
            k += 1;
        }
        let l = (len as usize).clamp(2, RUN_TABLE);
        // U = B / L, exact as L = b^k with k <= K.
        let unit = div_u64(ri.big, len as u64);
        // (pq[e], ps[e]) = 2^32 rev_k(e) / L as integer part and remainder over L. Walk
        // n = 0, 1, .. L - 1 (adding 2^32 / L exactly each time) and keep e = rev_k(n): a
        // carry out of digit j of n moves e by b^(k-1-j).
        let (mut pq, mut ps) = ([0u32; RUN_TABLE], [0u8; RUN_TABLE]);
        let (step_q, step_s) = (
            div_u64(TWO_32, len as u64) as u32,
            rem_u64(TWO_32, len as u64) as u32,
        );
        let (mut q, mut s, mut e) = (0u32, 0u32, 0u32);
        let top = div_u32(len, b); // b^(k-1), the weight of digit 0 of n in e
        let mut digit = [0u32; 8]; // k <= 8 (b = 2), 5 for b >= 3
        for _ in 0..l {
            if let (Some(a), Some(c)) = (pq.get_mut(e as usize), ps.get_mut(e as usize)) {
                (*a, *c) = (q, s as u8); // s < L <= 256
            }
            (q, s) = (q.wrapping_add(step_q), s + step_s);
            if s >= len {
                (q, s) = (q.wrapping_add(1), s - len);
            }
            let mut place = top;
            for d in digit.iter_mut().take(k as usize) {
                *d += 1;
                e += place;
                if *d < b {
                    break;
                }
                *d = 0;
                e -= place * b;
                place = div_u32(place, b);
            }
        }
        let low = rem_u32(start, len) as usize;
        let run_index = start - low as u32; // h L
        let (base_q, base_r) = ri.scale(ri.numerator(run_index));
        let mut state = RunFill {
            last: (pq[l - 1], ps[l - 1] as u64 * unit),
            pq,
            ps,
            ri: *ri,
            len,
            k,
            l,
            unit,
            // floor((2^64 - 1) / U): ceil(y / U) for y <= B by one multiply-high and a fix.
            unit_magic: div_u64(u64::MAX, unit),
            steps: [ri.step(k), ri.step(k + 1)], // k + 1 < K: b^(k+1) <= 256 b < 2^32
            run_index,
            // The lowest digit of h (that of h + 1 decides whether a carry passes digit k).
            next_digit: rem_u32(div_u32(run_index, len), b),
            base_q,
            base_r,
            thr: 0,
            d0: low,
        };
        state.thr = state.threshold();
        state
    }

    /// `ceil((B - r) / U)` for the run base's remainder `r`, in `1 ..= L`.
    #[inline]
    fn threshold(&self) -> u32 {
        let (y, unit) = (self.ri.big - self.base_r, self.unit); // 1 ..= B
        let q0 = ((y as u128 * self.unit_magic as u128) >> 64) as u64; // q - 1 or q
        let r0 = y - q0 * unit; // < 2 U
        let (q, r) = if r0 >= unit {
            (q0 + 1, r0 - unit)
        } else {
            (q0, r0)
        };
        (q + (r != 0) as u64) as u32
    }

    /// Moves to the next run; the caller guarantees a value of it is due (so its first
    /// index fits in `u32`).
    fn next_run(&mut self) {
        let ri = &self.ri;
        // (h + 1) L ends in t >= k zero digits, t > k iff h + 1 ends in 0.
        self.run_index = self.run_index.wrapping_add(self.len);
        self.next_digit += 1;
        let t = if self.next_digit < ri.base {
            self.k
        } else {
            self.next_digit = 0;
            ri.trailing_zero_digits(self.run_index)
        };
        let step = match t.wrapping_sub(self.k) {
            0 => self.steps[0],
            1 => self.steps[1],
            _ => ri.step(t),
        };
        // The run base moved by the carry step minus the last run's (L - 1) / L part.
        (self.base_q, self.base_r) = add_exact(
            add_exact((self.base_q, self.base_r), self.last, ri.big),
            step,
            ri.big,
        );
        self.thr = self.threshold();
        self.d0 = 0;
    }

    /// Writes the next `count` values to `out[0], out[stride], ..` (those in bounds); the
    /// caller guarantees their indices stay within `u32`.
    #[inline]
    pub(crate) fn write<T: FromFraction>(&mut self, out: &mut [T], stride: usize, count: usize) {
        let mut done = 0;
        while done < count {
            if self.d0 >= self.l {
                self.next_run();
            }
            let (d0, base_q, thr) = (self.d0, self.base_q, self.thr);
            let n = (self.l - d0).min(count - done);
            let run = self.pq.get(d0..d0 + n).unwrap_or(&[]);
            let run_s = self.ps.get(d0..d0 + n).unwrap_or(&[]);
            let value = |p: u32, s: u8| {
                base_q
                    .wrapping_add(p)
                    .wrapping_add((s as u32 >= thr) as u32)
            };
            write_run(
                out,
                done,
                stride,
                run.iter().zip(run_s).map(|(&p, &s)| value(p, s)),
            );
            self.d0 = d0 + n;
            done += n;
        }
    }
}

/// Writes `values`, converted, to `out[(done + j) stride]`, `j = 0, 1, ..` (those in
/// bounds): a plain zip for `stride = 1` (which vectorizes), else indexed stores.
#[inline(always)]
fn write_run<T: FromFraction>(
    out: &mut [T],
    done: usize,
    stride: usize,
    values: impl Iterator<Item = u32>,
) {
    if stride == 1 {
        for (slot, v) in out
            .get_mut(done..)
            .unwrap_or(&mut [])
            .iter_mut()
            .zip(values)
        {
            *slot = T::from_fraction(v);
        }
    } else {
        let mut pos = done.saturating_mul(stride);
        for v in values {
            if let Some(slot) = out.get_mut(pos) {
                *slot = T::from_fraction(v);
            }
            pos = pos.saturating_add(stride);
        }
    }
}

/// The base-2 sequential fill, by runs of `L = RUN_TABLE = 2^8` indices: for `e < L`,
/// `rev(h L + e) = rev(h L) | rev(e)` (the bit reversal `rev` of 32 bits maps the low 8
/// bits to the top 8 and the rest below them), with `rev(e)` from a table built by
/// `rev(e) = rev(e >> 1) >> 1 | (e & 1) << 31`. One load and one OR a value, one reversal a
/// run. Stack: 1 KiB. (The general [`RunFill`] also serves base 2 — the blocked Halton fill
/// uses it to keep one resumable state kind — but with its threshold compare and add it
/// measured 1.4x slower than this for the column fill of 2D Halton.)
fn fill_base_2<T: FromFraction>(start: u32, out: &mut [T], stride: usize) {
    let mut rev = [0u32; RUN_TABLE];
    for e in 1..RUN_TABLE {
        rev[e] = rev[e >> 1] >> 1 | ((e as u32 & 1) << 31);
    }
    let mut run_index = start & !(RUN_TABLE as u32 - 1);
    let mut d0 = (start - run_index) as usize;
    let count = out.len().div_ceil(stride); // values due
    let mut done = 0; // values written
    loop {
        let base = reverse_bits(run_index);
        let n = (RUN_TABLE - d0).min(count - done);
        let run = rev.get(d0..d0 + n).unwrap_or(&[]);
        write_run(out, done, stride, run.iter().map(|&p| base | p));
        done += n;
        if done >= count {
            break;
        }
        // A value of the next run is still due, so its index fits in u32.
        run_index = run_index.wrapping_add(RUN_TABLE as u32);
        d0 = 0;
    }
}

/// Checks that indices `start .. start + count` all fit in `u32`.
pub(crate) const fn check_range(start: u32, count: u64) -> Result<()> {
    let end = start as u64 + count;
    if end > TWO_32 {
        return Err(Error::IndexOutOfRange {
            index: end - 1,
            len: TWO_32,
        });
    }
    Ok(())
}

/// `(a + b) mod 2^32` for exact values `q + r / big` with `r < big`.
#[inline]
const fn add_exact(a: (u32, u64), b: (u32, u64), big: u64) -> (u32, u64) {
    let (r, overflow) = a.1.overflowing_add(b.1);
    if overflow || r >= big {
        (a.0.wrapping_add(b.0).wrapping_add(1), r.wrapping_sub(big))
    } else {
        (a.0.wrapping_add(b.0), r)
    }
}

/// The inverse of an odd `x` modulo 2^64 by Newton's iteration: `x` is its own inverse
/// modulo 8, and each step doubles the number of correct low bits (3, 6, 12, 24, 48, 96).
const fn inverse_mod_2_64(x: u64) -> u64 {
    let mut y = x;
    let mut k = 0;
    while k < 5 {
        y = y.wrapping_mul(2u64.wrapping_sub(x.wrapping_mul(y)));
        k += 1;
    }
    y
}

/// State of the sequential radical inverse for a base other than 2: `phi_b(i) 2^32` as
/// `q + r / B`, the lowest digit of the index, and the cached steps.
#[derive(Clone, Debug)]
struct Sequential {
    /// Index of the value held.
    index: u32,
    /// The two lowest base-`b` digits of `index`, `(d_1, d_2)`.
    low: (u32, u32),
    /// Integer part of `phi_b(index) 2^32`.
    q: u32,
    /// Remainder of `phi_b(index) 2^32`, over `B`.
    r: u64,
    steps: [(u32, u64); STEPS],
}

impl Sequential {
    const fn new(ri: &RadicalInverse, start: u32) -> Self {
        let (q, r) = ri.scale(ri.numerator(start));
        Sequential {
            index: start,
            low: (
                rem_u32(start, ri.base),
                rem_u32(div_u32(start, ri.base), ri.base),
            ),
            q,
            r,
            steps: ri.steps(),
        }
    }

    /// Moves to the next index; the caller guarantees `index < u32::MAX`.
    #[inline(always)]
    fn advance(&mut self, ri: &RadicalInverse) {
        (self.index, self.low, self.q, self.r) =
            advance(ri, &self.steps, self.index, self.low, self.q, self.r);
    }
}

/// One sequential step on the state `(index, low, q, r)`, as a pure function so that a
/// loop can keep the state in registers.
#[inline(always)]
fn advance(
    ri: &RadicalInverse,
    steps: &[(u32, u64); STEPS],
    index: u32,
    low: (u32, u32),
    q: u32,
    r: u64,
) -> (u32, (u32, u32), u32, u64) {
    let index = index.wrapping_add(1);
    let (low, (dq, dr)) = if low.0 + 1 < ri.base {
        ((low.0 + 1, low.1), steps[0])
    } else if low.1 + 1 < ri.base {
        ((0, low.1 + 1), steps[1])
    } else {
        ((0, 0), carry(ri, steps, index))
    };
    let (r, overflow) = r.overflowing_add(dr);
    let wrap = overflow || r >= ri.big;
    let r = if wrap { r.wrapping_sub(ri.big) } else { r };
    (index, low, q.wrapping_add(dq).wrapping_add(wrap as u32), r)
}

/// The two lowest digits wrapped: the step for the `t >= 2` trailing zero digits of
/// `index` (probability `b^-2`).
#[cold]
#[inline(never)]
fn carry(ri: &RadicalInverse, steps: &[(u32, u64); STEPS], index: u32) -> (u32, u64) {
    let t = ri.trailing_zero_digits(index);
    if (t as usize) < STEPS {
        steps[t as usize]
    } else {
        ri.step(t)
    }
}

/// Sequential radical inverse: yields `phi_b(start)`, `phi_b(start + 1)`, ... (as 0.32
/// fractions) up to index `u32::MAX`, bit-identical to [`RadicalInverse::sample`].
///
/// Keeps `phi_b(i) 2^32` exactly as an integer part and a remainder over `B`, plus the
/// lowest digit of `i`; a step adds a cached increment.
///
/// ```
/// use qmckit::RadicalInverse;
/// let phi5 = RadicalInverse::new(5).unwrap();
/// assert!(phi5.iter_from(17).take(1000).zip(17..).all(|(x, i)| x == phi5.sample(i)));
/// ```
#[derive(Clone, Debug)]
pub struct RadicalInverseIter {
    ri: RadicalInverse,
    seq: Sequential,
    /// Values left to yield (2^32 - start at the beginning).
    left: u64,
}

impl RadicalInverseIter {
    const fn new(ri: RadicalInverse, start: u32) -> Self {
        let seq = if ri.base == 2 {
            Sequential {
                index: start,
                low: (0, 0),
                q: reverse_bits(start),
                r: 0,
                steps: [(0, 0); STEPS],
            }
        } else {
            Sequential::new(&ri, start)
        };
        RadicalInverseIter {
            ri,
            seq,
            left: TWO_32 - start as u64,
        }
    }
}

impl Iterator for RadicalInverseIter {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        if self.left == 0 {
            return None;
        }
        let value = self.seq.q;
        self.left -= 1;
        if self.left > 0 {
            if self.ri.base == 2 {
                self.seq.index += 1;
                self.seq.q = reverse_bits(self.seq.index);
            } else {
                self.seq.advance(&self.ri);
            }
        }
        Some(value)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = usize::try_from(self.left).unwrap_or(usize::MAX);
        (left, usize::try_from(self.left).ok())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Oracle: the textbook digit loop with exact `u128` rational arithmetic.
    fn oracle(base: u32, index: u32) -> u32 {
        let (mut n, mut rev, mut den) = (index as u128, 0u128, 1u128);
        while n > 0 {
            rev = rev * base as u128 + n % base as u128;
            den *= base as u128;
            n /= base as u128;
        }
        ((rev << 32) / den) as u32
    }

    #[test]
    fn exact_against_u128_oracle() {
        // Both random-access paths (nested floors up to b^c = 2^16, exact numerator above)
        // and their edges: b^c = 2^16 - 1, 2^16, 2^16 + 1.
        let edges = [
            97, 251, 255, 256, 257, 1000, 1625, 1626, 8161, 65_521, 65_535, 65_536,
        ];
        let big = [65_537, 100_003, 1 << 31, u32::MAX];
        for base in (2..=40).chain(edges).chain(big) {
            let ri = RadicalInverse::new(base).unwrap();
            let mut x = 0x9E37_79B9u32;
            // Indices around the digit-count changes b^k - 1, b^k.
            let mut powers = vec![];
            let mut p = base as u64;
            while p <= u32::MAX as u64 {
                powers.extend([p as u32 - 1, p as u32]);
                p *= base as u64;
            }
            for i in (0..2000).chain([u32::MAX - 1, u32::MAX]).chain(powers) {
                assert_eq!(ri.sample(i), oracle(base, i), "base {base} index {i}");
                x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
                assert_eq!(ri.sample(x), oracle(base, x), "base {base} index {x}");
            }
        }
    }

    /// The wide numerator for every Halton base (chunk counts 2 to 8, magics present or
    /// zero) and the serial one for the composites with more than 8 chunks: the indices
    /// around every power `b^j` (where a chunk quotient changes), the largest indices and
    /// random ones, against the oracle.
    #[test]
    fn long_indices_against_oracle_for_every_halton_base() {
        let halton = crate::halton::HALTON_BASES.iter().map(|ri| ri.base());
        let mut x = 0x2545_F491u32;
        for base in halton.chain([4, 6, 8, 9, 10, 12, 14, 15, 16]) {
            let ri = RadicalInverse::new(base).unwrap();
            let mut edges = vec![u32::MAX, u32::MAX - 1, 1 << 31];
            let mut p = base as u64;
            while p <= u32::MAX as u64 {
                edges.extend([p - 1, p, p + 1].map(|v| v.min(u32::MAX as u64) as u32));
                p *= base as u64;
            }
            for i in edges {
                assert_eq!(ri.sample(i), oracle(base, i), "base {base} index {i}");
            }
            for _ in 0..300 {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                assert_eq!(ri.sample(x), oracle(base, x), "base {base} index {x}");
            }
        }
    }

    /// The wide numerator's tabled form sums six chunks: no tabled base has more.
    #[cfg(target_pointer_width = "64")]
    #[test]
    fn tabled_bases_have_at_most_six_chunks() {
        for base in [3, 5, 7, 11, 13] {
            let ri = RadicalInverse::new(base).unwrap();
            assert!(
                ri.table != 0 && ri.weight[0] != 0 && ri.weight[6] == 0,
                "base {base}"
            );
        }
    }

    /// Every index through the end of the three-chunk (nested-floor) range and into the
    /// long path, for bases with chunks from 3 to 2^16.
    #[test]
    fn short_indices_exhaustive_against_oracle() {
        for base in [
            3, 5, 7, 11, 13, 17, 31, 37, 40, 41, 131, 251, 255, 256, 257, 4093, 65_521,
        ] {
            let ri = RadicalInverse::new(base).unwrap();
            let q = ri.chunk as u64;
            let end = (q * q * q + 5000).min(1 << 21) as u32;
            for i in 0..end {
                assert_eq!(ri.sample(i), oracle(base, i), "base {base} index {i}");
            }
        }
    }

    #[test]
    fn sequential_matches_random_access() {
        for base in [
            2,
            3,
            4,
            5,
            6,
            7,
            10,
            31,
            256,
            8161,
            65_536,
            1 << 31,
            u32::MAX,
        ] {
            let ri = RadicalInverse::new(base).unwrap();
            for start in [0, 1, base - 1, 12_345, u32::MAX - 3000] {
                let got: Vec<u32> = ri.iter_from(start).take(3000).collect();
                for (k, g) in got.iter().enumerate() {
                    assert_eq!(
                        *g,
                        ri.sample(start + k as u32),
                        "base {base} at {start}+{k}"
                    );
                }
            }
            assert_eq!(ri.iter_from(u32::MAX).count(), 1);
        }
    }

    #[test]
    fn fill_matches_random_access() {
        let bases = [
            2,
            3,
            4,
            5,
            6,
            7,
            11,
            13,
            31,
            127,
            128,
            129,
            1000,
            1 << 31,
            u32::MAX,
        ];
        for base in bases {
            let ri = RadicalInverse::new(base).unwrap();
            let starts = [
                0,
                1,
                base - 1,
                base,
                base.wrapping_mul(base).wrapping_sub(3),
                12_345,
            ];
            for start in starts.into_iter().chain([u32::MAX - 700, 3u32.pow(12) - 5]) {
                for stride in [1, 3] {
                    let mut out = vec![0u32; 2000];
                    let n = 2000usize.div_ceil(stride) as u32;
                    if (start as u64 + n as u64) > 1 << 32 {
                        assert!(ri.fill_strided(start, &mut out, stride).is_err());
                        continue;
                    }
                    ri.fill_strided(start, &mut out, stride).unwrap();
                    for (k, x) in out.iter().step_by(stride).enumerate() {
                        assert_eq!(*x, ri.sample(start + k as u32), "b {base} {start}+{k}");
                    }
                    // Slots between the strided ones are untouched.
                    assert!(
                        out.iter()
                            .skip(1)
                            .step_by(stride.max(2))
                            .all(|&x| stride == 1 || x == 0)
                    );
                }
            }
            // The last index of the range.
            let mut last = [7u32; 1];
            ri.fill(u32::MAX, &mut last).unwrap();
            assert_eq!(last[0], ri.sample(u32::MAX));
        }
    }

    /// The run fills (bases up to `RUN_TABLE`, base 2 by its own table) and the bases just
    /// above, against random access: starts at and around run boundaries (`L = b^k`, `L b`),
    /// long carries (`b^12`), and a range ending exactly at `u32::MAX`.
    #[test]
    fn run_fill_every_small_base_against_random_access() {
        for base in 2..=(RUN_TABLE as u32 + 3) {
            let ri = RadicalInverse::new(base).unwrap();
            let mut run = base;
            while run * base <= RUN_TABLE as u32 {
                run *= base;
            }
            let deep = (base as u64).pow(12.min(31 / (32 - base.leading_zeros())));
            let starts = [
                0,
                1,
                run - 1,
                run,
                run * base - 2,
                (deep - 3) as u32,
                u32::MAX - 999,
            ];
            for start in starts {
                for stride in [1, 5] {
                    let mut out = vec![0u32; 1000 * stride];
                    ri.fill_strided(start, &mut out, stride).unwrap();
                    for (k, &x) in out.iter().step_by(stride).enumerate() {
                        assert_eq!(x, ri.sample(start + k as u32), "b {base} {start}+{k}");
                    }
                }
            }
            let mut over = [0u32; 1001];
            assert!(ri.fill(u32::MAX - 999, &mut over).is_err());
        }
    }

    #[test]
    fn long_carries_past_the_cached_steps() {
        // 3^12 - 1 -> 3^12 carries through 12 digits (> STEPS).
        let ri = RadicalInverse::new(3).unwrap();
        let start = 3u32.pow(12) - 5;
        assert!(
            ri.iter_from(start)
                .take(10)
                .zip(start..)
                .all(|(x, i)| x == ri.sample(i))
        );
    }

    #[test]
    fn inverse_round_trips() {
        for base in [2, 3, 5, 7, 16, 31, 65_536] {
            let ri = RadicalInverse::new(base).unwrap();
            let max = ri.inverse(0, 99).unwrap_err();
            let Error::TooManyDigits { max, .. } = max else {
                panic!()
            };
            assert!((base as u64).pow(max) <= 1 << 32);
            assert!((base as u64).pow(max + 1) > 1 << 32);
            for digits in 0..=max {
                let n = (base as u64).pow(digits).min(5000);
                for i in 0..n as u32 {
                    assert_eq!(
                        ri.inverse(ri.sample(i), digits),
                        Ok(i),
                        "b {base} d {digits}"
                    );
                }
            }
        }
    }

    #[test]
    fn rejects_small_bases() {
        assert_eq!(RadicalInverse::new(0), Err(Error::BaseTooSmall { base: 0 }));
        assert_eq!(RadicalInverse::new(1), Err(Error::BaseTooSmall { base: 1 }));
    }
}
