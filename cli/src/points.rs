//! `qmckit points SAMPLER -n N [-d D] ...`: write points of any sampler.

use std::io::BufWriter;

use clap::{Args, ValueEnum};
use qmckit::Sampler;
use qmckit::catalog::{
    self, BlueNoiseOptions, CatalogError, GeneratingVector, Params, RandomizerEntry,
    RandomizerKind, SamplerEntry, SamplerKind, Size,
};
use qmckit::digital::sobol::Order;
use qmckit::lattice::KUO_33002;

use super::Failure;
use super::blue_noise::{self, BlueNoiseArgs};
use super::names;
use super::output::{Format, PointWriter};
use super::warp::{Warp, WarpArgs};

/// Text shown after the options of `qmckit points --help`.
pub const AFTER_HELP: &str = "\
Options that apply (any other is an error that names it):
  --seed      independent, latin, pmj02, stratified (without --centered), and every --scramble
  --base      vdc            --strata, --centered   stratified
  --total     the finite sets: stratified, latin, hammersley, lp
  --order     sobol (gray: SciPy's order)
  --vector, --korobov   lattice (--total N: the N-point rule in linear order)
  --scramble  shift, shift-tent: lattice, kronecker; owen, perm, faure: faure (base b)
  --scramble  xor, fast-owen, fast-owen-lk, lms, shuffle-owen: base-2 digital
              constructions (sobol, lp, vdc base 2); owen: those and halton, hammersley,
              vdc (in base b); rotate: any; perm, faure: halton, hammersley, vdc

Limits: indices start..start+n-1 must lie in the construction (2^32 for the sequences;
--total for the sets); a point holds at most 2^27 coordinates (1 GiB at 8 bytes each);
halton at most 1024 dimensions, sobol as many as compiled in (21201 in the command).
Output is written in batches of about 1 MiB, so memory stays bounded for any N.

Formats: decimal (default), one point a line, the coordinates x / 2^32 as the shortest
decimals that parse back to the exact value (every one is an f64), separated by spaces;
u32, the integers x * 2^32 (the numerators) separated by spaces; csv, the decimals
separated by commas; npy, float64 of shape (N, D). 'qmckit discrepancy' and 'qmckit
spectrum' read all four back with default options.

Blue-noise sets (built whole; -n is the set size; --start, --total, --scramble, --warp do
not apply):
  poisson              Bridson Poisson disk: --radius R or -n N (about N points), -d D
                       (1 to 8), --torus, --maximal (no further disk fits), --candidates K
  best-candidate       Mitchell best candidate on the torus, 2D: -n N, --candidates M
  gaussian-blue-noise  Ahmed-Ren-Wonka Gaussian blue noise on the torus, 2D: -n N,
                       --iterations I
  lloyd, ccvt          Lloyd relaxation / capacity-constrained Voronoi (dense sample of 64
                       points a site), any -d to 64: -n N, --iterations I, --torus
  sot                  sliced optimal transport in the cube, any -d to 64: -n N,
                       --iterations I, --projective (every other direction in a 1D or
                       2D axis subspace: the projections are spread too)
  projective-blue-noise  dart throwing with radii in the full space and in every 1D and
                       2D axis projection, on the torus, -d 2 to 8: -n N
  forced-random        forced random sampling, 2D, constant density: the N cells of
                       lowest rank of a 128 x 128 void-and-cluster matrix: -n N
  bnot                 blue noise through optimal transport (equal-area power cells),
                       2D: -n N, --iterations I (default 50), --torus
  ldbn                 low-discrepancy blue noise, 2D: -n N a power of four (4 to 2^26): an
                       Owen-scrambled Sobol' net rearranged by a look-up table, still a net
  penrose              Penrose-tiling sampling (Ostromoukhov et al. 2004), 2D: -n N (the
                       N points of lowest rank), --seed (rotation and offset)
  aa-patterns          AA patterns (after Ahmed et al. 2015), 2D: -n N a perfect square, one
                       point a grid cell displaced by a table indexed by an automaton's label
  art                  adaptive regular tiles (after Ahmed et al. 2017), 2D: -n N (the N
                       samples of lowest rank of a 4 x 4 subdivision), --seed (a torus shift)
  step-blue-noise, single-peak-blue-noise
                       spectrum-controlled blue noise on the torus (Heck et al. 2013),
                       -d 1 to 6: -n N, --iterations I
  kde-blue-noise       kernel-density blue noise on the torus (Fattal 2011), -d 1 to 5:
                       -n N, --iterations I (sweeps a level), --temperature T
  --max-seconds S refuses, before starting, a set whose estimated time exceeds S
  (also pmj02bn, lloyd, ccvt, sot, projective-blue-noise, forced-random, bnot, ldbn,
  penrose, aa-patterns, art, step-blue-noise, single-peak-blue-noise, kde-blue-noise).

Other sets: cmj (Kensler's correlated multi-jitter, --total N, -d any, --seed);
cascaded-sobol (Paulin et al.'s cascaded Sobol', --total N a power of two, -d to 65536,
--seed: every consecutive pair of dimensions a (0, m, 2)-net, Owen-scrambled);
hex (hexagonal grid on the torus, 2D, --total N even; --scramble shift for a random
shift).";

/// A catalog sampler (`qmckit::catalog::SAMPLERS`).
pub type SamplerName = &'static SamplerEntry;

/// A catalog randomizer (`qmckit::catalog::RANDOMIZERS`).
pub type ScrambleName = &'static RandomizerEntry;

/// Point order (`--order`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum OrderName {
    /// Line k is point start+k.
    Natural,
    /// Gray-code order (Sobol' only): SciPy's qmc.Sobol order.
    Gray,
}

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

/// What [`build`] needs to construct a sampler: shared by `points` and `tvalue`.
#[derive(Clone, Debug)]
pub struct Spec {
    /// Which construction.
    pub sampler: SamplerName,
    /// Number of points asked for (the default set size of finite sets).
    pub n: u64,
    /// Dimensions [default: 1 for vdc, 2 otherwise].
    pub d: Option<usize>,
    /// Size of finite sets [default: n].
    pub total: Option<u64>,
    /// Seed of randomized samplers and scrambles.
    pub seed: u64,
    /// Randomization.
    pub scramble: ScrambleName,
    /// Point order.
    pub order: OrderName,
    /// Base of the van der Corput and Faure sequences [default: 2, faure the smallest prime
    /// at least d].
    pub base: Option<u32>,
    /// Strata per dimension for stratified (`8x4`).
    pub strata: Option<String>,
    /// Stratified: cell centers instead of jitter.
    pub centered: bool,
    /// Lattice: a generating-vector file.
    pub vector: Option<std::path::PathBuf>,
    /// Lattice: a Korobov parameter.
    pub korobov: Option<u64>,
    /// The time budget of sets built whole at super-linear cost (pmj02bn, lloyd, ccvt, bnot,
    /// sot).
    pub budget: qmckit::work::Budget,
    /// The options of the relaxed sets (lloyd, ccvt, sot, bnot: `--iterations`, `--torus`).
    pub blue_noise: BlueNoiseOptions,
}

impl Spec {
    /// The spec of an unordered, unwarped base-2 set of `n` points of `d` dimensions.
    pub fn base2(
        sampler: SamplerName,
        n: u64,
        d: usize,
        scramble: ScrambleName,
        seed: u64,
    ) -> Self {
        Spec {
            sampler,
            n,
            d: Some(d),
            total: None,
            seed,
            scramble,
            order: OrderName::Natural,
            base: None,
            strata: None,
            centered: false,
            vector: None,
            korobov: None,
            budget: qmckit::work::Budget::DEFAULT,
            blue_noise: BlueNoiseOptions::default(),
        }
    }
}

impl PointsArgs {
    /// The sampler part of the arguments, after refusing every option that does not apply
    /// to the chosen sampler and randomization.
    fn spec(&self, n: u64) -> Result<Spec, Failure> {
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
            seed: self.seed.unwrap_or(0),
            scramble: self.scramble,
            order: self.order.unwrap_or(OrderName::Natural),
            base: self.base,
            strata: self.strata.clone(),
            centered: self.centered,
            vector: self.vector.clone(),
            korobov: self.korobov,
            budget: self.blue.budget()?,
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

/// `true` for the relaxed sets built whole through the catalog (lloyd, ccvt, sot,
/// projective-blue-noise, forced-random, bnot, step-blue-noise, single-peak-blue-noise,
/// kde-blue-noise), which take `--max-seconds` and (lloyd,
/// ccvt, sot, bnot) `--iterations`, (lloyd, ccvt, bnot) `--torus`, (sot) `--projective`, (kde-blue-noise) `--temperature`; the catalog refuses the
/// other blue-noise options for them.
pub fn is_relaxed(sampler: SamplerName) -> bool {
    matches!(
        sampler.kind,
        SamplerKind::Lloyd
            | SamplerKind::Ccvt
            | SamplerKind::Sot
            | SamplerKind::ProjectiveBlueNoise
            | SamplerKind::ForcedRandom
            | SamplerKind::Bnot
            | SamplerKind::StepBlueNoise
            | SamplerKind::SinglePeakBlueNoise
            | SamplerKind::KdeBlueNoise
    )
}

/// The blue-noise set `sampler` names, if any.
pub fn blue_noise_kind(sampler: SamplerName) -> Option<blue_noise::Kind> {
    match sampler.kind {
        SamplerKind::Poisson => Some(blue_noise::Kind::Poisson),
        SamplerKind::BestCandidate => Some(blue_noise::Kind::BestCandidate),
        SamplerKind::GaussianBlueNoise => Some(blue_noise::Kind::Gaussian),
        _ => None,
    }
}

/// `true` for the finite point sets (sized by `--total`).
pub fn is_finite_set(sampler: SamplerName) -> bool {
    sampler.kind.size() == Size::Set
}

/// `-d` as given, else the construction's default: 1 for vdc, 2 otherwise.
pub fn dims_of(sampler: SamplerName, d: Option<usize>) -> usize {
    d.unwrap_or(sampler.kind.default_dims())
}

/// Bytes of a generating-vector file read (9125 dimensions take 60 KiB).
const MAX_VECTOR_FILE: u64 = 64 << 20;

/// The generating vector in `path`, read through the bounded reader: at least `d`
/// components.
fn read_vector(path: &std::path::Path, d: usize) -> Result<GeneratingVector, Failure> {
    let shown = path.display();
    let limits = super::input::Limits {
        bytes: MAX_VECTOR_FILE,
        line: 1 << 16,
        option: "--vector",
        records: u64::MAX,
    };
    let file = path.to_string_lossy();
    let (_, bytes) = super::input::read_bounded(Some(&file), limits)?;
    let text = String::from_utf8(bytes)
        .map_err(|e| Failure::usage(format!("--vector {shown}: not UTF-8 text ({e})")))?;
    GeneratingVector::parse(&text, d).map_err(|e| match e {
        CatalogError::Parameter {
            param: "vector",
            got: Some(read),
            ..
        } => Failure::usage(format!("{shown} has {read} components, -d asks for {d}")),
        other => Failure::usage(format!("{shown}: {other}")),
    })
}

/// The catalog's parameters for `spec`: `points` is `--total` (or `-n`) for the finite
/// sets and the sets built whole (stratified with `--strata`: only an explicit
/// `--total`), an explicit `--total` for lattice, nothing for the sequences.
fn params(spec: &Spec) -> Result<Params, Failure> {
    let kind = spec.sampler.kind;
    let d = dims_of(spec.sampler, spec.d);
    let explicit_strata = spec.strata.as_deref().map(parse_strata).transpose()?;
    let points = match kind.size() {
        Size::Sequence => None,
        Size::Rule => spec.total,
        Size::Set if kind == SamplerKind::Stratified && explicit_strata.is_some() => spec.total,
        Size::Set | Size::Whole => Some(spec.total.unwrap_or(spec.n)),
    };
    let strata = match (kind, explicit_strata) {
        (SamplerKind::Stratified, Some(strata)) => {
            if spec.d.is_some() && strata.len() != d {
                return Err(Failure::usage(format!(
                    "--strata {} has {} dimensions but -d is {d}",
                    spec.strata.as_deref().unwrap_or(""),
                    strata.len()
                )));
            }
            let cells = strata
                .iter()
                .try_fold(1u64, |n, &k| n.checked_mul(u64::from(k)));
            if let (Some(total), Some(cells)) = (spec.total, cells)
                && total != cells
            {
                return Err(Failure::usage(format!(
                    "--total {total} does not match the {cells} cells of --strata"
                )));
            }
            Some(strata)
        }
        (SamplerKind::Stratified, None) => {
            let n = points.unwrap_or(spec.n);
            let k = root(n, d)?;
            let mut strata = qmckit::size::vec_zeroed::<u32>(d)?;
            strata.fill(k);
            Some(strata)
        }
        (_, other) => other,
    };
    if kind == SamplerKind::Lattice {
        if spec.korobov.is_some() && spec.vector.is_some() {
            return Err(Failure::usage("--korobov and --vector exclude each other"));
        }
        if spec.korobov.is_some() && spec.total.is_none() {
            return Err(Failure::usage(
                "--korobov needs the number of points of the rule: pass --total N",
            ));
        }
        if spec.vector.is_none() && d > KUO_33002.len() {
            return Err(Failure::usage(format!(
                "lattice: the built-in vector has {} dimensions, -d is {d} (use --vector FILE)",
                KUO_33002.len()
            )));
        }
    }
    let vector = match &spec.vector {
        Some(path) if kind == SamplerKind::Lattice => Some(read_vector(path, d)?),
        _ => None,
    };
    if d == 0 {
        return Err(Failure::usage(
            "-d 0: at least 1 dimension is needed (the number of dimensions per point)",
        ));
    }
    // A stratified set with its strata computed from the size takes no separate size.
    let points = points.filter(|_| kind != SamplerKind::Stratified || spec.strata.is_some());
    Ok(Params {
        dims: spec.d,
        points,
        base: spec.base,
        seed: spec.seed,
        order: match spec.order {
            OrderName::Natural => Order::Natural,
            OrderName::Gray => Order::Gray,
        },
        strata: strata.filter(|_| kind == SamplerKind::Stratified),
        centered: spec.centered,
        korobov: spec.korobov,
        vector,
        budget: spec.budget,
        blue_noise: spec.blue_noise,
    })
}

/// Builds the sampler `spec` names, randomized as `--scramble` asks: the catalog's
/// builder (`qmckit::catalog::build`), whose rule says which randomizer applies to which
/// construction; its messages name the command's flags.
pub fn build(spec: &Spec) -> Result<Box<dyn Sampler>, Failure> {
    if spec.order == OrderName::Gray && spec.sampler.kind != SamplerKind::Sobol {
        return Err(Failure::usage(
            "--order gray applies to sobol only (other samplers have natural order)",
        ));
    }
    let params = params(spec)?;
    Ok(catalog::build(spec.sampler, spec.scramble, &params)?)
}

/// `k` with `k^d == n`, or a usage error.
fn root(n: u64, d: usize) -> Result<u32, Failure> {
    let guess = (n as f64).powf(1.0 / d as f64).round() as u64;
    let power = u32::try_from(d).unwrap_or(u32::MAX);
    for k in guess.saturating_sub(1)..=guess.saturating_add(1) {
        if k > 0 && k.checked_pow(power) == Some(n) {
            return u32::try_from(k).map_err(|_| {
                Failure::usage(format!(
                    "stratified: {n} points need {k} strata per axis, at most {} allowed",
                    u32::MAX
                ))
            });
        }
    }
    Err(Failure::usage(format!(
        "stratified: {n} points is not k^{d} for a whole number k; pass --strata (e.g. 8x4)"
    )))
}

/// Parses `8x4x2` into strata counts.
fn parse_strata(text: &str) -> Result<Vec<u32>, Failure> {
    text.split(['x', 'X'])
        .map(|part| {
            part.trim().parse::<u32>().map_err(|_| {
                Failure::usage(format!(
                    "--strata {text:?}: {part:?} is not a count (expected e.g. 8x4)"
                ))
            })
        })
        .collect()
}

/// Runs `qmckit points`.
pub fn run(args: &PointsArgs) -> Result<(), Failure> {
    if let Some(kind) = blue_noise_kind(args.sampler) {
        return args.run_blue_noise(kind);
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
    let spec = args.spec(n)?;
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
    let stdout = std::io::stdout().lock();
    let mut writer = PointWriter::new(BufWriter::new(stdout), args.format, n, width)?;
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
    fn run_blue_noise(&self, kind: blue_noise::Kind) -> Result<(), Failure> {
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
        let budget = self.blue.budget()?;
        let set = blue_noise::build(
            kind,
            &self.blue,
            self.n,
            self.d,
            self.seed.unwrap_or(0),
            budget,
        )?;
        blue_noise::write(&set, self.format)
    }
}

/// The first `spec.n` points of the sampler `spec` names, as 0.32 fractions (row-major),
/// with their dimension.
pub fn samples_u32(spec: &Spec) -> Result<(Vec<u32>, usize), Failure> {
    let sampler = build(spec)?;
    let dims = sampler.dims();
    let mut buf = qmckit::size::vec_zeroed(qmckit::size::coordinates(spec.n, dims)?)?;
    sampler.fill(0, &mut buf)?;
    Ok((buf, dims))
}
