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
#[cfg(all(test, feature = "std"))]
use crate::dispatch::Level;
use crate::dispatch::{self, Kernel};
use crate::hash::pbrt::{permutation_element, permutation_round};
use crate::randomize::{FastOwenScrambler, OwenHash, PbrtOwenScrambler};

/// A fill's body as a [`Kernel`]: compiled inside each build of [`crate::dispatch`] (the
/// closure must be `#[inline(always)]`, and so must what it calls to be widened).
struct Fill<F>(F);

impl<R, F: FnOnce() -> R> Kernel for Fill<F> {
    type Output = R;
    #[inline(always)]
    fn run(self) -> R {
        (self.0)()
    }
}

/// `f()` in the widest build this CPU runs (AVX2 or AVX-512 on x86-64 with `std`; the
/// baseline build elsewhere): integer and `f32` arithmetic whose results do not depend on
/// the vector width, so every build gives the same bits.
#[inline(always)]
pub(crate) fn dispatched<R>(f: impl FnOnce() -> R) -> R {
    #[cfg(all(test, feature = "std"))]
    if let Some(want) = FORCED.with(|c| c.get()) {
        return dispatch::run_at(want, Fill(f));
    }
    dispatch::run(Fill(f))
}

#[cfg(all(test, feature = "std"))]
std::thread_local! {
    /// The build the tests ask [`dispatched`] for.
    static FORCED: core::cell::Cell<Option<Level>> = const { core::cell::Cell::new(None) };
}

/// `f()` with the fills of this thread run at the build `want` (or the widest narrower
/// one the CPU runs): for the tests that compare the builds.
#[cfg(all(test, feature = "std"))]
pub(crate) fn at_level<R>(want: Level, f: impl FnOnce() -> R) -> R {
    FORCED.with(|c| c.set(Some(want)));
    let r = f();
    FORCED.with(|c| c.set(None));
    r
}

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

/// [`permutation_round`] for `w < 2^16`, in 16-bit arithmetic: every step of the round is
/// a product, an XOR or a right shift of bits below `w` (`(i & w) >> s`), and the low 16
/// bits of a product or XOR depend only on the low 16 bits of its operands, so the round
/// reduced mod `2^16` (keys and constants truncated) gives the same value below `w + 1`.
/// Eight lanes a 128-bit multiply (`pmullw`) where the 32-bit round needs emulated 32-bit
/// products on the baseline x86-64. O(1).
#[inline(always)]
pub(crate) const fn permutation_round16(i: u16, w: u16, p: u32) -> u16 {
    let mut i = i ^ p as u16;
    i = i.wrapping_mul(0x893d);
    i ^= (p >> 16) as u16;
    i ^= (i & w) >> 4;
    i ^= (p >> 8) as u16;
    i = i.wrapping_mul(0xeb3f);
    i ^= (p >> 23) as u16;
    i ^= (i & w) >> 1;
    i = i.wrapping_mul(1 | (p >> 27) as u16);
    i = i.wrapping_mul(0xfa69);
    i ^= (i & w) >> 11;
    i = i.wrapping_mul(0xb303);
    i ^= (i & w) >> 2;
    i = i.wrapping_mul(0x1cc3);
    i ^= (i & w) >> 2;
    i = i.wrapping_mul(0xa3df);
    i &= w;
    i ^ (i >> 5)
}

/// `out[k] = PermutationElement(start + k, l, p)` (pbrt's keyed permutation of `[0, l)`,
/// [`permutation_element`]). For `l` a power of two one round of the mixer always lands
/// below `l`, so the element is `(round(i) + p) mod l` with the modulus a mask: a loop
/// without division or branch, in 16-bit lanes up to `l = 2^16`
/// ([`permutation_round16`]). Other `l` walk the cycle per element. `start + k < l`.
#[inline(always)]
pub(crate) fn permutation_fill(start: u32, l: u32, p: u32, out: &mut [u32]) {
    if l.is_power_of_two() && l <= 1 << 16 {
        let (w, s) = ((l - 1) as u16, start as u16);
        // 16-bit indices (`start + k < l <= 2^16`): lanes of 16 bits throughout.
        for (k, o) in out.iter_mut().enumerate() {
            let i = s.wrapping_add(k as u16);
            *o = (permutation_round16(i, w, p).wrapping_add(p as u16) & w) as u32;
        }
    } else if l.is_power_of_two() {
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

/// [`permutation_fill`] as a call of its own, for a fill that is not dispatched (where
/// inlining the loop costs more than the call).
#[inline(never)]
pub(crate) fn permutation_fill_call(start: u32, l: u32, p: u32, out: &mut [u32]) {
    permutation_fill(start, l, p, out);
}

/// [`permutation_fill`] into 16-bit elements, for `l <= 2^16` (the elements are below `l`;
/// a larger `l` gives their low 16 bits).
#[inline(always)]
pub(crate) fn permutation_fill16(start: u32, l: u32, p: u32, out: &mut [u16]) {
    if l.is_power_of_two() && l <= 1 << 16 {
        let (w, s) = ((l - 1) as u16, start as u16);
        for (k, o) in out.iter_mut().enumerate() {
            let i = s.wrapping_add(k as u16);
            *o = permutation_round16(i, w, p).wrapping_add(p as u16) & w;
        }
    } else {
        for (k, o) in out.iter_mut().enumerate() {
            *o = permutation_element(start.wrapping_add(k as u32), l, p) as u16;
        }
    }
}

/// `a[k]` for `k < CHUNK` (a pass's index): the modulus drops the bound check, which
/// would otherwise leave a scalar tail of up to a vector's width in the fills' loops.
#[inline(always)]
pub(crate) fn at(a: &[u32; CHUNK], k: usize) -> u32 {
    a[k % CHUNK]
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
        Randomization::None => each(
            out,
            #[inline(always)]
            |k| {
                let [a, b] = rev(k);
                [conv(reverse_bits(a)), conv(reverse_bits(b))]
            },
        ),
        Randomization::PermuteDigits => {
            // reverse(a) ^ key = reverse(a ^ reverse(key)).
            let (ka, kb) = (reverse_bits(keys[0]), reverse_bits(keys[1]));
            each(
                out,
                #[inline(always)]
                |k| {
                    let [a, b] = rev(k);
                    [conv(reverse_bits(a ^ ka)), conv(reverse_bits(b ^ kb))]
                },
            )
        }
        Randomization::FastOwen => {
            let sa = FastOwenScrambler::from_key(keys[0], OwenHash::Vegdahl);
            let sb = FastOwenScrambler::from_key(keys[1], OwenHash::Vegdahl);
            each(
                out,
                #[inline(always)]
                |k| {
                    let [a, b] = rev(k);
                    [
                        conv(reverse_bits(sa.scramble_reversed(a))),
                        conv(reverse_bits(sb.scramble_reversed(b))),
                    ]
                },
            )
        }
        Randomization::Owen => {
            let (sa, sb) = (
                PbrtOwenScrambler::new(keys[0]),
                PbrtOwenScrambler::new(keys[1]),
            );
            each(
                out,
                #[inline(always)]
                |k| {
                    let [a, b] = rev(k);
                    [
                        conv(sa.scramble(reverse_bits(a))),
                        conv(sb.scramble(reverse_bits(b))),
                    ]
                },
            )
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
        Randomization::None => each(
            out,
            #[inline(always)]
            |k| conv(reverse_bits(rev(k))),
        ),
        Randomization::PermuteDigits => {
            let kr = reverse_bits(key);
            each(
                out,
                #[inline(always)]
                |k| conv(reverse_bits(rev(k) ^ kr)),
            )
        }
        Randomization::FastOwen => {
            let s = FastOwenScrambler::from_key(key, OwenHash::Vegdahl);
            each(
                out,
                #[inline(always)]
                |k| conv(reverse_bits(s.scramble_reversed(rev(k)))),
            )
        }
        Randomization::Owen => {
            let s = PbrtOwenScrambler::new(key);
            each(
                out,
                #[inline(always)]
                |k| conv(s.scramble(reverse_bits(rev(k)))),
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every build of the prepared fills gives the portable build's bits: each Sobol'
    /// sampler under each randomization, PMJ02BN, PMJ02, independent and the blue-noise
    /// table samplers, pairs and values, `u32` and `f32`, with more samples than a pass and
    /// dimensions past the tables.
    #[cfg(feature = "std")]
    #[test]
    fn every_build_fills_the_same() {
        use super::super::{
            BlueNoiseLattice, BlueNoiseSobol, ImageSobol, IndependentPixels, PaddedSobol,
            PixelSampler, Pmj02BnTables, Pmj02Pixels, Randomization as R, ZSobol,
        };
        fn all<S: PixelSampler>(s: &S, n: usize) -> std::vec::Vec<u32> {
            let mut v = std::vec::Vec::new();
            for (x, y) in [(0, 0), (13, 7), (30, 19)] {
                for d in [0, 2, 5, 63, 1000] {
                    let (mut a, mut b) = (std::vec![[0u32; 2]; n], std::vec![[0f32; 2]; n]);
                    let (mut c, mut e) = (std::vec![0u32; n], std::vec![0f32; n]);
                    s.fill_2d(x, y, d, &mut a).unwrap();
                    s.fill_2d_f32(x, y, d, &mut b).unwrap();
                    s.fill_1d(x, y, d, &mut c).unwrap();
                    s.fill_1d_f32(x, y, d, &mut e).unwrap();
                    v.extend(a.iter().flatten());
                    v.extend(b.iter().flatten().map(|f| f.to_bits()));
                    v.extend(c);
                    v.extend(e.iter().map(|f| f.to_bits()));
                }
            }
            v
        }
        let tables = Pmj02BnTables::new(16, 3).unwrap();
        let pmj = tables.sampler(31, 20, 3).unwrap();
        let bn_sobol = BlueNoiseSobol::new(31, 20, 16, 3).unwrap();
        let bn_lattice = BlueNoiseLattice::new(31, 20, 16, 3).unwrap();
        let pmj_plain = Pmj02Pixels::new(31, 20, 16, 3).unwrap();
        let independent = IndependentPixels::new(31, 20, 16, 3).unwrap();
        for lv in crate::dispatch::levels() {
            for r in [R::None, R::PermuteDigits, R::FastOwen, R::Owen] {
                for spp in [16, 128] {
                    let z = ZSobol::new(31, 20, spp, r, 7).unwrap();
                    let p = PaddedSobol::new(31, 20, spp, r, 7).unwrap();
                    let i = ImageSobol::new(31, 20, spp, r, 7).unwrap();
                    let n = spp as usize;
                    let want = at_level(Level::Portable, || [all(&z, n), all(&p, n), all(&i, n)]);
                    let got = at_level(lv, || [all(&z, n), all(&p, n), all(&i, n)]);
                    assert!(want == got, "{lv:?} {r:?} spp {spp}");
                }
            }
            let want = at_level(Level::Portable, || all(&pmj, 16));
            assert!(want == at_level(lv, || all(&pmj, 16)), "{lv:?} pmj02bn");
            let rest = || {
                [
                    all(&bn_sobol, 16),
                    all(&bn_lattice, 16),
                    all(&pmj_plain, 16),
                    all(&independent, 16),
                ]
            };
            let want = at_level(Level::Portable, rest);
            assert!(
                want == at_level(lv, rest),
                "{lv:?} blue noise, PMJ02, independent"
            );
        }
    }

    /// The 16-bit round is the 32-bit one for every power-of-two width up to `2^16`, over
    /// hashed keys and every index of the small widths.
    #[test]
    fn round16_is_the_round() {
        for b in 0..=16 {
            let w = (1u32 << b) - 1;
            for k in 0..64u64 {
                let p = crate::hash::mix64(k) as u32;
                for i in (0..=w).step_by((w as usize >> 8) + 1) {
                    let want = permutation_round(i, w, p);
                    assert_eq!(permutation_round16(i as u16, w as u16, p) as u32, want);
                }
            }
        }
    }
}
