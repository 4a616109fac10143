//! `qmckit points SAMPLER -n N [-d D] ...`: write points of any sampler.

use std::io::BufWriter;

use clap::Args;
use qmckit::digital::sobol::{Order, Sobol};
use qmckit::randomize::digits::DigitScramble;
use qmckit::randomize::shuffle::Shuffled;
use qmckit::randomize::{
    CranleyPatterson, DigitalShift, ExactOwen, FastOwen, Lms, OwenHash, Scrambled,
};
use qmckit::{
    Base2Digital, Halton, Hammersley, Independent, Jitter, LarcherPillichshammer, LatinHypercube,
    Sampler, Stratified, VanDerCorput,
};

use super::Failure;
use super::blue_noise::{self, BlueNoiseArgs};
use super::output::{Format, PointWriter};
pub use super::spec::{OrderName, SamplerName, ScrambleName, Spec, value_name};
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
  --max-seconds S refuses, before starting, a set whose estimated time exceeds S.";

/// Arguments of `qmckit points`.
#[derive(Args, Debug)]
pub struct PointsArgs {
    /// Which construction.
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
    #[arg(long, value_enum, default_value_t = ScrambleName::None)]
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
    fn spec(&self, n: u64) -> Result<Spec, Failure> {
        use SamplerName as S;
        let sampler = self.sampler;
        let name = value_name(&sampler);
        let refuse = |option: &str, why: &str| {
            Err(Failure::usage(format!(
                "{option} does not apply to {name}{why}"
            )))
        };
        let randomized = matches!(sampler, S::Independent | S::Latin | S::Pmj02 | S::Pmj02bn)
            || sampler.blue_noise().is_some()
            || (sampler == S::Stratified && !self.centered)
            || self.scramble != ScrambleName::None;
        if self.seed.is_some() && !randomized {
            return refuse(
                "--seed",
                if sampler == S::Stratified {
                    " with --centered (nothing is random)"
                } else {
                    " without --scramble (it is deterministic)"
                },
            );
        }
        if self.base.is_some() && !matches!(sampler, S::Vdc | S::Faure) {
            return refuse("--base", " (only vdc and faure take a base)");
        }
        if (self.vector.is_some() || self.korobov.is_some()) && sampler != S::Lattice {
            return refuse(
                "--vector/--korobov",
                " (only lattice has a generating vector)",
            );
        }
        if self.total.is_some() && !sampler.is_finite_set() && sampler != S::Lattice {
            return refuse(
                "--total",
                " (a sequence; only stratified, latin, hammersley and lp are sets)",
            );
        }
        if self.strata.is_some() && sampler != S::Stratified {
            return refuse("--strata", " (only stratified has strata)");
        }
        if self.centered && sampler != S::Stratified {
            return refuse("--centered", " (only stratified has cells)");
        }
        if self.order.is_some() && sampler != S::Sobol {
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
            base: self.base.unwrap_or(if sampler == S::Faure { 0 } else { 2 }),
            strata: self.strata.clone(),
            centered: self.centered,
            vector: self.vector.clone(),
            korobov: self.korobov,
            budget: self.blue.budget()?,
        })
    }
}

impl SamplerName {
    /// The blue-noise set this names, if any.
    pub fn blue_noise(self) -> Option<blue_noise::Kind> {
        match self {
            SamplerName::Poisson => Some(blue_noise::Kind::Poisson),
            SamplerName::BestCandidate => Some(blue_noise::Kind::BestCandidate),
            SamplerName::GaussianBlueNoise => Some(blue_noise::Kind::Gaussian),
            _ => None,
        }
    }

    /// `true` for the finite point sets (sized by `--total`).
    pub fn is_finite_set(self) -> bool {
        matches!(
            self,
            SamplerName::Stratified
                | SamplerName::Latin
                | SamplerName::Hammersley
                | SamplerName::Lp
        )
    }
}

/// A construction, classified by the library's types: which randomizations it takes.
enum Built {
    /// A base-2 digital construction ([`Base2Digital`]): every base-2 randomizer applies.
    Digital(Box<dyn Base2Digital>),
    /// Anything else: only the Cranley–Patterson rotation applies (digit scrambles, if
    /// asked, are already part of its radical inverse).
    Other(Box<dyn Sampler>),
}

/// Builds the sampler `args` names, randomized as `--scramble` asks. Which randomizer fits
/// which construction is the library's rule (`Scrambled<S, R>` is a sampler only when
/// `R: Randomizes<S>`); this only maps names to types.
pub fn build(args: &Spec) -> Result<Box<dyn Sampler>, Failure> {
    use ScrambleName as K;
    if matches!(
        args.sampler,
        SamplerName::Lattice | SamplerName::Kronecker | SamplerName::Faure
    ) {
        return super::toolbox::build(args);
    }
    if matches!(args.scramble, K::Shift | K::ShiftTent) {
        return Err(does_not_apply(args));
    }
    let seed = args.seed;
    let takes_digits = args.sampler.takes_digit_scrambles(args.base);
    let digits = match args.scramble {
        K::Perm => Some(DigitScramble::Permutations(seed)),
        K::Faure => Some(DigitScramble::Faure),
        K::Owen if takes_digits => Some(DigitScramble::Owen(seed)),
        _ => None,
    };
    if digits.is_some() && !takes_digits {
        return Err(does_not_apply(args));
    }
    let built = construct(args, digits.unwrap_or_default())?;
    Ok(match (built, args.scramble) {
        (Built::Digital(s), K::None) => Box::new(s),
        (Built::Other(s), _) if digits.is_some() => s,
        (Built::Other(s), K::None) => s,
        (Built::Other(s), K::Rotate) => Box::new(Scrambled::new(s, CranleyPatterson::new(seed))),
        (Built::Digital(s), K::Rotate) => Box::new(Scrambled::new(s, CranleyPatterson::new(seed))),
        (Built::Digital(s), K::Xor) => Box::new(Scrambled::new(s, DigitalShift::new(seed))),
        (Built::Digital(s), K::Owen) => Box::new(Scrambled::new(s, ExactOwen::new(seed))),
        (Built::Digital(s), K::FastOwen) => Box::new(Scrambled::new(s, FastOwen::new(seed))),
        (Built::Digital(s), K::FastOwenLk) => Box::new(Scrambled::new(
            s,
            FastOwen::with_hash(seed, OwenHash::LaineKarras),
        )),
        (Built::Digital(s), K::Lms) => {
            let lms = Lms::new(seed).cached(s.dims())?;
            Box::new(Scrambled::new(s, (lms, DigitalShift::new(seed))))
        }
        (Built::Digital(s), K::ShuffleOwen) => Box::new(Shuffled::new(
            Scrambled::new(s, FastOwen::new(seed)),
            seed,
            0,
        )?),
        (Built::Digital(_), K::Perm | K::Faure)
        | (Built::Other(_), K::Xor | K::Owen | K::FastOwen | K::FastOwenLk | K::Lms)
        | (Built::Other(_), K::ShuffleOwen | K::Perm | K::Faure)
        | (_, K::Shift | K::ShiftTent) => {
            return Err(does_not_apply(args));
        }
    })
}

/// The usage error of a randomization that does not fit the construction.
fn does_not_apply(args: &Spec) -> Failure {
    Failure::usage(format!(
        "--scramble {} does not apply to {} (base-2 kinds: sobol, lp, vdc base 2; \
         rotate: any; perm/faure/owen: halton, hammersley, vdc)",
        value_name(&args.scramble),
        value_name(&args.sampler),
    ))
}

impl SamplerName {
    /// Whether the construction is a radical inverse that takes a digit scramble
    /// (`with_scramble`): halton, hammersley, vdc in a base other than 2 (vdc base 2 is
    /// built as Sobol' dimension 0, the same bits, so the base-2 randomizers apply).
    fn takes_digit_scrambles(self, base: u32) -> bool {
        matches!(self, SamplerName::Halton | SamplerName::Hammersley)
            || (self == SamplerName::Vdc && base != 2)
    }
}

/// Builds the construction itself (digit scrambles are part of the radical inverse).
fn construct(args: &Spec, digits: DigitScramble) -> Result<Built, Failure> {
    let d = args.sampler.dims(args.d);
    let total = args.total.unwrap_or(args.n);
    if args.order == OrderName::Gray && args.sampler != SamplerName::Sobol {
        return Err(Failure::usage(
            "--order gray applies to sobol only (other samplers have natural order)",
        ));
    }
    if args.sampler == SamplerName::Vdc && args.base == 2 && digits.is_none() {
        if d != 1 {
            return Err(Failure::usage(format!(
                "vdc is one-dimensional: -d must be 1, got {d}"
            )));
        }
        // Van der Corput in base 2 is Sobol's dimension 0, bit for bit.
        return Ok(Built::Digital(Box::new(Sobol::new(1)?)));
    }
    if let Some(kind) = args.sampler.blue_noise() {
        let set = blue_noise::build(
            kind,
            &BlueNoiseArgs::default(),
            Some(total),
            args.d,
            args.seed,
            args.budget.started(),
        )?;
        return Ok(Built::Other(Box::new(set)));
    }
    Ok(Built::Other(match args.sampler {
        SamplerName::Sobol => {
            let order = match args.order {
                OrderName::Natural => Order::Natural,
                OrderName::Gray => Order::Gray,
            };
            return Ok(Built::Digital(Box::new(Sobol::with_order(d, order)?)));
        }
        SamplerName::Poisson | SamplerName::BestCandidate | SamplerName::GaussianBlueNoise => {
            return Err(Failure::usage(
                "a blue-noise set is built by 'qmckit points'",
            ));
        }
        SamplerName::Independent => Box::new(Independent::new(d, args.seed)?),
        SamplerName::Pmj02 => {
            if d != 2 {
                return Err(Failure::usage(format!(
                    "pmj02 is two-dimensional: -d must be 2, got {d}"
                )));
            }
            Box::new(qmckit::pmj::Pmj02::new(args.seed))
        }
        SamplerName::Pmj02bn => {
            if d != 2 {
                return Err(Failure::usage(format!(
                    "pmj02bn is two-dimensional: -d must be 2, got {d}"
                )));
            }
            Box::new(blue_noise::pmj02bn_set(total, args.seed, args.budget)?)
        }
        SamplerName::Halton => Box::new(Halton::with_scramble(d, digits)?),
        SamplerName::Vdc => {
            if d != 1 {
                return Err(Failure::usage(format!(
                    "vdc is one-dimensional: -d must be 1, got {d}"
                )));
            }
            Box::new(VanDerCorput::with_scramble(args.base, digits)?)
        }
        SamplerName::Hammersley => Box::new(Hammersley::with_scramble(total, d, digits)?),
        SamplerName::Latin => Box::new(LatinHypercube::new(total, d, args.seed)?),
        SamplerName::Lp => {
            if d != 2 {
                return Err(Failure::usage(format!(
                    "lp is two-dimensional: -d must be 2, got {d}"
                )));
            }
            return Ok(Built::Digital(Box::new(
                LarcherPillichshammer::with_points(total)?,
            )));
        }
        SamplerName::Lattice | SamplerName::Kronecker | SamplerName::Faure => {
            return Err(Failure::usage("unreachable: built by the toolbox"));
        }
        SamplerName::Stratified => {
            let strata = match &args.strata {
                Some(text) => parse_strata(text)?,
                None => {
                    let k = root(total, d)?;
                    let mut strata = qmckit::size::vec_zeroed::<u32>(d)?;
                    strata.fill(k);
                    strata
                }
            };
            if args.d.is_some() && strata.len() != d {
                return Err(Failure::usage(format!(
                    "--strata {} has {} dimensions but -d is {d}",
                    args.strata.as_deref().unwrap_or(""),
                    strata.len()
                )));
            }
            let jitter = if args.centered {
                Jitter::Center
            } else {
                Jitter::Random(args.seed)
            };
            let s = Stratified::new(&strata, jitter)?;
            if args.total.is_some_and(|t| t != s.len()) {
                return Err(Failure::usage(format!(
                    "--total {total} does not match the {} cells of --strata",
                    s.len()
                )));
            }
            Box::new(s)
        }
    }))
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
    if let Some(kind) = args.sampler.blue_noise() {
        return args.run_blue_noise(kind);
    }
    let budgeted = args.sampler == SamplerName::Pmj02bn;
    if let Some(option) = args.blue.first_given(budgeted) {
        let to = if option == "--max-seconds" {
            "poisson, best-candidate, gaussian-blue-noise, pmj02bn"
        } else {
            "poisson, best-candidate, gaussian-blue-noise"
        };
        return Err(Failure::usage(format!(
            "{option} does not apply to {} (only to {to})",
            value_name(&args.sampler)
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
            if args.sampler.is_finite_set() {
                "set"
            } else {
                "sequence"
            },
            if args.sampler.is_finite_set() {
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
        let name = value_name(&self.sampler);
        for (option, given) in [
            ("--start", self.start.is_some()),
            ("--total", self.total.is_some()),
            ("--order", self.order.is_some()),
            ("--base", self.base.is_some()),
            ("--strata", self.strata.is_some()),
            ("--centered", self.centered),
            ("--scramble", self.scramble != ScrambleName::None),
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
