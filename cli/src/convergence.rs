//! `qmckit convergence SAMPLER --integrand F [-d D] [--max-m M] [--scramble KIND] [--seeds S]`:
//! integration error against the number of points.

use std::io::{BufWriter, Write};

use clap::Args;
use qmckit::catalog::{IntegrandEntry, IntegrandParams, TestIntegrand, build_integrand};

use qmckit::blue_noise::{BestCandidate, GaussianBlueNoise, PoissonDisk};
use qmckit::randomize::{CranleyPatterson, Scrambled};
use qmckit::sampler::Sampler;
use qmckit::work::{Budget, Cost, Rate};

use super::Failure;
use super::budget::BudgetArgs;
use super::names;
use super::points::{SamplerName, ScrambleName, Spec, blue_noise_kind, build, dims_of};
use super::progress::with_progress;
use qmckit::catalog::{RandomizerKind, SamplerKind};

/// Text shown after the options of `qmckit convergence --help`.
pub const AFTER_HELP: &str = "\
Integrands: every integrand of the catalog (the --integrand list above), each with its
exact integral I: on the cube, gaussian-peak exp(-16 |x - c|^2) (c the centre; the
default), oscillatory cos(0.6 pi + 2 sum_k x_k), ball (radius 0.45 about the centre),
heaviside (sum_k sqrt(k + 2) (x_k - 1/2) >= 0, I = 1/2), Genz's six families (genz-*,
default difficulties), keister, european and asian-geometric (read at the cells' midpoints,
inside (0, 1), for their inverse-CDF transforms); in 2D, the torus and pixel integrands.
An integrand that does not take -d D is refused in one line.

For N = 1, 2, 4, ..., 2^M (stratified: N = k^d for k = 1, 2, 4, ...), the first N points of
the sampler (finite sets: a set of N points, every point of it: a Poisson-disk set asked
for N holds about N) estimate I by their average; sizes a construction cannot make at the
start of the list (Gaussian blue noise needs N >= 2) are left out. With --seeds S
the sampler is drawn with seeds --seed, --seed + 1, ... and the root mean square of the S
errors is reported (unrandomized sequences give S equal errors). Output: a '# n rmse'
header, then 'N RMSE' lines, RMSE with 17 significant digits.

Cost: S (1 + 2 + ... + 2^M) d coordinates generated and integrated. Before starting, the
command times a probe of the same sampler, randomization and integrand (a few thousand
points), extrapolates, and refuses a request whose estimate exceeds --max-seconds; the
rate differs a hundredfold between, e.g., unscrambled Sobol' and exactly Owen-scrambled
Halton; the blue-noise sets (poisson, best-candidate, gaussian-blue-noise) are estimated by
their construction cost instead, and built within the same deadline. Largest set: 2^24
points. Errors: one line, exit code 2.";

/// Arguments of `qmckit convergence`.
#[derive(Args, Debug)]
pub struct ConvergenceArgs {
    /// Which construction, as for `qmckit points`.
    #[arg(value_parser = names::samplers())]
    sampler: SamplerName,
    /// The integrand (see below).
    #[arg(long, default_value = "gaussian-peak", value_parser = names::integrands())]
    integrand: &'static IntegrandEntry,
    /// Dimensions [default: 1 for vdc, 2 otherwise].
    #[arg(short = 'd', value_name = "D")]
    d: Option<usize>,
    /// Largest set: 2^M points (M <= 24) [default: 12; 10 for best-candidate and
    /// gaussian-blue-noise, whose sets cost N^2 to build].
    #[arg(long, value_name = "M")]
    max_m: Option<u32>,
    /// Randomization, as for `qmckit points`.
    #[arg(long, value_parser = names::randomizers(), default_value = "none")]
    scramble: ScrambleName,
    /// Number of seeds whose errors are averaged (root mean square).
    #[arg(long, default_value_t = 1)]
    seeds: u64,
    /// First seed.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    #[command(flatten)]
    budget: BudgetArgs,
}

/// Largest `--max-m`.
const MAX_M: u32 = 24;

/// Coordinates of the probe that measures the rate of a request: the largest set within
/// this many (the smallest set when none is).
const PROBE_VALUES: f64 = (1 << 18) as f64;

/// A rate no sampler reaches (coordinates a second, generated and integrated): requests
/// too large even at this rate are refused without a probe.
const FASTEST: Rate = Rate::per_second(2e9);

/// Coordinates a second generated and integrated from a blue-noise set already built (a
/// conservative rate, as no probe is timed for them).
const BLUE_RATE: Rate = Rate::per_second(5e7);

/// How much slower than its probe a full run is assumed to be: 1.1 (larger sets leave the
/// caches). The probe itself errs on the slow side (it pays the sampler's setup for a few
/// thousand points), and it is run twice, the faster taken, so that a moment of load on the
/// machine does not inflate the estimate. Measured: Owen-scrambled Halton, 2^18 points,
/// four seeds: 1.8 s of CPU against 1.7 to 2.8 s estimated on a loaded machine.
const PROBE_SLACK: f64 = 1.1;

/// The time the probe may take whatever the budget: a request is estimated by its probe
/// even under a budget shorter than the probe, so that its refusal names the estimate.
const PROBE_SECONDS: f64 = 2.0;

/// The set sizes: powers of two up to `2^m`, or for stratified sets `k^d`, `k` doubling.
fn sizes(sampler: SamplerName, d: usize, m: u32) -> Vec<u64> {
    let top = 1u64 << m;
    let power = u32::try_from(d).unwrap_or(u32::MAX);
    let mut sizes = Vec::new();
    let mut k = 1u64;
    while k <= top {
        let n = if sampler.kind == SamplerKind::Stratified {
            k.checked_pow(power).unwrap_or(u64::MAX)
        } else {
            k
        };
        if n > top {
            break;
        }
        sizes.push(n);
        k *= 2;
    }
    sizes
}

/// Coordinates generated at once (bounded memory for any set size).
const BATCH_VALUES: usize = 1 << 20;

/// The set `spec` names: the blue-noise sets built by the library within `budget` (the
/// command's deadline; the same sets, seeds and options as `qmckit points` builds), any
/// other through [`build`] (its whole-set constructions, pmj02bn, take `spec.budget`).
fn sampler_of(spec: &Spec, budget: &Budget) -> Result<Box<dyn Sampler>, Failure> {
    let (n, seed) = (spec.n, spec.seed);
    let set = match spec.sampler.kind {
        SamplerKind::Poisson => PoissonDisk::with_points(spec.d.unwrap_or(2), n)?
            .torus(false)
            .maximal(false)
            .seed(seed)
            .generate(budget)?,
        SamplerKind::BestCandidate => BestCandidate::new(n)?.seed(seed).generate(budget)?,
        SamplerKind::GaussianBlueNoise => GaussianBlueNoise::new(n)?.seed(seed).generate(budget)?,
        _ => return build(spec),
    };
    Ok(match spec.scramble.kind {
        RandomizerKind::Rotate => Box::new(Scrambled::new(set, CranleyPatterson::new(seed))),
        _ => Box::new(set),
    })
}

/// The estimated construction time of the blue-noise set `spec` names (0 for the others,
/// whose cost the probe measures).
fn construction(spec: &Spec) -> Result<f64, Failure> {
    let n = spec.n;
    Ok(match spec.sampler.kind {
        SamplerKind::Poisson => PoissonDisk::with_points(spec.d.unwrap_or(2), n)?
            .cost()?
            .seconds(),
        SamplerKind::BestCandidate => BestCandidate::new(n)?.cost().seconds(),
        SamplerKind::GaussianBlueNoise => GaussianBlueNoise::new(n)?.cost().seconds(),
        _ => 0.0,
    })
}

/// The integration error of the first `count` points of the set `spec` names (all of a
/// finite set holding fewer, as a Poisson-disk set may), its points generated in batches:
/// the sum of `f` over the batches divided by the count, minus `I`.
/// The deadline of `budget` is read once per batch.
fn error_of(spec: &Spec, f: &TestIntegrand, count: u64, budget: &Budget) -> Result<f64, Failure> {
    let sampler = sampler_of(spec, budget)?;
    let count = count.min(sampler.len());
    let dims = sampler.dims();
    let rows = (BATCH_VALUES / dims).max(1);
    let mut raw: Vec<u32> = qmckit::size::vec_zeroed(rows.saturating_mul(dims))?;
    let mut point: Vec<f64> = qmckit::size::vec_zeroed(dims)?;
    let (mut weighted, mut start) = (0.0, 0u64);
    while start < count {
        budget.check_deadline("the convergence curve")?;
        let take = rows.min((count - start) as usize);
        let buf = &mut raw[..take * dims];
        let first = u32::try_from(start).map_err(|_| Failure::usage("index past 2^32"))?;
        sampler.fill(first, buf)?;
        let mut sum = 0.0;
        for row in buf.chunks_exact(dims) {
            for (x, &r) in point.iter_mut().zip(row) {
                *x = f.coordinate(r);
            }
            sum += f.eval(&point);
        }
        weighted += sum;
        start += take as u64;
    }
    Ok(weighted / count as f64 - f.exact())
}

/// The measured rate, in coordinates a second, of generating and integrating a prefix of
/// at most [`PROBE_VALUES`] coordinates (at least one point) of the largest set, setup
/// included. A probe stopped by the deadline of `budget` gives the rate it reached, more
/// than the real one.
fn probe_rate(
    spec: &impl Fn(u64, u64) -> Spec,
    f: &TestIntegrand,
    sizes: &[u64],
    d: usize,
    budget: &Budget,
) -> Result<Rate, Failure> {
    let n = sizes.last().copied().unwrap_or(1);
    let count = ((PROBE_VALUES / d as f64) as u64).clamp(1, n);
    let clock = std::time::Instant::now();
    let done = error_of(&spec(n, 0), f, count, budget);
    let seconds = clock.elapsed().as_secs_f64().max(1e-6);
    let rate = Rate::per_second(count as f64 * d as f64 / seconds);
    match done {
        Ok(_) => Ok(rate),
        // Stopped by the deadline: the rate is lower still (the probe did not finish), so
        // the estimate made from it is a lower bound, past the budget.
        Err(_) if budget.check_deadline("the convergence probe").is_err() => Ok(rate),
        Err(e) => Err(e),
    }
}

/// Runs `qmckit convergence`.
pub fn run(args: &ConvergenceArgs) -> Result<(), Failure> {
    let max_m = args.max_m.unwrap_or(match args.sampler.kind {
        SamplerKind::BestCandidate | SamplerKind::GaussianBlueNoise => 10,
        _ => 12,
    });
    if max_m > MAX_M {
        return Err(Failure::usage(format!("--max-m {max_m}: at most {MAX_M}")));
    }
    if args.seeds == 0 {
        return Err(Failure::usage("--seeds must be at least 1"));
    }
    let d = dims_of(args.sampler, args.d);
    if d == 0 {
        return Err(Failure::usage("-d must be at least 1"));
    }
    let budget = args.budget.budget()?;
    let mut sizes = sizes(args.sampler, d, max_m);
    let params = IntegrandParams {
        dims: Some(d),
        ..IntegrandParams::default()
    };
    let f = &build_integrand(args.integrand, &params)
        .map_err(|e| Failure::usage(format!("--integrand {}: {e}", args.integrand.name)))?;
    let spec = |n: u64, k: u64| Spec {
        budget,
        ..Spec::base2(args.sampler, n, d, args.scramble, args.seed.wrapping_add(k))
    };
    let blue = blue_noise_kind(args.sampler).is_some();
    // Validates the request (sampler, d, scramble) before anything is timed; leading sizes
    // the construction refuses (too few points for it) are left out.
    let first = loop {
        let small = Spec {
            // Blue-noise sets: only the options are checked here (built small, outside the
            // command's budget: a set of two points costs nothing).
            n: sizes[0].min(if blue { 2 } else { u64::MAX }),
            budget: Budget::DEFAULT,
            ..spec(sizes[0], 0)
        };
        match build(&small) {
            Ok(_) => break Ok(()),
            Err(_) if sizes.len() > 1 => {
                sizes.remove(0);
            }
            Err(e) => break Err(e),
        }
    };
    first?;
    let values: Vec<f64> = sizes
        .iter()
        .map(|&n| args.seeds as f64 * n as f64 * d as f64)
        .collect();
    let total: f64 = values.iter().sum();
    let over = |e: qmckit::Error| {
        Failure::usage(format!(
            "{e}: lower --seeds, --max-m or -d, or raise --max-seconds"
        ))
    };
    // Past the budget even at the fastest rate: refused at once (no probe) when that alone
    // is longer than a probe may take; otherwise the probe names the estimate.
    let fastest = Cost::steps(total, FASTEST);
    if fastest.seconds() > budget.max_seconds().max(PROBE_SECONDS) {
        budget
            .check(
                "the convergence curve, at the fastest rate of any sampler",
                fastest,
            )
            .map_err(over)?;
    }
    let estimate = if blue {
        // Construction dominates: the sets' estimates, and the integration at a
        // conservative rate (no probe: a probe set would itself be costly to build).
        let mut built = 0.0;
        for &n in &sizes {
            built += construction(&spec(n, 0))? * args.seeds as f64;
        }
        Cost::steps(built * BLUE_RATE.steps_per_second() + total, BLUE_RATE)
    } else {
        // The probe runs within the command's deadline, or a probe's time if that is
        // shorter.
        let probe_budget = if budget.max_seconds() >= PROBE_SECONDS {
            budget
        } else {
            Budget::seconds(PROBE_SECONDS)?.started()
        };
        let first = probe_rate(&spec, f, &sizes, d, &probe_budget)?;
        let rate = if first.steps_per_second() * PROBE_SECONDS > 10.0 * PROBE_VALUES {
            // A quick probe (under a tenth of PROBE_SECONDS): once more, the faster kept.
            let second = probe_rate(&spec, f, &sizes, d, &probe_budget)?;
            Rate::per_second(first.steps_per_second().max(second.steps_per_second()))
        } else {
            first
        };
        Cost::steps(total * PROBE_SLACK, rate)
    };
    budget
        .check("the convergence curve", estimate)
        .map_err(over)?;
    let label = format!("{} on {}", args.integrand.name, args.sampler.name);
    let rows = with_progress(&label, |progress| -> Result<Vec<(u64, f64)>, Failure> {
        let mut rows = Vec::with_capacity(sizes.len());
        let mut done = 0.0;
        for (&n, &v) in sizes.iter().zip(&values) {
            let mut squares = 0.0;
            for k in 0..args.seeds {
                let e = error_of(&spec(n, k), f, n, &budget)?;
                squares += e * e;
                done += v / args.seeds as f64;
                progress((1000.0 * done / total) as usize, 1000);
            }
            rows.push((n, (squares / args.seeds as f64).sqrt()));
        }
        Ok(rows)
    })?;
    let mut out = BufWriter::new(std::io::stdout().lock());
    writeln!(out, "# n rmse")?;
    for (n, rmse) in rows {
        writeln!(out, "{n} {rmse:.16e}")?;
    }
    out.flush()?;
    Ok(())
}
