//! `qmckit integration-test [SAMPLER[+RANDOMIZER]]... [--family F] [-d D] [--min-m A]
//! [--max-m B] [--integrands J] [--seed S]`: the integration benchmark of
//! `qmckit::analysis::integrate::benchmark` for catalog samplers.

use std::io::{BufWriter, Write};

use clap::Args;
use qmckit::analysis::integrate::{BenchmarkCurve, BenchmarkOptions, Family, benchmark};
use qmckit::catalog::{self, Params, RandomizerEntry, SamplerEntry, Size};
use qmckit::sampler::Sampler;
use qmckit::work::Limits;

use super::Failure;
use super::budget::BudgetArgs;
use super::progress::with_progress;

/// Text shown after the options of `qmckit integration-test --help`.
pub const AFTER_HELP: &str = "\
Each SAMPLER is a catalog sampler, optionally '+' a catalog randomizer (sobol+owen,
halton+perm, lattice+shift, independent); default: independent, stratified, halton+perm,
sobol+owen, lattice+shift, pmj02. For N = 2^A .. 2^B (the sizes a construction makes:
stratified takes the k^d among them) and J random integrands of the family, each drawn
from seed S + j, the sampler is built for N points with seed S + j and the integration
error taken; each curve is the root mean square over the J integrands.

Families on [0, 1]^d, each with its exact integral:
  gaussian          anisotropic axis-aligned Gaussians, random centre, widths 0.05..0.5
  gaussian-mixture  mixtures of four of them, random weights
  rotated-gaussian  the same Gaussians with axes rotated by a random angle (a full
                    covariance), 2D; the reference integral by quadrature to 1e-13
  heaviside         1 on one side of a random hyperplane through a random point (d <= 8;
                    the volume exact by inclusion-exclusion in integers)
  blinn-phong       Blinn-Phong lobes max(0, w.h)^n on the sphere, w from a coordinate
                    pair by the area-preserving map, random axis h, n in 1..32 (a product
                    over the pairs; integral 1/(2(n+1)) each)

Theory: independent -0.5 on every family; jittered -1 on smooth integrands and
-(1/2 + 1/(2d)) on a Heaviside (-0.75 in 2D); Owen-scrambled nets about -1.5 on smooth
integrands, -0.75 on a Heaviside in 2D.

Output (what 'qmckit plot' draws as a convergence figure): a '# n rmse' header, then per
sampler a block: '#', '# label: NAME', '# slope: S' (the least-squares slope of log RMSE
against log N), and 'N RMSE' lines (17 significant digits). Refused when the estimated
time exceeds --max-seconds; stopped at its deadline. Errors: one line, exit code 2.";

/// The default samplers: white noise, jittered, and the low-discrepancy families.
const DEFAULT_SAMPLERS: [&str; 6] = [
    "independent",
    "stratified",
    "halton+perm",
    "sobol+owen",
    "lattice+shift",
    "pmj02",
];

/// Arguments of `qmckit integration-test`.
#[derive(Args, Debug)]
pub struct IntegrationTestArgs {
    /// Samplers: SAMPLER or SAMPLER+RANDOMIZER, catalog names (see below).
    samplers: Vec<String>,
    /// The integrand family (the library's `Family::ALL`, by name).
    #[arg(long, default_value = "gaussian", value_parser = clap::builder::PossibleValuesParser::new(Family::ALL.map(Family::name)))]
    family: String,
    /// Dimensions.
    #[arg(short = 'd', default_value_t = 2)]
    d: usize,
    /// Smallest size 2^A.
    #[arg(long, default_value_t = 4, value_name = "A")]
    min_m: u32,
    /// Largest size 2^B (at most 20).
    #[arg(long, default_value_t = 12, value_name = "B")]
    max_m: u32,
    /// Random integrands J (1 to 2^20).
    #[arg(long, default_value_t = 256, value_name = "J")]
    integrands: u32,
    /// Seed of the integrands and the randomizations.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    #[command(flatten)]
    budget: BudgetArgs,
}

/// `SAMPLER[+RANDOMIZER]` as catalog entries.
fn parse(spec: &str) -> Result<(&'static SamplerEntry, &'static RandomizerEntry), Failure> {
    let (s, r) = spec.split_once('+').unwrap_or((spec, "none"));
    Ok((catalog::sampler(s)?, catalog::randomizer(r)?))
}

/// The catalog's sampler for `n` points (when it is a finite set) with `seed`.
fn build(
    s: &'static SamplerEntry,
    r: &'static RandomizerEntry,
    d: usize,
    n: u64,
    seed: u64,
    budget: &qmckit::work::Budget,
) -> Result<Box<dyn Sampler>, catalog::CatalogError> {
    // A set built whole may take the run's whole budget (its deadline bounds the run).
    let params = Params {
        budget: *budget,
        ..Params::dims(d).with_seed(seed)
    };
    let params = if s.kind.size() == Size::Sequence {
        params
    } else {
        params.with_points(n)
    };
    catalog::build(s, r, &params)
}

/// One benchmark run's settings (the command's options).
#[derive(Clone, Copy, Debug)]
pub struct Plan {
    /// The integrand family.
    pub family: Family,
    /// Dimensions.
    pub d: usize,
    /// Sizes `2^min_m ..= 2^max_m` (those the construction makes).
    pub min_m: u32,
    /// See `min_m`.
    pub max_m: u32,
    /// Random integrands.
    pub integrands: u32,
    /// Seed of the integrands and the randomizations.
    pub seed: u64,
}

/// The benchmark of each `SAMPLER[+RANDOMIZER]` spec under `plan`, within `budget` (a
/// progress bar a sampler): `(label, curve)` pairs in the order of `specs`. Used by the
/// command and by the report.
///
/// # Errors
/// Unknown names, a construction that makes none of the sizes (the catalog's reason), the
/// benchmark's errors (budget, deadline).
pub fn curves(
    specs: &[String],
    plan: &Plan,
    budget: &qmckit::work::Budget,
) -> Result<Vec<(String, BenchmarkCurve)>, Failure> {
    let mut chosen = Vec::new();
    for spec in specs {
        let (s, r) = parse(spec)?;
        // The sizes the construction makes, checked once each with seed 0.
        let sizes: Vec<u64> = (plan.min_m..=plan.max_m)
            .map(|m| 1u64 << m)
            .filter(|&n| build(s, r, plan.d, n, 0, budget).is_ok())
            .collect();
        if sizes.is_empty() {
            // The catalog's reason, for the smallest size.
            build(s, r, plan.d, 1 << plan.min_m, 0, budget)?;
        }
        let label = if r.name == "none" {
            s.name.to_string()
        } else {
            format!("{} + {}", s.name, r.name)
        };
        chosen.push((s, r, sizes, label));
    }
    let mut blocks = Vec::new();
    for (s, r, sizes, label) in &chosen {
        let opts = BenchmarkOptions {
            family: plan.family,
            dims: plan.d,
            sizes: sizes.clone(),
            integrands: plan.integrands,
            seed: plan.seed,
        };
        let make = |n: u64, seed: u64| -> qmckit::Result<Box<dyn Sampler>> {
            build(s, r, plan.d, n, seed, budget).map_err(|e| match e {
                catalog::CatalogError::Build(e) => e,
                _ => qmckit::Error::InvalidParameter {
                    what: "a size the construction refused after accepting it",
                },
            })
        };
        let title = format!("{} on {}", plan.family.name(), label);
        let curve = with_progress(&title, |progress| {
            benchmark(&make, &opts, Limits::new(*budget).with_progress(progress))
        })?;
        blocks.push((label.clone(), curve));
    }
    Ok(blocks)
}

/// Runs `qmckit integration-test`.
pub fn run(args: &IntegrationTestArgs) -> Result<(), Failure> {
    if args.max_m > 20 || args.min_m > args.max_m {
        return Err(Failure::usage(format!(
            "--min-m {} --max-m {}: need A <= B <= 20",
            args.min_m, args.max_m
        )));
    }
    let family = Family::from_name(&args.family)
        .ok_or_else(|| Failure::usage(format!("--family {}: unknown", args.family)))?;
    let budget = args.budget.budget()?;
    let specs: Vec<String> = if args.samplers.is_empty() {
        DEFAULT_SAMPLERS.iter().map(|s| s.to_string()).collect()
    } else {
        args.samplers.clone()
    };
    let plan = Plan {
        family,
        d: args.d,
        min_m: args.min_m,
        max_m: args.max_m,
        integrands: args.integrands,
        seed: args.seed,
    };
    let blocks = curves(&specs, &plan, &budget)?;
    let out = std::io::stdout();
    let mut w = BufWriter::new(out.lock());
    writeln!(w, "# n rmse")?;
    writeln!(
        w,
        "# integration-test: family {}, d {}, {} integrands, seed {}",
        plan.family.name(),
        args.d,
        args.integrands,
        args.seed
    )?;
    for (label, curve) in &blocks {
        writeln!(w, "#")?;
        writeln!(w, "# label: {label}")?;
        match curve.slope {
            Some(s) => writeln!(w, "# slope: {s:.3}")?,
            None => writeln!(w, "# slope: -")?,
        }
        for (n, e) in &curve.rmse {
            writeln!(w, "{n} {e:.16e}")?;
        }
    }
    w.flush()?;
    Ok(())
}
