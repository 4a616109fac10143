//! `qmckit tvalue SAMPLER -m M [-d D] [--scramble KIND] [--seed S] [--explain]`: the t-value
//! of the first `2^m` points of a base-2 construction (or `b^m` of faure); `qmckit tvalue
//! FILE|-`: the t-value of a point file of `b^m` points.

use std::io::Write;

use clap::Args;
use qmckit::analysis::tvalue::{
    IntervalFailure, elementary_interval_failures_u32, failures_cost, t_value_cost,
    t_value_u32_expecting,
};
use qmckit::digital::DigitalNet2;
use qmckit::digital::rank::t_value;
use qmckit::work::{Budget, Cost, Limits};

use super::Failure;
use super::budget::BudgetArgs;
use qmckit::catalog::{RandomizerKind, SamplerKind};

use super::input::{InputArgs, InputFormat, read_point_sets};
use super::names;
use super::points::{SamplerName, ScrambleName, Spec, dims_of, samples_u32};
use super::progress::{with_progress, with_spinner};

/// Text shown after the options of `qmckit tvalue --help`.
pub const AFTER_HELP: &str = "\
Samplers (base 2): sobol (any d), lp (d = 2), hammersley (d = 2: (i/2^m, phi_2(i))),
vdc (d = 1, base 2); pmj02 and pmj02bn (d = 2, seeded by --seed, generated and counted).
In base b: faure (the first b^m points, counted exactly in base b; --base B, a prime >= d;
--scramble owen|perm|faure; output adds a 'base B' line). Other catalog samplers are
refused in one line.

A point file (FILE, or '-' for standard input) of b^m points (base --base B, default 2),
in any format 'qmckit points' writes, is judged by counting its elementary intervals:
  qmckit points pmj02bn -n 256 | qmckit tvalue -
prints 'file', 'base', 'm', 'd', 'method count' and 't' lines.

Method: without --scramble, the rank test on the generator matrices (exact, m <= 32; its
cost grows like C(m - t + 1 + d, d), fast for small d; estimated first and refused when the
estimate exceeds --max-seconds, e.g. -m 32 -d 50 or -m 20 -d 1000). With --scramble KIND
(any kind `qmckit points` accepts for the sampler), the 2^m points are generated and counted
in elementary intervals (exact; m <= 21 and 2^m * d <= 2^25, and an estimate within
--max-seconds: the levels rho of the binary search for t, each C(rho + d - 1, d - 1) 2^m
(d + 1) steps at 1.2e9 a second on each of two cores, following the search for the
t-value of the unscrambled net, which every scramble but rotate keeps (a rotated set is
estimated as no net, t = m - 1); e.g. m <= 21 in 2D,
m <= 20 in 4D by default; larger requests are refused). --explain counts one level too,
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

/// What `tvalue` judges: a catalog sampler, or a point file (`-`: standard input).
#[derive(Clone, Debug)]
pub enum TvalueInput {
    /// A catalog sampler that tvalue can judge.
    Sampler(SamplerName),
    /// A point file of `b^m` points (`-` is standard input).
    File(String),
}

/// The samplers `tvalue` judges: the base-2 digital constructions, hammersley, faure and
/// the (0,2)-sequences pmj02 and pmj02bn.
fn judged(e: &qmckit::catalog::SamplerEntry) -> bool {
    matches!(
        e.kind,
        SamplerKind::Sobol
            | SamplerKind::Lp
            | SamplerKind::Vdc
            | SamplerKind::Hammersley
            | SamplerKind::Faure
            | SamplerKind::Pmj02
            | SamplerKind::Pmj02bn
    )
}

/// Parses `SAMPLER|FILE|-`: a catalog name (any alias) first, else `-` or an existing file.
#[derive(Clone)]
struct InputParser;

impl clap::builder::TypedValueParser for InputParser {
    type Value = TvalueInput;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<TvalueInput, clap::Error> {
        let text = value.to_string_lossy();
        if qmckit::catalog::sampler(&text).is_err()
            && (text == "-" || std::path::Path::new(value).is_file())
        {
            return Ok(TvalueInput::File(text.into_owned()));
        }
        names::samplers()
            .only(
                judged,
                "tvalue judges sobol, lp, vdc, hammersley, faure, pmj02 and pmj02bn; for \
                 another set write b^m points and pass the file, e.g. 'qmckit points NAME -n \
                 256 | qmckit tvalue -'",
            )
            .parse_ref(cmd, arg, value)
            .map(TvalueInput::Sampler)
    }

    fn possible_values(
        &self,
    ) -> Option<Box<dyn Iterator<Item = clap::builder::PossibleValue> + '_>> {
        Some(Box::new(
            qmckit::catalog::SAMPLERS
                .iter()
                .filter(|e| judged(e))
                .map(|e| clap::builder::PossibleValue::new(e.name).help(e.summary)),
        ))
    }
}

/// Arguments of `qmckit tvalue`.
#[derive(Args, Debug)]
pub struct TvalueArgs {
    /// Which construction, or a point file of b^m points ('-': standard input).
    #[arg(value_parser = InputParser, value_name = "SAMPLER|FILE|-")]
    sampler: TvalueInput,
    /// The set has 2^m points (m <= 32; m <= 21 when counting) [a file: its size].
    #[arg(short = 'm', value_name = "M")]
    m: Option<u32>,
    /// Dimensions [default: 1 for vdc, 2 otherwise].
    #[arg(short = 'd', value_name = "D")]
    d: Option<usize>,
    /// Randomization, as for `qmckit points` (then the points are counted).
    #[arg(long, value_parser = names::randomizers(), default_value = "none")]
    scramble: ScrambleName,
    /// Seed of the randomization.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Name up to five elementary intervals that break t-1.
    #[arg(long)]
    explain: bool,
    /// Base of faure (a prime at least d) [default: the smallest such prime].
    #[arg(long)]
    base: Option<u32>,
    #[command(flatten)]
    budget: BudgetArgs,
}

/// Largest `m` whose points are generated and counted.
const COUNT_MAX_M: u32 = 21;
/// Largest number of coordinates (`2^m d`) generated for counting.
const COUNT_MAX_VALUES: u64 = 1 << 25;

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
    Ok(match sampler.kind {
        SamplerKind::Sobol if d > qmckit::SOBOL_MAX_DIMS => {
            return Err(Failure::usage(format!(
                "sobol has {} dimensions: -d must be at most that, got {d}",
                qmckit::SOBOL_MAX_DIMS
            )));
        }
        SamplerKind::Sobol => DigitalNet2::from_sobol(d, m)?,
        SamplerKind::Lp => {
            fixed(2, "lp")?;
            DigitalNet2::larcher_pillichshammer(m)?
        }
        SamplerKind::Hammersley => {
            fixed(2, "hammersley in base 2")?;
            DigitalNet2::hammersley(m)?
        }
        SamplerKind::Vdc => {
            fixed(1, "vdc")?;
            DigitalNet2::van_der_corput(m)?
        }
        _ => {
            return Err(Failure::usage(format!(
                "tvalue measures base-2 constructions (sobol, lp, hammersley, vdc); {} is not one",
                sampler.name
            )));
        }
    })
}

/// Refuses point counts too large to generate and count in reasonable time and memory, and
/// counts whose estimated time (`cost`) exceeds the budget.
fn check_countable(
    m: u32,
    d: usize,
    why: &str,
    cost: Cost,
    budget: &Budget,
) -> Result<(), Failure> {
    let values = (1u64 << m).saturating_mul(d as u64);
    if m > COUNT_MAX_M || values > COUNT_MAX_VALUES {
        return Err(Failure::usage(format!(
            "{why} counts points: 2^{m} points of {d} dimensions are too many \
             (m <= {COUNT_MAX_M} and 2^m * d <= 2^25)"
        )));
    }
    if let Err(e) = budget.check("counting", cost) {
        return Err(Failure::usage(format!(
            "{why} counts points: 2^{m} points of {d} dimensions take too long to count \
             ({e}); lower -m or -d, or raise --max-seconds"
        )));
    }
    Ok(())
}

/// Does `scramble` keep the t-value of a base-2 digital net? Every digital scramble does
/// (digital shifts, Owen's nested scrambles, linear matrix scrambles, digit permutations,
/// the nested index shuffle); a rotation modulo 1 does not.
fn keeps_nets(scramble: ScrambleName) -> bool {
    !matches!(
        scramble.kind,
        RandomizerKind::Rotate | RandomizerKind::Shift | RandomizerKind::ShiftTent
    )
}

/// The budget of the rank test that predicts the t-value of a scrambled net: one second (it
/// usually takes milliseconds, but its own estimate errs on the long side).
const PREDICT_SECONDS: f64 = 1.0;

/// The t-value the scrambled points are expected to have, for the estimate of the count:
/// the unscrambled net's by the rank test when the scramble keeps it (none when the rank
/// test does not fit in [`PREDICT_SECONDS`]: then the estimate assumes a net, the most a
/// count takes). A rotation breaks the digital structure: the set is expected to be no net
/// at all, `t = m - 1` (measured t = 15 for 2^16 rotated Sobol' points in 2D and 4D, and
/// for Larcher–Pillichshammer; Hammersley keeps t = 3 and van der Corput t = 0, whose
/// counts in one and two dimensions take milliseconds whatever the estimate). The
/// (0,2)-sequences (no generator matrices, `net` none) are estimated as nets.
fn expected_t(net: Option<&DigitalNet2>, scramble: ScrambleName) -> Option<u32> {
    let net = net?;
    if !keeps_nets(scramble) {
        return Some(net.m().saturating_sub(1));
    }
    let quick = Budget::seconds(PREDICT_SECONDS).ok()?;
    t_value(net, &quick).ok()
}

/// Runs `qmckit tvalue`.
pub fn run(args: &TvalueArgs) -> Result<(), Failure> {
    let budget = args.budget.budget()?;
    let sampler = match &args.sampler {
        TvalueInput::Sampler(s) => *s,
        TvalueInput::File(file) => return run_file(args, file, &budget),
    };
    let m = args
        .m
        .ok_or_else(|| Failure::usage("-m M is needed: the set has 2^m points"))?;
    if m > 32 {
        return Err(Failure::usage(format!(
            "-m {m}: at most 32 (2^m points of 32-bit coordinates)"
        )));
    }
    let d = dims_of(sampler, args.d);
    if d == 0 {
        return Err(Failure::usage("-d must be at least 1"));
    }
    if args.base.is_some() && sampler.kind != SamplerKind::Faure {
        return Err(Failure::usage("--base applies to faure only"));
    }
    if sampler.kind == SamplerKind::Faure {
        if args.explain {
            return Err(Failure::usage("--explain is for base-2 constructions"));
        }
        let (t, b) =
            super::toolbox::tvalue_faure(m, d, args.base, args.scramble, args.seed, &budget)?;
        let mut out = std::io::stdout().lock();
        writeln!(out, "sampler faure\nbase {b}")?;
        writeln!(out, "scramble {}", args.scramble.name)?;
        writeln!(out, "m {m}\nd {d}\nmethod count\nt {t}")?;
        out.flush()?;
        return Ok(());
    }
    // The (0,2)-sequences are not digital: their points are generated and counted.
    let generated = matches!(sampler.kind, SamplerKind::Pmj02 | SamplerKind::Pmj02bn);
    // Validates the sampler and d for both methods.
    let net = if generated {
        if d != 2 {
            return Err(Failure::usage(format!(
                "{} is 2-dimensional: -d must be 2, got {d}",
                sampler.name
            )));
        }
        None
    } else {
        Some(net(sampler, m, d)?)
    };
    let counting = generated || args.scramble.kind != RandomizerKind::None;
    let n = 1u64 << m;
    if args.explain && !counting {
        // The size here; the level's count, `m - t + 1`, is estimated once t is known.
        check_countable(m, d, "--explain", Cost::from_seconds(0.0), &budget)?;
    }
    let (t, samples) = if counting {
        // The estimate follows the search for the t-value expected (see
        // `t_value_u32_expecting`); --explain counts one level more, `m - t + 1`.
        let expected = expected_t(net.as_ref(), args.scramble);
        let mut cost = t_value_cost(n, d, m, 2, expected);
        if args.explain {
            let level = expected.map_or(m, |t| (m + 1).saturating_sub(t).min(m));
            cost = cost.plus(failures_cost(n, d, level, 2));
        }
        check_countable(m, d, "--scramble", cost, &budget)?;
        let spec = Spec::base2(sampler, 1u64 << m, d, args.scramble, args.seed);
        let (samples, dims) = samples_u32(&spec)?;
        let t = with_spinner("t-value (counting)", || {
            t_value_u32_expecting(&samples, dims, m, expected, &budget)
        })?;
        (t, Some(samples))
    } else {
        let net = net
            .as_ref()
            .ok_or_else(|| Failure::usage("unreachable: no generator matrices"))?;
        let t = with_progress("t-value (rank test)", |progress| {
            t_value(net, Limits::new(budget).with_progress(progress))
        })?;
        (t, None)
    };
    let mut out = std::io::stdout().lock();
    writeln!(out, "sampler {}", sampler.name)?;
    writeln!(out, "scramble {}", args.scramble.name)?;
    writeln!(out, "m {m}\nd {d}")?;
    writeln!(out, "method {}", if counting { "count" } else { "rank" })?;
    writeln!(out, "t {t}")?;
    if args.explain && t > 0 {
        let samples = match samples {
            Some(s) => s,
            None => match &net {
                Some(net) => net.points()?,
                None => return Err(Failure::usage("unreachable: no points")),
            },
        };
        let failures: Vec<IntervalFailure> = with_spinner("elementary intervals", || {
            elementary_interval_failures_u32(&samples, d, m, t - 1, EXPLAIN_LIMIT, &budget)
        })?;
        for f in failures {
            writeln!(out, "fail {f}")?;
        }
    }
    out.flush()?;
    Ok(())
}

/// `qmckit tvalue FILE|-`: the t-value of a point file of `b^m` points in base `--base`
/// (default 2), counted in elementary intervals.
fn run_file(args: &TvalueArgs, file: &str, budget: &Budget) -> Result<(), Failure> {
    for (option, given) in [
        ("-d", args.d.is_some()),
        ("--scramble", args.scramble.kind != RandomizerKind::None),
        ("--explain", args.explain),
    ] {
        if given {
            return Err(Failure::usage(format!(
                "{option} does not apply to a point file (its points are counted as they are)"
            )));
        }
    }
    let input = InputArgs {
        input_format: InputFormat::Auto,
        file: Some(file.to_owned()),
    };
    let (name, sets) = read_point_sets(&input)?;
    let [set] = sets.as_slice() else {
        return Err(Failure::usage(format!(
            "{name}: {} point sets; tvalue judges one",
            sets.len()
        )));
    };
    let points = set
        .points()
        .map_err(|e| Failure::usage(format!("{name}: {e}")))?;
    let n = points.len() as u64;
    let base = args.base.unwrap_or(2);
    if base < 2 {
        return Err(Failure::usage(format!("--base {base}: at least 2")));
    }
    let mut m = 0u32;
    let mut size = 1u64;
    while size < n {
        size = size.saturating_mul(u64::from(base));
        m += 1;
    }
    if size != n {
        return Err(Failure::usage(format!(
            "{name}: {n} points is not a power of the base {base} (a (t,m,s)-net has b^m points)"
        )));
    }
    if args.m.is_some_and(|given| given != m) {
        return Err(Failure::usage(format!(
            "-m {}: the file holds {n} = {base}^{m} points",
            args.m.unwrap_or(0)
        )));
    }
    let d = points.dims();
    let t = with_spinner("t-value (counting)", || {
        qmckit::analysis::tvalue::t_value_points(points, base, m, budget)
    })?;
    let mut out = std::io::stdout().lock();
    writeln!(
        out,
        "file {name}\nbase {base}\nm {m}\nd {d}\nmethod count\nt {t}"
    )?;
    out.flush()?;
    Ok(())
}
