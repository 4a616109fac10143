//! `qmckit points poisson|best-candidate|gaussian-blue-noise|pmj02bn`: the point sets
//! built whole (they are not sequences), budgeted by `--max-seconds`.

use clap::Args;
use qmckit::blue_noise::{BestCandidate, GaussianBlueNoise, PointSet, PoissonDisk};
use qmckit::work::{Budget, DEFAULT_SECONDS};

use super::Failure;
use super::output::{Format, PointWriter};

/// Options of the blue-noise samplers (flattened into `points`).
#[derive(Args, Debug, Clone, Default)]
pub struct BlueNoiseArgs {
    /// poisson: the disk radius (no two points closer), instead of -n.
    #[arg(long, value_name = "R")]
    pub radius: Option<f64>,
    /// poisson: on the unit torus (toroidal distance) instead of the unit cube.
    #[arg(long)]
    pub torus: bool,
    /// poisson: fill up to a maximal set (no further disk of the radius fits).
    #[arg(long)]
    pub maximal: bool,
    /// poisson: candidates per step [default: 30]; best-candidate: the multiplier m
    /// (point i is the best of m i candidates) [default: 10].
    #[arg(long, value_name = "C")]
    pub candidates: Option<u32>,
    /// gaussian-blue-noise: gradient-descent iterations [default: 500].
    #[arg(long, value_name = "I")]
    pub iterations: Option<u32>,
    /// sot: projective sampling, every other slicing direction in an axis-aligned 1D or
    /// 2D subspace (the projections are spread too).
    #[arg(long)]
    pub projective: bool,
    /// kde-blue-noise: the temperature T [default: 0.001].
    #[arg(long, value_name = "T")]
    pub temperature: Option<f64>,
    /// The time budget of the blue-noise sets and of pmj02bn ('inf': no limit)
    /// [default: 10].
    #[arg(long, value_name = "SECONDS")]
    pub max_seconds: Option<f64>,
}

/// Which blue-noise set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Bridson Poisson disk.
    Poisson,
    /// Mitchell best candidate.
    BestCandidate,
    /// Gaussian blue noise.
    Gaussian,
}

impl BlueNoiseArgs {
    /// The first blue-noise option given, for refusing it on other samplers; `budgeted`
    /// samplers (pmj02bn) take `--max-seconds`.
    pub fn first_given(&self, budgeted: bool) -> Option<&'static str> {
        [
            ("--radius", self.radius.is_some()),
            ("--torus", self.torus),
            ("--maximal", self.maximal),
            ("--candidates", self.candidates.is_some()),
            ("--iterations", self.iterations.is_some()),
            ("--projective", self.projective),
            ("--temperature", self.temperature.is_some()),
            ("--max-seconds", self.max_seconds.is_some() && !budgeted),
        ]
        .into_iter()
        .find(|(_, given)| *given)
        .map(|(name, _)| name)
    }

    /// The budget of one of `sets` sets (at least 1): `--max-seconds` divided among them,
    /// not started (each set starts its own, so the command stays within `GRACE` times
    /// `--max-seconds`).
    pub fn budget_per_set(&self, sets: u64) -> Result<Budget, Failure> {
        let s = self.max_seconds.unwrap_or(DEFAULT_SECONDS);
        let refused = || {
            Failure::usage(format!(
                "--max-seconds must be a positive number of seconds, not {s}"
            ))
        };
        Budget::seconds(s).map_err(|_| refused())?;
        Budget::seconds(s / sets.max(1) as f64).map_err(|_| refused())
    }
}

/// Builds the set `kind` names: `n` points (or the radius), `d` dimensions, `seed`, within
/// `budget` (its estimate checked first, its deadline bounding the construction; the
/// caller starts it, so one deadline covers the command).
pub fn build(
    kind: Kind,
    args: &BlueNoiseArgs,
    n: Option<u64>,
    d: Option<usize>,
    seed: u64,
    budget: Budget,
) -> Result<PointSet, Failure> {
    let name = match kind {
        Kind::Poisson => "poisson",
        Kind::BestCandidate => "best-candidate",
        Kind::Gaussian => "gaussian-blue-noise",
    };
    let refuse = |option: &str| Err(Failure::usage(format!("{option} does not apply to {name}")));
    let budget = budget.started();
    if kind != Kind::Poisson {
        for (option, given) in [
            ("--radius", args.radius.is_some()),
            ("--torus", args.torus),
            ("--maximal", args.maximal),
        ] {
            if given {
                return refuse(option);
            }
        }
        if d.is_some_and(|d| d != 2) {
            return Err(Failure::usage(format!(
                "{name} is two-dimensional: -d must be 2"
            )));
        }
    }
    if args.projective {
        return refuse("--projective");
    }
    if args.temperature.is_some() {
        return refuse("--temperature");
    }
    if kind != Kind::Gaussian && args.iterations.is_some() {
        return refuse("--iterations");
    }
    if kind == Kind::Gaussian && args.candidates.is_some() {
        return refuse("--candidates");
    }
    let need_n =
        || n.ok_or_else(|| Failure::usage(format!("{name} needs -n N (the number of points)")));
    Ok(match kind {
        Kind::Poisson => {
            let d = d.unwrap_or(2);
            let pd = match (args.radius, n) {
                (Some(_), Some(_)) => {
                    return Err(Failure::usage(
                        "poisson takes --radius R or -n N (about N points), not both",
                    ));
                }
                (Some(r), None) => PoissonDisk::new(d, r)?,
                (None, Some(n)) => PoissonDisk::with_points(d, n)?,
                (None, None) => {
                    return Err(Failure::usage("poisson needs --radius R or -n N"));
                }
            };
            let mut pd = pd.torus(args.torus).maximal(args.maximal).seed(seed);
            if let Some(k) = args.candidates {
                pd = pd.candidates(k)?;
            }
            pd.generate(&budget)?
        }
        Kind::BestCandidate => {
            let mut bc = BestCandidate::new(need_n()?)?.seed(seed);
            if let Some(m) = args.candidates {
                bc = bc.candidates(m)?;
            }
            bc.generate(&budget)?
        }
        Kind::Gaussian => {
            let mut g = GaussianBlueNoise::new(need_n()?)?.seed(seed);
            if let Some(i) = args.iterations {
                g = g.iterations(i)?;
            }
            g.generate(&budget)?
        }
    })
}

/// Writes the set in `format`.
pub fn write(set: &PointSet, format: Format, out: impl std::io::Write) -> Result<(), Failure> {
    use qmckit::Sampler;
    let mut writer = PointWriter::new(out, format, set.len(), set.dims())?;
    writer.write(set.coords(), set.dims())?;
    writer.finish()
}
