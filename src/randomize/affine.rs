//! Affine maps over GF(2): `x -> M x ^ c` on 0.32 fractions, the shape of the linear
//! scrambles (digital shift, [`Lms`](super::Lms), their compositions).
//!
//! A sequence whose coordinates are GF(2)-linear in the index bits (Sobol',
//! `x_i = C i`) folds such a map into its generator matrix: `M (C i) ^ c = (M C) i ^ c`, so
//! the scrambled sequence costs what the plain one does (SciPy scrambles Sobol' this way).
//! [`Scrambler::AFFINE`](super::Scrambler::AFFINE) marks the scramblers that have one, and
//! [`crate::Sampler::fill_affine`] is where a sequence takes it.

use crate::bits::gf2_mul;

/// `x -> M x ^ shift`, `M` given by the images of the 32 bits (`images[k] = M 2^k`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Affine {
    /// `M 2^k`.
    pub images: [u32; 32],
    /// `c`.
    pub shift: u32,
}

impl Affine {
    /// The identity.
    pub const IDENTITY: Affine = {
        let mut images = [0u32; 32];
        let mut k = 0;
        while k < 32 {
            images[k] = 1 << k;
            k += 1;
        }
        Affine { images, shift: 0 }
    };

    /// `x -> x ^ c`.
    pub const fn shift(c: u32) -> Affine {
        Affine {
            images: Affine::IDENTITY.images,
            shift: c,
        }
    }

    /// `M x` (without the shift). `const`; 32 AND/XOR steps.
    #[inline]
    pub const fn linear(&self, x: u32) -> u32 {
        gf2_mul(&self.images, x)
    }

    /// `M x ^ c`. `const`.
    #[inline]
    pub const fn apply(&self, x: u32) -> u32 {
        self.linear(x) ^ self.shift
    }

    /// `self`, then `next`: `x -> M_n (M x ^ c) ^ c_n`. `const`; 33 applications of `M_n`.
    pub const fn then(&self, next: &Affine) -> Affine {
        let mut images = [0u32; 32];
        let mut k = 0;
        while k < 32 {
            images[k] = next.linear(self.images[k]);
            k += 1;
        }
        Affine {
            images,
            shift: next.apply(self.shift),
        }
    }
}
