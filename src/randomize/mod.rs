//! Randomizations of low-discrepancy points (randomized QMC).
//!
//! A randomizer is a small `Copy` value, keyed by an integer seed, applied to a coordinate:
//! construction, randomization and ordering stay separate pieces, so "Sobol' + Owen",
//! "Sobol' + LMS + shift" or "Halton + digit permutations" are combinations, not new types.
//!
//! * Base 2 (Sobol', van der Corput, Hammersley's first two dimensions, LP), applied to the
//!   0.32 fraction by [`Randomizer::apply`]: [`DigitalShift`] (XOR), [`Owen`] (exact nested
//!   uniform scrambling), [`FastOwen`] (hash-based nested scrambling, Laine–Karras or
//!   Vegdahl), [`Lms`] (random linear matrix scramble), and [`CranleyPatterson`] (a toroidal
//!   rotation; not a digital randomization, so it does not keep nets). Pairs compose:
//!   `(Lms::new(s), DigitalShift::new(t))` applies the matrix, then the shift.
//! * Index shuffling ([`shuffle`]): Burley's shuffled scrambled Sobol' permutes the indices
//!   by a nested scramble, so that independent dimensions decorrelate.
//! * Base `b` (Halton, radical inverse): [`digits`] permutes digits inside the radical
//!   inverse: random permutations per digit position, Faure's permutations, and Owen
//!   scrambling in base `b`.
//!
//! Every base-2 randomizer here except Cranley–Patterson is a bijection on `u32` whose bit
//! `k` depends only on bits above it (a nested, "triangular" map), which is why it keeps a
//! (t, m, s)-net a (t, m, s)-net (tested for thousands of seeds).

mod lms;
mod owen;
mod shift;

pub mod digits;
pub mod shuffle;

#[cfg(feature = "std")]
pub use lms::LmsCache;
pub use lms::{Lms, LmsDimension};
pub use owen::{FastOwen, Owen, OwenHash, laine_karras, vegdahl};
pub use shift::{CranleyPatterson, DigitalShift};

use crate::error::Result;
use crate::sampler::Sampler;

/// A randomization of base-2 digital points, applied to coordinate `dim` of a point.
pub trait Randomizer {
    /// The randomized coordinate. Pure: the same `(x, dim)` always gives the same output.
    fn apply(&self, x: u32, dim: usize) -> u32;
}

/// No randomization.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Identity;

impl Randomizer for Identity {
    #[inline]
    fn apply(&self, x: u32, _dim: usize) -> u32 {
        x
    }
}

/// A reference to a randomizer is a randomizer (so `&dyn Randomizer` works).
impl<R: Randomizer + ?Sized> Randomizer for &R {
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        (**self).apply(x, dim)
    }
}

/// A boxed randomizer is a randomizer (for run-time choices).
#[cfg(feature = "std")]
impl<R: Randomizer + ?Sized> Randomizer for Box<R> {
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        (**self).apply(x, dim)
    }
}

/// Composition: apply `self.0`, then `self.1`.
impl<A: Randomizer, B: Randomizer> Randomizer for (A, B) {
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.1.apply(self.0.apply(x, dim), dim)
    }
}

/// The per-dimension seed of randomizer `seed` in dimension `dim`: a 32-bit hash, so that
/// dimensions get independent randomizations.
#[inline]
pub const fn dimension_seed(seed: u64, dim: usize) -> u32 {
    (crate::hash::hash3(seed, dim as u64, 0x5EED) >> 32) as u32
}

/// A sampler whose coordinates pass through a randomizer: `sample(i, k) = r.apply(s(i, k), k)`.
///
/// ```
/// use qmckit::randomize::{Owen, Scrambled};
/// use qmckit::{Sampler, Sobol};
/// let s = Scrambled::new(Sobol::new(2)?, Owen::new(7));
/// let p = [s.sample(5, 0)?, s.sample(5, 1)?];
/// # let _ = p;
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Scrambled<S, R> {
    sampler: S,
    randomizer: R,
}

impl<S: Sampler, R: Randomizer> Scrambled<S, R> {
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

impl<S: Sampler, R: Randomizer> Sampler for Scrambled<S, R> {
    fn dims(&self) -> usize {
        self.sampler.dims()
    }

    fn len(&self) -> u64 {
        self.sampler.len()
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        Ok(self.randomizer.apply(self.sampler.sample(index, dim)?, dim))
    }

    /// The sampler's own (sequential) fill, then the randomizer over the buffer.
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        self.sampler.fill(start, out)?;
        let dims = self.dims();
        if dims == 0 {
            return Ok(());
        }
        for row in out.chunks_exact_mut(dims) {
            for (dim, x) in row.iter_mut().enumerate() {
                *x = self.randomizer.apply(*x, dim);
            }
        }
        Ok(())
    }
}
