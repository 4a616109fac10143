//! pbrt-v4's integer hashes (`util/hash.h`, `util/math.h`), bit for bit: the 64-bit
//! finalizer `MixBits`, MurmurHash64A of packed arguments (`Hash(...)`) and Kensler's
//! `PermutationElement`. They key every pbrt sampler, so parity with pbrt needs them exactly.

/// pbrt-v4's `MixBits`: `v ^= v >> 31; v *= 0x7fb5d329728ea185; v ^= v >> 27;
/// v *= 0x81dadef4bc2dd44d; v ^= v >> 33`. A bijection of `u64`. `const`; 5 operations.
///
/// ```
/// assert_eq!(qmckit::hash::pbrt::mix_bits(1), 0xccde_22c1_faa4_d20f);
/// ```
#[inline]
pub const fn mix_bits(mut v: u64) -> u64 {
    v ^= v >> 31;
    v = v.wrapping_mul(0x7fb5_d329_728e_a185);
    v ^= v >> 27;
    v = v.wrapping_mul(0x81da_def4_bc2d_d44d);
    v ^ (v >> 33)
}

/// MurmurHash64A (Appleby), 64-bit little-endian, of `key` with `seed`: pbrt-v4's
/// `MurmurHash64A`. `const`; one multiply-xor round per 8 bytes.
///
/// ```
/// use qmckit::hash::pbrt::murmur_hash64a;
/// assert_eq!(murmur_hash64a(&[0; 8], 0), 0x7208_f7fa_198a_2d81);
/// ```
pub const fn murmur_hash64a(key: &[u8], seed: u64) -> u64 {
    const M: u64 = 0xc6a4_a793_5bd1_e995;
    const R: u32 = 47;
    let len = key.len();
    let mut h = seed ^ (len as u64).wrapping_mul(M);
    let full = len / 8 * 8;
    let mut o = 0;
    while o < full {
        let mut k = 0u64;
        let mut j = 0;
        while j < 8 {
            k |= (key[o + j] as u64) << (8 * j);
            j += 1;
        }
        k = k.wrapping_mul(M);
        k ^= k >> R;
        k = k.wrapping_mul(M);
        h ^= k;
        h = h.wrapping_mul(M);
        o += 8;
    }
    let rest = len - full;
    if rest > 0 {
        let mut j = rest;
        while j > 0 {
            j -= 1;
            h ^= (key[full + j] as u64) << (8 * j);
        }
        h = h.wrapping_mul(M);
    }
    h ^= h >> R;
    h = h.wrapping_mul(M);
    h ^ (h >> R)
}

/// pbrt-v4's `Hash(a, b)` of two 32-bit ints (`Hash(dimension, seed)`): MurmurHash64A, seed
/// 0, of their 8 little-endian bytes. `u32` arguments carry the same bits as pbrt's `int`s.
///
/// ```
/// use qmckit::hash::pbrt::hash2;
/// assert_eq!(hash2(0, 0), 0x7208_f7fa_198a_2d81);
/// assert_eq!(hash2(3, 7), 0x7ddd_e854_6997_7f6a);
/// ```
#[inline]
pub const fn hash2(a: u32, b: u32) -> u64 {
    murmur_words(&[(a as u64) | ((b as u64) << 32)], 8)
}

/// pbrt-v4's `Hash(a, b, c)` of three 32-bit ints (the Halton sampler's `Hash(base,
/// digitIndex, seed)`): MurmurHash64A, seed 0, of their 12 little-endian bytes, as one
/// whole word and a 4-byte tail. O(1).
///
/// ```
/// use qmckit::hash::pbrt::{hash3, murmur_hash64a};
/// let bytes = [5, 0, 0, 0, 2, 0, 0, 0, 9, 0, 0, 0];
/// assert_eq!(hash3(5, 2, 9), murmur_hash64a(&bytes, 0));
/// ```
#[inline]
pub const fn hash3(a: u32, b: u32, c: u32) -> u64 {
    const M: u64 = 0xc6a4_a793_5bd1_e995;
    let mut k = ((a as u64) | ((b as u64) << 32)).wrapping_mul(M);
    k ^= k >> 47;
    k = k.wrapping_mul(M);
    let mut h = 12u64.wrapping_mul(M) ^ k;
    h = h.wrapping_mul(M);
    h ^= c as u64;
    h = h.wrapping_mul(M);
    h ^= h >> 47;
    h = h.wrapping_mul(M);
    h ^ (h >> 47)
}

/// pbrt-v4's `Hash(Point2i p, int dim, int seed)`: MurmurHash64A of the 16 bytes
/// `(p.x, p.y, dim, seed)`.
///
/// ```
/// use qmckit::hash::pbrt::hash4;
/// assert_eq!(hash4(3, 5, 0, 0), 0xd539_d46e_d315_9a89);
/// ```
#[inline]
pub const fn hash4(a: u32, b: u32, c: u32, d: u32) -> u64 {
    murmur_words(
        &[
            (a as u64) | ((b as u64) << 32),
            (c as u64) | ((d as u64) << 32),
        ],
        16,
    )
}

/// [`murmur_hash64a`] of whole little-endian 64-bit words (`len = 8 * words.len()` bytes),
/// without the byte loop: the same value, for the fixed-size keys of [`hash2`], [`hash4`].
#[inline]
pub(crate) const fn murmur_words(words: &[u64], len: u64) -> u64 {
    const M: u64 = 0xc6a4_a793_5bd1_e995;
    let mut h = len.wrapping_mul(M);
    let mut w = 0;
    while w < words.len() {
        let mut k = words[w].wrapping_mul(M);
        k ^= k >> 47;
        k = k.wrapping_mul(M);
        h ^= k;
        h = h.wrapping_mul(M);
        w += 1;
    }
    h ^= h >> 47;
    h = h.wrapping_mul(M);
    h ^ (h >> 47)
}

/// pbrt-v4's `PermutationElement(i, l, p)`: element `i` of a pseudo-random permutation of
/// `[0, l)` keyed by `p` (Kensler 2013, "Correlated multi-jittered sampling": a keyed
/// bijection of the next power of two, cycle-walked into `[0, l)`, then rotated by `p` modulo 2^32).
/// For `i < l`, `l >= 1`; returns 0 for `l = 0`. `O(1)` expected (fewer than 2 rounds).
///
/// ```
/// use qmckit::hash::pbrt::permutation_element;
/// assert_eq!(permutation_element(3, 16, 0x1234_5678), 12);
/// assert_eq!(permutation_element(5, 7, 42), 3);
/// ```
pub const fn permutation_element(i: u32, l: u32, p: u32) -> u32 {
    if l == 0 {
        return 0;
    }
    let mut w = l - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    // An `i >= l` is reduced first, so the walk always starts on a cycle through [0, l).
    let mut i = i % l;
    loop {
        i = permutation_round(i, w, p);
        if i < l {
            return i.wrapping_add(p) % l; // u32 arithmetic, as in pbrt
        }
    }
}

/// One round of Kensler's keyed permutation ("Correlated Multi-Jittered Sampling", 2013):
/// an invertible mixer of `[0, w + 1)`, `w + 1` a power of two, keyed by `p`. Cycle-walking
/// it until the value falls below `l` permutes `[0, l)` ([`permutation_element`]). O(1).
#[inline]
pub const fn permutation_round(mut i: u32, w: u32, p: u32) -> u32 {
    i ^= p;
    i = i.wrapping_mul(0xe170_893d);
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i = i.wrapping_mul(0x0929_eb3f);
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i = i.wrapping_mul(1 | (p >> 27));
    i = i.wrapping_mul(0x6935_fa69);
    i ^= (i & w) >> 11;
    i = i.wrapping_mul(0x74dc_b303);
    i ^= (i & w) >> 2;
    i = i.wrapping_mul(0x9e50_1cc3);
    i ^= (i & w) >> 2;
    i = i.wrapping_mul(0xc860_a3df);
    i &= w;
    i ^= i >> 5;
    i
}
