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
//! `sigma = 0.45` and `T = 0.001`, in these units (the paper's energy is scaled
//! differently, so its numbers do not carry over); chosen on measurements at `N = 1024`
//! in 2D: mean nearest-neighbour distance about `0.95 s`, low-band power about `6e-4` of
//! white noise's (`sigma = 1/sqrt(2)` at the same temperature gives `0.74 s`, a weaker
//! repulsion at a spacing).
//!
//! ## The sampler
//!
//! The paper's multi-scale scheme (module `multiscale`): `L` levels (default 3) of
//! `N / 2^(d l)` points with kernels `2^l` times wider, relaxed coarse to fine by
//! overdamped Langevin steps at a temperature falling from `4 T` to `T` within each
//! level, each point of a level split into `2^d` at the next. A coarse level arranges the
//! long wavelengths cheaply, which the single-scale sampler (`levels(1)`) does in many
//! sweeps: at `N = 4096`, 60 sweeps, the low band is 0.0006 of white noise with 3 levels
//! and 0.013 with one (tested). Default 60 sweeps a level.
//!
//! Non-uniform targets (the paper's density adaptation, each kernel's width following the
//! local spacing): [`KdeBlueNoise::sample`] with a density function (module `density`).
//!
//! ## Range and cost
//!
//! Dimensions 1 to 5, 2 to 2^22 points. The pair sum is cut where its term is below
//! `e^-9` (`6 sigma` mean spacings) and each pair is counted at its nearest image; when the
//! cut-off reaches past half the torus (fewer than `(2 r_cut)^d` points, `r_cut = 6 sigma +
//! sqrt(d)`: 128 in 2D) that is an approximation of the periodic energy. A sweep of a
//! level of `n_l` points costs `n_l m` kernel terms and gradients for the `m` points in
//! the `3^d` neighbour cells (cell lists), one core; the levels together about
//! `1 + 2^-d + ...` times the finest. Estimated against a [`Budget`]
//! ([`KdeBlueNoise::cost`]) and stopped at its deadline (read every sweep and every 4096
//! points).
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
mod multiscale;

pub use density::KDE_MAX_DENSITY_RATIO;

use super::PointSet;
use super::lloyd::unit_point_set;
use super::rng::Rng;
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

/// Sweeps a level by default.
const DEFAULT_SWEEPS: u32 = 60;

/// The uniform model's temperature by default.
const DEFAULT_TEMPERATURE: f64 = 0.001;

/// The uniform model's kernel width by default, in mean spacings.
const DEFAULT_SIGMA: f64 = 0.45;

/// The density adaptation's temperature by default.
const DENSITY_TEMPERATURE: f64 = 0.01;

/// The density adaptation's kernel width by default (`1/sqrt(2)`).
const DENSITY_SIGMA: f64 = core::f64::consts::FRAC_1_SQRT_2;

/// Heat-bath sweeps of the density adaptation by default.
const DENSITY_SWEEPS: u32 = 200;

/// Levels of the multi-scale sampler by default.
const DEFAULT_LEVELS: u32 = 3;

/// The most levels.
pub const KDE_MAX_LEVELS: u32 = 8;

/// Kernel-density blue noise (builder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KdeBlueNoise {
    n: u64,
    dims: usize,
    /// `None`: the default of the sampler used (uniform: [`DEFAULT_TEMPERATURE`];
    /// density adaptation: [`DENSITY_TEMPERATURE`]).
    temperature: Option<f64>,
    /// `None`: as the temperature ([`DEFAULT_SIGMA`], [`DENSITY_SIGMA`]).
    sigma: Option<f64>,
    /// `None`: the default of the sampler used (uniform: [`DEFAULT_SWEEPS`] a level;
    /// density adaptation: [`DENSITY_SWEEPS`]).
    sweeps: Option<u32>,
    levels: u32,
    seed: u64,
}

impl KdeBlueNoise {
    /// `n` points in `dims` dimensions, `T = 0.001`, `sigma = 0.45`, 60 sweeps a level, 3
    /// levels, seed 0 (the density adaptation: `T = 0.01`, `sigma = 1/sqrt(2)`, 200 sweeps
    /// unless set).
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::ZeroDimensions`],
    /// [`Error::DimensionOutOfRange`]; [`Error::InvalidParameter`] for one point.
    pub fn new(n: u64, dims: usize) -> Result<Self> {
        crate::size::points(n, KDE_MAX_POINTS)?;
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
            temperature: None,
            sigma: None,
            sweeps: None,
            levels: DEFAULT_LEVELS,
            seed: 0,
        };
        if n < 2 {
            return Err(Error::InvalidParameter {
                what: "kernel-density blue noise needs at least two points",
            });
        }
        Ok(k)
    }

    /// The uniform model's kernel width.
    fn uniform_sigma(&self) -> f64 {
        self.sigma.unwrap_or(DEFAULT_SIGMA)
    }

    /// The density adaptation's kernel width.
    fn density_sigma(&self) -> f64 {
        self.sigma.unwrap_or(DENSITY_SIGMA)
    }

    /// The cut-off window of the density adaptation's heat-bath updates (pairs plus the
    /// candidates' reach) in mean spacings.
    fn reach(&self) -> f64 {
        CUT_SIGMAS * self.density_sigma() + 2.0 * WINDOW * (self.dims as f64).sqrt()
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
        self.temperature = Some(t);
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
        self.sigma = Some(sigma);
        Ok(self)
    }

    /// The sweeps a level (0 to 10^5; 0 returns the uniform start).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] past 10^5.
    pub fn sweeps(mut self, sweeps: u32) -> Result<Self> {
        if sweeps > 100_000 {
            return Err(Error::InvalidParameter {
                what: "kernel-density blue noise takes at most 10^5 sweeps",
            });
        }
        self.sweeps = Some(sweeps);
        Ok(self)
    }

    /// The levels `L` of the multi-scale sampler (1 to [`KDE_MAX_LEVELS`]; 1 is single
    /// scale). Levels whose point count would fall below 2 are not used.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn levels(mut self, levels: u32) -> Result<Self> {
        if !(1..=KDE_MAX_LEVELS).contains(&levels) {
            return Err(Error::InvalidParameter {
                what: "kernel-density blue noise takes 1 to 8 levels",
            });
        }
        self.levels = levels;
        Ok(self)
    }

    /// The levels used for `n` points: at most [`levels`](Self::levels), the coarsest with
    /// at least 16 points (fewer have no long wavelengths to arrange).
    fn used_levels(&self) -> u32 {
        let c = multiscale::counts(self.n as usize, self.dims, self.levels);
        c.iter().take_while(|&&m| m >= 16).count().max(1) as u32
    }

    /// The seed (start and updates).
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// Points visited a query of `n` points whose cells are at least `reach` mean
    /// spacings wide: the `3^d` cells around a point's, or all points.
    fn visits(&self, n: f64, reach: f64) -> f64 {
        let d = self.dims as i32;
        let cut = reach * n.powf(-1.0 / self.dims as f64);
        let g = (1.0 / cut)
            .floor()
            .min((2.0 * n).powf(1.0 / self.dims as f64).floor());
        if g >= 3.0 && 3f64.powi(d) < n {
            3f64.powi(d) * n / g.powi(d)
        } else {
            n
        }
    }

    /// The estimated running time of the uniform model: at each level `l`, the sweeps
    /// times `n_l` times the points visited (one kernel term and gradient each, plus `d`
    /// normal deviates a point), one core.
    pub fn cost(&self) -> Cost {
        let sweeps = f64::from(self.sweeps.unwrap_or(DEFAULT_SWEEPS));
        let reach = CUT_SIGMAS * self.uniform_sigma() + 1.0;
        let counts = multiscale::counts(self.n as usize, self.dims, self.used_levels());
        let work: f64 = counts
            .iter()
            .map(|&m| {
                let m = m as f64;
                sweeps * m * (self.visits(m, reach) + 4.0 * self.dims as f64)
            })
            .sum();
        Cost::steps(work, TERMS)
    }

    /// The heat-bath sampler's estimated running time (the density adaptation's base):
    /// sweeps times `N` times (the points visited plus `C` times those within the
    /// cut-off).
    fn heat_bath_cost(&self) -> Cost {
        let n = self.n as f64;
        let v = self.visits(n, self.reach());
        let sweeps = f64::from(self.sweeps.unwrap_or(DENSITY_SWEEPS));
        Cost::steps(sweeps * n * (v * (1.0 + CANDIDATES as f64 / 4.0)), TERMS)
    }

    /// The set, refused before it starts when [`cost`](Self::cost) exceeds `budget`,
    /// stopped at the budget's deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let pts = self.run(budget)?;
        unit_point_set(&pts, self.dims)
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
        let mut rng = Rng::new(self.seed, 0x4B44_454E_5349_5459); // "KDENSITY"
        let sweeps = self.sweeps.unwrap_or(DEFAULT_SWEEPS);
        if sweeps == 0 {
            let len = crate::size::coordinates(self.n, d)?;
            let mut pts = crate::size::vec_zeroed::<f64>(len)?;
            pts.iter_mut().for_each(|x| *x = rng.unit());
            return Ok(pts);
        }
        let schedule = multiscale::Schedule {
            dims: d,
            sigma: self.uniform_sigma(),
            temperature: self.temperature.unwrap_or(DEFAULT_TEMPERATURE),
            coarse_sweeps: sweeps,
            fine_sweeps: sweeps,
            levels: self.used_levels(),
        };
        schedule.run(n, &mut rng, &budget, WHAT)
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
