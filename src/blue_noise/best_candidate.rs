//! Mitchell's best-candidate sampling (Mitchell, "Spectrally optimal sampling for
//! distribution ray tracing", SIGGRAPH 1991) on the unit torus.
//!
//! Point 0 is uniform; point `i` is the best of `m i` uniform candidates, the one farthest
//! (toroidal distance) from its nearest earlier point. The candidate count grows with the
//! set, so every prefix is itself a blue-noise set (the construction is progressive). With
//! `m = 10`: min distance about 0.74 and mean nearest-neighbour distance about 0.83 of the
//! hexagonal spacing `sqrt(2 / (sqrt(3) N))`.
//!
//! Cost: `m N^2 / 2` candidate tests, each a ring search in a uniform grid rebuilt as the
//! set doubles (about 2 points a cell), stopped as soon as the candidate cannot win;
//! estimated before it runs and checked against a [`Budget`].
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

/// Candidate tests a second (one core, release; a conservative figure).
const TESTS: Rate = Rate::per_second(2e7);

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
        if n == 0 {
            return Err(Error::ZeroPoints);
        }
        if n > BEST_CANDIDATE_MAX_POINTS {
            return Err(Error::TooManyPoints {
                requested: n,
                max: BEST_CANDIDATE_MAX_POINTS,
            });
        }
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
                let c = [rng.fraction(), rng.fraction()].map(|v| f64::from(v) / SCALE);
                if let Some(d2) = grid.nearest_beyond(&pts, &c, best_d2) {
                    best_d2 = d2;
                    best = c;
                }
            }
            pts.push(best);
            grid.insert(&pts, pts.len() - 1);
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
                let x = (cx as i64 + dx).rem_euclid(g) as usize;
                let y = (cy as i64 + dy).rem_euclid(g) as usize;
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
