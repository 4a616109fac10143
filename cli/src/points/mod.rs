//! `qmckit points SAMPLER -n N [-d D] ...`: write points of any sampler, one set or
//! `--sets K` of them.

use std::io::{BufWriter, Write};

use clap::Args;
use qmckit::Sampler;
use qmckit::catalog::{BlueNoiseOptions, RandomizerKind, SamplerKind};
use qmckit::work::Budget;

use super::Failure;
use super::blue_noise::{self, BlueNoiseArgs};
use super::names;
use super::output::{Format, PointWriter};
use super::warp::{Warp, WarpArgs};

mod help;
mod spec;

pub use help::AFTER_HELP;
pub use spec::{
    OrderName, SamplerName, ScrambleName, Spec, blue_noise_kind, build, dims_of, is_finite_set,
    is_relaxed, samples_u32,
};

/// Arguments of `qmckit points`.
#[derive(Args, Debug)]
pub struct PointsArgs {
    /// Which construction (a catalog name or alias, any case).
    #[arg(value_parser = names::samplers())]
    sampler: SamplerName,
    /// Number of points to write (poisson: about N points, or --radius).
    #[arg(short = 'n', value_name = "N")]
    n: Option<u64>,
    /// Dimensions per point [default: 1 for vdc, 2 otherwise].
    #[arg(short = 'd', value_name = "D")]
    d: Option<usize>,
    /// Index of the first point written [default: 0].
    #[arg(long, value_name = "I")]
    start: Option<u64>,
    /// Size of the point set for finite sets (stratified, latin, hammersley, lp) [default: n].
    /// Points start..start+n-1 of it are written.
    #[arg(long)]
    total: Option<u64>,
    /// Seed of the randomized samplers (independent, stratified, latin) and of --scramble
    /// [default: 0].
    #[arg(long)]
    seed: Option<u64>,
    /// Write K sets, with the seeds S, S + 1, ..., S + K - 1 (S from --seed), a line '#'
    /// between two sets (the separator 'qmckit discrepancy' and 'qmckit spectrum' read):
    /// randomized samplers only, text formats only; --max-seconds S gives each set S / K
    /// [default: 1].
    #[arg(long, value_name = "K")]
    sets: Option<u64>,
    /// Randomization; which kinds apply depends on the sampler (see the list below).
    #[arg(long, value_parser = names::randomizers(), default_value = "none")]
    scramble: ScrambleName,
    /// Point order (sobol only) [default: natural].
    #[arg(long, value_enum)]
    order: Option<OrderName>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Decimal)]
    format: Format,
    /// Base of the van der Corput sequence (vdc only) [default: 2].
    #[arg(long)]
    base: Option<u32>,
    /// Strata per dimension for stratified, e.g. 8x4 (their product is the set size).
    #[arg(long)]
    strata: Option<String>,
    /// Stratified: put each point at its cell's center instead of jittering it.
    #[arg(long)]
    centered: bool,
    /// Lattice: read the generating vector from FILE (LDData 'lattice' format or Kuo's
    /// 'j z_j' rows).
    #[arg(long, value_name = "FILE")]
    vector: Option<std::path::PathBuf>,
    /// Lattice: the Korobov vector (1, a, a^2, ...) mod N, with N from --total.
    #[arg(long, value_name = "A")]
    korobov: Option<u64>,
    #[command(flatten)]
    warp: WarpArgs,
    #[command(flatten)]
    blue: BlueNoiseArgs,
}

/// Bytes of coordinates generated per batch (bounded memory for any n and d).
const BATCH_BYTES: usize = 1 << 20;

impl PointsArgs {
    /// The sampler part of the arguments, after refusing every option that does not apply
    /// to the chosen sampler and randomization.
    fn spec(&self, n: u64, seed: u64, budget: Budget) -> Result<Spec, Failure> {
        use SamplerKind as S;
        let sampler = self.sampler;
        let name = sampler.name;
        let refuse = |option: &str, why: &str| {
            Err(Failure::usage(format!(
                "{option} does not apply to {name}{why}"
            )))
        };
        let kind = sampler.kind;
        let randomized = matches!(
            kind,
            S::Independent
                | S::Latin
                | S::Pmj02
                | S::Pmj02bn
                | S::Cmj
                | S::CascadedSobol
                | S::Ldbn
                | S::Penrose
                | S::AaPatterns
                | S::Art
        ) || is_relaxed(sampler)
            || blue_noise_kind(sampler).is_some()
            || (kind == S::Stratified && !self.centered)
            || self.scramble.kind != RandomizerKind::None;
        if self.sets.is_some_and(|k| k > 1) && !randomized {
            return refuse(
                "--sets",
                " (it is deterministic: every set would be the same; randomize it with --scramble)",
            );
        }
        if self.seed.is_some() && !randomized {
            return refuse(
                "--seed",
                if kind == S::Stratified {
                    " with --centered (nothing is random)"
                } else {
                    " without --scramble (it is deterministic)"
                },
            );
        }
        if self.base.is_some() && !matches!(kind, S::Vdc | S::Faure) {
            return refuse("--base", " (only vdc and faure take a base)");
        }
        if (self.vector.is_some() || self.korobov.is_some()) && kind != S::Lattice {
            return refuse(
                "--vector/--korobov",
                " (only lattice has a generating vector)",
            );
        }
        if self.total.is_some() && !is_finite_set(sampler) && kind != S::Lattice {
            return refuse(
                "--total",
                " (a sequence; only stratified, latin, hammersley and lp are sets)",
            );
        }
        if self.strata.is_some() && kind != S::Stratified {
            return refuse("--strata", " (only stratified has strata)");
        }
        if self.centered && kind != S::Stratified {
            return refuse("--centered", " (only stratified has cells)");
        }
        if self.order.is_some() && kind != S::Sobol {
            return refuse("--order", " (only sobol has a Gray-code order)");
        }
        Ok(Spec {
            sampler,
            n,
            d: self.d,
            total: self.total,
            seed,
            scramble: self.scramble,
            order: self.order.unwrap_or(OrderName::Natural),
            base: self.base,
            strata: self.strata.clone(),
            centered: self.centered,
            vector: self.vector.clone(),
            korobov: self.korobov,
            budget,
            blue_noise: if is_relaxed(sampler) {
                BlueNoiseOptions {
                    radius: self.blue.radius,
                    torus: self.blue.torus,
                    maximal: self.blue.maximal,
                    candidates: self.blue.candidates,
                    iterations: self.blue.iterations,
                    projective: self.blue.projective,
                    temperature: self.blue.temperature,
                }
            } else {
                BlueNoiseOptions::default()
            },
        })
    }
}

/// Runs `qmckit points`: `--sets K` sets (default 1) to standard output, `#` between them.
pub fn run(args: &PointsArgs) -> Result<(), Failure> {
    let sets = args.sets.unwrap_or(1);
    if sets == 0 {
        return Err(Failure::usage("--sets must be at least 1"));
    }
    if sets > 1 && args.format == Format::Npy {
        return Err(Failure::usage(
            "--sets: an npy file holds one array; use --format decimal, csv or u32",
        ));
    }
    let first = args.seed.unwrap_or(0);
    if first.checked_add(sets - 1).is_none() {
        return Err(Failure::usage(format!(
            "--seed {first} --sets {sets}: the last seed would pass 2^64 - 1"
        )));
    }
    let budget = args.blue.budget_per_set(sets)?;
    let mut out = BufWriter::new(std::io::stdout().lock());
    for k in 0..sets {
        if k > 0 {
            out.write_all(b"#\n")?;
        }
        run_set(args, first + k, budget.started(), &mut out)?;
    }
    out.flush()?;
    Ok(())
}

/// Writes the one set of seed `seed` to `out`, within `budget`.
fn run_set(
    args: &PointsArgs,
    seed: u64,
    budget: Budget,
    out: &mut impl Write,
) -> Result<(), Failure> {
    if let Some(kind) = blue_noise_kind(args.sampler) {
        return args.run_blue_noise(kind, seed, budget, out);
    }
    let budgeted = matches!(
        args.sampler.kind,
        SamplerKind::Pmj02bn
            | SamplerKind::Ldbn
            | SamplerKind::Penrose
            | SamplerKind::AaPatterns
            | SamplerKind::Art
    );
    if let Some(option) = args.blue.first_given(budgeted)
        && !is_relaxed(args.sampler)
    {
        // The samplers that take the option, from the catalog: every set built whole takes
        // the budget; the blue-noise options go to the blue-noise sets (the relaxed ones
        // take `--iterations` and `--torus`, and the catalog judges the rest).
        let to: Vec<&str> = qmckit::catalog::SAMPLERS
            .iter()
            .filter(|e| {
                let whole = e.kind.size() == qmckit::catalog::Size::Whole;
                match option {
                    "--max-seconds" => whole,
                    "--iterations" | "--torus" => blue_noise_kind(e).is_some() || is_relaxed(e),
                    "--projective" => e.kind == SamplerKind::Sot,
                    "--temperature" => e.kind == SamplerKind::KdeBlueNoise,
                    _ => blue_noise_kind(e).is_some(),
                }
            })
            .map(|e| e.name)
            .collect();
        return Err(Failure::usage(format!(
            "{option} does not apply to {} (only to {})",
            args.sampler.name,
            to.join(", ")
        )));
    }
    let n = args
        .n
        .ok_or_else(|| Failure::usage("-n N (the number of points) is needed"))?;
    if n == 0 {
        return Err(Failure::usage("-n must be at least 1"));
    }
    // One row of coordinates must fit the allocation limit: refused here, before any
    // construction sizes a table by -d.
    let max_dims = qmckit::size::MAX_ALLOC_BYTES / 8;
    if let Some(d) = args.d.filter(|&d| d as u64 > max_dims) {
        return Err(Failure::usage(format!(
            "-d {d}: a point of {d} coordinates is too large: at most {max_dims}"
        )));
    }
    let spec = args.spec(n, seed, budget)?;
    args.warp.check_options()?;
    let sampler = build(&spec)?;
    let dims = sampler.dims();
    let start = args.start.unwrap_or(0);
    let end = qmckit::size::end(start, n, sampler.len()).map_err(|e| match e {
        qmckit::Error::IndexOutOfRange { index, len } => Failure::usage(format!(
            "points {start}..{index} are past the end: this {} has {len} points{}",
            if is_finite_set(args.sampler) {
                "set"
            } else {
                "sequence"
            },
            if is_finite_set(args.sampler) {
                " (see --total)"
            } else {
                ""
            },
        )),
        other => Failure::from(other),
    })?;
    let warp = match args.warp.warp {
        Some(name) => {
            if args.format == Format::U32 {
                return Err(Failure::usage(
                    "warped points are real numbers: use --format decimal, csv or npy",
                ));
            }
            Some(Warp::new(&args.warp, name, dims)?)
        }
        None => None,
    };
    let width = warp.as_ref().map_or(dims, |w| w.width(dims));
    // One row of the widest form must fit the allocation limit.
    if dims.max(width) as u64 > max_dims {
        return Err(Failure::usage(format!(
            "a point of {} coordinates is too large: at most {max_dims}",
            dims.max(width)
        )));
    }
    let batch = qmckit::size::rows_within(BATCH_BYTES, dims.max(width), 8);
    let rows_first = batch.min(usize::try_from(n).unwrap_or(usize::MAX));
    let mut buf: Vec<u32> =
        qmckit::size::vec_zeroed(qmckit::size::coordinates(rows_first as u64, dims)?)?;
    let mut writer = PointWriter::new(out, args.format, n, width)?;
    let mut warped: Vec<f32> = Vec::new();
    let mut u: Vec<f32> = qmckit::size::vec_zeroed(dims)?;
    let mut index = start;
    while index < end {
        let rows = usize::try_from(end - index).map_or(batch, |left| left.min(batch));
        let chunk = &mut buf[..rows * dims];
        // index < end <= 2^32, so it is a u32.
        sampler.fill(index as u32, chunk)?;
        match &warp {
            None => writer.write(chunk, dims)?,
            Some(w) => {
                warped.clear();
                qmckit::size::reserve(&mut warped, qmckit::size::coordinates(rows as u64, width)?)?;
                for row in chunk.chunks_exact(dims) {
                    for (uk, &x) in u.iter_mut().zip(row) {
                        *uk = qmckit::bits::to_f32(x);
                    }
                    warped.extend(w.map(&u)?);
                }
                writer.write_f32(&warped, width)?;
            }
        }
        index += rows as u64;
    }
    writer.finish()
}

impl PointsArgs {
    /// `points poisson|best-candidate|gaussian-blue-noise`: the options that do not apply
    /// are refused, the set is built whole and written.
    fn run_blue_noise(
        &self,
        kind: blue_noise::Kind,
        seed: u64,
        budget: Budget,
        out: &mut impl Write,
    ) -> Result<(), Failure> {
        let name = self.sampler.name;
        for (option, given) in [
            ("--start", self.start.is_some()),
            ("--total", self.total.is_some()),
            ("--order", self.order.is_some()),
            ("--base", self.base.is_some()),
            ("--strata", self.strata.is_some()),
            ("--centered", self.centered),
            ("--scramble", self.scramble.kind != RandomizerKind::None),
            ("--warp", self.warp.warp.is_some()),
        ] {
            if given {
                return Err(Failure::usage(format!(
                    "{option} does not apply to {name} (a blue-noise set built whole)"
                )));
            }
        }
        self.warp.check_options()?;
        if self.n == Some(0) {
            return Err(Failure::usage("-n must be at least 1"));
        }
        let set = blue_noise::build(kind, &self.blue, self.n, self.d, seed, budget)?;
        blue_noise::write(&set, self.format, out)
    }
}
