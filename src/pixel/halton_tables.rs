//! [`PreparedHalton`]: a [`HaltonSampler`] with its randomized radical inverses tabulated
//! once for the image (`std`), as pbrt-v4's `HaltonSampler` computes its digit
//! permutations once in its constructor.

use super::halton::{digit_hash, owen_key, permute_digit_count};
use super::halton_digits::reciprocal;
use super::{
    F32_ONE_MINUS_EPSILON, HALTON_PIXEL_DIMS, HaltonSampler, PixelGrid, PixelPoint, PixelSampler,
    Randomization,
};
use crate::error::{Error, Result};
use crate::hash::pbrt::{mix_bits, permutation_element};
use crate::radical_inverse::halton::PRIMES;
use std::vec::Vec;

/// The most entries a digit-group table holds: `b^c <= 4096` for a group of `c` digits.
const GROUP_ENTRIES: u64 = 4096;

/// The most digit groups a dimension has (`PermuteDigits` takes at most 12 digits in base
/// 5, 6 in base 67, fewer above, so a group of at least one digit fits).
const MAX_GROUPS: usize = 8;

/// `c` digits of base `b` read at once: `a mod b^c` indexes `entries[offset ..]`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Group {
    /// `b^c`.
    size: u64,
    /// `floor(2^64 / b^c) + 1`: `a / b^c = (a recip) >> 64` for `a < 2^32`.
    recip: u64,
    /// Where the group's `b^c` entries start.
    offset: usize,
}

impl Group {
    /// `(a / size, a mod size)`, by the reciprocal when `SMALL` (`a < 2^32`).
    #[inline(always)]
    fn split<const SMALL: bool>(&self, a: u64) -> (u64, usize) {
        let q = if SMALL {
            ((a as u128 * self.recip as u128) >> 64) as u64
        } else {
            a / self.size
        };
        (q, (a - q * self.size) as usize)
    }
}

/// One dimension's tables.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Dim {
    /// The prime `b`.
    base: u64,
    /// `n`, the digits pbrt takes.
    digits: usize,
    /// `b^n`.
    power: u64,
    /// pbrt's `fl(b^-n)`.
    inv_m: f32,
    /// `PermuteDigits`: groups covering the `n` digits, lowest first. `Owen`: one group, the
    /// first digits; the rest digit by digit.
    groups: [Group; MAX_GROUPS],
    /// Groups in use; 0 when the dimension is not tabulated.
    count: usize,
    /// Digits the groups cover.
    covered: usize,
    /// `Owen`: the dimension's key.
    key: u32,
}

impl Dim {
    /// The 0.32 truncation of `R / b^n`.
    #[inline(always)]
    fn exact(&self, reversed: u64) -> u32 {
        // R < b^n: the quotient is below 2^32.
        if self.power <= 1 << 32 {
            ((reversed << 32) / self.power) as u32
        } else {
            (((reversed as u128) << 32) / self.power as u128) as u32
        }
    }

    /// pbrt's float, `min(float(R) fl(b^-n), 1 - 2^-24)` (`R < 2^63`, so the signed
    /// conversion is the unsigned one).
    #[inline(always)]
    fn float(&self, reversed: u64) -> f32 {
        let f = (reversed as i64) as f32 * self.inv_m;
        if f < F32_ONE_MINUS_EPSILON {
            f
        } else {
            F32_ONE_MINUS_EPSILON
        }
    }
}

/// A [`HaltonSampler`] with owned tables (`std`): the same values, bit for bit, from
/// tables built once.
///
/// For dimension `d` in base `b` (`2 <= d <` the `dims` given), pbrt's randomized radical
/// inverse `R = sum_k pi_k(a_k) b^(n-1-k)` of the `n` digits `a_k` it takes is split into
/// groups of `c` digits (`b^c <= 4096`): a group's digits form one base-`b^c` digit `v`,
/// and its table holds `sum_t pi_(s+t)(v_t) b^(c-1-t)`, so that `R` is a Horner sum over the
/// groups, `R = (T_0(v_0) b^(c_1) + T_1(v_1)) b^(c_2) + ...`:
///
/// * [`Randomization::PermuteDigits`]: every digit is grouped; a value costs one
///   multiply-high (the quotient by `b^c`), one table read and one multiply-add per group
///   (3 groups in base 5, 12 digits) instead of a 64-bit division, a hash and a permutation
///   per digit.
/// * [`Randomization::Owen`]: digit `k`'s permutation depends on the digits below it, so
///   only the first group is tabulated (the scrambled prefix of the first `c` digits); the
///   others go digit by digit as in [`HaltonSampler`].
/// * [`Randomization::None`] is not tabulated.
///
/// Dimensions from `dims` on, and fills whose Halton indices pass `2^32` for
/// `PermuteDigits`' and `Owen`'s quotients by reciprocal, are computed as the
/// [`HaltonSampler`] computes them. Memory: for each dimension, `sum_groups b^c` `u16`
/// entries (12 KiB in base 5, `n b` entries above base 64, 47 KiB in base 7919; for
/// `PermuteDigits` dimensions `2 .. 64` take 0.25 MiB, all 1000 take 25 MiB, as pbrt's
/// digit permutations do); building costs one permutation per entry digit.
///
/// ```
/// use qmckit::pixel::{HaltonSampler, PixelSampler, PreparedHalton, Randomization};
/// let h = HaltonSampler::new(64, 64, 16, Randomization::PermuteDigits, 7)?;
/// let p = PreparedHalton::new(h, 32)?;
/// let (mut a, mut b) = ([[0f32; 2]; 16], [[0f32; 2]; 16]);
/// h.fill_2d_f32(5, 9, 2, &mut a)?;
/// p.fill_2d_f32(5, 9, 2, &mut b)?;
/// assert_eq!(a, b);
/// assert!(p.table_bytes() < 1 << 20);
/// assert!(PreparedHalton::new(h, 1001).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PreparedHalton {
    sampler: HaltonSampler,
    /// Dimension `d`'s tables at `d - 2`.
    dims: Vec<Dim>,
    entries: Vec<u16>,
}

impl PreparedHalton {
    /// The tables of `sampler` for dimensions `2 .. dims` (none for
    /// [`Randomization::None`]).
    ///
    /// # Errors
    /// [`Error::TooLarge`] for `dims` past [`HALTON_PIXEL_DIMS`]; an allocation failure as
    /// [`crate::size::vec_zeroed`].
    pub fn new(sampler: HaltonSampler, dims: usize) -> Result<Self> {
        if dims > HALTON_PIXEL_DIMS {
            return Err(Error::TooLarge {
                what: "tabulated Halton dimensions",
                requested: dims as u64,
                max: HALTON_PIXEL_DIMS as u64,
            });
        }
        let r = sampler.randomization();
        let tabulate = matches!(r, Randomization::PermuteDigits | Randomization::Owen);
        let count = if tabulate { dims.saturating_sub(2) } else { 0 };
        let mut layout = crate::size::vec_zeroed::<Dim>(count)?;
        let mut total = 0usize;
        for (i, dim) in layout.iter_mut().enumerate() {
            *dim = plan(i + 2, r, &mut total);
        }
        let mut entries = crate::size::vec_zeroed::<u16>(total)?;
        let scratch = layout
            .iter()
            .filter(|t| t.count > 0 && !matches!(r, Randomization::Owen))
            .map(|t| t.digits * t.base as usize)
            .max()
            .unwrap_or(0);
        let mut perm = crate::size::vec_zeroed::<u16>(scratch)?;
        for dim in &layout {
            fill_dim(dim, &sampler, &mut perm, &mut entries);
        }
        Ok(PreparedHalton {
            sampler,
            dims: layout,
            entries,
        })
    }

    /// The sampler the tables belong to.
    pub const fn sampler(&self) -> &HaltonSampler {
        &self.sampler
    }

    /// The bytes the tables take.
    pub fn table_bytes(&self) -> usize {
        self.entries.len() * 2 + self.dims.len() * core::mem::size_of::<Dim>()
    }

    /// Dimension `d`'s tables, if it has them.
    #[inline]
    fn dim(&self, d: usize) -> Option<&Dim> {
        d.checked_sub(2)
            .and_then(|i| self.dims.get(i))
            .filter(|t| t.count > 0)
    }

    /// `R` of Halton index `h` in dimension `t` (`h < 2^32` when `SMALL`).
    #[inline(always)]
    fn reversed<const SMALL: bool>(&self, t: &Dim, h: u64) -> u64 {
        let (mut a, mut r) = (h, 0u64);
        for g in &t.groups[..t.count] {
            let (q, v) = g.split::<SMALL>(a);
            let e = self.entries.get(g.offset + v).copied().unwrap_or(0);
            r = r * g.size + e as u64;
            a = q;
        }
        if matches!(self.sampler.randomization(), Randomization::Owen) {
            let step = Group {
                size: t.base,
                recip: recip64(t.base),
                offset: 0,
            };
            for _ in t.covered..t.digits {
                let (q, digit) = step.split::<SMALL>(a);
                let hash = mix_bits(t.key as u64 ^ r) as u32;
                r = r * t.base + permutation_element(digit as u32, t.base as u32, hash) as u64;
                a = q;
            }
        }
        r
    }

    /// The value of sample `h` in dimension `t`, converted by `pick`.
    #[inline(always)]
    fn value<T>(&self, t: &Dim, h: u64, pick: impl Fn(&Dim, u64) -> T) -> T {
        if h >> 32 == 0 {
            pick(t, self.reversed::<true>(t, h))
        } else {
            pick(t, self.reversed::<false>(t, h))
        }
    }

    /// The prepared pair fill, or `None` when dimension `d` or `d + 1` has no tables.
    #[inline(always)]
    fn fill_pairs<T>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        out: &mut [[T; 2]],
        pick: impl Fn(&Dim, u64) -> T + Copy,
    ) -> Option<Result<()>> {
        let d = self.sampler.counter_dimension(dim, 2);
        let (a, b) = (self.dim(d)?, self.dim(d + 1)?);
        if let Err(e) = self.sampler.grid().check_fill(x, y, out.len()) {
            return Some(Err(e));
        }
        let h0 = self.sampler.pixel_key(x, y, 0);
        let stride = self.sampler.stride();
        if self.sampler.small_indices(out.len()) {
            for (i, o) in out.iter_mut().enumerate() {
                let h = h0 + i as u64 * stride;
                *o = [
                    pick(a, self.reversed::<true>(a, h)),
                    pick(b, self.reversed::<true>(b, h)),
                ];
            }
        } else {
            for (i, o) in out.iter_mut().enumerate() {
                let h = h0 + i as u64 * stride;
                *o = [self.value(a, h, pick), self.value(b, h, pick)];
            }
        }
        Some(Ok(()))
    }

    /// The prepared 1D fill, or `None` when dimension `d` has no tables.
    #[inline(always)]
    fn fill_values<T>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        out: &mut [T],
        pick: impl Fn(&Dim, u64) -> T + Copy,
    ) -> Option<Result<()>> {
        let d = self.sampler.counter_dimension(dim, 1);
        let a = self.dim(d)?;
        if let Err(e) = self.sampler.grid().check_fill(x, y, out.len()) {
            return Some(Err(e));
        }
        let h0 = self.sampler.pixel_key(x, y, 0);
        let stride = self.sampler.stride();
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.value(a, h0 + i as u64 * stride, pick);
        }
        Some(Ok(()))
    }
}

/// The digits pbrt's `OwenScrambledRadicalInverse` takes in base `b`: while `1 - fl(b^-n)
/// < 1` in `f32`.
fn owen_digit_count(base: u64) -> usize {
    let inv_base = 1.0f32 / base as f32;
    let (mut inv_m, mut n) = (1.0f32, 0);
    while 1.0 - inv_m < 1.0 && n < 64 {
        inv_m *= inv_base;
        n += 1;
    }
    n
}

/// `fl(b^-n)`: `n` factors `fl(1 / b)` multiplied in `f32`, as pbrt's loops accumulate it.
fn inverse_power(base: u64, n: usize) -> f32 {
    let inv_base = 1.0f32 / base as f32;
    let mut inv_m = 1.0f32;
    for _ in 0..n {
        inv_m *= inv_base;
    }
    inv_m
}

/// `floor(2^64 / b) + 1` as a `u64` (`b >= 2`; `2^63` for `b = 2`).
const fn recip64(b: u64) -> u64 {
    let r = reciprocal(b);
    if r > u64::MAX as u128 {
        u64::MAX
    } else {
        r as u64
    }
}

/// The layout of dimension `d` under `r`, its groups placed at `*total` onwards (which
/// moves past them); an untabulated [`Dim`] when `b^n` does not stay below `2^63`.
fn plan(d: usize, r: Randomization, total: &mut usize) -> Dim {
    let base = PRIMES[d] as u64;
    let owen = matches!(r, Randomization::Owen);
    let digits = if owen {
        owen_digit_count(base)
    } else {
        permute_digit_count(base)
    };
    let mut power = 1u64;
    for _ in 0..digits {
        match power.checked_mul(base) {
            Some(p) if p < 1 << 63 => power = p,
            _ => return Dim::default(),
        }
    }
    // c digits a group: the largest with b^c <= GROUP_ENTRIES (at least one).
    let (mut c, mut size) = (1usize, base);
    while size * base <= GROUP_ENTRIES {
        size *= base;
        c += 1;
    }
    let mut t = Dim {
        base,
        digits,
        power,
        inv_m: inverse_power(base, digits),
        key: if owen { owen_key(d) } else { 0 },
        ..Dim::default()
    };
    let mut start = 0;
    while start < digits && t.count < MAX_GROUPS {
        let n = c.min(digits - start);
        let size = base.pow(n as u32);
        t.groups[t.count] = Group {
            size,
            recip: recip64(size),
            offset: *total,
        };
        *total += size as usize;
        t.count += 1;
        start += n;
        if owen {
            break;
        }
    }
    if !owen && start < digits {
        // Not all digits grouped: leave the dimension to the sampler.
        *total -= t.groups[..t.count]
            .iter()
            .map(|g| g.size as usize)
            .sum::<usize>();
        return Dim::default();
    }
    t.covered = start;
    t
}

/// Fills a dimension's group tables (`t` from [`plan`]); `perm` is scratch of at least
/// `n b` entries for `PermuteDigits`.
fn fill_dim(t: &Dim, sampler: &HaltonSampler, perm: &mut [u16], entries: &mut [u16]) {
    if t.count == 0 {
        return;
    }
    let b = t.base;
    let owen = matches!(sampler.randomization(), Randomization::Owen);
    if !owen {
        // pbrt's DigitPermutation: digit k's image of v at k b + v.
        for k in 0..t.digits {
            let key = digit_hash(b as u32, k as u32, sampler.seed()) as u32;
            for v in 0..b {
                if let Some(p) = perm.get_mut(k * b as usize + v as usize) {
                    *p = permutation_element(v as u32, b as u32, key) as u16;
                }
            }
        }
    }
    let mut start = 0;
    for g in &t.groups[..t.count] {
        let n = g.size.ilog(b) as usize;
        for v in 0..g.size {
            let (mut w, mut r) = (v, 0u64);
            for k in start..start + n {
                let digit = w % b;
                let image = if owen {
                    let hash = mix_bits(t.key as u64 ^ r) as u32;
                    permutation_element(digit as u32, b as u32, hash) as u64
                } else {
                    perm.get(k * b as usize + digit as usize)
                        .copied()
                        .unwrap_or(0) as u64
                };
                r = r * b + image;
                w /= b;
            }
            if let Some(e) = entries.get_mut(g.offset + v as usize) {
                *e = r as u16;
            }
        }
        start += n;
    }
}

impl PixelSampler for PreparedHalton {
    fn grid(&self) -> PixelGrid {
        self.sampler.grid()
    }

    fn pixel_key(&self, x: u32, y: u32, index: u32) -> u64 {
        self.sampler.pixel_key(x, y, index)
    }

    fn sample_index(&self, at: &PixelPoint, dim: usize) -> Option<u64> {
        self.sampler.sample_index(at, dim)
    }

    fn counter_dimension(&self, dim: usize, width: usize) -> usize {
        self.sampler.counter_dimension(dim, width)
    }

    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        match self.dim(dim) {
            Some(t) => self.value(t, at.key(), Dim::exact),
            None => self.sampler.value_1d(at, dim),
        }
    }

    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        [self.value_1d(at, dim), self.value_1d(at, dim + 1)]
    }

    fn value_1d_f32(&self, at: &PixelPoint, dim: usize) -> f32 {
        match self.dim(dim) {
            Some(t) => self.value(t, at.key(), Dim::float),
            None => self.sampler.value_1d_f32(at, dim),
        }
    }

    fn value_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
        [self.value_1d_f32(at, dim), self.value_1d_f32(at, dim + 1)]
    }

    fn value_pixel_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        self.sampler.value_pixel_2d(at, dim)
    }

    fn value_pixel_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
        self.sampler.value_pixel_2d_f32(at, dim)
    }

    fn pixel_2d_moves_counter(&self) -> bool {
        self.sampler.pixel_2d_moves_counter()
    }

    fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
        match self.fill_pairs(x, y, dim, out, Dim::exact) {
            Some(r) => r,
            None => self.sampler.fill_2d(x, y, dim, out),
        }
    }

    fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
        match self.fill_pairs(x, y, dim, out, Dim::float) {
            Some(r) => r,
            None => self.sampler.fill_2d_f32(x, y, dim, out),
        }
    }

    fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> Result<()> {
        match self.fill_values(x, y, dim, out, Dim::exact) {
            Some(r) => r,
            None => self.sampler.fill_1d(x, y, dim, out),
        }
    }

    fn fill_1d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [f32]) -> Result<()> {
        match self.fill_values(x, y, dim, out, Dim::float) {
            Some(r) => r,
            None => self.sampler.fill_1d_f32(x, y, dim, out),
        }
    }
}
