//! Mitchell's best-candidate sampling (Mitchell, "Spectrally optimal sampling for
//! distribution ray tracing", SIGGRAPH 1991) on the unit torus.
//!
//! Point 0 is uniform; point `i` is the best of `m i` uniform candidates, the one farthest
//! (toroidal distance) from its nearest earlier point. The candidate count grows with the
//! set, so every prefix is itself a blue-noise set (the construction is progressive). With
//! `m = 10`: min distance about 0.74 and mean nearest-neighbour distance about 0.83 of the
//! hexagonal spacing `sqrt(2 / (sqrt(3) N))`.
//!
//! Cost: `m N^2 / 2` candidate tests. Most are settled by one look-up in a raster of
//! `(4 sqrt N)^2` cells (at most `2048^2`) holding an upper bound of the distance from the
//! cell to its nearest point: a candidate in a cell nearer than its round's best so far
//! cannot win. The others take a ring search in a uniform grid rebuilt as the set doubles
//! (about 2 points a cell), stopped as soon as the candidate cannot win. Both tests are
//! exact (the raster's bounds are conservative), so the sets are those of the ring search
//! alone. Estimated before it runs and checked against a [`Budget`].
//!
//! ```
//! use qmckit::blue_noise::BestCandidate;
//! use qmckit::work::Budget;
//! let set = BestCandidate::new(256)?.candidates(10)?.seed(1).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 256);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::grid::{SCALE, axis_gap};
use super::rng::Rng;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The most points [`BestCandidate`] makes (its cost is quadratic): 2^20.
pub const BEST_CANDIDATE_MAX_POINTS: u64 = 1 << 20;

/// Candidate tests a second (one core, release; measured about 1.5e8 at N = 1024 with
/// the cover raster, taken lower).
const TESTS: Rate = Rate::per_second(6e7);

/// Mitchell's best-candidate construction (builder).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BestCandidate {
    n: u64,
    m: u32,
    seed: u64,
}

impl BestCandidate {
    /// `n` points (1 to [`BEST_CANDIDATE_MAX_POINTS`]), `m = 10`, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`].
    pub fn new(n: u64) -> Result<Self> {
        crate::size::points(n, BEST_CANDIDATE_MAX_POINTS)?;
        Ok(BestCandidate { n, m: 10, seed: 0 })
    }

    /// The candidate multiplier `m` (1 to 1000): point `i` draws `m i` candidates.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn candidates(mut self, m: u32) -> Result<Self> {
        if !(1..=1000).contains(&m) {
            return Err(Error::InvalidParameter {
                what: "best-candidate multiplier must be 1 to 1000",
            });
        }
        self.m = m;
        Ok(self)
    }

    /// The seed.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The estimated running time: `m N^2 / 2` candidate tests.
    pub fn cost(&self) -> Cost {
        let n = self.n as f64;
        Cost::steps(f64::from(self.m) * n * n / 2.0, TESTS)
    }

    /// The set, refused before it starts when [`cost`](Self::cost) exceeds `budget`, and
    /// stopped at the budget's deadline (started here if the caller has not; the clock is
    /// read once every [`crate::work::PACER_INTERVAL`] candidates).
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let budget = budget.started();
        budget.check("best-candidate sampling", self.cost())?;
        let mut pacer = budget.pacer("best-candidate sampling");
        let n = self.n as usize;
        let mut rng = Rng::new(self.seed, 0x4245_5354_4341_4E44);
        let mut pts: Vec<[f64; 2]> = crate::size::vec_with_capacity(n)?;
        let mut grid = RingGrid::new(1);
        let first = [rng.fraction(), rng.fraction()].map(|c| f64::from(c) / SCALE);
        pts.push(first);
        grid.rebuild(&pts);
        let mut cover = Cover::new(n)?;
        cover.add(&first, 1);
        for i in 1..n {
            if i >= 2 * grid.built_for {
                grid = RingGrid::new(i);
                grid.rebuild(&pts);
            }
            let tries = (self.m as usize).saturating_mul(i);
            let mut best = first;
            let mut best_d2 = -1.0;
            for _ in 0..tries {
                pacer.tick()?;
                let (u, v) = (rng.fraction(), rng.fraction());
                if cover.loses(u, v, best_d2) {
                    continue;
                }
                let c = [u, v].map(|v| f64::from(v) / SCALE);
                if let Some(d2) = grid.nearest_beyond(&pts, &c, best_d2) {
                    best_d2 = d2;
                    best = c;
                }
            }
            pts.push(best);
            grid.insert(&pts, pts.len() - 1);
            cover.add(&best, pts.len());
        }
        let mut coords = crate::size::vec_zeroed::<u32>(crate::size::coordinates(n as u64, 2)?)?;
        for (row, p) in coords.chunks_exact_mut(2).zip(&pts) {
            for (c, x) in row.iter_mut().zip(p) {
                *c = (x * SCALE) as u32;
            }
        }
        PointSet::new(coords, 2)
    }
}

/// A raster of `R x R` cells over the torus holding, for each cell, an upper bound of the
/// squared distance from any location in it to its nearest point (`+inf` until a point
/// comes near). A candidate whose cell's bound is below the best squared distance of its
/// round cannot win, whatever its exact nearest distance: it is rejected with one look-up,
/// and the result is the same as the exact test's. Each new point `i` lowers the bounds of
/// the cells within `2 / sqrt(i)` of it (about `64 N / i` cells of side `1 / (2 sqrt N)`):
/// `O(N log N)` updates in all; the bounds are conservative (the unwrapped distance to the
/// cell's farthest corner, rounded up to `f32`).
struct Cover {
    /// Cells along an axis, a power of two (`2^bits`).
    bits: u32,
    ub: Vec<f32>,
}

impl Cover {
    fn new(n: usize) -> Result<Self> {
        let want = (4.0 * (n as f64).sqrt()).clamp(1.0, 2048.0);
        let bits = want.log2().ceil() as u32;
        let r = 1usize << bits;
        let mut ub = crate::size::vec_zeroed::<f32>(r * r)?;
        ub.fill(f32::INFINITY);
        Ok(Cover { bits, ub })
    }

    /// `true` when the cell of the fraction pair `(u, v)` is closer than `best_d2`
    /// everywhere to some point, with a relative margin of `1e-6`.
    #[inline]
    fn loses(&self, u: u32, v: u32, best_d2: f64) -> bool {
        if self.bits == 0 {
            return false;
        }
        let sh = 32 - self.bits;
        let idx = (((v >> sh) as usize) << self.bits) | (u >> sh) as usize;
        self.ub
            .get(idx)
            .is_some_and(|&b| f64::from(b) * (1.0 + 1e-6) < best_d2)
    }

    /// Lowers the bounds around `p`, the `count`-th point.
    fn add(&mut self, p: &[f64; 2], count: usize) {
        if self.bits == 0 {
            return;
        }
        let r = 1i64 << self.bits;
        let h = 1.0 / r as f64;
        let reach = 2.0 / (count as f64).sqrt();
        let k = ((reach / h).ceil() as i64).min(r / 2 - 1).max(0);
        let (px, py) = (p[0], p[1]);
        let (hx, hy) = ((px * r as f64) as i64, (py * r as f64) as i64);
        let far = |lo: f64, x: f64| (lo - x).abs().max((lo + h - x).abs());
        for dy in -k..=k {
            let cy = hy + dy;
            let gy = far(cy as f64 * h, py);
            let y = cy.rem_euclid(r) as usize;
            for dx in -k..=k {
                let cx = hx + dx;
                let gx = far(cx as f64 * h, px);
                let d2 = gx * gx + gy * gy;
                let x = cx.rem_euclid(r) as usize;
                if let Some(b) = self.ub.get_mut((y << self.bits) | x) {
                    // Rounded up: the stored bound never falls below the true one.
                    let f = d2 as f32;
                    let f = if f64::from(f) < d2 { f.next_up() } else { f };
                    if f < *b {
                        *b = f;
                    }
                }
            }
        }
    }
}

/// A uniform toroidal grid with per-cell linked lists of point indices.
struct RingGrid {
    g: usize,
    built_for: usize,
    head: Vec<u32>,
    next: Vec<u32>,
}

const NONE: u32 = u32::MAX;

impl RingGrid {
    /// A grid sized for about `count` points, two a cell.
    fn new(count: usize) -> Self {
        let g = ((count as f64 / 2.0).sqrt().floor() as usize).max(1);
        RingGrid {
            g,
            built_for: count.max(1),
            head: vec![NONE; g * g],
            next: Vec::new(),
        }
    }

    fn cell(&self, p: &[f64; 2]) -> (usize, usize) {
        let g = self.g as f64;
        (
            ((p[0] * g) as usize).min(self.g - 1),
            ((p[1] * g) as usize).min(self.g - 1),
        )
    }

    fn rebuild(&mut self, pts: &[[f64; 2]]) {
        self.next.clear();
        for i in 0..pts.len() {
            self.insert(pts, i);
        }
    }

    fn insert(&mut self, pts: &[[f64; 2]], i: usize) {
        let Some(p) = pts.get(i) else { return };
        let (cx, cy) = self.cell(p);
        let idx = cy * self.g + cx;
        if self.next.len() <= i {
            self.next.resize(i + 1, NONE);
        }
        if let (Some(h), Some(nx)) = (self.head.get(idx).copied(), self.next.get_mut(i)) {
            *nx = h;
        }
        if let Some(h) = self.head.get_mut(idx) {
            *h = i as u32;
        }
    }

    /// The squared toroidal distance from `c` to its nearest point, when it exceeds
    /// `floor2`; `None` as soon as some point is within `floor2` (the candidate loses).
    fn nearest_beyond(&self, pts: &[[f64; 2]], c: &[f64; 2], floor2: f64) -> Option<f64> {
        let g = self.g as i64;
        let side = 1.0 / self.g as f64;
        let (cx, cy) = self.cell(c);
        let mut best = f64::INFINITY;
        let max_ring = (g / 2) + 1;
        for ring in 0..=max_ring {
            // Points of ring `ring` are at least (ring - 1) cells away.
            let gap = (ring - 1).max(0) as f64 * side;
            if gap * gap >= best {
                break;
            }
            let all = 2 * ring + 1 >= g;
            let visit = |dx: i64, dy: i64, best: &mut f64| -> bool {
                // |dx|, |dy| < g here: one wrap, no division.
                let wrap = |v: i64| {
                    if v < 0 {
                        v + g
                    } else if v >= g {
                        v - g
                    } else {
                        v
                    }
                };
                let x = wrap(cx as i64 + dx) as usize;
                let y = wrap(cy as i64 + dy) as usize;
                let mut k = self.head.get(y * self.g + x).copied().unwrap_or(NONE);
                while k != NONE {
                    if let Some(p) = pts.get(k as usize) {
                        let (ax, ay) = (axis_gap(p[0], c[0], true), axis_gap(p[1], c[1], true));
                        let d2 = ax * ax + ay * ay;
                        if d2 < *best {
                            *best = d2;
                            if d2 <= floor2 {
                                return true;
                            }
                        }
                    }
                    k = self.next.get(k as usize).copied().unwrap_or(NONE);
                }
                false
            };
            if all {
                for dy in 0..g {
                    for dx in 0..g {
                        if visit(dx, dy, &mut best) {
                            return None;
                        }
                    }
                }
                break;
            }
            for dy in -ring..=ring {
                let step = if dy == -ring || dy == ring {
                    1
                } else {
                    2 * ring
                };
                let mut dx = -ring;
                while dx <= ring {
                    if visit(dx, dy, &mut best) {
                        return None;
                    }
                    dx += step.max(1);
                }
            }
        }
        (best > floor2).then_some(best)
    }
}
