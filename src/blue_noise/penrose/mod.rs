//! Hierarchical sampling on a Penrose tiling, after Ostromoukhov, Donohue & Jodoin 2004
//! ("Fast Hierarchical Importance Sampling with Blue Noise Properties", ACM TOG 23(3),
//! SIGGRAPH): one sample a tile of a recursively subdivided Penrose tiling, the tiles
//! ranked through the subdivision so that thresholding the ranks against a density gives
//! that density, at any level of the hierarchy.
//!
//! ## The tiling
//!
//! The rhombus tiling (P3) cut into Robinson triangles: a *thin* half (the golden triangle,
//! angles 36°, 72°, 72°, legs `l`, base `l / phi`) and a *thick* half (the golden gnomon,
//! 108°, 36°, 36°, legs `l`, base `phi l`), `phi = (1 + sqrt 5) / 2`. A triangle
//! `(a, b, c)` with its apex `a` subdivides into triangles of legs `l / phi`:
//!
//! * thin: `p = a + (b - a) / phi`; children thin `(c, p, b)` and thick `(p, c, a)`;
//! * thick: `q = b + (a - b) / phi`, `r = b + (c - b) / phi`; children thick `(r, c, a)`,
//!   thick `(q, r, b)` and thin `(r, q, a)`.
//!
//! Areas shrink by `phi^2` a level, and a thin (thick) triangle has `F(2h + 1)`
//! (`F(2h + 2)`) descendants `h` levels down, `F` the Fibonacci numbers (`F(1) = F(2) = 1`):
//! the counts obey `thin(h) = thin(h-1) + thick(h-1)`, `thick(h) = thin(h-1) + 2 thick(h-1)`.
//! The start is the "sun", ten thin triangles of legs 1 around the origin (a decagon of
//! area `5 sin 36°`), subdivided `L` levels; the unit square sits inside it, rotated by a
//! random angle and moved by a random offset of at most 0.1 from the centre (the seed).
//! Each leaf triangle carries one sample, at its centroid moved by a correction vector
//! (below).
//!
//! ## The ranks
//!
//! A tile `T` of height `h` with children `C_1 .. C_k` (their leaf counts `m_j`, `n = sum
//! m_j`) orders its leaves by interleaving its children's orders: slot `s = 0 .. n-1` of
//! `T` goes to the child with the largest deficit `(s + 1) m_j - t_j n` (`t_j` the slots it
//! has, ties to the first child), and that child's next leaf takes it. So among the first
//! `s` leaves of `T`, child `j` holds `s m_j / n` within one, at every level at once: the
//! first `t n` leaves of the whole tiling hold about `t` of the leaves of every tile (to
//! within one leaf a level). The leaves' global ranks are the paper's thresholds; where
//! the paper numbers the tiles in the Fibonacci number system, the ranks here follow the
//! same Fibonacci counts through this interleaving (our construction).
//!
//! * [`Penrose::generate`]: `N` points, the first `N` leaves of the square in rank order
//!   (the depth `L` the least with at least `N` leaves in the square). The set is
//!   progressive: every prefix of it is a uniform set of that many points.
//! * [`importance`]: density `rho` (points per unit area): the leaf at `x` of global rank
//!   `i` is kept when `(i + 1/2) / n_leaves < rho(x) / D`, `D = n_leaves / area` the leaf
//!   density (at least the density's maximum). The expected count in a region is the
//!   integral of `rho` over it, to the rank stratification's error.
//!
//! ## Correction vectors
//!
//! As in the paper, samples move by vectors learned offline by relaxation: the sample of a
//! leaf `(a, b, c)` is `centroid + alpha (b - a) + beta (c - a)`, `(alpha, beta)` from a
//! [`Table`] indexed by the leaf's class (its index among the 89 or 144 leaves of its
//! ancestor five levels up: the last five levels of its path, the counterpart of the
//! paper's structural index, the last digits of the F-code) and the band of the threshold
//! fraction `t` (21 bands of `(phi^-2, 1]`, equal in `log t`, as the paper's 21 importance
//! indices cut a level's period); a move that would leave the square stops at its border.
//! The table, `tables/penrose_corrections.rs`, is made by our optimizer
//! ([`crate::blue_noise::penrose_train`]). [`Penrose::corrected`]`(false)` keeps the
//! centroids (the tiling's rings of centroids around its vertices, a minimum distance of
//! about 0.57 of the hexagonal spacing).
//!
//! ## Deviation from the paper
//!
//! The paper's samples sit on the tiling's vertices and are thresholded by their F-codes;
//! here one sample a triangle, at its centroid, thresholded by the interleaved ranks
//! above. The table's indexing (five levels where the paper's structural index reads
//! three) and values are ours; [`importance`] leaves its samples at the centroids (its
//! threshold varies over the square, and a table row holds for one band); the depth is
//! uniform (the paper refines only where the density asks). The sun's centre lies within
//! 0.1 of the square's, so its ten-fold configuration recurs around it, and a few pairs
//! that the table moves towards each other are sometimes both kept (at 1024 points about
//! 0.1% of the samples have a neighbour within 0.05 of the hexagonal spacing).
//!
//! ## Cost
//!
//! `O(M L)` for the `M` leaves in and around the square (`M` at most `phi^2 N` plus the
//! border) and `L = O(log N)` levels, plus sorting `M` ranks; memory about `M + 0.42 n`
//! words for `n` leaves of the whole sun (the rank tables). Estimated ([`Penrose::cost`])
//! against a [`Budget`] and stopped at its deadline.
//!
//! ```
//! use qmckit::blue_noise::Penrose;
//! use qmckit::work::Budget;
//! let set = Penrose::new(500)?.seed(1).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 500);
//! # Ok::<(), qmckit::Error>(())
//! ```

mod corrections;
mod tiling;

pub use corrections::Table;
pub(crate) use corrections::{BANDS, CLASSES, NO_CLASS, band, place};
pub(crate) use tiling::{Frame, Leaf};

use super::PointSet;
use super::lloyd::to_fraction;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};
use corrections::CORRECTIONS;
use tiling::{PHI, Tables, leaves, square_leaves, sun_area};

/// The most points [`Penrose`] and [`importance`] give: 2^20.
pub const PENROSE_MAX_POINTS: u64 = 1 << 20;

/// The deepest subdivision (the sun then has `10 F(2 L + 1)` leaves, 2.9e8 at 20).
const MAX_LEVELS: usize = 20;

/// Leaf steps a second, one core, release (a leaf's rank walk over its levels counted as
/// one step a level; 10^6 points, written by the command, took 6.6 s on a loaded machine
/// against 2.5 s estimated at 5e7, so taken at 2e7).
const STEPS: Rate = Rate::per_second(2e7);

/// The least depth whose leaves in the square number at least `density` a unit area (on
/// average), or an error past [`MAX_LEVELS`].
pub(crate) fn depth_for(density: f64) -> Result<usize> {
    (1..=MAX_LEVELS)
        .find(|&l| 10.0 * leaves(l).0 as f64 / sun_area() >= density)
        .ok_or(Error::InvalidParameter {
            what: "penrose sampling takes at most 2^20 points a unit area",
        })
}

/// The estimated cost of a subdivision giving about `density` leaves a unit area: the
/// square's leaves (at most `phi^2` times the density), their rank walks of `L` levels,
/// the pruned border and the rank tables.
fn cost_for(density: f64) -> Cost {
    let levels = depth_for(density).unwrap_or(MAX_LEVELS) as f64;
    let leaves = density * PHI * PHI * 1.3;
    Cost::steps(leaves * (levels + 2.0 + leaves.log2().max(1.0)), STEPS)
}

/// The leaves of the square at `levels` for `seed`, sorted by rank, the frame, and the
/// number of leaves of the sun.
pub(crate) fn ranked(levels: usize, seed: u64, budget: &Budget) -> Result<(Vec<Leaf>, Frame, u64)> {
    const WHAT: &str = "penrose sampling";
    let mut pacer = budget.pacer(WHAT);
    let tables = Tables::new(levels, &mut pacer)?;
    let frame = Frame::new(seed);
    let mut leaves = square_leaves(&tables, &frame, &mut pacer)?;
    leaves.sort_unstable_by_key(|l| l.rank);
    Ok((leaves, frame, tables.total()))
}

/// The legs of the leaves of a sun of legs 1 subdivided `levels` times.
pub(crate) fn leg(levels: usize) -> f64 {
    PHI.powi(-(levels as i32))
}

fn to_set(points: impl ExactSizeIterator<Item = [f64; 2]>) -> Result<PointSet> {
    let mut coords =
        crate::size::vec_with_capacity(crate::size::coordinates(points.len() as u64, 2)?)?;
    coords.extend(points.flat_map(|p| p.map(to_fraction)));
    PointSet::new(coords, 2)
}

/// Penrose-tiling sampling of the unit square (builder): `N` points in rank order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Penrose {
    n: u64,
    seed: u64,
    corrected: bool,
}

impl Penrose {
    /// `n` points (1 to [`PENROSE_MAX_POINTS`]), seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`].
    pub fn new(n: u64) -> Result<Self> {
        crate::size::points(n, PENROSE_MAX_POINTS)?;
        Ok(Penrose {
            n,
            seed: 0,
            corrected: true,
        })
    }

    /// Whether the samples move by the correction table (default `true`; `false`: the
    /// leaves' centroids).
    pub fn corrected(mut self, corrected: bool) -> Self {
        self.corrected = corrected;
        self
    }

    /// The seed: the rotation and offset of the square in the tiling.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The estimated running time (module doc, "Cost").
    pub fn cost(&self) -> Cost {
        cost_for(self.n as f64)
    }

    /// The `N` points of lowest rank among the leaves in the square: every prefix of the
    /// set is a uniform set. Refused before it starts when [`cost`](Self::cost) exceeds
    /// `budget`, stopped at its deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let budget = budget.started();
        budget.check("penrose sampling", self.cost())?;
        let mut levels = depth_for(self.n as f64)?;
        loop {
            let (leaves, frame, _) = ranked(levels, self.seed, &budget)?;
            if leaves.len() as u64 >= self.n {
                let b = band(self.n as f64 / leaves.len() as f64);
                let (leg, n) = (leg(levels), self.n as usize);
                return to_set(leaves.iter().take(n).map(|l| {
                    if self.corrected {
                        place(l, &frame, leg, b, &CORRECTIONS)
                    } else {
                        l.p
                    }
                }));
            }
            // The square holds fewer leaves than the mean says (its border): one more level.
            levels += 1;
            if levels > MAX_LEVELS {
                return Err(Error::InvalidParameter {
                    what: "penrose sampling: too many points for the deepest subdivision",
                });
            }
        }
    }
}

/// Importance sampling of the unit square by thresholding Penrose ranks: about
/// `integral of density` points, `density(x, y)` points a unit area, at most
/// `max_density` (1 to [`PENROSE_MAX_POINTS`]), in rank order (the set of a smaller
/// multiple of the density is a prefix-closed subset).
///
/// ```
/// use qmckit::blue_noise::penrose;
/// use qmckit::work::Budget;
/// // 2000 x on the square: about 1000 points, more to the right.
/// let set = penrose::importance(|x, _| 2000.0 * x, 2000.0, 0, &Budget::DEFAULT)?;
/// assert!((set.count() as f64 - 1000.0).abs() < 50.0);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for a `max_density` outside that range or a density value
/// that is not finite or outside `[0, max_density]`; as [`Penrose::generate`].
pub fn importance<F: Fn(f64, f64) -> f64>(
    density: F,
    max_density: f64,
    seed: u64,
    budget: &Budget,
) -> Result<PointSet> {
    if !(1.0..=PENROSE_MAX_POINTS as f64).contains(&max_density) {
        return Err(Error::InvalidParameter {
            what: "penrose importance sampling takes a maximum density from 1 to 2^20",
        });
    }
    let budget = budget.started();
    budget.check("penrose sampling", cost_for(max_density))?;
    let levels = depth_for(max_density)?;
    let (leaves, _, total) = ranked(levels, seed, &budget)?;
    let total = total as f64;
    let leaf_density = total / sun_area();
    let mut kept = crate::size::vec_with_capacity::<[f64; 2]>(0)?;
    for leaf in leaves {
        let rho = density(leaf.p[0], leaf.p[1]);
        if !(0.0..=max_density).contains(&rho) {
            return Err(Error::InvalidParameter {
                what: "penrose importance sampling: a density value not in [0, max_density]",
            });
        }
        if (f64::from(leaf.rank) + 0.5) / total < rho / leaf_density {
            crate::size::reserve(&mut kept, 1)?;
            kept.push(leaf.p);
        }
    }
    to_set(kept.into_iter())
}
