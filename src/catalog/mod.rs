//! One catalog of everything the crate offers by name: sampler constructions, randomizers,
//! pixel samplers, measures and test integrands, each with a canonical kebab-case name,
//! documented aliases, a one-line description, its mathematics with its paper, its
//! parameters, and (behind the features its builder needs) a builder.
//!
//! | list | entries | resolve | build |
//! |---|---|---|---|
//! | [`SAMPLERS`] | [`SamplerKind`]: vdc, halton, sobol, lattice, ... | [`sampler`] | [`build`] (`std`): a `Box<dyn Sampler>` |
//! | [`RANDOMIZERS`] | [`RandomizerKind`]: none, xor, owen, lms, shift, ... | [`randomizer`] | inside [`build`]; the rule is [`applies`] |
//! | [`PIXEL_SAMPLERS`] | [`PixelKind`]: zsobol, image-sobol, ... | [`pixel_sampler`] | [`build_pixel`] (`std`): a `Box<dyn PixelSampler>` |
//! | [`MEASURES`] | [`MeasureKind`]: star, cd, t-value, spectrum, ... | [`measure`] | `MeasureEntry::scalar` (`analysis`) |
//! | [`INTEGRANDS`] | [`IntegrandKind`]: gaussian-peak, genz-*, keister, ... | [`integrand`] | `build_integrand` (`analysis`) |
//!
//! The tables, the name resolution and the applicability rule are `no_std` and allocate
//! nothing; the builders need `std` (boxes) and, for the blue-noise sets, the measures
//! and the integrands, `analysis`.
//!
//! ## Names
//!
//! Every entry has one canonical name (what the command line prints) and aliases (the
//! names other tools use: pbrt-v4's `RandomizeStrategy`, SciPy's and QMCPy's class and
//! option names, this crate's older spellings). Each alias says where it comes from
//! ([`Alias::source`]). A name resolves by [`Entry::matches`]: ASCII case is ignored and so
//! are the separators `-`, `_`, space and `'`, so `FastOwen`, `fast_owen` and `fast-owen`
//! name one entry, `LatinHypercube` names `latin`, `Sobol'` names `sobol`. Within a list
//! no two names (canonical or alias) are equal under that rule (tested). A name that
//! resolves to nothing is a [`CatalogError::Unknown`] whose message lists the valid names.
//!
//! ```
//! use qmckit::catalog;
//! assert_eq!(catalog::randomizer("PermuteDigits")?.name, "xor");
//! assert_eq!(catalog::sampler("jittered")?.name, "stratified");
//! let e = catalog::sampler("sobel").unwrap_err();
//! assert!(e.to_string().contains("halton, hammersley, lp, sobol"));
//! # Ok::<(), qmckit::catalog::CatalogError>(())
//! ```
//!
//! ## Which randomizer applies to which sampler
//!
//! Each sampler belongs to a [`Family`] (base-2 digital, radical inverse in base `b`,
//! base-`b` digital net, lattice, random, blue noise; van der Corput is base-2 digital in
//! base 2 and a radical inverse otherwise), and each randomizer lists the families it
//! applies to ([`RandomizerKind::families`]). [`applies`] is that rule, once; [`build`]
//! calls it first, so a combination that does not apply is an error that says why:
//!
//! ```
//! use qmckit::catalog::{self, Params};
//! let e = catalog::build(catalog::sampler("halton")?, catalog::randomizer("lms")?,
//!     &Params::default()).err().unwrap();
//! assert_eq!(e.to_string(),
//!     "lms applies to base-2 digital constructions (sobol, lp, vdc base 2), not halton");
//! # Ok::<(), qmckit::catalog::CatalogError>(())
//! ```
//!
//! ## Adding a construction
//!
//! A new sampler is one entry: a [`SamplerKind`] variant, one row of [`SAMPLERS`] (name,
//! aliases with their sources, summary, the formula and its paper, parameters, the item
//! that implements it), its [`Family`] in [`SamplerKind::family`] (which decides its
//! randomizers; nothing else needs to change for them), its [`Size`] and dimension rule,
//! and one arm in the builder (`build.rs`) that constructs it from [`Params`]. The
//! conformance tests (`tests/suite/catalog.rs`) walk every row and every randomizer that
//! applies to it, so the new entry is checked against the [`crate::Sampler`] contract
//! without a new test. A randomizer, pixel sampler, measure or integrand is added the same
//! way in its own file.

use core::fmt;

#[cfg(feature = "std")]
mod build;
#[cfg(feature = "std")]
mod examples;
mod integrands;
mod measures;
mod pixel;
mod randomizers;
mod samplers;
#[cfg(feature = "std")]
mod whole;

#[cfg(feature = "std")]
pub use build::{GeneratingVector, MAX_DIMS, Params, build, build_named};
#[cfg(feature = "std")]
pub use examples::examples;
pub use integrands::{INTEGRANDS, IntegrandEntry, IntegrandKind};
#[cfg(feature = "analysis")]
pub use integrands::{IntegrandParams, TestIntegrand, build_integrand};
pub use measures::{MEASURES, MeasureEntry, MeasureKind, Output};
pub use pixel::{PIXEL_SAMPLERS, PixelEntry, PixelKind};
#[cfg(feature = "std")]
pub use pixel::{PixelParams, build_pixel};
pub use randomizers::{RANDOMIZERS, RandomizerEntry, RandomizerKind, applies};
pub use samplers::{Family, SAMPLERS, SamplerEntry, SamplerKind, Size};
#[cfg(feature = "std")]
pub use whole::BlueNoiseOptions;

/// One entry of a list: a name, its aliases, what it is, and its parameters. `K` is the
/// list's kind enum ([`SamplerKind`], ...), whose methods carry the list's own rules.
#[derive(Clone, Copy, Debug)]
pub struct Entry<K: 'static> {
    /// The kind, for matching in code.
    pub kind: K,
    /// The canonical name, kebab-case (what the command line prints).
    pub name: &'static str,
    /// Other names that resolve to this entry, with where each comes from.
    pub aliases: &'static [Alias],
    /// What it is, in one line.
    pub summary: &'static str,
    /// Its mathematics in one line, with its paper.
    pub math: &'static str,
    /// Its parameters (beyond those every entry of the list takes).
    pub params: &'static [Param],
    /// The item of this crate that implements it (a path, for the documentation).
    pub item: &'static str,
}

/// Another name of an entry and where it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Alias {
    /// The alias, as the other tool spells it.
    pub name: &'static str,
    /// Where it comes from (`"pbrt-v4 RandomizeStrategy::PermuteDigits"`).
    pub source: &'static str,
}

/// A static description of one parameter of an entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Param {
    /// The parameter's name (a field of the builder's parameters, e.g. `dims`).
    pub name: &'static str,
    /// What it means.
    pub meaning: &'static str,
    /// Its default, in words.
    pub default: &'static str,
    /// The values allowed, in words.
    pub range: &'static str,
}

impl<K> Entry<K> {
    /// Whether `name` names this entry (its canonical name or an alias), ignoring ASCII
    /// case and the separators `-`, `_`, space and `'`.
    pub fn matches(&self, name: &str) -> bool {
        same_name(self.name, name) || self.aliases.iter().any(|a| same_name(a.name, name))
    }

    /// The canonical name, then the aliases.
    pub fn names(&self) -> impl Iterator<Item = &'static str> + '_ {
        core::iter::once(self.name).chain(self.aliases.iter().map(|a| a.name))
    }

    /// The parameter called `name`, if the entry has one.
    pub fn param(&self, name: &str) -> Option<&'static Param> {
        self.params.iter().find(|p| p.name == name)
    }
}

/// The characters a name comparison skips.
const fn is_separator(b: u8) -> bool {
    matches!(b, b'-' | b'_' | b' ' | b'\'')
}

/// `a` and `b` are the same name: equal after dropping separators and ASCII case.
pub fn same_name(a: &str, b: &str) -> bool {
    let mut x = a.bytes().filter(|&c| !is_separator(c));
    let mut y = b.bytes().filter(|&c| !is_separator(c));
    loop {
        match (x.next(), y.next()) {
            (None, None) => return true,
            (Some(p), Some(q)) if p.eq_ignore_ascii_case(&q) => {}
            _ => return false,
        }
    }
}

/// The five lists, for messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum List {
    /// [`SAMPLERS`].
    Samplers,
    /// [`RANDOMIZERS`].
    Randomizers,
    /// [`PIXEL_SAMPLERS`].
    PixelSamplers,
    /// [`MEASURES`].
    Measures,
    /// [`INTEGRANDS`].
    Integrands,
}

impl List {
    /// `"sampler"`, `"randomizer"`, ...: one entry of the list, in words.
    pub const fn noun(self) -> &'static str {
        match self {
            List::Samplers => "sampler",
            List::Randomizers => "randomizer",
            List::PixelSamplers => "pixel sampler",
            List::Measures => "measure",
            List::Integrands => "integrand",
        }
    }

    /// The canonical names of the list, in its order.
    pub const fn names(self) -> Names {
        Names {
            list: self,
            next: 0,
        }
    }

    /// The number of entries.
    pub const fn len(self) -> usize {
        match self {
            List::Samplers => SAMPLERS.len(),
            List::Randomizers => RANDOMIZERS.len(),
            List::PixelSamplers => PIXEL_SAMPLERS.len(),
            List::Measures => MEASURES.len(),
            List::Integrands => INTEGRANDS.len(),
        }
    }

    /// Always `false`: every list has entries.
    pub const fn is_empty(self) -> bool {
        self.len() == 0
    }
}

/// The canonical names of a [`List`], in its order ([`List::names`]).
#[derive(Clone, Debug)]
pub struct Names {
    list: List,
    next: usize,
}

impl Iterator for Names {
    type Item = &'static str;

    fn next(&mut self) -> Option<&'static str> {
        let k = self.next;
        let name = match self.list {
            List::Samplers => SAMPLERS.get(k).map(|e| e.name),
            List::Randomizers => RANDOMIZERS.get(k).map(|e| e.name),
            List::PixelSamplers => PIXEL_SAMPLERS.get(k).map(|e| e.name),
            List::Measures => MEASURES.get(k).map(|e| e.name),
            List::Integrands => INTEGRANDS.get(k).map(|e| e.name),
        }?;
        self.next += 1;
        Some(name)
    }
}

/// Bytes of an unknown name an error keeps (longer names are cut at a character
/// boundary).
const GIVEN_BYTES: usize = 40;

/// A name as given, kept without allocating (up to 40 bytes).
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct Given {
    bytes: [u8; GIVEN_BYTES],
    len: u8,
}

impl Given {
    /// `name`, cut to at most 40 bytes at a character boundary.
    pub fn new(name: &str) -> Self {
        let mut len = name.len().min(GIVEN_BYTES);
        while !name.is_char_boundary(len) {
            len -= 1;
        }
        let mut bytes = [0u8; GIVEN_BYTES];
        if let (Some(dst), Some(src)) = (bytes.get_mut(..len), name.as_bytes().get(..len)) {
            dst.copy_from_slice(src);
        }
        Given {
            bytes,
            len: len as u8,
        }
    }

    /// The name (possibly cut).
    pub fn as_str(&self) -> &str {
        let b = self.bytes.get(..self.len as usize).unwrap_or(&[]);
        core::str::from_utf8(b).unwrap_or("")
    }
}

impl fmt::Debug for Given {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.as_str(), f)
    }
}

/// Why a name did not resolve or a combination could not be built.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CatalogError {
    /// No entry of `list` has this name; the message lists the valid names.
    Unknown {
        /// The list searched.
        list: List,
        /// The name given.
        given: Given,
    },
    /// The randomizer does not apply to the sampler ([`applies`]).
    NotApplicable {
        /// The randomizer's canonical name.
        randomizer: &'static str,
        /// The sampler's canonical name.
        sampler: &'static str,
        /// The base, when it decides the family (van der Corput).
        base: Option<u32>,
        /// The samplers it applies to, in words.
        rule: &'static str,
    },
    /// A parameter that this entry does not take.
    Unused {
        /// The entry's canonical name.
        entry: &'static str,
        /// The parameter.
        param: &'static str,
        /// Why not, in words.
        why: &'static str,
    },
    /// A parameter outside the entry's range.
    Parameter {
        /// The entry's canonical name.
        entry: &'static str,
        /// The parameter.
        param: &'static str,
        /// The value given, when it is a number.
        got: Option<u64>,
        /// What is needed, in words.
        expected: &'static str,
    },
    /// The construction itself refused (the library's error).
    Build(crate::Error),
}

impl From<crate::Error> for CatalogError {
    fn from(e: crate::Error) -> Self {
        CatalogError::Build(e)
    }
}

impl fmt::Display for CatalogError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CatalogError::Unknown { list, given } => {
                write!(
                    f,
                    "unknown {} {:?}: the {}s are ",
                    list.noun(),
                    given.as_str(),
                    list.noun()
                )?;
                for (k, name) in list.names().enumerate() {
                    if k > 0 {
                        f.write_str(", ")?;
                    }
                    f.write_str(name)?;
                }
                f.write_str(" (or one of their aliases)")
            }
            CatalogError::NotApplicable {
                randomizer,
                sampler,
                base,
                rule,
            } => {
                write!(f, "{randomizer} applies to {rule}, not {sampler}")?;
                match base {
                    Some(b) => write!(f, " in base {b}"),
                    None => Ok(()),
                }
            }
            CatalogError::Unused { entry, param, why } => {
                write!(f, "{param} does not apply to {entry} ({why})")
            }
            CatalogError::Parameter {
                entry,
                param,
                got,
                expected,
            } => match got {
                Some(v) => write!(f, "{entry}: {param} {v}: {expected}"),
                None => write!(f, "{entry}: {param}: {expected}"),
            },
            CatalogError::Build(e) => fmt::Display::fmt(e, f),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for CatalogError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            CatalogError::Build(e) => Some(e),
            _ => None,
        }
    }
}

/// The entry of `table` that `name` names.
fn find<K>(
    table: &'static [Entry<K>],
    list: List,
    name: &str,
) -> Result<&'static Entry<K>, CatalogError> {
    table
        .iter()
        .find(|e| e.matches(name))
        .ok_or(CatalogError::Unknown {
            list,
            given: Given::new(name),
        })
}

/// The sampler `name` names (canonical or alias, any case).
///
/// # Errors
/// [`CatalogError::Unknown`], listing the samplers.
pub fn sampler(name: &str) -> Result<&'static SamplerEntry, CatalogError> {
    find(SAMPLERS, List::Samplers, name)
}

/// The randomizer `name` names.
///
/// # Errors
/// [`CatalogError::Unknown`], listing the randomizers.
pub fn randomizer(name: &str) -> Result<&'static RandomizerEntry, CatalogError> {
    find(RANDOMIZERS, List::Randomizers, name)
}

/// The pixel sampler `name` names.
///
/// # Errors
/// [`CatalogError::Unknown`], listing the pixel samplers.
pub fn pixel_sampler(name: &str) -> Result<&'static PixelEntry, CatalogError> {
    find(PIXEL_SAMPLERS, List::PixelSamplers, name)
}

/// The measure `name` names.
///
/// # Errors
/// [`CatalogError::Unknown`], listing the measures.
pub fn measure(name: &str) -> Result<&'static MeasureEntry, CatalogError> {
    find(MEASURES, List::Measures, name)
}

/// The integrand `name` names.
///
/// # Errors
/// [`CatalogError::Unknown`], listing the integrands.
pub fn integrand(name: &str) -> Result<&'static IntegrandEntry, CatalogError> {
    find(INTEGRANDS, List::Integrands, name)
}

/// Shorthand for an [`Alias`] in the tables.
const fn alias(name: &'static str, source: &'static str) -> Alias {
    Alias { name, source }
}

/// Shorthand for a [`Param`] in the tables.
const fn param(
    name: &'static str,
    meaning: &'static str,
    default: &'static str,
    range: &'static str,
) -> Param {
    Param {
        name,
        meaning,
        default,
        range,
    }
}
