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
//! Let `K` be the smallest digit count with `B = b^K >= 2^32`; every `u32` index has at most
//! `K` digits and `phi_b(i) = N / B` with the integer `N = sum_j d_j b^(K-j) < B < 2^64`.
//! Random access ([`RadicalInverse::sample`]) builds `N` digit by digit, dividing the index
//! by `b` with a precomputed multiply-high (Lemire, Kaser & Kurz 2019, "Faster remainder by
//! direct computation") and stepping the digit weight down by multiplying with the inverse
//! of `b` modulo 2^64 (an exact division), then rounds `N * 2^32 / B` down with a
//! precomputed reciprocal and one correction step (Granlund & Montgomery 1994). Cost: about
//! `log_b(i)` iterations of three multiplications, plus three for the final scaling; base 2
//! is a single bit reversal.
//!
//! Sequential access ([`RadicalInverse::iter_from`], [`RadicalInverse::fill`]) keeps
//! `phi_b(i) * 2^32` as an integer part and an exact remainder over `B` and adds a
//! precomputed step: when `i + 1` ends in `t` zero digits, `phi_b` changes by
//! `b^(-t) + b^(-t-1) - 1`, which is `b^(-1)` in the common case `t = 0`. That is one add,
//! one compare and a conditional subtract per value. Both paths return the same bits (tested).

use crate::bits::reverse_bits;
use crate::error::{Error, Result};

/// 2^32 as `u64`.
const TWO_32: u64 = 1 << 32;

/// Number of carry steps cached by [`RadicalInverseIter`]; longer carries (probability
/// `b^-STEPS`) are computed on the spot.
const STEPS: usize = 8;

/// A validated base with its precomputed constants: the radical inverse `phi_b` as a cheap,
/// infallible, `const`-callable function of the index.
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
    /// `K`: digits of the largest `u32` index, the smallest `K` with `b^K >= 2^32`.
    digits: u32,
    /// Trailing zero bits of `base` (its power-of-two factor).
    shift: u32,
    /// `ceil(2^64 / base)`: `n / base == mulhi(n, magic)` for every `u32` `n`.
    magic: u64,
    /// Inverse of the odd part of `base` modulo 2^64 (exact division by multiplication).
    inv: u64,
    /// `B = base^K`, the common denominator of all outputs.
    big: u64,
    /// `floor((2^96 - 1) / B)`: reciprocal for rounding `N * 2^32 / B` down.
    recip: u64,
}

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
        let b = base as u64;
        let mut big = 1u64;
        let mut digits = 0u32;
        while big < TWO_32 {
            big *= b; // < 2^32 * 2^32: no overflow
            digits += 1;
        }
        let shift = base.trailing_zeros();
        Ok(RadicalInverse {
            base,
            digits,
            shift,
            magic: u64::MAX / b + 1,
            inv: inverse_mod_2_64((base >> shift) as u64),
            big,
            recip: ((u128::MAX >> 32) / big as u128) as u64,
        })
    }

    /// The base `b`.
    #[inline]
    pub const fn base(&self) -> u32 {
        self.base
    }

    /// `K`, the number of base-`b` digits of the largest `u32` index (`b^K >= 2^32`).
    #[inline]
    pub const fn digits(&self) -> u32 {
        self.digits
    }

    /// `floor(phi_b(index) * 2^32)`, exact. Defined for every `u32` index.
    ///
    /// Cost: `ceil(log_b(index + 1))` digit steps of ~3 multiplications each plus a fixed
    /// ~3 for the final scaling; base 2 is one bit reversal.
    #[inline]
    pub const fn sample(&self, index: u32) -> u32 {
        if self.base == 2 {
            return reverse_bits(index);
        }
        self.scale(self.numerator(index)).0
    }

    /// `N` with `phi_b(index) = N / B`: the digits of `index` reversed into `K` places.
    #[inline]
    const fn numerator(&self, index: u32) -> u64 {
        let mut n = index;
        let mut weight = self.div_exact(self.big); // b^(K-1)
        let mut acc = 0u64;
        while n != 0 {
            let q = self.div(n);
            let digit = n - q * self.base;
            acc += digit as u64 * weight; // sum < B: no overflow
            weight = self.div_exact(weight);
            n = q;
        }
        acc
    }

    /// `n / base` for any `u32` `n`, by multiply-high.
    #[inline]
    const fn div(&self, n: u32) -> u32 {
        ((self.magic as u128 * n as u128) >> 64) as u32
    }

    /// `w / base` for `w` a multiple of `base` (exact division by the modular inverse).
    /// Wraps harmlessly when `w` is not a multiple (the last weight of a loop is unused).
    #[inline]
    const fn div_exact(&self, w: u64) -> u64 {
        (w >> self.shift).wrapping_mul(self.inv)
    }

    /// `(q, r)` with `n * 2^32 = q * B + r`, `0 <= r < B`, for `n < B` (so `q < 2^32`).
    #[inline]
    const fn scale(&self, n: u64) -> (u32, u64) {
        // q0 <= q and q0 > n 2^32 / B - 1, so q is q0 or q0 + 1.
        let q0 = ((n as u128 * self.recip as u128) >> 64) as u64;
        let r0 = ((n as u128) << 32) - q0 as u128 * self.big as u128;
        if r0 >= self.big as u128 {
            ((q0 + 1) as u32, (r0 - self.big as u128) as u64)
        } else {
            (q0 as u32, r0 as u64)
        }
    }

    /// `2^32 b^-j` modulo 2^32 as `(q, r)` over `B`, for `1 <= j <= K`.
    const fn power(&self, j: u32) -> (u32, u64) {
        let mut w = self.big;
        let mut k = 0;
        while k < j {
            w = self.div_exact(w);
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
        let max = if self.big == TWO_32 {
            self.digits
        } else {
            self.digits - 1
        };
        if digits > max {
            return Err(Error::TooManyDigits { digits, max });
        }
        let b = self.base as u64;
        let mut bk = 1u64;
        let mut k = 0;
        while k < digits {
            bk *= b;
            k += 1;
        }
        // value = floor(a 2^32 / b^k) for the reversed-digit integer a, so
        // a = ceil(value b^k / 2^32); value * b^k + 2^32 - 1 < 2^64.
        let mut a = ((value as u64 * bk + (TWO_32 - 1)) >> 32) % bk;
        let mut index = 0u64;
        k = 0;
        while k < digits {
            index = index * b + a % b;
            a /= b;
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
    /// # Errors
    /// [`Error::IndexOutOfRange`] if the indices pass 2^32; [`Error::BufferLength`] for a
    /// zero stride.
    pub fn fill_strided(&self, start: u32, out: &mut [u32], stride: usize) -> Result<()> {
        if stride == 0 {
            return Err(Error::BufferLength {
                expected: 1,
                got: 0,
            });
        }
        let count = out.len().div_ceil(stride) as u64;
        check_range(start, count)?;
        if self.base == 2 {
            for (k, slot) in out.iter_mut().step_by(stride).enumerate() {
                *slot = reverse_bits(start.wrapping_add(k as u32));
            }
            return Ok(());
        }
        let mut it = self.iter_from(start);
        for slot in out.iter_mut().step_by(stride) {
            *slot = it.value();
            it.advance();
        }
        Ok(())
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

/// Sequential radical inverse: yields `phi_b(start)`, `phi_b(start + 1)`, ... (as 0.32
/// fractions) up to index `u32::MAX`, bit-identical to [`RadicalInverse::sample`].
///
/// Keeps `phi_b(i) 2^32` exactly as an integer part and a remainder over `B`, plus the
/// lowest digit of `i`; a step adds a cached increment. 128 bytes of cached steps.
///
/// ```
/// use qmckit::RadicalInverse;
/// let phi5 = RadicalInverse::new(5).unwrap();
/// assert!(phi5.iter_from(17).take(1000).zip(17..).all(|(x, i)| x == phi5.sample(i)));
/// ```
#[derive(Clone, Debug)]
pub struct RadicalInverseIter {
    ri: RadicalInverse,
    /// Index of the value held (2^32 once exhausted).
    index: u64,
    /// Lowest base-`b` digit of `index`.
    low: u32,
    /// Integer part of `phi_b(index) 2^32`.
    q: u32,
    /// Remainder of `phi_b(index) 2^32`, over `B`.
    r: u64,
    steps: [(u32, u64); STEPS],
}

impl RadicalInverseIter {
    const fn new(ri: RadicalInverse, start: u32) -> Self {
        let (q, r) = if ri.base == 2 {
            (reverse_bits(start), 0)
        } else {
            ri.scale(ri.numerator(start))
        };
        let mut steps = [(0u32, 0u64); STEPS];
        if ri.base != 2 {
            let mut t = 0;
            while t < STEPS {
                if (t as u32) < ri.digits {
                    steps[t] = ri.step(t as u32);
                }
                t += 1;
            }
        }
        RadicalInverseIter {
            ri,
            index: start as u64,
            low: start % ri.base,
            q,
            r,
            steps,
        }
    }

    /// The value at the current index.
    #[inline]
    const fn value(&self) -> u32 {
        self.q
    }

    /// Moves to the next index (no-op past `u32::MAX`).
    #[inline]
    fn advance(&mut self) {
        self.index += 1;
        if self.index >= TWO_32 {
            self.index = TWO_32;
            return;
        }
        let ri = &self.ri;
        if ri.base == 2 {
            self.q = reverse_bits(self.index as u32);
            return;
        }
        let t = if self.low + 1 < ri.base {
            self.low += 1;
            0
        } else {
            self.low = 0;
            // i + 1 ends in t >= 1 zero digits: count them.
            let mut m = ri.div(self.index as u32);
            let mut t = 1u32;
            loop {
                let q = ri.div(m);
                if q * ri.base != m {
                    break;
                }
                m = q;
                t += 1;
            }
            t
        };
        let step = if (t as usize) < STEPS {
            self.steps[t as usize]
        } else {
            ri.step(t)
        };
        (self.q, self.r) = add_exact((self.q, self.r), step, ri.big);
    }
}

impl Iterator for RadicalInverseIter {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        if self.index >= TWO_32 {
            return None;
        }
        let v = self.q;
        self.advance();
        Some(v)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = (TWO_32 - self.index) as usize;
        (left, Some(left))
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
        for base in (2..=40).chain([97, 251, 256, 1000, 65_521, 65_536, 1 << 31, u32::MAX]) {
            let ri = RadicalInverse::new(base).unwrap();
            let mut x = 0x9E37_79B9u32;
            for i in (0..2000).chain([u32::MAX - 1, u32::MAX]) {
                assert_eq!(ri.sample(i), oracle(base, i), "base {base} index {i}");
                x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
                assert_eq!(ri.sample(x), oracle(base, x), "base {base} index {x}");
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
