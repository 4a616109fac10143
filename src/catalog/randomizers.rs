//! The randomizers, and the one rule of which applies to which sampler.

use super::samplers::{Family, SamplerEntry};
use super::{CatalogError, Entry, Param, alias, param};

/// A randomizer of [`RANDOMIZERS`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RandomizerKind {
    /// No randomization.
    None,
    /// Digital shift (XOR) in base 2.
    Xor,
    /// Cranley–Patterson rotation, any construction.
    Rotate,
    /// Owen's nested uniform scrambling (exact), in base 2 or base `b`.
    Owen,
    /// Hash-based Owen scrambling, Vegdahl's hash.
    FastOwen,
    /// Hash-based Owen scrambling, Laine and Karras's hash.
    FastOwenLk,
    /// Random linear matrix scramble plus digital shift.
    Lms,
    /// Burley's index shuffle plus hash-based Owen scrambling.
    ShuffleOwen,
    /// Random digit permutations.
    Perm,
    /// Faure's digit permutations.
    Faure,
    /// Random shift modulo 1 of a lattice.
    Shift,
    /// Random shift, then the tent (baker's) transform.
    ShiftTent,
}

/// Every family.
const ANY: &[Family] = &[
    Family::Base2Digital,
    Family::RadicalInverse,
    Family::BaseBNet,
    Family::Lattice,
    Family::Random,
    Family::BlueNoise,
];

impl RandomizerKind {
    /// The families of samplers it applies to.
    pub const fn families(self) -> &'static [Family] {
        match self {
            RandomizerKind::None | RandomizerKind::Rotate => ANY,
            RandomizerKind::Xor
            | RandomizerKind::FastOwen
            | RandomizerKind::FastOwenLk
            | RandomizerKind::Lms
            | RandomizerKind::ShuffleOwen => &[Family::Base2Digital],
            RandomizerKind::Owen => &[
                Family::Base2Digital,
                Family::RadicalInverse,
                Family::BaseBNet,
            ],
            RandomizerKind::Perm | RandomizerKind::Faure => {
                &[Family::RadicalInverse, Family::BaseBNet]
            }
            RandomizerKind::Shift | RandomizerKind::ShiftTent => &[Family::Lattice],
        }
    }

    /// The samplers it applies to, in words (the end of a [`CatalogError::NotApplicable`]).
    pub const fn rule(self) -> &'static str {
        match self {
            RandomizerKind::None | RandomizerKind::Rotate => "every sampler",
            RandomizerKind::Xor
            | RandomizerKind::FastOwen
            | RandomizerKind::FastOwenLk
            | RandomizerKind::Lms
            | RandomizerKind::ShuffleOwen => Family::Base2Digital.describe(),
            RandomizerKind::Owen => {
                "base-2 digital constructions (sobol, lp, vdc base 2), radical inverses \
                 (halton, hammersley, vdc base b) and faure"
            }
            RandomizerKind::Perm | RandomizerKind::Faure => {
                "radical inverses (halton, hammersley, vdc base b) and faure"
            }
            RandomizerKind::Shift | RandomizerKind::ShiftTent => Family::Lattice.describe(),
        }
    }

    /// Whether it applies to a sampler of `family`.
    pub fn applies_to(self, family: Family) -> bool {
        self.families().contains(&family)
    }

    /// Whether the seed changes it (all but `none` and `faure`).
    pub const fn is_seeded(self) -> bool {
        !matches!(self, RandomizerKind::None | RandomizerKind::Faure)
    }

    /// pbrt-v4's `RandomizeStrategy` of the pixel samplers, for the four it has: `none`,
    /// `xor` (`PermuteDigits`), `fast-owen` (`FastOwen`) and `owen` (`Owen`, pbrt's hashes).
    pub const fn pixel(self) -> Option<crate::pixel::Randomization> {
        use crate::pixel::Randomization as R;
        match self {
            RandomizerKind::None => Some(R::None),
            RandomizerKind::Xor => Some(R::PermuteDigits),
            RandomizerKind::FastOwen => Some(R::FastOwen),
            RandomizerKind::Owen => Some(R::Owen),
            _ => None,
        }
    }
}

/// An entry of [`RANDOMIZERS`].
pub type RandomizerEntry = Entry<RandomizerKind>;

/// The rule, once: `Ok` when `randomizer` applies to `sampler` (with van der Corput's
/// `base`, which decides its family), else why not.
///
/// ```
/// use qmckit::catalog::{applies, randomizer, sampler};
/// let owen = randomizer("owen")?;
/// assert!(applies(owen, sampler("halton")?, None).is_ok()); // in base b
/// assert!(applies(owen, sampler("lattice")?, None).is_err());
/// assert!(applies(randomizer("xor")?, sampler("vdc")?, Some(2)).is_ok());
/// let e = applies(randomizer("xor")?, sampler("vdc")?, Some(3)).unwrap_err();
/// assert_eq!(e.to_string(),
///     "xor applies to base-2 digital constructions (sobol, lp, vdc base 2), not vdc in base 3");
/// # Ok::<(), qmckit::catalog::CatalogError>(())
/// ```
///
/// # Errors
/// [`CatalogError::NotApplicable`].
pub fn applies(
    randomizer: &RandomizerEntry,
    sampler: &SamplerEntry,
    base: Option<u32>,
) -> Result<(), CatalogError> {
    if randomizer.kind.applies_to(sampler.family(base)) {
        return Ok(());
    }
    let vdc_base = match (sampler.kind, base) {
        (super::SamplerKind::Vdc, Some(b)) => Some(b),
        _ => None,
    };
    Err(CatalogError::NotApplicable {
        randomizer: randomizer.name,
        sampler: sampler.name,
        base: vdc_base,
        rule: randomizer.kind.rule(),
    })
}

const SEED: Param = param(
    "seed",
    "seed of the randomization (hashed per dimension)",
    "0",
    "any u64",
);

/// Every randomizer, in the order of the command's list.
pub static RANDOMIZERS: &[RandomizerEntry] = &[
    Entry {
        kind: RandomizerKind::None,
        name: "none",
        aliases: &[alias("identity", "qmckit::randomize::Identity")],
        summary: "no randomization (pbrt-v4 RandomizeStrategy::None)",
        math: "x -> x",
        params: &[],
        item: "qmckit::randomize::Identity",
    },
    Entry {
        kind: RandomizerKind::Xor,
        name: "xor",
        aliases: &[
            alias("digital-shift", "the usual name"),
            alias("permute-digits", "pbrt-v4 RandomizeStrategy::PermuteDigits"),
            alias("ds", "QMCPy DigitalNetB2 randomize='DS'"),
        ],
        summary: "random digital shift (XOR) in base 2",
        math: "x -> x ^ s_k, s_k uniform on 32 bits (Kollig & Keller 2002)",
        params: &[SEED],
        item: "qmckit::randomize::DigitalShift",
    },
    Entry {
        kind: RandomizerKind::Rotate,
        name: "rotate",
        aliases: &[
            alias("cranley-patterson", "the rotation's authors"),
            alias("rotation", "Cranley-Patterson rotation"),
        ],
        summary: "Cranley–Patterson rotation, any construction (does not keep nets)",
        math: "x -> frac(x + u_k), u_k uniform (Cranley & Patterson 1976)",
        params: &[SEED],
        item: "qmckit::randomize::CranleyPatterson",
    },
    Entry {
        kind: RandomizerKind::Owen,
        name: "owen",
        aliases: &[
            alias("nested-uniform", "Owen 1995's name"),
            alias("nus", "QMCPy DigitalNetB2 randomize='NUS'"),
            alias("exact-owen", "qmckit::randomize::ExactOwen"),
        ],
        summary: "Owen's exact nested uniform scrambling: in base 2 for digital constructions, \
                  in base b for radical inverses and faure (pbrt-v4's RandomizeStrategy::Owen \
                  is the same randomization with pbrt's hashes, used by the pixel samplers)",
        math: "digit j permuted at random given digits 0..j-1 (Owen 1995)",
        params: &[SEED],
        item: "qmckit::randomize::ExactOwen",
    },
    Entry {
        kind: RandomizerKind::FastOwen,
        name: "fast-owen",
        aliases: &[alias("hash-owen", "hash-based Owen scrambling")],
        summary: "hash-based Owen scrambling, Vegdahl's hash, base 2 (pbrt-v4 \
                  RandomizeStrategy::FastOwen)",
        math: "x -> rev(h(rev(x), s_k)), h a nested hash (Laine & Karras 2011; Burley 2020; Vegdahl 2021)",
        params: &[SEED],
        item: "qmckit::randomize::FastOwen",
    },
    Entry {
        kind: RandomizerKind::FastOwenLk,
        name: "fast-owen-lk",
        aliases: &[alias("laine-karras", "the hash's authors")],
        summary: "hash-based Owen scrambling, Laine and Karras's hash, base 2",
        math: "x -> rev(h_LK(rev(x), s_k)) (Laine & Karras 2011)",
        params: &[SEED],
        item: "qmckit::randomize::FastOwen::with_hash",
    },
    Entry {
        kind: RandomizerKind::Lms,
        name: "lms",
        aliases: &[
            alias("lms-ds", "QMCPy DigitalNetB2 randomize='LMS_DS'"),
            alias("matousek", "the scramble's author"),
        ],
        summary: "random linear matrix scramble plus digital shift, base 2 (SciPy \
                  qmc.Sobol(scramble=True))",
        math: "x -> M_k x ^ s_k, M_k random lower-triangular over GF(2), unit diagonal (Matoušek 1998)",
        params: &[SEED],
        item: "qmckit::randomize::Lms",
    },
    Entry {
        kind: RandomizerKind::ShuffleOwen,
        name: "shuffle-owen",
        aliases: &[
            alias("burley", "Burley 2020's shuffled scrambled Sobol'"),
            alias("shuffled-owen", "a spelling"),
        ],
        summary: "index shuffle by a nested scramble, then hash-based Owen scrambling, base 2",
        math: "x(i) -> fast-owen(x(owen(i))) (Burley 2020)",
        params: &[SEED],
        item: "qmckit::randomize::shuffle::Shuffled",
    },
    Entry {
        kind: RandomizerKind::Perm,
        name: "perm",
        aliases: &[
            alias("digit-permutations", "the usual name"),
            alias("permutations", "a short form"),
        ],
        summary: "random digit permutations per digit position, base b (SciPy \
                  qmc.Halton(scramble=True); pbrt-v4's PermuteDigits for Halton)",
        math: "digit a_j -> pi_(k,j)(a_j), independent random permutations (Owen 2017)",
        params: &[SEED],
        item: "qmckit::randomize::digits::DigitScramble::Permutations",
    },
    Entry {
        kind: RandomizerKind::Faure,
        name: "faure",
        aliases: &[alias("faure-permutations", "the permutations' author")],
        summary: "Faure's deterministic digit permutations, base b",
        math: "digit a_j -> sigma_b(a_j), Faure's permutations (Faure 1992)",
        params: &[],
        item: "qmckit::randomize::digits::DigitScramble::Faure",
    },
    Entry {
        kind: RandomizerKind::Shift,
        name: "shift",
        aliases: &[
            alias("random-shift", "QMCPy Lattice randomize='SHIFT'"),
            alias("lattice-shift", "a spelling"),
        ],
        summary: "random shift modulo 1 of a lattice (the same values as rotate)",
        math: "x -> frac(x + Delta_k), Delta_k uniform (Cranley & Patterson 1976)",
        params: &[SEED],
        item: "qmckit::randomize::CranleyPatterson",
    },
    Entry {
        kind: RandomizerKind::ShiftTent,
        name: "shift-tent",
        aliases: &[
            alias("tent", "the tent transform"),
            alias("baker", "the baker's transform"),
        ],
        summary: "random shift, then the tent (baker's) transform, for lattices",
        math: "x -> 1 - |2 frac(x + Delta_k) - 1| (Hickernell 2002)",
        params: &[SEED],
        item: "qmckit::randomize::Tent",
    },
];
