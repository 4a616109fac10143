//! `qmckit variance SAMPLER -n N [--integrand disk|gaussian] [--sets S]`: the integration
//! variance of a randomly torus-shifted sampler, predicted from its mean periodogram and
//! measured, one `key value` line each.

use std::io::{BufWriter, Write};

use clap::Args;
use clap::builder::{PossibleValue, TypedValueParser};
use qmckit::analysis::Points;
use qmckit::analysis::spectrum::{
    DEFAULT_TOLERANCE, SPECTRUM_MAX_K, choose_method, estimated_cost, periodogram_2d,
};
use qmckit::analysis::variance::{Measured, TorusIntegrand, predicted_variance, shifted_error};
use qmckit::blue_noise::{GaussianBlueNoise, PoissonDisk};
use qmckit::catalog::{
    self, Family, IntegrandEntry, IntegrandKind, Params, RandomizerEntry, RandomizerKind,
    SamplerEntry, SamplerKind, Size,
};

use super::budget::BudgetArgs;
use super::progress::with_spinner;
use super::{Failure, names};

/// Text shown after the options of `qmckit variance --help`.
pub const AFTER_HELP: &str = "\
Each of the S sets of N 2D points is shifted on the unit torus by its own uniform random
offset, and the integrand (the disk of radius R, or the periodized Gaussian of standard
deviation sigma, centred at (1/2, 1/2)) is averaged over it. Output, one 'key value' line
each:
  sampler, n, integrand, parameter (R or sigma), sets, k_max
  n_mean      the mean number of points a set (N, except for poisson: about N)
  predicted   the mean over the S sets of (1/N_s) sum_{k != 0} |c_k|^2 P_s(k), P_s the
              periodogram of set s on [-K, K]^2, the rest of Parseval's sum at P = 1
              (Pilleboue et al. 2015; = (1/N) sum |c_k|^2 E P(k) at a fixed N)
  tail        the part of 'predicted' from outside [-K, K]^2
  measured    mean of the S squared errors (the exact integral is known)
  std_error   its standard error
  ratio       measured / predicted
  white       the white-noise variance (||f||^2 - c_0^2) / n_mean
Deterministic samplers (halton, sobol) have one set, shifted S times. Default K is
2 ceil(sqrt(N)) (at least 16); a given --k-max (1 to 2048) is used as given. Values with 17 significant digits. Refused when the S
periodograms are estimated to exceed --max-seconds. Errors: one line, exit code 2.";

/// What `variance` draws: a catalog sampler with a randomizer (`owen-sobol` is the
/// shorthand for `sobol --scramble owen`).
#[derive(Clone, Copy, Debug)]
pub struct VarianceSampler {
    sampler: &'static SamplerEntry,
    shorthand: Option<&'static RandomizerEntry>,
}

/// Parses a catalog sampler name, or the shorthand `owen-sobol`.
#[derive(Clone)]
struct SamplerParser;

impl TypedValueParser for SamplerParser {
    type Value = VarianceSampler;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<VarianceSampler, clap::Error> {
        if catalog::same_name(&value.to_string_lossy(), "owen-sobol") {
            return Ok(VarianceSampler {
                sampler: catalog::sampler("sobol")
                    .map_err(|_| clap::Error::new(clap::error::ErrorKind::InvalidValue))?,
                shorthand: catalog::randomizer("owen").ok(),
            });
        }
        names::samplers()
            .parse_ref(cmd, arg, value)
            .map(|sampler| VarianceSampler {
                sampler,
                shorthand: None,
            })
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        let shorthand = PossibleValue::new("owen-sobol").help("shorthand: sobol --scramble owen");
        let listed: Vec<PossibleValue> = names::samplers()
            .possible_values()
            .into_iter()
            .flatten()
            .chain([shorthand])
            .collect();
        Some(Box::new(listed.into_iter()))
    }
}

/// The integrands `variance` takes: the torus ones.
fn on_torus(e: &IntegrandEntry) -> bool {
    matches!(
        e.kind,
        IntegrandKind::TorusDisk | IntegrandKind::TorusGaussian
    )
}

/// Arguments of `qmckit variance`.
#[derive(Args, Debug)]
pub struct VarianceArgs {
    /// Which sampler (a catalog name or alias, any case; owen-sobol is sobol --scramble
    /// owen).
    #[arg(value_parser = SamplerParser)]
    sampler: VarianceSampler,
    /// Randomization, as for `qmckit points` (the torus shift comes after it).
    #[arg(long, value_parser = names::randomizers())]
    scramble: Option<&'static RandomizerEntry>,
    /// Points per set.
    #[arg(short = 'n', value_name = "N")]
    n: u32,
    /// The integrand (a catalog integrand on the torus).
    #[arg(long, default_value = "torus-disk", value_parser = names::integrands().only(
        on_torus,
        "variance integrates the torus integrands: torus-disk, torus-gaussian",
    ))]
    integrand: &'static IntegrandEntry,
    /// Disk radius R, in [1e-50, 0.5].
    #[arg(long, default_value_t = 0.25, value_name = "R")]
    radius: f64,
    /// Gaussian standard deviation, in [1e-50, 0.15].
    #[arg(long, default_value_t = 0.1, value_name = "SIGMA")]
    sigma: f64,
    /// Number of randomized sets.
    #[arg(long, default_value_t = 1000, value_name = "S")]
    sets: u32,
    /// Largest frequency of the mean periodogram, 1 to 2048 [default: 2 ceil(sqrt(N)), at
    /// least 16].
    #[arg(long, value_name = "K")]
    k_max: Option<usize>,
    /// Seed of the randomized samplers and of the shifts.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    #[command(flatten)]
    budget: BudgetArgs,
}

/// Set `s` of the sampler, as 2D points in `[0, 1)` (the blue-noise sets within the
/// command's started `budget`: the caller checked the cost of all of them, the deadline
/// bounds them).
fn points_of(
    which: &Drawn,
    n: u32,
    seed: u64,
    s: u32,
    budget: &qmckit::work::Budget,
) -> Result<Vec<f64>, Failure> {
    let key = qmckit::hash::hash3(seed, s as u64, 0x5e7);
    let set = match which.sampler.kind {
        SamplerKind::Poisson => Some(
            PoissonDisk::with_points(2, u64::from(n))?
                .torus(true)
                .seed(key)
                .generate(budget)?,
        ),
        SamplerKind::GaussianBlueNoise => Some(
            GaussianBlueNoise::new(u64::from(n))?
                .seed(key)
                .generate(budget)?,
        ),
        _ => None,
    };
    if let Some(set) = set {
        return Ok(set.to_f64());
    }
    let kind = which.sampler.kind;
    let side = (n as f64).sqrt().round() as u32;
    let stratified = kind == SamplerKind::Stratified;
    let params = Params {
        dims: (kind.fixed_dims() != Some(1)).then_some(2),
        points: (matches!(kind.size(), Size::Set | Size::Whole) && !stratified)
            .then_some(u64::from(n)),
        strata: stratified.then(|| vec![side, side]),
        seed: key,
        budget: *budget,
        ..Params::default()
    };
    let sampler = catalog::build(which.sampler, which.scramble, &params)?;
    if sampler.dims() != 2 {
        return Err(Failure::usage(format!(
            "{} is {}-dimensional: variance needs 2-dimensional points",
            which.sampler.name,
            sampler.dims()
        )));
    }
    if sampler.len() < u64::from(n) {
        return Err(Failure::usage(format!(
            "-n {n}: {} has {} points",
            which.sampler.name,
            sampler.len()
        )));
    }
    let mut raw: Vec<u32> = qmckit::size::vec_zeroed(2 * n as usize)?;
    sampler.fill(0, &mut raw)?;
    Ok(Points::from_u32(&raw))
}

/// The sampler and randomizer drawn.
struct Drawn {
    sampler: &'static SamplerEntry,
    scramble: &'static RandomizerEntry,
}

/// Runs `qmckit variance`.
pub fn run(args: &VarianceArgs) -> Result<(), Failure> {
    let budget = args.budget.budget()?;
    let n = args.n;
    if n == 0 || args.sets == 0 {
        return Err(Failure::usage("-n and --sets must be at least 1"));
    }
    if n > 1 << 24 {
        return Err(Failure::usage(format!("-n {n}: at most 16777216")));
    }
    let drawn = match (args.sampler.shorthand, args.scramble) {
        (Some(_), Some(_)) => {
            return Err(Failure::usage(
                "--scramble does not apply to owen-sobol (it is sobol --scramble owen)",
            ));
        }
        (Some(r), None) | (None, Some(r)) => Drawn {
            sampler: args.sampler.sampler,
            scramble: r,
        },
        (None, None) => Drawn {
            sampler: args.sampler.sampler,
            scramble: catalog::randomizer("none")?,
        },
    };
    if matches!(
        drawn.sampler.kind,
        SamplerKind::Poisson | SamplerKind::GaussianBlueNoise
    ) && drawn.scramble.kind != RandomizerKind::None
    {
        return Err(Failure::usage(format!(
            "--scramble does not apply to {} here (its sets are drawn on the torus, each \
             shifted at random already)",
            drawn.sampler.name
        )));
    }
    if drawn.sampler.kind == SamplerKind::Stratified {
        let side = (n as f64).sqrt().round() as u32;
        if side * side != n {
            return Err(Failure::usage(format!(
                "-n {n}: stratified (jittered) needs a square number of points"
            )));
        }
    }
    let f = match args.integrand.kind {
        IntegrandKind::TorusGaussian => TorusIntegrand::gaussian(args.sigma),
        _ => TorusIntegrand::disk(args.radius),
    }
    .map_err(|e| Failure::usage(e.to_string()))?;
    // The default is 2 ceil(sqrt N), at least 16; a given --k-max is used as given.
    let k_max = match args.k_max {
        Some(0) => return Err(Failure::usage("--k-max 0: must be at least 1")),
        Some(k) => k,
        None => (2 * (n as f64).sqrt().ceil() as usize).max(16),
    };
    if k_max > SPECTRUM_MAX_K {
        return Err(Failure::usage(format!(
            "--k-max {k_max}: at most {SPECTRUM_MAX_K}"
        )));
    }
    // Deterministic constructions, unrandomized, have one set, shifted S times.
    let random = drawn.scramble.kind != RandomizerKind::None
        || matches!(
            drawn.sampler.kind.family(None),
            Family::Random | Family::BlueNoise
        );
    let spectra = if random { args.sets } else { 1 };
    let method = choose_method(n as usize, k_max, DEFAULT_TOLERANCE);
    let one = estimated_cost(n as usize, k_max, method, DEFAULT_TOLERANCE).seconds();
    let evals = args.sets as f64 * n as f64 * 5e-9;
    let construct = match drawn.sampler.kind {
        SamplerKind::Poisson => PoissonDisk::with_points(2, u64::from(n))
            .and_then(|p| p.torus(true).cost())
            .map_err(|e| Failure::usage(e.to_string()))?
            .seconds(),
        SamplerKind::GaussianBlueNoise => GaussianBlueNoise::new(u64::from(n))
            .map_err(|e| Failure::usage(e.to_string()))?
            .cost()
            .seconds(),
        _ => 0.0,
    };
    let total = (one + construct) * spectra as f64 + evals;
    if total > budget.max_seconds() {
        return Err(Failure::usage(format!(
            "{spectra} sets, their periodograms and {} evaluations: estimated {total:.3} s, more than \
             --max-seconds {} (raise it to run them)",
            args.sets as u64 * n as u64,
            args.budget.max_seconds
        )));
    }
    // The shift variance of one set is exactly (1/N_s) sum |c_k|^2 P_s(k), linear in P_s:
    // the mean of the per-set predictions is the prediction of the mean periodogram, and it
    // stays exact when the sets differ in size (Poisson disk by count).
    if !random {
        // Refuses a construction that cannot make the set before anything is timed.
        points_of(&drawn, n, args.seed, 0, &budget)?;
    }
    let (predicted, counts, errors) = with_spinner("variance", || -> Result<_, Failure> {
        let (mut variance, mut tail, mut counts) = (0.0, 0.0, 0usize);
        let mut errors: Vec<f64> = qmckit::size::vec_with_capacity(args.sets as usize)?;
        let mut pts = Vec::new();
        let mut pacer = budget.pacer("the integration variance");
        for s in 0..args.sets {
            if random || s == 0 {
                budget.check_deadline("the integration variance")?;
                pts = points_of(&drawn, n, args.seed, s, &budget)?;
                let p = Points::new(&pts, 2)?;
                let one = predicted_variance(
                    &periodogram_2d(p, k_max, method, DEFAULT_TOLERANCE, &budget)?,
                    &f,
                );
                variance += one.variance;
                tail += one.tail;
                counts += pts.len() / 2;
            }
            let shift = [0, 1]
                .map(|d| qmckit::bits::to_f64(qmckit::hash::uniform(args.seed ^ 0x5417, s, d)));
            errors.push(shifted_error(Points::new(&pts, 2)?, &f, shift)?);
            pacer.tick_n(n)?;
        }
        let inv = 1.0 / f64::from(spectra);
        Ok(((variance * inv, tail * inv), counts as f64 * inv, errors))
    })?;
    let measured = Measured::from_errors(&errors)?;
    let ratio = measured.variance / predicted.0;
    if !ratio.is_finite() {
        return Err(Failure::usage(
            "the predicted variance is zero or not representable: no ratio (take a larger \
             --radius or --sigma)",
        ));
    }
    let mut out = BufWriter::new(std::io::stdout().lock());
    let (name, parameter) = match f {
        TorusIntegrand::Disk { radius } => ("torus-disk", radius),
        TorusIntegrand::Gaussian { sigma } => ("torus-gaussian", sigma),
    };
    writeln!(out, "sampler {}", drawn.sampler.name)?;
    writeln!(out, "scramble {}", drawn.scramble.name)?;
    writeln!(out, "n {n}")?;
    writeln!(out, "integrand {name}")?;
    writeln!(out, "parameter {parameter}")?;
    writeln!(out, "sets {}", args.sets)?;
    writeln!(out, "k_max {k_max}")?;
    writeln!(out, "n_mean {counts}")?;
    writeln!(out, "predicted {:.16e}", predicted.0)?;
    writeln!(out, "tail {:.16e}", predicted.1)?;
    writeln!(out, "measured {:.16e}", measured.variance)?;
    writeln!(out, "std_error {:.16e}", measured.std_error)?;
    writeln!(out, "ratio {ratio:.16e}")?;
    writeln!(out, "white {:.16e}", f.white_noise_variance() / counts)?;
    out.flush()?;
    Ok(())
}
