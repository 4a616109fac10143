//! PMJ02 as a pixel sampler: a seeded PMJ02 sequence per pixel and dimension, its first
//! `spp` points visited through a hashed permutation.

use super::prepared::{CHUNK, dispatched, permutation_fill};
use super::{PixelGrid, PixelPoint, PixelSampler, pbrt_f32, seed_hash4};
use crate::error::Result;
use crate::hash::pbrt::permutation_element;
use crate::pmj::Pmj02;

/// PMJ02 pixels: with `h = Hash(x, y, d, seed)` (pbrt's MurmurHash of 16 bytes), sample `i`
/// of pixel `(x, y)` at dimension `d` is point `PermutationElement(i, spp, low32(h))` of the
/// PMJ02 sequence seeded by `h` ([`Pmj02`]); a 1D value is its first coordinate. The
/// layout of pbrt-v4's `PMJ02BNSampler` for dimensions past the pixel position (a per-pixel,
/// per-dimension index permutation), with a generated sequence per pixel instead of pbrt's
/// shipped tables and blue-noise shifts. With `spp = 2^m` each pixel's samples are a
/// (0, m, 2)-net in every dimension pair. Any dimension (it only feeds the hash). Cost:
/// one MurmurHash, one permutation and `2 log2(spp)` hashes a 2D value; the prepared fills
/// ([`PixelSampler::fill_2d`]) hash and seed once per pixel and dimension and, for `spp <=
/// 256`, generate the pixel's sequence prefix in one pass, two hashes a point.
///
/// ```
/// use qmckit::pixel::{PixelSampler, Pmj02Pixels};
/// let s = Pmj02Pixels::new(8, 8, 16, 0)?;
/// let mut rows = [false; 16];
/// for i in 0..16 {
///     let p = s.start_pixel_sample(3, 4, i)?.get_2d();
///     rows[(p[1] >> 28) as usize] = true;
/// }
/// assert!(rows.iter().all(|&r| r)); // stratified in y
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Pmj02Pixels {
    grid: PixelGrid,
    seed: u64,
}

impl Pmj02Pixels {
    /// The sampler of a `width x height` image with `spp` samples a pixel; the `seed` is
    /// hashed as pbrt's `int` seed below `2^32`, with all its 64 bits above.
    ///
    /// # Errors
    /// As [`PixelGrid::new`].
    pub const fn new(width: u32, height: u32, spp: u32, seed: u64) -> Result<Self> {
        match PixelGrid::new(width, height, spp, false) {
            Ok(grid) => Ok(Pmj02Pixels { grid, seed }),
            Err(e) => Err(e),
        }
    }

    #[inline]
    fn point(&self, at: &PixelPoint, dim: usize) -> (Pmj02, u32) {
        let h = seed_hash4(at.x(), at.y(), dim, self.seed);
        (
            Pmj02::new(h),
            permutation_element(at.index(), self.grid.spp, h as u32),
        )
    }
}

/// The largest `spp` whose sequence prefix a prepared fill generates whole, on the stack
/// (2 KiB).
const SEQUENCE: usize = crate::pmj::SHORT;

/// The smaller stack scratch for counts up to 16.
const SMALL: usize = 16;

impl Pmj02Pixels {
    /// The prepared fill: the hash and the sequence once, `value(sequence, permuted i,
    /// point)` per sample, where `point` is the sequence's point `i` when the fill generated
    /// the prefix (`spp <=` [`SEQUENCE`], `O(1)` a point), `None` when the value is to be
    /// computed by random access (`O(log2 spp)` hashes).
    #[inline(always)]
    fn fill_with<T>(
        &self,
        x: u32,
        y: u32,
        dim: usize,
        out: &mut [T],
        value: impl Fn(&Pmj02, u32, Option<[u32; 2]>) -> T,
    ) -> Result<()> {
        self.grid.check_fill(x, y, out.len())?;
        let h = seed_hash4(x, y, dim, self.seed);
        let p = Pmj02::new(h);
        let spp = self.grid.spp as usize;
        if spp <= SMALL {
            // Stack scratch of 16 points for the common counts.
            let mut seq = [[0u32; 2]; SMALL];
            crate::pmj::fill_short::<SMALL>(h, &mut seq[..spp]);
            return self.read(h, &seq[..spp], out, &p, value);
        }
        if spp <= SEQUENCE {
            let mut seq = [[0u32; 2]; SEQUENCE];
            crate::pmj::fill_short::<SEQUENCE>(h, &mut seq[..spp]);
            return self.read(h, &seq[..spp], out, &p, value);
        }
        let mut perm = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let perm = &mut perm[..chunk.len()];
            permutation_fill((c * CHUNK) as u32, self.grid.spp, h as u32, perm);
            for (o, &i) in chunk.iter_mut().zip(perm.iter()) {
                *o = value(&p, i, None);
            }
        }
        Ok(())
    }

    /// The pixel's sequence prefix `seq` (its `spp` points, two hashes a point, each point
    /// from its parent) read through the permutation into `out`.
    #[inline(always)]
    fn read<T>(
        &self,
        h: u64,
        seq: &[[u32; 2]],
        out: &mut [T],
        p: &Pmj02,
        value: impl Fn(&Pmj02, u32, Option<[u32; 2]>) -> T,
    ) -> Result<()> {
        let mut perm = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let perm = &mut perm[..chunk.len()];
            permutation_fill((c * CHUNK) as u32, self.grid.spp, h as u32, perm);
            for (o, &i) in chunk.iter_mut().zip(perm.iter()) {
                let [a, b] = seq.get(i as usize).copied().unwrap_or_default();
                *o = value(p, i, Some([a, b]));
            }
        }
        Ok(())
    }
}

impl PixelSampler for Pmj02Pixels {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
        dispatched(
            #[inline(always)]
            || {
                self.fill_with(x, y, dim, out, |p, i, q| {
                    q.unwrap_or_else(|| [p.value(i, 0), p.value(i, 1)])
                })
            },
        )
    }

    fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
        dispatched(
            #[inline(always)]
            || {
                self.fill_with(x, y, dim, out, |p, i, q| {
                    q.unwrap_or_else(|| [p.value(i, 0), p.value(i, 1)])
                        .map(pbrt_f32)
                })
            },
        )
    }

    fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> Result<()> {
        dispatched(
            #[inline(always)]
            || {
                self.fill_with(x, y, dim, out, |p, i, q| {
                    q.map_or_else(|| p.value(i, 0), |q| q[0])
                })
            },
        )
    }

    fn fill_1d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [f32]) -> Result<()> {
        dispatched(
            #[inline(always)]
            || {
                self.fill_with(x, y, dim, out, |p, i, q| {
                    pbrt_f32(q.map_or_else(|| p.value(i, 0), |q| q[0]))
                })
            },
        )
    }

    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        let (p, i) = self.point(at, dim);
        p.value(i, 0)
    }

    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        let (p, i) = self.point(at, dim);
        [p.value(i, 0), p.value(i, 1)]
    }
}
