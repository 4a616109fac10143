//! Integer hashing and keyed permutations: the randomness of the randomized samplers,
//! as pure functions of `(seed, index, dimension)`, so every sampler stays random-access.
//!
//! All the crate's hashes live here:
//!
//! * [`mix64`], [`hash3`] (split as [`hash3_key`] and [`hash3_keyed`]), [`uniform`],
//!   [`permute`]: qmckit's own (splitmix64's finalizer,
//!   its nesting over arguments, and a keyed bijection of `[0, n)` by cycle walking); the
//!   blue-noise generator steps [`mix64`] too.
//! * [`laine_karras`], [`vegdahl`]: the nested hashes of hash-based Owen scrambling
//!   ([`crate::randomize::FastOwen`]) and of index shuffling ([`crate::randomize::shuffle`]).
//! * [`pbrt`]: pbrt-v4's hashes, bit for bit (`MixBits`, MurmurHash64A, `Hash(...)`,
//!   `PermutationElement`), which key the pixel samplers ([`crate::pixel`]) and pbrt's exact
//!   Owen scrambler ([`crate::randomize::PbrtOwenScrambler`]).

mod nested;
pub mod pbrt;

pub use nested::{laine_karras, vegdahl};
pub(crate) use nested::{vegdahl_multiplier, vegdahl_prepared};

/// A bijective 64-bit mixer: the `splitmix64` finalizer (Steele, Lea & Flood 2014, with
/// Stafford's "Mix13" constants). Every output bit depends on every input bit.
///
/// ```
/// assert_ne!(qmckit::hash::mix64(1), qmckit::hash::mix64(2));
/// ```
#[inline]
pub const fn mix64(mut x: u64) -> u64 {
    x ^= x >> 30;
    x = x.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x ^= x >> 27;
    x = x.wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^ (x >> 31)
}

/// Golden-ratio increment (2^64 / phi), the Weyl step of splitmix64.
const WEYL: u64 = 0x9E37_79B9_7F4A_7C15;

/// A 64-bit hash of `(seed, a, b)`: nested [`mix64`] with Weyl offsets, so that swapping
/// or shifting arguments gives unrelated outputs.
#[inline]
pub const fn hash3(seed: u64, a: u64, b: u64) -> u64 {
    hash3_keyed(hash3_key(seed), a, b)
}

/// The part of [`hash3`] that depends on the seed alone (its first [`mix64`]), for callers
/// hashing many `(a, b)` with one seed: `hash3(seed, a, b) == hash3_keyed(hash3_key(seed),
/// a, b)`.
///
/// ```
/// use qmckit::hash::{hash3, hash3_key, hash3_keyed};
/// let k = hash3_key(42);
/// assert!((0..4).all(|d| hash3_keyed(k, d, 7) == hash3(42, d, 7)));
/// ```
#[inline]
pub const fn hash3_key(seed: u64) -> u64 {
    mix64(seed.wrapping_add(WEYL))
}

/// [`hash3`] from the seed's part [`hash3_key`]: two [`mix64`] calls.
#[inline]
pub const fn hash3_keyed(key: u64, a: u64, b: u64) -> u64 {
    let h = mix64(key ^ a.wrapping_add(WEYL.wrapping_mul(2)));
    mix64(h ^ b.wrapping_add(WEYL.wrapping_mul(3)))
}

/// A uniform 0.32 fraction for `(seed, index, dim)`: the top 32 bits of [`hash3`].
#[inline]
pub const fn uniform(seed: u64, index: u32, dim: u64) -> u32 {
    (hash3(seed, index as u64, dim) >> 32) as u32
}

/// A keyed bijection of `[0, n)`, evaluated one element at a time: the image of `index`.
///
/// A keyed invertible mixer on `k`-bit integers, `2^(k-1) < n <= 2^k` (xor with a key,
/// multiplication by an odd constant and xor-shifts, all modulo 2^k), iterated until the
/// value falls in `[0, n)` ("cycle walking", as in Kensler 2013, "Correlated multi-jittered
/// sampling"). Since the mixer permutes `[0, 2^k)`, the walk stays on the cycle through
/// `index` and returns to `[0, n)`; fewer than two rounds are expected because `n > 2^k / 2`.
///
/// A bijection for `index < n <= 2^32`; returns 0 for `n <= 1`, and reads `n > 2^32` as
/// `2^32` (every `u32` index), so the result always fits a `u32` and is below `n`. An
/// `index >= n` is taken modulo `n` (a walk started outside `[0, n)` might never enter it).
/// `O(1)` expected.
///
/// ```
/// use qmckit::hash::permute;
/// let mut seen = [false; 10];
/// for i in 0..10 { seen[permute(i, 10, 42) as usize] = true; }
/// assert!(seen.iter().all(|&s| s));
/// ```
pub const fn permute(index: u32, n: u64, key: u64) -> u32 {
    if n <= 1 {
        return 0;
    }
    let n = if n > 1 << 32 { 1 << 32 } else { n };
    let bits = 64 - (n - 1).leading_zeros();
    let mask = if bits >= 64 {
        u64::MAX
    } else {
        (1u64 << bits) - 1
    };
    let k1 = mix64(key);
    let k2 = mix64(k1);
    let half = bits / 2 + 1;
    let mut x = index as u64 % n;
    loop {
        x = (x ^ k1) & mask;
        x = x.wrapping_mul(0x9E37_79B9_7F4A_7C15 | 1) & mask;
        x ^= x >> half;
        x = x.wrapping_add(k2) & mask;
        x = x.wrapping_mul(0xD6E8_FEB8_6659_FD93 | 1) & mask;
        x ^= x >> half;
        x = x.wrapping_mul(0xBF58_476D_1CE4_E5B9 | 1) & mask;
        x ^= x >> (half / 2 + 1);
        if x < n {
            return x as u32;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permute_is_a_bijection() {
        for n in [1u64, 2, 3, 7, 8, 9, 100, 1000, 4097] {
            for key in 0..20 {
                let mut seen = vec![false; n as usize];
                for i in 0..n as u32 {
                    let p = permute(i, n, key) as usize;
                    assert!(p < n as usize && !seen[p], "n {n} key {key} i {i}");
                    seen[p] = true;
                }
            }
        }
    }

    #[test]
    fn permute_depends_on_key() {
        let a: Vec<u32> = (0..64).map(|i| permute(i, 64, 1)).collect();
        let b: Vec<u32> = (0..64).map(|i| permute(i, 64, 2)).collect();
        assert_ne!(a, b);
        // Not the identity either.
        assert!(
            a.iter()
                .enumerate()
                .filter(|(i, p)| *i as u32 == **p)
                .count()
                < 16
        );
    }
}
