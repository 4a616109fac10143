//! Blue-noise Sobol' by Morton-ordered, hashed base-4 digit permutations (Ahmed & Wonka 2020,
//! "Screen-space blue-noise diffusion of Monte Carlo sampling error via hierarchical ordering
//! of pixels"), bit-identical to pbrt-v4's `ZSobolSampler`.

use super::prepared::{CHUNK, at, dispatched, randomize_pairs, randomize_values, sobol1_reversed};
use super::{
    PixelGrid, PixelPoint, PixelSampler, Randomization, pbrt_f32, seed_hash2, sobol0, sobol1,
};
use crate::error::{Error, Result};
use crate::hash::pbrt::mix_bits;

/// The 24 permutations of `(0, 1, 2, 3)` in pbrt-v4's order: row `6a + 2b + c` is the
/// identity after swapping positions `(0, a)`, then `(1, 1 + b)`, then `(2, 2 + c)`.
pub const PERMUTATIONS_24: [[u8; 4]; 24] = {
    let mut out = [[0u8; 4]; 24];
    let mut r = 0;
    while r < 24 {
        let (a, b, c) = (r / 6, (r / 2) % 3, r % 2);
        let mut p = [0u8, 1, 2, 3];
        let t = p[0];
        p[0] = p[a];
        p[a] = t;
        let t = p[1];
        p[1] = p[1 + b];
        p[1 + b] = t;
        let t = p[2];
        p[2] = p[2 + c];
        p[2 + c] = t;
        out[r] = p;
        r += 1;
    }
    out
};

/// The 32 bits of `v` moved to the even bit positions of a `u64` (pbrt's `LeftShift2`).
const fn spread(v: u32) -> u64 {
    let mut x = v as u64;
    x = (x ^ (x << 16)) & 0x0000_ffff_0000_ffff;
    x = (x ^ (x << 8)) & 0x00ff_00ff_00ff_00ff;
    x = (x ^ (x << 4)) & 0x0f0f_0f0f_0f0f_0f0f;
    x = (x ^ (x << 2)) & 0x3333_3333_3333_3333;
    (x ^ (x << 1)) & 0x5555_5555_5555_5555
}

/// pbrt-v4's `ZSobolSampler`: sample `i` of pixel `p` is Sobol' point `Z(p, i, d)` where the
/// Morton index `(EncodeMorton2(p.x, p.y) << log2(spp)) | i` has each base-4 digit permuted by
/// one of 24 permutations chosen by `MixBits(higher digits ^ 0x55555555 * d) >> 24 mod 24`
/// (a random quadtree permutation, re-drawn per dimension `d`); an odd `log2(spp)` leaves a
/// last binary digit, flipped by one hash bit. Values are Sobol' dimension 0 (1D) or
/// dimensions (0, 1) (2D) scrambled with `Hash(d + 1, seed)` or `Hash(d + 2, seed)`. The
/// dimension only feeds hashes (its low 32 bits, pbrt's `int`), so every dimension is valid.
///
/// So each pixel's `spp` indices form one aligned block, distinct pixels get distinct
/// blocks, and neighbouring pixels get well-spread points of one (0, 2)-sequence: the error
/// is blue noise across the image. Any resolution (`RoundUpPow2(max(w, h))` sets the digit
/// count), power-of-two `spp`, `2 log2(side) + log2(spp) <= 64`.
/// Cost: the Morton index once per [`start_pixel_sample`](PixelSampler::start_pixel_sample);
/// per value, `log4(side^2 spp)` [`mix_bits`] plus one MurmurHash and the scramble. The
/// prepared fills ([`PixelSampler::fill_2d`]) permute the pixel's digits and hash the
/// keys once per pixel and dimension, then the sample digits as a tree (`ceil(spp / 3)`
/// [`mix_bits`] for the pixel's `spp` samples, plus `spp` more for the last bit of an odd
/// `log2(spp)`), and scramble in the bit-reversed domain (Sobol' dimension 0 reversed is
/// the index itself): about `1/3` of a [`mix_bits`] and two bit reversals a 2D value.
///
/// ```
/// use qmckit::pixel::{PixelSampler, Randomization, ZSobol};
/// let z = ZSobol::new(16, 9, 4, Randomization::FastOwen, 0)?;
/// let mut s = z.start_pixel_sample(1, 0, 3)?;
/// assert_eq!(s.sample_index(), Some(4));
/// assert_eq!(s.get_1d_f32(), 0.336978048);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ZSobol {
    grid: PixelGrid,
    randomize: Randomization,
    seed: u64,
    log2_spp: u32,
    digits: u32,
}

impl ZSobol {
    /// The sampler of a `width x height` image with `spp` samples a pixel (a power of two).
    /// Below `2^32` the `seed` is pbrt's `int` seed as its 32 bits (bit-identical); a larger
    /// seed is hashed with all its 64 bits.
    ///
    /// # Errors
    /// As [`PixelGrid::new`]; [`Error::TooLarge`] when the Morton index would pass 64 bits.
    pub const fn new(
        width: u32,
        height: u32,
        spp: u32,
        randomize: Randomization,
        seed: u64,
    ) -> Result<Self> {
        let grid = match PixelGrid::new(width, height, spp, true) {
            Ok(g) => g,
            Err(e) => return Err(e),
        };
        let log2_spp = spp.trailing_zeros();
        let digits = grid.pow2_side().trailing_zeros() + log2_spp.div_ceil(2);
        let bits = 2 * digits - (log2_spp & 1);
        if bits > 64 {
            return Err(Error::TooLarge {
                what: "bits of the Morton sample index",
                requested: bits as u64,
                max: 64,
            });
        }
        Ok(ZSobol {
            grid,
            randomize,
            seed,
            log2_spp,
            digits,
        })
    }

    /// pbrt's `EncodeMorton2(x, y)`: `x` in the even bits, `y` in the odd bits.
    ///
    /// ```
    /// use qmckit::pixel::ZSobol;
    /// assert_eq!(ZSobol::morton2(1, 0), 1);
    /// assert_eq!(ZSobol::morton2(0, 1), 2);
    /// assert_eq!(ZSobol::morton2(3, 5), 0b10_01_11);
    /// ```
    pub const fn morton2(x: u32, y: u32) -> u64 {
        (spread(y) << 1) | spread(x)
    }

    /// The randomization.
    pub const fn randomization(&self) -> Randomization {
        self.randomize
    }

    /// The Morton index of sample `index` of pixel `(x, y)` (unchecked arguments).
    #[inline]
    const fn morton(&self, x: u32, y: u32, index: u32) -> u64 {
        (Self::morton2(x, y) << self.log2_spp) | index as u64
    }

    /// pbrt's `GetSampleIndex` for a Morton index at dimension `dim`: the permuted base-4
    /// digits (plus the hashed last bit when `log2(spp)` is odd).
    #[inline]
    pub const fn permuted_index(&self, morton: u64, dim: usize) -> u64 {
        let salt = Self::salt(dim);
        let low = self.low_digits();
        self.permute_digits(morton, salt, low, self.digits) | self.permute_low(morton, salt)
    }

    /// pbrt's salt of dimension `dim`: `0x55555555 * dim` as a `u32` (of the low 32 bits of
    /// `dim`, pbrt's `int`), zero-extended.
    #[inline]
    const fn salt(dim: usize) -> u64 {
        0x5555_5555u32.wrapping_mul(dim as u32) as u64
    }

    /// The scramble key of a 1D value at `dim`: `low32(Hash(dim + 1, seed))`.
    #[inline]
    const fn key_1d(&self, dim: usize) -> u32 {
        seed_hash2((dim as u32).wrapping_add(1), self.seed) as u32
    }

    /// The scramble keys of a 2D value at `dim`: `Hash(dim + 2, seed)`.
    #[inline]
    const fn key_2d(&self, dim: usize) -> u64 {
        seed_hash2((dim as u32).wrapping_add(2), self.seed)
    }

    /// The number of base-4 digits that hold bits of the sample index (`ceil(log2(spp) / 2)`);
    /// the digits above them, and the nodes that permute them, depend on the pixel only.
    #[inline]
    const fn low_digits(&self) -> u32 {
        self.log2_spp.div_ceil(2)
    }

    /// The permuted digits `from..to` (the bits `2 i - odd ..` of digit `i`) of `morton`.
    #[inline]
    const fn permute_digits(&self, morton: u64, salt: u64, from: u32, to: u32) -> u64 {
        let odd = self.log2_spp & 1;
        let from = if from > odd { from } else { odd };
        let mut index = 0u64;
        let mut i = to;
        while i > from {
            i -= 1;
            let shift = 2 * i - odd;
            let digit = ((morton >> shift) & 3) as usize;
            let higher = match morton.checked_shr(shift + 2) {
                Some(h) => h,
                None => 0,
            };
            let p = ((mix_bits(higher ^ salt) >> 24) % 24) as usize;
            index |= (PERMUTATIONS_24[p][digit] as u64) << shift;
        }
        index
    }

    /// The permuted digits below [`low_digits`](Self::low_digits), with the hashed last
    /// bit of an odd `log2(spp)`: the part of the index that changes with the sample.
    #[inline]
    const fn permute_low(&self, morton: u64, salt: u64) -> u64 {
        let mut index = self.permute_digits(morton, salt, 0, self.low_digits());
        if self.log2_spp & 1 == 1 {
            index |= (morton & 1) ^ (mix_bits((morton >> 1) ^ salt) & 1);
        }
        index
    }

    /// Pixel `(x, y)` and dimension `dim` prepared for all its samples: the permuted
    /// digits of the pixel's part of the Morton index (all but the lowest
    /// `ceil(log2(spp) / 2)` digits) and the scramble keys `Hash(dim + 1, seed)`,
    /// `Hash(dim + 2, seed)` computed once, so a sample costs `ceil(log4 spp)` [`mix_bits`]
    /// and the scramble instead of `log4(side^2 spp)` and a MurmurHash. The batch path
    /// (one dimension, every sample of a pixel); bit-identical to the handle's draws.
    ///
    /// ```
    /// use qmckit::pixel::{PixelSampler, Randomization, ZSobol};
    /// let z = ZSobol::new(1920, 1080, 16, Randomization::FastOwen, 3)?;
    /// let d = z.pixel_dimension(700, 300, 4)?;
    /// for i in 0..16 {
    ///     let mut s = z.start_pixel_sample(700, 300, i)?.with_dimension(4);
    ///     let mut t = s;
    ///     assert_eq!(d.get_2d(i), s.get_2d());
    ///     assert_eq!(d.get_1d(i), t.get_1d());
    /// }
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`PixelGrid::check`] (with sample index 0).
    pub const fn pixel_dimension(&self, x: u32, y: u32, dim: usize) -> Result<ZSobolPixelDim<'_>> {
        if let Err(e) = self.grid.check(x, y, 0) {
            return Err(e);
        }
        let base = self.morton(x, y, 0);
        let salt = Self::salt(dim);
        Ok(ZSobolPixelDim {
            sampler: self,
            base,
            salt,
            high: self.permute_digits(base, salt, self.low_digits(), self.digits),
            key1: self.key_1d(dim),
            key2: self.key_2d(dim),
        })
    }
}

/// One pixel and dimension of a [`ZSobol`] sampler, prepared by [`ZSobol::pixel_dimension`].
#[derive(Clone, Copy, Debug)]
pub struct ZSobolPixelDim<'a> {
    sampler: &'a ZSobol,
    base: u64,
    salt: u64,
    high: u64,
    key1: u32,
    key2: u64,
}

impl ZSobolPixelDim<'_> {
    /// pbrt's `GetSampleIndex` of sample `index` (reduced modulo `spp`).
    #[inline]
    pub const fn sample_index(&self, index: u32) -> u64 {
        let z = self.sampler;
        let morton = self.base | (index & (z.grid.spp - 1)) as u64;
        self.high | z.permute_low(morton, self.salt)
    }

    /// The 1D value of sample `index` (reduced modulo `spp`).
    #[inline]
    pub const fn get_1d(&self, index: u32) -> u32 {
        let z = self.sampler;
        z.randomize
            .apply(sobol0(self.sample_index(index)), self.key1)
    }

    /// The 2D value of sample `index` (reduced modulo `spp`).
    #[inline]
    pub const fn get_2d(&self, index: u32) -> [u32; 2] {
        let z = self.sampler;
        let i = self.sample_index(index);
        [
            z.randomize.apply(sobol0(i), self.key2 as u32),
            z.randomize.apply(sobol1(i), (self.key2 >> 32) as u32),
        ]
    }
}

impl ZSobol {
    /// The sample part of the permuted Morton indices (the digits below
    /// [`low_digits`](Self::low_digits), with the hashed last bit of an odd `log2(spp)`)
    /// of samples `start .. start + out.len()` of the pixel whose Morton index is `base`
    /// (its low `log2 spp` bits zero), into `out`. Digit `i` of every sample in a block of
    /// `4^(i+1)` samples (shift `2 i - odd`) is permuted by the same hashed permutation,
    /// so each block costs one [`mix_bits`] and each of its four digit values one masked
    /// OR over a run of samples: no data-dependent branch.
    #[inline(always)]
    fn low_indices(&self, base: u64, salt: u64, start: u32, out: &mut [u32]) {
        out.iter_mut().for_each(|o| *o = 0);
        let odd = self.log2_spp & 1;
        let (start, end) = (start as u64, start as u64 + out.len() as u64);
        let mut i = self.low_digits();
        while i > odd {
            i -= 1;
            let shift = 2 * i - odd;
            let seg = 1u64 << shift;
            let mut b0 = start & !((seg << 2) - 1);
            while b0 < end {
                let higher = (base | b0) >> (shift + 2);
                let row = &PERMUTATIONS_24[((mix_bits(higher ^ salt) >> 24) % 24) as usize];
                for (digit, &v) in row.iter().enumerate() {
                    let s0 = b0 + digit as u64 * seg;
                    let lo = s0.max(start).min(end) - start;
                    let hi = (s0 + seg).max(start).min(end) - start;
                    let v = (v as u32) << shift;
                    if let Some(run) = out.get_mut(lo as usize..hi as usize) {
                        run.iter_mut().for_each(|o| *o |= v);
                    }
                }
                b0 += seg << 2;
            }
        }
        if odd == 1 {
            for (k, o) in out.iter_mut().enumerate() {
                let m = base | (start + k as u64);
                *o |= ((m & 1) ^ (mix_bits((m >> 1) ^ salt) & 1)) as u32;
            }
        }
    }

    /// The prepared fills' per-pixel part: the Morton base, the salt and the permuted
    /// pixel digits as reversed-domain constants of Sobol' dimensions 0 and 1.
    #[inline(always)]
    fn pixel_constants(&self, x: u32, y: u32, dim: usize) -> (u64, u64, [u32; 2]) {
        let base = self.morton(x, y, 0);
        let salt = Self::salt(dim);
        let high = self.permute_digits(base, salt, self.low_digits(), self.digits);
        // Sobol' 0 reversed is the low 32 bits of the index; Sobol' 1 reversed is linear.
        let r1 = sobol1_reversed(high as u32) ^ sobol1_reversed((high >> 32) as u32);
        (base, salt, [high as u32, r1])
    }

    /// The prepared pair fill, converted by `conv`.
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
        let (base, salt, [c0, c1]) = self.pixel_constants(x, y, dim);
        let h = self.key_2d(dim);
        let keys = [h as u32, (h >> 32) as u32];
        let mut low_all = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let low = &mut low_all[..chunk.len()];
            self.low_indices(base, salt, (c * CHUNK) as u32, low);
            let low = &low_all;
            randomize_pairs(
                self.randomize,
                keys,
                chunk,
                |k| {
                    let l = at(low, k);
                    [c0 | l, c1 ^ sobol1_reversed(l)]
                },
                conv,
            );
        }
        Ok(())
    }

    /// The prepared 1D fill, converted by `conv`.
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
        let (base, salt, [c0, _]) = self.pixel_constants(x, y, dim);
        let key = self.key_1d(dim);
        let mut low_all = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let low = &mut low_all[..chunk.len()];
            self.low_indices(base, salt, (c * CHUNK) as u32, low);
            let low = &low_all;
            randomize_values(self.randomize, key, chunk, |k| c0 | at(low, k), conv);
        }
        Ok(())
    }
}

impl PixelSampler for ZSobol {
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

    /// The Morton index `(EncodeMorton2(x, y) << log2 spp) | index`.
    fn pixel_key(&self, x: u32, y: u32, index: u32) -> u64 {
        self.morton(x, y, index)
    }

    fn sample_index(&self, at: &PixelPoint, dim: usize) -> Option<u64> {
        Some(self.permuted_index(at.key(), dim))
    }

    #[inline]
    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        let index = self.permuted_index(at.key(), dim);
        self.randomize.apply(sobol0(index), self.key_1d(dim))
    }

    #[inline]
    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        let index = self.permuted_index(at.key(), dim);
        let h = self.key_2d(dim);
        [
            self.randomize.apply(sobol0(index), h as u32),
            self.randomize.apply(sobol1(index), (h >> 32) as u32),
        ]
    }
}
