//! The builder (`std`): a sampler entry, a randomizer entry and [`Params`] to a boxed
//! [`Sampler`], the applicability rule applied once, the construction and the seed mapped
//! exactly as the `qmckit points` command maps them (same bits for the same options).

use std::boxed::Box;
use std::vec::Vec;

// The constructions, by path: the one place to update when library modules move.
use crate::digital::cascaded::CascadedSobol;
use crate::digital::sobol::Order;
use crate::digital::{DigitalNetB, MAX_BASE, is_prime};
use crate::lattice::hex::HexGrid;
use crate::lattice::kronecker::Kronecker;
use crate::lattice::{KUO_33002, Rank1Lattice, korobov, parse_lattice};
use crate::pmj::Pmj02;
use crate::random::cmj::CorrelatedMultiJitter;
use crate::randomize::digits::DigitScramble;
use crate::randomize::shuffle::Shuffled;
use crate::randomize::{
    CranleyPatterson, DigitalShift, ExactOwen, FastOwen, Lms, OwenHash, Scrambled, Tent,
};
use crate::work::Budget;
use crate::{
    Base2Digital, Halton, Hammersley, Independent, Jitter, LarcherPillichshammer, LatinHypercube,
    Sampler, Sobol, Stratified, VanDerCorput,
};

use super::whole::BlueNoiseOptions;
use super::{
    CatalogError, RandomizerEntry, RandomizerKind as R, SamplerEntry, SamplerKind as S, Size,
    applies,
};

/// The most coordinates a point may hold: 2^27 (a row of `f64`s within the crate's 1 GiB
/// allocation limit), as `qmckit points` allows.
pub const MAX_DIMS: usize = (crate::size::MAX_ALLOC_BYTES / 8) as usize;

/// A generating vector read from a file (`qmckit points lattice --vector`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GeneratingVector {
    /// Its components (at least the sampler's `dims`; the first `dims` are used).
    pub z: Vec<u32>,
    /// The modulus `N` the file names, if it does.
    pub modulus: Option<u64>,
}

impl GeneratingVector {
    /// The first `dims` components of the vector in `text` (LDData's `lattice` format or
    /// Kuo's `j z_j` rows, [`parse_lattice`]) and its modulus.
    ///
    /// # Errors
    /// The parser's; [`CatalogError::Parameter`] when the file has fewer than `dims`
    /// components.
    pub fn parse(text: &str, dims: usize) -> Result<Self, CatalogError> {
        let mut z = crate::size::vec_zeroed(dims)?;
        let info = parse_lattice(text, &mut z)?;
        if info.read < dims {
            return Err(CatalogError::Parameter {
                entry: "lattice",
                param: "vector",
                got: Some(info.read as u64),
                expected: "components read: fewer than dims",
            });
        }
        Ok(GeneratingVector {
            z,
            modulus: info.modulus,
        })
    }
}

/// What [`build`] needs besides the two entries. Every field has a default
/// ([`Params::default`]); a field the sampler does not take, when given, is a
/// [`CatalogError::Unused`] (the seed excepted: deterministic constructions ignore it).
#[derive(Clone, Debug, PartialEq)]
pub struct Params {
    /// Coordinates of each point (default 1 for vdc, 2 otherwise; stratified: the strata's).
    pub dims: Option<usize>,
    /// The size `N` of the set ([`Size`]): needed by the finite sets and the sets built
    /// whole, optional for lattice (the `N`-point rule in linear order) and stratified
    /// (then the product of `strata`), refused by the sequences.
    pub points: Option<u64>,
    /// vdc: the base (default 2); faure: the prime base (default the smallest prime
    /// `>= max(dims, 2)`).
    pub base: Option<u32>,
    /// The seed of the random constructions and of the randomizer (one seed for both, as
    /// the command has).
    pub seed: u64,
    /// sobol: the order (default natural); gray is SciPy's.
    pub order: Order,
    /// stratified: strata per dimension.
    pub strata: Option<Vec<u32>>,
    /// stratified: points at the cells' centres (then nothing is random).
    pub centered: bool,
    /// lattice: the Korobov parameter `a` (needs `points`).
    pub korobov: Option<u64>,
    /// lattice: a generating vector.
    pub vector: Option<GeneratingVector>,
    /// The time budget of the sets built whole (default [`Budget::DEFAULT`], 10 s).
    pub budget: Budget,
    /// The blue-noise sets' options.
    pub blue_noise: BlueNoiseOptions,
}

impl Default for Params {
    fn default() -> Self {
        Params {
            dims: None,
            points: None,
            base: None,
            seed: 0,
            order: Order::Natural,
            strata: None,
            centered: false,
            korobov: None,
            vector: None,
            budget: Budget::DEFAULT,
            blue_noise: BlueNoiseOptions::default(),
        }
    }
}

impl Params {
    /// `dims` dimensions, the defaults otherwise.
    pub fn dims(dims: usize) -> Self {
        Params {
            dims: Some(dims),
            ..Params::default()
        }
    }

    /// These parameters with `points`.
    pub fn with_points(self, points: u64) -> Self {
        Params {
            points: Some(points),
            ..self
        }
    }

    /// These parameters with `seed`.
    pub fn with_seed(self, seed: u64) -> Self {
        Params { seed, ..self }
    }
}

/// [`build`] by names ([`super::sampler`], [`super::randomizer`]).
///
/// ```
/// use qmckit::{Sampler, catalog::{Params, build_named}};
/// let s = build_named("sobol", "fast-owen", &Params::dims(3).with_seed(7))?;
/// assert_eq!((s.dims(), s.len()), (3, 1 << 32));
/// # Ok::<(), qmckit::catalog::CatalogError>(())
/// ```
///
/// # Errors
/// As the lookups and [`build`].
pub fn build_named(
    sampler: &str,
    randomizer: &str,
    params: &Params,
) -> Result<Box<dyn Sampler>, CatalogError> {
    build(
        super::sampler(sampler)?,
        super::randomizer(randomizer)?,
        params,
    )
}

/// The sampler `sampler` randomized by `randomizer` with `params`: the same points, bit
/// for bit, as `qmckit points SAMPLER --scramble RANDOMIZER` with the same options
/// (`seed` is `--seed`, `points` `--total` or `-n`, `dims` `-d`, ...).
///
/// The checks, in order: options the sampler does not take ([`CatalogError::Unused`]);
/// the randomizer's applicability ([`applies`]); the dimensions (at least 1, at most
/// [`MAX_DIMS`], the construction's fixed count); then the construction's own.
///
/// ```
/// use qmckit::{Sampler, catalog::{self, Params}};
/// let lp = catalog::sampler("larcher-pillichshammer")?;
/// let s = catalog::build(lp, catalog::randomizer("lms")?, &Params::default().with_points(64))?;
/// assert_eq!((s.dims(), s.len()), (2, 64));
/// let e = catalog::build(lp, catalog::randomizer("none")?, &Params::default().with_points(48));
/// assert!(e.is_err()); // 48 is not a power of two
/// # Ok::<(), qmckit::catalog::CatalogError>(())
/// ```
///
/// # Errors
/// [`CatalogError::Unused`], [`CatalogError::NotApplicable`],
/// [`CatalogError::Parameter`], and the constructions' errors as [`CatalogError::Build`].
pub fn build(
    sampler: &SamplerEntry,
    randomizer: &RandomizerEntry,
    params: &Params,
) -> Result<Box<dyn Sampler>, CatalogError> {
    unused(sampler, params)?;
    applies(randomizer, sampler, params.base)?;
    let d = dims(sampler, params)?;
    let (kind, r, seed) = (sampler.kind, randomizer.kind, params.seed);
    match kind {
        S::Lattice => return shifted(lattice(params, d)?, r, seed),
        S::Kronecker => return shifted(Kronecker::r_d(d)?, r, seed),
        S::Faure => return faure(params.base, d, r, seed),
        S::Hex => return shifted(HexGrid::new(needed(sampler, params)?)?, r, seed),
        S::MaximinLattice => return shifted(maximin_lattice(sampler, params)?, r, seed),
        _ => {}
    }
    let takes_digits = matches!(kind, S::Halton | S::Hammersley)
        || (kind == S::Vdc && params.base.is_some_and(|b| b != 2));
    let digits = match r {
        R::Perm => DigitScramble::Permutations(seed),
        R::Faure => DigitScramble::Faure,
        R::Owen if takes_digits => DigitScramble::Owen(seed),
        _ => DigitScramble::None,
    };
    let built = construct(sampler, params, d, digits)?;
    Ok(match (built, r) {
        (Built::Digital(s), R::None) => Box::new(s),
        (Built::Other(s), _) if !digits.is_none() => s,
        (Built::Other(s), R::None) => s,
        (Built::Other(s), R::Rotate) => Box::new(Scrambled::new(s, CranleyPatterson::new(seed))),
        (Built::Digital(s), R::Rotate) => Box::new(Scrambled::new(s, CranleyPatterson::new(seed))),
        (Built::Digital(s), R::Xor) => Box::new(Scrambled::new(s, DigitalShift::new(seed))),
        (Built::Digital(s), R::Owen) => Box::new(Scrambled::new(s, ExactOwen::new(seed))),
        (Built::Digital(s), R::FastOwen) => Box::new(Scrambled::new(s, FastOwen::new(seed))),
        (Built::Digital(s), R::FastOwenLk) => Box::new(Scrambled::new(
            s,
            FastOwen::with_hash(seed, OwenHash::LaineKarras),
        )),
        (Built::Digital(s), R::Lms) => {
            let lms = Lms::new(seed).cached(s.dims())?;
            Box::new(Scrambled::new(s, (lms, DigitalShift::new(seed))))
        }
        (Built::Digital(s), R::ShuffleOwen) => Box::new(Shuffled::new(
            Scrambled::new(s, FastOwen::new(seed)),
            seed,
            0,
        )?),
        // `applies` refused these above; kept as errors, never a panic.
        (_, _) => {
            return Err(CatalogError::NotApplicable {
                randomizer: randomizer.name,
                sampler: sampler.name,
                base: params.base,
                rule: r.rule(),
            });
        }
    })
}

/// Refuses the parameters the sampler does not take.
fn unused(sampler: &SamplerEntry, p: &Params) -> Result<(), CatalogError> {
    let kind = sampler.kind;
    let refuse = |param, why| {
        Err(CatalogError::Unused {
            entry: sampler.name,
            param,
            why,
        })
    };
    if p.base.is_some() && !matches!(kind, S::Vdc | S::Faure) {
        return refuse("base", "only vdc and faure take a base");
    }
    if (p.korobov.is_some() || p.vector.is_some()) && kind != S::Lattice {
        return refuse(
            if p.korobov.is_some() {
                "korobov"
            } else {
                "vector"
            },
            "only lattice has a generating vector",
        );
    }
    if p.points.is_some() && kind.size() == Size::Sequence {
        return refuse(
            "points",
            "a sequence; stratified, latin, hammersley, lp, lattice and the sets built \
             whole take a size",
        );
    }
    if p.strata.is_some() && kind != S::Stratified {
        return refuse("strata", "only stratified has strata");
    }
    if p.centered && kind != S::Stratified {
        return refuse("centered", "only stratified has cells");
    }
    if p.order == Order::Gray && kind != S::Sobol {
        return refuse("order", "only sobol has a Gray-code order");
    }
    if let Some((param, why)) = p.blue_noise.unused(kind) {
        return refuse(param, why);
    }
    Ok(())
}

/// The dimension count: given, or the strata's, or the default; checked against 1,
/// [`MAX_DIMS`] and the construction's fixed count.
fn dims(sampler: &SamplerEntry, p: &Params) -> Result<usize, CatalogError> {
    let kind = sampler.kind;
    let strata = p.strata.as_ref().map(Vec::len);
    let d = p
        .dims
        .or(strata.filter(|_| kind == S::Stratified))
        .unwrap_or(kind.default_dims());
    let bad = |expected| {
        Err(CatalogError::Parameter {
            entry: sampler.name,
            param: "dims",
            got: Some(d as u64),
            expected,
        })
    };
    if d == 0 {
        return bad("must be at least 1");
    }
    if d > MAX_DIMS {
        return bad("a point of that many coordinates is too large: at most 2^27");
    }
    match kind.fixed_dims() {
        Some(1) if d != 1 => bad("one-dimensional: must be 1"),
        Some(2) if d != 2 => bad("two-dimensional: must be 2"),
        _ => Ok(d),
    }
}

/// `points`, which the sampler needs.
fn needed(sampler: &SamplerEntry, p: &Params) -> Result<u64, CatalogError> {
    p.points.ok_or(CatalogError::Parameter {
        entry: sampler.name,
        param: "points",
        got: None,
        expected: "needed: the size of the set",
    })
}

/// A construction, classified by the randomizations it takes.
enum Built {
    /// Base-2 digital: every base-2 randomizer applies.
    Digital(Box<dyn Base2Digital>),
    /// Anything else (digit scrambles, if asked, are inside its radical inverse).
    Other(Box<dyn Sampler>),
}

/// The construction itself, for the samplers other than lattice, kronecker and faure.
fn construct(
    sampler: &SamplerEntry,
    p: &Params,
    d: usize,
    digits: DigitScramble,
) -> Result<Built, CatalogError> {
    let seed = p.seed;
    Ok(Built::Other(match sampler.kind {
        // Van der Corput in base 2 is Sobol's dimension 0, bit for bit.
        S::Vdc if p.base.is_none_or(|b| b == 2) => {
            return Ok(Built::Digital(Box::new(Sobol::new(1)?)));
        }
        S::Vdc => Box::new(VanDerCorput::with_scramble(p.base.unwrap_or(2), digits)?),
        S::Sobol => return Ok(Built::Digital(Box::new(Sobol::with_order(d, p.order)?))),
        S::Lp => {
            let n = needed(sampler, p)?;
            return Ok(Built::Digital(Box::new(
                LarcherPillichshammer::with_points(n)?,
            )));
        }
        S::Independent => Box::new(Independent::new(d, seed)?),
        S::Pmj02 => Box::new(Pmj02::new(seed)),
        S::Halton => Box::new(Halton::with_scramble(d, digits)?),
        S::Hammersley => Box::new(Hammersley::with_scramble(needed(sampler, p)?, d, digits)?),
        S::Latin => Box::new(LatinHypercube::new(needed(sampler, p)?, d, seed)?),
        S::Stratified => Box::new(stratified(sampler, p, d)?),
        S::Cmj => Box::new(CorrelatedMultiJitter::new(needed(sampler, p)?, d, seed)?),
        S::CascadedSobol => Box::new(CascadedSobol::new(needed(sampler, p)?, d, seed)?),
        #[cfg(feature = "analysis")]
        S::Pmj02bn => Box::new(super::whole::pmj02bn(needed(sampler, p)?, seed, &p.budget)?),
        #[cfg(feature = "analysis")]
        S::Poisson | S::BestCandidate | S::GaussianBlueNoise => Box::new(super::whole::blue_noise(
            sampler.kind,
            sampler.name,
            &p.blue_noise,
            p.points,
            p.dims,
            seed,
            &p.budget,
        )?),
        #[cfg(feature = "analysis")]
        S::Penrose | S::AaPatterns | S::Art => Box::new(super::whole::tiled(
            sampler.kind,
            needed(sampler, p)?,
            seed,
            &p.budget,
        )?),
        #[cfg(feature = "analysis")]
        S::Lloyd
        | S::Ccvt
        | S::Sot
        | S::Bnot
        | S::ProjectiveBlueNoise
        | S::ForcedRandom
        | S::StepBlueNoise
        | S::SinglePeakBlueNoise
        | S::KdeBlueNoise => Box::new(super::whole::relaxed(
            sampler.kind,
            &p.blue_noise,
            needed(sampler, p)?,
            d,
            seed,
            &p.budget,
        )?),
        #[cfg(feature = "analysis")]
        S::Ldbn => {
            Box::new(crate::blue_noise::Ldbn::new(needed(sampler, p)?, seed)?.generate(&p.budget)?)
        }
        #[cfg(not(feature = "analysis"))]
        S::Pmj02bn
        | S::Ldbn
        | S::Poisson
        | S::BestCandidate
        | S::GaussianBlueNoise
        | S::Lloyd
        | S::Ccvt
        | S::Sot
        | S::Bnot
        | S::ProjectiveBlueNoise
        | S::Penrose
        | S::AaPatterns
        | S::Art
        | S::ForcedRandom
        | S::StepBlueNoise
        | S::SinglePeakBlueNoise
        | S::KdeBlueNoise => {
            return Err(super::whole::unavailable(sampler.name));
        }
        S::Lattice | S::Kronecker | S::Faure | S::Hex | S::MaximinLattice => {
            return Err(CatalogError::Unused {
                entry: sampler.name,
                param: "the construction",
                why: "built with its shifts",
            });
        }
    }))
}

/// The stratified sampler: the strata given, or `k` in each dimension with `k^d = N`.
fn stratified(sampler: &SamplerEntry, p: &Params, d: usize) -> Result<Stratified, CatalogError> {
    let bad = |param, got, expected| CatalogError::Parameter {
        entry: sampler.name,
        param,
        got,
        expected,
    };
    let strata = match &p.strata {
        Some(strata) => strata.clone(),
        None => {
            let n = p.points.ok_or(bad(
                "points",
                None,
                "needed (or strata): the size k^d of the grid",
            ))?;
            let k = root(n, d).ok_or(bad(
                "points",
                Some(n),
                "not k^d for a whole number k <= 2^32 - 1 (give strata, e.g. [8, 4])",
            ))?;
            let mut strata = crate::size::vec_zeroed::<u32>(d)?;
            strata.fill(k);
            strata
        }
    };
    if p.dims.is_some() && strata.len() != d {
        return Err(bad(
            "strata",
            Some(strata.len() as u64),
            "entries: must be dims",
        ));
    }
    let jitter = if p.centered {
        Jitter::Center
    } else {
        Jitter::Random(p.seed)
    };
    let s = Stratified::new(&strata, jitter)?;
    if p.strata.is_some() && p.points.is_some_and(|t| t != s.len()) {
        return Err(bad(
            "points",
            p.points,
            "does not match the cells of strata",
        ));
    }
    Ok(s)
}

/// `k` with `k^d == n` and `k < 2^32`.
fn root(n: u64, d: usize) -> Option<u32> {
    let guess = (n as f64).powf(1.0 / d as f64).round() as u64;
    let power = u32::try_from(d).unwrap_or(u32::MAX);
    (guess.saturating_sub(1)..=guess.saturating_add(1))
        .find(|&k| k > 0 && k.checked_pow(power) == Some(n))
        .and_then(|k| u32::try_from(k).ok())
}

/// The 2D rank-1 lattice of `points` points with the largest minimum distance
/// ([`crate::lattice::maximin`]), searched within the set budget.
fn maximin_lattice(
    sampler: &SamplerEntry,
    p: &Params,
) -> Result<Rank1Lattice<[u32; 2]>, CatalogError> {
    let n = needed(sampler, p)?;
    let n = u32::try_from(n).map_err(|_| CatalogError::Parameter {
        entry: sampler.name,
        param: "points",
        got: Some(n),
        expected: "1 to 2^32 - 1",
    })?;
    let (a, _) = crate::lattice::maximin::max_min_distance(n, &p.budget)?;
    Ok(Rank1Lattice::linear([1, a], n as u64)?)
}

/// The lattice: Kuo's vector, a given vector or Korobov's, in radical-inverse order, or
/// of `points` points in linear order.
fn lattice(p: &Params, d: usize) -> Result<Box<dyn Sampler>, CatalogError> {
    let bad = |param, got, expected| CatalogError::Parameter {
        entry: "lattice",
        param,
        got,
        expected,
    };
    if p.korobov.is_some() && p.vector.is_some() {
        return Err(bad("korobov", None, "excludes vector"));
    }
    if let Some(a) = p.korobov {
        let n = p.points.ok_or(bad(
            "korobov",
            Some(a),
            "needs points, the size of the rule",
        ))?;
        let mut z = crate::size::vec_zeroed(d)?;
        korobov(a, n, &mut z)?;
        return Ok(Box::new(Rank1Lattice::linear(z, n)?));
    }
    if let Some(v) = &p.vector {
        let z = v.z.get(..d).ok_or(bad(
            "vector",
            Some(v.z.len() as u64),
            "components: fewer than dims",
        ))?;
        let z = z.to_vec();
        return Ok(match (p.points, v.modulus) {
            (Some(n), _) => Box::new(Rank1Lattice::linear(z, n)?),
            (None, Some(n)) if n.is_power_of_two() => {
                Box::new(Rank1Lattice::extensible(z, n.trailing_zeros())?)
            }
            (None, Some(n)) => Box::new(Rank1Lattice::linear(z, n)?),
            (None, None) => {
                return Err(bad(
                    "points",
                    None,
                    "needed: the vector does not name its modulus",
                ));
            }
        });
    }
    let z = KUO_33002.get(..d).ok_or(bad(
        "dims",
        Some(d as u64),
        "past the 9125 dimensions of Kuo's vector (give a vector)",
    ))?;
    Ok(match p.points {
        Some(n) => Box::new(Rank1Lattice::linear(z, n)?),
        None => Box::new(Rank1Lattice::kuo(d)?),
    })
}

/// A lattice or Kronecker sequence randomized by `none`, `shift`/`rotate` (the same
/// random shift) or `shift-tent`.
fn shifted<L: Sampler + 'static>(s: L, r: R, seed: u64) -> Result<Box<dyn Sampler>, CatalogError> {
    Ok(match r {
        R::Shift | R::Rotate => Box::new(Scrambled::new(s, CranleyPatterson::new(seed))),
        R::ShiftTent => Box::new(Scrambled::new(s, (CranleyPatterson::new(seed), Tent))),
        _ => Box::new(s),
    })
}

/// The smallest prime `>= max(d, 2)`, Faure's default base.
fn faure_base(d: usize) -> u32 {
    let mut b = u32::try_from(d.max(2)).unwrap_or(u32::MAX);
    while !is_prime(b) && b < MAX_BASE {
        b += 1;
    }
    b
}

/// Faure's sequence in `base` (default the smallest prime `>= d`), digit-scrambled, or
/// rotated.
fn faure(base: Option<u32>, d: usize, r: R, seed: u64) -> Result<Box<dyn Sampler>, CatalogError> {
    let bad = |param, got: u64, expected| CatalogError::Parameter {
        entry: "faure",
        param,
        got: Some(got),
        expected,
    };
    if d as u64 > MAX_BASE as u64 {
        return Err(bad(
            "dims",
            d as u64,
            "needs a prime base of at least dims, past the largest base (MAX_BASE)",
        ));
    }
    let base = base.unwrap_or_else(|| faure_base(d));
    if !is_prime(base) || (d as u64) > base as u64 || base > MAX_BASE {
        return Err(bad(
            "base",
            base as u64,
            "must be a prime of at least dims (and at most MAX_BASE)",
        ));
    }
    let digits = match r {
        R::Owen => DigitScramble::Owen(seed),
        R::Perm => DigitScramble::Permutations(seed),
        R::Faure => DigitScramble::Faure,
        _ => DigitScramble::None,
    };
    let net = DigitalNetB::faure(base, d)?.with_scramble(digits);
    Ok(match r {
        R::Rotate => Box::new(Scrambled::new(net, CranleyPatterson::new(seed))),
        _ => Box::new(net),
    })
}
