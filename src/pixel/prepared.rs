//! The shared pieces of the prepared per-pixel fills ([`PixelSampler::fill_2d`] and
//! kin): Sobol' dimension 1 in the bit-reversed domain, a pixel's index permutation in one
//! pass, and the randomizations applied to reversed values, each as a loop over the
//! samples with the randomization chosen once outside it.
//!
//! In the reversed domain (bit `k` of a value is the coefficient of `2^-(k+1)`), Sobol'
//! dimension 0 of an index is the index itself, dimension 1 is the superset-XOR
//! transform of it ([`sobol1_reversed`]), and hash-based Owen scrambling is a hash of the
//! reversed value (Laine & Karras 2011; Burley 2020): so a scrambled value costs one bit
//! reversal, at the end, instead of three.
//!
//! [`PixelSampler::fill_2d`]: super::PixelSampler::fill_2d

use super::Randomization;
use crate::bits::reverse_bits;
use crate::hash::pbrt::{permutation_element, permutation_round};
use crate::randomize::{FastOwenScrambler, OwenHash, PbrtOwenScrambler};

/// Samples handled per pass of a fill: the size of the fills' stack scratch.
pub(crate) const CHUNK: usize = 64;

/// Sobol' dimension 1 (the Pascal matrix mod 2) of a 32-bit index, bit-reversed:
/// `reverse(sobol1(i))`. [`super::sobol1`] sets bit `P` of its value to the XOR of the bits
/// `31 - S` of `i` over the subsets `S ⊆ P` (as 5-bit sets, Lucas' theorem); reversed, bit
/// `Q = 31 - P` is the XOR of `i`'s bits `T ⊇ Q` (`T = 31 - S`): the superset-XOR
/// transform, one shift-mask-XOR per bit of the position and no reversal. Linear over
/// GF(2). O(1).
#[inline]
pub(crate) const fn sobol1_reversed(i: u32) -> u32 {
    let mut v = i;
    v ^= (v >> 1) & 0x5555_5555;
    v ^= (v >> 2) & 0x3333_3333;
    v ^= (v >> 4) & 0x0f0f_0f0f;
    v ^= (v >> 8) & 0x00ff_00ff;
    v ^ ((v >> 16) & 0x0000_ffff)
}

/// `out[k] = PermutationElement(start + k, l, p)` (pbrt's keyed permutation of `[0, l)`,
/// [`permutation_element`]). For `l` a power of two one round of the mixer always lands
/// below `l`, so the element is `(round(i) + p) mod l` with the modulus a mask: a loop
/// without division or branch. Other `l` walk the cycle per element. `start + k < l`.
#[inline]
pub(crate) fn permutation_fill(start: u32, l: u32, p: u32, out: &mut [u32]) {
    if l.is_power_of_two() {
        let w = l - 1;
        for (k, o) in out.iter_mut().enumerate() {
            let i = start.wrapping_add(k as u32);
            *o = permutation_round(i, w, p).wrapping_add(p) & w;
        }
    } else {
        for (k, o) in out.iter_mut().enumerate() {
            *o = permutation_element(start.wrapping_add(k as u32), l, p);
        }
    }
}

/// `out[k] = f(k)`: the fills' loop, kept small so that it vectorizes.
#[inline(always)]
fn each<T>(out: &mut [T], f: impl Fn(usize) -> T) {
    for (k, o) in out.iter_mut().enumerate() {
        *o = f(k);
    }
}

/// `out[k] = [conv(r.apply(reverse(a), key0)), conv(r.apply(reverse(b), key1))]` with
/// `[a, b] = rev(k)`: the randomization of a pair of values given bit-reversed
/// ([`Randomization::apply`] of the plain values; bit-identical), the match outside the
/// loop. `FastOwen` hashes the reversed values directly (one reversal a value).
#[inline(always)]
pub(crate) fn randomize_pairs<T>(
    r: Randomization,
    keys: [u32; 2],
    out: &mut [[T; 2]],
    rev: impl Fn(usize) -> [u32; 2],
    conv: impl Fn(u32) -> T,
) {
    match r {
        Randomization::None => each(out, |k| {
            let [a, b] = rev(k);
            [conv(reverse_bits(a)), conv(reverse_bits(b))]
        }),
        Randomization::PermuteDigits => {
            // reverse(a) ^ key = reverse(a ^ reverse(key)).
            let (ka, kb) = (reverse_bits(keys[0]), reverse_bits(keys[1]));
            each(out, |k| {
                let [a, b] = rev(k);
                [conv(reverse_bits(a ^ ka)), conv(reverse_bits(b ^ kb))]
            })
        }
        Randomization::FastOwen => {
            let sa = FastOwenScrambler::from_key(keys[0], OwenHash::Vegdahl);
            let sb = FastOwenScrambler::from_key(keys[1], OwenHash::Vegdahl);
            each(out, |k| {
                let [a, b] = rev(k);
                [
                    conv(reverse_bits(sa.scramble_reversed(a))),
                    conv(reverse_bits(sb.scramble_reversed(b))),
                ]
            })
        }
        Randomization::Owen => {
            let (sa, sb) = (
                PbrtOwenScrambler::new(keys[0]),
                PbrtOwenScrambler::new(keys[1]),
            );
            each(out, |k| {
                let [a, b] = rev(k);
                [
                    conv(sa.scramble(reverse_bits(a))),
                    conv(sb.scramble(reverse_bits(b))),
                ]
            })
        }
    }
}

/// [`randomize_pairs`] for single values.
#[inline(always)]
pub(crate) fn randomize_values<T>(
    r: Randomization,
    key: u32,
    out: &mut [T],
    rev: impl Fn(usize) -> u32,
    conv: impl Fn(u32) -> T,
) {
    match r {
        Randomization::None => each(out, |k| conv(reverse_bits(rev(k)))),
        Randomization::PermuteDigits => {
            let kr = reverse_bits(key);
            each(out, |k| conv(reverse_bits(rev(k) ^ kr)))
        }
        Randomization::FastOwen => {
            let s = FastOwenScrambler::from_key(key, OwenHash::Vegdahl);
            each(out, |k| conv(reverse_bits(s.scramble_reversed(rev(k)))))
        }
        Randomization::Owen => {
            let s = PbrtOwenScrambler::new(key);
            each(out, |k| conv(s.scramble(reverse_bits(rev(k)))))
        }
    }
}
