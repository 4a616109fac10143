//! Blue noise through optimal transport (de Goes, Breeden, Ostromoukhov & Desbrun 2012,
//! "Blue Noise through Optimal Transport", ACM TOG 31(6), SIGGRAPH Asia): `N` points of
//! the unit square or the unit torus that are the centroids of their own equal-capacity
//! power cells.
//!
//! ## The iteration
//!
//! BNOT minimizes the transport energy `E(X) = W_2^2(mu, (1/N) sum_i delta_x_i)` between
//! the uniform measure `mu` of the domain and the points, the least
//! `sum_i int_{C_i} |x - x_i|^2 dx` over partitions into cells `C_i` of area `1/N`. For
//! fixed points the optimal partition is the power diagram whose weights solve the
//! semi-discrete transport problem ([`super::transport`], damped Newton); for a fixed
//! partition the best points are the cells' centroids. An iteration does both:
//!
//! 1. solve the weights `w` so that every Laguerre cell of `X` has area `1/N` (within the
//!    tolerance, default `1e-9` on `max_i |N A_i - 1|`), warm-started from the previous
//!    weights;
//! 2. move every point to its cell's centroid (on the torus modulo 1).
//!
//! Step 2 lowers `sum_i int_{C_i} |x - x_i|^2` by `sum_i A_i |x_i - c_i|^2` (the parallel
//! axis theorem) with the cells kept, and step 1 of the next iteration finds the least
//! cost over all equal-capacity partitions, at most that of the kept cells: `E` does not
//! increase (tested, up to the solve's tolerance). The points start uniform at random.
//! [`Bnot::run`] reports `E` and the centroidal residual after every solve and the final
//! capacity error. Positions are exact `f64` and written as 0.32 fractions.
//!
//! ## The final regularization
//!
//! After the fixed iterations the last points are the centroids of the *previous* cells,
//! not of their own. The paper finishes with a regularization that brings every site to
//! the centroid of its own capacity-constrained cell. [`Bnot::regularize`] does it as
//! further steps of the same two moves (move to the centroids, re-solve the equal
//! capacities) until the centroidal residual
//!
//! `rho = sqrt(N sum_i A_i |x_i - c_i|^2)`
//!
//! (the area-weighted distance of the sites from their cells' centroids `c_i`, in units
//! of the mean spacing `1/sqrt N`; on the torus the distance is wrapped) falls to the
//! residual tolerance (default `1e-3`), or the steps asked for are spent. Every step ends
//! with a solve, so the cells keep their equal capacity `1/N`, and `rho^2 / N` is what the
//! next move takes off the energy: the points end at a fixed point of the iteration (a
//! capacity-constrained centroidal power diagram) within the tolerance. Off by default
//! (0 steps), so the default set is the paper's main loop.
//!
//! ## Cost
//!
//! An iteration is one warm solve, typically 1 to 3 Newton steps of one power diagram
//! each (`O(N)`) and conjugate gradients (`O(N^1.5)`); estimated by [`Bnot::cost`],
//! stopped at the budget's deadline. Memory about `30 N` words. 4096 points, 50
//! iterations: a few seconds (see `docs/blue-noise.md`).
//!
//! ```
//! use qmckit::blue_noise::Bnot;
//! use qmckit::work::Budget;
//! let t = Bnot::new(64)?.torus(true).iterations(10)?.seed(2).run(&Budget::DEFAULT)?;
//! assert!(t.max_error <= 1e-9);
//! assert!(t.energy.last() < t.energy.first());
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::lloyd::to_fraction;
use super::power::{self, PowerDiagram};
use super::rng::Rng;
use super::transport::{self, DEFAULT_TOLERANCE};
use crate::work::{Budget, Cost};
use crate::{Error, Result};

/// The most points [`Bnot`] takes: 2^18.
pub const BNOT_MAX_POINTS: u64 = 1 << 18;

/// The default residual tolerance of [`Bnot::regularize`]: `1e-3` of the mean spacing.
pub const BNOT_DEFAULT_RESIDUAL: f64 = 1e-3;

/// A warm iteration as a fraction of a cold solve (measured about 0.15 at 1024 and 4096
/// points, 1 to 3 Newton steps against 5 or 6).
const WARM_SOLVES: f64 = 0.2;

/// Blue noise through optimal transport (builder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bnot {
    n: u64,
    iterations: u32,
    torus: bool,
    tolerance: f64,
    seed: u64,
    regularize: u32,
    residual_tolerance: f64,
}

/// What [`Bnot::run`] reports besides the points.
#[derive(Clone, Debug, PartialEq)]
pub struct BnotTrace {
    /// The transport energy `E = sum_i int_{C_i} |x - x_i|^2` after each solve: the
    /// random start's first, then one an iteration.
    pub energy: Vec<f64>,
    /// The centroidal residual `rho = sqrt(N sum_i A_i |x_i - c_i|^2)` after each solve
    /// (one entry for each entry of `energy`).
    pub residual: Vec<f64>,
    /// The regularization steps taken (see [`Bnot::regularize`]).
    pub regularization_steps: u32,
    /// `max_i |N A_i - 1|` of the last solve.
    pub max_error: f64,
    /// The points, row-major `(x, y)` in `[0, 1]` (`[0, 1)` on the torus).
    pub sites: Vec<f64>,
    /// The weights of the last solve (their cells have area `1/N`).
    pub weights: Vec<f64>,
}

impl Bnot {
    /// `n` points (1 to [`BNOT_MAX_POINTS`]) in the unit square, 50 iterations, the
    /// default tolerance, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`].
    pub fn new(n: u64) -> Result<Self> {
        crate::size::points(n, BNOT_MAX_POINTS)?;
        Ok(Bnot {
            n,
            iterations: 50,
            torus: false,
            tolerance: DEFAULT_TOLERANCE,
            seed: 0,
            regularize: 0,
            residual_tolerance: BNOT_DEFAULT_RESIDUAL,
        })
    }

    /// The final regularization (see the module): at most `steps` further moves to the
    /// centroids of the equal-capacity cells, each followed by a solve, stopped once the
    /// centroidal residual is at most `residual` (in units of the mean spacing, `1e-9` to
    /// 1; [`BNOT_DEFAULT_RESIDUAL`] is `1e-3`). `steps` 0 to 10^4.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for `steps` past 10^4 or `residual` out of range.
    ///
    /// ```
    /// use qmckit::blue_noise::Bnot;
    /// use qmckit::work::Budget;
    /// let t = Bnot::new(64)?.iterations(10)?.regularize(200, 1e-3)?.run(&Budget::DEFAULT)?;
    /// assert!(t.residual.last() < t.residual.get(10));
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn regularize(mut self, steps: u32, residual: f64) -> Result<Self> {
        if steps > 10_000 || !(1e-9..=1.0).contains(&residual) {
            return Err(Error::InvalidParameter {
                what: "BNOT regularization: at most 10^4 steps, a residual of 1e-9 to 1",
            });
        }
        self.regularize = steps;
        self.residual_tolerance = residual;
        Ok(self)
    }

    /// Iterations (0 to 10^4; 0 returns the random start).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] past 10^4.
    pub fn iterations(mut self, iterations: u32) -> Result<Self> {
        if iterations > 10_000 {
            return Err(Error::InvalidParameter {
                what: "BNOT takes at most 10^4 iterations",
            });
        }
        self.iterations = iterations;
        Ok(self)
    }

    /// The capacity tolerance of every solve, on `max_i |N A_i - 1|`
    /// ([`transport::MIN_TOLERANCE`] to 0.1).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn tolerance(mut self, tolerance: f64) -> Result<Self> {
        if !(transport::MIN_TOLERANCE..=0.1).contains(&tolerance) {
            return Err(Error::InvalidParameter {
                what: "the BNOT tolerance must be 1e-11 to 0.1",
            });
        }
        self.tolerance = tolerance;
        Ok(self)
    }

    /// On the unit torus (periodic cells) instead of the square.
    pub fn torus(mut self, torus: bool) -> Self {
        self.torus = torus;
        self
    }

    /// The seed of the random start.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The estimated running time: a cold solve and `iterations` warm ones, and at most
    /// the regularization's steps.
    pub fn cost(&self) -> Cost {
        let n = self.n as usize;
        let cold = transport::cost(n);
        let warm = f64::from(self.iterations) + f64::from(self.regularize);
        Cost::from_seconds(cold.seconds() * (1.0 + WARM_SOLVES * warm))
    }

    /// The points, refused before they start when [`cost`](Self::cost) exceeds `budget`,
    /// stopped at the budget's deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::OutOfTime`], [`Error::TooLarge`], and a solve's
    /// [`Error::InvalidParameter`] should it fail.
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let t = self.run(budget)?;
        let mut coords = crate::size::vec_with_capacity(t.sites.len())?;
        coords.extend(t.sites.iter().map(|&x| to_fraction(x)));
        PointSet::new(coords, 2)
    }

    /// The construction with its energies and final weights ([`BnotTrace`]).
    ///
    /// # Errors
    /// As [`Bnot::generate`].
    pub fn run(&self, budget: &Budget) -> Result<BnotTrace> {
        const WHAT: &str = "BNOT";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let n = self.n as usize;
        let mut rng = Rng::new(self.seed, 0x424E_4F54_5350_4C53); // "BNOTSPLS"
        let mut pts = crate::size::vec_with_capacity::<[f64; 2]>(n)?;
        pts.extend((0..n).map(|_| [rng.unit(), rng.unit()]));
        let mut weights = crate::size::vec_zeroed::<f64>(n)?;
        let mut energy = Vec::new();
        let mut residual = Vec::new();
        let mut max_error;
        let mut regularization_steps = 0;
        let mut it = 0u32;
        let mut prev = None;
        loop {
            budget.check_deadline(WHAT)?;
            power::check_distinct(&pts)?;
            // The previous diagram's neighbours are clipped first (the points moved little).
            let t = transport::solve_points(
                &pts,
                self.torus,
                weights,
                self.tolerance,
                prev.as_ref(),
                &budget,
            )?;
            energy.push(t.cost());
            max_error = t.max_error();
            let d: &PowerDiagram = t.diagram();
            let rho = centroidal_residual(&pts, d, self.torus);
            residual.push(rho);
            let more = if it < self.iterations {
                true
            } else if regularization_steps < self.regularize && rho > self.residual_tolerance {
                regularization_steps += 1;
                true
            } else {
                false
            };
            if more {
                for (i, p) in pts.iter_mut().enumerate() {
                    let c = d.centroid(i);
                    *p = if self.torus {
                        [modulo_one(c[0]), modulo_one(c[1])]
                    } else {
                        [c[0].clamp(0.0, 1.0), c[1].clamp(0.0, 1.0)]
                    };
                }
            }
            let (w, d) = t.into_parts();
            (weights, prev) = (w, Some(d));
            if !more {
                break;
            }
            it += 1;
        }
        let mut sites = crate::size::vec_with_capacity(2 * n)?;
        sites.extend(pts.iter().flatten());
        Ok(BnotTrace {
            energy,
            residual,
            regularization_steps,
            max_error,
            sites,
            weights,
        })
    }
}

/// `sqrt(N sum_i A_i |x_i - c_i|^2)` of the sites `pts` in their diagram `d` (on the
/// torus the centroids are in the unrolled coordinates around their sites).
fn centroidal_residual(pts: &[[f64; 2]], d: &PowerDiagram, torus: bool) -> f64 {
    let sum: f64 = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let c = d.centroid(i);
            let (mut dx, mut dy) = (c[0] - p[0], c[1] - p[1]);
            if torus {
                dx -= dx.round();
                dy -= dy.round();
            }
            d.area(i) * (dx * dx + dy * dy)
        })
        .sum();
    (pts.len() as f64 * sum).sqrt()
}

/// `x` modulo 1 in `[0, 1)` (a tiny negative `x` rounds `x + 1` to 1: taken as 0).
fn modulo_one(x: f64) -> f64 {
    let r = x - x.floor();
    if r >= 1.0 { 0.0 } else { r }
}
