//! Randomizations of low-discrepancy points (randomized QMC).
//!
//! A randomizer is a small `Copy` value keyed by an integer seed. For one dimension it hands
//! out a [`Scrambler`] ([`Randomizer::scrambler`]): the dimension's seed is hashed once,
//! and the scrambler is then applied to every value of that dimension (the shape of
//! pbrt-v4's scramblers). [`Scrambled`] prepares each dimension's scrambler once per
//! `sample` or `fill` call, so a fill pays the per-dimension setup once, not per coordinate.
//! Construction, randomization and ordering stay separate pieces: "Sobol' + Owen",
//! "Sobol' + LMS + shift" or "Halton + digit permutations" are combinations, not new types.
//!
//! | randomizer | what it is | applies to | cost per value |
//! |---|---|---|---|
//! | [`DigitalShift`] | XOR with a uniform `s_d` (digital shift in base 2) | [`Base2Digital`] | 1 XOR |
//! | [`CranleyPatterson`] | `x + u_d mod 1` (Cranley & Patterson 1976); does not keep nets | any [`Sampler`] | 1 add |
//! | [`ExactOwen`] | nested uniform scrambling (Owen 1995), one random flip per bit prefix | [`Base2Digital`] | 32 hashes |
//! | [`FastOwen`] | hash-based Owen scrambling (Laine & Karras 2011, Burley 2020, Vegdahl 2021) | [`Base2Digital`] | ~12 integer ops |
//! | [`Lms`] | random lower-triangular matrix over GF(2) (Matoušek 1998) | [`Base2Digital`] | 32 AND/XOR; none in a Sobol' fill (below) |
//! | `(A, B)` | `A`, then `B` | what both apply to | sum |
//! | [`shuffle::Shuffled`] | index permutation by a nested scramble (Burley 2020) | samplers of `2^m` points | ~12 ops |
//! | [`digits::DigitScramble`] | base-`b` digit permutations, Faure, Owen in base `b` | inside [`crate::RadicalInverse`] (Halton, Hammersley, van der Corput `with_scramble`) | per digit |
//!
//! The affine scramblers (digital shift, LMS, the identity and their compositions, marked by
//! [`Scrambler::AFFINE`]) are folded into Sobol's direction numbers by `Scrambled`'s `fill`
//! ([`Affine`], [`Base2Digital::fill_affine`]): `M (C i) ^ c = (M C) i ^ c`, so a filled
//! LMS + shift Sobol' costs what the plain one does. Same bits as scrambling each value.
//!
//! Which randomizer applies to which construction is a type rule: `Scrambled<S, R>` is a
//! [`Sampler`] only when `R:` [`Randomizes<S>`]. The base-2 digital randomizers require
//! `S:` [`Base2Digital`] ([`crate::Sobol`], [`crate::LarcherPillichshammer`]); the
//! Cranley–Patterson rotation takes any sampler; base-`b` digit scrambles live inside the
//! radical inverse. So `Scrambled<Halton, FastOwen>` is not a sampler:
//!
//! ```compile_fail
//! use qmckit::randomize::{FastOwen, Scrambled};
//! use qmckit::{Halton, Sampler};
//! let s = Scrambled::new(Halton::new(2)?, FastOwen::new(1));
//! let _ = s.sample(0, 0); // error: FastOwen does not randomize Halton
//! # Ok::<(), qmckit::Error>(())
//! ```
//!
//! Every base-2 randomizer here except Cranley–Patterson is a bijection on `u32` whose bit
//! `k` depends only on bits above it (a nested, "triangular" map), which is why it keeps a
//! (t, m, s)-net a (t, m, s)-net (tested for thousands of seeds).
//!
//! ## Baking a scrambled pattern into a `const`
//!
//! The scramblers are `const fn`, so the compiler can evaluate a scrambled pattern and
//! store it in flash:
//!
//! ```
//! use qmckit::randomize::FastOwen;
//! use qmckit::digital::sobol::SobolDimension;
//! const OWEN: FastOwen = FastOwen::new(42);
//! /// 64 Owen-scrambled 2D Sobol' points, computed by the compiler.
//! const PATTERN: [[u32; 2]; 64] = {
//!     let (x, y) = match (SobolDimension::new(0), SobolDimension::new(1)) {
//!         (Ok(x), Ok(y)) => (x, y),
//!         _ => panic!(), // a compile error, never a run-time panic
//!     };
//!     let (sx, sy) = (OWEN.scrambler(0), OWEN.scrambler(1));
//!     let mut p = [[0u32; 2]; 64];
//!     let mut i = 0;
//!     while i < 64 {
//!         p[i] = [sx.scramble(x.sample(i as u32)), sy.scramble(y.sample(i as u32))];
//!         i += 1;
//!     }
//!     p
//! };
//! // The same bits as the run-time sampler.
//! use qmckit::{Sampler, Sobol, randomize::Scrambled};
//! let s = Scrambled::new(Sobol::new(2)?, OWEN);
//! assert_eq!(PATTERN[37], [s.sample(37, 0)?, s.sample(37, 1)?]);
//! # Ok::<(), qmckit::Error>(())
//! ```

mod kernels;
mod lms;
mod owen;
mod pbrt_owen;
mod scrambled;
mod shift;
mod tent;

pub mod digits;
pub mod shuffle;

pub use crate::bits::Affine;
#[cfg(feature = "std")]
pub use lms::LmsCache;
pub use lms::{Lms, LmsDimension};
#[cfg(feature = "std")]
pub use owen::ExactOwenTable;
pub use owen::{ExactOwen, ExactOwenScrambler, FastOwen, FastOwenScrambler, OwenHash};
pub use pbrt_owen::PbrtOwenScrambler;
pub use scrambled::{COLUMN, ROW_LANES, Scrambled};
pub use shift::{CranleyPatterson, DigitalShift, DigitalShiftScrambler, RotationScrambler};
pub use tent::{Shift, ShiftScrambler, Tent, TentScrambler};

pub use crate::sampler::Base2Digital;

use crate::bits::FromFraction;
use crate::error::Result;
use crate::sampler::Sampler;

/// One dimension's randomization, prepared by [`Randomizer::scrambler`]: a tiny `Copy`
/// value applied to every coordinate of that dimension.
pub trait Scrambler: Copy {
    /// Whether every scrambler of this type is affine over GF(2) (`x -> M x ^ c`) and
    /// [`affine`](Self::affine) returns its map: the digital shift, LMS, the identity and
    /// compositions of them. A linear sequence (Sobol') then folds the map into its
    /// generator matrices ([`Base2Digital::fill_affine`]).
    const AFFINE: bool = false;

    /// The randomized coordinate (a 0.32 fraction). Pure.
    fn scramble(&self, x: u32) -> u32;

    /// The map, when [`AFFINE`](Self::AFFINE): `scramble(x) == affine().apply(x)` for every
    /// `x`. `None` (the default) otherwise.
    #[inline]
    fn affine(&self) -> Option<Affine> {
        None
    }

    /// `xs[j] = lanes[j % lanes.len()].scramble(xs[j])` for every `j`: scramblers laid over
    /// a row-major buffer. The default is that loop; scramblers whose per-value work has a
    /// branch on a field shared by every lane override it with a branch-free loop the
    /// compiler can vectorize. Must give the same values as the default.
    #[inline(always)]
    fn scramble_lanes(lanes: &[Self], xs: &mut [u32]) {
        for chunk in xs.chunks_mut(lanes.len().max(1)) {
            for (x, s) in chunk.iter_mut().zip(lanes) {
                *x = s.scramble(*x);
            }
        }
    }

    /// Whether [`scramble_lanes_reversed`](Self::scramble_lanes_reversed) saves work over
    /// reversing the input first: scramblers that work on bit-reversed values (the
    /// hash-based Owen scramble, `reverse(hash(reverse(x)))`). [`Scrambled`]'s fill then
    /// asks the sampler for reversed values ([`Base2Digital::fill_reversed`]).
    const TAKES_REVERSED: bool = false;

    /// [`scramble_lanes`](Self::scramble_lanes) of bit-reversed input:
    /// `xs[j] = lanes[j % lanes.len()].scramble(reverse(xs[j]))`. The default reverses, then
    /// scrambles; must give the same values.
    #[inline(always)]
    fn scramble_lanes_reversed(lanes: &[Self], xs: &mut [u32]) {
        for x in xs.iter_mut() {
            *x = crate::bits::reverse_bits(*x);
        }
        Self::scramble_lanes(lanes, xs);
    }

    /// [`scramble_lanes`](Self::scramble_lanes) (of bit-reversed input when `reversed`:
    /// [`scramble_lanes_reversed`](Self::scramble_lanes_reversed)), then
    /// `out[j] = T::from_fraction(xs[j] & keep)` for `j` below the shorter length: what
    /// [`Scrambled`]'s converting fills run on each buffer the sampler fills. `keep` clears
    /// low bits (`u32::MAX` keeps them all). The default is [`scramble_into_by_parts`];
    /// scramblers with a vectorized lane loop fuse the two steps a vector at a time, so that
    /// the stores to `out` (the fill's memory traffic) spread over the whole loop. Must give
    /// the same values as the default; `xs` may be left changed.
    #[inline(always)]
    fn scramble_lanes_into<T: FromFraction>(
        lanes: &[Self],
        xs: &mut [u32],
        out: &mut [T],
        reversed: bool,
        keep: u32,
    ) {
        scramble_into_by_parts(lanes, xs, out, reversed, keep);
    }
}

/// Values [`scramble_into_by_parts`] scrambles, then converts, at a time (rounded to whole
/// lane patterns): 4 KiB of `u32`, in the L1 cache between the two steps.
const BY_PARTS: usize = 1024;

/// The default [`Scrambler::scramble_lanes_into`]: a few whole lane patterns at a time,
/// scrambled in place ([`Scrambler::scramble_lanes`] or, with `reversed`,
/// [`Scrambler::scramble_lanes_reversed`]), then masked with `keep` and converted.
#[inline(always)]
pub fn scramble_into_by_parts<S: Scrambler, T: FromFraction>(
    lanes: &[S],
    xs: &mut [u32],
    out: &mut [T],
    reversed: bool,
    keep: u32,
) {
    let width = lanes.len().max(1);
    let part = (BY_PARTS / width).max(1) * width;
    for (xs, out) in xs.chunks_mut(part).zip(out.chunks_mut(part)) {
        if reversed {
            S::scramble_lanes_reversed(lanes, xs);
        } else {
            S::scramble_lanes(lanes, xs);
        }
        for (y, &x) in out.iter_mut().zip(xs.iter()) {
            *y = T::from_fraction(x & keep);
        }
    }
}

/// A randomization of the coordinates of a point set, keyed by a seed.
///
/// Implementors prepare one dimension at a time ([`scrambler`](Self::scrambler): the
/// dimension's seed hashed once) and apply it per value; [`apply`](Self::apply) is the
/// one-shot form, `self.scrambler(dim).scramble(x)`, and what `dyn Randomizer` offers.
pub trait Randomizer {
    /// The prepared randomization of one dimension.
    type Scrambler: Scrambler
    where
        Self: Sized;

    /// The scrambler of dimension `dim`.
    fn scrambler(&self, dim: usize) -> Self::Scrambler
    where
        Self: Sized;

    /// Coordinate `x` of dimension `dim`, randomized: the same as
    /// `self.scrambler(dim).scramble(x)`.
    fn apply(&self, x: u32, dim: usize) -> u32;
}

/// `R: Randomizes<S>`: `R` is a valid randomization of the points of `S` (see the module
/// table), which makes `Scrambled<S, R>` a [`Sampler`].
pub trait Randomizes<S: ?Sized>: Randomizer {
    /// How [`Scrambled`]'s fill reaches the sampler's folded affine fill
    /// ([`Base2Digital::fill_affine`]): the base-2 digital randomizers, which require
    /// `S: Base2Digital`, forward to it; the default (randomizers of any sampler) answers
    /// `None`, and `Scrambled` then scrambles value by value. Only called when the
    /// scrambler is [`Scrambler::AFFINE`]; `None` may leave `out` partly written.
    ///
    /// # Errors
    /// As [`Sampler::fill`], inside the `Some`.
    #[inline]
    fn affine_fill(
        sampler: &S,
        start: u32,
        out: &mut [u32],
        maps: &dyn Fn(usize) -> Option<Affine>,
    ) -> Option<Result<()>>
    where
        Self: Sized,
    {
        let _ = (sampler, start, out, maps);
        None
    }

    /// How [`Scrambled`]'s fill reaches the sampler's bit-reversed fill
    /// ([`Base2Digital::fill_reversed`]): the base-2 digital randomizers forward to it; the
    /// default answers `None` (`out` untouched). Only called when the scrambler
    /// [`Scrambler::TAKES_REVERSED`].
    ///
    /// # Errors
    /// As [`Sampler::fill`], inside the `Some`.
    #[inline]
    fn reversed_fill(sampler: &S, start: u32, out: &mut [u32]) -> Option<Result<()>>
    where
        Self: Sized,
    {
        let _ = (sampler, start, out);
        None
    }
}

/// The bodies of [`Randomizes::affine_fill`] and [`Randomizes::reversed_fill`] for
/// randomizers of [`Base2Digital`] constructions.
macro_rules! base2_affine_fill {
    () => {
        #[inline]
        fn affine_fill(
            sampler: &S,
            start: u32,
            out: &mut [u32],
            maps: &dyn Fn(usize) -> Option<crate::randomize::Affine>,
        ) -> Option<crate::error::Result<()>> {
            sampler.fill_affine(start, out, maps)
        }
        #[inline]
        fn reversed_fill(
            sampler: &S,
            start: u32,
            out: &mut [u32],
        ) -> Option<crate::error::Result<()>> {
            sampler.fill_reversed(start, out)
        }
    };
}
pub(crate) use base2_affine_fill;

/// No randomization.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Identity;

/// The scrambler of [`Identity`]: `x -> x`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct IdentityScrambler;

impl Scrambler for IdentityScrambler {
    const AFFINE: bool = true;
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        x
    }
    #[inline]
    fn affine(&self) -> Option<Affine> {
        Some(Affine::IDENTITY)
    }
}

impl Randomizer for Identity {
    type Scrambler = IdentityScrambler;
    #[inline]
    fn scrambler(&self, _dim: usize) -> IdentityScrambler {
        IdentityScrambler
    }
    #[inline]
    fn apply(&self, x: u32, _dim: usize) -> u32 {
        x
    }
}

impl<S: Sampler + ?Sized> Randomizes<S> for Identity {}

/// A reference to a randomizer is the same randomizer.
impl<R: Randomizer> Randomizer for &R {
    type Scrambler = R::Scrambler;
    #[inline]
    fn scrambler(&self, dim: usize) -> R::Scrambler {
        (**self).scrambler(dim)
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        (**self).apply(x, dim)
    }
}

impl<S: ?Sized, R: Randomizes<S>> Randomizes<S> for &R {
    #[inline]
    fn affine_fill(
        sampler: &S,
        start: u32,
        out: &mut [u32],
        maps: &dyn Fn(usize) -> Option<Affine>,
    ) -> Option<Result<()>> {
        R::affine_fill(sampler, start, out, maps)
    }
    #[inline]
    fn reversed_fill(sampler: &S, start: u32, out: &mut [u32]) -> Option<Result<()>> {
        R::reversed_fill(sampler, start, out)
    }
}

/// The scrambler of a `&dyn Randomizer`: the trait object and the dimension, applied per
/// value through [`Randomizer::apply`] (a virtual call and the dimension's setup each
/// value; concrete randomizers prepare once).
pub struct DynScrambler<'a> {
    randomizer: &'a dyn Randomizer,
    dim: usize,
}

impl Clone for DynScrambler<'_> {
    fn clone(&self) -> Self {
        *self
    }
}

impl Copy for DynScrambler<'_> {}

impl Scrambler for DynScrambler<'_> {
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        self.randomizer.apply(x, self.dim)
    }
}

/// A trait object is a randomizer (for run-time choices).
impl<'a> Randomizer for &'a dyn Randomizer {
    type Scrambler = DynScrambler<'a>;
    #[inline]
    fn scrambler(&self, dim: usize) -> DynScrambler<'a> {
        DynScrambler {
            randomizer: *self,
            dim,
        }
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        (**self).apply(x, dim)
    }
}

/// A trait object may hold any randomizer, so it is accepted where all of them apply: on
/// [`Base2Digital`] constructions.
impl<S: Base2Digital + ?Sized> Randomizes<S> for &dyn Randomizer {
    base2_affine_fill!();
}

/// Composition: `self.0`, then `self.1`.
impl<A: Scrambler, B: Scrambler> Scrambler for (A, B) {
    const AFFINE: bool = A::AFFINE && B::AFFINE;
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        self.1.scramble(self.0.scramble(x))
    }
    #[inline]
    fn affine(&self) -> Option<Affine> {
        Some(self.0.affine()?.then(&self.1.affine()?))
    }
}

/// Composition: apply `self.0`, then `self.1`.
impl<A: Randomizer, B: Randomizer> Randomizer for (A, B) {
    type Scrambler = (A::Scrambler, B::Scrambler);
    #[inline]
    fn scrambler(&self, dim: usize) -> Self::Scrambler {
        (self.0.scrambler(dim), self.1.scrambler(dim))
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.1.apply(self.0.apply(x, dim), dim)
    }
}

impl<S: ?Sized, A: Randomizes<S>, B: Randomizes<S>> Randomizes<S> for (A, B) {
    /// Whichever of the two reaches the sampler's affine fill.
    #[inline]
    fn affine_fill(
        sampler: &S,
        start: u32,
        out: &mut [u32],
        maps: &dyn Fn(usize) -> Option<Affine>,
    ) -> Option<Result<()>> {
        match A::affine_fill(sampler, start, out, maps) {
            Some(done) => Some(done),
            None => B::affine_fill(sampler, start, out, maps),
        }
    }
}

/// The per-dimension seed of randomizer `seed` in dimension `dim`: the top 32 bits of
/// [`crate::hash::hash3`]`(seed, dim, 0x5EED)`, so that dimensions get independent
/// randomizations. Three [`crate::hash::mix64`] calls.
#[inline]
pub const fn dimension_seed(seed: u64, dim: usize) -> u32 {
    (crate::hash::hash3(seed, dim as u64, 0x5EED) >> 32) as u32
}

/// [`dimension_seed`] of dimensions `first .. first + N`, with the seed's part of the hash
/// ([`crate::hash::hash3_key`]) computed once: `1 + 2N` [`crate::hash::mix64`] calls
/// instead of `3N`, and the `N` chains independent (what a reseed per pixel pays).
///
/// ```
/// use qmckit::randomize::{dimension_seed, dimension_seeds};
/// let k: [u32; 4] = dimension_seeds(9, 2);
/// assert!((0..4).all(|j| k[j] == dimension_seed(9, 2 + j)));
/// ```
#[inline]
pub const fn dimension_seeds<const N: usize>(seed: u64, first: usize) -> [u32; N] {
    let key = crate::hash::hash3_key(seed);
    let mut out = [0u32; N];
    let mut j = 0;
    while j < N {
        let dim = first.wrapping_add(j) as u64;
        out[j] = (crate::hash::hash3_keyed(key, dim, 0x5EED) >> 32) as u32;
        j += 1;
    }
    out
}
