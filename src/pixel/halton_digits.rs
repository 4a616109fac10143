//! The digit permutations a [`super::HaltonSampler`] with `PermuteDigits` carries for its
//! first dimensions: pbrt's `ComputeRadicalInversePermutations` for dimensions
//! `2 .. 2 + CARRIED_DIMS`, computed once by the constructor (as pbrt's constructor computes
//! all of them), so that neither a draw nor a prepared fill of those dimensions hashes or
//! walks a permutation. Also the prepared fills' per-dimension [`Plan`] and digit tables.

use super::halton::{digit_hash, finish, permute_digit_count};
use super::prepared::permutation_round16;
use crate::hash::pbrt::permutation_element;
use crate::radical_inverse::halton::PRIMES;

/// The first dimension carried (the first the dimension counter hands out).
pub(super) const FIRST_CARRIED: usize = 2;

/// Dimensions carried: `2 ..= 9`, bases 5 to 29 (a sample's first four 2D draws).
pub(super) const CARRIED_DIMS: usize = 8;

/// Where dimension `FIRST_CARRIED + c`'s rows start: dimension `d` (base `b`, `n` digits)
/// has `n` rows of `b` bytes, row `k` digit `k`'s images of `0 .. b`.
const OFFSETS: [usize; CARRIED_DIMS + 1] = offsets();

/// The bytes of all carried rows (966).
const CARRIED_BYTES: usize = OFFSETS[CARRIED_DIMS];

/// The carried dimensions' [`Plan`]s (pbrt's digit count, `fl(b^-n)`, `b^n`, `1 / b`),
/// computed by the compiler (the same IEEE `f32` arithmetic as at run time; a test
/// compares them with [`Plan::new`]).
const PLANS: [Plan; CARRIED_DIMS] = plans();

const fn offsets() -> [usize; CARRIED_DIMS + 1] {
    let mut o = [0usize; CARRIED_DIMS + 1];
    let mut c = 0;
    while c < CARRIED_DIMS {
        let b = PRIMES[FIRST_CARRIED + c] as u64;
        o[c + 1] = o[c] + permute_digit_count(b) * b as usize;
        c += 1;
    }
    o
}

const fn plans() -> [Plan; CARRIED_DIMS] {
    let mut p = [Plan::EMPTY; CARRIED_DIMS];
    let mut c = 0;
    while c < CARRIED_DIMS {
        if let Some(plan) = Plan::new(PRIMES[FIRST_CARRIED + c] as u64) {
            p[c] = plan;
        }
        c += 1;
    }
    p
}

/// The carried permutations (all zero, and unused, for the other randomizations).
#[derive(Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub(super) struct CarriedDigits([u8; CARRIED_BYTES]);

impl core::fmt::Debug for CarriedDigits {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "CarriedDigits({} bytes)", CARRIED_BYTES)
    }
}

impl CarriedDigits {
    /// No tables (for `None` and `Owen`).
    pub(super) const EMPTY: CarriedDigits = CarriedDigits([0; CARRIED_BYTES]);

    /// pbrt's permutations of seed `seed`: row `k` of base `b` holds
    /// `PermutationElement(v, b, Hash(b, k, seed))` for `v < b`. About 1,000
    /// permutation elements (the bases are below 256: a byte an entry).
    pub(super) const fn new(seed: u64) -> CarriedDigits {
        let mut t = [0u8; CARRIED_BYTES];
        let mut c = 0;
        while c < CARRIED_DIMS {
            let b = PRIMES[FIRST_CARRIED + c] as u32;
            let mut at = OFFSETS[c];
            let mut k = 0u32;
            while at < OFFSETS[c + 1] {
                let p = digit_hash(b, k, seed) as u32;
                let mut v = 0;
                while v < b {
                    t[at] = permutation_element(v, b, p) as u8;
                    at += 1;
                    v += 1;
                }
                k += 1;
            }
            c += 1;
        }
        CarriedDigits(t)
    }

    /// Dimension `dim`'s rows and plan, if it is carried.
    #[inline]
    pub(super) fn rows(&self, dim: usize) -> Option<(&[u8], &'static Plan)> {
        let c = dim.checked_sub(FIRST_CARRIED)?;
        let plan = PLANS.get(c)?;
        let rows = self.0.get(*OFFSETS.get(c)?..*OFFSETS.get(c + 1)?)?;
        Some((rows, plan))
    }

    /// Dimension `dim`'s rows as the prepared digits of the indices up to `h_max`, if it
    /// is carried.
    #[inline]
    pub(super) fn table(&self, dim: usize, h_max: u64) -> Option<Digits<'_, &[u8]>> {
        let (table, plan) = self.rows(dim)?;
        let (full, scale, tail) = zero_digits(plan, &table, h_max);
        Some(Digits {
            plan,
            table,
            full,
            scale,
            tail,
        })
    }
}

/// Entries of a prepared `PermuteDigits` fill's digit-permutation table (`base` entries
/// per digit); a dimension whose table would not fit permutes as the handle does.
pub(super) const TABLE_ENTRIES: usize = 512;

/// `floor(2^64 / b) + 1`: `(a M) >> 64` is `a / b` for every `a < 2^32` and `2 <= b <
/// 2^32` (the error `a (M - 2^64 / b) / 2^64 < 2^-32` stays below `1 / b`).
pub(super) const fn reciprocal(b: u64) -> u128 {
    (u64::MAX / b) as u128 + 1
}

/// The per-dimension constants of a prepared `PermuteDigits` value: pbrt's digit count
/// (`ScrambledRadicalInverse`'s loop, [`permute_digit_count`]), its `f32` scale
/// `fl(b^-n)` (the product of `n` factors `fl(1 / b)`), `b^n` and the reciprocal of `b`
/// (`floor(2^64 / b) + 1`, [`reciprocal`], which fits 64 bits for `b >= 2`).
#[derive(Clone, Copy)]
pub(super) struct Plan {
    pub(super) base: u64,
    pub(super) recip: u64,
    pub(super) digits: u32,
    pub(super) inv_m: f32,
    pub(super) power: u128,
}

/// A dimension's prepared `PermuteDigits` digits for the indices up to some `h_max`
/// ([`digit_table`], or the rows the sampler carries): the plan, the
/// permutation table (`table[k b + v]` is digit `k`'s image of `v`), the number `full` of
/// digits that can be nonzero, and the zero digits' images above them as `reversed * scale
/// + tail`.
pub(super) struct Digits<'a, T> {
    plan: &'a Plan,
    table: T,
    full: u32,
    scale: u64,
    tail: u64,
}

/// A digit table's entry `at` (`k b + v`, in range for `k` below the digit count).
pub(super) trait DigitRows {
    fn entry(&self, at: usize) -> u64;
}

impl DigitRows for &[u16; TABLE_ENTRIES] {
    #[inline(always)]
    fn entry(&self, at: usize) -> u64 {
        self[at % TABLE_ENTRIES] as u64
    }
}

impl DigitRows for &[u8] {
    #[inline(always)]
    fn entry(&self, at: usize) -> u64 {
        self.get(at).copied().unwrap_or(0) as u64
    }
}

impl Plan {
    /// A placeholder (base 0), never read.
    pub(super) const EMPTY: Plan = Plan {
        base: 0,
        recip: 0,
        digits: 0,
        inv_m: 0.0,
        power: 1,
    };

    /// The plan of base `base >= 2`, or `None` when the reversed digits could reach the
    /// overflow guard of [`digits_by`] (never for the primes of the sampler's dimensions).
    pub(super) const fn new(base: u64) -> Option<Plan> {
        let inv_base = 1.0f32 / base as f32;
        let digits = permute_digit_count(base) as u32;
        let (mut inv_m, mut power) = (1.0f32, 1u128);
        let mut k = 0;
        while k < digits {
            inv_m *= inv_base;
            power *= base as u128;
            k += 1;
        }
        // The reversed digits stay below power: digits_by's guard `reversed >= limit`
        // never fires while power <= limit, so the loops agree digit for digit.
        let limit = (u64::MAX / base - base) as u128;
        if power <= limit {
            Some(Plan {
                base,
                recip: reciprocal(base) as u64,
                digits,
                inv_m,
                power,
            })
        } else {
            None
        }
    }
}

/// `Digits::full`, `scale` and `tail` of a table of `plan.digits` rows for the indices up
/// to `h_max`: digit `k` of every such index is 0 once `b^k > h_max`, so those rows enter
/// as the constant `tail` (their images of 0, exact integers: the reversed value stays
/// below `b^n`) under `scale`.
#[inline]
fn zero_digits<T: DigitRows>(plan: &Plan, table: &T, h_max: u64) -> (u32, u64, u64) {
    let (base, digits) = (plan.base, plan.digits);
    let (mut full, mut power) = (0u32, 1u64);
    while full < digits && power <= h_max {
        power = power.saturating_mul(base);
        full += 1;
    }
    let (mut tail, mut scale) = (0u64, 1u64);
    for k in full..digits {
        tail = tail * base + table.entry((k as u64 * base) as usize);
        scale *= base;
    }
    (full, scale, tail)
}

/// `PermuteDigits`' digit permutations of dimension `dim` for the first digits, as a
/// table written into `table` (`table[k base + v]` is digit `k`'s image of `v`), or
/// `None` when they do not fit [`TABLE_ENTRIES`]; for the digits of indices up to `h_max`
/// (a row whose digit is 0 in all of them holds only its image of 0). Per digit, the
/// mixer round of `PermutationElement` is computed once for each of `[0, w]` (`w + 1`
/// the power of two `>= base`, in 16-bit lanes: [`permutation_round16`]), then each `v
/// < base` walks that table until it lands below `base`, and `(i + p) mod base` is a
/// reciprocal multiplication: the elements of `permutation_element(v, base, p)` for
/// every `v`, without its `w + 1` divisions. The carried dimensions
/// ([`CarriedDigits`]) skip all of it.
pub(super) fn digit_table<'t>(
    seed: u64,
    dim: usize,
    h_max: u64,
    plan: &'t Plan,
    table: &'t mut [u16; TABLE_ENTRIES],
) -> Option<Digits<'t, &'t [u16; TABLE_ENTRIES]>> {
    let base = PRIMES[dim] as usize;
    let digits = plan.digits as usize;
    if base * digits > TABLE_ENTRIES {
        return None;
    }
    let (mut full, mut power) = (0usize, 1u64);
    while full < digits && power <= h_max {
        power = power.saturating_mul(base as u64);
        full += 1;
    }
    // base <= TABLE_ENTRIES: w < 2 TABLE_ENTRIES <= 2^16.
    let w = ((base as u32).next_power_of_two() - 1) as u16;
    let m = plan.recip;
    let mut round = [0u16; 2 * TABLE_ENTRIES];
    for (k, row) in table.chunks_exact_mut(base).take(digits).enumerate() {
        let p = digit_hash(base as u32, k as u32, seed) as u32;
        let round = &mut round[..=w as usize];
        for (i, r) in (0u16..).zip(round.iter_mut()) {
            *r = permutation_round16(i, w, p);
        }
        let row = if k < full { row } else { &mut row[..1] };
        for (v, t) in row.iter_mut().enumerate() {
            // A walk on the cycle through v: at most w + 1 steps.
            let mut i = round.get(v).copied().unwrap_or(0);
            for _ in 0..w {
                if (i as usize) < base {
                    break;
                }
                i = round.get(i as usize).copied().unwrap_or(0);
            }
            let a = (i as u32).wrapping_add(p) as u64;
            let q = ((a as u128 * m as u128) >> 64) as u64;
            *t = (a - q * base as u64) as u16;
        }
    }
    let table = &*table;
    let (full, scale, tail) = zero_digits(plan, &table, h_max);
    Some(Digits {
        plan,
        table,
        full,
        scale,
        tail,
    })
}

/// Dimension `base` of Halton index `h <= h_max < 2^32` under `PermuteDigits` from its
/// prepared [`Digits`]: the digits that vary by reciprocal multiplication (one 64-bit
/// multiply-high) and a table read each, then the constant images of the zero digits
/// above them in one multiply-add, and the plan's `f32` scale (no `f32` work in the
/// loop).
#[inline]
pub(super) fn permuted_small<T: DigitRows>(h: u64, t: &Digits<'_, T>) -> (u32, f32) {
    let (base, m) = (t.plan.base, t.plan.recip);
    let (mut a, mut reversed) = (h, 0u64);
    for k in 0..t.full {
        let next = ((a as u128 * m as u128) >> 64) as u64;
        let digit = a - next * base;
        reversed = reversed * base + t.table.entry((k as u64 * base + digit) as usize);
        a = next;
    }
    finish(reversed * t.scale + t.tail, t.plan.power, t.plan.inv_m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The compiler's plans and offsets equal the run-time computation, and every row is a
    /// permutation equal to `permutation_element` of pbrt's digit hash.
    #[test]
    fn carried_rows_are_pbrts_permutations() {
        assert_eq!(CARRIED_BYTES, 966);
        for seed in [0u64, 7, 1 << 40] {
            let t = CarriedDigits::new(seed);
            for c in 0..CARRIED_DIMS {
                let d = FIRST_CARRIED + c;
                let b = PRIMES[d] as u32;
                let (rows, plan) = t.rows(d).unwrap();
                let want = Plan::new(b as u64).unwrap();
                assert_eq!(plan.digits as usize, permute_digit_count(b as u64));
                assert_eq!(plan.inv_m.to_bits(), want.inv_m.to_bits());
                assert_eq!((plan.power, plan.recip), (want.power, want.recip));
                assert_eq!(rows.len(), plan.digits as usize * b as usize);
                for (k, row) in rows.chunks_exact(b as usize).enumerate() {
                    let p = digit_hash(b, k as u32, seed) as u32;
                    let mut seen = vec![false; b as usize];
                    for (v, &e) in row.iter().enumerate() {
                        assert_eq!(e as u32, permutation_element(v as u32, b, p));
                        seen[e as usize] = true;
                    }
                    assert!(seen.iter().all(|&s| s), "row {k} of base {b}");
                }
            }
            assert!(t.rows(1).is_none() && t.rows(FIRST_CARRIED + CARRIED_DIMS).is_none());
        }
    }
}
