//! What a `qmckit points` request builds: the [`Spec`] of a sampler (shared with
//! `tvalue` and `convergence`), its catalog parameters and the sampler itself.

use clap::ValueEnum;
use qmckit::Sampler;
use qmckit::catalog::{
    self, BlueNoiseOptions, CatalogError, GeneratingVector, Params, RandomizerEntry, SamplerEntry,
    SamplerKind, Size,
};
use qmckit::digital::sobol::Order;
use qmckit::lattice::KUO_33002;

use crate::Failure;
use crate::blue_noise;

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
    let limits = crate::input::Limits {
        bytes: MAX_VECTOR_FILE,
        line: 1 << 16,
        option: "--vector",
        records: u64::MAX,
    };
    let file = path.to_string_lossy();
    let (_, bytes) = crate::input::read_bounded(Some(&file), limits)?;
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

/// The first `spec.n` points of the sampler `spec` names, as 0.32 fractions (row-major),
/// with their dimension.
pub fn samples_u32(spec: &Spec) -> Result<(Vec<u32>, usize), Failure> {
    let sampler = build(spec)?;
    let dims = sampler.dims();
    let mut buf = qmckit::size::vec_zeroed(qmckit::size::coordinates(spec.n, dims)?)?;
    sampler.fill(0, &mut buf)?;
    Ok((buf, dims))
}
