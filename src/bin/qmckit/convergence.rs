//! `qmckit convergence SAMPLER --integrand F [-d D] [--max-m M] [--scramble KIND] [--seeds S]`:
//! integration error against the number of points.

use std::io::{BufWriter, Write};

use clap::{Args, ValueEnum};
use qmckit::analysis::Points;
use qmckit::analysis::integration::{Integrand, integration_error};

use crate::Failure;
use crate::points::{SamplerName, ScrambleName, Spec, build, value_name};
use crate::progress::with_spinner;

/// Text shown after the options of `qmckit convergence --help`.
pub const AFTER_HELP: &str = "\
Integrands over [0, 1]^d, each with a closed-form integral I:
  gaussian     exp(-16 |x - c|^2), c the centre (Genz's Gaussian peak)
  oscillatory  cos(0.6 pi + 2 sum_k x_k) (Genz's oscillatory)
  ball         1 inside the ball of radius 0.45 about the centre
  heaviside    1 where sum_k sqrt(k + 2) (x_k - 1/2) >= 0 (I = 1/2)

For N = 1, 2, 4, ..., 2^M (stratified: N = k^d for k = 1, 2, 4, ...), the first N points of
the sampler (finite sets: a set of N points) estimate I by their average; with --seeds S
the sampler is drawn with seeds --seed, --seed + 1, ... and the root mean square of the S
errors is reported (unrandomized sequences give S equal errors). Output: a '# n rmse'
header, then 'N RMSE' lines, RMSE with 17 significant digits. At most 2^24 points and 1e9
coordinates in all (S 2^(M+1) d). Errors: one line, exit code 2.";

/// The integrands by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum IntegrandName {
    /// Genz's Gaussian peak.
    Gaussian,
    /// Genz's oscillatory.
    Oscillatory,
    /// Ball indicator.
    Ball,
    /// Half-space indicator.
    Heaviside,
}

/// Arguments of `qmckit convergence`.
#[derive(Args, Debug)]
pub struct ConvergenceArgs {
    /// Which construction, as for `qmckit points`.
    sampler: SamplerName,
    /// The integrand (see below).
    #[arg(long, value_enum, default_value_t = IntegrandName::Gaussian)]
    integrand: IntegrandName,
    /// Dimensions [default: 1 for vdc, 2 otherwise].
    #[arg(short = 'd', value_name = "D")]
    d: Option<usize>,
    /// Largest set: 2^M points (M <= 24).
    #[arg(long, default_value_t = 12, value_name = "M")]
    max_m: u32,
    /// Randomization, as for `qmckit points`.
    #[arg(long, value_enum, default_value_t = ScrambleName::None)]
    scramble: ScrambleName,
    /// Number of seeds whose errors are averaged (root mean square).
    #[arg(long, default_value_t = 1)]
    seeds: u64,
    /// First seed.
    #[arg(long, default_value_t = 0)]
    seed: u64,
}

/// Largest `--max-m`.
const MAX_M: u32 = 24;
/// Most coordinates generated in all.
const MAX_VALUES: f64 = 1e9;

/// The set sizes: powers of two up to `2^m`, or for stratified sets `k^d`, `k` doubling.
fn sizes(sampler: SamplerName, d: usize, m: u32) -> Vec<u64> {
    let top = 1u64 << m;
    let power = u32::try_from(d).unwrap_or(u32::MAX);
    let mut sizes = Vec::new();
    let mut k = 1u64;
    while k <= top {
        let n = if sampler == SamplerName::Stratified {
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

/// The integration error of the set `spec` names, its points generated in batches: the
/// batches' errors weighted by their sizes, `sum_b N_b (mean_b - I) / N = mean - I`.
fn error_of(spec: &Spec, f: Integrand) -> Result<f64, Failure> {
    let sampler = build(spec)?;
    let dims = sampler.dims();
    let rows = (BATCH_VALUES / dims).max(1);
    let mut raw = vec![0u32; rows * dims];
    let (mut weighted, mut start) = (0.0, 0u64);
    while start < spec.n {
        let take = rows.min((spec.n - start) as usize);
        let buf = &mut raw[..take * dims];
        let first = u32::try_from(start).map_err(|_| Failure::usage("index past 2^32"))?;
        sampler.fill(first, buf)?;
        let data = Points::from_u32(buf);
        weighted += take as f64 * integration_error(Points::new(&data, dims)?, f);
        start += take as u64;
    }
    Ok(weighted / spec.n as f64)
}

/// Runs `qmckit convergence`.
pub fn run(args: &ConvergenceArgs) -> Result<(), Failure> {
    if args.max_m > MAX_M {
        return Err(Failure::usage(format!(
            "--max-m {}: at most {MAX_M}",
            args.max_m
        )));
    }
    if args.seeds == 0 {
        return Err(Failure::usage("--seeds must be at least 1"));
    }
    let d = args.sampler.dims(args.d);
    if d == 0 {
        return Err(Failure::usage("-d must be at least 1"));
    }
    let sizes = sizes(args.sampler, d, args.max_m);
    let values = args.seeds as f64 * sizes.iter().sum::<u64>() as f64 * d as f64;
    if values > MAX_VALUES {
        return Err(Failure::usage(format!(
            "{} seeds of up to 2^{} points in {d} dimensions are {values:.1e} coordinates \
             (at most {MAX_VALUES:.0e}); lower --seeds, --max-m or -d",
            args.seeds, args.max_m
        )));
    }
    let f = match args.integrand {
        IntegrandName::Gaussian => Integrand::Gaussian,
        IntegrandName::Oscillatory => Integrand::Oscillatory,
        IntegrandName::Ball => Integrand::Ball,
        IntegrandName::Heaviside => Integrand::Heaviside,
    };
    let label = format!(
        "{} on {}",
        value_name(&args.integrand),
        value_name(&args.sampler)
    );
    let rows = with_spinner(&label, || -> Result<Vec<(u64, f64)>, Failure> {
        let mut rows = Vec::with_capacity(sizes.len());
        for &n in &sizes {
            let mut squares = 0.0;
            for k in 0..args.seeds {
                let seed = args.seed.wrapping_add(k);
                let e = error_of(&Spec::base2(args.sampler, n, d, args.scramble, seed), f)?;
                squares += e * e;
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
