//! Pixel samplers: the sample values a renderer asks for, as pure functions of
//! `(pixel x, y; sample index; dimension)` and a seed, bit-identical to pbrt-v4's samplers.
//!
//! A renderer consumes dimensions in order: for pixel `(x, y)` and sample `i` it asks for a
//! 2D value (the position in the pixel), then 1D and 2D values (lens, time, light, BSDF...).
//! pbrt-v4's samplers keep a dimension counter: `Get1D` returns the value at the current
//! dimension `d` and moves it to `d + 1`; `Get2D` returns a pair and moves it to `d + 2`.
//! [`PixelSampler::get_1d`]`(x, y, i, d)` and [`PixelSampler::get_2d`]`(x, y, i, d)` are
//! those two calls made with the counter at `d`: random access, no state. [`PixelStream`]
//! is the counter, for code written the pbrt way. A 2D request does not realign the counter
//! (a 1D request then a 2D one asks for the pair at dimension 1), and the samplers built on
//! Sobol' dimensions (0, 1) "pad": every request, 1D or 2D, reuses those two dimensions
//! under a fresh scramble, so any number of dimensions is available.
//!
//! | sampler | what it is | global index |
//! |---|---|---|
//! | [`ZSobol`] | Ahmed & Wonka 2020 blue-noise Sobol': Morton-ordered pixels, hashed base-4 digit permutations | yes (`u64`) |
//! | [`ImageSobol`] | pbrt's `SobolSampler`: one Sobol' sequence over the image plane (Grünschloss et al. 2012) | yes |
//! | [`PaddedSobol`] | per pixel and dimension: hashed index permutation and scramble of Sobol' (0, 1) | no |
//! | [`Pmj02Pixels`] | a seeded PMJ02 sequence per pixel and dimension, index permuted (the layout of pbrt's `PMJ02BNSampler`, generated) | no |
//! | [`Pmj02BnPixels`] | pbrt's `PMJ02BNSampler` layout: one PMJ02BN table bucketed into a pixel tile, permuted blocks plus blue-noise shifts for the other dimensions | no |
//! | [`IndependentPixels`] | independent uniform values from a hash of `(seed, pixel, index, dimension)` | no |
//!
//! Values are 0.32 fractions (`u32`); [`pbrt_f32`] converts them as pbrt does
//! (`min(float(v) * 2^-32, 1 - 2^-24)`), and the `*_f32` methods return pbrt's floats.
//!
//! ```
//! use qmckit::pixel::{PixelSampler, Randomization, ZSobol};
//! let z = ZSobol::new(16, 9, 1, Randomization::FastOwen, 0)?;
//! assert_eq!(z.sample_index(1, 0, 0, 0)?, Some(1));
//! assert_eq!(z.get_1d_f32(1, 0, 0, 0)?, 0.570228934);
//! assert_eq!(z.get_2d_f32(1, 0, 0, 0)?, [0.702183783, 0.853890479]);
//! # Ok::<(), qmckit::Error>(())
//! ```

mod image_sobol;
mod independent;
mod padded;
pub mod pmj02bn;
mod pmj_pixels;
mod zsobol;

pub use image_sobol::{IMAGE_SOBOL_DIMS, ImageSobol, PBRT_SOBOL_DIMS};
pub use independent::IndependentPixels;
pub use padded::PaddedSobol;
pub use pmj_pixels::Pmj02Pixels;
pub use pmj02bn::Pmj02BnPixels;
#[cfg(feature = "std")]
pub use pmj02bn::Pmj02BnTables;
pub use zsobol::{ZSobol, ZSobolPixel, ZSobolPixelDim};

use crate::bits::reverse_bits;
use crate::error::{Error, Result};
use crate::randomize::{FastOwenScrambler, OwenHash, PbrtOwenScrambler};

/// How a pbrt sampler randomizes its Sobol' values (pbrt-v4's `RandomizeStrategy`), each keyed
/// by a 32-bit hash of the dimension (and pixel) and the seed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Randomization {
    /// No randomization (`None`).
    None,
    /// XOR with the key, a digital shift (`PermuteDigits`).
    PermuteDigits,
    /// Hash-based Owen scrambling with the reversed Vegdahl hash (`FastOwen`, the default).
    #[default]
    FastOwen,
    /// pbrt's exact Owen scrambling, one hash per bit ([`PbrtOwenScrambler`]).
    Owen,
}

impl Randomization {
    /// The randomized 0.32 fraction `v` under `key`. `const`.
    #[inline]
    pub const fn apply(self, v: u32, key: u32) -> u32 {
        match self {
            Randomization::None => v,
            Randomization::PermuteDigits => v ^ key,
            Randomization::FastOwen => {
                FastOwenScrambler::from_key(key, OwenHash::Vegdahl).scramble(v)
            }
            Randomization::Owen => PbrtOwenScrambler::new(key).scramble(v),
        }
    }
}

/// The largest `f32` below 1, `1 - 2^-24` (pbrt's `FloatOneMinusEpsilon`).
pub const F32_ONE_MINUS_EPSILON: f32 = 0.999_999_94;

/// A 0.32 fraction as pbrt-v4 makes its `f32`: `min(float(v) * 2^-32, 1 - 2^-24)`, with
/// `float(v)` rounded to nearest. (Unlike [`crate::bits::to_f32`], which truncates.)
///
/// ```
/// use qmckit::pixel::pbrt_f32;
/// assert_eq!(pbrt_f32(0x8000_0000), 0.5);
/// assert_eq!(pbrt_f32(u32::MAX), qmckit::pixel::F32_ONE_MINUS_EPSILON);
/// ```
#[inline]
pub const fn pbrt_f32(v: u32) -> f32 {
    let f = v as f32 * (1.0 / 4_294_967_296.0);
    if f < F32_ONE_MINUS_EPSILON {
        f
    } else {
        F32_ONE_MINUS_EPSILON
    }
}

/// Sobol' dimension 0 of a 64-bit index, as pbrt's 52-column `SobolSample`: the bit
/// reversal of the low 32 bits (higher bits have zero columns).
#[inline]
pub const fn sobol0(index: u64) -> u32 {
    reverse_bits(index as u32)
}

/// Sobol' dimension 1 (the Pascal matrix mod 2) of a 64-bit index. By Lucas' theorem
/// column `32 + k` equals column `k` in the top 32 rows, so it is `P(low) ^ P(high)`.
#[inline]
pub const fn sobol1(index: u64) -> u32 {
    let hi = (index >> 32) as u32;
    let lo = pascal(index as u32);
    if hi == 0 { lo } else { lo ^ pascal(hi) }
}

/// The Pascal matrix mod 2 times the bits of `i` (column `k + 1` is `c ^ (c >> 1)` of
/// column `k`, from the top bit), in 5 steps: by
/// Lucas' theorem output bit `31 - j` is the XOR of the bits `k` of `i` with `k ⊇ j` (as
/// 5-bit sets), so on the reversed bits `r` (bit `31 - k` = bit `k` of `i`, Sobol'
/// dimension 0) output bit `P` is the XOR of `r`'s bits at the subsets of `P`: the subset
/// XOR transform, one shift-mask-XOR per bit of the position.
#[inline]
const fn pascal(i: u32) -> u32 {
    let mut v = reverse_bits(i);
    v ^= (v << 1) & 0xaaaa_aaaa;
    v ^= (v << 2) & 0xcccc_cccc;
    v ^= (v << 4) & 0xf0f0_f0f0;
    v ^= (v << 8) & 0xff00_ff00;
    v ^ ((v << 16) & 0xffff_0000)
}

/// An image size and a per-pixel sample count, validated once.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PixelGrid {
    /// Width in pixels, `>= 1`.
    pub width: u32,
    /// Height in pixels, `>= 1`.
    pub height: u32,
    /// Samples per pixel, `>= 1`.
    pub spp: u32,
}

/// The largest image side the pixel samplers accept (pbrt's pixel coordinates are `int`s).
pub const MAX_SIDE: u32 = 1 << 30;

impl PixelGrid {
    /// Validates `1 <= width, height <= 2^30` and `spp >= 1`; `power_of_two` also asks that
    /// `spp` be a power of two.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`] for an empty image or `spp = 0`, [`Error::TooLarge`] for a side
    /// past [`MAX_SIDE`], [`Error::NotPowerOfTwo`].
    pub const fn new(width: u32, height: u32, spp: u32, power_of_two: bool) -> Result<Self> {
        if width == 0 || height == 0 || spp == 0 {
            return Err(Error::ZeroPoints);
        }
        if width > MAX_SIDE || height > MAX_SIDE {
            let side = if width > height { width } else { height };
            return Err(Error::TooLarge {
                what: "pixels on an image side",
                requested: side as u64,
                max: MAX_SIDE as u64,
            });
        }
        if power_of_two && !spp.is_power_of_two() {
            return Err(Error::NotPowerOfTwo { n: spp as u64 });
        }
        Ok(PixelGrid { width, height, spp })
    }

    /// Checks that `(x, y)` is in the image and `index < spp`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a pixel outside the image, [`Error::IndexOutOfRange`]
    /// for a sample index past `spp`.
    #[inline]
    pub const fn check(&self, x: u32, y: u32, index: u32) -> Result<()> {
        if x >= self.width || y >= self.height {
            return Err(Error::InvalidParameter {
                what: "pixel outside the image",
            });
        }
        if index >= self.spp {
            return Err(Error::IndexOutOfRange {
                index: index as u64,
                len: self.spp as u64,
            });
        }
        Ok(())
    }

    /// `RoundUpPow2(max(width, height))`, the side of the square power-of-two grid pbrt's
    /// Sobol' samplers lay over the image.
    pub const fn pow2_side(&self) -> u32 {
        let side = if self.width > self.height {
            self.width
        } else {
            self.height
        };
        side.next_power_of_two()
    }
}

/// The interface of the pixel samplers: pbrt-v4's `Get1D`/`Get2D`/`GetPixel2D` with the
/// dimension counter at `dim`, as pure functions (see the [module documentation](self)).
/// Every method validates its pixel and index and returns an [`Error`] instead of panicking.
pub trait PixelSampler {
    /// The image and sample count.
    fn grid(&self) -> PixelGrid;

    /// The global index of sample `index` of pixel `(x, y)` at dimension `dim`, where the
    /// sampler has one (the index into the underlying sequence), else `None`.
    ///
    /// # Errors
    /// As [`PixelGrid::check`].
    /// The default is `None` after the range check: samplers without a global sequence
    /// (independent, PMJ02 tables) keep it.
    fn sample_index(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<Option<u64>> {
        let _ = dim;
        self.grid().check(x, y, index)?;
        Ok(None)
    }

    /// The 1D value (0.32 fraction) of sample `index` of pixel `(x, y)` with the dimension
    /// counter at `dim` (pbrt's `Get1D`, which then moves the counter to `dim + 1`).
    ///
    /// # Errors
    /// As [`PixelGrid::check`]; [`Error::DimensionOutOfRange`] where dimensions are finite.
    fn get_1d(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<u32>;

    /// The 2D value with the counter at `dim` (pbrt's `Get2D`, then `dim + 2`).
    ///
    /// # Errors
    /// As [`get_1d`](Self::get_1d).
    fn get_2d(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<[u32; 2]>;

    /// The position in the pixel, `[0, 1)^2` (pbrt's `GetPixel2D`, with the counter at
    /// `dim`); the same as [`get_2d`](Self::get_2d) except for [`ImageSobol`].
    ///
    /// # Errors
    /// As [`get_1d`](Self::get_1d).
    fn get_pixel_2d(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<[u32; 2]> {
        self.get_2d(x, y, index, dim)
    }

    /// The dimension a request of `width` values (1 for `Get1D`, 2 for `Get2D`) reads with
    /// the counter at `dim`; [`PixelStream`] moves its counter on from there, as pbrt's
    /// samplers do. `dim` itself, except for [`ImageSobol`], which reads a counter below 2
    /// as 2 and wraps to 2 at the end of its Sobol' table ([`IMAGE_SOBOL_DIMS`]). The
    /// samplers built on Sobol' dimensions (0, 1) ([`ZSobol`], [`PaddedSobol`]) need no
    /// wrap: as in pbrt, their counter only feeds hashes, so every `u32` is a dimension.
    fn counter_dimension(&self, dim: u32, width: u32) -> u32 {
        let _ = width;
        dim
    }

    /// Whether pbrt's `GetPixel2D` moves the dimension counter (by 2): true except for
    /// [`ImageSobol`], whose pixel position uses Sobol' dimensions 0 and 1 outside the counter.
    fn pixel_2d_moves_counter(&self) -> bool {
        true
    }

    /// [`get_1d`](Self::get_1d) as pbrt's `f32` ([`pbrt_f32`]).
    ///
    /// # Errors
    /// As [`get_1d`](Self::get_1d).
    fn get_1d_f32(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<f32> {
        Ok(pbrt_f32(self.get_1d(x, y, index, dim)?))
    }

    /// [`get_2d`](Self::get_2d) as pbrt's `f32`s.
    ///
    /// # Errors
    /// As [`get_1d`](Self::get_1d).
    fn get_2d_f32(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<[f32; 2]> {
        let [a, b] = self.get_2d(x, y, index, dim)?;
        Ok([pbrt_f32(a), pbrt_f32(b)])
    }

    /// [`get_pixel_2d`](Self::get_pixel_2d) as pbrt's `f32`s.
    ///
    /// # Errors
    /// As [`get_1d`](Self::get_1d).
    fn get_pixel_2d_f32(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<[f32; 2]> {
        let [a, b] = self.get_pixel_2d(x, y, index, dim)?;
        Ok([pbrt_f32(a), pbrt_f32(b)])
    }

    /// The 1D values at `dim` of samples `0, 1, ...` of pixel `(x, y)` into `out`
    /// (`out.len() <= spp`).
    ///
    /// # Errors
    /// [`Error::BufferLength`] if `out` is longer than `spp`; as [`get_1d`](Self::get_1d).
    fn fill_1d(&self, x: u32, y: u32, dim: u32, out: &mut [u32]) -> Result<()> {
        check_len(self.grid(), out.len())?;
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = self.get_1d(x, y, i as u32, dim)?;
        }
        Ok(())
    }

    /// The 2D values at `dim` of samples `0, 1, ...` of pixel `(x, y)` into `out`.
    ///
    /// # Errors
    /// As [`fill_1d`](Self::fill_1d).
    fn fill_2d(&self, x: u32, y: u32, dim: u32, out: &mut [[u32; 2]]) -> Result<()> {
        check_len(self.grid(), out.len())?;
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = self.get_2d(x, y, i as u32, dim)?;
        }
        Ok(())
    }

    /// [`fill_2d`](Self::fill_2d) as pbrt's `f32`s.
    ///
    /// # Errors
    /// As [`fill_1d`](Self::fill_1d).
    fn fill_2d_f32(&self, x: u32, y: u32, dim: u32, out: &mut [[f32; 2]]) -> Result<()> {
        check_len(self.grid(), out.len())?;
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = self.get_2d_f32(x, y, i as u32, dim)?;
        }
        Ok(())
    }
}

/// Refuses a per-pixel fill longer than the pixel's sample count.
const fn check_len(grid: PixelGrid, len: usize) -> Result<()> {
    if len as u64 > grid.spp as u64 {
        return Err(Error::BufferLength {
            expected: grid.spp as usize,
            got: len,
        });
    }
    Ok(())
}

/// pbrt's stateful sampler on top of a [`PixelSampler`]: `start(x, y, index, dim)` then
/// `next_1d` / `next_2d` / `next_pixel_2d`, each moving the dimension counter by one or two.
///
/// ```
/// use qmckit::pixel::{PixelSampler, PixelStream, Randomization, ZSobol};
/// let z = ZSobol::new(16, 9, 4, Randomization::FastOwen, 0)?;
/// let mut s = PixelStream::start(&z, 1, 0, 3, 0)?;
/// let a = s.next_1d()?;
/// let b = s.next_2d()?; // the pair at dimension 1
/// assert_eq!((a, b), (z.get_1d(1, 0, 3, 0)?, z.get_2d(1, 0, 3, 1)?));
/// assert_eq!(s.dimension(), 3);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct PixelStream<'a, S: PixelSampler + ?Sized> {
    sampler: &'a S,
    x: u32,
    y: u32,
    index: u32,
    dim: u32,
}

impl<'a, S: PixelSampler + ?Sized> PixelStream<'a, S> {
    /// pbrt's `StartPixelSample(p, index, dim)`.
    ///
    /// # Errors
    /// As [`PixelGrid::check`].
    pub fn start(sampler: &'a S, x: u32, y: u32, index: u32, dim: u32) -> Result<Self> {
        sampler.grid().check(x, y, index)?;
        Ok(PixelStream {
            sampler,
            x,
            y,
            index,
            dim,
        })
    }

    /// The dimension counter.
    pub const fn dimension(&self) -> u32 {
        self.dim
    }

    /// Moves the counter by `by`, refusing to wrap.
    fn advance(&mut self, by: u32) -> Result<u32> {
        let d = self.dim;
        self.dim = d.checked_add(by).ok_or(Error::DimensionOutOfRange {
            dim: d as usize,
            dims: u32::MAX as usize,
        })?;
        Ok(d)
    }

    /// `Get1D`: the value at the counter, which moves by 1.
    ///
    /// # Errors
    /// As [`PixelSampler::get_1d`].
    pub fn next_1d(&mut self) -> Result<u32> {
        let d = self.sampler.counter_dimension(self.dim, 1);
        let v = self.sampler.get_1d(self.x, self.y, self.index, d)?;
        self.dim = d;
        self.advance(1)?;
        Ok(v)
    }

    /// `Get2D`: the pair at the counter, which moves by 2.
    ///
    /// # Errors
    /// As [`PixelSampler::get_2d`].
    pub fn next_2d(&mut self) -> Result<[u32; 2]> {
        let d = self.sampler.counter_dimension(self.dim, 2);
        let v = self.sampler.get_2d(self.x, self.y, self.index, d)?;
        self.dim = d;
        self.advance(2)?;
        Ok(v)
    }

    /// `GetPixel2D`: the position in the pixel (the counter moves by 2, as in pbrt, except
    /// for [`ImageSobol`], whose pixel dimensions are separate and do not move it).
    ///
    /// # Errors
    /// As [`PixelSampler::get_pixel_2d`].
    pub fn next_pixel_2d(&mut self) -> Result<[u32; 2]> {
        let v = self
            .sampler
            .get_pixel_2d(self.x, self.y, self.index, self.dim)?;
        if !self.sampler.pixel_2d_moves_counter() {
            return Ok(v);
        }
        self.advance(2)?;
        Ok(v)
    }
}
