//! Independent uniform values per pixel: the white-noise baseline of the pixel samplers.

use super::{PixelGrid, PixelSampler};
use crate::error::Result;
use crate::hash::{hash3, mix64};

/// Independent per-pixel sampling: every value is the top 32 bits of
/// `hash3(seed_pixel, index, 2 dim + k)` ([`crate::hash::hash3`], splitmix64 finalizers) with
/// `seed_pixel = mix64(seed ^ (x << 32 | y))` and `k = 0, 1` for the two coordinates of a 2D
/// value (a 1D value is `k = 0`). Not pbrt's `IndependentSampler` (which steps a PCG32
/// stream); the same statistics: independent, uniform, no stratification. `O(1)` a value.
///
/// ```
/// use qmckit::pixel::{IndependentPixels, PixelSampler};
/// let s = IndependentPixels::new(4, 4, 8, 1)?;
/// assert_ne!(s.get_1d(0, 0, 0, 0)?, s.get_1d(1, 0, 0, 0)?);
/// assert_eq!(s.get_1d(2, 3, 5, 7)?, s.get_2d(2, 3, 5, 7)?[0]);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct IndependentPixels {
    grid: PixelGrid,
    seed: u64,
}

impl IndependentPixels {
    /// The sampler of a `width x height` image with `spp` samples a pixel.
    ///
    /// # Errors
    /// As [`PixelGrid::new`].
    pub const fn new(width: u32, height: u32, spp: u32, seed: u64) -> Result<Self> {
        match PixelGrid::new(width, height, spp, false) {
            Ok(grid) => Ok(IndependentPixels { grid, seed }),
            Err(e) => Err(e),
        }
    }

    #[inline]
    const fn value(&self, x: u32, y: u32, index: u32, coord: u64) -> u32 {
        let pixel = mix64(self.seed ^ (((x as u64) << 32) | y as u64));
        (hash3(pixel, index as u64, coord) >> 32) as u32
    }
}

impl PixelSampler for IndependentPixels {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    fn get_1d(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<u32> {
        self.grid.check(x, y, index)?;
        Ok(self.value(x, y, index, 2 * dim as u64))
    }

    fn get_2d(&self, x: u32, y: u32, index: u32, dim: u32) -> Result<[u32; 2]> {
        self.grid.check(x, y, index)?;
        let c = 2 * dim as u64;
        Ok([self.value(x, y, index, c), self.value(x, y, index, c + 1)])
    }
}
