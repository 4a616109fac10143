//! AA patterns (after Ahmed, Huang & Deussen 2015, "AA Patterns for Point Sets with
//! Controlled Spectral Properties", ACM TOG 34(6), SIGGRAPH Asia): one point in each cell
//! of a `K x K` grid, displaced inside its cell by a vector read from a small table, the
//! table indexed by the cell's label under an additive automaton, a discrete irrational
//! rotation of the integer lattice.
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
//! `d` in cell units, `|d_x|, |d_y| < 1/2`; the point of cell `q` is
//! `((x + 1/2 + d_x) / K, (y + 1/2 + d_y) / K)`, always inside its cell. The table is
//! `tables/aa_displacements.rs`, made by `examples/aa_optimize.rs`: gradient descent, on
//! `192 x 192` patches of the pattern (each bin's displacement moved by the mean gradient
//! of the cells that read it), of the mismatch between the patch's pair correlation and
//! that of step blue noise with cutoff `u0 = 0.5` (Heck, Schlömer & Deussen 2013) plus a
//! hard-core penalty `W sum (r0 - r)^2` on the pairs closer than `r0 = 1.07` cells. The
//! paper optimizes its displacement vectors towards a target spectrum with the points kept
//! apart; the penalty is that spacing (without it, pairs come as close as in jittered
//! sampling), the pair-correlation term keeps the grid's regularity out (the penalty alone
//! is minimal near the grid, which has distance 1). The angle, bins and objective are this
//! module's choices, not the paper's. Its sets at `N = 1024` have a mean nearest-neighbour
//! distance about 0.97 cell and no pair closer than half a cell (tested).
//!
//! ## Range and cost
//!
//! `N = K^2`, `K` from 1 to 4096; any seed. `O(N)`: two wrapping additions and one table
//! read a point; memory `2N` words through [`crate::size`]. Estimated ([`AaPattern::cost`])
//! against a [`Budget`], the deadline read every 4096 rows.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::blue_noise::AaPattern;
//! use qmckit::work::Budget;
//! let set = AaPattern::new(1024, 7)?.generate(&Budget::DEFAULT)?;
//! // One point in each of the 32 x 32 cells.
//! let mut cells = [0u32; 1024];
//! for i in 0..1024 {
//!     let (x, y) = (set.sample(i, 0)? >> 27, set.sample(i, 1)? >> 27);
//!     cells[(x * 32 + y) as usize] += 1;
//! }
//! assert!(cells.iter().all(|&c| c == 1));
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

/// Points a second, one core, release (a label addition and a table read; measured 3.5e7
/// with the command's output, `qmckit points aa-patterns -n 16777216`, 0.48 s; taken low).
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
        if n == 0 {
            return Err(Error::ZeroPoints);
        }
        if n > AA_MAX_POINTS {
            return Err(Error::TooManyPoints {
                requested: n,
                max: AA_MAX_POINTS,
            });
        }
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

    /// The set, row by row (point `x + K y` in cell `(x, y)`), refused before it starts
    /// when [`cost`](Self::cost) exceeds `budget`.
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
        let scale = 1.0 / f64::from(k);
        let mut row = self.start();
        for y in 0..k {
            if y % 4096 == 0 {
                budget.check_deadline(WHAT)?;
            }
            let mut l = row;
            for x in 0..k {
                let d = self.table.entries.get(bin(l)).copied().unwrap_or([0.0; 2]);
                coords.push(to_fraction((f64::from(x) + 0.5 + d[0]) * scale));
                coords.push(to_fraction((f64::from(y) + 0.5 + d[1]) * scale));
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
        PointSet::new(coords, 2)
    }
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
