//! pbrt-v4's `HaltonSampler`: one Halton sequence over the image plane, the pixel's samples
//! found through the first two radical inverses (Pharr, Jakob & Humphreys 2023, §8.6).

use super::halton_digits::{
    CarriedDigits, Digits, Plan, TABLE_ENTRIES, digit_table, permuted_small,
};
use super::{F32_ONE_MINUS_EPSILON, PixelGrid, PixelPoint, PixelSampler, Randomization};
use crate::error::{Error, Result};
use crate::hash::pbrt::{hash3, mix_bits, murmur_words, permutation_element};
use crate::radical_inverse::halton::PRIMES;

/// The dimensions the Halton pixel sampler has (pbrt's `PrimeTableSize`): a request that
/// would read past the last prime starts again at dimension 2.
pub const HALTON_PIXEL_DIMS: usize = 1000;

/// The largest pixel period pbrt's Halton sampler resolves (`MaxHaltonResolution`): pixel
/// `(x, y)` shares its samples' structure with `(x mod 128, y mod 128)`.
const MAX_RESOLUTION: u32 = 128;

/// pbrt-v4's `HaltonSampler`.
///
/// With `2^j >= min(width, 128)` and `3^k >= min(height, 128)` the smallest such powers, the
/// first two Halton coordinates of indices `0 .. 2^j 3^k` put exactly one point in each cell
/// of a `2^j x 3^k` grid; pixel `p` (mod 128) owns the index `o(p) < 2^j 3^k` with
/// `o = (r2(px) 3^k m2 + r3(py) 2^j m3) mod 2^j 3^k` (`r_b` the `j`- or `k`-digit inverse
/// radical inverse, `m2 = (3^k)^-1 mod 2^j`, `m3 = (2^j)^-1 mod 3^k`, by the Chinese
/// remainder theorem), and its sample `i` is the Halton point at `h = o(p) + i 2^j 3^k`.
/// Dimension `d` (`2 <= d < 1000`) is the radical inverse of `h` in the `d`-th prime:
///
/// * [`Randomization::None`]: plain (`RadicalInverse`);
/// * [`Randomization::PermuteDigits`] (pbrt's default): digit `k` of base `b` through the
///   permutation `PermutationElement(·, b, Hash(b, k, seed))` (pbrt's
///   `ComputeRadicalInversePermutations`; the sampler carries the permutations of
///   dimensions 2 to 9, bases 5 to 29, as 966 bytes computed by [`new`](Self::new), and
///   computes those of later dimensions on the fly);
/// * [`Randomization::Owen`]: each digit permuted by a hash of the digits above it, keyed by
///   `MixBits(1 + 16 d)` (pbrt's `OwenScrambledRadicalInverse`; the seed is not used).
///
/// [`Randomization::FastOwen`] is refused, as pbrt refuses it. The position in the pixel
/// ([`get_pixel_2d`](super::PixelSample::get_pixel_2d)) is the unrandomized radical inverses
/// of `h / 2^j` (base 2) and `h / 3^k` (base 3), and does not move the dimension counter;
/// the counter starts at 2 and a request past dimension 999 starts again at 2, as in pbrt.
///
/// Values: the 0.32 fractions are the exact truncations of the randomized radical inverse
/// `R / b^n` (`n` digits); the `f32` draws are pbrt's float computation (`R` rounded to
/// `f32`, times `b^-n` accumulated in `f32`, capped at `1 - 2^-24`), bit-identical to
/// pbrt-v4. Any `spp >= 1`. Cost: per start, `j + k` divisions; per value `n ≈ 24 / log2 b`
/// digit steps (one 64-bit division each; a multiply-high below `2^32` in the carried
/// dimensions), plus, outside the carried dimensions, one MurmurHash and one permutation
/// per digit for `PermuteDigits`; one `MixBits` and one permutation per digit for `Owen`.
/// Construction with `PermuteDigits` costs the carried permutations' 966 elements (pbrt's
/// constructor computes those of all 1000 dimensions).
/// The prepared fills ([`PixelSampler::fill_2d`]) find the pixel's Halton index once
/// (sample `i` adds `i 2^j 3^k`) and, for `PermuteDigits`, read the carried rows or, past
/// them, tabulate each digit's permutation once per fill (one hash a digit instead of one
/// a digit and value); the digits the fill's indices leave at 0 enter as one constant.
/// `PreparedHalton` (`std`) builds the tables of as many dimensions as asked for once, as
/// pbrt does, grouped several digits a read, and fills about twice as fast again.
///
/// ```
/// use qmckit::pixel::{HaltonSampler, PixelSampler, Randomization};
/// let h = HaltonSampler::new(16, 9, 1, Randomization::None, 0)?;
/// // 2^4 x 3^2 cells; pixel (1, 0) owns index 72 (72 = 1001000 in base 2, 22000 in base 3).
/// let mut s = h.start_pixel_sample(1, 0, 0)?;
/// assert_eq!(s.sample_index(), Some(72));
/// // In the pixel: base 2 of 72 / 2^4 = 4 is 0.001, base 3 of 72 / 3^2 = 8 = 22 is 0.22.
/// let [px, py] = s.get_pixel_2d_f32();
/// assert_eq!(px, 0.125);
/// assert!((py - 8.0 / 9.0).abs() < 1e-6);
/// // Dimension 2 is base 5: 72 = 242 in base 5, reversed 0.242 = 72 / 125.
/// assert_eq!(s.get_1d_f32(), 72.0 * (0.2f32 * 0.2 * 0.2));
/// assert!(HaltonSampler::new(16, 9, 1, Randomization::FastOwen, 0).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct HaltonSampler {
    grid: PixelGrid,
    randomize: Randomization,
    seed: u64,
    /// `2^j`, `3^k`.
    scales: [u64; 2],
    /// `j`, `k`.
    exponents: [u32; 2],
    /// `(3^k)^-1 mod 2^j`, `(2^j)^-1 mod 3^k`.
    inverses: [u64; 2],
    /// `PermuteDigits`' permutations of the first dimensions (empty otherwise).
    carried: CarriedDigits,
}

impl HaltonSampler {
    /// The sampler of a `width x height` image with `spp` samples a pixel. Below `2^32` the
    /// `seed` is pbrt's `int` seed as its 32 bits (bit-identical); a larger one is hashed
    /// with all its 64 bits. Only `PermuteDigits` uses the seed.
    ///
    /// # Errors
    /// As [`PixelGrid::new`]; [`Error::Unsupported`] for [`Randomization::FastOwen`] (pbrt's
    /// Halton sampler has none); [`Error::TooLarge`] when the last sample's index
    /// `2^j 3^k spp` passes `2^63`.
    pub const fn new(
        width: u32,
        height: u32,
        spp: u32,
        randomize: Randomization,
        seed: u64,
    ) -> Result<Self> {
        let grid = match PixelGrid::new(width, height, spp, false) {
            Ok(g) => g,
            Err(e) => return Err(e),
        };
        if matches!(randomize, Randomization::FastOwen) {
            return Err(Error::Unsupported {
                what: "FastOwen randomization of the Halton sampler (pbrt's has none)",
            });
        }
        let mut scales = [1u64; 2];
        let mut exponents = [0u32; 2];
        let res = [width, height];
        let mut i = 0;
        while i < 2 {
            let base = if i == 0 { 2 } else { 3 };
            let cap = if res[i] < MAX_RESOLUTION {
                res[i]
            } else {
                MAX_RESOLUTION
            };
            while scales[i] < cap as u64 {
                scales[i] *= base;
                exponents[i] += 1;
            }
            i += 1;
        }
        // 2^7 3^5 spp < 2^15 2^32: no overflow, but keep the bound explicit.
        let stride = scales[0] * scales[1];
        if stride.checked_mul(spp as u64).is_none() {
            return Err(Error::TooLarge {
                what: "Halton sample indices",
                requested: spp as u64,
                max: u64::MAX / stride,
            });
        }
        Ok(HaltonSampler {
            grid,
            randomize,
            seed,
            scales,
            exponents,
            inverses: [
                inverse_mod(scales[1] % scales[0], scales[0]),
                inverse_mod(scales[0] % scales[1], scales[1]),
            ],
            carried: if matches!(randomize, Randomization::PermuteDigits) {
                CarriedDigits::new(seed)
            } else {
                CarriedDigits::EMPTY
            },
        })
    }

    /// The randomization.
    #[cfg(feature = "std")]
    pub(super) const fn randomization(&self) -> Randomization {
        self.randomize
    }

    /// The seed.
    #[cfg(feature = "std")]
    pub(super) const fn seed(&self) -> u64 {
        self.seed
    }

    /// `2^j 3^k`: the Halton index step between a pixel's samples.
    pub(super) const fn stride(&self) -> u64 {
        self.scales[0] * self.scales[1]
    }

    /// `(R, b^n)` of dimension `dim`'s randomized radical inverse of `h`: the value is
    /// `R / b^n`; and pbrt's `f32` of it.
    fn dimension(&self, h: u64, dim: usize) -> (u32, f32) {
        let base = PRIMES[dim] as u64;
        match self.randomize {
            Randomization::None => radical_inverse(base, h),
            Randomization::Owen => {
                let key = owen_key(dim);
                digits(base, h, Stop::Owen, |_, digit, reversed| {
                    let hash = mix_bits(key as u64 ^ reversed) as u32;
                    permutation_element(digit, base as u32, hash)
                })
            }
            // FastOwen is refused by `new`.
            _ => match self.carried.rows(dim) {
                Some((rows, plan)) => {
                    let m = plan.recip;
                    digits_by(
                        base,
                        h,
                        Stop::Permute,
                        // The reciprocal is exact below 2^32.
                        |a| {
                            if a >> 32 == 0 {
                                ((a as u128 * m as u128) >> 64) as u64
                            } else {
                                a / base
                            }
                        },
                        |k, digit, _| {
                            let at = k as usize * base as usize + digit as usize;
                            rows.get(at).copied().unwrap_or(0) as u32
                        },
                    )
                }
                None => digits(base, h, Stop::Permute, |k, digit, _| {
                    let hash = digit_hash(base as u32, k, self.seed) as u32;
                    permutation_element(digit, base as u32, hash)
                }),
            },
        }
    }
}

impl HaltonSampler {
    /// The prepared fill: `value(h, d)` for the Halton indices `h` of samples
    /// `0 .. out.len()` of pixel `(x, y)` (`h0 + i 2^j 3^k`, `h0` found once), with
    /// `d` the dimension through the counter rule for a request of `width` values.
    #[inline]
    fn fill_with<T>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        width: usize,
        out: &mut [T],
        value: impl Fn(u64, usize) -> T,
    ) -> Result<()> {
        self.grid.check_fill(x, y, out.len())?;
        let d = self.counter_dimension(dim, width);
        let h0 = self.pixel_key(x, y, 0);
        let stride = self.stride();
        for (i, o) in out.iter_mut().enumerate() {
            *o = value(h0 + i as u64 * stride, d);
        }
        Ok(())
    }

    /// The rows the sampler carries for dimension `dim` ([`CarriedDigits`], `PermuteDigits`
    /// only) as the prepared digits of the indices up to `h_max`: no hashing.
    #[inline]
    fn carried_table(&self, dim: usize, h_max: u64) -> Option<Digits<'_, &[u8]>> {
        if !matches!(self.randomize, Randomization::PermuteDigits) {
            return None;
        }
        self.carried.table(dim, h_max)
    }

    /// The prepared pair fill: the `(R, float)` pairs of dimensions `d, d + 1` through
    /// `pick` (the fraction or pbrt's float).
    #[inline]
    fn fill_pairs<T: Copy>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        out: &mut [[T; 2]],
        pick: impl Fn((u32, f32)) -> T,
    ) -> Result<()> {
        let d = self.counter_dimension(dim, 2);
        if matches!(self.randomize, Randomization::PermuteDigits) && self.small_indices(out.len()) {
            let h_max = self.last_index(x, y, out.len());
            if let (Some(t0), Some(t1)) = (
                self.carried_table(d, h_max),
                self.carried_table(d + 1, h_max),
            ) {
                return self.fill_with(x, y, dim, 2, out, |h, _| {
                    [pick(permuted_small(h, &t0)), pick(permuted_small(h, &t1))]
                });
            }
            let (p0, p1) = (Plan::new(PRIMES[d] as u64), Plan::new(PRIMES[d + 1] as u64));
            let (mut b0, mut b1) = ([0u16; TABLE_ENTRIES], [0u16; TABLE_ENTRIES]);
            if let (Some(p0), Some(p1)) = (&p0, &p1)
                && let (Some(t0), Some(t1)) = (
                    digit_table(self.seed, d, h_max, p0, &mut b0),
                    digit_table(self.seed, d + 1, h_max, p1, &mut b1),
                )
            {
                return self.fill_with(x, y, dim, 2, out, |h, _| {
                    [pick(permuted_small(h, &t0)), pick(permuted_small(h, &t1))]
                });
            }
        }
        self.fill_with(x, y, dim, 2, out, |h, d| {
            [pick(self.dimension(h, d)), pick(self.dimension(h, d + 1))]
        })
    }

    /// The prepared 1D fill.
    #[inline]
    fn fill_values<T: Copy>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        out: &mut [T],
        pick: impl Fn((u32, f32)) -> T,
    ) -> Result<()> {
        let d = self.counter_dimension(dim, 1);
        if matches!(self.randomize, Randomization::PermuteDigits) && self.small_indices(out.len()) {
            let h_max = self.last_index(x, y, out.len());
            if let Some(t) = self.carried_table(d, h_max) {
                return self.fill_with(x, y, dim, 1, out, |h, _| pick(permuted_small(h, &t)));
            }
            let mut buf = [0u16; TABLE_ENTRIES];
            if let Some(p) = Plan::new(PRIMES[d] as u64)
                && let Some(t) = digit_table(self.seed, d, h_max, &p, &mut buf)
            {
                return self.fill_with(x, y, dim, 1, out, |h, _| pick(permuted_small(h, &t)));
            }
        }
        self.fill_with(x, y, dim, 1, out, |h, d| pick(self.dimension(h, d)))
    }

    /// The Halton index of the last of `n >= 1` samples of pixel `(x, y)` (0 for `n = 0`;
    /// an upper bound of the fill's indices).
    fn last_index(&self, x: u32, y: u32, n: usize) -> u64 {
        let h0 = self.pixel_key(x, y, 0);
        h0.saturating_add((n.saturating_sub(1) as u64).saturating_mul(self.stride()))
    }

    /// Whether the Halton indices of `n` samples of any pixel stay below `2^32`.
    pub(super) fn small_indices(&self, n: usize) -> bool {
        let stride = self.stride();
        (n as u64).saturating_mul(stride) <= 1 << 32
    }
}

/// The digits pbrt's `ScrambledRadicalInverse` takes in base `b`: while
/// `1 - (b - 1) fl(b^-n) < 1` in `f32` (the index's value does not matter).
pub(super) const fn permute_digit_count(base: u64) -> usize {
    let inv_base = 1.0f32 / base as f32;
    let (mut inv_m, mut n) = (1.0f32, 0);
    while 1.0 - (base - 1) as f32 * inv_m < 1.0 && n < 64 {
        inv_m *= inv_base;
        n += 1;
    }
    n
}

/// The Owen key of dimension `dim`: `MixBits(1 + 16 dim)`, low 32 bits (pbrt's
/// `OwenScrambledRadicalInverse` hash).
pub(super) const fn owen_key(dim: usize) -> u32 {
    mix_bits(1 + ((dim as u64) << 4)) as u32
}

/// pbrt's `Hash(base, digitIndex, seed)`: MurmurHash64A of the 12 bytes for a 32-bit seed,
/// of 16 bytes (the seed's 64 bits) above.
pub(super) const fn digit_hash(base: u32, k: u32, seed: u64) -> u64 {
    if seed >> 32 == 0 {
        hash3(base, k, seed as u32)
    } else {
        murmur_words(&[(base as u64) | ((k as u64) << 32), seed], 16)
    }
}

/// `a^-1 mod n` for `gcd(a, n) = 1` (0 for `n = 1`), by the extended Euclidean algorithm.
const fn inverse_mod(a: u64, n: u64) -> u64 {
    if n <= 1 {
        return 0;
    }
    let (mut r0, mut r1) = (n as i64, a as i64);
    let (mut t0, mut t1) = (0i64, 1i64);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    t0.rem_euclid(n as i64) as u64
}

/// `InverseRadicalInverse`: the `n` base-`b` digits of `v`, reversed.
const fn inverse_radical_inverse(mut v: u64, base: u64, n: u32) -> u64 {
    let mut index = 0;
    let mut k = 0;
    while k < n {
        index = index * base + v % base;
        v /= base;
        k += 1;
    }
    index
}

/// When a radical inverse stops taking digits (pbrt's loop conditions, in `f32`).
#[derive(Clone, Copy)]
enum Stop {
    /// `1 - (b - 1) b^-n < 1`: `ScrambledRadicalInverse`.
    Permute,
    /// `1 - b^-n < 1`: `OwenScrambledRadicalInverse`.
    Owen,
}

/// The 0.32 truncation of `R / b^n` and pbrt's `f32` `min(float(R) * fl(b^-n), 1 - 2^-24)`,
/// with `fl(b^-n)` the product of `n` factors `fl(1 / b)` rounded at each step.
#[inline]
pub(super) fn finish(reversed: u64, power: u128, inv_m: f32) -> (u32, f32) {
    let exact = ((reversed as u128) << 32) / power;
    let exact = if exact > u32::MAX as u128 {
        u32::MAX
    } else {
        exact as u32
    };
    let f = reversed as f32 * inv_m;
    (
        exact,
        if f < F32_ONE_MINUS_EPSILON {
            f
        } else {
            F32_ONE_MINUS_EPSILON
        },
    )
}

/// pbrt's `RadicalInverse`: the digits of `a` until none are left (or the reversed value
/// would overflow).
fn radical_inverse(base: u64, mut a: u64) -> (u32, f32) {
    let limit = u64::MAX / base - base;
    let inv_base = 1.0f32 / base as f32;
    let (mut inv_m, mut power, mut reversed) = (1.0f32, 1u128, 0u64);
    while a != 0 && reversed < limit {
        let next = a / base;
        reversed = reversed * base + (a - next * base);
        inv_m *= inv_base;
        power *= base as u128;
        a = next;
    }
    finish(reversed, power, inv_m)
}

/// A randomized radical inverse: digit `k` (value `v`, the reversed digits so far `r`)
/// becomes `permute(k, v, r)`, for as many digits as `stop` allows.
#[inline]
fn digits(base: u64, a: u64, stop: Stop, permute: impl Fn(u32, u32, u64) -> u32) -> (u32, f32) {
    digits_by(base, a, stop, |a| a / base, permute)
}

/// [`digits`] with the quotient `a / base` computed by `div` (exact for the indices given).
#[inline]
fn digits_by(
    base: u64,
    mut a: u64,
    stop: Stop,
    div: impl Fn(u64) -> u64,
    permute: impl Fn(u32, u32, u64) -> u32,
) -> (u32, f32) {
    let limit = u64::MAX / base - base;
    let inv_base = 1.0f32 / base as f32;
    let (mut inv_m, mut power, mut reversed, mut k) = (1.0f32, 1u128, 0u64, 0u32);
    loop {
        let more = match stop {
            Stop::Permute => 1.0 - (base - 1) as f32 * inv_m < 1.0,
            Stop::Owen => 1.0 - inv_m < 1.0,
        };
        if !more || reversed >= limit {
            break;
        }
        let next = div(a);
        let digit = (a - next * base) as u32;
        reversed = reversed * base + permute(k, digit, reversed) as u64;
        inv_m *= inv_base;
        power *= base as u128;
        k += 1;
        a = next;
    }
    finish(reversed, power, inv_m)
}

impl PixelSampler for HaltonSampler {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
        self.fill_pairs(x, y, dim, out, |v| v.0)
    }

    fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
        self.fill_pairs(x, y, dim, out, |v| v.1)
    }

    fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> Result<()> {
        self.fill_values(x, y, dim, out, |v| v.0)
    }

    fn fill_1d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [f32]) -> Result<()> {
        self.fill_values(x, y, dim, out, |v| v.1)
    }

    /// The Halton index `h` of the sample.
    fn pixel_key(&self, x: u32, y: u32, index: u32) -> u64 {
        let stride = self.stride();
        let mut h = 0;
        if stride > 1 {
            let p = [x % MAX_RESOLUTION, y % MAX_RESOLUTION];
            let mut i = 0;
            while i < 2 {
                let base = if i == 0 { 2 } else { 3 };
                let offset = inverse_radical_inverse(p[i] as u64, base, self.exponents[i]);
                // offset < scale, (stride / scale) * inverse < stride: below 2^30.
                h += offset * (stride / self.scales[i]) * self.inverses[i];
                i += 1;
            }
            h %= stride;
        }
        h + index as u64 * stride
    }

    fn sample_index(&self, at: &PixelPoint, _dim: usize) -> Option<u64> {
        Some(at.key())
    }

    fn counter_dimension(&self, dim: usize, width: usize) -> usize {
        super::global_counter_dimension(dim, width, HALTON_PIXEL_DIMS)
    }

    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        self.dimension(at.key(), dim).0
    }

    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        [
            self.dimension(at.key(), dim).0,
            self.dimension(at.key(), dim + 1).0,
        ]
    }

    fn value_1d_f32(&self, at: &PixelPoint, dim: usize) -> f32 {
        self.dimension(at.key(), dim).1
    }

    fn value_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
        [
            self.dimension(at.key(), dim).1,
            self.dimension(at.key(), dim + 1).1,
        ]
    }

    fn value_pixel_2d(&self, at: &PixelPoint, _dim: usize) -> [u32; 2] {
        let h = at.key();
        [
            radical_inverse(2, h >> self.exponents[0]).0,
            radical_inverse(3, h / self.scales[1]).0,
        ]
    }

    fn value_pixel_2d_f32(&self, at: &PixelPoint, _dim: usize) -> [f32; 2] {
        let h = at.key();
        [
            radical_inverse(2, h >> self.exponents[0]).1,
            radical_inverse(3, h / self.scales[1]).1,
        ]
    }

    fn pixel_2d_moves_counter(&self) -> bool {
        false
    }
}
