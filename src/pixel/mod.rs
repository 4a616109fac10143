//! Pixel samplers: the sample values a renderer asks for, as pure functions of
//! `(pixel x, y; sample index; dimension)` and a seed, bit-identical to pbrt-v4's samplers.
//!
//! Validate at the boundary, infallible inside: [`PixelSampler::start_pixel_sample`]`(x, y,
//! i)` is pbrt's `StartPixelSample(p, i)`. It checks the pixel and the index once (the only
//! [`Result`] on the way), does the sampler's per-pixel work once (ZSobol's Morton index,
//! the image-plane Sobol' index, the pixel hash) and returns a [`PixelSample`] handle whose
//! draws cannot fail: [`get_pixel_2d`](PixelSample::get_pixel_2d) (the position in the
//! pixel), [`get_1d`](PixelSample::get_1d), [`get_2d`](PixelSample::get_2d) and their `_f32`
//! forms. The handle keeps pbrt's dimension counter `d`: `get_1d` returns the value at `d`
//! and moves it to `d + 1`, `get_2d` the pair at `d` and moves it to `d + 2` (a 2D request is
//! not aligned: a 1D request then a 2D one reads the pair at dimension 1);
//! [`with_dimension`](PixelSample::with_dimension) sets it (pbrt's `StartPixelSample(p, i,
//! dim)`). Every dimension is answered, as in pbrt: the samplers built on Sobol' dimensions
//! (0, 1) "pad" (every request reuses those two dimensions under a fresh hash of `d`, whose
//! low 32 bits are pbrt's `int` dimension), [`ImageSobol`] wraps to dimension 2 at the end of
//! its table, [`HaltonSampler`] wraps to 2 past its last prime, [`StratifiedSampler`] hashes
//! `d` and reads its PCG32 stream at `65536 i + d`, [`Pmj02BnPixels`] and [`Pmj02Pixels`]
//! hash `d` into a permutation (an index shuffle and scrambles for [`Pmj02Pixels`]).
//!
//! Types: pixel coordinates and the per-pixel sample index are `u32` (the index is the point
//! index, `< spp`), dimensions are `usize` (as [`crate::Sampler`]'s), seeds `u64` (below
//! `2^32` a seed is pbrt's `int` seed as its 32 bits, bit-identical; above, all 64 bits are
//! hashed), values 0.32 fractions (`u32`); the global index into an underlying sequence
//! ([`PixelSample::sample_index`]) is a `u64`, as it can pass `2^32`.
//!
//! | sampler | what it is | global index | per start | per value |
//! |---|---|---|---|---|
//! | [`ZSobol`] | Ahmed & Wonka 2020 blue-noise Sobol': Morton-ordered pixels, hashed base-4 digit permutations | yes (`u64`) | Morton index | `log4(side^2 spp)` MixBits, one MurmurHash, the scramble |
//! | [`ImageSobol`] | pbrt's `SobolSampler`: one Sobol' sequence over the image plane (Grünschloss et al. 2012) | yes | the Sobol' index, `O(m + log2 spp)` XORs | one Sobol' value, one MurmurHash, the scramble |
//! | [`PaddedSobol`] | per pixel and dimension: hashed index permutation and scramble of Sobol' (0, 1) | no | nothing | one MurmurHash, one permutation, the scramble |
//! | [`Pmj02Pixels`] | one shared 65,536-point PMJ02 table (Christensen et al. 2018), per pixel and dimension index-shuffled (a nested scramble of the index) and Owen-scrambled: every power-of-two prefix a (0, m, 2)-net | no | nothing | one MurmurHash, one `MixBits`, three Vegdahl hashes, a table read |
//! | [`Pmj02BnPixels`] | pbrt's `PMJ02BNSampler` layout: one PMJ02BN table bucketed into a pixel tile, permuted blocks plus blue-noise shifts for the other dimensions | no | the tile entry | one MurmurHash, one permutation, two mask reads |
//! | [`HaltonSampler`] | pbrt's `HaltonSampler`: one Halton sequence over the image plane, the pixel's indices by the Chinese remainder theorem | yes | `j + k` digit steps | `~24 / log2 b` digit steps (a hash and a permutation each when randomized) |
//! | [`StratifiedSampler`] | pbrt's `StratifiedSampler`: strata permuted per pixel and dimension, PCG32 jitter | no | the pixel hash | one MurmurHash, one permutation, a PCG32 jump |
//! | [`IndependentPixels`] | independent uniform values from a hash of `(seed, pixel, index, dimension)` | no | the pixel hash | one `hash3` |
//! | [`BlueNoiseSobol`] | Owen-scrambled Sobol' per pixel, keys from an optimized blue-noise tile (Heitz & Belcour 2019; Belcour & Heitz 2021); dimension `d` the [`domain`] `new_domain(d)` | no | nothing | 2 `hash3`, a table read, 3 Vegdahl hashes |
//! | [`BlueNoiseLattice`] | a rank-1 lattice per pixel, Cranley–Patterson shifts from an optimized blue-noise tile (Belcour & Heitz 2021) | no | nothing | 2 `hash3`, a table read, one Vegdahl hash |
//!
//! [`HaltonSampler`] and [`StratifiedSampler`] compute their floats as pbrt does, in `f32`
//! arithmetic ([`PixelSampler::value_1d_f32`]); their 0.32 fractions are the exact values
//! those floats round. [`pbrt_f32`] converts a 0.32 fraction as pbrt does (`min(float(v) * 2^-32, 1 - 2^-24)`);
//! the `*_f32` draws return pbrt's floats. The batch path of one pixel and one dimension
//! over all its samples is [`PixelSampler::fill_2d`] (and `fill_1d`, `fill_2d_f32`,
//! `fill_1d_f32`): every sampler computes what depends only on `(pixel, dimension)` once
//! (hashes, keys, ZSobol's pixel digits, the image-plane Sobol' system, Halton's pixel
//! index and digit tables, the stratified stream's jump) and fills the samples in one pass,
//! the Sobol' samplers in the bit-reversed domain, in the widest vector build the CPU runs
//! (run-time dispatch; the same bits in every build); bit-identical to the handle's draws.
//! `PreparedHalton` (`std`) is a [`HaltonSampler`] with its digit permutations tabulated
//! once for the image, as pbrt's constructor does (the catalog's boxed Halton sampler).
//! [`ZSobol::pixel_dimension`] is the per-sample form of ZSobol's.
//!
//! [`domain`] derives dimensions by key instead of by counter ([`Domain`]: `new_domain(key)`,
//! `split`, `chain`), for path tracers; its bits are documented as stable.
//!
//! A renderer's loop: for each pixel, for each sample, start, then draw.
//!
//! ```
//! use qmckit::pixel::{PixelSampler, Randomization, ZSobol};
//! let (w, h, spp) = (16, 9, 4);
//! let z = ZSobol::new(w, h, spp, Randomization::FastOwen, 0)?;
//! let mut image = vec![0f32; (w * h) as usize];
//! for y in 0..h {
//!     for x in 0..w {
//!         for i in 0..spp {
//!             let mut s = z.start_pixel_sample(x, y, i)?; // the one check
//!             let [fx, fy] = s.get_pixel_2d_f32(); // dimensions 0, 1: film
//!             let [lu, lv] = s.get_2d_f32(); // 2, 3: lens
//!             let t = s.get_1d_f32(); // 4: time
//!             image[(y * w + x) as usize] += (fx + fy + lu + lv + t) / spp as f32;
//!         }
//!     }
//! }
//! // pbrt-v4's check values: pixel (1, 0), one sample a pixel, seed 0.
//! let z1 = ZSobol::new(16, 9, 1, Randomization::FastOwen, 0)?;
//! let mut s = z1.start_pixel_sample(1, 0, 0)?;
//! assert_eq!(s.sample_index(), Some(1));
//! assert_eq!(s.get_1d_f32(), 0.570228934);
//! let mut s = z1.start_pixel_sample(1, 0, 0)?;
//! assert_eq!(s.get_2d_f32(), [0.702183783, 0.853890479]);
//! assert!(z1.start_pixel_sample(16, 0, 0).is_err()); // outside the image
//! # Ok::<(), qmckit::Error>(())
//! ```

mod blue_noise_pixels;
pub mod domain;
mod grid;
mod halton;
mod halton_digits;
#[cfg(feature = "std")]
mod halton_tables;
mod image_sobol;
mod independent;
mod padded;
pub mod pmj02bn;
mod pmj_pixels;
mod prepared;
mod seed_hash;
mod stratified;
mod zsobol;

pub use blue_noise_pixels::{
    BLUE_NOISE_LATTICE_GENERATOR, BLUE_NOISE_LATTICE_SHIFTS, BLUE_NOISE_SOBOL_KEYS,
    BLUE_NOISE_TILE_SIDE, BlueNoiseLattice, BlueNoiseSobol,
};
pub use domain::Domain;
pub use grid::{MAX_SIDE, PixelGrid, PixelPoint};
pub use halton::{HALTON_PIXEL_DIMS, HaltonSampler};
#[cfg(feature = "std")]
pub use halton_tables::PreparedHalton;
pub use image_sobol::{IMAGE_SOBOL_DIMS, ImageSobol, PBRT_SOBOL_DIMS};
pub use independent::IndependentPixels;
pub use padded::PaddedSobol;
pub use pmj_pixels::{PMJ02_TABLE_LEN, Pmj02Pixels, pmj02_table_point};
pub use pmj02bn::Pmj02BnPixels;
#[cfg(feature = "std")]
pub use pmj02bn::Pmj02BnTables;
pub use stratified::StratifiedSampler;
pub use zsobol::{ZSobol, ZSobolPixelDim};

use crate::bits::reverse_bits;
use crate::error::Result;
use crate::randomize::{FastOwenScrambler, OwenHash, PbrtOwenScrambler};
pub(crate) use seed_hash::{seed_hash2, seed_hash4};

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

/// pbrt's counter rule for the global samplers (its `SobolSampler` and `HaltonSampler`),
/// whose first two dimensions place the sample in the pixel: a request of `width` values
/// (1 for `Get1D`, 2 for `Get2D`) with the counter at `dim` reads `max(dim, 2)`, or 2 when
/// its last dimension `max(dim, 2) + width - 1` reaches the table's `dims`. O(1).
pub(crate) const fn global_counter_dimension(dim: usize, width: usize, dims: usize) -> usize {
    let d = if dim < 2 { 2 } else { dim };
    if d.saturating_add(width.saturating_sub(1)) >= dims {
        2
    } else {
        d
    }
}

/// The interface a pixel sampler implements: its grid, its per-pixel precomputation and its
/// draws at a validated [`PixelPoint`]. Renderers use it through the handle
/// [`PixelSample`], made by [`start_pixel_sample`](Self::start_pixel_sample) (see the
/// [module documentation](self)): the only place where anything is checked. The draw
/// methods take a dimension `dim: usize` (the type of [`crate::Sampler`]'s dimensions)
/// and are total: every dimension is answered (see [`counter_dimension`](Self::counter_dimension)).
pub trait PixelSampler {
    /// The image and sample count.
    fn grid(&self) -> PixelGrid;

    /// The per-pixel (and per-sample) precomputation, stored in the [`PixelPoint`]; called
    /// once by [`start_pixel_sample`](Self::start_pixel_sample) after the checks, so
    /// `x < width`, `y < height`, `index < spp`. The default is 0 (nothing to keep).
    fn pixel_key(&self, x: u32, y: u32, index: u32) -> u64 {
        let _ = (x, y, index);
        0
    }

    /// The global index of the sample at dimension `dim`, where the sampler has one (the
    /// index into the underlying sequence, which can pass `u32`), else `None` (the default).
    fn sample_index(&self, at: &PixelPoint, dim: usize) -> Option<u64> {
        let _ = (at, dim);
        None
    }

    /// The dimension a request of `width` values (1 for `Get1D`, 2 for `Get2D`) reads with
    /// the counter at `dim`; [`PixelSample`] moves its counter on from there, as pbrt's
    /// samplers do. `dim` itself (the default) for the samplers whose dimension only feeds
    /// hashes ([`ZSobol`], [`PaddedSobol`], [`Pmj02Pixels`], [`IndependentPixels`]): every
    /// dimension is valid, the hashes read its low 32 bits (pbrt's `int`). [`ImageSobol`]
    /// reads a counter below 2 as 2 and wraps to 2 at the end of its Sobol' table
    /// ([`IMAGE_SOBOL_DIMS`]), [`HaltonSampler`] likewise at [`HALTON_PIXEL_DIMS`];
    /// [`Pmj02BnPixels`] reads a counter below 2 as 2 (pbrt's `max(2, dim)` in
    /// `StartPixelSample`).
    fn counter_dimension(&self, dim: usize, width: usize) -> usize {
        let _ = width;
        dim
    }

    /// The 1D value (0.32 fraction) at dimension `dim` (already through
    /// [`counter_dimension`](Self::counter_dimension)): pbrt's `Get1D`.
    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32;

    /// The 2D value at dimension `dim` (through `counter_dimension`): pbrt's `Get2D`.
    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2];

    /// [`value_1d`](Self::value_1d) as pbrt's `f32`; the default converts with
    /// [`pbrt_f32`]. [`HaltonSampler`] and [`StratifiedSampler`] compute their floats as pbrt
    /// does (radical inverses and strata in `f32` arithmetic), which the 0.32 fraction does
    /// not determine.
    fn value_1d_f32(&self, at: &PixelPoint, dim: usize) -> f32 {
        pbrt_f32(self.value_1d(at, dim))
    }

    /// [`value_2d`](Self::value_2d) as pbrt's `f32`s; the default converts with
    /// [`pbrt_f32`].
    fn value_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
        self.value_2d(at, dim).map(pbrt_f32)
    }

    /// The position in the pixel, `[0, 1)^2`, with the counter at `dim` (pbrt's
    /// `GetPixel2D`); the default is [`value_2d`](Self::value_2d).
    fn value_pixel_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        self.value_2d(at, dim)
    }

    /// [`value_pixel_2d`](Self::value_pixel_2d) as pbrt's `f32`s; the default converts
    /// with [`pbrt_f32`].
    fn value_pixel_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
        self.value_pixel_2d(at, dim).map(pbrt_f32)
    }

    /// Whether pbrt's `GetPixel2D` moves the dimension counter (by 2): true except for
    /// [`ImageSobol`], [`HaltonSampler`] and [`Pmj02BnPixels`], whose pixel positions are
    /// outside the counter.
    fn pixel_2d_moves_counter(&self) -> bool {
        true
    }

    /// The pixel's samples at one dimension pair, prepared: `out[i]` becomes the pair
    /// pbrt's `Get2D` returns for sample `i` of pixel `(x, y)` with the counter at `dim`
    /// (`start_pixel_sample(x, y, i)?.with_dimension(dim).get_2d()`), for `i <
    /// out.len() <= spp`. The samplers override it with one pass over the samples that
    /// computes what depends on `(pixel, dimension)` once (the default runs the handle's
    /// draws). Bit-identical to the handle.
    ///
    /// ```
    /// use qmckit::pixel::{PaddedSobol, PixelSampler, Randomization};
    /// let p = PaddedSobol::new(64, 64, 16, Randomization::FastOwen, 1)?;
    /// let mut out = [[0u32; 2]; 16];
    /// p.fill_2d(9, 40, 6, &mut out)?;
    /// for (i, v) in (0..16).zip(out) {
    ///     assert_eq!(v, p.start_pixel_sample(9, 40, i)?.with_dimension(6).get_2d());
    /// }
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`PixelGrid::check`] for the pixel; [`Error::BufferLength`](crate::Error::BufferLength) when `out` holds
    /// more than `spp` samples.
    fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
        self.grid().check_fill(x, y, out.len())?;
        let d = self.counter_dimension(dim, 2);
        for (i, o) in (0u32..).zip(out.iter_mut()) {
            let at = PixelPoint::new(self, x, y, i);
            *o = self.value_2d(&at, d);
        }
        Ok(())
    }

    /// [`fill_2d`](Self::fill_2d) as pbrt's `f32`s (`get_2d_f32`).
    ///
    /// # Errors
    /// As [`fill_2d`](Self::fill_2d).
    fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
        self.grid().check_fill(x, y, out.len())?;
        let d = self.counter_dimension(dim, 2);
        for (i, o) in (0u32..).zip(out.iter_mut()) {
            let at = PixelPoint::new(self, x, y, i);
            *o = self.value_2d_f32(&at, d);
        }
        Ok(())
    }

    /// The 1D values of the pixel's samples with the counter at `dim`: `out[i]` is
    /// `start_pixel_sample(x, y, i)?.with_dimension(dim).get_1d()`, `i < out.len() <= spp`.
    ///
    /// # Errors
    /// As [`fill_2d`](Self::fill_2d).
    fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> Result<()> {
        self.grid().check_fill(x, y, out.len())?;
        let d = self.counter_dimension(dim, 1);
        for (i, o) in (0u32..).zip(out.iter_mut()) {
            let at = PixelPoint::new(self, x, y, i);
            *o = self.value_1d(&at, d);
        }
        Ok(())
    }

    /// [`fill_1d`](Self::fill_1d) as pbrt's `f32`s (`get_1d_f32`).
    ///
    /// # Errors
    /// As [`fill_2d`](Self::fill_2d).
    fn fill_1d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [f32]) -> Result<()> {
        self.grid().check_fill(x, y, out.len())?;
        let d = self.counter_dimension(dim, 1);
        for (i, o) in (0u32..).zip(out.iter_mut()) {
            let at = PixelPoint::new(self, x, y, i);
            *o = self.value_1d_f32(&at, d);
        }
        Ok(())
    }

    /// pbrt's `StartPixelSample(p, index)`: checks `(x, y)` and `index` once, does the
    /// per-pixel precomputation, and returns the handle whose draws cannot fail, with the
    /// dimension counter at 0 ([`PixelSample::with_dimension`] sets it).
    ///
    /// The handle is typed by the sampler, so its draws inline. A `Box<dyn PixelSampler>`
    /// is a sampler and starts as any other; for a `s: &dyn PixelSampler`, write
    /// `PixelSampler::start_pixel_sample(&s, x, y, i)` (the `&S` implementation: a bare
    /// trait object cannot name its own handle type).
    ///
    /// # Errors
    /// As [`PixelGrid::check`].
    fn start_pixel_sample(&self, x: u32, y: u32, index: u32) -> Result<PixelSample<'_, Self>>
    where
        Self: Sized,
    {
        PixelSample::start(self, x, y, index)
    }
}

/// A borrowed or boxed sampler is a sampler (so `&dyn PixelSampler` and
/// `Box<dyn PixelSampler>` start pixel samples too).
macro_rules! forward_pixel_sampler {
    ($($t:ty),*) => {$(
        impl<S: PixelSampler + ?Sized> PixelSampler for $t {
            fn grid(&self) -> PixelGrid {
                (**self).grid()
            }
            fn pixel_key(&self, x: u32, y: u32, index: u32) -> u64 {
                (**self).pixel_key(x, y, index)
            }
            fn sample_index(&self, at: &PixelPoint, dim: usize) -> Option<u64> {
                (**self).sample_index(at, dim)
            }
            fn counter_dimension(&self, dim: usize, width: usize) -> usize {
                (**self).counter_dimension(dim, width)
            }
            #[inline]
            fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
                (**self).value_1d(at, dim)
            }
            #[inline]
            fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
                (**self).value_2d(at, dim)
            }
            #[inline]
            fn value_1d_f32(&self, at: &PixelPoint, dim: usize) -> f32 {
                (**self).value_1d_f32(at, dim)
            }
            #[inline]
            fn value_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
                (**self).value_2d_f32(at, dim)
            }
            fn value_pixel_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
                (**self).value_pixel_2d(at, dim)
            }
            fn value_pixel_2d_f32(&self, at: &PixelPoint, dim: usize) -> [f32; 2] {
                (**self).value_pixel_2d_f32(at, dim)
            }
            fn pixel_2d_moves_counter(&self) -> bool {
                (**self).pixel_2d_moves_counter()
            }
            fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
                (**self).fill_2d(x, y, dim, out)
            }
            fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
                (**self).fill_2d_f32(x, y, dim, out)
            }
            fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> Result<()> {
                (**self).fill_1d(x, y, dim, out)
            }
            fn fill_1d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [f32]) -> Result<()> {
                (**self).fill_1d_f32(x, y, dim, out)
            }
        }
    )*};
}

forward_pixel_sampler!(&S);
#[cfg(feature = "std")]
forward_pixel_sampler!(std::boxed::Box<S>);

/// One sample of one pixel, validated: pbrt's sampler after `StartPixelSample(p, index)`.
/// Made by [`PixelSampler::start_pixel_sample`]; its draws cannot fail. Each draw reads the
/// dimension at the counter (through [`PixelSampler::counter_dimension`]) and moves the
/// counter on by the values it returns, as pbrt's `Get1D`/`Get2D`/`GetPixel2D` do; the
/// counter wraps at `usize::MAX` instead of overflowing.
///
/// ```
/// use qmckit::pixel::{PixelSampler, Randomization, ZSobol};
/// let z = ZSobol::new(16, 9, 4, Randomization::FastOwen, 0)?;
/// let mut s = z.start_pixel_sample(1, 0, 3)?;
/// let a = s.get_1d();
/// let b = s.get_2d(); // the pair at dimension 1
/// assert_eq!(s.dimension(), 3);
/// let mut t = z.start_pixel_sample(1, 0, 3)?.with_dimension(1);
/// assert_eq!(t.get_2d(), b);
/// assert_eq!(z.start_pixel_sample(1, 0, 3)?.get_1d(), a);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub struct PixelSample<'a, S: PixelSampler + ?Sized> {
    sampler: &'a S,
    at: PixelPoint,
    dim: usize,
}

// By hand: a handle is a reference and two words, `Copy` whatever the sampler is.
impl<S: PixelSampler + ?Sized> Clone for PixelSample<'_, S> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S: PixelSampler + ?Sized> Copy for PixelSample<'_, S> {}

impl<S: PixelSampler + ?Sized> core::fmt::Debug for PixelSample<'_, S> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PixelSample")
            .field("at", &self.at)
            .field("dim", &self.dim)
            .finish()
    }
}

impl<'a, S: PixelSampler + ?Sized> PixelSample<'a, S> {
    /// The checks and the precomputation of [`PixelSampler::start_pixel_sample`].
    fn start(sampler: &'a S, x: u32, y: u32, index: u32) -> Result<Self> {
        sampler.grid().check(x, y, index)?;
        Ok(PixelSample {
            sampler,
            at: PixelPoint::new(sampler, x, y, index),
            dim: 0,
        })
    }

    /// The handle with the dimension counter at `dim` (pbrt's `StartPixelSample(p, index,
    /// dim)`).
    #[must_use]
    pub const fn with_dimension(mut self, dim: usize) -> Self {
        self.dim = dim;
        self
    }

    /// The dimension counter.
    pub const fn dimension(&self) -> usize {
        self.dim
    }

    /// The pixel `(x, y)`.
    pub const fn pixel(&self) -> (u32, u32) {
        (self.at.x(), self.at.y())
    }

    /// The sample index in the pixel.
    pub const fn index(&self) -> u32 {
        self.at.index()
    }

    /// The global index of the sample with the counter where it is (pbrt's
    /// `GetSampleIndex`), where the sampler has one.
    pub fn sample_index(&self) -> Option<u64> {
        self.sampler.sample_index(&self.at, self.dim)
    }

    /// `Get1D`: the value at the counter, which moves by 1.
    #[inline]
    pub fn get_1d(&mut self) -> u32 {
        let d = self.sampler.counter_dimension(self.dim, 1);
        self.dim = d.wrapping_add(1);
        self.sampler.value_1d(&self.at, d)
    }

    /// `Get2D`: the pair at the counter, which moves by 2.
    #[inline]
    pub fn get_2d(&mut self) -> [u32; 2] {
        let d = self.sampler.counter_dimension(self.dim, 2);
        self.dim = d.wrapping_add(2);
        self.sampler.value_2d(&self.at, d)
    }

    /// `GetPixel2D`: the position in the pixel (the counter moves by 2, as in pbrt, except
    /// for [`ImageSobol`], [`HaltonSampler`] and [`Pmj02BnPixels`], whose pixel positions
    /// are separate).
    #[inline]
    pub fn get_pixel_2d(&mut self) -> [u32; 2] {
        let v = self.sampler.value_pixel_2d(&self.at, self.dim);
        self.move_past_pixel_2d();
        v
    }

    /// [`get_1d`](Self::get_1d) as pbrt's `f32` ([`pbrt_f32`]).
    #[inline]
    pub fn get_1d_f32(&mut self) -> f32 {
        let d = self.sampler.counter_dimension(self.dim, 1);
        self.dim = d.wrapping_add(1);
        self.sampler.value_1d_f32(&self.at, d)
    }

    /// [`get_2d`](Self::get_2d) as pbrt's `f32`s.
    #[inline]
    pub fn get_2d_f32(&mut self) -> [f32; 2] {
        let d = self.sampler.counter_dimension(self.dim, 2);
        self.dim = d.wrapping_add(2);
        self.sampler.value_2d_f32(&self.at, d)
    }

    /// [`get_pixel_2d`](Self::get_pixel_2d) as pbrt's `f32`s (for [`ImageSobol`], pbrt's
    /// own conversion in pixel coordinates).
    #[inline]
    pub fn get_pixel_2d_f32(&mut self) -> [f32; 2] {
        let v = self.sampler.value_pixel_2d_f32(&self.at, self.dim);
        self.move_past_pixel_2d();
        v
    }

    fn move_past_pixel_2d(&mut self) {
        if self.sampler.pixel_2d_moves_counter() {
            self.dim = self.dim.wrapping_add(2);
        }
    }
}
