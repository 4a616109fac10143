//! Kernel-density blue noise (Fattal, "Blue-Noise Point Sampling using Kernel Density
//! Model", ACM TOG 30(4), SIGGRAPH 2011): `N` points on the unit torus `[0, 1)^d` drawn
//! from a statistical-mechanics model whose energy is the mismatch between the points'
//! kernel density estimate and the target density, at a temperature `T`.
//!
//! ## The model
//!
//! With a Gaussian kernel `k_sigma` of standard deviation `sigma s` (`s = N^(-1/d)` the mean
//! spacing) the density estimate is `f(x) = sum_i k_sigma(x - x_i)`, and its squared
//! distance to a uniform target `D`, `int (f - D)^2`, is on the torus a constant plus
//! `sum_{i != j} (k_sigma * k_sigma)(x_i - x_j)` (the cross term `int f D` does not depend on
//! the points). The convolution of two Gaussians is a Gaussian of variance `2 sigma^2`, so
//! up to a constant and a factor the energy is the pair sum
//!
//! ```text
//! E(X) = sum_{i < j} exp(-|x_i - x_j|^2 / (4 sigma^2 s^2))
//! ```
//!
//! in units of one pair's largest overlap. The points are a sample of the Gibbs
//! distribution `p(X) ∝ exp(-E(X) / T)`: at `T = 0` the energy's minima (near the hexagonal
//! arrangement in 2D), as `T` grows more randomness, white noise as `T -> inf`. Fattal's
//! point is that intermediate temperatures give blue noise with the randomness set by `T`:
//! lower `T`, less low-frequency power and a stronger peak (tested). Defaults:
//! `sigma = 1/sqrt(2)` (so `E` is `sum exp(-rho^2/2)` in mean spacings, the width of
//! [`super::GaussianBlueNoise`]'s energy) and `T = 0.01`, in these units (the paper's energy
//! is scaled differently, so its numbers do not carry over).
//!
//! ## The sampler
//!
//! Local updates, as in the paper: a sweep visits every point once, in order, and draws its
//! new position from its conditional distribution `p(x_i | rest) ∝ exp(-E_i(x_i) / T)`,
//! `E_i(x) = sum_{j != i} exp(-|x - x_j|^2 / (4 sigma^2 s^2))`, restricted to `C = 16`
//! candidates: the current position and 15 uniform in the cube of half-width `s/2` around
//! it (a heat-bath step on a random discretization of the conditional; at `T = 0` the best
//! candidate). The points start uniform at random. Not implemented: the paper's
//! multi-scale scheme (it speeds up the relaxation of long wavelengths).
//!
//! Non-uniform targets (the paper's density adaptation, each kernel's width following the
//! local spacing): [`KdeBlueNoise::sample`] with a density function (module `density`).
//!
//! ## Range and cost
//!
//! Dimensions 1 to 5, 2 to 2^22 points. The pair sum is cut where its term is below
//! `e^-9` (`6 sigma` mean spacings) and each pair is counted at its nearest image; when the
//! cut-off reaches past half the torus (fewer than `(2 r_cut)^d` points, `r_cut = 6 sigma +
//! sqrt(d)`: 128 in 2D) that is an approximation of the periodic energy. A sweep
//! costs `N C m` kernel terms for the `m` points within the cut-off (found by cell
//! lists), one core; estimated against a [`Budget`] ([`KdeBlueNoise::cost`]) and stopped
//! at its deadline (read every 4096 points).
//!
//! ```
//! use qmckit::blue_noise::KdeBlueNoise;
//! use qmckit::work::Budget;
//! let set = KdeBlueNoise::new(256, 2)?.sweeps(20)?.seed(1).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 256);
//! assert!(KdeBlueNoise::new(256, 2)?.temperature(-1.0).is_err());
//! # Ok::<(), qmckit::Error>(())
//! ```

mod density;

pub use density::KDE_MAX_DENSITY_RATIO;

use super::PointSet;
use super::lloyd::to_fraction;
use super::rng::Rng;
use super::torus_cells::{Cells, wrap};
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The most points [`KdeBlueNoise`] takes: 2^22.
pub const KDE_MAX_POINTS: u64 = 1 << 22;

/// The most dimensions [`KdeBlueNoise`] takes.
pub const KDE_MAX_DIMS: usize = 5;

/// Candidates a local update.
const CANDIDATES: usize = 16;

/// The candidates' window half-width, in mean spacings.
const WINDOW: f64 = 0.5;

/// The pair sum's cut-off in units of `sigma` (mean spacings): `exp(-36/4) = e^-9`.
const CUT_SIGMAS: f64 = 6.0;

/// Points between two readings of the clock.
const DEADLINE_POINTS: usize = 4096;

/// Kernel terms a second, one core (an exponential, a distance; measured about 5e7 for
/// 4096 points in 2D, taken lower).
const TERMS: Rate = Rate::per_second(1.2e8);

/// Kernel-density blue noise (builder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KdeBlueNoise {
    n: u64,
    dims: usize,
    temperature: f64,
    sigma: f64,
    sweeps: u32,
    seed: u64,
}

impl KdeBlueNoise {
    /// `n` points in `dims` dimensions, `T = 0.01`, `sigma = 1/sqrt(2)`, 200 sweeps, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::ZeroDimensions`],
    /// [`Error::DimensionOutOfRange`]; [`Error::InvalidParameter`] for one point.
    pub fn new(n: u64, dims: usize) -> Result<Self> {
        if n == 0 {
            return Err(Error::ZeroPoints);
        }
        if n > KDE_MAX_POINTS {
            return Err(Error::TooManyPoints {
                requested: n,
                max: KDE_MAX_POINTS,
            });
        }
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if dims > KDE_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: dims,
                dims: KDE_MAX_DIMS,
            });
        }
        let k = KdeBlueNoise {
            n,
            dims,
            temperature: 0.01,
            sigma: core::f64::consts::FRAC_1_SQRT_2,
            sweeps: 200,
            seed: 0,
        };
        if n < 2 {
            return Err(Error::InvalidParameter {
                what: "kernel-density blue noise needs at least two points",
            });
        }
        Ok(k)
    }

    /// The cut-off window (pairs plus the candidates' reach) in mean spacings.
    fn reach(&self) -> f64 {
        CUT_SIGMAS * self.sigma + 2.0 * WINDOW * (self.dims as f64).sqrt()
    }

    /// The temperature `T` (0 to 100; 0 is greedy descent).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range or not finite.
    pub fn temperature(mut self, t: f64) -> Result<Self> {
        if !(t.is_finite() && (0.0..=100.0).contains(&t)) {
            return Err(Error::InvalidParameter {
                what: "the kernel-density temperature must be 0 to 100",
            });
        }
        self.temperature = t;
        Ok(self)
    }

    /// The kernel width `sigma` in mean spacings (0.25 to 1.5).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn sigma(mut self, sigma: f64) -> Result<Self> {
        if !(sigma.is_finite() && (0.25..=1.5).contains(&sigma)) {
            return Err(Error::InvalidParameter {
                what: "the kernel-density sigma must be 0.25 to 1.5 mean spacings",
            });
        }
        self.sigma = sigma;
        Ok(self)
    }

    /// The sweeps (0 to 10^5; 0 returns the uniform start).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] past 10^5.
    pub fn sweeps(mut self, sweeps: u32) -> Result<Self> {
        if sweeps > 100_000 {
            return Err(Error::InvalidParameter {
                what: "kernel-density blue noise takes at most 10^5 sweeps",
            });
        }
        self.sweeps = sweeps;
        Ok(self)
    }

    /// The seed (start and updates).
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// Points visited a query: the `3^d` cells around a point's, or all points.
    fn visits(&self) -> f64 {
        let n = self.n as f64;
        let d = self.dims as i32;
        let cut = self.reach() * n.powf(-1.0 / self.dims as f64);
        let g = (1.0 / cut)
            .floor()
            .min((2.0 * n).powf(1.0 / self.dims as f64).floor());
        if g >= 3.0 && 3f64.powi(d) < n {
            3f64.powi(d) * n / g.powi(d)
        } else {
            n
        }
    }

    /// The estimated running time: sweeps times `N` times (the points visited plus `C`
    /// times those within the cut-off), one core.
    pub fn cost(&self) -> Cost {
        let v = self.visits();
        let work = f64::from(self.sweeps) * self.n as f64 * (v * (1.0 + CANDIDATES as f64 / 4.0));
        Cost::steps(work, TERMS)
    }

    /// The set, refused before it starts when [`cost`](Self::cost) exceeds `budget`,
    /// stopped at the budget's deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let pts = self.run(budget)?;
        let mut coords = crate::size::vec_with_capacity(pts.len())?;
        coords.extend(pts.iter().map(|&x| to_fraction(x)));
        PointSet::new(coords, self.dims)
    }

    /// The points as `f64` in `[0, 1)`, row-major.
    ///
    /// # Errors
    /// As [`KdeBlueNoise::generate`].
    pub fn run(&self, budget: &Budget) -> Result<Vec<f64>> {
        const WHAT: &str = "kernel-density blue noise";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let (n, d) = (self.n as usize, self.dims);
        let len = crate::size::coordinates(self.n, d)?;
        let mut rng = Rng::new(self.seed, 0x4B44_454E_5349_5459); // "KDENSITY"
        let mut pts = crate::size::vec_zeroed::<f64>(len)?;
        pts.iter_mut().for_each(|x| *x = rng.unit());
        let s = (n as f64).powf(-1.0 / d as f64);
        let inv = 1.0 / (4.0 * self.sigma * self.sigma * s * s);
        let cut = CUT_SIGMAS * self.sigma * s;
        let cut2 = cut * cut;
        let half = WINDOW * s;
        // Neighbours any candidate may reach: within the cut-off plus the window's diagonal.
        let keep = cut + half * (d as f64).sqrt();
        let keep2 = keep * keep;
        // Neighbour differences x_j - x_i of the current point (reused buffer).
        let mut near: Vec<f64> = Vec::new();
        let mut cand = [[0.0f64; KDE_MAX_DIMS]; CANDIDATES];
        let mut energy = [0.0f64; CANDIDATES];
        for _ in 0..self.sweeps {
            budget.check_deadline(WHAT)?;
            let cells = Cells::new(&pts, d, self.reach() * s)?;
            for i in 0..n {
                if i % DEADLINE_POINTS == 0 {
                    budget.check_deadline(WHAT)?;
                }
                near.clear();
                {
                    let Some(p) = pts.get(i * d..i * d + d) else {
                        continue;
                    };
                    cells.near(p, n, |j| {
                        if j == i {
                            return;
                        }
                        if let Some(q) = pts.get(j * d..j * d + d) {
                            let r2: f64 = q.iter().zip(p).map(|(b, a)| wrap(b - a).powi(2)).sum();
                            if r2 < keep2 {
                                near.extend(q.iter().zip(p).map(|(b, a)| wrap(b - a)));
                            }
                        }
                    });
                }
                // Candidates as offsets from x_i: the first is 0 (stay).
                for (c, off) in cand.iter_mut().enumerate() {
                    for o in off.iter_mut().take(d) {
                        *o = if c == 0 {
                            0.0
                        } else {
                            (2.0 * rng.unit() - 1.0) * half
                        };
                    }
                }
                for (e, off) in energy.iter_mut().zip(&cand) {
                    *e = near
                        .chunks_exact(d)
                        .map(|q| {
                            let r2: f64 = q.iter().zip(off).map(|(a, b)| (a - b) * (a - b)).sum();
                            if r2 < cut2 { (-inv * r2).exp() } else { 0.0 }
                        })
                        .sum();
                }
                let pick = choose(&energy, self.temperature, &mut rng);
                if let (Some(p), Some(off)) = (pts.get_mut(i * d..i * d + d), cand.get(pick)) {
                    for (x, o) in p.iter_mut().zip(off) {
                        let y = *x + o;
                        let y = y - y.floor();
                        *x = if y >= 1.0 { 0.0 } else { y };
                    }
                }
            }
        }
        Ok(pts)
    }
}

/// A candidate drawn with probability `∝ exp(-e_c / T)` (the least energy at `T = 0`).
fn choose(energy: &[f64; CANDIDATES], t: f64, rng: &mut Rng) -> usize {
    let min = energy.iter().copied().fold(f64::INFINITY, f64::min);
    if t <= 0.0 {
        return energy.iter().position(|&e| e == min).unwrap_or(0);
    }
    let mut w = [0.0f64; CANDIDATES];
    let mut total = 0.0;
    for (wi, &e) in w.iter_mut().zip(energy) {
        *wi = (-(e - min) / t).exp();
        total += *wi;
    }
    let mut u = rng.unit() * total;
    for (c, &wi) in w.iter().enumerate() {
        if u < wi {
            return c;
        }
        u -= wi;
    }
    0
}
