//! Linear matrix scrambling (Matoušek 1998, "On the L2-discrepancy for anchored boxes"):
//! `x -> L x` over GF(2) with `L` a random nonsingular lower-triangular matrix in digit
//! order (unit diagonal), usually followed by a digital shift, as SciPy scrambles Sobol'.
//!
//! Output digit `j` is digit `j` of `x` XOR a random subset of the digits above it, so the
//! map is nested (keeps nets) and a bijection. Column `p` (input bit `p`) is `2^p` plus
//! random bits below `p`.

use super::{Base2Digital, Randomizer, Randomizes, Scrambler, dimension_seed};
use crate::bits::gf2_mul;
use crate::hash::hash3;

/// A random linear scramble for every dimension, keyed by `seed`.
///
/// Its [`Scrambler`] is the dimension's matrix, [`LmsDimension`] (32 hashes to build, 128
/// bytes), so [`super::Scrambled`]'s fills build each matrix once a call. For random access
/// across calls build the matrices once: [`Lms::dimension`] for one, [`Lms::cached`] (with
/// `std`) for many.
///
/// ```
/// use qmckit::randomize::{DigitalShift, Lms, Randomizer};
/// let scramble = (Lms::new(9), DigitalShift::new(9)); // SciPy's Sobol' scrambling
/// let d = Lms::new(9).dimension(0);
/// assert_eq!(d.apply(0x8000_0000) >> 31, 1); // the top digit is kept (unit diagonal)
/// assert_eq!(d.apply(1), 1); // the last digit only feeds itself (unit diagonal)
/// assert_eq!(scramble.scrambler(0).1.scramble(0), DigitalShift::new(9).shift(0, 0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Lms {
    seed: u64,
}

impl Lms {
    /// The scramble for `seed`.
    pub const fn new(seed: u64) -> Self {
        Lms { seed }
    }

    /// With the seed drawn from `rng`.
    #[cfg(feature = "rand_core")]
    pub fn from_rng<R: rand_core::Rng + ?Sized>(rng: &mut R) -> Self {
        Self::new(rng.next_u64())
    }

    /// The matrix of dimension `dim`. `const`; 32 hashes.
    pub const fn dimension(&self, dim: usize) -> LmsDimension {
        let key = dimension_seed(self.seed, dim) as u64;
        let mut cols = [0u32; 32];
        let mut p = 0;
        while p < 32 {
            let below = (1u32 << p).wrapping_sub(1);
            let random = (hash3(self.seed, key, p as u64) >> 32) as u32;
            cols[p] = (1 << p) | (random & below);
            p += 1;
        }
        LmsDimension { cols }
    }
}

impl Lms {
    /// The matrices of dimensions `0..dims`, built once (128 bytes each, 32 hashes each):
    /// the same scramble as `self`, at 32 AND/XOR steps a coordinate.
    ///
    /// ```
    /// use qmckit::randomize::{Lms, Randomizer};
    /// let cache = Lms::new(1).cached(3)?;
    /// assert_eq!(cache.apply(12345, 2), Lms::new(1).apply(12345, 2));
    /// assert!(Lms::new(1).cached(usize::MAX).is_err()); // 2^71 bytes: refused, no panic
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`crate::Error::TooLarge`] (`what: "bytes"`) when `128 dims` bytes exceed
    /// [`crate::size::MAX_ALLOC_BYTES`] (more than 2^23 dimensions) or the allocation fails.
    #[cfg(feature = "std")]
    pub fn cached(&self, dims: usize) -> crate::Result<LmsCache> {
        let bytes = crate::size::bytes(dims, core::mem::size_of::<LmsDimension>())?;
        let mut matrices = Vec::new();
        matrices
            .try_reserve_exact(dims)
            .map_err(|_| crate::Error::TooLarge {
                what: "bytes",
                requested: bytes as u64,
                max: crate::size::MAX_ALLOC_BYTES,
            })?;
        matrices.extend((0..dims).map(|d| self.dimension(d)));
        Ok(LmsCache {
            lms: *self,
            dims: matrices,
        })
    }
}

/// Prebuilt [`Lms`] matrices for the first dimensions (from [`Lms::cached`]); dimensions past
/// them fall back to building the matrix on the spot.
#[cfg(feature = "std")]
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LmsCache {
    lms: Lms,
    dims: Vec<LmsDimension>,
}

#[cfg(feature = "std")]
impl Randomizer for LmsCache {
    type Scrambler = LmsDimension;
    #[inline]
    fn scrambler(&self, dim: usize) -> LmsDimension {
        match self.dims.get(dim) {
            Some(m) => *m,
            None => self.lms.dimension(dim),
        }
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        match self.dims.get(dim) {
            Some(m) => m.apply(x),
            None => self.lms.dimension(dim).apply(x),
        }
    }
}

#[cfg(feature = "std")]
impl<S: Base2Digital + ?Sized> Randomizes<S> for LmsCache {
    super::base2_affine_fill!();
}

impl Randomizer for Lms {
    type Scrambler = LmsDimension;
    #[inline]
    fn scrambler(&self, dim: usize) -> LmsDimension {
        self.dimension(dim)
    }
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.dimension(dim).apply(x)
    }
}

impl<S: Base2Digital + ?Sized> Randomizes<S> for Lms {
    super::base2_affine_fill!();
}

impl Scrambler for LmsDimension {
    const AFFINE: bool = true;
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        self.apply(x)
    }
    #[inline]
    fn affine(&self) -> Option<super::Affine> {
        Some(super::Affine {
            images: self.cols,
            shift: 0,
        })
    }
}

/// One dimension's linear scramble: the 32 columns of `L` (128 bytes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LmsDimension {
    cols: [u32; 32],
}

impl LmsDimension {
    /// `L x`. `const`, 32 AND/XOR steps.
    #[inline]
    pub const fn apply(&self, x: u32) -> u32 {
        gf2_mul(&self.cols, x)
    }

    /// `L x`, the [`Scrambler`] name of [`apply`](Self::apply). `const`.
    #[inline]
    pub const fn scramble(&self, x: u32) -> u32 {
        gf2_mul(&self.cols, x)
    }

    /// `L C` for a generator matrix `C` given by its columns: the scrambled matrix, so that
    /// scrambling costs nothing per point (SciPy scrambles Sobol's direction numbers so).
    pub const fn scramble_columns(&self, cols: &[u32; 32]) -> [u32; 32] {
        let mut out = [0u32; 32];
        let mut k = 0;
        while k < 32 {
            out[k] = self.apply(cols[k]);
            k += 1;
        }
        out
    }
}
