//! AA patterns (after Ahmed, Huang & Deussen 2015, "AA Patterns for Point Sets with
//! Controlled Spectral Properties", ACM TOG 34(6), SIGGRAPH Asia): one point in each cell
//! of a turned square lattice, displaced inside its cell by a vector read from a small
//! table, the table indexed by the cell's label under an additive automaton, a discrete
//! irrational rotation of the integer lattice.
//!
//! ## The automaton
//!
//! Rotate the integer lattice `Z^2` by the angle `theta` with `cos theta = 1/phi`
//! (`phi` the golden ratio, `sin theta = phi^(-1/2)`); the label of cell `q = (x, y)` is the
//! quantization error of the rotated point, read on the torus:
//!
//! `l(q) = s + x A + y B (mod 1)`, `A = R e_1 = (cos theta, sin theta)`,
//! `B = R e_2 = (-sin theta, cos theta)`,
//!
//! with `s` a start label drawn from the seed. The labels are 0.32 fractions and the
//! automaton adds them (`l(x + 1, y) = l(x, y) + A`, a wrapping integer addition): no
//! multiplication, no floating point. Since `1`, `cos theta` and `sin theta` are linearly
//! independent over the rationals, the labels are equidistributed on the torus (Weyl), and
//! the labels of the neighbours of `q` are `l(q) + (i A + j B)`: the whole neighbourhood of
//! a cell is a function of its label. This is what the paper calls the structural
//! indexing of AA patterns: cells with nearby labels see the same surroundings, as tiles
//! of one kind do in a tile set, without any repetition of the pattern.
//!
//! ## The displacement table
//!
//! The label torus is cut into `32 x 32` bins; [`AA_TABLE`] gives each bin a displacement
//! `d` in cell units, `|d_x|, |d_y| < 1/2`. The table is
//! `tables/aa_displacements.rs`, made by `examples/aa_optimize.rs`: gradient descent, on
//! `192 x 192` patches of the pattern laid on the turned lattices of `K` = 16, 32, 64 and
//! 128 in turn (below; each bin's displacement moved by the mean gradient of the cells that
//! read it), of the mismatch between the patch's pair correlation and that of step blue
//! noise with cutoff `u0 = 0.5` (Heck, Schlömer & Deussen 2013) plus a hard-core penalty
//! `W sum (r0 - r)^2` on the pairs closer than `r0 = 1.04` cells. The paper optimizes its
//! displacement vectors towards a target spectrum with the points kept apart; the penalty
//! is that spacing (without it, pairs come as close as in jittered sampling), the
//! pair-correlation term keeps the lattice's regularity out (the penalty alone is minimal
//! near the lattice, which has distance 1). The angle, bins and objective are this
//! module's choices, not the paper's. Its sets at `N = 1024` have a mean nearest-neighbour
//! distance about 0.97 cell and no pair closer than half a cell (tested).
//!
//! ## The lattice
//!
//! The cells are those of the lattice `G Z^2 / K^2` on the unit torus,
//! `G = [[a, -b], [b, d]]` with `a d + b^2 = K^2` ([`lattice`]): the point of cell
//! `q = (x, y)` is `G (q + 1/2 + D(l(q))) / K^2 (mod 1)` (`D` the table's displacement), `q` over the `K^2` integer
//! vectors with `G q` in `[0, K^2)^2` (one for each point of the lattice on the torus,
//! since `adj G = K^2 G^-1` is an integer matrix). `G / K` is a rotation by 20° to 40°
//! up to `|d - a| / K <= 1/10` (exactly, when `K^2 - b^2 = a^2`: `K = 5` gives the rotation
//! by `atan(3/4)`), so a cell's neighbourhood is the table's, turned. The turn is what the
//! paper's construction has and an axis-aligned grid does not: its points follow the AA
//! pattern of a rotated and scaled lattice, not the cells of the square's grid. Read on an
//! axis-aligned `K x K` grid the table's displacements (fitted to spread the points, so
//! concentrated in the middle half of the cell in each coordinate) leave every column and
//! row of cells with the same uneven profile: the projections on the axes have
//! discrepancy about `0.3 / K` and the star discrepancy at `N = 1024` is 0.020; on the
//! turned lattice the profile falls across each column at every phase and `D*` is 0.0094
//! (32 seeds; a jittered grid 0.0133). When no such `G` exists (`K` = 1 to 4, 6 to 9, 12
//! and 18, the only ones up to 4096) the lattice is the axis-aligned grid, `G = K I`. Points
//! are wrapped into the square: the labels jump only at its border, where the lattice
//! is cut.
//!
//! ## Range and cost
//!
//! `N = K^2`, `K` from 1 to 4096; any seed. `O(N)`: the lattice vectors `q` of a box of
//! about `(b + d) (a + b)`, at most `2 N`, are tried, and each kept one costs two wrapping
//! additions and one table read; memory `2N` words through [`crate::size`]. Estimated
//! ([`AaPattern::cost`]) against a [`Budget`], the deadline read every 4096 rows.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::blue_noise::AaPattern;
//! use qmckit::work::Budget;
//! let set = AaPattern::new(1024, 7)?.generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 1024);
//! // The lattice: G = [[24, -20], [20, 26]], 24 * 26 + 20^2 = 32^2.
//! assert_eq!(qmckit::blue_noise::aa::lattice(32), [24, 20, 26]);
//! // One point in each cell: adj G = K^2 G^-1 = [[26, 20], [-20, 24]] takes a point to
//! // q + 1/2 + d, whose floor is its cell q, known up to the periods adj G Z^2 (the
//! // wrapping); G q mod K^2 names the cell.
//! let mut cells = std::collections::HashSet::new();
//! for i in 0..1024 {
//!     let x = set.sample(i, 0)? as f64 / 4_294_967_296.0;
//!     let y = set.sample(i, 1)? as f64 / 4_294_967_296.0;
//!     let (q1, q2) = ((26.0 * x + 20.0 * y).floor() as i64, (24.0 * y - 20.0 * x).floor() as i64);
//!     cells.insert(((24 * q1 - 20 * q2).rem_euclid(1024), (20 * q1 + 26 * q2).rem_euclid(1024)));
//! }
//! assert_eq!(cells.len(), 1024);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::lloyd::to_fraction;
use super::rng::Rng;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The most points [`AaPattern`] takes: `4096^2 = 2^24`.
pub const AA_MAX_POINTS: u64 = 1 << 24;

/// Bins a side of the label torus: the table has `AA_BINS^2` entries.
pub const AA_BINS: usize = 32;

/// `A = R e_1` as 0.32 fractions: `(cos theta, sin theta)`, `cos theta = 1/phi`.
pub const AA_STEP_X: [u32; 2] = [0x9e37_79b9, 0xc941_3779];

/// `B = R e_2` as 0.32 fractions: `(-sin theta, cos theta)` modulo 1.
pub const AA_STEP_Y: [u32; 2] = [0x36be_c887, 0x9e37_79b9];

/// Points a second, one core, release (a lattice vector tried or kept, a label addition and
/// a table read; measured 3.2e7 with the command's output, `qmckit points aa-patterns -n
/// 16777216 --format u32`, 0.52 s of user time; taken low).
const POINTS: Rate = Rate::per_second(2e7);

/// The label of cell `(x, y)` for start label `s`: `s + x A + y B` modulo 1.
pub const fn label(s: [u32; 2], x: u32, y: u32) -> [u32; 2] {
    [
        s[0].wrapping_add(x.wrapping_mul(AA_STEP_X[0]))
            .wrapping_add(y.wrapping_mul(AA_STEP_Y[0])),
        s[1].wrapping_add(x.wrapping_mul(AA_STEP_X[1]))
            .wrapping_add(y.wrapping_mul(AA_STEP_Y[1])),
    ]
}

/// The table bin of a label: `u_bin + AA_BINS v_bin`.
pub const fn bin(l: [u32; 2]) -> usize {
    let shift = 32 - AA_BINS.trailing_zeros();
    (l[0] >> shift) as usize + AA_BINS * (l[1] >> shift) as usize
}

/// A displacement table: for each bin, `(d_x, d_y)` in cell units, each in `(-1/2, 1/2)`.
#[derive(Clone, Debug, PartialEq)]
pub struct AaTable {
    entries: [[f64; 2]; AA_BINS * AA_BINS],
}

impl AaTable {
    /// No displacement: the cell centres, the `K x K` grid.
    pub const ZERO: AaTable = AaTable {
        entries: [[0.0; 2]; AA_BINS * AA_BINS],
    };

    /// The table of `entries`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an entry that is not finite or not in `(-1/2, 1/2)`.
    pub fn new(entries: [[f64; 2]; AA_BINS * AA_BINS]) -> Result<Self> {
        if entries
            .iter()
            .flatten()
            .any(|d| d.is_nan() || d.abs() >= 0.5)
        {
            return Err(Error::InvalidParameter {
                what: "an AA displacement is in cell units, strictly between -1/2 and 1/2",
            });
        }
        Ok(AaTable { entries })
    }

    /// The entries, by bin.
    pub fn entries(&self) -> &[[f64; 2]; AA_BINS * AA_BINS] {
        &self.entries
    }
}

/// The optimized table, `tables/aa_displacements.rs` (see the module documentation).
pub const AA_TABLE: AaTable = AaTable {
    entries: include!("../../tables/aa_displacements.rs"),
};

/// An AA-pattern point set (builder): `N = K^2` points, seed 0, [`AA_TABLE`].
#[derive(Clone, Debug, PartialEq)]
pub struct AaPattern {
    side: u32,
    seed: u64,
    table: AaTable,
}

impl AaPattern {
    /// `n` points, a perfect square `K^2` from 1 to [`AA_MAX_POINTS`]; the start label
    /// drawn from `seed`.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::InvalidParameter`] unless
    /// `n` is a perfect square.
    pub fn new(n: u64, seed: u64) -> Result<Self> {
        crate::size::points(n, AA_MAX_POINTS)?;
        let side = n.isqrt();
        if side * side != n {
            return Err(Error::InvalidParameter {
                what: "AA patterns take a square number of points (N = K^2, one a grid cell)",
            });
        }
        Ok(AaPattern {
            side: side as u32,
            seed,
            table: AA_TABLE,
        })
    }

    /// With `table` instead of [`AA_TABLE`] ([`AaTable::ZERO`] gives the grid of cell
    /// centres).
    pub fn table(mut self, table: AaTable) -> Self {
        self.table = table;
        self
    }

    /// The start label `s` of the automaton for the seed.
    pub fn start(&self) -> [u32; 2] {
        let mut rng = Rng::new(self.seed, 0xaa);
        [rng.fraction(), rng.fraction()]
    }

    /// The estimated running time: `N` points.
    pub fn cost(&self) -> Cost {
        Cost::steps(f64::from(self.side) * f64::from(self.side), POINTS)
    }

    /// The set, by lattice row (`q_2`, then `q_1`; on the axis-aligned grid point
    /// `x + K y` is in cell `(x, y)`), refused before it starts when [`cost`](Self::cost)
    /// exceeds `budget`.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::OutOfTime`], [`Error::TooLarge`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        const WHAT: &str = "AA patterns";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let k = self.side;
        let n = u64::from(k) * u64::from(k);
        let mut coords = crate::size::vec_with_capacity(crate::size::coordinates(n, 2)?)?;
        let [a, b, d] = lattice(k).map(i64::from);
        let k2 = i64::from(k) * i64::from(k);
        let scale = 1.0 / k2 as f64;
        let (af, bf, df) = (a as f64, b as f64, d as f64);
        let wrap = |v: f64| v - v.floor();
        let s = self.start();
        // The lattice points `G q` in `[0, K^2)^2`: `q_1` in `[0, b + d]`, `q_2` in
        // `[-b, a]` (the preimage of the square under `G`, `G^-1 = adj G / K^2`).
        for q2 in -b..=a {
            if q2 % 4096 == 0 {
                budget.check_deadline(WHAT)?;
            }
            let mut l = label(s, 0, q2 as u32);
            for q1 in 0..=(b + d) {
                let (y1, y2) = (a * q1 - b * q2, b * q1 + d * q2);
                if (0..k2).contains(&y1) && (0..k2).contains(&y2) {
                    let e = self.table.entries.get(bin(l)).copied().unwrap_or([0.0; 2]);
                    let u = (q1 as f64 + 0.5 + e[0], q2 as f64 + 0.5 + e[1]);
                    coords.push(to_fraction(wrap((af * u.0 - bf * u.1) * scale)));
                    coords.push(to_fraction(wrap((bf * u.0 + df * u.1) * scale)));
                }
                l = [
                    l[0].wrapping_add(AA_STEP_X[0]),
                    l[1].wrapping_add(AA_STEP_X[1]),
                ];
            }
        }
        PointSet::new(coords, 2)
    }
}

/// `tan 20°` and `tan 40°`: the range of the lattice's angle.
const TAN_LO: f64 = 0.363_970_234_266_202_4;
const TAN_HI: f64 = 0.839_099_631_177_28;

/// The lattice matrix `G = [[a, -b], [b, d]]` (returned as `[a, b, d]`) of side `K`:
/// `det G = a d + b^2 = K^2`, so that `G Z^2 / K^2` contains `Z^2` with index `K^2`
/// (exactly `K^2` points on the unit torus), and `G / K` is within `|d - a| / K <= 1/10`
/// of a rotation by `atan(2 b / (a + d))`, between 20° and 40°. Among the `b` in
/// `1..K` (for each the factorization `K^2 - b^2 = a d`, `a <= d`, with `d - a` least), the
/// least `d - a`, the first such `b`; without one (`K` = 1 to 4, 6 to 9, 12 and 18), the
/// axis-aligned grid `[K, 0, K]`. `K = 32` gives `[24, 20, 26]` (38.7°, 6%). Cost
/// `O(K^2 / 20)` divisions at most.
pub fn lattice(k: u32) -> [u32; 3] {
    let k = u64::from(k);
    let mut best: Option<(u64, [u32; 3])> = None;
    for b in 1..k {
        let m = k * k - b * b;
        let root = m.isqrt();
        // a + d >= 2 sqrt(m): the angle is at most atan(b / sqrt m).
        if (b as f64) < TAN_LO * root as f64 {
            continue;
        }
        let limit = best.map_or(k / 10, |(delta, _)| delta.saturating_sub(1));
        let mut a = root;
        while a > 0 && m / a - a <= limit {
            if m % a == 0 {
                let d = m / a;
                let t = 2.0 * b as f64 / (a + d) as f64;
                if (TAN_LO..=TAN_HI).contains(&t) {
                    best = Some((d - a, [a as u32, b as u32, d as u32]));
                }
                break;
            }
            a -= 1;
        }
    }
    best.map_or([k as u32, 0, k as u32], |(_, g)| g)
}
#[cfg(test)]
mod tests {
    use super::*;

    /// The automaton's additions are the closed form, and the steps are the rotation.
    #[test]
    fn automaton_is_the_rotated_lattice() {
        let s = [12345, 987654321];
        let mut row = s;
        for y in 0..50 {
            let mut l = row;
            for x in 0..50 {
                assert_eq!(l, label(s, x, y));
                l = [
                    l[0].wrapping_add(AA_STEP_X[0]),
                    l[1].wrapping_add(AA_STEP_X[1]),
                ];
            }
            row = [
                row[0].wrapping_add(AA_STEP_Y[0]),
                row[1].wrapping_add(AA_STEP_Y[1]),
            ];
        }
        let f = |v: u32| f64::from(v) / 4_294_967_296.0;
        let c = 2.0 / (1.0 + 5f64.sqrt());
        let s = (1.0 - c * c).sqrt();
        assert!((f(AA_STEP_X[0]) - c).abs() < 1e-9 && (f(AA_STEP_X[1]) - s).abs() < 1e-9);
        assert!((f(AA_STEP_Y[0]) - (1.0 - s)).abs() < 1e-9);
        assert!((f(AA_STEP_Y[1]) - c).abs() < 1e-9);
    }

    #[test]
    fn the_table_keeps_points_in_their_cells() {
        assert!(AaTable::new(*AA_TABLE.entries()).is_ok());
    }
}
