//! pbrt-v4's `PaddedSobolSampler`: Sobol' dimensions (0, 1) re-used for every dimension
//! pair, decorrelated by a hashed per-pixel, per-dimension index permutation and scramble.

use super::prepared::{
    CHUNK, at, dispatched, permutation_fill, randomize_pairs, randomize_values, sobol1_reversed,
};
use super::{
    PixelGrid, PixelPoint, PixelSampler, Randomization, pbrt_f32, seed_hash4, sobol0, sobol1,
};
use crate::error::Result;
use crate::hash::pbrt::permutation_element;

/// Padded Sobol': with `h = Hash(p.x, p.y, d, seed)` (MurmurHash64A of 16 bytes), sample
/// `i` of pixel `p` at dimension `d` uses Sobol' index
/// `PermutationElement(i, spp, low32(h))`; a 1D value is Sobol' dimension 0 scrambled with
/// `high32(h)`, a 2D value is dimensions (0, 1) scrambled with `low32(h)` and `high32(h)`.
/// Every pixel's `spp` samples are a scrambled (0, m, 2)-net in each dimension pair when
/// `spp = 2^m`, but the pairs are independent of each other and of the neighbours (white
/// noise across pixels). Any `spp >= 1`; any dimension (it only feeds the hash, its low 32
/// bits as pbrt's `int`). Cost: nothing to precompute per pixel (the hash needs the
/// dimension); per value one MurmurHash, one permutation (about 20 multiplications) and the
/// scramble. The prepared fills ([`PixelSampler::fill_2d`]) hash `(pixel, dimension)`
/// once and run the permutation (one branch-free round for a power-of-two `spp`) and the
/// scramble in the bit-reversed domain over the pixel's samples.
///
/// ```
/// use qmckit::pixel::{PaddedSobol, PixelSampler, Randomization};
/// let p = PaddedSobol::new(16, 16, 16, Randomization::None, 0)?;
/// assert_eq!(p.start_pixel_sample(3, 5, 0)?.get_2d_f32(), [0.5625, 0.4375]);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PaddedSobol {
    grid: PixelGrid,
    randomize: Randomization,
    seed: u64,
}

impl PaddedSobol {
    /// The sampler of a `width x height` image with `spp` samples a pixel (any count; a
    /// power of two keeps the nets). Below `2^32` the `seed` is pbrt's `int` seed as its 32
    /// bits (bit-identical); a larger seed is hashed with all its 64 bits.
    ///
    /// # Errors
    /// As [`PixelGrid::new`].
    pub const fn new(
        width: u32,
        height: u32,
        spp: u32,
        randomize: Randomization,
        seed: u64,
    ) -> Result<Self> {
        match PixelGrid::new(width, height, spp, false) {
            Ok(grid) => Ok(PaddedSobol {
                grid,
                randomize,
                seed,
            }),
            Err(e) => Err(e),
        }
    }

    /// The hash and the permuted Sobol' index.
    #[inline]
    fn index(&self, at: &PixelPoint, dim: usize) -> (u64, u32) {
        let h = seed_hash4(at.x(), at.y(), dim, self.seed);
        (h, permutation_element(at.index(), self.grid.spp, h as u32))
    }
}

impl PaddedSobol {
    /// The prepared pair fill: the hash once, then per chunk of samples the permuted
    /// indices and the randomized pairs, converted by `conv`.
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
        let h = seed_hash4(x, y, dim, self.seed);
        let keys = [h as u32, (h >> 32) as u32];
        let mut all = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let perm = &mut all[..chunk.len()];
            permutation_fill((c * CHUNK) as u32, self.grid.spp, keys[0], perm);
            let perm = &all;
            randomize_pairs(
                self.randomize,
                keys,
                chunk,
                |k| {
                    let p = at(perm, k);
                    [p, sobol1_reversed(p)]
                },
                conv,
            );
        }
        Ok(())
    }

    /// The prepared 1D fill (Sobol' dimension 0, the high key).
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
        let h = seed_hash4(x, y, dim, self.seed);
        let mut all = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let perm = &mut all[..chunk.len()];
            permutation_fill((c * CHUNK) as u32, self.grid.spp, h as u32, perm);
            let perm = &all;
            randomize_values(
                self.randomize,
                (h >> 32) as u32,
                chunk,
                |k| at(perm, k),
                conv,
            );
        }
        Ok(())
    }
}

impl PixelSampler for PaddedSobol {
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

    fn grid(&self) -> PixelGrid {
        self.grid
    }

    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        let (h, i) = self.index(at, dim);
        self.randomize.apply(sobol0(i as u64), (h >> 32) as u32)
    }

    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        let (h, i) = self.index(at, dim);
        [
            self.randomize.apply(sobol0(i as u64), h as u32),
            self.randomize.apply(sobol1(i as u64), (h >> 32) as u32),
        ]
    }
}
