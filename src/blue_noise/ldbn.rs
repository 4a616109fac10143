//! Low-discrepancy blue noise (after Ahmed, Perrier, Coeurjolly, Ostromoukhov, Guo, Yan,
//! Huang & Deussen 2016, "Low-Discrepancy Blue Noise Sampling", ACM TOG 35(6)): an
//! Owen-scrambled 2D Sobol' `(0, m, 2)`-net whose points are rearranged inside small tiles
//! by permutations read from a lookup table, indexed by the tile's local configuration and
//! chosen offline for a blue-noise spectrum; the rearrangement keeps the net a net.
//!
//! ## The template and the tiles
//!
//! `N = 4^k` points, `K = 2^k`. The template is the Owen-scrambled Sobol' net
//! ([`Sobol`] dimensions 0 and 1, [`ExactOwen`] of the seed: the catalog's
//! `sobol --scramble owen`): a `(0, 2k, 2)`-net, so each of the `K x K` square cells holds
//! one point `((c + u)/K, (r + v)/K)`, `u, v` its offsets in the cell. The cells are
//! grouped into `2 x 2` tiles, cells `A = (2a, 2b)`, `B = (2a+1, 2b)`, `C = (2a, 2b+1)`,
//! `D = (2a+1, 2b+1)` (column, row).
//!
//! A tile's *configuration* is 8 bits of its offsets: the order of the `u` of the two
//! cells of each column (`A, C` and `B, D`) and of the `v` of the two cells of each row
//! (`A, B` and `C, D`), and whether each of those four differences is at least half a
//! cell. The table ([`LdbnTable`], 256 entries) maps it to 4 bits: exchange the `u` of
//! column 0's two cells, of column 1's, the `v` of row 0's, of row 1's. A point keeps its
//! cell and its index; only offsets move, and only between the two cells of a tile column
//! (`u`) or a tile row (`v`).
//!
//! ## What is kept: the net
//!
//! For an elementary interval `2^-a x 2^-b`, `a + b = 2k`: if `a = b = k` it is a cell
//! (one point each, kept). If `a < k`, its `x` range covers whole tile columns (width
//! `2^-a >= 2/K`, aligned), its `y` range lies in one cell row and selects by `v`; the
//! exchanges of `v` within that row stay within the range, so the multiset of `v` in it,
//! and the count, are the template's. `a > k` is the same with `x` and `y` swapped. So
//! the output is a `(0, 2k, 2)`-net, like the template (the tests count it), and in
//! particular one point in each of the `N` columns and rows of width `1/N`. (Tiles larger
//! than `2 x 2` would break the intervals whose width is two cells.)
//!
//! ## The table
//!
//! [`LDBN_TABLE`] is `tables/ldbn-2x2.txt`, produced by `examples/ldbn_optimize.rs`:
//! coordinate descent over the 256 entries, each of the 16 choices tried in turn, of a
//! Gaussian pair energy `sum_(i<j) exp(-|x_i - x_j|^2 / (2 s^2))` on the torus over a
//! training batch of templates (the paper fitted its table to a reference blue-noise
//! spectrum by assignment; the energy here is Ahmed, Ren & Wonka's Gaussian blue-noise
//! objective instead). The paper's table is not reproduced; its tiles and configurations
//! are this module's own choice (the smallest tiles that keep every interval).
//!
//! ## Range and cost
//!
//! `N = 4^k`, `k` from 1 to 13 (4 to 2^26 points); any seed. `O(N)`: the template (64
//! hashes a point), a cell grid of `N` indices, one table look-up a tile; memory `4N`
//! words through [`crate::size`]. Estimated ([`Ldbn::cost`]) against a [`Budget`],
//! the deadline read every 4096 tiles.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::blue_noise::Ldbn;
//! use qmckit::work::Budget;
//! let set = Ldbn::new(256, 3)?.generate(&Budget::DEFAULT)?;
//! // One point in each of the 16 x 16 cells.
//! let mut cells = [0; 256];
//! for i in 0..256 {
//!     let (x, y) = (set.sample(i, 0)? >> 28, set.sample(i, 1)? >> 28);
//!     cells[(x * 16 + y) as usize] += 1;
//! }
//! assert!(cells.iter().all(|&c| c == 1));
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use crate::randomize::{ExactOwen, Scrambled};
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result, Sampler, Sobol};

/// The most points [`Ldbn`] takes: `4^13 = 2^26`.
pub const LDBN_MAX_POINTS: u64 = 1 << 26;

/// Template points a second, one core, release (two exact Owen scrambles of 32 hashes
/// each dominate; about 6e6 measured, taken lower).
const POINTS: Rate = Rate::per_second(3e6);

/// The 256-entry look-up table: configuration (8 bits) to exchanges (4 bits; bit 0 the
/// `u` of column 0, bit 1 of column 1, bit 2 the `v` of row 0, bit 3 of row 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LdbnTable {
    entries: [u8; 256],
}

impl LdbnTable {
    /// No exchange anywhere: the output is the template.
    pub const IDENTITY: LdbnTable = LdbnTable { entries: [0; 256] };

    /// The table of `entries`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an entry above 15.
    pub const fn new(entries: [u8; 256]) -> Result<Self> {
        let mut i = 0;
        while i < 256 {
            if entries[i] > 15 {
                return Err(Error::InvalidParameter {
                    what: "an LDBN table entry is 4 bits (0 to 15)",
                });
            }
            i += 1;
        }
        Ok(LdbnTable { entries })
    }

    /// The entries.
    pub const fn entries(&self) -> &[u8; 256] {
        &self.entries
    }

    /// The exchanges for configuration `key`.
    pub const fn get(&self, key: u8) -> u8 {
        self.entries[key as usize]
    }
}

/// Parses the 256 whitespace-separated decimal entries of `tables/ldbn-2x2.txt` (lines
/// starting with `#` are comments); at compile time, so a bad file fails the build.
const fn parse_table(text: &[u8]) -> [u8; 256] {
    let mut out = [0u8; 256];
    let (mut i, mut n) = (0, 0);
    while i < text.len() {
        let c = text[i];
        if c == b'#' {
            while i < text.len() && text[i] != b'\n' {
                i += 1;
            }
        } else if c.is_ascii_digit() {
            let mut v = 0u32;
            while i < text.len() && text[i].is_ascii_digit() {
                v = v * 10 + (text[i] - b'0') as u32;
                i += 1;
            }
            assert!(n < 256 && v < 16, "tables/ldbn-2x2.txt: bad entry");
            out[n] = v as u8;
            n += 1;
        } else {
            assert!(c.is_ascii_whitespace(), "tables/ldbn-2x2.txt: bad byte");
            i += 1;
        }
    }
    assert!(n == 256, "tables/ldbn-2x2.txt: needs 256 entries");
    out
}

/// The optimized table, `tables/ldbn-2x2.txt` (see the module documentation).
pub const LDBN_TABLE: LdbnTable = LdbnTable {
    entries: parse_table(include_bytes!("../../tables/ldbn-2x2.txt")),
};

/// Low-discrepancy blue noise (builder): `N = 4^k` points, seed 0, [`LDBN_TABLE`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ldbn {
    k: u32,
    seed: u64,
    table: LdbnTable,
}

impl Ldbn {
    /// `n` points, a power of four from 4 to [`LDBN_MAX_POINTS`]; the template scrambled
    /// from `seed`.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::InvalidParameter`] unless
    /// `n` is a power of four of at least 4.
    pub fn new(n: u64, seed: u64) -> Result<Self> {
        if n == 0 {
            return Err(Error::ZeroPoints);
        }
        if n > LDBN_MAX_POINTS {
            return Err(Error::TooManyPoints {
                requested: n,
                max: LDBN_MAX_POINTS,
            });
        }
        if n < 4 || !n.is_power_of_two() || !n.trailing_zeros().is_multiple_of(2) {
            return Err(Error::InvalidParameter {
                what: "LDBN takes a power of four of at least 4 points (N = 4^k)",
            });
        }
        Ok(Ldbn {
            k: n.trailing_zeros() / 2,
            seed,
            table: LDBN_TABLE,
        })
    }

    /// With `table` instead of [`LDBN_TABLE`] (the optimizer's candidates;
    /// [`LdbnTable::IDENTITY`] gives the template).
    pub fn table(mut self, table: LdbnTable) -> Self {
        self.table = table;
        self
    }

    /// The estimated running time: `N` template points.
    pub fn cost(&self) -> Cost {
        Cost::steps((1u64 << (2 * self.k)) as f64, POINTS)
    }

    /// The set (in the template's index order: point `i` stays in template point `i`'s
    /// cell), refused before it starts when [`cost`](Self::cost) exceeds `budget`.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::OutOfTime`], [`Error::TooLarge`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        const WHAT: &str = "low-discrepancy blue noise";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let (k, n) = (self.k, 1usize << (2 * self.k));
        let side = 1usize << k;
        let template = Scrambled::new(Sobol::new(2)?, ExactOwen::new(self.seed));
        let mut pts = crate::size::vec_zeroed::<u32>(crate::size::coordinates(n as u64, 2)?)?;
        template.fill(0, &mut pts)?;
        budget.check_deadline(WHAT)?;
        // cell[c + side r] = the index of the point in column c, row r.
        let mut cell = crate::size::vec_zeroed::<u32>(n)?;
        for (i, p) in pts.chunks_exact(2).enumerate() {
            let (c, r) = ((p[0] >> (32 - k)) as usize, (p[1] >> (32 - k)) as usize);
            if let Some(slot) = cell.get_mut(c + side * r) {
                *slot = i as u32;
            }
        }
        let half = side / 2;
        for t in 0..half * half {
            if t % 4096 == 0 {
                budget.check_deadline(WHAT)?;
            }
            let (a, b) = (2 * (t % half), 2 * (t / half));
            let at = |c: usize, r: usize| cell.get(c + side * r).map_or(0, |&i| i as usize);
            let idx = [at(a, b), at(a + 1, b), at(a, b + 1), at(a + 1, b + 1)];
            let coord = |i: usize, d: usize| pts.get(2 * i + d).copied().unwrap_or(0);
            let u = idx.map(|i| coord(i, 0) << k);
            let v = idx.map(|i| coord(i, 1) << k);
            let swaps = self.table.get(configuration(u, v));
            // (bit, dimension, the two cells): columns exchange u, rows exchange v.
            for (bit, d, p, q) in [(0, 0, 0, 2), (1, 0, 1, 3), (2, 1, 0, 1), (3, 1, 2, 3)] {
                if swaps >> bit & 1 == 1 {
                    exchange_offsets(&mut pts, 2 * idx[p] + d, 2 * idx[q] + d, k);
                }
            }
        }
        PointSet::new(pts, 2)
    }
}

/// A tile's configuration from the in-cell offsets (0.32 fractions of a cell) of its
/// cells `A, B, C, D`: bits 0 to 3 the orders `u_A > u_C`, `u_B > u_D`, `v_A > v_B`,
/// `v_C > v_D`; bits 4 to 7 whether those differences are at least half a cell.
pub const fn configuration(u: [u32; 4], v: [u32; 4]) -> u8 {
    let pairs = [(u[0], u[2]), (u[1], u[3]), (v[0], v[1]), (v[2], v[3])];
    let mut key = 0u8;
    let mut j = 0;
    while j < 4 {
        let (p, q) = pairs[j];
        if p > q {
            key |= 1 << j;
        }
        if p.abs_diff(q) >= 1 << 31 {
            key |= 1 << (j + 4);
        }
        j += 1;
    }
    key
}

/// Exchanges the in-cell offsets (the bits below the top `k`) of coordinates `i` and `j`.
fn exchange_offsets(pts: &mut [u32], i: usize, j: usize, k: u32) {
    let low = u32::MAX >> k;
    if let (Some(&x), Some(&y)) = (pts.get(i), pts.get(j)) {
        if let Some(p) = pts.get_mut(i) {
            *p = (x & !low) | (y & low);
        }
        if let Some(p) = pts.get_mut(j) {
            *p = (y & !low) | (x & low);
        }
    }
}
