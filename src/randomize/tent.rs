//! The baker's (tent) transform and the explicit random shift, as randomizers.

use crate::randomize::{Randomizer, Randomizes, Scrambler};
use crate::sampler::Sampler;

/// The baker's transform `x -> 1 - |2x - 1|` (Hickernell 2002), applied after a random
/// shift: a shifted lattice rule followed by the tent map integrates non-periodic smooth
/// functions with the error order of periodic ones (up to `O(n^-2)`). Deterministic (no
/// seed); one shift and a compare a value.
///
/// In 0.32 fixed point: `2x` for `x < 1/2`, `2 - 2x` (mod 1) otherwise; the value `1`,
/// reached only at `x = 1/2`, is returned as `0` (the same point of the torus).
///
/// ```
/// use qmckit::randomize::Tent;
/// use qmckit::randomize::Randomizer;
/// let t = Tent.scrambler(0);
/// use qmckit::randomize::Scrambler;
/// assert_eq!(t.scramble(0x2000_0000), 0x4000_0000); // 1/8 -> 1/4
/// assert_eq!(t.scramble(0xE000_0000), 0x4000_0000); // 7/8 -> 1/4
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Tent;

/// [`Tent`] for one dimension (all dimensions are the same map).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct TentScrambler;

impl TentScrambler {
    /// `1 - |2x - 1|` in 0.32 fixed point. `const`.
    #[inline]
    pub const fn scramble(&self, x: u32) -> u32 {
        if x < 0x8000_0000 {
            x << 1
        } else {
            0u32.wrapping_sub(x << 1)
        }
    }
}

impl Scrambler for TentScrambler {
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        TentScrambler::scramble(self, x)
    }
}

impl Randomizer for Tent {
    type Scrambler = TentScrambler;
    #[inline]
    fn scrambler(&self, _dim: usize) -> TentScrambler {
        TentScrambler
    }
    #[inline]
    fn apply(&self, x: u32, _dim: usize) -> u32 {
        TentScrambler.scramble(x)
    }
}

impl<S: Sampler + ?Sized> Randomizes<S> for Tent {}

/// A shift modulo 1 by given offsets, `x + u_dim mod 1` (0.32 fractions; dimensions past
/// the offsets are not shifted). The seeded form is [`crate::randomize::CranleyPatterson`];
/// this one reproduces a known shift (e.g. QMCPy's `Lattice.shift` times `2^32`).
///
/// ```
/// use qmckit::lattice::Rank1Lattice;
/// use qmckit::randomize::{Scrambled, Shift};
/// use qmckit::Sampler;
/// let l = Scrambled::new(Rank1Lattice::linear([1u32, 3], 4)?, Shift::new([0x1000_0000u32, 0]));
/// assert_eq!(l.sample(1, 0)?, 0x5000_0000); // 1/4 + 1/16
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shift<A> {
    offsets: A,
}

impl<A: AsRef<[u32]>> Shift<A> {
    /// The shift by `offsets[dim]` in dimension `dim`.
    pub const fn new(offsets: A) -> Self {
        Shift { offsets }
    }
}

/// [`Shift`] for one dimension: `x -> x + u mod 2^32`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ShiftScrambler {
    offset: u32,
}

impl Scrambler for ShiftScrambler {
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        x.wrapping_add(self.offset)
    }
}

impl<A: AsRef<[u32]>> Randomizer for Shift<A> {
    type Scrambler = ShiftScrambler;
    #[inline]
    fn scrambler(&self, dim: usize) -> ShiftScrambler {
        ShiftScrambler {
            offset: self.offsets.as_ref().get(dim).copied().unwrap_or(0),
        }
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.scrambler(dim).scramble(x)
    }
}

impl<S: Sampler + ?Sized, A: AsRef<[u32]>> Randomizes<S> for Shift<A> {}
