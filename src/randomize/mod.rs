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
pub use shift::{CranleyPatterson, DigitalShift, DigitalShiftScrambler, RotationScrambler};
pub use tent::{Shift, ShiftScrambler, Tent, TentScrambler};

pub use crate::sampler::Base2Digital;

use crate::bits::FromFraction;
use crate::dispatch::{self, Level};
use crate::error::Result;
use crate::sampler::{Sampler, check_fill};
use kernels::{scramble_lanes_at, scramble_lanes_into_at, scramble_slice_at};

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

/// A sampler whose coordinates pass through a randomizer:
/// `sample(i, k) = r.scrambler(k).scramble(s(i, k))`. A [`Sampler`] when `R:`
/// [`Randomizes<S>`].
///
/// `sample` prepares one scrambler a call; `fill` (and so `fill_as`) runs the sampler's own
/// fill, then prepares each dimension's scrambler once: up to [`ROW_LANES`] dimensions, the
/// scramblers are laid over whole rows and applied element-wise (vectorized); above that,
/// down each dimension's column. Scramblers that work on bit-reversed values
/// ([`Scrambler::TAKES_REVERSED`]: the hash-based Owen scramble) take the sampler's
/// reversed fill where it has one ([`Base2Digital::fill_reversed`]: Sobol' in up to four
/// dimensions), which saves a reversal a value; the bits are the same.
///
/// ```
/// use qmckit::randomize::{ExactOwen, Scrambled};
/// use qmckit::{Sampler, Sobol};
/// let s = Scrambled::new(Sobol::new(2)?, ExactOwen::new(7));
/// let p = [s.sample(5, 0)?, s.sample(5, 1)?];
/// // Owen scrambling keeps the top bit's stratification: points 0 and 1 of Sobol'
/// // lie in different halves in each dimension, and so do their scrambled images.
/// assert_ne!(s.sample(4, 0)? >> 31, p[0] >> 31);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Scrambled<S, R> {
    sampler: S,
    randomizer: R,
}

impl<S, R> Scrambled<S, R> {
    /// `sampler` randomized by `randomizer`.
    pub const fn new(sampler: S, randomizer: R) -> Self {
        Scrambled {
            sampler,
            randomizer,
        }
    }

    /// The underlying sampler.
    pub const fn sampler(&self) -> &S {
        &self.sampler
    }

    /// The randomizer.
    pub const fn randomizer(&self) -> &R {
        &self.randomizer
    }
}

impl<S: Sampler, R: Randomizes<S>> Scrambled<S, R> {
    /// Lays the dimensions' scramblers over `lanes` (a whole number of rows), each prepared
    /// once; `lanes` starts as dimension 0's scrambler everywhere. In place: the array is
    /// written once and read by the kernel where it is (no copy of it to wait on).
    #[inline(always)]
    fn spread_lanes(&self, lanes: &mut [R::Scrambler]) {
        let dims = self.dims().max(1);
        for dim in 1..dims {
            let s = self.randomizer.scrambler(dim);
            for lane in lanes.iter_mut().skip(dim).step_by(dims) {
                *lane = s;
            }
        }
    }

    /// The fill of points of at most [`ROW_LANES`] dimensions (`rows` validated): the
    /// scramblers laid over `width = lane_width(dims)` lanes, prepared once for the whole
    /// request, and the CPU's build asked once. In place for `u32` (`T = u32` and `out`
    /// the sampler's own buffer), else through a stack buffer of whole lane patterns,
    /// scrambled and converted in one pass.
    #[inline]
    fn fill_rows<const W: usize, T: FromFraction>(
        &self,
        level: Level,
        width: usize,
        start: u32,
        out: &mut [T],
        in_place: Option<&mut [u32]>,
    ) -> Result<()> {
        let mut all = [self.randomizer.scrambler(0); W];
        let lanes = all.get_mut(..width).unwrap_or(&mut []);
        self.spread_lanes(lanes);
        let lanes = &*lanes;
        if let Some(xs) = in_place {
            let reversed = self.fill_source(start, xs)?;
            scramble_lanes_at(level, lanes, xs, reversed);
            return Ok(());
        }
        let dims = self.dims().max(1);
        if out.len() <= SMALL {
            let mut buf = [0u32; SMALL];
            let xs = buf.get_mut(..out.len()).unwrap_or(&mut []);
            let reversed = self.fill_source(start, xs)?;
            scramble_lanes_into_at(level, lanes, xs, out, reversed);
            return Ok(());
        }
        // Whole lane patterns a chunk (width is a multiple of dims, so whole points too).
        let chunk = ROWS_CHUNK / width * width;
        let per = chunk / dims;
        let mut buf = [0u32; ROWS_CHUNK];
        for (c, part) in out.chunks_mut(chunk).enumerate() {
            let xs = buf.get_mut(..part.len()).unwrap_or(&mut []);
            // c * per < rows, so the index is at most the last one the caller validated.
            let reversed = self.fill_source(start + (c * per) as u32, xs)?;
            scramble_lanes_into_at(level, lanes, xs, part, reversed);
        }
        Ok(())
    }

    /// The sampler's values for the scramblers: bit-reversed (`Ok(true)`) when the
    /// scrambler takes reversed input and the sampler produces it
    /// ([`Randomizes::reversed_fill`]), else the plain fill (`Ok(false)`).
    #[inline(always)]
    fn fill_source(&self, start: u32, xs: &mut [u32]) -> Result<bool> {
        if <R::Scrambler as Scrambler>::TAKES_REVERSED
            && let Some(done) = R::reversed_fill(&self.sampler, start, xs)
        {
            return done.map(|()| true);
        }
        self.sampler.fill(start, xs)?;
        Ok(false)
    }

    /// [`fill_rows`](Self::fill_rows) with the lane width of this dimension count;
    /// `dims <= ROW_LANES`.
    #[inline]
    fn fill_low<T: FromFraction>(
        &self,
        start: u32,
        out: &mut [T],
        in_place: Option<&mut [u32]>,
    ) -> Result<()> {
        let level = dispatch::level();
        let width = lane_width(self.dims());
        if width <= 16 {
            self.fill_rows::<16, T>(level, width, start, out, in_place)
        } else {
            self.fill_rows::<ROW_LANES, T>(level, width, start, out, in_place)
        }
    }
}

/// Values a chunk of [`Scrambled::fill_as`]'s long fills: each chunk restarts the
/// sampler's fill (Sobol's sequential fill rebuilds its step table and start point, a few
/// hundred operations a dimension), so 64-bit targets take 16 KiB chunks, which keep that
/// below a tenth of an operation a value and stay in the L1 cache; 32-bit targets keep
/// [`CONVERT_CHUNK`](crate::sampler::CONVERT_CHUNK) (4 KiB of stack).
#[cfg(target_pointer_width = "64")]
const ROWS_CHUNK: usize = 4096;
#[cfg(not(target_pointer_width = "64"))]
const ROWS_CHUNK: usize = crate::sampler::CONVERT_CHUNK;

/// Values [`Scrambled::fill_as`] fills through its small stack buffer (one pixel's 16
/// four-dimensional samples).
const SMALL: usize = 64;

/// A sampler with its dimensions' affine maps prepared (`Scrambled::fill_as`).
#[cfg(feature = "std")]
struct Prepared<'a, S> {
    sampler: &'a S,
    maps: &'a [Affine],
    /// The randomizer's way to the sampler's folded fill ([`Randomizes::affine_fill`]).
    fold: FoldFn<S>,
}

/// [`Randomizes::affine_fill`] of some randomizer.
#[cfg(feature = "std")]
type FoldFn<S> = fn(&S, u32, &mut [u32], &dyn Fn(usize) -> Option<Affine>) -> Option<Result<()>>;

#[cfg(feature = "std")]
impl<S: Sampler> Prepared<'_, S> {
    fn map(&self, dim: usize) -> Affine {
        self.maps.get(dim).copied().unwrap_or(Affine::IDENTITY)
    }
}

#[cfg(feature = "std")]
impl<S: Sampler> Sampler for Prepared<'_, S> {
    fn dims(&self) -> usize {
        self.sampler.dims()
    }

    fn len(&self) -> u64 {
        self.sampler.len()
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        Ok(self.map(dim).apply(self.sampler.sample(index, dim)?))
    }

    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        if let Some(done) =
            (self.fold)(self.sampler, start, out, &|dim| self.maps.get(dim).copied())
        {
            return done;
        }
        self.sampler.fill(start, out)?;
        let dims = self.dims().max(1);
        for row in out.chunks_exact_mut(dims) {
            for (dim, x) in row.iter_mut().enumerate() {
                *x = self.map(dim).apply(*x);
            }
        }
        Ok(())
    }
}

impl<S: Sampler, R: Randomizes<S>> Sampler for Scrambled<S, R> {
    fn dims(&self) -> usize {
        self.sampler.dims()
    }

    fn len(&self) -> u64 {
        self.sampler.len()
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        let x = self.sampler.sample(index, dim)?;
        Ok(self.randomizer.scrambler(dim).scramble(x))
    }

    /// With `std` and an affine scrambler, the dimensions' maps are prepared once for the
    /// whole request and folded into the sampler's fill where it can. Otherwise, up to
    /// [`ROW_LANES`] dimensions, the scramblers are prepared once for the whole request and
    /// each buffer the sampler fills is scrambled and converted in one pass (one vectorized
    /// loop in the widest build the CPU runs); wider points take the default.
    fn fill_as<T: FromFraction>(&self, start: u32, out: &mut [T]) -> Result<()>
    where
        Self: Sized,
    {
        #[cfg(feature = "std")]
        if <R::Scrambler as Scrambler>::AFFINE {
            let dims = self.dims();
            let mut maps = Vec::new();
            if maps.try_reserve_exact(dims).is_ok() {
                for dim in 0..dims {
                    match self.randomizer.scrambler(dim).affine() {
                        Some(m) => maps.push(m),
                        None => break,
                    }
                }
                if maps.len() == dims {
                    let prepared = Prepared {
                        sampler: &self.sampler,
                        maps: &maps,
                        fold: R::affine_fill,
                    };
                    return crate::sampler::fill_as_by_chunks(&prepared, start, out);
                }
            }
        }
        let dims = self.dims();
        if dims == 0 || dims > ROW_LANES {
            return crate::sampler::fill_as_by_chunks(self, start, out);
        }
        check_fill(self, start, out.len())?;
        self.fill_low(start, out, None)
    }

    /// An affine scrambler (digital shift, LMS, compositions) folded into the sampler's
    /// generator matrices where it has them ([`Base2Digital::fill_affine`]: Sobol').
    /// Otherwise the sampler's own (sequential) fill, then each dimension's scrambler,
    /// prepared once. Up to [`ROW_LANES`] dimensions the scramblers are repeated over a whole
    /// number of rows and applied element-wise to each chunk of that width; wider points have
    /// each column gathered [`COLUMN`] values at a time into a contiguous buffer, scrambled
    /// there and stored back. Both are vectorized (on x86-64 with `std` in the widest build
    /// the CPU runs).
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        if <R::Scrambler as Scrambler>::AFFINE
            && let Some(done) = R::affine_fill(&self.sampler, start, out, &|dim| {
                self.randomizer.scrambler(dim).affine()
            })
        {
            return done;
        }
        let dims = self.dims();
        if dims == 0 {
            return self.sampler.fill(start, out); // refuses zero dimensions
        }
        if dims == 1 {
            self.sampler.fill(start, out)?;
            scramble_slice_at(dispatch::level(), self.randomizer.scrambler(0), out);
            return Ok(());
        }
        if dims <= ROW_LANES {
            // Low dimensions: the scramblers repeated over whole rows, applied element-wise
            // (one scrambler prepared per dimension, copied down the lanes).
            return self.fill_low::<u32>(start, &mut [], Some(out));
        }
        self.sampler.fill(start, out)?;
        let level = dispatch::level();
        let mut tmp = [0u32; COLUMN];
        for dim in 0..dims {
            let s = self.randomizer.scrambler(dim);
            for rows in out.chunks_mut(COLUMN * dims) {
                let n = rows.len() / dims;
                for (t, row) in tmp.iter_mut().zip(rows.chunks_exact(dims)) {
                    *t = row.get(dim).copied().unwrap_or(0);
                }
                let part = tmp.get_mut(..n).unwrap_or(&mut []);
                scramble_slice_at(level, s, part);
                for (row, t) in rows.chunks_exact_mut(dims).zip(part.iter()) {
                    if let Some(x) = row.get_mut(dim) {
                        *x = *t;
                    }
                }
            }
        }
        Ok(())
    }
}

/// Values of one column [`Scrambled`]'s fill scrambles at a time (256 bytes of stack).
pub const COLUMN: usize = 64;

/// Scramblers [`Scrambled`]'s fill lays over a row-major chunk when points have at most this
/// many dimensions (the dimensions' scramblers repeated a whole number of rows).
pub const ROW_LANES: usize = 64;

/// The row-major chunk width for `dims <= ROW_LANES` dimensions: `lcm(dims, 16)` (whole
/// 16-lane vectors) when that fits in [`ROW_LANES`], else the largest multiple of `dims`
/// that does.
const fn lane_width(dims: usize) -> usize {
    let mut w = dims;
    while !w.is_multiple_of(16) && w + dims <= ROW_LANES {
        w += dims;
    }
    if w.is_multiple_of(16) {
        w
    } else {
        ROW_LANES / dims * dims
    }
}
