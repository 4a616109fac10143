//! `qmckit discrepancy [--metric M[,M..]] [FILE|-]`: measure point sets read from text.

use std::io::{BufWriter, Write};

use clap::Args;
use qmckit::analysis::Points;
use qmckit::analysis::l2::L2Metric;
use qmckit::analysis::pointfile::PointSet;
use qmckit::analysis::star;
use qmckit::analysis::star::thiemard;
use qmckit::work::{Budget, Limits};

use super::Failure;
use super::budget::{BudgetArgs, over_budget};
use super::input::{InputArgs, read_point_sets, set_label};
use super::progress::{with_progress, with_spinner};
use clap::builder::{PossibleValue, TypedValueParser};
use qmckit::catalog::{self, MEASURES, MeasureEntry, MeasureKind};

/// Text shown after the options of `qmckit discrepancy --help`.
pub const AFTER_HELP: &str = "\
Input: one point a line, coordinates in [0, 1] separated by spaces/tabs or by single commas;
'#' starts a comment; a line holding only '#' separates point sets; blank lines are ignored.
Line ends \\n, \\r\\n or \\r. qmckit's own u32 output (whole numbers, one above 1) and .npy
files are recognized; --input-format forces a reading.

Output: one 'metric value' line per metric, the value in scientific notation with 17
significant digits (it parses back to the exact f64). With several point sets, each set's
block is preceded by a '# set K' line (K from 1).

Conventions:
  star      star discrepancy D*, exact (1D closed form; 2D sweep; d-D by
            Dobkin-Eppstein-Mitchell). Refused with an error when the estimated time
            exceeds --max-seconds (default 10: N <= 114016 in 2D, 64517 at d = 3, 557 at
            d = 6; 600 admits 1893 at d = 6). A bar shows the progress on a terminal.
  star-bounds  guaranteed bounds on D* for sets too large for the exact value: two lines,
            'star-lower' (the best of Thiemard's cover and threshold accepting: a value
            D* reaches) and 'star-upper' (Thiemard's cover: at most D* + delta); --delta
            sets the gap (default 0.05; smaller is slower). Both are estimated first and
            refused when the estimate exceeds --max-seconds (e.g. any delta < 1 for two
            points in 1000 dimensions; delta 0.0002 in 2D, 0.08 in 5D for 1000 points fit).
  extreme   extreme (unanchored box) discrepancy, exact, 2D only, refused past
            --max-seconds (N^3 / 2 steps at 1.7e8 a second: N <= 1503 by default)
  l2-star   L2-star (Warnock), square root taken (SciPy method=\"L2-star\")
  cd        centered L2, squared (SciPy method=\"CD\")
  wd        wrap-around L2, squared (SciPy method=\"WD\")
  md        mixture L2, squared (SciPy method=\"MD\")
  sl2       symmetric L2, square root taken (UTK SymmetricL2Discrepancy)
  ul2       unanchored L2, square root taken (UTK UnanchoredL2Discrepancy)
  gl2       generalized L2, square root taken (UTK GL2Discrepancy)
  diaphony  Zinterhof's diaphony, square root taken (UTK Diaphony)
  all       star, then the eight L2 measures in the order above; more metrics may follow
            (all,extreme). A measure of all that is refused (past the budget, or a value
            outside the range of f64) is replaced by a '# NAME skipped: REASON' line and
            the others are still computed; a refused measure named on its own is an error.

The L2 measures cost about N^2 d / 2 steps (the Warnock tree for l2-star in low d: about
N log^(d-1) N), estimated first (per measure: 30000 points in 8D about 0.4 s on two
cores) and refused past --max-seconds; in any dimension they are
computed with tracked exponents, so a value representable in f64 is right to about 1e-13
and one that is not is refused, never NaN or 0. A bar shows on a terminal when a metric
takes more than a second. Errors: 'qmckit: error: FILE: line N: reason', exit code 2.";

/// A measure `--metric` names: a catalog measure this command computes, or `all`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Metric {
    /// One catalog measure.
    One(MeasureKind, &'static str),
    /// star and the eight L2 measures (`MeasureKind::ALL_DISCREPANCIES`).
    All,
}

impl Metric {
    /// The library measure behind an L2 name.
    fn l2(self) -> Option<L2Metric> {
        match self {
            Metric::One(kind, _) => kind.l2(),
            Metric::All => None,
        }
    }

    /// The measure's kind (`all` has none).
    fn kind(self) -> Option<MeasureKind> {
        match self {
            Metric::One(kind, _) => Some(kind),
            Metric::All => None,
        }
    }

    /// The measure's canonical name.
    fn name(self) -> &'static str {
        match self {
            Metric::One(_, name) => name,
            Metric::All => "all",
        }
    }

    /// The metric of `kind`.
    fn of(kind: MeasureKind) -> Metric {
        let name = MEASURES
            .iter()
            .find(|e| e.kind == kind)
            .map_or("", |e| e.name);
        Metric::One(kind, name)
    }
}

/// The measures this command computes: the star discrepancy, its bounds, the extreme
/// discrepancy and the L2 measures.
fn computed(e: &MeasureEntry) -> bool {
    e.kind.l2().is_some()
        || matches!(
            e.kind,
            MeasureKind::Star | MeasureKind::StarBounds | MeasureKind::Extreme
        )
}

/// Parses `--metric`: `all` or a catalog measure (any alias) this command computes.
#[derive(Clone)]
struct MetricParser;

impl TypedValueParser for MetricParser {
    type Value = Metric;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<Metric, clap::Error> {
        let text = value.to_string_lossy();
        if text.eq_ignore_ascii_case("all") {
            return Ok(Metric::All);
        }
        let found = match catalog::measure(&text) {
            Ok(e) if computed(e) => Ok(Metric::One(e.kind, e.name)),
            Ok(e) => Err(format!(
                "{}: discrepancy computes star, star-bounds, extreme and the L2 measures (see \
                 'qmckit {}' where there is one)",
                e.name,
                match e.kind {
                    MeasureKind::TValue => "tvalue",
                    MeasureKind::Spectrum | MeasureKind::RadialSpectrum => "spectrum",
                    MeasureKind::Pcf => "pcf",
                    MeasureKind::Variance => "variance",
                    MeasureKind::IntegrationError => "convergence",
                    _ => "--help",
                }
            )),
            Err(e) => Err(e.to_string()),
        };
        found.map_err(|reason| {
            let mut err = clap::Error::new(clap::error::ErrorKind::InvalidValue).with_cmd(cmd);
            if let Some(arg) = arg {
                err.insert(
                    clap::error::ContextKind::InvalidArg,
                    clap::error::ContextValue::String(arg.to_string()),
                );
            }
            err.insert(
                clap::error::ContextKind::InvalidValue,
                clap::error::ContextValue::String(reason),
            );
            err
        })
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new(
            MEASURES
                .iter()
                .filter(|e| computed(e))
                .map(|e| PossibleValue::new(e.name).help(e.summary))
                .chain([PossibleValue::new("all").help("star and the eight L2 measures")]),
        ))
    }
}

/// Arguments of `qmckit discrepancy`.
#[derive(Args, Debug)]
pub struct DiscrepancyArgs {
    /// Metrics to compute, comma-separated (see below).
    #[arg(long, value_parser = MetricParser, value_delimiter = ',', default_value = "all")]
    metric: Vec<Metric>,
    /// Gap between the bounds of star-bounds, in (0, 1].
    #[arg(long, default_value_t = 0.05)]
    delta: f64,
    #[command(flatten)]
    budget: BudgetArgs,
    #[command(flatten)]
    input: InputArgs,
}

/// Why an exact measure refused, as the command reports it; `limit` names what set the
/// limit, if an option did.
fn refusal(e: qmckit::Error, what: &str, set: &PointSet, limit: &str) -> String {
    match e {
        qmckit::Error::TooManyPoints { max, .. } => format!(
            "{} points in {} dimensions are too many for the exact {what} (at most {max}{limit})",
            set.len(),
            set.dims
        ),
        other => over_budget(other),
    }
}

/// Threshold-accepting iterations for star-bounds: about 3e8 point-coordinate steps.
fn lower_bound_iterations(p: Points<'_>) -> u64 {
    (3e8 / (p.len() * p.dims()).max(1) as f64).clamp(1000.0, 100_000.0) as u64
}

/// One measure of one set as `(name, value)` lines, or why it was refused.
fn measure(
    metric: Metric,
    p: Points<'_>,
    set: &PointSet,
    args: &DiscrepancyArgs,
    budget: &Budget,
) -> Result<Vec<(String, f64)>, String> {
    let name = metric.name().to_owned();
    if let Some(l2) = metric.l2() {
        let value = with_progress(&name, |progress| {
            l2.eval(p, Limits::new(*budget).with_progress(progress))
        })
        .map_err(over_budget)?;
        return Ok(vec![(name.clone(), value)]);
    }
    let kind = match metric {
        Metric::One(kind, _) => kind,
        Metric::All => return Err("'all' is expanded".to_owned()),
    };
    let value = match kind {
        MeasureKind::Star => {
            let estimate = star::star_cost(p.len(), p.dims()).seconds();
            let limit = format!(" within --max-seconds {}", args.budget.max_seconds);
            with_progress(&name, |progress| {
                star::star_exact(p, Limits::new(*budget).with_progress(progress))
            })
            .map_err(|e| match e {
                qmckit::Error::TooManyPoints { .. } => format!(
                    "{}; estimated {estimate:.3} s",
                    refusal(e, "star", set, &limit)
                ),
                e => refusal(e, "star", set, &limit),
            })
        }
        MeasureKind::StarBounds => {
            let b = with_spinner(&name, || thiemard::bounds(p, args.delta, budget)).map_err(
                |e| match e {
                    qmckit::Error::TooManyPoints { max: 0, .. } => format!(
                        "star-bounds: Thiemard's cover at --delta {} takes longer than \
                         --max-seconds {} for {} dimensions; take a larger delta",
                        args.delta, args.budget.max_seconds, set.dims
                    ),
                    e => refusal(e, "star-bounds", set, ""),
                },
            )?;
            let ta = with_spinner(&name, || {
                star::star_lower_bound(p, 0, lower_bound_iterations(p), budget)
            })
            .map_err(over_budget)?;
            // Both are valid lower bounds, the cover's upper bound is valid too: D* lies
            // between, so their order only breaks by rounding.
            return Ok(vec![
                ("star-lower".to_owned(), b.lower.max(ta).min(b.upper)),
                ("star-upper".to_owned(), b.upper),
            ]);
        }
        MeasureKind::Extreme if set.dims != 2 => Err(format!(
            "extreme is implemented for 2-dimensional points only, not {}",
            set.dims
        )),
        MeasureKind::Extreme => with_spinner(&name, || star::extreme_2d(p, budget))
            .map_err(|e| refusal(e, "extreme", set, "")),
        _ => Err(format!("{name} is not computed here")),
    }?;
    Ok(vec![(name, value)])
}

/// The metrics to compute, in the order given: `all` stands for its nine, and a metric
/// named twice (or inside `all` and again) is computed once.
fn expand(asked: &[Metric]) -> Vec<Metric> {
    let mut out = Vec::new();
    for &m in asked {
        let items: Vec<Metric> = if m == Metric::All {
            MeasureKind::ALL_DISCREPANCIES.map(Metric::of).to_vec()
        } else {
            vec![m]
        };
        for item in items {
            if !out.contains(&item) {
                out.push(item);
            }
        }
    }
    out
}

/// Runs `qmckit discrepancy`.
pub fn run(args: &DiscrepancyArgs) -> Result<(), Failure> {
    let budget = args.budget.budget()?;
    let (name, sets) = read_point_sets(&args.input)?;
    let all = args.metric.contains(&Metric::All);
    let metrics = expand(&args.metric);
    let mut out = BufWriter::new(std::io::stdout().lock());
    for (k, set) in sets.iter().enumerate() {
        let p = set
            .points()
            .map_err(|e| Failure::usage(format!("{name}: set {}: {e}", k + 1)))?;
        if sets.len() > 1 {
            writeln!(out, "# set {}", k + 1)?;
        }
        for &metric in &metrics {
            match measure(metric, p, set, args, &budget) {
                Ok(lines) => {
                    for (label, value) in lines {
                        writeln!(out, "{label} {value:.16e}")?;
                    }
                }
                Err(reason)
                    if all
                        && metric
                            .kind()
                            .is_some_and(|k| MeasureKind::ALL_DISCREPANCIES.contains(&k)) =>
                {
                    // Past the deadline every later measure would stop too: one error.
                    if let Err(e) = budget.check_deadline("the discrepancy measures") {
                        out.flush()?;
                        return Err(Failure::usage(format!("{name}: {}", over_budget(e))));
                    }
                    writeln!(out, "# {} skipped: {reason}", metric.name())?;
                }
                Err(reason) => {
                    out.flush()?;
                    let set = set_label(k, sets.len());
                    return Err(Failure::usage(format!("{name}: {set}{reason}")));
                }
            }
        }
    }
    out.flush()?;
    Ok(())
}
