//! Independent uniform values per pixel: the white-noise baseline of the pixel samplers.

use super::prepared::dispatched;
use super::{PixelGrid, PixelPoint, PixelSampler, pbrt_f32};
use crate::error::Result;
use crate::hash::{hash3, hash3_key, hash3_keyed, mix64};

/// Independent per-pixel sampling: every value is the top 32 bits of
/// `hash3(seed_pixel, index, 2 dim + k)` ([`crate::hash::hash3`], splitmix64 finalizers) with
/// `seed_pixel = mix64(seed ^ (x << 32 | y))` and `k = 0, 1` for the two coordinates of a 2D
/// value (a 1D value is `k = 0`). Not pbrt's `IndependentSampler` (which steps a PCG32
/// stream); the same statistics: independent, uniform, no stratification. Any dimension
/// (`2 dim + k` wraps in `u64`). `seed_pixel` once per start; one `hash3` a value.
///
/// ```
/// use qmckit::pixel::{IndependentPixels, PixelSampler};
/// let s = IndependentPixels::new(4, 4, 8, 1)?;
/// assert_ne!(s.start_pixel_sample(0, 0, 0)?.get_1d(), s.start_pixel_sample(1, 0, 0)?.get_1d());
/// let mut one = s.start_pixel_sample(2, 3, 5)?.with_dimension(7);
/// let mut two = one; // a handle is `Copy`: the same sample, the same counter
/// assert_eq!(one.get_1d(), two.get_2d()[0]);
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

    /// Coordinate `coord` of the sample at `at`.
    #[inline]
    const fn value(at: &PixelPoint, coord: u64) -> u32 {
        (hash3(at.key(), at.index() as u64, coord) >> 32) as u32
    }
}

impl PixelSampler for IndependentPixels {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    /// The pixel hash once, one `hash3` a value.
    fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
        self.grid.check_fill(x, y, out.len())?;
        let key = self.pixel_key(x, y, 0);
        let c = (dim as u64).wrapping_mul(2);
        let k = hash3_key(key);
        dispatched(
            #[inline(always)]
            || {
                for (i, o) in (0u64..).zip(out.iter_mut()) {
                    *o = [
                        (hash3_keyed(k, i, c) >> 32) as u32,
                        (hash3_keyed(k, i, c.wrapping_add(1)) >> 32) as u32,
                    ];
                }
            },
        );
        Ok(())
    }

    fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
        self.grid.check_fill(x, y, out.len())?;
        let key = self.pixel_key(x, y, 0);
        let c = (dim as u64).wrapping_mul(2);
        let k = hash3_key(key);
        dispatched(
            #[inline(always)]
            || {
                for (i, o) in (0u64..).zip(out.iter_mut()) {
                    *o = [
                        pbrt_f32((hash3_keyed(k, i, c) >> 32) as u32),
                        pbrt_f32((hash3_keyed(k, i, c.wrapping_add(1)) >> 32) as u32),
                    ];
                }
            },
        );
        Ok(())
    }

    /// `seed_pixel = mix64(seed ^ (x << 32 | y))`.
    fn pixel_key(&self, x: u32, y: u32, _index: u32) -> u64 {
        mix64(self.seed ^ (((x as u64) << 32) | y as u64))
    }

    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        Self::value(at, (dim as u64).wrapping_mul(2))
    }

    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        let c = (dim as u64).wrapping_mul(2);
        [Self::value(at, c), Self::value(at, c.wrapping_add(1))]
    }
}
