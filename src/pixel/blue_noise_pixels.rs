//! Blue-noise pixel samplers driven by small optimized tables: Owen-scrambled Sobol' with
//! per-pixel scrambling keys ([`BlueNoiseSobol`]; Heitz & Belcour 2019, "Distributing
//! Monte Carlo errors as a blue noise in screen space by permuting pixel seeds between
//! frames"; Belcour & Heitz 2021, "Lessons learned and improvements when building
//! screen-space samplers with blue-noise error distribution") and a rank-1 lattice with
//! per-pixel Cranley–Patterson shifts ([`BlueNoiseLattice`], Belcour & Heitz 2021).
//!
//! Each pixel integrates with its own randomized point set (an Owen-scrambled Sobol' net,
//! or a shifted lattice): unbiased, and as accurate per pixel as independent per-pixel
//! randomization. What the table adds is *which* randomization each pixel gets: the keys
//! (shifts) of a random pool are permuted over a toroidal `64 x 64` tile so that
//! neighbouring pixels' errors on a family of test integrands cancel, which moves the
//! error to high frequencies of the image (`examples/optimize_pixel_tables.rs`; the
//! tables are `tables/pixel-bn-*.bin`, see `tables/README.md`). Every dimension pair `d`
//! is the [`Domain`] `root.new_domain(d)`, so it reads the tile at its own hashed toroidal
//! offset (blue in every pair, uncorrelated between pairs) and permutes the pixel's
//! sample indices within their net (the pixel's point set, hence its error, is the one
//! optimized); the seed moves every offset. Dimensions never run out.
//!
//! Since only the assignment of keys to pixels is optimized (a permutation of a uniformly
//! random pool), a pixel under a random offset gets a uniformly random key of the pool:
//! the estimate stays unbiased for any integrand, not only the test family.
//!
//! The tile is optimized for sample counts 1, 2, 4, 8 and 16 (the prefixes of the pixel's
//! sequence); any `spp` works (the pixel reads the first `2^ceil(log2 spp)` points of its
//! own net through the permutation), the blue noise is best at those counts.

use super::domain::{
    Domain, DomainBase, KeyTable, ShiftTable, TAG_NEW, TAG_ROOT, Table, fill_pairs, fill_values,
};
use super::prepared::dispatched;
use super::{PixelGrid, PixelPoint, PixelSampler, pbrt_f32};
use crate::error::Result;
use crate::hash::hash3;

/// A sampler's root state `H(seed, 0, ROOT)` and the states `H(root, d, NEW)` of its first
/// dimension pairs, hashed once at construction (a fill then hashes only the pixel's
/// shuffle key).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Roots {
    root: u64,
    first: [u64; 8],
}

impl Roots {
    const fn new(seed: u64) -> Self {
        let root = hash3(seed, 0, TAG_ROOT);
        let mut first = [0u64; 8];
        let mut d = 0;
        while d < first.len() {
            first[d] = hash3(root, d as u64, TAG_NEW);
            d += 1;
        }
        Roots { root, first }
    }

    /// `H(root, dim, NEW)`.
    #[inline]
    const fn state(&self, dim: usize) -> u64 {
        if dim < self.first.len() {
            self.first[dim]
        } else {
            hash3(self.root, dim as u64, TAG_NEW)
        }
    }
}

/// The prepared fills of a table sampler (a `base()`, `grid` and `roots`): the dimension
/// pair's state once, then [`fill_pairs`] or [`fill_values`] over the pixel's samples.
macro_rules! table_fills {
    () => {
        fn fill_2d(&self, x: u32, y: u32, dim: usize, out: &mut [[u32; 2]]) -> Result<()> {
            self.grid.check_fill(x, y, out.len())?;
            let (spp, state) = (self.grid.spp as u64, self.roots.state(dim));
            dispatched(
                #[inline(always)]
                || fill_pairs(self.base(), (x, y), spp, state, out, |v| v),
            );
            Ok(())
        }

        fn fill_2d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [[f32; 2]]) -> Result<()> {
            self.grid.check_fill(x, y, out.len())?;
            let (spp, state) = (self.grid.spp as u64, self.roots.state(dim));
            dispatched(
                #[inline(always)]
                || fill_pairs(self.base(), (x, y), spp, state, out, pbrt_f32),
            );
            Ok(())
        }

        fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> Result<()> {
            self.grid.check_fill(x, y, out.len())?;
            let (spp, state) = (self.grid.spp as u64, self.roots.state(dim));
            dispatched(
                #[inline(always)]
                || fill_values(self.base(), (x, y), spp, state, out, |v| v),
            );
            Ok(())
        }

        fn fill_1d_f32(&self, x: u32, y: u32, dim: usize, out: &mut [f32]) -> Result<()> {
            self.grid.check_fill(x, y, out.len())?;
            let (spp, state) = (self.grid.spp as u64, self.roots.state(dim));
            dispatched(
                #[inline(always)]
                || fill_values(self.base(), (x, y), spp, state, out, pbrt_f32),
            );
            Ok(())
        }
    };
}

/// The side of the shipped tiles, 64.
pub const BLUE_NOISE_TILE_SIDE: u32 = 64;

/// The little-endian `u32`s of `bytes` (length `4 N`, checked at compile time).
const fn le_u32s<const N: usize>(bytes: &[u8]) -> [u32; N] {
    assert!(bytes.len() == 4 * N, "table length");
    let mut out = [0u32; N];
    let mut i = 0;
    while i < N {
        out[i] = u32::from_le_bytes([
            bytes[4 * i],
            bytes[4 * i + 1],
            bytes[4 * i + 2],
            bytes[4 * i + 3],
        ]);
        i += 1;
    }
    out
}

/// Pairs of little-endian `u32`s of `bytes` (length `8 N`).
const fn le_pairs<const N: usize>(bytes: &[u8]) -> [[u32; 2]; N] {
    let flat: [u32; 8192] = le_u32s(bytes);
    assert!(N * 2 == 8192, "table length");
    let mut out = [[0u32; 2]; N];
    let mut i = 0;
    while i < N {
        out[i] = [flat[2 * i], flat[2 * i + 1]];
        i += 1;
    }
    out
}

/// The Owen-scrambling keys of [`BlueNoiseSobol`], `64 x 64`, row-major
/// (`tables/pixel-bn-sobol-keys-64.bin`).
pub static BLUE_NOISE_SOBOL_KEYS: [u32; 4096] =
    le_u32s(include_bytes!("../../tables/pixel-bn-sobol-keys-64.bin"));

/// The Cranley–Patterson shifts of [`BlueNoiseLattice`], `64 x 64`, row-major
/// (`tables/pixel-bn-lattice-shifts-64.bin`).
pub static BLUE_NOISE_LATTICE_SHIFTS: [[u32; 2]; 4096] = le_pairs(include_bytes!(
    "../../tables/pixel-bn-lattice-shifts-64.bin"
));

/// The generator `g` of [`BlueNoiseLattice`]'s extensible rank-1 lattice `(rev(j), rev(j)
/// g)`: odd, its low `m` bits a good 2D lattice of `2^m` points for every `m <= 16`
/// (searched by `examples/optimize_pixel_tables.rs`: the largest smallest shortest
/// lattice vector over `m = 1..16`).
pub const BLUE_NOISE_LATTICE_GENERATOR: u32 = 0x4613;

/// Blue-noise Owen-scrambled Sobol': pixel `(x, y)`'s dimension pair `d` is the [`Domain`]
/// `new_domain(d)` of its root over an optimized key table
/// ([`DomainBase::OwenSobolTable`]). See the [pixel module](crate::pixel).
///
/// ```
/// use qmckit::pixel::{BlueNoiseSobol, PixelSampler};
/// let s = BlueNoiseSobol::new(128, 128, 16, 0)?;
/// let mut p = s.start_pixel_sample(3, 4, 15)?;
/// let [u, v] = p.get_pixel_2d_f32(); // dimension pair 0
/// let [a, b] = p.get_2d_f32(); // dimension pair 2
/// assert!(u < 1.0 && v < 1.0 && a < 1.0 && b < 1.0);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlueNoiseSobol<'t> {
    grid: PixelGrid,
    roots: Roots,
    table: KeyTable<'t>,
}

impl BlueNoiseSobol<'static> {
    /// The sampler on the shipped table ([`BLUE_NOISE_SOBOL_KEYS`]).
    ///
    /// # Errors
    /// As [`PixelGrid::new`] (any `spp >= 1`).
    pub const fn new(width: u32, height: u32, spp: u32, seed: u64) -> Result<Self> {
        match Table::new(6, &BLUE_NOISE_SOBOL_KEYS) {
            Ok(t) => Self::with_table(width, height, spp, seed, t),
            Err(e) => Err(e),
        }
    }
}

impl<'t> BlueNoiseSobol<'t> {
    /// The sampler on a caller's key table (e.g. one optimized for another `spp`).
    ///
    /// # Errors
    /// As [`PixelGrid::new`].
    pub const fn with_table(
        width: u32,
        height: u32,
        spp: u32,
        seed: u64,
        table: KeyTable<'t>,
    ) -> Result<Self> {
        match PixelGrid::new(width, height, spp, false) {
            Ok(grid) => Ok(BlueNoiseSobol {
                grid,
                roots: Roots::new(seed),
                table,
            }),
            Err(e) => Err(e),
        }
    }

    /// The root [`Domain`] of sample `index` of pixel `(x, y)`, for a renderer that derives
    /// its own domains (dimension pair `d` of the sampler is `root.new_domain(d)`).
    ///
    /// # Errors
    /// As [`PixelGrid::check`].
    pub const fn domain(&self, x: u32, y: u32, index: u32) -> Result<Domain<'t>> {
        if let Err(e) = self.grid.check(x, y, index) {
            return Err(e);
        }
        Ok(self.root_of(x, y, index))
    }

    /// The domains' base: the key table.
    const fn base(&self) -> DomainBase<'t> {
        DomainBase::OwenSobolTable(self.table)
    }

    const fn root_of(&self, x: u32, y: u32, index: u32) -> Domain<'t> {
        Domain::from_parts(
            DomainBase::OwenSobolTable(self.table),
            (x, y),
            index,
            self.grid.spp as u64,
            self.roots.root,
        )
    }

    /// The domain of dimension `dim` at a validated sample: state `H(root, dim, NEW)`.
    #[inline]
    const fn dimension(&self, at: &PixelPoint, dim: usize) -> Domain<'t> {
        Domain::from_parts(
            DomainBase::OwenSobolTable(self.table),
            (at.x(), at.y()),
            at.index(),
            self.grid.spp as u64,
            self.roots.state(dim),
        )
    }
}

impl PixelSampler for BlueNoiseSobol<'_> {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    table_fills!();

    #[inline]
    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        self.dimension(at, dim).draw_1d()
    }

    #[inline]
    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        self.dimension(at, dim).draw_2d()
    }
}

/// Blue-noise rank-1 lattice: pixel `(x, y)`'s dimension pair `d` is the lattice
/// `(rev(j), rev(j) g)` ([`BLUE_NOISE_LATTICE_GENERATOR`]) shifted by the pixel's cell of
/// an optimized shift table at the offset of [`Domain`] `new_domain(d)`
/// ([`DomainBase::LatticeTable`]). See the [pixel module](crate::pixel).
///
/// ```
/// use qmckit::pixel::{BlueNoiseLattice, PixelSampler};
/// let s = BlueNoiseLattice::new(64, 64, 4, 1)?;
/// let p: Vec<[u32; 2]> = (0..4)
///     .map(|i| s.start_pixel_sample(5, 6, i).map(|mut p| p.get_pixel_2d()))
///     .collect::<Result<_, _>>()?;
/// // A shifted lattice of 4 points: x takes each quarter once.
/// let mut q: Vec<u32> = p.iter().map(|v| v[0].wrapping_sub(p[0][0]) >> 30).collect();
/// q.sort();
/// assert_eq!(q, [0, 1, 2, 3]);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlueNoiseLattice<'t> {
    grid: PixelGrid,
    roots: Roots,
    table: ShiftTable<'t>,
    generator: u32,
}

impl BlueNoiseLattice<'static> {
    /// The sampler on the shipped table ([`BLUE_NOISE_LATTICE_SHIFTS`]) and generator.
    ///
    /// # Errors
    /// As [`PixelGrid::new`] (any `spp >= 1`).
    pub const fn new(width: u32, height: u32, spp: u32, seed: u64) -> Result<Self> {
        match Table::new(6, &BLUE_NOISE_LATTICE_SHIFTS) {
            Ok(t) => Self::with_table(width, height, spp, seed, t, BLUE_NOISE_LATTICE_GENERATOR),
            Err(e) => Err(e),
        }
    }
}

impl<'t> BlueNoiseLattice<'t> {
    /// The sampler on a caller's shift table and generator (`generator | 1` is used: an
    /// even generator would not be a lattice of `2^m` distinct points).
    ///
    /// # Errors
    /// As [`PixelGrid::new`].
    pub const fn with_table(
        width: u32,
        height: u32,
        spp: u32,
        seed: u64,
        table: ShiftTable<'t>,
        generator: u32,
    ) -> Result<Self> {
        match PixelGrid::new(width, height, spp, false) {
            Ok(grid) => Ok(BlueNoiseLattice {
                grid,
                roots: Roots::new(seed),
                table,
                generator: generator | 1,
            }),
            Err(e) => Err(e),
        }
    }

    /// The root [`Domain`] of sample `index` of pixel `(x, y)`.
    ///
    /// # Errors
    /// As [`PixelGrid::check`].
    pub const fn domain(&self, x: u32, y: u32, index: u32) -> Result<Domain<'t>> {
        if let Err(e) = self.grid.check(x, y, index) {
            return Err(e);
        }
        Ok(Domain::from_parts(
            DomainBase::LatticeTable(self.table, self.generator),
            (x, y),
            index,
            self.grid.spp as u64,
            self.roots.root,
        ))
    }

    /// The domains' base: the shift table and the generator.
    const fn base(&self) -> DomainBase<'t> {
        DomainBase::LatticeTable(self.table, self.generator)
    }

    #[inline]
    const fn dimension(&self, at: &PixelPoint, dim: usize) -> Domain<'t> {
        Domain::from_parts(
            DomainBase::LatticeTable(self.table, self.generator),
            (at.x(), at.y()),
            at.index(),
            self.grid.spp as u64,
            self.roots.state(dim),
        )
    }
}

impl PixelSampler for BlueNoiseLattice<'_> {
    fn grid(&self) -> PixelGrid {
        self.grid
    }

    table_fills!();

    #[inline]
    fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
        self.dimension(at, dim).draw_1d()
    }

    #[inline]
    fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
        self.dimension(at, dim).draw_2d()
    }
}
