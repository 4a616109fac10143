//! pbrt-v4's `SobolSampler`: one Sobol' sequence over the whole image plane, the samples of a
//! pixel found by solving for their indices (Grünschloss, Raab & Keller 2012, "Enumerating
//! quasi-Monte Carlo point sequences in elementary intervals").

use super::prepared::{CHUNK, at, dispatched, randomize_pairs, randomize_values};
use super::{
    F32_ONE_MINUS_EPSILON, PixelGrid, PixelPoint, PixelSampler, Randomization, pbrt_f32,
    seed_hash2, sobol0, sobol1,
};
use crate::bits::reverse_bits;
use crate::digital::sobol::SobolDimension;
use crate::error::{Error, Result};

/// pbrt-v4's number of Sobol' dimensions (`NSobolDimensions`): its `SobolSampler` wraps
/// the dimension counter to 2 there.
pub const PBRT_SOBOL_DIMS: usize = 1024;

/// Where this build's [`ImageSobol`] wraps the dimension counter to 2: pbrt's rule applied to
/// the Sobol' table compiled in, `min(`[`SOBOL_MAX_DIMS`](crate::digital::sobol::SOBOL_MAX_DIMS)`,
/// `[`PBRT_SOBOL_DIMS`]`)`. That is 1024, pbrt's own value, with the `sobol-dims-1024` or
/// `sobol-dims-21201` feature (the `cli` feature enables the latter): every dimension is
/// then bit-identical to pbrt. The default table holds 64 dimensions, so a default build
/// matches pbrt below dimension 64 and from there reads dimensions 2, 3, ... again where
/// pbrt reads its dimensions 64 to 1023.
pub const IMAGE_SOBOL_DIMS: usize = {
    let compiled = crate::digital::sobol::SOBOL_MAX_DIMS;
    if compiled < PBRT_SOBOL_DIMS {
        compiled
    } else {
        PBRT_SOBOL_DIMS
    }
};

/// The image-plane Sobol' sampler. With `2^m = RoundUpPow2(max(w, h))`, sample `i` of pixel
/// `p` is the `i`-th Sobol' index whose first two coordinates fall in pixel `p` of the
/// `2^m x 2^m` grid: since Sobol' (0, 1) is a (0, 2)-sequence, every frame of `2^2m`
/// consecutive indices holds one such index, `i 2^2m + l`, and `l` solves a `2m x 2m`
/// system over GF(2). The matrices are computed by [`ImageSobol::new`] (Gaussian
/// elimination on the first two Sobol' dimensions), not shipped.
///
/// `get_pixel_2d` is the unscrambled point scaled into the pixel; 1D and 2D values start at
/// Sobol' dimension 2 (a counter below 2 reads as 2), scrambled with `low32(Hash(d, seed))`.
/// Past the Sobol' table the sampler pads as pbrt's `Get1D`/`Get2D` do: a request whose
/// dimension `d` (or `d + 1` for a pair) reaches [`IMAGE_SOBOL_DIMS`] reads dimension 2
/// (and [`PixelSample`](super::PixelSample) counts on from there), so every counter value
/// is answered; see [`IMAGE_SOBOL_DIMS`] for what that means for bit-exactness. Needs
/// `spp 2^2m <= 2^32` (32-bit Sobol' indices; pbrt allows 52 bits).
/// Cost: setup `O(m^2)`; per [`start_pixel_sample`](PixelSampler::start_pixel_sample)
/// `O(m + log2 spp)` XORs for the index (pbrt's `SobolIntervalToIndex`, once); per value one
/// Sobol' value (32 AND/XOR), one MurmurHash and the scramble.
///
/// The prepared fills ([`PixelSampler::fill_2d`]) use that the index is linear over GF(2)
/// in the pixel code and the sample's frame: sample `i`'s index is `l(p) ^ e(i)` with
/// `e(i)` the XOR of one column per set bit of `i`, so its Sobol' value in dimension `d`
/// is `S_d(l(p)) ^ XOR of S_d(e_c)`. Per pixel and dimension: the system solved once,
/// `S_d` of it and of the `log2 spp` frame columns, the hash; per sample one XOR (the
/// table doubles over the frame bits) and the scramble in the bit-reversed domain.
///
/// ```
/// use qmckit::pixel::{ImageSobol, PixelSampler, Randomization};
/// let s = ImageSobol::new(16, 9, 4, Randomization::FastOwen, 0)?;
/// let mut p = s.start_pixel_sample(3, 5, 2)?;
/// assert_eq!(p.sample_index().unwrap_or(0) >> 8, 2); // frame 2 of 256 indices
/// let [u, v] = p.get_pixel_2d_f32();
/// assert!((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v));
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ImageSobol {
    grid: PixelGrid,
    randomize: Randomization,
    seed: u64,
    m: u32,
    /// `f(2^(2m + c))`: what frame bit `c` adds to the pixel code.
    frame_cols: [u32; 32],
    /// The index `l < 2^2m` with `f(l) = 2^c`.
    inverse: [u32; 32],
    /// What sample bit `c` adds to the index: `2^(2m + c) ^ l(frame_cols[c])` (zero past
    /// the 32 bits), so sample `i`'s index is `l(p) ^ XOR of these` over its set bits.
    frame_index: [u32; 32],
}

/// The pixel code of Sobol' index `i` on the `2^m` grid:
/// `(top m bits of x) << m | (top m bits of y)`. Linear over GF(2) in the bits of `i`.
fn code(m: u32, i: u64) -> u32 {
    if m == 0 {
        return 0;
    }
    ((sobol0(i) >> (32 - m)) << m) | (sobol1(i) >> (32 - m))
}

impl ImageSobol {
    /// The sampler of a `width x height` image with `spp` samples a pixel (any count; pbrt
    /// advises a power of two). Below `2^32` the `seed` is pbrt's `int` seed as its 32 bits
    /// (bit-identical); a larger seed is hashed with all its 64 bits.
    ///
    /// # Errors
    /// As [`PixelGrid::new`]; [`Error::TooLarge`] when `spp 2^2m` passes `2^32`.
    pub fn new(
        width: u32,
        height: u32,
        spp: u32,
        randomize: Randomization,
        seed: u64,
    ) -> Result<Self> {
        let grid = PixelGrid::new(width, height, spp, false)?;
        let m = grid.pow2_side().trailing_zeros();
        // m <= 30 (sides up to 2^30), so the shift stays inside u64.
        let needed = (spp as u64) << (2 * m).min(63);
        if 2 * m > 32 || needed > 1 << 32 {
            return Err(Error::TooLarge {
                what: "Sobol' indices of the image (spp * side^2)",
                requested: needed,
                max: 1 << 32,
            });
        }
        let n = (2 * m) as usize;
        let mut frame_cols = [0u32; 32];
        for (c, col) in frame_cols.iter_mut().enumerate().take(32 - n) {
            *col = code(m, 1u64 << (n + c));
        }
        // Gauss-Jordan: cols[j] = f(comb[j]); reduce cols to the unit vectors.
        let mut cols = [0u32; 32];
        let mut comb = [0u32; 32];
        for j in 0..n {
            if let (Some(c), Some(k)) = (cols.get_mut(j), comb.get_mut(j)) {
                *c = code(m, 1u64 << j);
                *k = 1 << j;
            }
        }
        for bit in 0..n {
            let pivot = (bit..n).find(|&j| cols.get(j).is_some_and(|c| c >> bit & 1 == 1));
            let Some(p) = pivot else {
                return Err(Error::Unsupported {
                    what: "a singular pixel-code matrix (not a (0,2)-sequence)",
                });
            };
            cols.swap(bit, p);
            comb.swap(bit, p);
            let (pc, pk) = (
                cols.get(bit).copied().unwrap_or(0),
                comb.get(bit).copied().unwrap_or(0),
            );
            for j in 0..n {
                if j != bit
                    && let (Some(c), Some(k)) = (cols.get_mut(j), comb.get_mut(j))
                    && *c >> bit & 1 == 1
                {
                    *c ^= pc;
                    *k ^= pk;
                }
            }
        }
        let frame_index = core::array::from_fn(|c| {
            let (Some(&f), true) = (frame_cols.get(c), (c as u32) + 2 * m < 32) else {
                return 0;
            };
            product(&comb, f) ^ (1u32 << (2 * m + c as u32))
        });
        Ok(ImageSobol {
            grid,
            randomize,
            seed,
            m,
            frame_cols,
            inverse: comb,
            frame_index,
        })
    }

    /// pbrt's `SobolIntervalToIndex(m, frame, p)`: the Sobol' index of frame `frame` whose
    /// point lies in pixel `(x, y)` of the `2^m` grid (unchecked: `x, y < 2^m`, and
    /// `frame 2^2m < 2^32`).
    #[inline]
    pub fn interval_to_index(&self, frame: u32, x: u32, y: u32) -> u64 {
        let m = self.m;
        if m == 0 {
            return frame as u64;
        }
        // Both products over GF(2) branch-free (32 masked XORs each).
        let delta = product(&self.frame_cols, frame);
        let low = product(&self.inverse, ((x << m) | y) ^ delta);
        ((frame as u64) << (2 * m)) | low as u64
    }

    /// Sobol' dimension `d` of `index` (`2 <= d <` [`IMAGE_SOBOL_DIMS`], so in the table),
    /// scrambled with `low32(Hash(d, seed))`.
    fn dimension(&self, index: u64, d: usize) -> u32 {
        let v = match SobolDimension::new(d) {
            Ok(s) => s.sample(index as u32),
            Err(_) => 0, // unreachable: `counter_dimension` keeps `d` in the table
        };
        match self.randomize {
            Randomization::None => v,
            r => r.apply(v, seed_hash2(d as u32, self.seed) as u32),
        }
    }
}

/// `S(i)`: the XOR of the Sobol' columns `cols[b]` over the set bits `b` of `i` (the
/// matrix-vector product over GF(2)), branch-free.
#[inline(always)]
fn product(cols: &[u32; 32], i: u32) -> u32 {
    cols.iter()
        .enumerate()
        .fold(0, |v, (b, &c)| v ^ (c & 0u32.wrapping_sub((i >> b) & 1)))
}

impl ImageSobol {
    /// The reversed-domain Sobol' values of dimension `d` (`< IMAGE_SOBOL_DIMS`) of samples
    /// `start .. start + out.len()` of the pixel whose frame-0 index is `l0`, into `out`:
    /// the pixel's value, the chunk's high frame bits, then the table doubled over the low
    /// ones.
    #[inline(always)]
    fn reversed_values(&self, d: usize, l0: u32, start: u32, out: &mut [u32]) {
        let cols = match SobolDimension::new(d) {
            Ok(s) => *s.directions(),
            Err(_) => [0; 32], // unreachable: `counter_dimension` keeps `d` in the table
        };
        // Only the sample bits in use: those of the chunk's last sample.
        let last = start.saturating_add(out.len().saturating_sub(1) as u32);
        let bits = (32 - last.leading_zeros()) as usize;
        let mut w = [0u32; 32];
        for (wc, &e) in w.iter_mut().zip(&self.frame_index).take(bits) {
            *wc = reverse_bits(product(&cols, e));
        }
        let v0 = reverse_bits(product(&cols, l0));
        let first = w.iter().take(bits).enumerate().fold(v0, |v, (c, &wc)| {
            v ^ (wc & 0u32.wrapping_sub((start >> c) & 1))
        });
        if let Some(o) = out.first_mut() {
            *o = first;
        }
        // `start` is a multiple of CHUNK, so the low bits of the chunk's samples are `k`.
        let mut len = 1;
        for &wc in &w {
            if len >= out.len() {
                break;
            }
            let (lo, hi) = out.split_at_mut(len);
            let n = len.min(hi.len());
            for (h, &l) in hi[..n].iter_mut().zip(lo.iter()) {
                *h = l ^ wc;
            }
            len *= 2;
        }
    }

    /// The prepared pair fill at dimensions `d, d + 1` (`d` through the counter rule).
    #[inline(always)]
    fn fill_pairs<T>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        out: &mut [[T; 2]],
        conv: impl Fn(u32) -> T + Copy,
    ) -> Result<()> {
        self.grid.check_fill(x, y, out.len())?;
        let d = self.counter_dimension(dim, 2);
        let keys = [
            seed_hash2(d as u32, self.seed) as u32,
            seed_hash2(d.wrapping_add(1) as u32, self.seed) as u32,
        ];
        let l0 = self.interval_to_index(0, x, y) as u32;
        let (mut a_all, mut b_all) = ([0u32; CHUNK], [0u32; CHUNK]);
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let start = (c * CHUNK) as u32;
            let (a, b) = (&mut a_all[..chunk.len()], &mut b_all[..chunk.len()]);
            self.reversed_values(d, l0, start, a);
            self.reversed_values(d.wrapping_add(1), l0, start, b);
            let (a, b) = (&a_all, &b_all);
            randomize_pairs(self.randomize, keys, chunk, |k| [at(a, k), at(b, k)], conv);
        }
        Ok(())
    }

    /// The prepared 1D fill.
    #[inline(always)]
    fn fill_values<T>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        out: &mut [T],
        conv: impl Fn(u32) -> T + Copy,
    ) -> Result<()> {
        self.grid.check_fill(x, y, out.len())?;
        let d = self.counter_dimension(dim, 1);
        let key = seed_hash2(d as u32, self.seed) as u32;
        let l0 = self.interval_to_index(0, x, y) as u32;
        let mut all = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let a = &mut all[..chunk.len()];
            self.reversed_values(d, l0, (c * CHUNK) as u32, a);
            let a = &all;
            randomize_values(self.randomize, key, chunk, |k| at(a, k), conv);
        }
        Ok(())
    }
}

impl PixelSampler for ImageSobol {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
        dispatched(
            #[inline(always)]
            || self.fill_pairs(x, y, dim, out, |v| v),
        )
    }

    fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
        dispatched(
            #[inline(always)]
            || self.fill_pairs(x, y, dim, out, pbrt_f32),
        )
    }

    fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> Result<()> {
        dispatched(
            #[inline(always)]
            || self.fill_values(x, y, dim, out, |v| v),
        )
    }

    fn fill_1d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [f32]) -> Result<()> {
        dispatched(
            #[inline(always)]
            || self.fill_values(x, y, dim, out, pbrt_f32),
        )
    }

    /// The Sobol' index of the sample, `SobolIntervalToIndex(m, index, (x, y))`.
    fn pixel_key(&self, x: u32, y: u32, index: u32) -> u64 {
        self.interval_to_index(index, x, y)
    }

    fn sample_index(&self, at: &PixelPoint, _dim: usize) -> Option<u64> {
        Some(at.key())
    }

    /// pbrt's counter rule: `max(dim, 2)`, and 2 when the request's last dimension,
    /// `dim + width - 1`, reaches [`IMAGE_SOBOL_DIMS`].
    fn counter_dimension(&self, dim: usize, width: usize) -> usize {
        super::global_counter_dimension(dim, width, IMAGE_SOBOL_DIMS)
    }

    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        self.dimension(at.key(), self.counter_dimension(dim, 1))
    }

    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        let d = self.counter_dimension(dim, 2); // d + 1 < IMAGE_SOBOL_DIMS
        [
            self.dimension(at.key(), d),
            self.dimension(at.key(), d.wrapping_add(1)),
        ]
    }

    /// The unscrambled point of dimensions (0, 1) in pixel coordinates as a 0.32 fraction:
    /// `frac(2^m u)`, the bits below the pixel's.
    fn value_pixel_2d(&self, at: &PixelPoint, _dim: usize) -> [u32; 2] {
        let (i, m) = (at.key(), self.m);
        [sobol0(i) << m, sobol1(i) << m] // m <= 16
    }

    /// pbrt's floats: `clamp(float(u) 2^m - p, 0, 1 - 2^-24)` with `float(u)` from
    /// [`pbrt_f32`] (so it can differ from the fraction's conversion in the last bits).
    fn value_pixel_2d_f32(&self, at: &PixelPoint, _dim: usize) -> [f32; 2] {
        let i = at.key();
        let scale = (1u64 << self.m) as f32;
        let f = |u: u32, p: u32| {
            let t = pbrt_f32(u) * scale - p as f32;
            t.clamp(0.0, F32_ONE_MINUS_EPSILON)
        };
        [f(sobol0(i), at.x()), f(sobol1(i), at.y())]
    }

    fn pixel_2d_moves_counter(&self) -> bool {
        false
    }
}
