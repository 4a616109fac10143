//! pbrt-v4's `StratifiedSampler`: per pixel and dimension, the samples permuted over the
//! strata of `[0, 1)` or of an `xs x ys` grid, jittered by a PCG32 stream.

use super::prepared::{CHUNK, permutation_fill_call};
use super::{PixelGrid, PixelPoint, PixelSampler, pbrt_f32, seed_hash4};
use crate::error::{Error, Result};
use crate::hash::pbrt::{mix_bits, murmur_hash64a, permutation_element};

/// PCG32's multiplier (O'Neill 2014), as pbrt's `RNG`.
const PCG_MULT: u64 = 0x5851_f42d_4c95_7f2d;

/// pbrt-v4's `StratifiedSampler` with `xs x ys` samples a pixel (`n = xs ys`).
///
/// Sample `i` of pixel `p` at dimension `d` lies in stratum
/// `s = PermutationElement(i, n, Hash(p, d, seed))` (a different permutation of the samples
/// per pixel and dimension): a 1D value is `(s + δ) / n`, a 2D value
/// `((s mod xs + δx) / xs, (⌊s / xs⌋ + δy) / ys)`. Jittered, the offsets `δ` are pbrt's
/// PCG32 stream of the pixel (sequence `Hash(p, seed)`) at position `65536 i + d` (and
/// `+ 1` for `δy`): each dimension reads its own position, so any start and any mix of
/// draws gives pbrt's values. Not jittered, `δ = 1/2` (the strata's centres). The position
/// in the pixel is a 2D value and moves the dimension counter, as in pbrt. Any dimension is
/// answered (its low 32 bits are pbrt's `int`).
///
/// Values: the `f32` draws are pbrt's float arithmetic, bit-identical to pbrt-v4 (`δ` is
/// `min(u 2^-32, 1 - 2^-24)` of the stream's `u32` `u`); the 0.32 fractions are the exact
/// truncations of `(s + u 2^-32) / n` (`u = 2^31` unjittered), which the floats round.
/// Cost: nothing per start but one MurmurHash; per value one MurmurHash, one permutation and
/// a PCG32 jump, `O(log2(65536 i + d))` 64-bit multiplications.
/// The prepared fills ([`PixelSampler::fill_2d`]) hash once per pixel and dimension, jump
/// the stream once to sample 0 and then from sample to sample by one precomputed affine
/// step (`65536` draws: one multiplication and one addition), and permute the strata
/// branch-free for a power-of-two `spp`.
///
/// ```
/// use qmckit::pixel::{PixelSampler, StratifiedSampler};
/// let s = StratifiedSampler::new(16, 9, 2, 2, false, 0)?;
/// // Unjittered, the 4 samples of a pixel take the 4 strata centres once each.
/// let mut v: Vec<f32> = (0..4)
///     .map(|i| Ok(s.start_pixel_sample(3, 5, i)?.get_1d_f32()))
///     .collect::<qmckit::Result<_>>()?;
/// v.sort_by(f32::total_cmp);
/// assert_eq!(v, [0.125, 0.375, 0.625, 0.875]);
/// assert!(StratifiedSampler::new(16, 9, 0, 2, true, 0).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StratifiedSampler {
    grid: PixelGrid,
    xs: u32,
    ys: u32,
    jitter: bool,
    seed: u64,
}

impl StratifiedSampler {
    /// The sampler of a `width x height` image with `x_samples x y_samples` samples a pixel,
    /// jittered or at the strata's centres. Below `2^32` the `seed` is pbrt's `int` seed as
    /// its 32 bits (bit-identical); a larger one is hashed with all its 64 bits.
    ///
    /// # Errors
    /// [`Error::ZeroStrata`] for no strata on an axis, [`Error::TooLarge`] when
    /// `x_samples y_samples` passes `2^31 - 1` (pbrt's `int`); as [`PixelGrid::new`].
    pub const fn new(
        width: u32,
        height: u32,
        x_samples: u32,
        y_samples: u32,
        jitter: bool,
        seed: u64,
    ) -> Result<Self> {
        if x_samples == 0 || y_samples == 0 {
            return Err(Error::ZeroStrata {
                dim: if x_samples == 0 { 0 } else { 1 },
            });
        }
        let spp = match x_samples.checked_mul(y_samples) {
            Some(n) if n <= i32::MAX as u32 => n,
            _ => {
                return Err(Error::TooLarge {
                    what: "strata per pixel",
                    requested: x_samples as u64 * y_samples as u64,
                    max: i32::MAX as u64,
                });
            }
        };
        match PixelGrid::new(width, height, spp, false) {
            Ok(grid) => Ok(StratifiedSampler {
                grid,
                xs: x_samples,
                ys: y_samples,
                jitter,
                seed,
            }),
            Err(e) => Err(e),
        }
    }

    /// The sampler with pbrt's split of `spp` into strata (`StratifiedSampler::Create` given
    /// a sample count): `div = ⌊√spp⌋` lowered to a divisor of `spp`, `xs = spp / div`,
    /// `ys = div` (so `xs >= ys`; a prime `spp` gives `spp x 1`).
    ///
    /// # Errors
    /// As [`new`](Self::new); [`Error::ZeroPoints`] for `spp = 0`.
    pub fn with_spp(width: u32, height: u32, spp: u32, jitter: bool, seed: u64) -> Result<Self> {
        if spp == 0 {
            return Err(Error::ZeroPoints);
        }
        let mut div = spp.isqrt();
        while !spp.is_multiple_of(div) {
            div -= 1;
        }
        Self::new(width, height, spp / div, div, jitter, seed)
    }

    /// Strata on the two axes, `(xs, ys)`.
    pub const fn strata(&self) -> (u32, u32) {
        (self.xs, self.ys)
    }

    /// The stratum of sample `at` at dimension `dim`.
    #[inline]
    fn stratum(&self, at: &PixelPoint, dim: usize) -> u32 {
        let h = seed_hash4(at.x(), at.y(), dim, self.seed);
        permutation_element(at.index(), self.grid.spp, h as u32)
    }

    /// The `k` stream values (`u32`) at pbrt's position `65536 i + d` of the pixel's PCG32
    /// stream (pbrt's `SetSequence(Hash(p, seed))` then `Advance`), or `2^31` unjittered.
    fn offsets<const K: usize>(&self, at: &PixelPoint, dim: usize) -> [u32; K] {
        if !self.jitter {
            return [1 << 31; K];
        }
        // pbrt's `int` dimension, widened with its sign.
        let d = dim as u32 as i32 as i64 as u64;
        let delta = (at.index() as u64).wrapping_mul(65536).wrapping_add(d);
        let mut pcg = Pcg32::sequence(at.key());
        pcg.advance(delta);
        let mut out = [0; K];
        let mut k = 0;
        while k < K {
            out[k] = pcg.next_u32();
            k += 1;
        }
        out
    }
}

impl StratifiedSampler {
    /// The prepared fill of samples `0 .. out.len()` of pixel `(x, y)` at dimension `dim`:
    /// `value(stratum, [u, v])` per sample, the strata from one hash and the stream
    /// values `u, v` at `65536 i + d` from one jump and an affine step per sample.
    #[inline]
    fn fill_with<T>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        out: &mut [T],
        value: impl Fn(u32, [u32; 2]) -> T,
    ) -> Result<()> {
        self.grid.check_fill(x, y, out.len())?;
        let h = seed_hash4(x, y, dim, self.seed);
        let mut pcg = Pcg32::sequence(self.pixel_key(x, y, 0));
        // pbrt's `int` dimension, widened with its sign.
        pcg.advance(dim as u32 as i32 as i64 as u64);
        let step = pcg.jump(65536);
        let mut perm = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let perm = &mut perm[..chunk.len()];
            permutation_fill_call((c * CHUNK) as u32, self.grid.spp, h as u32, perm);
            for (o, &s) in chunk.iter_mut().zip(perm.iter()) {
                let offsets = if self.jitter {
                    let mut p = Pcg32 {
                        state: pcg.state,
                        inc: pcg.inc,
                    };
                    [p.next_u32(), p.next_u32()]
                } else {
                    [1 << 31; 2]
                };
                *o = value(s, offsets);
                pcg.state = step.0.wrapping_mul(pcg.state).wrapping_add(step.1);
            }
        }
        Ok(())
    }
}

/// The exact 0.32 truncation of `(s + u 2^-32) / n`.
fn fraction(s: u32, u: u32, n: u32) -> u32 {
    ((((s as u64) << 32) | u as u64) / n as u64) as u32
}

/// PCG32 (XSH-RR, 64-bit state), as pbrt's `RNG`.
struct Pcg32 {
    state: u64,
    inc: u64,
}

impl Pcg32 {
    /// pbrt's `SetSequence(index)`: the stream `index`, started at offset `MixBits(index)`.
    fn sequence(index: u64) -> Self {
        let mut p = Pcg32 {
            state: 0,
            inc: (index << 1) | 1,
        };
        p.next_u32();
        p.state = p.state.wrapping_add(mix_bits(index));
        p.next_u32();
        p
    }

    fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(PCG_MULT).wrapping_add(self.inc);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        xorshifted.rotate_right((old >> 59) as u32)
    }

    /// The affine map `state -> a state + c` of `delta` steps (Brown 1994: the one-step
    /// map squared per bit of `delta`), `(a, c)`.
    fn jump(&self, mut delta: u64) -> (u64, u64) {
        let (mut cur_mult, mut cur_plus) = (PCG_MULT, self.inc);
        let (mut acc_mult, mut acc_plus) = (1u64, 0u64);
        while delta > 0 {
            if delta & 1 == 1 {
                acc_mult = acc_mult.wrapping_mul(cur_mult);
                acc_plus = acc_plus.wrapping_mul(cur_mult).wrapping_add(cur_plus);
            }
            cur_plus = cur_mult.wrapping_add(1).wrapping_mul(cur_plus);
            cur_mult = cur_mult.wrapping_mul(cur_mult);
            delta >>= 1;
        }
        (acc_mult, acc_plus)
    }

    /// `delta` steps at once (Brown 1994's jump: the affine map squared per bit).
    fn advance(&mut self, delta: u64) {
        let (a, c) = self.jump(delta);
        self.state = a.wrapping_mul(self.state).wrapping_add(c);
    }
}

impl PixelSampler for StratifiedSampler {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
        let (xs, ys) = (self.xs, self.ys);
        self.fill_with(x, y, dim, out, |s, [u, v]| {
            [fraction(s % xs, u, xs), fraction(s / xs, v, ys)]
        })
    }

    fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
        let (xs, ys, jitter) = (self.xs, self.ys, self.jitter);
        self.fill_with(x, y, dim, out, |s, o| {
            let [dx, dy] = if jitter { o.map(pbrt_f32) } else { [0.5; 2] };
            [
                ((s % xs) as f32 + dx) / xs as f32,
                ((s / xs) as f32 + dy) / ys as f32,
            ]
        })
    }

    fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> Result<()> {
        let n = self.grid.spp;
        self.fill_with(x, y, dim, out, |s, [u, _]| fraction(s, u, n))
    }

    fn fill_1d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [f32]) -> Result<()> {
        let (n, jitter) = (self.grid.spp, self.jitter);
        self.fill_with(x, y, dim, out, |s, [u, _]| {
            let delta = if jitter { pbrt_f32(u) } else { 0.5 };
            (s as f32 + delta) / n as f32
        })
    }

    /// The pixel's PCG32 sequence index, pbrt's `Hash(p, seed)`.
    fn pixel_key(&self, x: u32, y: u32, _index: u32) -> u64 {
        let (x, y, s) = (x.to_le_bytes(), y.to_le_bytes(), self.seed.to_le_bytes());
        let bytes = [
            x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3], s[0], s[1], s[2], s[3], s[4], s[5],
            s[6], s[7],
        ];
        if self.seed >> 32 == 0 {
            murmur_hash64a(&bytes[..12], 0)
        } else {
            murmur_hash64a(&bytes, 0)
        }
    }

    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        let [u] = self.offsets::<1>(at, dim);
        fraction(self.stratum(at, dim), u, self.grid.spp)
    }

    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        let s = self.stratum(at, dim);
        let [u, v] = self.offsets::<2>(at, dim);
        [
            fraction(s % self.xs, u, self.xs),
            fraction(s / self.xs, v, self.ys),
        ]
    }

    fn value_1d_f32(&self, at: &PixelPoint, dim: usize) -> f32 {
        let s = self.stratum(at, dim);
        let delta = if self.jitter {
            pbrt_f32(self.offsets::<1>(at, dim)[0])
        } else {
            0.5
        };
        (s as f32 + delta) / self.grid.spp as f32
    }

    fn value_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
        let s = self.stratum(at, dim);
        let [dx, dy] = if self.jitter {
            self.offsets::<2>(at, dim).map(pbrt_f32)
        } else {
            [0.5; 2]
        };
        [
            ((s % self.xs) as f32 + dx) / self.xs as f32,
            ((s / self.xs) as f32 + dy) / self.ys as f32,
        ]
    }

    fn value_pixel_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
        self.value_2d_f32(at, dim)
    }
}
