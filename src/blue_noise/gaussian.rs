//! Gaussian blue noise (Ahmed, Ren & Wonka, "Gaussian blue noise", ACM TOG 41(6), 2022) on
//! the unit torus in 2D.
//!
//! Gradient descent on the energy `E = sum_{i != j} exp(-N |x_i - x_j|^2 / (2 sigma^2))`
//! (toroidal nearest-image differences, `sigma = 1` in units of the mean spacing
//! `1/sqrt(N)`): from `N` uniform points, each iteration moves every point at once (Jacobi)
//! by `x_i <- x_i + s sum_{j != i} d_ij exp(-N |d_ij|^2 / (2 sigma^2))`, `d_ij = x_i - x_j`
//! wrapped to `[-1/2, 1/2)`, `s = 0.25` (the paper's step for 2D), modulo 1. The sum is cut
//! at `|d| < 6 sigma / sqrt(N)` (dropped terms below `e^-18`). A few hundred iterations give
//! a spectrum near zero up to about `0.6 sqrt(N)` (below 0.01 of white noise for
//! `|k| < 0.5 sqrt(N)` after 500 iterations, tested).
//!
//! Cost: `O(N c)` per iteration for `c ≈ 36 pi` neighbours (a grid of cells at least the
//! cut-off), in parallel over points; the result does not depend on the thread count.
//! Estimated before it runs and checked against a [`Budget`].
//!
//! ```
//! use qmckit::blue_noise::GaussianBlueNoise;
//! use qmckit::work::Budget;
//! let set = GaussianBlueNoise::new(128)?.iterations(50)?.seed(2).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 128);
//! # Ok::<(), qmckit::Error>(())
//! ```

use rayon::prelude::*;

use super::PointSet;
use super::grid::SCALE;
use super::rng::Rng;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The most points [`GaussianBlueNoise`] takes: 2^24.
pub const GBN_MAX_POINTS: u64 = 1 << 24;

/// Pair terms a second on two cores (release; measured 1.7e8 to 1.9e8 for 10^3 to 10^5
/// points, docs/budgets.md).
const TERMS: Rate = Rate::per_second(1.6e8);

/// Points between two readings of the clock inside one iteration (a few hundred
/// microseconds of work).
const DEADLINE_POINTS: usize = 4096;

/// The cut-off in units of `sigma / sqrt(N)`.
const CUTOFF: f64 = 6.0;

/// The Gaussian blue-noise construction (builder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaussianBlueNoise {
    n: u64,
    iterations: u32,
    sigma: f64,
    seed: u64,
}

impl GaussianBlueNoise {
    /// `n` points (2 to [`GBN_MAX_POINTS`]), 500 iterations, `sigma = 1`, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::InvalidParameter`] for one
    /// point (there is no pair to optimize).
    pub fn new(n: u64) -> Result<Self> {
        if n == 0 {
            return Err(Error::ZeroPoints);
        }
        if n == 1 {
            return Err(Error::InvalidParameter {
                what: "Gaussian blue noise needs at least two points",
            });
        }
        if n > GBN_MAX_POINTS {
            return Err(Error::TooManyPoints {
                requested: n,
                max: GBN_MAX_POINTS,
            });
        }
        Ok(GaussianBlueNoise {
            n,
            iterations: 500,
            sigma: 1.0,
            seed: 0,
        })
    }

    /// The iteration count (0 to 10^6; 0 returns the uniform start).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] past 10^6.
    pub fn iterations(mut self, iterations: u32) -> Result<Self> {
        if iterations > 1_000_000 {
            return Err(Error::InvalidParameter {
                what: "Gaussian blue noise takes at most 10^6 iterations",
            });
        }
        self.iterations = iterations;
        Ok(self)
    }

    /// The kernel width `sigma` relative to the mean spacing (0.5 to 2; default 1).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn sigma(mut self, sigma: f64) -> Result<Self> {
        if !(0.5..=2.0).contains(&sigma) {
            return Err(Error::InvalidParameter {
                what: "the Gaussian blue-noise sigma must be 0.5 to 2",
            });
        }
        self.sigma = sigma;
        Ok(self)
    }

    /// The seed.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    fn cutoff(&self) -> f64 {
        CUTOFF * self.sigma / (self.n as f64).sqrt()
    }

    /// The estimated running time: iterations times `N` times the pairs within the cells,
    /// times `1 + 0.4 (log2 N - 16)+^2` for the cache misses of large sets.
    pub fn cost(&self) -> Cost {
        let n = self.n as f64;
        let g = (1.0 / self.cutoff()).floor();
        let per_point = if g >= 3.0 { 9.0 * n / (g * g) } else { n };
        // Past 2^16 points the neighbours' coordinates leave the caches: each term's read
        // misses (measured: 10^6 points, 5 iterations, 69 s of CPU, about 5 times the
        // in-cache rate; 10^5 points: 1.1 times).
        let memory = 1.0 + 0.27 * (n.log2() - 16.0).max(0.0).powi(2);
        Cost::steps(
            f64::from(self.iterations) * n * (per_point + 4.0) * memory,
            TERMS,
        )
    }

    /// The set, refused before it starts when [`cost`](Self::cost) exceeds `budget`, and
    /// stopped at the budget's deadline (started here if the caller has not): the clock is
    /// read once an iteration and, within one, once every `DEADLINE_POINTS` points of
    /// each worker.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let budget = budget.started();
        budget.check("Gaussian blue noise", self.cost())?;
        let n = self.n as usize;
        crate::size::bytes(n, 64)?;
        let mut rng = Rng::new(self.seed, 0x4742_4E32_4430_3232);
        let mut pts: Vec<[f64; 2]> = crate::size::vec_with_capacity(n)?;
        pts.extend((0..n).map(|_| [rng.fraction(), rng.fraction()].map(|c| f64::from(c) / SCALE)));
        let nf = n as f64;
        let inv = nf / (2.0 * self.sigma * self.sigma);
        let step = 0.25 / (self.sigma * self.sigma).max(1.0);
        let cut = self.cutoff();
        let cut2 = cut * cut;
        let g = ((1.0 / cut).floor() as usize).max(1);
        let use_grid = g >= 3;
        let mut head = crate::size::vec_zeroed::<u32>(g * g)?;
        let mut next = crate::size::vec_zeroed::<u32>(n)?;
        next.fill(u32::MAX);
        for _ in 0..self.iterations {
            budget.check_deadline("Gaussian blue noise")?;
            if use_grid {
                head.fill(u32::MAX);
                for (i, p) in pts.iter().enumerate() {
                    let c = cell(p, g);
                    if let (Some(h), Some(nx)) = (head.get_mut(c.1 * g + c.0), next.get_mut(i)) {
                        *nx = *h;
                        *h = i as u32;
                    }
                }
            }
            let old = &pts;
            let (head, next) = (&head, &next);
            let moved: Vec<[f64; 2]> = (0..n)
                .into_par_iter()
                .map(|i| {
                    if i % DEADLINE_POINTS == 0 {
                        budget.check_deadline("Gaussian blue noise")?;
                    }
                    let Some(p) = old.get(i) else {
                        return Ok([0.0; 2]);
                    };
                    let mut grad = [0.0f64; 2];
                    let mut term = |q: &[f64; 2]| {
                        let dx = wrap(p[0] - q[0]);
                        let dy = wrap(p[1] - q[1]);
                        let d2 = dx * dx + dy * dy;
                        if d2 < cut2 && d2 > 0.0 {
                            let w = (-inv * d2).exp();
                            grad[0] += dx * w;
                            grad[1] += dy * w;
                        }
                    };
                    if use_grid {
                        let (cx, cy) = cell(p, g);
                        for oy in [g - 1, 0, 1] {
                            for ox in [g - 1, 0, 1] {
                                let idx = ((cy + oy) % g) * g + (cx + ox) % g;
                                let mut k = head.get(idx).copied().unwrap_or(u32::MAX);
                                while k != u32::MAX {
                                    if k as usize != i
                                        && let Some(q) = old.get(k as usize)
                                    {
                                        term(q);
                                    }
                                    k = next.get(k as usize).copied().unwrap_or(u32::MAX);
                                }
                            }
                        }
                    } else {
                        for (j, q) in old.iter().enumerate() {
                            if j != i {
                                term(q);
                            }
                        }
                    }
                    Ok([p[0] + step * grad[0], p[1] + step * grad[1]].map(|x| x - x.floor()))
                })
                .collect::<Result<Vec<_>>>()?;
            pts = moved;
        }
        let mut coords = crate::size::vec_zeroed::<u32>(crate::size::coordinates(n as u64, 2)?)?;
        for (row, p) in coords.chunks_exact_mut(2).zip(&pts) {
            for (c, x) in row.iter_mut().zip(p) {
                // x in [0, 1]; 1.0 (from rounding) wraps to 0.
                *c = ((x * SCALE) as u64 & 0xFFFF_FFFF) as u32;
            }
        }
        PointSet::new(coords, 2)
    }
}

/// `d` (a difference of two coordinates of `[0, 1)`) wrapped to `[-1/2, 1/2)`: the same
/// bits as `d - floor(d + 1/2)`, without the `floor` call (a library call on baseline
/// x86-64, in the innermost loop).
#[inline]
fn wrap(d: f64) -> f64 {
    if d >= 0.5 {
        d - 1.0
    } else if d < -0.5 {
        d + 1.0
    } else {
        d
    }
}

#[inline]
fn cell(p: &[f64; 2], g: usize) -> (usize, usize) {
    let gf = g as f64;
    (
        ((p[0] * gf) as usize).min(g - 1),
        ((p[1] * gf) as usize).min(g - 1),
    )
}
