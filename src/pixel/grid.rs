//! The image and its samples: [`PixelGrid`] (an image size and a per-pixel sample count,
//! validated once) and [`PixelPoint`] (one validated pixel sample with its sampler's
//! per-pixel key).

use super::PixelSampler;
use crate::error::{Error, Result};

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

    /// Checks that `(x, y)` is in the image and that `count <= spp` samples are asked for
    /// (the fill paths' one check).
    ///
    /// # Errors
    /// As [`check`](Self::check); [`Error::BufferLength`] for `count > spp`.
    #[inline]
    pub const fn check_fill(&self, x: u32, y: u32, count: usize) -> Result<()> {
        if let Err(e) = self.check(x, y, 0) {
            return Err(e);
        }
        if count > self.spp as usize {
            return Err(Error::BufferLength {
                expected: self.spp as usize,
                got: count,
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

/// A pixel sample validated by [`PixelSampler::start_pixel_sample`]: the pixel, the sample
/// index and the sampler's per-pixel precomputation (`key`: ZSobol's Morton index, the
/// image-plane Sobol' index, the independent sampler's pixel hash, a PMJ02BN tile entry).
/// Only a start makes one, so a [`PixelSampler`]'s draws given a `PixelPoint` need no checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PixelPoint {
    x: u32,
    y: u32,
    index: u32,
    key: u64,
}

impl PixelPoint {
    /// The point of sample `index` of pixel `(x, y)` with the sampler's key, unchecked (the
    /// fill paths check the pixel and the count once).
    #[inline]
    pub(super) fn new<S: PixelSampler + ?Sized>(sampler: &S, x: u32, y: u32, index: u32) -> Self {
        PixelPoint {
            x,
            y,
            index,
            key: sampler.pixel_key(x, y, index),
        }
    }

    /// The pixel's column.
    pub const fn x(&self) -> u32 {
        self.x
    }

    /// The pixel's row.
    pub const fn y(&self) -> u32 {
        self.y
    }

    /// The sample index in the pixel, `< spp`.
    pub const fn index(&self) -> u32 {
        self.index
    }

    /// What the sampler's [`pixel_key`](PixelSampler::pixel_key) computed for this sample.
    pub const fn key(&self) -> u64 {
        self.key
    }
}
