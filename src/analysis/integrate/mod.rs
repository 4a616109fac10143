//! Integration with an error estimate: replicated randomized QMC, doubling the points until
//! a Student-t interval meets a tolerance or a point budget is spent; and the integration
//! error of a point set on test integrands with closed-form integrals ([`Integrand`],
//! [`integration_error`]).
//!
//! # Method
//!
//! `R` independent randomizations of one construction (`make(seed + r)`, `r < R`: random
//! shifts of a lattice, Owen scrambles of Sobol', ...) each give an unbiased estimate
//! `mu_r = (1/n) sum_(i<n) f(x_i^(r))`. Their mean `mu` has the interval
//!
//! ```text
//! mu +- t_(level, R-1) s / sqrt(R),    s^2 = (1/(R-1)) sum_r (mu_r - mu)^2
//! ```
//!
//! (Student's t with `R - 1` degrees of freedom; Owen, "Practical QMC", ch. 17; L'Ecuyer et
//! al. 2023 on its coverage). Starting from `n_start` points per replication the loop
//! doubles `n` (reusing the points already summed: extensible constructions in their
//! sequence order, e.g. Sobol' or a lattice in radical-inverse order, so every `n = 2^m`
//! prefix is a net or a lattice) until the half-width is at most
//! `max(abs_tol, rel_tol |mu|)`, or the next level would pass `max_points` evaluations in
//! all (the result then says `converged: false`). Coordinates are passed to `f` as
//! `(x + 1/2) / 2^32`, strictly inside `(0, 1)`, so inverse-CDF transforms stay finite.
//!
//! Cost: `R n` evaluations of `f` and `R n d` coordinates, bounded by `max_points`; memory
//! `O(d)` per batch of [`BATCH`] points.
//!
//! ```
//! use qmckit::analysis::integrate::{Options, integrate};
//! use qmckit::lattice::Rank1Lattice;
//! use qmckit::randomize::{CranleyPatterson, Scrambled};
//! use qmckit::work::Budget;
//! // The integral of x y over the unit square is 1/4.
//! let opts = Options { abs_tol: 1e-6, ..Options::default() };
//! let est = integrate(|x| x[0] * x[1], 2, |seed| {
//!     Ok(Scrambled::new(Rank1Lattice::kuo(2)?, CranleyPatterson::new(seed)))
//! }, &opts, &Budget::UNLIMITED)?;
//! assert!(est.converged && (est.value - 0.25).abs() < 1e-5);
//! # Ok::<(), qmckit::Error>(())
//! ```

mod benchmark;
mod families;
mod integrands;
mod problems;
mod rotated;
mod student;

pub use benchmark::{
    BENCHMARK_RATE, BenchmarkCurve, BenchmarkOptions, Factory, MAX_INTEGRANDS, benchmark,
};
pub use families::{Family, GAUSSIAN_MAX_DIMS, HEAVISIDE_MAX_DIMS, ROTATED_DIMS, RandomIntegrand};
pub use integrands::{Integrand, integration_error};
pub use problems::{GenzFamily, Market, Problem, ProblemKind, normal_quantile, test_suite};
pub use rotated::ROTATED_TOLERANCE;
pub use student::{t_quantile, two_sided_cdf};

use crate::error::{Error, Result};
use crate::sampler::Sampler;
use crate::work::Limits;

/// The most replications [`integrate`] takes (`2^20`: one sampler and one running sum
/// each are held at once).
pub const MAX_REPLICATIONS: u32 = 1 << 20;

/// Points evaluated per batch (per replication).
pub const BATCH: usize = 1024;

/// What [`integrate`] aims at and may spend.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Independent randomizations `R` (at least 2) [default 16].
    pub replications: u32,
    /// Absolute tolerance on the interval's half-width [default 1e-3]; 0 for none.
    pub abs_tol: f64,
    /// Relative tolerance (times `|estimate|`) [default 0]; the looser of the two counts.
    pub rel_tol: f64,
    /// Confidence level of the interval, in `(0, 1)` [default 0.95].
    pub level: f64,
    /// Points per replication of the first level, a power of two [default 2^8].
    pub n_start: u64,
    /// Most evaluations of `f` in all (`R n` summed over the last level) [default 2^26].
    pub max_points: u64,
    /// First seed: replication `r` is `make(seed + r)` [default 0].
    pub seed: u64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            replications: 16,
            abs_tol: 1e-3,
            rel_tol: 0.0,
            level: 0.95,
            n_start: 1 << 8,
            max_points: 1 << 26,
            seed: 0,
        }
    }
}

/// One level of the doubling loop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Level {
    /// Points per replication.
    pub n: u64,
    /// The mean of the replicate estimates.
    pub value: f64,
    /// Half-width of the interval.
    pub half_width: f64,
}

/// The result of [`integrate`].
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// The estimate: the mean of the `R` replicate means.
    pub value: f64,
    /// Half-width of the interval `value +- half_width`.
    pub half_width: f64,
    /// Points per replication at the last level.
    pub n: u64,
    /// Evaluations of `f` in all (`R n`).
    pub points: u64,
    /// `true` when the tolerance was met; `false` when the point budget (or the
    /// construction's length) stopped the loop first.
    pub converged: bool,
    /// Every level, first to last.
    pub levels: Vec<Level>,
}

impl Estimate {
    /// The interval `(value - half_width, value + half_width)`.
    pub fn interval(&self) -> (f64, f64) {
        (self.value - self.half_width, self.value + self.half_width)
    }
}

fn invalid(what: &'static str) -> Error {
    Error::InvalidParameter { what }
}

/// Checks `opts`.
fn check_options(opts: &Options) -> Result<()> {
    if opts.replications < 2 {
        return Err(invalid("integrate needs at least 2 replications"));
    }
    if opts.replications > MAX_REPLICATIONS {
        return Err(invalid("integrate takes at most 2^20 replications"));
    }
    let tolerance_ok = |t: f64| t.is_finite() && t >= 0.0;
    if !tolerance_ok(opts.abs_tol) || !tolerance_ok(opts.rel_tol) {
        return Err(invalid("tolerances must be finite and non-negative"));
    }
    if !(opts.level > 0.0 && opts.level < 1.0) {
        return Err(invalid("the confidence level must lie in (0, 1)"));
    }
    if opts.n_start == 0 || !opts.n_start.is_power_of_two() {
        return Err(invalid("n_start must be a power of two"));
    }
    if opts.n_start.saturating_mul(u64::from(opts.replications)) > opts.max_points {
        return Err(invalid(
            "max_points is below the first level (replications x n_start)",
        ));
    }
    Ok(())
}

/// The integral of `f` over `[0, 1]^dims` with a confidence interval, by replicated
/// randomized QMC with doubling (see the [module docs](self)). `make(seed)` builds one
/// randomization (its `dims()` must be `dims`).
///
/// The limits: a budget whose deadline (started here if it was not) is read once per batch
/// of [`BATCH`] points; pass `&Budget::UNLIMITED` for none. The work is bounded by
/// `opts.max_points` evaluations of `f` (and the construction's length); the deadline
/// bounds its time whatever `f` costs.
///
/// # Errors
/// [`Error::InvalidParameter`] for bad options (among them more than
/// [`MAX_REPLICATIONS`]), a sampler of another dimension, or a non-finite value of `f`;
/// [`Error::NotRepresentable`] when the running sums, the estimate or its half-width
/// overflow `f64` (values of `f` near `1e308`: an error, never `inf ± NaN`); errors of
/// `make` and of the samplers; [`Error::OutOfTime`] past the deadline.
pub fn integrate<'a, S, M, F>(
    f: F,
    dims: usize,
    make: M,
    opts: &Options,
    limits: impl Into<Limits<'a>>,
) -> Result<Estimate>
where
    S: Sampler,
    M: Fn(u64) -> Result<S>,
    F: Fn(&[f64]) -> f64,
{
    let limits = limits.into();
    let budget = limits.budget();
    check_options(opts)?;
    let budget = budget.started();
    if dims == 0 {
        return Err(Error::ZeroDimensions);
    }
    let reps = opts.replications as usize;
    let samplers = (0..opts.replications)
        .map(|r| make(opts.seed.wrapping_add(u64::from(r))))
        .collect::<Result<Vec<S>>>()?;
    if samplers.iter().any(|s| s.dims() != dims) {
        return Err(invalid("make built a sampler of another dimension"));
    }
    let len = samplers.iter().map(Sampler::len).min().unwrap_or(0);
    let t = t_quantile(opts.level, opts.replications - 1)?;
    let mut sums: Vec<f64> = crate::size::vec_zeroed(reps)?;
    let mut raw = crate::size::vec_zeroed(crate::size::coordinates(BATCH as u64, dims)?)?;
    let mut x = vec![0f64; dims];
    let (mut done, mut n) = (0u64, opts.n_start);
    let mut levels = Vec::new();
    loop {
        if n > len {
            break;
        }
        for (s, sum) in samplers.iter().zip(sums.iter_mut()) {
            let mut i = done;
            while i < n {
                budget.check_deadline("the integral")?;
                let rows = (n - i).min(BATCH as u64) as usize;
                let part = raw.get_mut(..rows * dims).unwrap_or(&mut []);
                // i < n <= len <= 2^32.
                s.fill(i as u32, part)?;
                for row in part.chunks_exact(dims) {
                    for (xk, &r) in x.iter_mut().zip(row) {
                        *xk = (f64::from(r) + 0.5) * (1.0 / 4_294_967_296.0);
                    }
                    let y = f(&x);
                    if !y.is_finite() {
                        return Err(invalid("the integrand returned a non-finite value"));
                    }
                    *sum += y;
                }
                i += rows as u64;
            }
        }
        done = n;
        let means: Vec<f64> = sums.iter().map(|s| s / n as f64).collect();
        let value = means.iter().sum::<f64>() / reps as f64;
        let var = means.iter().map(|m| (m - value).powi(2)).sum::<f64>() / (reps as f64 - 1.0);
        let half_width = t * (var / reps as f64).sqrt();
        if !(sums.iter().all(|s| s.is_finite()) && value.is_finite() && half_width.is_finite()) {
            return Err(Error::NotRepresentable {
                what: "the integral estimate (or its half-width)",
            });
        }
        levels.push(Level {
            n,
            value,
            half_width,
        });
        let tol = opts.abs_tol.max(opts.rel_tol * value.abs());
        let next_points = (2 * n).saturating_mul(u64::from(opts.replications));
        if half_width <= tol || next_points > opts.max_points || 2 * n > len {
            return Ok(Estimate {
                value,
                half_width,
                n,
                points: n * u64::from(opts.replications),
                converged: half_width <= tol,
                levels,
            });
        }
        n *= 2;
    }
    Err(invalid(
        "the construction has fewer points than the first level (n_start)",
    ))
}
