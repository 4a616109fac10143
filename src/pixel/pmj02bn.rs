//! PMJ02BN as a pixel sampler, laid out as pbrt-v4's `PMJ02BNSampler`: one table of
//! [`TABLE_LEN`] PMJ02BN points bucketed into a tile of pixels for the pixel position, and a
//! per-pixel, per-dimension permutation of aligned blocks of the same table, shifted by a
//! blue-noise value, for the other dimensions.

use super::prepared::{
    CHUNK, dispatched, permutation_fill, permutation_fill16, permutation_round16,
};
use super::{PixelGrid, PixelPoint, PixelSampler, pbrt_f32, seed_hash4};
use crate::blue_noise::mask64::MASK64;
use crate::error::{Error, Result};
use crate::hash::pbrt::{mix_bits, permutation_element};
use crate::pmj::bn;

/// Points in the table, `2^16` (pbrt's `nPMJ02bnSamples`).
pub const TABLE_LEN: usize = 1 << 16;

/// Samples a pass of the prepared pair fill handles (its stack scratch: small, as a fill is
/// often one pixel's 16 or 64 samples).
const PAIR_CHUNK: usize = 16;

/// `0, 1, ..`: a pass's sample offsets as 16-bit lanes.
const IOTA: [u16; PAIR_CHUNK] = {
    let mut a = [0u16; PAIR_CHUNK];
    let mut k = 0;
    while k < PAIR_CHUNK {
        a[k] = k as u16;
        k += 1;
    }
    a
};

/// `log2` of the tile side for `spp` samples a pixel: `8 - log4(RoundUpPow4(spp))`
/// (pbrt's `pixelTileSize`), and `log4(RoundUpPow4(spp))`.
const fn tile_log2(spp: u32) -> Result<(u32, u32)> {
    if spp == 0 {
        return Err(Error::ZeroPoints);
    }
    if spp as usize > TABLE_LEN {
        return Err(Error::TooLarge {
            what: "samples a pixel (the PMJ02BN table holds 65536)",
            requested: spp as u64,
            max: TABLE_LEN as u64,
        });
    }
    let log4 = spp.next_power_of_two().trailing_zeros().div_ceil(2);
    Ok((8 - log4, log4))
}

/// The two tables a [`Pmj02BnPixels`] reads: fills `table` (`TABLE_LEN` points) with the
/// PMJ02BN sequence of `seed` ([`bn::fill`]) and `tile`
/// (`TABLE_LEN` entries) with the same points bucketed by pixel: with `T = 2^(8 -
/// log4 spp')`, `spp' = RoundUpPow4(spp)`, the `T x T` pixels of a tile each get exactly the
/// `spp'` points of the table that fall in them (a (0, 16, 2)-net puts that many in each
/// cell of side `1/T`), in table order, as positions in the pixel (`frac(T p)`), pixel
/// `(x, y)` at entries `(y T + x) spp' ..`. `work` is scratch of [`bn::workspace_len`]`(TABLE_LEN)`
/// words. Cost: that of [`bn::fill`] for 65,536 points plus one pass.
///
/// # Errors
/// [`Error::BufferLength`] for a `table` or `tile` not of [`TABLE_LEN`] entries or a
/// short `work`; as [`bn::fill`]; [`Error::TooLarge`] for `spp > 65536`.
pub fn build_tables(
    seed: u64,
    spp: u32,
    table: &mut [[u32; 2]],
    tile: &mut [[u32; 2]],
    work: &mut [u32],
) -> Result<()> {
    let (tb, log4) = tile_log2(spp)?;
    for len in [table.len(), tile.len()] {
        if len != TABLE_LEN {
            return Err(Error::BufferLength {
                expected: TABLE_LEN,
                got: len,
            });
        }
    }
    bn::fill(seed, table, work, &crate::work::Budget::UNLIMITED)?;
    let cells = 1usize << (2 * tb);
    let per = 1u32 << (2 * log4);
    let counts = work.get_mut(..cells).ok_or(Error::BufferLength {
        expected: cells,
        got: 0,
    })?;
    counts.iter_mut().for_each(|c| *c = 0);
    for p in table.iter() {
        let (px, py) = if tb == 0 {
            (0, 0)
        } else {
            (p[0] >> (32 - tb), p[1] >> (32 - tb))
        };
        let cell = ((py << tb) | px) as usize;
        let Some(c) = counts.get_mut(cell) else {
            continue;
        };
        if *c >= per {
            return Err(Error::InvalidParameter {
                what: "a PMJ02BN pixel tile cell overflowed (the table is not a net)",
            });
        }
        if let Some(slot) = tile.get_mut(cell * per as usize + *c as usize) {
            *slot = [p[0] << tb, p[1] << tb];
        }
        *c += 1;
    }
    Ok(())
}

/// A blue-noise 0.32 fraction for dimension `t` at pixel `(x, y)`: the crate's 64x64
/// void-and-cluster mask ([`MASK64`]) read at an offset hashed from `(seed, t)`
/// (`MixBits(rotl(seed, 32) ^ t)`, `(seed << 32) | t` for a 32-bit seed), rank `r` giving
/// `(r + 1/2) / 4096`. (pbrt reads one of 48 shipped 128x128 textures instead.)
#[inline]
const fn blue_noise(seed: u64, t: u32, x: u32, y: u32) -> u32 {
    let h = mix_bits(seed.rotate_left(32) ^ t as u64);
    let ox = x.wrapping_add(h as u32) & 63;
    let oy = y.wrapping_add((h >> 32) as u32) & 63;
    let r = MASK64[(oy * 64 + ox) as usize] as u32;
    (r << 20) | (1 << 19)
}

/// PMJ02BN pixels (pbrt-v4's `PMJ02BNSampler` layout, on generated tables; see
/// [`build_tables`]):
/// * position in the pixel ([`get_pixel_2d`](super::PixelSample::get_pixel_2d)): entry `i` of
///   pixel `(x mod T, y mod T)` of the tile, so each pixel's first `spp` samples come from
///   one cell of the table's (0, 16, 2)-net (for `spp` a power of 4, a (0, log2 spp, 2)-net
///   in the pixel), and neighbouring pixels hold neighbouring, well-spaced points;
/// * a 2D value at dimension `d >= 2` (the counter starts at 2, as pbrt's): with `h =
///   Hash(x, y, d, seed)`, point `b spp2 + PermutationElement(i, spp, low32 h)` of the
///   table (`spp2` the power of two `>= spp`, `b` an aligned block picked by `high32 h`: a
///   (0, m, 2)-net for `spp = 2^m`), Cranley-Patterson shifted by the blue-noise values of
///   dimensions `d` and `d + 1` (pbrt shifts by its blue-noise textures; pbrt takes sets
///   1 to 4 of five shipped tables unpermuted and permutes from set 5 on, where this uses
///   one table, permuted, for every dimension);
/// * a 1D value: `(PermutationElement(i, spp, low32 h) + blue noise(d)) / spp` (as pbrt).
///
/// The blue-noise values read the crate's 64x64 void-and-cluster mask at a per-dimension
/// hashed offset (pbrt ships 48 textures of 128x128). Any `spp` in `1..=65536`; any
/// dimension (its low 32 bits feed the hashes, as pbrt's `int`).
/// Cost: the tile entry once per start; one MurmurHash, one permutation and two mask reads
/// a value; `O(1)` position. The prepared fills ([`PixelSampler::fill_2d`]) hash, pick
/// the block and read the blue noise once per pixel and dimension; per sample one
/// permutation (a branch-free round for a power-of-two `spp`), one table read and the
/// shift, and the 1D division by `spp` is a shift for a power of two.
///
/// ```
/// use qmckit::pixel::{PixelSampler, Pmj02BnPixels, pmj02bn};
/// let (mut table, mut tile) = (vec![[0u32; 2]; 65536], vec![[0u32; 2]; 65536]);
/// let mut work = vec![0u32; qmckit::pmj::bn::workspace_len(65536)?];
/// pmj02bn::build_tables(0, 16, &mut table, &mut tile, &mut work)?;
/// let s = Pmj02BnPixels::new(100, 100, 16, 0, &table, &tile)?;
/// let mut cols = [false; 16];
/// for i in 0..16 {
///     cols[(s.start_pixel_sample(70, 3, i)?.get_pixel_2d()[0] >> 28) as usize] = true;
/// }
/// assert!(cols.iter().all(|&c| c)); // stratified in x within the pixel
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pmj02BnPixels<'t> {
    grid: PixelGrid,
    seed: u64,
    tile_log2: u32,
    per_pixel: u32,
    table: &'t [[u32; 2]],
    tile: &'t [[u32; 2]],
}

impl<'t> Pmj02BnPixels<'t> {
    /// The sampler of a `width x height` image with `spp` samples a pixel, on tables from
    /// [`build_tables`] (called with the same `spp`). The `seed` is hashed as pbrt's `int`
    /// seed below `2^32`, with all its 64 bits above.
    ///
    /// # Errors
    /// As [`PixelGrid::new`]; [`Error::TooLarge`] past 65,536 spp; [`Error::BufferLength`]
    /// for tables not of [`TABLE_LEN`] entries.
    pub fn new(
        width: u32,
        height: u32,
        spp: u32,
        seed: u64,
        table: &'t [[u32; 2]],
        tile: &'t [[u32; 2]],
    ) -> Result<Self> {
        let grid = PixelGrid::new(width, height, spp, false)?;
        let (tile_log2, log4) = tile_log2(spp)?;
        for len in [table.len(), tile.len()] {
            if len != TABLE_LEN {
                return Err(Error::BufferLength {
                    expected: TABLE_LEN,
                    got: len,
                });
            }
        }
        Ok(Pmj02BnPixels {
            grid,
            seed,
            tile_log2,
            per_pixel: 1 << (2 * log4),
            table,
            tile,
        })
    }

    /// `(h, the permuted index)` of the sample at dimension `d`.
    #[inline]
    fn permuted(&self, at: &PixelPoint, d: usize) -> (u64, u32) {
        let h = seed_hash4(at.x(), at.y(), d, self.seed);
        (h, permutation_element(at.index(), self.grid.spp, h as u32))
    }
}

impl Pmj02BnPixels<'_> {
    /// The prepared pair fill (the counter read as `max(dim, 2)`), converted by `conv`.
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
        let d = dim.max(2);
        let h = seed_hash4(x, y, d, self.seed);
        let block = self.grid.spp.next_power_of_two() as u64;
        // TABLE_LEN / block by a shift (both powers of two).
        let blocks = TABLE_LEN as u64 >> block.trailing_zeros();
        let first = (((h >> 32) * blocks) >> 32) * block;
        // The table has TABLE_LEN = 2^16 entries (checked by `new`) and `first + i <
        // TABLE_LEN`: indexing the array by a `u16` needs no bound check in the loop.
        let Ok(table) = <&[[u32; 2]; TABLE_LEN]>::try_from(self.table) else {
            return Ok(());
        };
        let t = d as u32;
        let (n0, n1) = (
            blue_noise(self.seed, t, x, y),
            blue_noise(self.seed, t.wrapping_add(1), x, y),
        );
        let spp = self.grid.spp;
        if spp.is_power_of_two() {
            // One round of the mixer in 16-bit lanes, the table read and the shift in one
            // loop over a whole pass (the lanes past a short last pass read inside the
            // block and are dropped).
            let (w, f) = ((spp - 1) as u16, first as u16);
            let p = h as u32;
            for (c, chunk) in out.chunks_mut(PAIR_CHUNK).enumerate() {
                let s = (c * PAIR_CHUNK) as u16;
                let mut raw = [[0u32; 2]; PAIR_CHUNK];
                for (r, &k) in raw.iter_mut().zip(IOTA.iter()) {
                    let i = permutation_round16(s.wrapping_add(k), w, p).wrapping_add(p as u16) & w;
                    let q = table[f.wrapping_add(i) as usize];
                    *r = [q[0].wrapping_add(n0), q[1].wrapping_add(n1)];
                }
                for (o, r) in chunk.iter_mut().zip(raw.iter()) {
                    *o = [conv(r[0]), conv(r[1])];
                }
            }
            return Ok(());
        }
        // Scratch of PAIR_CHUNK samples (spp <= 2^16: 16-bit elements).
        let (mut perm, mut raw) = ([0u16; PAIR_CHUNK], [[0u32; 2]; PAIR_CHUNK]);
        for (c, chunk) in out.chunks_mut(PAIR_CHUNK).enumerate() {
            let perm = &mut perm[..chunk.len()];
            let raw = &mut raw[..chunk.len()];
            permutation_fill16((c * PAIR_CHUNK) as u32, spp, h as u32, perm);
            // The reads, then the conversion in a loop of its own (which vectorizes).
            for (r, &i) in raw.iter_mut().zip(perm.iter()) {
                let p = table[(first as u16).wrapping_add(i) as usize];
                *r = [p[0].wrapping_add(n0), p[1].wrapping_add(n1)];
            }
            for (o, r) in chunk.iter_mut().zip(raw.iter()) {
                *o = [conv(r[0]), conv(r[1])];
            }
        }
        Ok(())
    }

    /// The prepared 1D fill, `(PermutationElement(i) 2^32 + blue noise) / spp`.
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
        let d = dim.max(2);
        let h = seed_hash4(x, y, d, self.seed);
        let noise = blue_noise(self.seed, d as u32, x, y) as u64;
        let spp = self.grid.spp;
        let mut perm = [0u32; CHUNK];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            let perm = &mut perm[..chunk.len()];
            permutation_fill((c * CHUNK) as u32, spp, h as u32, perm);
            if spp.is_power_of_two() {
                let shift = spp.trailing_zeros();
                for (o, &i) in chunk.iter_mut().zip(perm.iter()) {
                    *o = conv(((((i as u64) << 32) + noise) >> shift) as u32);
                }
            } else {
                for (o, &i) in chunk.iter_mut().zip(perm.iter()) {
                    *o = conv(((((i as u64) << 32) + noise) / spp as u64) as u32);
                }
            }
        }
        Ok(())
    }
}

impl PixelSampler for Pmj02BnPixels<'_> {
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

    /// The sample's entry in the tile: `(pixel in the tile) per_pixel + index`.
    fn pixel_key(&self, x: u32, y: u32, index: u32) -> u64 {
        let mask = (1u32 << self.tile_log2) - 1;
        let cell = (((y & mask) << self.tile_log2) | (x & mask)) as u64;
        cell * self.per_pixel as u64 + index as u64
    }

    /// `max(dim, 2)`: pbrt's `StartPixelSample` starts the counter at 2 at least.
    fn counter_dimension(&self, dim: usize, _width: usize) -> usize {
        dim.max(2)
    }

    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        let d = dim.max(2);
        let (_, i) = self.permuted(at, d);
        let v = ((i as u64) << 32) + blue_noise(self.seed, d as u32, at.x(), at.y()) as u64;
        (v / self.grid.spp as u64) as u32
    }

    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        let d = dim.max(2);
        let (h, i) = self.permuted(at, d);
        let block = self.grid.spp.next_power_of_two() as u64;
        let blocks = TABLE_LEN as u64 / block;
        let b = ((h >> 32) * blocks) >> 32;
        let p = self
            .table
            .get((b * block + i as u64) as usize)
            .copied()
            .unwrap_or([0, 0]);
        let t = d as u32;
        [
            p[0].wrapping_add(blue_noise(self.seed, t, at.x(), at.y())),
            p[1].wrapping_add(blue_noise(self.seed, t.wrapping_add(1), at.x(), at.y())),
        ]
    }

    fn value_pixel_2d(&self, at: &PixelPoint, _dim: usize) -> [u32; 2] {
        self.tile.get(at.key() as usize).copied().unwrap_or([0, 0])
    }

    /// False: as in pbrt, the pixel position is read from the tile, outside the counter.
    fn pixel_2d_moves_counter(&self) -> bool {
        false
    }
}

/// Owned tables for a [`Pmj02BnPixels`] (`std`).
#[cfg(feature = "std")]
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pmj02BnTables {
    spp: u32,
    table: std::vec::Vec<[u32; 2]>,
    tile: std::vec::Vec<[u32; 2]>,
}

#[cfg(feature = "std")]
impl Pmj02BnTables {
    /// [`build_tables`] for `spp` samples a pixel, into
    /// new buffers (1 MiB of tables, 2 MiB of scratch while building).
    ///
    /// # Errors
    /// As [`build_tables`]; an allocation failure as [`crate::size::vec_zeroed`].
    pub fn new(spp: u32, seed: u64) -> Result<Self> {
        let mut table = crate::size::vec_zeroed::<[u32; 2]>(TABLE_LEN)?;
        let mut tile = crate::size::vec_zeroed::<[u32; 2]>(TABLE_LEN)?;
        let mut work = crate::size::vec_zeroed::<u32>(bn::workspace_len(TABLE_LEN)?)?;
        build_tables(seed, spp, &mut table, &mut tile, &mut work)?;
        Ok(Pmj02BnTables { spp, table, tile })
    }

    /// The sampler of a `width x height` image on these tables.
    ///
    /// # Errors
    /// As [`Pmj02BnPixels::new`].
    pub fn sampler(&self, width: u32, height: u32, seed: u64) -> Result<Pmj02BnPixels<'_>> {
        Pmj02BnPixels::new(width, height, self.spp, seed, &self.table, &self.tile)
    }

    /// The sampler on these tables for a `grid` of their `spp` validated before (by
    /// [`sampler`](Self::sampler)): no checks, for the catalog's owned form.
    pub(crate) fn sampler_of(&self, grid: PixelGrid, seed: u64) -> Pmj02BnPixels<'_> {
        // `new` checked `spp`, so the default is unreachable.
        let (tile_log2, log4) = tile_log2(self.spp).unwrap_or_default();
        Pmj02BnPixels {
            grid,
            seed,
            tile_log2,
            per_pixel: 1 << (2 * log4),
            table: &self.table,
            tile: &self.tile,
        }
    }

    /// The PMJ02BN sequence the tables come from.
    pub fn sequence(&self) -> &[[u32; 2]] {
        &self.table
    }
}
