//! The integration benchmark: one sampler against thousands of random integrands of a
//! [`Family`] over a range of point counts, the root-mean-square error at each count and its
//! fitted convergence rate.
//!
//! For each size `N` and each integrand `j < J` (drawn from `seed + j`), the sampler is
//! built for `N` points with seed `seed + j` (so a randomized sampler is redrawn with each
//! integrand; a deterministic one gives the same set) and the error
//! `e_j(N) = (1/N') sum_(i<N') f_j(x_i) - I_j` is taken over its `N' = min(N, len)` points
//! (a Poisson-disk set holds about `N`). The curve holds
//! `RMSE(N) = sqrt((1/J) sum_j e_j(N)^2)` and the least-squares slope of `log RMSE` against
//! `log N` ([`fit_slope`](crate::analysis::variance::fit_slope)), the rate to compare with
//! theory: `-0.5` for independent points on every family; for jittered points `-1` on
//! smooth integrands and `-(1/2 + 1/(2d))` on discontinuous ones (`-0.75` in 2D); `-1.5`
//! for Owen-scrambled nets on smooth integrands (Owen 1997), `-(1/2 + 1/(2d))` on a
//! Heaviside too in the worst case (`-0.75` in 2D).
//!
//! The sampler comes from a factory `make(n, seed)`, so any construction or the catalog's
//! builder (`qmckit::catalog::build`) can be measured. Points are read as
//! `(x + 1/2) / 2^32`, strictly inside the cube, as [`integrate`](super::integrate) does.
//!
//! Cost: `J sum_N N d` coordinates generated and integrands evaluated (a mixture four
//! times), plus the factory's own cost `J` times a size (large for sets built whole);
//! parallel over the integrands. The budget's estimate is checked first
//! ([`BENCHMARK_RATE`]) and its deadline once per sampler built.

use std::boxed::Box;
use std::vec::Vec;

use rayon::prelude::*;

use super::families::{Family, RandomIntegrand};
use crate::error::{Error, Result};
use crate::sampler::Sampler;
use crate::work::{Cost, Limits, Rate};

/// The estimate's rate: coordinates generated and integrated a second on one core (a
/// conservative figure for the sequences; the blue-noise sets' construction is bounded by
/// the deadline, not by this estimate).
pub const BENCHMARK_RATE: Rate = Rate::per_second(5.0e7);

/// The most integrands a benchmark draws.
pub const MAX_INTEGRANDS: u32 = 1 << 20;

/// What the benchmark runs.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchmarkOptions {
    /// The integrand family.
    pub family: Family,
    /// The dimensions (within the family's [`max_dims`](Family::max_dims)).
    pub dims: usize,
    /// The point counts, increasing, each at least 1.
    pub sizes: Vec<u64>,
    /// How many integrands (1 to [`MAX_INTEGRANDS`]).
    pub integrands: u32,
    /// The seed of the integrands and the randomizations.
    pub seed: u64,
}

/// One sampler's measured curve.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchmarkCurve {
    /// `(N, RMSE)` for each size (`N` as asked).
    pub rmse: Vec<(u64, f64)>,
    /// The fitted slope of `log RMSE` against `log N`; `None` with fewer than two sizes or
    /// an error of exactly zero.
    pub slope: Option<f64>,
}

/// A sampler factory: `make(n, seed)` builds the sampler for `n` points with `seed`.
pub type Factory<'a> = &'a (dyn Fn(u64, u64) -> Result<Box<dyn Sampler>> + Sync);

/// Runs the benchmark for the sampler that `make` builds (see the module's documentation),
/// within `limits` (a budget, and a progress report that counts sampler builds).
///
/// # Errors
/// [`Error::InvalidParameter`] for no sizes, a size of 0, sizes not increasing, no
/// integrands or more than [`MAX_INTEGRANDS`], dimensions out of the family's range;
/// the budget's refusal ([`Budget::check`](crate::work::Budget::check)) before starting and
/// [`Error::OutOfTime`] past its deadline; the factory's errors.
///
/// ```
/// use qmckit::analysis::integrate::{BenchmarkOptions, Family, benchmark};
/// use qmckit::randomize::{FastOwen, Scrambled};
/// use qmckit::work::Budget;
/// use qmckit::{Sampler, Sobol};
/// let opts = BenchmarkOptions {
///     family: Family::Gaussian, dims: 2, sizes: vec![64, 256, 1024], integrands: 64, seed: 1,
/// };
/// let make = |_n: u64, seed: u64| -> qmckit::Result<Box<dyn Sampler>> {
///     Ok(Box::new(Scrambled::new(Sobol::new(2)?, FastOwen::new(seed))))
/// };
/// let curve = benchmark(&make, &opts, &Budget::DEFAULT)?;
/// // Owen-scrambled Sobol' on smooth integrands: close to N^-1.5.
/// assert!(curve.slope.unwrap() < -1.2);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn benchmark<'a>(
    make: Factory<'_>,
    opts: &BenchmarkOptions,
    limits: impl Into<Limits<'a>>,
) -> Result<BenchmarkCurve> {
    let limits = limits.into();
    let progress = limits.progress();
    let bad = |what| Err(Error::InvalidParameter { what });
    if opts.sizes.is_empty() || opts.sizes[0] == 0 {
        return bad("benchmark sizes: at least one, each at least 1");
    }
    if opts.sizes.windows(2).any(|w| w[0] >= w[1]) {
        return bad("benchmark sizes: increasing");
    }
    if opts.integrands == 0 || opts.integrands > MAX_INTEGRANDS {
        return bad("benchmark integrands: 1 to 2^20");
    }
    // Refuses bad dimensions before anything runs.
    RandomIntegrand::draw(opts.family, opts.dims, opts.seed)?;
    let budget = limits.budget().started();
    let coords: f64 = opts.sizes.iter().map(|&n| n as f64).sum::<f64>()
        * opts.dims as f64
        * opts.integrands as f64;
    budget.check(
        "the integration benchmark",
        Cost::steps(coords, BENCHMARK_RATE),
    )?;
    let integrands: Vec<RandomIntegrand> = (0..opts.integrands as u64)
        .map(|j| RandomIntegrand::draw(opts.family, opts.dims, opts.seed.wrapping_add(j)))
        .collect::<Result<_>>()?;
    let total = opts.sizes.len() * integrands.len();
    let done = core::sync::atomic::AtomicUsize::new(0);
    let mut rmse = Vec::with_capacity(opts.sizes.len());
    for &n in &opts.sizes {
        let errors: Vec<f64> = integrands
            .par_iter()
            .enumerate()
            .map(|(j, f)| {
                budget.check_deadline("the integration benchmark")?;
                let s = make(n, opts.seed.wrapping_add(j as u64))?;
                let e = error(&*s, f, n);
                progress(
                    done.fetch_add(1, core::sync::atomic::Ordering::Relaxed) + 1,
                    total,
                );
                e
            })
            .collect::<Result<_>>()?;
        let ms = errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64;
        rmse.push((n, ms.sqrt()));
    }
    let pairs: Vec<(f64, f64)> = rmse.iter().map(|&(n, e)| (n as f64, e)).collect();
    let slope = crate::analysis::variance::fit_slope(&pairs).ok();
    Ok(BenchmarkCurve { rmse, slope })
}

/// The integration error of the first `min(n, len)` points of `s` on `f`.
fn error(s: &dyn Sampler, f: &RandomIntegrand, n: u64) -> Result<f64> {
    let d = s.dims();
    if d != f.dims() {
        return Err(Error::InvalidParameter {
            what: "benchmark: the sampler's dimensions differ from the integrand's",
        });
    }
    let count = n.min(s.len());
    const ROWS: u64 = 256;
    let mut raw = crate::size::vec_zeroed::<u32>(d.saturating_mul(ROWS as usize))?;
    let mut x = crate::size::vec_zeroed::<f64>(d)?;
    let mut sum = 0.0;
    let mut start = 0u64;
    while start < count {
        let rows = ROWS.min(count - start) as usize;
        let first = u32::try_from(start).map_err(|_| Error::InvalidParameter {
            what: "benchmark: a point index past 2^32",
        })?;
        let buf = &mut raw[..rows * d];
        s.fill(first, buf)?;
        for row in buf.chunks_exact(d) {
            for (x, &r) in x.iter_mut().zip(row) {
                *x = (f64::from(r) + 0.5) * (1.0 / 4_294_967_296.0);
            }
            sum += f.eval(&x);
        }
        start += rows as u64;
    }
    Ok(sum / count.max(1) as f64 - f.exact())
}
