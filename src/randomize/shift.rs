//! Shifts: the digital shift (XOR, a base-2 digital randomization that keeps nets) and the
//! Cranley–Patterson rotation (addition modulo 1, Cranley & Patterson 1976).

use super::{Randomizer, dimension_seed};

/// Random digital shift in base 2: `x ^ s_dim`, one uniform `s_dim` per dimension. Keeps every
/// (t, m, s)-net a net with the same t; each point becomes uniform on `[0, 1)`.
///
/// ```
/// use qmckit::randomize::{DigitalShift, Randomizer};
/// let s = DigitalShift::new(1);
/// assert_eq!(s.apply(s.apply(12345, 0), 0), 12345); // an involution
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

    /// `x ^ s_dim`. `const`.
    #[inline]
    pub const fn shift(&self, x: u32, dim: usize) -> u32 {
        x ^ dimension_seed(self.seed ^ 0xD5, dim)
    }
}

impl Randomizer for DigitalShift {
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.shift(x, dim)
    }
}

/// Cranley–Patterson rotation: `x + u_dim mod 1` (wrapping `u32` addition), one uniform
/// `u_dim` per dimension. Unbiased and cheap, but not a digital randomization: it does not
/// keep (t, m, s)-nets (a rotated elementary interval straddles two), so prefer
/// [`DigitalShift`] or [`super::Owen`] for nets.
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

    /// `x + u_dim` modulo 2^32. `const`.
    #[inline]
    pub const fn rotate(&self, x: u32, dim: usize) -> u32 {
        x.wrapping_add(dimension_seed(self.seed ^ 0xC9, dim))
    }
}

impl Randomizer for CranleyPatterson {
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.rotate(x, dim)
    }
}
