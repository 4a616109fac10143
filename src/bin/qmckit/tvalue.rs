//! `qmckit tvalue SAMPLER -m M [-d D] [--scramble KIND] [--seed S] [--explain]`: the t-value
//! of the first `2^m` points of a base-2 construction.

use std::io::Write;

use clap::Args;
use qmckit::analysis::tvalue::{
    DigitalNet2, IntervalFailure, elementary_interval_failures_u32, t_value, t_value_u32,
};

use super::Failure;
use super::points::{SamplerName, ScrambleName, Spec, samples_u32, value_name};
use super::progress::with_spinner;

/// Text shown after the options of `qmckit tvalue --help`.
pub const AFTER_HELP: &str = "\
Samplers (base 2 only): sobol (any d), lp (d = 2), hammersley (d = 2: (i/2^m, phi_2(i))),
vdc (d = 1, base 2). Other samplers are refused.

Method: without --scramble, the rank test on the generator matrices (exact, m <= 32; its
cost grows like C(m - t + 1 + d, d), fast for small d). With --scramble KIND (any kind
`qmckit points` accepts for the sampler), the 2^m points are generated and counted in
elementary intervals (exact; m <= 21, 2^m * d <= 2^25, and 2^m d C(m + d - 1, d - 1) <= 1e8
steps, e.g. m <= 21 in 2D, m <= 17 in 3D; larger requests are refused). --explain counts too,
so it has the same limits.

Output, one 'key value' line each:
  sampler NAME
  scramble KIND
  m M
  d D
  method rank|count
  t T
With --explain and t > 0, up to five 'fail ...' lines follow, each an elementary interval
of volume 2^(t-1-m) that does not hold 2^(t-1) points (why t-1 fails), e.g.
  fail shape [1, 2]: [0, 1)/2^1 x [3, 4)/2^2 holds 0 point(s), 1 expected";

/// Arguments of `qmckit tvalue`.
#[derive(Args, Debug)]
pub struct TvalueArgs {
    /// Which construction: sobol, lp, hammersley or vdc.
    sampler: SamplerName,
    /// The set has 2^m points (m <= 32; m <= 21 when counting).
    #[arg(short = 'm', value_name = "M")]
    m: u32,
    /// Dimensions [default: 1 for vdc, 2 otherwise].
    #[arg(short = 'd', value_name = "D")]
    d: Option<usize>,
    /// Randomization, as for `qmckit points` (then the points are counted).
    #[arg(long, value_enum, default_value_t = ScrambleName::None)]
    scramble: ScrambleName,
    /// Seed of the randomization.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Name up to five elementary intervals that break t-1.
    #[arg(long)]
    explain: bool,
}

/// Largest `m` whose points are generated and counted.
const COUNT_MAX_M: u32 = 21;
/// Largest number of coordinates (`2^m d`) generated for counting.
const COUNT_MAX_VALUES: u64 = 1 << 25;

/// Largest [`count_work`] accepted: seconds on two cores.
const COUNT_MAX_WORK: f64 = 1e8;

/// Failures listed by `--explain`.
const EXPLAIN_LIMIT: usize = 5;

/// The unscrambled construction as generator matrices, after checking `d`.
fn net(sampler: SamplerName, m: u32, d: usize) -> Result<DigitalNet2, Failure> {
    let fixed = |want: usize, what: &str| {
        if d == want {
            Ok(())
        } else {
            Err(Failure::usage(format!(
                "{what} is {want}-dimensional: -d must be {want}, got {d}"
            )))
        }
    };
    Ok(match sampler {
        SamplerName::Sobol if d > qmckit::SOBOL_MAX_DIMS => {
            return Err(Failure::usage(format!(
                "sobol has {} dimensions: -d must be at most that, got {d}",
                qmckit::SOBOL_MAX_DIMS
            )));
        }
        SamplerName::Sobol => DigitalNet2::from_sobol(d, m)?,
        SamplerName::Lp => {
            fixed(2, "lp")?;
            DigitalNet2::larcher_pillichshammer(m)?
        }
        SamplerName::Hammersley => {
            fixed(2, "hammersley in base 2")?;
            DigitalNet2::hammersley(m)?
        }
        SamplerName::Vdc => {
            fixed(1, "vdc")?;
            DigitalNet2::van_der_corput(m)?
        }
        other => {
            return Err(Failure::usage(format!(
                "tvalue measures base-2 constructions (sobol, lp, hammersley, vdc); {} is not one",
                value_name(&other)
            )));
        }
    })
}

/// Estimated steps of counting `2^m` points of `d` dimensions into the cells of every
/// interval shape of size up to `m`: `2^m d C(m + d - 1, d - 1)`.
fn count_work(m: u32, d: usize) -> f64 {
    let shapes = (1..d).fold(1.0, |c, k| c * (m as f64 + k as f64) / k as f64);
    (1u64 << m) as f64 * d as f64 * shapes
}

/// Refuses point counts too large to generate and count in reasonable time and memory.
fn check_countable(m: u32, d: usize, why: &str) -> Result<(), Failure> {
    let values = (1u64 << m).saturating_mul(d as u64);
    if m > COUNT_MAX_M || values > COUNT_MAX_VALUES {
        return Err(Failure::usage(format!(
            "{why} counts points: 2^{m} points of {d} dimensions are too many \
             (m <= {COUNT_MAX_M} and 2^m * d <= 2^25)"
        )));
    }
    let work = count_work(m, d);
    if work > COUNT_MAX_WORK {
        return Err(Failure::usage(format!(
            "{why} counts points: 2^{m} points of {d} dimensions take too long to count \
             (about {work:.1e} steps, at most {COUNT_MAX_WORK:.0e}); lower -m or -d"
        )));
    }
    Ok(())
}

/// Runs `qmckit tvalue`.
pub fn run(args: &TvalueArgs) -> Result<(), Failure> {
    let m = args.m;
    if m > 32 {
        return Err(Failure::usage(format!(
            "-m {m}: at most 32 (2^m points of 32-bit coordinates)"
        )));
    }
    let d = args.sampler.dims(args.d);
    if d == 0 {
        return Err(Failure::usage("-d must be at least 1"));
    }
    // Validates the sampler and d for both methods.
    let net = net(args.sampler, m, d)?;
    let counting = args.scramble != ScrambleName::None;
    if args.explain {
        check_countable(m, d, "--explain")?;
    }
    let (t, samples) = if counting {
        check_countable(m, d, "--scramble")?;
        let spec = Spec::base2(args.sampler, 1u64 << m, d, args.scramble, args.seed);
        let (samples, dims) = samples_u32(&spec)?;
        let t = with_spinner("t-value (counting)", || t_value_u32(&samples, dims, m))?;
        (t, Some(samples))
    } else {
        (with_spinner("t-value (rank test)", || t_value(&net)), None)
    };
    let mut out = std::io::stdout().lock();
    writeln!(out, "sampler {}", value_name(&args.sampler))?;
    writeln!(out, "scramble {}", value_name(&args.scramble))?;
    writeln!(out, "m {m}\nd {d}")?;
    writeln!(out, "method {}", if counting { "count" } else { "rank" })?;
    writeln!(out, "t {t}")?;
    if args.explain && t > 0 {
        let samples = match samples {
            Some(s) => s,
            None => net.points()?,
        };
        let failures: Vec<IntervalFailure> = with_spinner("elementary intervals", || {
            elementary_interval_failures_u32(&samples, d, m, t - 1, EXPLAIN_LIMIT)
        })?;
        for f in failures {
            writeln!(out, "fail {f}")?;
        }
    }
    out.flush()?;
    Ok(())
}
