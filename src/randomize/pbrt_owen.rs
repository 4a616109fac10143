//! pbrt-v4's exact Owen scrambler (`OwenScrambler` in pbrt-v4's `lowdiscrepancy.h`), keyed by
//! one 32-bit seed, for bit-parity with renderers built on pbrt.
//!
//! pbrt's hash-based `FastOwenScrambler(seed)` needs no new type: it is
//! [`FastOwenScrambler::from_key`](super::FastOwenScrambler::from_key)`(seed,`
//! [`OwenHash::Vegdahl`](super::OwenHash::Vegdahl)`)`, the same reversed Vegdahl hash.
//! pbrt's exact scrambler differs from [`ExactOwen`](super::ExactOwen) in how it hashes each
//! bit prefix, so it lives here.

use super::Scrambler;
use crate::hash::pbrt::mix_bits;

/// pbrt-v4's `OwenScrambler(seed)`: nested uniform scrambling (Owen 1995) with one hash per
/// bit. The top bit flips when `seed` is odd; bit `31 - b` (`b = 1..32`) flips when bit `b`
/// of `low32(MixBits((x & top_b_bits) ^ seed))` is set, so each flip depends only on the
/// bits above it. A bijection on `u32` that keeps (t, m, s)-nets. Cost: 31 [`mix_bits`].
///
/// ```
/// use qmckit::randomize::PbrtOwenScrambler;
/// assert_eq!(PbrtOwenScrambler::new(0x1234_5678).scramble(0x8000_0000), 0xbf7f_d854);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct PbrtOwenScrambler {
    seed: u32,
}

impl PbrtOwenScrambler {
    /// The scrambler of the 32-bit `seed`.
    pub const fn new(seed: u32) -> Self {
        PbrtOwenScrambler { seed }
    }

    /// The scrambled 0.32 fraction. `const`.
    pub const fn scramble(&self, x: u32) -> u32 {
        let mut v = x;
        if self.seed & 1 == 1 {
            v ^= 1 << 31;
        }
        let mut b = 1u32;
        while b < 32 {
            let mask = u32::MAX << (32 - b);
            if (mix_bits(((v & mask) ^ self.seed) as u64) as u32) & (1 << b) != 0 {
                v ^= 1 << (31 - b);
            }
            b += 1;
        }
        v
    }
}

impl Scrambler for PbrtOwenScrambler {
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        PbrtOwenScrambler::scramble(self, x)
    }
}
