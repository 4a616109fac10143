//! Shifts: the digital shift (XOR, a base-2 digital randomization that keeps nets) and the
//! Cranley–Patterson rotation (addition modulo 1, Cranley & Patterson 1976).

use super::{Base2Digital, Randomizer, Randomizes, Scrambler, dimension_seed};
use crate::sampler::Sampler;

/// Random digital shift in base 2: `x ^ s_dim`, one uniform `s_dim` per dimension. Keeps every
/// (t, m, s)-net a net with the same t; each point becomes uniform on `[0, 1)`.
///
/// ```
/// use qmckit::randomize::{DigitalShift, Randomizer};
/// let s = DigitalShift::new(1).scrambler(0);
/// assert_eq!(s.scramble(s.scramble(12345)), 12345); // an involution
/// assert_ne!(s.scramble(12345), 12345);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct DigitalShift {
    seed: u64,
}

impl DigitalShift {
    /// The shift for `seed`.
    pub const fn new(seed: u64) -> Self {
        DigitalShift { seed }
    }

    /// With the seed drawn from `rng`.
    #[cfg(feature = "rand_core")]
    pub fn from_rng<R: rand_core::Rng + ?Sized>(rng: &mut R) -> Self {
        Self::new(rng.next_u64())
    }

    /// The scrambler of dimension `dim`: `s_dim = dimension_seed(seed ^ 0xD5, dim)`. `const`.
    #[inline]
    pub const fn scrambler(&self, dim: usize) -> DigitalShiftScrambler {
        DigitalShiftScrambler {
            shift: dimension_seed(self.seed ^ 0xD5, dim),
        }
    }

    /// `x ^ s_dim`. `const`.
    #[inline]
    pub const fn shift(&self, x: u32, dim: usize) -> u32 {
        self.scrambler(dim).scramble(x)
    }
}

/// [`DigitalShift`] prepared for one dimension: `x -> x ^ s`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct DigitalShiftScrambler {
    shift: u32,
}

impl DigitalShiftScrambler {
    /// `x ^ s`. `const`.
    #[inline]
    pub const fn scramble(&self, x: u32) -> u32 {
        x ^ self.shift
    }
}

impl Scrambler for DigitalShiftScrambler {
    const AFFINE: bool = true;
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        DigitalShiftScrambler::scramble(self, x)
    }
    #[inline]
    fn affine(&self) -> Option<super::Affine> {
        Some(super::Affine::shift(self.shift))
    }
}

impl Randomizer for DigitalShift {
    type Scrambler = DigitalShiftScrambler;
    #[inline]
    fn scrambler(&self, dim: usize) -> DigitalShiftScrambler {
        DigitalShift::scrambler(self, dim)
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.shift(x, dim)
    }
}

impl<S: Base2Digital + ?Sized> Randomizes<S> for DigitalShift {
    super::base2_affine_fill!();
}

/// Cranley–Patterson rotation: `x + u_dim mod 1` (wrapping `u32` addition), one uniform
/// `u_dim` per dimension. Unbiased and cheap, but not a digital randomization: it does not
/// keep (t, m, s)-nets (a rotated elementary interval straddles two), so prefer
/// [`DigitalShift`] or [`super::FastOwen`] for nets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CranleyPatterson {
    seed: u64,
}

impl CranleyPatterson {
    /// The rotation for `seed`.
    pub const fn new(seed: u64) -> Self {
        CranleyPatterson { seed }
    }

    /// With the seed drawn from `rng`.
    #[cfg(feature = "rand_core")]
    pub fn from_rng<R: rand_core::Rng + ?Sized>(rng: &mut R) -> Self {
        Self::new(rng.next_u64())
    }

    /// The scrambler of dimension `dim`: `u_dim = dimension_seed(seed ^ 0xC9, dim)`. `const`.
    #[inline]
    pub const fn scrambler(&self, dim: usize) -> RotationScrambler {
        RotationScrambler {
            offset: dimension_seed(self.seed ^ 0xC9, dim),
        }
    }

    /// `x + u_dim` modulo 2^32. `const`.
    #[inline]
    pub const fn rotate(&self, x: u32, dim: usize) -> u32 {
        self.scrambler(dim).scramble(x)
    }
}

/// [`CranleyPatterson`] prepared for one dimension: `x -> x + u mod 2^32`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RotationScrambler {
    offset: u32,
}

impl RotationScrambler {
    /// `x + u` modulo 2^32. `const`.
    #[inline]
    pub const fn scramble(&self, x: u32) -> u32 {
        x.wrapping_add(self.offset)
    }
}

impl Scrambler for RotationScrambler {
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        RotationScrambler::scramble(self, x)
    }
}

impl Randomizer for CranleyPatterson {
    type Scrambler = RotationScrambler;
    #[inline]
    fn scrambler(&self, dim: usize) -> RotationScrambler {
        CranleyPatterson::scrambler(self, dim)
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.rotate(x, dim)
    }
}

/// A rotation applies to any sampler (it keeps uniformity, not nets).
impl<S: Sampler + ?Sized> Randomizes<S> for CranleyPatterson {}
