//! Blue-noise Sobol' by Morton-ordered, hashed base-4 digit permutations (Ahmed & Wonka 2020,
//! "Screen-space blue-noise diffusion of Monte Carlo sampling error via hierarchical ordering
//! of pixels"), bit-identical to pbrt-v4's `ZSobolSampler`.

use super::{PixelGrid, PixelSampler, Randomization, sobol0, sobol1};
use crate::error::{Error, Result};
use crate::hash::pbrt::{hash2, mix_bits};

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
/// dimensions (0, 1) (2D) scrambled with `Hash(d + 1, seed)` or `Hash(d + 2, seed)`.
///
/// So each pixel's `spp` indices form one aligned block, distinct pixels get distinct
/// blocks, and neighbouring pixels get well-spread points of one (0, 2)-sequence: the error
/// is blue noise across the image. Any resolution (`RoundUpPow2(max(w, h))` sets the digit
/// count), power-of-two `spp`, `2 log2(side) + log2(spp) <= 64`.
/// Cost: per value, `log4(side^2 spp)` [`mix_bits`] plus one MurmurHash and the scramble.
///
/// ```
/// use qmckit::pixel::{PixelSampler, Randomization, ZSobol};
/// let z = ZSobol::new(16, 9, 4, Randomization::FastOwen, 0)?;
/// assert_eq!(z.sample_index(1, 0, 3, 0)?, Some(4));
/// assert_eq!(z.get_1d_f32(1, 0, 3, 0)?, 0.336978048);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ZSobol {
    grid: PixelGrid,
    randomize: Randomization,
    seed: u32,
    log2_spp: u32,
    digits: u32,
}

impl ZSobol {
    /// The sampler of a `width x height` image with `spp` samples a pixel (a power of two).
    /// `seed` is pbrt's `int` seed, as its 32 bits.
    ///
    /// # Errors
    /// As [`PixelGrid::new`]; [`Error::TooLarge`] when the Morton index would pass 64 bits.
    pub const fn new(
        width: u32,
        height: u32,
        spp: u32,
        randomize: Randomization,
        seed: u32,
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
    pub const fn permuted_index(&self, morton: u64, dim: u32) -> u64 {
        let salt = Self::salt(dim);
        let low = self.low_digits();
        self.permute_digits(morton, salt, low, self.digits) | self.permute_low(morton, salt)
    }

    /// pbrt's salt of dimension `dim`: `0x55555555 * dim` as a `u32`, zero-extended.
    #[inline]
    const fn salt(dim: u32) -> u64 {
        0x5555_5555u32.wrapping_mul(dim) as u64
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

    /// The 1D value at a prepared Morton index (no checks).
    #[inline]
    fn value_1d(&self, morton: u64, dim: u32) -> u32 {
        let index = self.permuted_index(morton, dim);
        let key = hash2(dim.wrapping_add(1), self.seed) as u32;
        self.randomize.apply(sobol0(index), key)
    }

    /// The 2D value at a prepared Morton index (no checks).
    #[inline]
    fn value_2d(&self, morton: u64, dim: u32) -> [u32; 2] {
        let index = self.permuted_index(morton, dim);
        let h = hash2(dim.wrapping_add(2), self.seed);
        [
            self.randomize.apply(sobol0(index), h as u32),
            self.randomize.apply(sobol1(index), (h >> 32) as u32),
        ]
    }

    /// Pixel `(x, y)` prepared for its samples: the Morton code computed once.
    ///
    /// # Errors
    /// As [`PixelGrid::check`].
    pub const fn pixel(&self, x: u32, y: u32) -> Result<ZSobolPixel<'_>> {
        if let Err(e) = self.grid.check(x, y, 0) {
            return Err(e);
        }
        Ok(ZSobolPixel {
            sampler: self,
            base: self.morton(x, y, 0),
        })
    }
}

/// One pixel of a [`ZSobol`] sampler, for the fast per-sample calls.
#[derive(Clone, Copy, Debug)]
pub struct ZSobolPixel<'a> {
    sampler: &'a ZSobol,
    base: u64,
}

impl ZSobolPixel<'_> {
    /// The 1D value of sample `index` at dimension `dim`; `index` is reduced modulo `spp`.
    #[inline]
    pub fn get_1d(&self, index: u32, dim: u32) -> u32 {
        let i = index & (self.sampler.grid.spp - 1);
        self.sampler.value_1d(self.base | i as u64, dim)
    }

    /// The 2D value of sample `index` at dimension `dim`; `index` is reduced modulo `spp`.
    #[inline]
    pub fn get_2d(&self, index: u32, dim: u32) -> [u32; 2] {
        let i = index & (self.sampler.grid.spp - 1);
        self.sampler.value_2d(self.base | i as u64, dim)
    }
}

impl<'a> ZSobolPixel<'a> {
    /// The pixel prepared for the samples of one dimension counter `dim`: the permuted
    /// digits of the pixel's part of the Morton index (all but the lowest
    /// `ceil(log2(spp) / 2)` digits) and the scramble keys `Hash(dim + 1, seed)`,
    /// `Hash(dim + 2, seed)` computed once, so a sample costs `ceil(log4 spp)` [`mix_bits`]
    /// and the scramble instead of `log4(side^2 spp)` and a MurmurHash. Bit-identical to
    /// [`ZSobol::get_1d`] and [`ZSobol::get_2d`].
    ///
    /// ```
    /// use qmckit::pixel::{PixelSampler, Randomization, ZSobol};
    /// let z = ZSobol::new(1920, 1080, 16, Randomization::FastOwen, 3)?;
    /// let d = z.pixel(700, 300)?.dim(4);
    /// for i in 0..16 {
    ///     assert_eq!(d.get_2d(i), z.get_2d(700, 300, i, 4)?);
    ///     assert_eq!(d.get_1d(i), z.get_1d(700, 300, i, 4)?);
    /// }
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    #[inline]
    pub fn dim(&self, dim: u32) -> ZSobolPixelDim<'a> {
        let z = self.sampler;
        let salt = ZSobol::salt(dim);
        ZSobolPixelDim {
            sampler: z,
            base: self.base,
            salt,
            high: z.permute_digits(self.base, salt, z.low_digits(), z.digits),
            key1: hash2(dim.wrapping_add(1), z.seed) as u32,
            key2: hash2(dim.wrapping_add(2), z.seed),
        }
    }
}

/// One pixel and dimension counter of a [`ZSobol`] sampler, prepared by
/// [`ZSobolPixel::dim`].
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
    pub fn sample_index(&self, index: u32) -> u64 {
        let z = self.sampler;
        let morton = self.base | (index & (z.grid.spp - 1)) as u64;
        self.high | z.permute_low(morton, self.salt)
    }

    /// The 1D value of sample `index` (reduced modulo `spp`).
    #[inline]
    pub fn get_1d(&self, index: u32) -> u32 {
        let z = self.sampler;
        z.randomize
            .apply(sobol0(self.sample_index(index)), self.key1)
    }

    /// The 2D value of sample `index` (reduced modulo `spp`).
    #[inline]
    pub fn get_2d(&self, index: u32) -> [u32; 2] {
        let z = self.sampler;
        let i = self.sample_index(index);
        [
            z.randomize.apply(sobol0(i), self.key2 as u32),
            z.randomize.apply(sobol1(i), (self.key2 >> 32) as u32),
        ]
    }
}

impl PixelSampler for ZSobol {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    fn sample_index(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<Option<u64>> {
        self.grid.check(x, y, index)?;
        Ok(Some(self.permuted_index(self.morton(x, y, index), dim)))
    }

    fn get_1d(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<u32> {
        self.grid.check(x, y, index)?;
        Ok(self.value_1d(self.morton(x, y, index), dim))
    }

    fn get_2d(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<[u32; 2]> {
        self.grid.check(x, y, index)?;
        Ok(self.value_2d(self.morton(x, y, index), dim))
    }
}
