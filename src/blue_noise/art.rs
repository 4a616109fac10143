//! Adaptive regular tiles, ART (after Ahmed, Niese, Huang & Deussen 2017, "An Adaptive
//! Point Sampler on a Regular Lattice", ACM TOG 36(4), SIGGRAPH): the unit square
//! subdivided recursively into `4 x 4` square tiles, one sample a tile, its offset in the
//! tile read from a small table indexed by the tile's word; every tile's sample is also one
//! of its children's (self-coincident), so the samples of all levels form one progressive
//! sequence, and a density is followed by thresholding the ranks.
//!
//! ## Tiles, words and samples
//!
//! A tile of level `j` is a square of side `4^-j`; its 16 children are numbered
//! `c = c_x + 4 c_y`. The tile's word, which picks its table entry, is
//! `id = c + 16 i + 256 t`: its own child number, the child number `i` of the sibling
//! that inherits the parent's sample, and the Thue–Morse bit `t = t(x) xor t(y)` of its
//! integer position `(x, y)` at its level (`t(n)` the parity of the binary digits of `n`:
//! the parity of all the digits of the tile's path). With `i` the word knows where the
//! inherited sample lies and hence the tile's rank digit (below), so an entry places a
//! sample for the prefixes it belongs to. The Thue–Morse bit, which has no period, breaks
//! the repetition the child numbers alone would have (the paper builds its tile
//! identifiers from the Thue–Morse word for the same reason; the exact word here is this
//! module's choice). The root's word is 0.
//!
//! The root's sample is `o[0]` (table offsets `o` in tile units, in `(0, 1)^2`). A tile
//! passes its sample to the child that contains it; every other child `C` places its own at
//! `corner(C) + 4^-j o[id(C)]`. So the samples of level `j` are one a tile (`16^j` of
//! them) and contain those of every coarser level.
//!
//! ## Ranks: a progressive sequence
//!
//! Among 16 siblings, the inheriting child has rank digit 0 and the others follow the
//! `4 x 4` Bayer (ordered-dither) matrix read from the inheriting child's position
//! (`r = B[(c_x - i_x) mod 4][(c_y - i_y) mod 4]`): the dispersed order that fills a tile's
//! children evenly. A tile of level `L` has rank `sum_(j=1..L) r_j 16^(j-1)`, its
//! coarsest digit least significant (the bit reversal of the paper): the tiles of rank
//! below `16^j` are the ones that inherit the samples of level `j`, and the descendants of
//! a level-`j` tile take every `16^j`-th rank. The `N`-point set is the `N` samples of
//! lowest rank at level `L = ceil(log_16 N)`: exactly `N` points, one in each tile of the
//! finest complete level, each prefix the set of its size.
//!
//! ## Density
//!
//! [`importance`] keeps a level-`L` tile when `rank + 1/2 < rho(sample)`, `rho` the density
//! in points a unit area and `16^L` at least its maximum: a level-`j` tile of area
//! `16^-j` keeps about `rho 16^-j` samples, its own first ones, so the count follows the
//! density and the kept samples stay spread (this is the paper's recursive filling,
//! written as a threshold).
//!
//! ## The table
//!
//! [`ART_TABLE`] (512 offsets) is `tables/art_offsets.rs`, made by
//! `examples/art_optimize.rs`: gradient descent, over the prefixes of 256, 1024 and 4096
//! points on the torus (1024 weighted seven times: it lies between two complete
//! levels, where the offsets have the least room), of the mismatch of their pair
//! correlation with step blue noise (Heck, Schlömer & Deussen 2013) plus a hard-core
//! penalty `sum (r0 - r)^2` on pairs closer than `r0 = 1` mean spacing, plus (started from
//! the table of those two terms) an axis term, `V sum_(d, j <= 3 sqrt N) |S_d(j)|^2 /
//! (N j^2)` with `S_d(j)` the Fourier sum of the `d`-th coordinates: the squared `L2`
//! discrepancy of the projections on the axes. At 1024 points (one sample in each `1/32`
//! square) the first two terms alone kept the samples in the middle of their squares, the
//! projections' discrepancy 0.015 and the star discrepancy 0.024; with the axis term
//! (`V = 100`) 0.012. The paper relaxes its offsets so that the samples of every level
//! spread out; its optimizer and table are not reproduced.
//!
//! ## Range and cost
//!
//! `N` from 1 to [`ART_MAX_POINTS`] = `16^6`, any seed (a toroidal shift of the set:
//! `x <- x + s mod 1`). `O(N log N)`: about `17 N` tiles made (16 children of each tile
//! whose rank can be kept), a sort of the `N` kept; memory `O(N)` through [`crate::size`].
//! Estimated against a [`Budget`], the deadline read as tiles are made.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::blue_noise::Art;
//! use qmckit::work::Budget;
//! // 256 points: one in each tile of the second level, a 16 x 16 grid.
//! let set = Art::new(256)?.seed(3).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 256);
//! // The first 16 are the first level's, one in each 4 x 4 tile of the shifted grid.
//! assert_eq!(Art::new(16)?.seed(3).generate(&Budget::DEFAULT)?.coords(), &set.coords()[..32]);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::lloyd::to_fraction;
use super::rng::Rng;
use crate::work::{Budget, Cost, Pacer, Rate};
use crate::{Error, Result};

/// The most points [`Art`] takes, and the largest maximum density of [`importance`]:
/// `16^6 = 2^24`.
pub const ART_MAX_POINTS: u64 = 1 << 24;

/// Table entries: 16 child numbers, 16 inheriting-child numbers, the Thue–Morse bit.
pub const ART_IDS: usize = 512;

/// The deepest level (`16^6` tiles).
pub const ART_MAX_LEVELS: u32 = 6;

/// The `4 x 4` Bayer matrix, index `d_x + 4 d_y`: the rank digits of the children.
pub const BAYER: [u8; 16] = [0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5];

/// Estimate steps (`17 + log2 N` a point) a second, one core, release: measured 2.3e8
/// (`qmckit points art -n 4000000`, 0.67 s), taken lower for loaded machines.
const TILES: Rate = Rate::per_second(8e7);

/// The offsets, by word: `(o_x, o_y)` in tile units, each in `(0, 1)`.
#[derive(Clone, Debug, PartialEq)]
pub struct ArtTable {
    entries: [[f64; 2]; ART_IDS],
}

impl ArtTable {
    /// Every sample at its tile's centre.
    pub const CENTRES: ArtTable = ArtTable {
        entries: [[0.5; 2]; ART_IDS],
    };

    /// The table of `entries`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an entry that is not finite or not in `(0, 1)`.
    pub fn new(entries: [[f64; 2]; ART_IDS]) -> Result<Self> {
        if entries
            .iter()
            .flatten()
            .any(|o| o.is_nan() || *o <= 0.0 || *o >= 1.0)
        {
            return Err(Error::InvalidParameter {
                what: "an ART offset is in tile units, strictly between 0 and 1",
            });
        }
        Ok(ArtTable { entries })
    }

    /// The entries, by word.
    pub fn entries(&self) -> &[[f64; 2]; ART_IDS] {
        &self.entries
    }

    fn get(&self, id: usize) -> [f64; 2] {
        self.entries.get(id).copied().unwrap_or([0.5; 2])
    }
}

/// The optimized table, `tables/art_offsets.rs` (see the module documentation).
pub const ART_TABLE: ArtTable = ArtTable {
    entries: include!("../../tables/art_offsets.rs"),
};

/// A tile of the subdivision with its sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tile {
    /// Its level `j` (side `4^-j`).
    pub level: u32,
    /// Its column and row at its level.
    pub pos: [u32; 2],
    /// Its child number among its siblings (0 for the root).
    pub child: u8,
    /// Its rank (module documentation).
    pub rank: u64,
    /// Its sample in the unit square (before the seed's shift).
    pub point: [f64; 2],
    /// The word of the tile that placed the sample, and that tile's level.
    pub source: (u16, u32),
}

impl Tile {
    /// The root: the unit square, sample `o[0]`.
    pub fn root(table: &ArtTable) -> Tile {
        Tile {
            level: 0,
            pos: [0, 0],
            child: 0,
            rank: 0,
            point: table.get(0),
            source: (0, 0),
        }
    }

    /// The 16 children, by child number.
    pub fn children(&self, table: &ArtTable) -> [Tile; 16] {
        let level = self.level + 1;
        let side = 0.25f64.powi(level as i32);
        let corner = |v: u32| f64::from(v) * side * 4.0;
        let inherit = |d: usize| {
            let f = ((self.point[d] - corner(self.pos[d])) / side).floor();
            f.clamp(0.0, 3.0) as u32
        };
        let (ix, iy) = (inherit(0), inherit(1));
        let weight = 16u64.pow(self.level);
        core::array::from_fn(|c| {
            let (cx, cy) = (c as u32 % 4, c as u32 / 4);
            let pos = [4 * self.pos[0] + cx, 4 * self.pos[1] + cy];
            let digit = BAYER[(((cx + 4 - ix) % 4) + 4 * ((cy + 4 - iy) % 4)) as usize];
            let (point, source) = if cx == ix && cy == iy {
                (self.point, self.source)
            } else {
                let t = (pos[0].count_ones() + pos[1].count_ones()) as usize % 2;
                let id = c + 16 * (ix + 4 * iy) as usize + 256 * t;
                let o = table.get(id);
                let at = |d: usize| f64::from(pos[d]) * side + side * o[d];
                ([at(0), at(1)], (id as u16, level))
            };
            Tile {
                level,
                pos,
                child: c as u8,
                rank: self.rank + u64::from(digit) * weight,
                point,
                source,
            }
        })
    }
}

/// The tiles of level `levels` whose rank is below `limit`, in no particular order.
///
/// # Errors
/// [`Error::OutOfTime`] at the deadline of `pacer`, [`Error::TooLarge`].
pub fn tiles(levels: u32, limit: f64, table: &ArtTable, pacer: &mut Pacer) -> Result<Vec<Tile>> {
    let mut out = crate::size::vec_with_capacity::<Tile>(0)?;
    let mut stack = crate::size::vec_with_capacity::<Tile>(16 * levels as usize + 1)?;
    stack.push(Tile::root(table));
    while let Some(t) = stack.pop() {
        if t.level == levels {
            crate::size::reserve(&mut out, 1)?;
            out.push(t);
            continue;
        }
        pacer.tick_n(16)?;
        for c in t.children(table) {
            if (c.rank as f64) < limit {
                crate::size::reserve(&mut stack, 1)?;
                stack.push(c);
            }
        }
    }
    Ok(out)
}

/// The level `L = ceil(log_16 n)`, `n >= 1`.
fn level_for(n: f64) -> u32 {
    let mut l = 0;
    while 16f64.powi(l as i32) < n && l < ART_MAX_LEVELS {
        l += 1;
    }
    l
}

/// The estimated cost for `n` kept tiles: `17 n` tiles made and a sort.
fn cost_for(n: f64) -> Cost {
    Cost::steps(n * (17.0 + n.max(2.0).log2()), TILES)
}

/// The seed's toroidal shift.
fn seed_shift(seed: u64) -> [f64; 2] {
    let mut rng = Rng::new(seed, 0xa27);
    [rng.unit(), rng.unit()]
}

fn shifted(p: [f64; 2], s: [f64; 2]) -> [f64; 2] {
    let wrap = |v: f64| if v >= 1.0 { v - 1.0 } else { v };
    [wrap(p[0] + s[0]), wrap(p[1] + s[1])]
}

fn to_set(points: &[[f64; 2]]) -> Result<PointSet> {
    let mut coords =
        crate::size::vec_with_capacity(crate::size::coordinates(points.len() as u64, 2)?)?;
    coords.extend(points.iter().flat_map(|p| p.map(to_fraction)));
    PointSet::new(coords, 2)
}

/// ART sampling of the unit torus (builder): `N` points in rank order, seed 0,
/// [`ART_TABLE`].
#[derive(Clone, Debug, PartialEq)]
pub struct Art {
    n: u64,
    seed: u64,
    table: ArtTable,
}

impl Art {
    /// `n` points, 1 to [`ART_MAX_POINTS`].
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`].
    pub fn new(n: u64) -> Result<Self> {
        crate::size::points(n, ART_MAX_POINTS)?;
        Ok(Art {
            n,
            seed: 0,
            table: ART_TABLE,
        })
    }

    /// The seed: the toroidal shift of the set.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The seed's toroidal shift `s`: the samples are `x + s mod 1`.
    pub fn shift(&self) -> [f64; 2] {
        seed_shift(self.seed)
    }

    /// With `table` instead of [`ART_TABLE`] ([`ArtTable::CENTRES`]: tile centres).
    pub fn table(mut self, table: ArtTable) -> Self {
        self.table = table;
        self
    }

    /// The estimated running time (module documentation, "Range and cost").
    pub fn cost(&self) -> Cost {
        cost_for(self.n as f64)
    }

    /// The `N` samples of lowest rank, in rank order, refused before it starts when
    /// [`cost`](Self::cost) exceeds `budget`, stopped at its deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::OutOfTime`], [`Error::TooLarge`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        const WHAT: &str = "ART sampling";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let mut pacer = budget.pacer(WHAT);
        let n = self.n as f64;
        let mut kept = tiles(level_for(n), n, &self.table, &mut pacer)?;
        kept.sort_unstable_by_key(|t| t.rank);
        let s = self.shift();
        let mut points = crate::size::vec_with_capacity::<[f64; 2]>(kept.len())?;
        points.extend(kept.iter().map(|t| shifted(t.point, s)));
        to_set(&points)
    }
}

/// Importance sampling of the unit square by ART ranks: about `integral of density`
/// points, `density(x, y)` points a unit area (at most `max_density`, 1 to
/// [`ART_MAX_POINTS`]), the tiling shifted by the seed, the samples in rank order (the set
/// of a smaller multiple of the density is a subset).
///
/// ```
/// use qmckit::blue_noise::art;
/// use qmckit::work::Budget;
/// // 2000 x on the square: about 1000 points, more to the right.
/// let set = art::importance(|x, _| 2000.0 * x, 2000.0, 0, &Budget::DEFAULT)?;
/// assert!((set.count() as f64 - 1000.0).abs() < 50.0);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for a `max_density` outside that range or a density value
/// that is not finite or outside `[0, max_density]`; as [`Art::generate`].
pub fn importance<F: Fn(f64, f64) -> f64>(
    density: F,
    max_density: f64,
    seed: u64,
    budget: &Budget,
) -> Result<PointSet> {
    const WHAT: &str = "ART importance sampling";
    if !(1.0..=ART_MAX_POINTS as f64).contains(&max_density) {
        return Err(Error::InvalidParameter {
            what: "ART importance sampling takes a maximum density from 1 to 2^24",
        });
    }
    let budget = budget.started();
    budget.check(WHAT, cost_for(max_density))?;
    let mut pacer = budget.pacer(WHAT);
    let mut leaves = tiles(level_for(max_density), max_density, &ART_TABLE, &mut pacer)?;
    leaves.sort_unstable_by_key(|t| t.rank);
    let s = seed_shift(seed);
    let mut kept = crate::size::vec_with_capacity::<[f64; 2]>(0)?;
    for t in &leaves {
        let p = shifted(t.point, s);
        let rho = density(p[0], p[1]);
        if !(0.0..=max_density).contains(&rho) {
            return Err(Error::InvalidParameter {
                what: "ART importance sampling: a density value not in [0, max_density]",
            });
        }
        if t.rank as f64 + 0.5 < rho {
            crate::size::reserve(&mut kept, 1)?;
            kept.push(p);
        }
    }
    to_set(&kept)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each child is inside its parent, exactly one inherits the parent's sample, the rank
    /// digits are a permutation, and every sample is inside its tile.
    #[test]
    fn children_partition_their_parent() {
        let mut level = vec![Tile::root(&ART_TABLE)];
        for _ in 0..3 {
            let mut next = Vec::new();
            for t in &level {
                let ch = t.children(&ART_TABLE);
                assert_eq!(ch.iter().filter(|c| c.point == t.point).count(), 1);
                let mut digits: Vec<u64> = ch
                    .iter()
                    .map(|c| (c.rank - t.rank) >> (4 * t.level))
                    .collect();
                digits.sort_unstable();
                assert!(digits.iter().enumerate().all(|(i, &d)| d == i as u64));
                for c in &ch {
                    let side = 0.25f64.powi(c.level as i32);
                    for d in 0..2 {
                        let lo = f64::from(c.pos[d]) * side;
                        assert!(c.point[d] >= lo && c.point[d] < lo + side);
                    }
                }
                next.extend(ch);
            }
            level = next;
        }
        let mut ranks: Vec<u64> = level.iter().map(|t| t.rank).collect();
        ranks.sort_unstable();
        assert!(ranks.iter().enumerate().all(|(i, &r)| r == i as u64));
    }

    #[test]
    fn the_table_is_valid() {
        assert!(ArtTable::new(*ART_TABLE.entries()).is_ok());
    }
}
