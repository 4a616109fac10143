//! Constants of the random-access paths: magics for division by powers of the chunk, the
//! flat formulas' coefficients and the digit-reversal tables, all computed in `const fn`.

#[cfg(target_pointer_width = "64")]
use super::*;

/// Most chunks the wide numerator handles (every prime base: at most 8 chunks, for 17, 19
/// and 23; the composite bases 4 to 15 without a reversal table have more and take the
/// serial numerator).
#[cfg(target_pointer_width = "64")]
pub(super) const WIDE: usize = 8;

/// [`RadicalInverse::power_magic`] for chunk `q` and `m` chunks.
#[cfg(target_pointer_width = "64")]
pub(super) const fn power_magics(q: u64, m: u32) -> [u64; 3] {
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
pub(super) const fn wide_weights(q: u64, m: u32) -> [u32; WIDE] {
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
pub(super) const FLAT3_MAX: u64 = 40;
#[cfg(target_pointer_width = "64")]
pub(super) const FLAT2_MAX: u64 = 256;

/// [`RadicalInverse::flat`] for the reversal table id and chunk `q`: bases without a table
/// (`c = 1`) up to [`FLAT3_MAX`]: `(q^2, q^3 - q, q^2 - 1)` up to index `q^3 - 1`; up to
/// [`FLAT2_MAX`]: `(0, 0, 0)` (the two-digit path needs no coefficients; `A'' = 0` selects
/// it) up to `q^2 - 1` (all below 2^16); else zeros.
#[cfg(target_pointer_width = "64")]
pub(super) const fn flat_coefficients(table: u8, q: u64) -> [u16; 4] {
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
pub(super) const fn mul_hi(m: u64, x: u32) -> u32 {
    ((m as u128 * x as u128) >> 64) as u32
}

/// `floor(m x / 2^64)` as a `u32` (the caller knows it fits).
#[cfg(target_pointer_width = "64")]
#[inline(always)]
pub(super) const fn mul_hi_64(m: u64, x: u64) -> u32 {
    ((m as u128 * x as u128) >> 64) as u32
}

/// `rev(lo - q hi) w`: chunk `lo - q hi` of the wide numerator, reversed and weighted.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
pub(super) const fn rev_weighted(table: &[u8], q: u32, hi: u32, lo: u32, w: u32) -> u64 {
    reverse_in(table, lo.wrapping_sub(hi.wrapping_mul(q))) as u64 * w as u64
}

/// Digit-reversal tables for the small prime bases: entry `r` is the `c`-digit reversal of
/// `r < b^c`, with `b^c <= 256` so entries fit a byte. They let random access consume `c`
/// digits per step (5 for base 3). 707 bytes in all.
pub(super) static REVERSAL: [&[u8]; 6] = [
    &[],
    &reversal_table::<243>(3),
    &reversal_table::<125>(5),
    &reversal_table::<49>(7),
    &reversal_table::<121>(11),
    &reversal_table::<169>(13),
];

/// `table[r]`, or `r` itself past the table's end (an empty table: `c = 1`, no reversal).
#[inline(always)]
pub(super) const fn reverse_in(table: &[u8], r: u32) -> u32 {
    if (r as usize) < table.len() {
        table[r as usize] as u32
    } else {
        r
    }
}

/// `[rev_c(r) for r < N]` for `N = b^c`.
pub(super) const fn reversal_table<const N: usize>(base: u32) -> [u8; N] {
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
pub(super) const fn reversal_for(base: u32) -> (u8, u32) {
    match base {
        3 => (1, 5),
        5 => (2, 3),
        7 => (3, 2),
        11 => (4, 2),
        13 => (5, 2),
        _ => (0, 1),
    }
}

/// `(a + b) mod 2^32` for exact values `q + r / big` with `r < big`.
#[inline]
pub(super) const fn add_exact(a: (u32, u64), b: (u32, u64), big: u64) -> (u32, u64) {
    let (r, overflow) = a.1.overflowing_add(b.1);
    if overflow || r >= big {
        (a.0.wrapping_add(b.0).wrapping_add(1), r.wrapping_sub(big))
    } else {
        (a.0.wrapping_add(b.0), r)
    }
}

/// The inverse of an odd `x` modulo 2^64 by Newton's iteration: `x` is its own inverse
/// modulo 8, and each step doubles the number of correct low bits (3, 6, 12, 24, 48, 96).
pub(super) const fn inverse_mod_2_64(x: u64) -> u64 {
    let mut y = x;
    let mut k = 0;
    while k < 5 {
        y = y.wrapping_mul(2u64.wrapping_sub(x.wrapping_mul(y)));
        k += 1;
    }
    y
}
