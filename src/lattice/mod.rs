//! Rank-1 lattice rules, fixed-size and extensible (Sloan & Joe 1994; Cools, Kuo & Nuyens
//! 2006), with their generating vectors.
//!
//! # The point sets
//!
//! A rank-1 lattice with `n` points and generating vector `z = (z_1, .., z_s)` is
//!
//! ```text
//! x_i = frac(i z / n),        i = 0, .., n - 1      (LatticeOrder::Linear)
//! ```
//!
//! computed exactly as `floor(((i z_j) mod n) 2^32 / n)` in 64-bit integers. An
//! *extensible* (embedded) base-2 lattice is good for every `n = 2^m` in a range; its
//! sequence order is the radical-inverse order
//!
//! ```text
//! x_i = frac(phi_2(i) z),                               (LatticeOrder::RadicalInverse)
//! ```
//!
//! which in 0.32 fixed point is one wrapping multiply, `reverse_bits(i) * z_j mod 2^32`,
//! exact for every `i < 2^32`. Its first `2^m` points are the `2^m`-point linear lattice
//! (in another order), so any power-of-two prefix is a lattice rule. QMCPy's
//! `Lattice(order="RADICAL INVERSE")` and `order="LINEAR"` give the same points.
//!
//! Lattice rules integrate smooth *periodic* functions with error `O(n^-alpha (log n)^c)`
//! (alpha the smoothness); for non-periodic integrands apply the baker's (tent) transform
//! [`crate::randomize::Tent`] after a random shift (Hickernell 2002), which makes the rule
//! second-order.
//!
//! # Randomization
//!
//! The random shift `x + u mod 1` is [`crate::randomize::CranleyPatterson`] (seeded) or
//! [`crate::randomize::Shift`] (explicit offsets, e.g. to reproduce another library's shift); both apply to
//! any sampler through [`crate::randomize::Scrambled`]. `(CranleyPatterson, Tent)` is the
//! shifted, baker-transformed rule.
//!
//! # Generating vectors
//!
//! [`KUO_33002`] is Kuo's extensible base-2 vector `lattice-33002-1024-1048576.9125`
//! (order-3 weights, 9125 dimensions, `n = 2^10 .. 2^20`; QMCPy's default), shipped with
//! its provenance in `tables/LICENSE-kuo-lattice`. [`parse_lattice`] reads any vector in
//! the LDData `lattice` text format at run time; [`korobov`] makes `(1, a, a^2, ..) mod n`.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::lattice::Rank1Lattice;
//! let l = Rank1Lattice::kuo(3)?; // 2^20 points in radical-inverse order
//! // Point 2 is frac(z / 4) with z = (1, 182667, 213731): (1/4, 3/4, 3/4).
//! assert_eq!([l.sample(2, 0)?, l.sample(2, 1)?, l.sample(2, 2)?],
//!            [0x4000_0000, 0xC000_0000, 0xC000_0000]);
//! # Ok::<(), qmckit::Error>(())
//! ```

pub mod hex;
pub mod kronecker;
mod kuo;
pub mod maximin;
mod vectors;

pub use kuo::{KUO_33002, KUO_33002_DIMS};
pub use vectors::{LatticeFile, korobov, parse_lattice};

use crate::error::{Error, Result};
use crate::sampler::{FULL_RANGE, Sampler, check, check_fill};

/// The order in which a rank-1 lattice lists its points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LatticeOrder {
    /// `x_i = frac(i z / n)`: the fixed-size rule with `n` points.
    Linear,
    /// `x_i = frac(phi_2(i) z)`: the extensible order; every prefix of `2^m` points is the
    /// `2^m`-point lattice.
    RadicalInverse,
}

/// A rank-1 lattice rule: `x_i = frac(i z / n)` or, extensible, `frac(phi_2(i) z)`.
///
/// `Z` holds the generating vector (`&'static [u32]` for the shipped table, `Vec<u32>`
/// for a loaded or Korobov vector, any `AsRef<[u32]>`). Cost: one 64-bit multiply and
/// one division a value (linear order), one 32-bit multiply (radical-inverse order).
///
/// ```
/// use qmckit::Sampler;
/// use qmckit::lattice::Rank1Lattice;
/// // The Fibonacci lattice with n = 13, z = (1, 8): point 2 is (2/13, 3/13).
/// let f = Rank1Lattice::linear([1u32, 8], 13)?;
/// assert_eq!(f.sample(2, 1)?, ((3u64 << 32) / 13) as u32);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rank1Lattice<Z = &'static [u32]> {
    z: Z,
    n: u64,
    order: LatticeOrder,
}

impl Rank1Lattice<&'static [u32]> {
    /// The first `dims` components of Kuo's extensible vector [`KUO_33002`] in
    /// radical-inverse order, with `2^20` points (the vector's design range).
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`], [`Error::DimensionOutOfRange`] past 9125.
    pub fn kuo(dims: usize) -> Result<Self> {
        let z = KUO_33002.get(..dims).ok_or(Error::DimensionOutOfRange {
            dim: dims.saturating_sub(1),
            dims: KUO_33002_DIMS,
        })?;
        Self::extensible(z, 20)
    }
}

impl<Z: AsRef<[u32]>> Rank1Lattice<Z> {
    /// The fixed-size rule `frac(i z / n)`, `i < n`, with the components reduced mod `n`.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`] past `2^32`,
    /// [`Error::ZeroDimensions`] for an empty `z`.
    pub fn linear(z: Z, n: u64) -> Result<Self> {
        crate::sampler::check_set(n, z.as_ref().len())?;
        Ok(Rank1Lattice {
            z,
            n,
            order: LatticeOrder::Linear,
        })
    }

    /// The extensible rule `frac(phi_2(i) z)` with `2^m_max` points (`m_max <= 32`): its
    /// first `2^m` points, `m <= m_max`, are the linear rule with `n = 2^m`.
    ///
    /// # Errors
    /// [`Error::MTooLarge`] past 32, [`Error::ZeroDimensions`].
    pub fn extensible(z: Z, m_max: u32) -> Result<Self> {
        if m_max > 32 {
            return Err(Error::MTooLarge { m: m_max, max: 32 });
        }
        let n = 1u64 << m_max;
        crate::sampler::check_set(n, z.as_ref().len())?;
        Ok(Rank1Lattice {
            z,
            n,
            order: LatticeOrder::RadicalInverse,
        })
    }

    /// The generating vector.
    pub fn vector(&self) -> &[u32] {
        self.z.as_ref()
    }

    /// The order of the points.
    pub const fn order(&self) -> LatticeOrder {
        self.order
    }

    /// Coordinate `dim` of point `index`, unchecked beyond the vector's length (0 past it).
    #[inline]
    fn value(&self, index: u32, z: u32) -> u32 {
        match self.order {
            LatticeOrder::RadicalInverse => index.reverse_bits().wrapping_mul(z),
            LatticeOrder::Linear => {
                let k = (index as u64 * z as u64) % self.n;
                // k < n <= 2^32, so k << 32 fits and the quotient is below 2^32.
                ((k << 32) / self.n) as u32
            }
        }
    }
}

impl<Z: AsRef<[u32]>> Sampler for Rank1Lattice<Z> {
    fn dims(&self) -> usize {
        self.z.as_ref().len()
    }

    fn len(&self) -> u64 {
        self.n
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        let z = self.z.as_ref();
        check(index, self.n, dim, z.len())?;
        Ok(self.value(index, z.get(dim).copied().unwrap_or(0)))
    }

    /// Row by row; in radical-inverse order the bit reversal is done once a point. Same
    /// values as [`sample`](Sampler::sample).
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        check_fill(self, start, out.len())?;
        let z = self.z.as_ref();
        for (k, row) in out.chunks_exact_mut(z.len().max(1)).enumerate() {
            let index = start + k as u32;
            match self.order {
                LatticeOrder::RadicalInverse => {
                    let r = index.reverse_bits();
                    for (x, &zj) in row.iter_mut().zip(z) {
                        *x = r.wrapping_mul(zj);
                    }
                }
                LatticeOrder::Linear => {
                    for (x, &zj) in row.iter_mut().zip(z) {
                        *x = self.value(index, zj);
                    }
                }
            }
        }
        Ok(())
    }
}

/// `2^32`, the most points a lattice here can have.
pub const MAX_POINTS: u64 = FULL_RANGE;
