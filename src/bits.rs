//! Bit-level building blocks and conversions of 0.32 fixed-point fractions.
//!
//! Every coordinate in qmckit is a `u32` read as the fraction `x / 2^32` in `[0, 1)`. The
//! conversions here never leave that interval: in particular [`to_f32`] rounds toward zero,
//! so it never returns `1.0` (a plain `x as f32 / 2^32` does for `x >= 0xFFFF_FF80`).

/// Reverses the 32 bits of `x`: bit `k` moves to bit `31 - k`.
///
/// This *is* the base-2 radical inverse: the digits of the index mirrored around the binary
/// point, read as a 0.32 fraction. One instruction on ARMv7-M (`rbit`) and RISC-V with Zbb,
/// about a dozen elsewhere.
///
/// ```
/// assert_eq!(qmckit::bits::reverse_bits(1), 0x8000_0000);
/// assert_eq!(qmckit::bits::reverse_bits(6), 0x6000_0000); // 6 = 110b -> 0.011b = 0.375
/// ```
#[inline]
pub const fn reverse_bits(x: u32) -> u32 {
    x.reverse_bits()
}

/// The binary-reflected Gray code of `i`, `i ^ (i >> 1)`: consecutive indices differ in
/// exactly one bit, the lowest set bit of `i + 1`, which is what Sobol's sequential
/// (Antonov–Saleev) update uses.
///
/// ```
/// use qmckit::bits::{gray, gray_inverse};
/// assert_eq!(gray(2), 3);
/// assert_eq!(gray_inverse(gray(123_456)), 123_456);
/// ```
#[inline]
pub const fn gray(i: u32) -> u32 {
    i ^ (i >> 1)
}

/// Inverse of [`gray`]: bit `k` of the result is the parity of bits `k..32` of `g`.
///
/// Five shift-xor steps (a prefix-xor toward the low bits).
#[inline]
pub const fn gray_inverse(g: u32) -> u32 {
    let mut x = g;
    x ^= x >> 1;
    x ^= x >> 2;
    x ^= x >> 4;
    x ^= x >> 8;
    x ^= x >> 16;
    x
}

/// 2^-32 as a float, the weight of the lowest bit of a 0.32 fraction.
const INV_2_POW_32: f64 = 1.0 / 4_294_967_296.0;

/// `x / 2^32` as `f64`: exact (a `u32` fits the 53-bit significand).
///
/// ```
/// assert_eq!(qmckit::bits::to_f64(0x8000_0000), 0.5);
/// assert!(qmckit::bits::to_f64(u32::MAX) < 1.0);
/// ```
#[inline]
pub const fn to_f64(x: u32) -> f64 {
    // 2^20 + x 2^-32 has exponent 20 and ulp 2^-32, so its bits are those of 2^20 with `x`
    // in the low 32 significand bits; subtracting 2^20 is exact.
    f64::from_bits(0x4130_0000_0000_0000 | x as u64) - 1_048_576.0
}

/// `x / 2^32` as `f32`, rounded toward zero, so the result is always in `[0, 1)`.
///
/// Keeps the 24 leading significant bits of `x` (clears the bits below them) and scales
/// exactly by 2^-32. Values below 2^-8 are exact; the largest result is `1 - 2^-24`. The map
/// is monotone and `to_f32(x) <= x / 2^32 < to_f32(x) + ulp`. All 2^32 inputs are checked
/// by a test. Cost: a leading-zero count, a shift and a mask, one conversion.
///
/// ```
/// use qmckit::bits::to_f32;
/// assert_eq!(to_f32(u32::MAX), 1.0 - f32::EPSILON / 2.0);
/// assert_eq!(to_f32(0x4000_0000), 0.25);
/// ```
#[inline]
pub const fn to_f32(x: u32) -> f32 {
    // Number of low bits that do not fit a 24-bit significand (0 when x < 2^24).
    let drop = 8u32.saturating_sub(x.leading_zeros());
    let kept = (x >> drop) << drop;
    kept as f32 * (INV_2_POW_32 as f32)
}

/// The same function as [`to_f32`] (bit for bit, checked for all 2^32 inputs), computed with
/// `f64` arithmetic: `x / 2^32` is exact in `f64`; clearing the 29 low significand bits
/// truncates it to `f32` precision, and the final conversion is then exact. No leading-zero
/// count, so it vectorizes on hosts (SSE2/AVX2); on FPU-less microcontrollers prefer
/// [`to_f32`].
///
/// ```
/// use qmckit::bits::{to_f32, to_f32_via_f64};
/// for x in [0, 1, 0x00FF_FFFF, 0x0100_0001, 0xFFFF_FFFF] {
///     assert_eq!(to_f32_via_f64(x).to_bits(), to_f32(x).to_bits());
/// }
/// ```
#[inline]
pub const fn to_f32_via_f64(x: u32) -> f32 {
    let d = x as f64 * INV_2_POW_32;
    f64::from_bits(d.to_bits() & !((1u64 << 29) - 1)) as f32
}

/// The same function as [`to_f32`] (bit for bit, checked for all 2^32 inputs), in `u32`
/// lanes: the leading one of `x` is smeared down (`y = x | x >> 1 | .. | x >> 31` by five
/// shift-ORs), `y >> 24` masks the bits below the 24 leading significant ones, and the
/// kept value converts to `f32` exactly and scales exactly by 2^-32. No leading-zero count
/// and no `f64`, so sixteen values fill one AVX-512 vector (eight in the `f64` form of
/// [`to_f32_via_f64`]). Cost: eleven integer operations, one conversion, one multiply.
///
/// ```
/// use qmckit::bits::{to_f32, to_f32_lanes};
/// for x in [0, 1, 0x00FF_FFFF, 0x0100_0001, 0x8000_00FF, 0xFFFF_FFFF] {
///     assert_eq!(to_f32_lanes(x).to_bits(), to_f32(x).to_bits());
/// }
/// ```
#[inline]
pub const fn to_f32_lanes(x: u32) -> f32 {
    let mut y = x | (x >> 1);
    y |= y >> 2;
    y |= y >> 4;
    y |= y >> 8;
    y |= y >> 16;
    let kept = x & !(y >> 24);
    kept as f32 * (INV_2_POW_32 as f32)
}

/// The same function as [`to_f32`] (bit for bit, checked for all 2^32 inputs), for lanes
/// with a leading-zero count `lz = lz(x)`: the window of the 24 bits below and including
/// the leading one of `x` is `0xFFFF_FF00 >> lz` (bits `8 - lz ..= 31 - lz`; for `lz >= 8`
/// every bit of `x`, which is then exact; for `x = 0` the shift is out of range and the
/// window empty), so one variable shift and one AND keep the 24 leading significant bits;
/// the kept value converts to `f32` exactly and scales exactly by 2^-32. Cost: a
/// leading-zero count, two integer operations, one conversion, one multiply (an AVX-512 CD
/// build counts leading zeros in one instruction a vector, and its variable shift gives 0
/// for counts of 32 or more; without one, [`to_f32_lanes`] is the cheaper form).
///
/// ```
/// use qmckit::bits::{to_f32, to_f32_lz};
/// for x in [0, 1, 0x00FF_FFFF, 0x0100_0001, 0x8000_00FF, 0xFFFF_FFFF] {
///     assert_eq!(to_f32_lz(x).to_bits(), to_f32(x).to_bits());
/// }
/// ```
#[inline]
pub const fn to_f32_lz(x: u32) -> f32 {
    let window = match 0xFFFF_FF00u32.checked_shr(x.leading_zeros()) {
        Some(w) => w,
        None => 0, // x = 0
    };
    let kept = x & window;
    kept as f32 * (INV_2_POW_32 as f32)
}

/// [`to_f32`] of the bit reversal of `h`, `to_f32(reverse_bits(h))` (bit for bit, checked
/// for all 2^32 inputs), for pipelines that end in the reversed domain (the hash-based Owen
/// scramble). The 24 leading significant bits of `reverse(h)` are, before the reversal,
/// the 24 bits of `h` from its lowest set bit `t` up: `l = h & -h = 2^t` isolates that bit
/// and `(l << 24) - l` (mod 2^32) sets bits `t ..= min(t + 23, 31)` (the shift drops
/// `2^(t+24)` when `t + 24 >= 32`, leaving every bit from `t` up; `h = 0` gives an empty
/// window). The kept, reversed value converts to `f32` exactly and scales exactly by
/// 2^-32. Cost: five integer operations, the reversal, one conversion, one multiply; no
/// leading-zero count, so it suits vector builds without one (SSE2, AVX2).
///
/// ```
/// use qmckit::bits::{reverse_bits, reversed_to_f32, to_f32};
/// for x in [0, 1, 0x00FF_FFFF, 0x0100_0001, 0x8000_00FF, 0xFFFF_FFFF] {
///     assert_eq!(reversed_to_f32(reverse_bits(x)).to_bits(), to_f32(x).to_bits());
/// }
/// ```
#[inline]
pub const fn reversed_to_f32(h: u32) -> f32 {
    let low = h & h.wrapping_neg();
    let window = (low << 24).wrapping_sub(low);
    reverse_bits(h & window) as f32 * (INV_2_POW_32 as f32)
}

/// `x / 2^32` as a `fixed` crate `U0F32` (same bits, no rounding).
#[cfg(feature = "fixed")]
#[inline]
pub const fn to_fixed(x: u32) -> fixed::types::U0F32 {
    fixed::types::U0F32::from_bits(x)
}

/// A coordinate type that 0.32 fixed-point fractions convert into: `u32` itself (the
/// identity), `f64` ([`to_f64`], exact), `f32` ([`to_f32`], rounded toward zero, never
/// `1.0`) and, with feature `fixed`, `U0F32` ([`to_fixed`], same bits). The typed fills
/// (e.g. [`Sampler::fill_as`](crate::Sampler::fill_as)) convert as they store, so no
/// second pass over the buffer is needed.
///
/// ```
/// use qmckit::bits::FromFraction;
/// assert_eq!(f64::from_fraction(0xC000_0000), 0.75);
/// assert_eq!(f32::from_fraction(u32::MAX), 1.0 - f32::EPSILON / 2.0);
/// assert_eq!(u32::from_fraction(7), 7);
/// ```
#[cfg_attr(not(feature = "fixed"), allow(rustdoc::broken_intra_doc_links))]
pub trait FromFraction: Copy {
    /// The fraction `x / 2^32` in this type.
    fn from_fraction(x: u32) -> Self;
}

impl FromFraction for u32 {
    #[inline(always)]
    fn from_fraction(x: u32) -> Self {
        x
    }
}

impl FromFraction for f64 {
    #[inline(always)]
    fn from_fraction(x: u32) -> Self {
        to_f64(x)
    }
}

impl FromFraction for f32 {
    /// [`to_f32`]; on 64-bit targets computed as [`to_f32_lanes`] (the same bits for all
    /// 2^32 inputs, and it vectorizes).
    #[inline(always)]
    fn from_fraction(x: u32) -> Self {
        #[cfg(target_pointer_width = "64")]
        return to_f32_lanes(x);
        #[cfg(not(target_pointer_width = "64"))]
        return to_f32(x);
    }
}

#[cfg(feature = "fixed")]
impl FromFraction for fixed::types::U0F32 {
    #[inline(always)]
    fn from_fraction(x: u32) -> Self {
        to_fixed(x)
    }
}

/// `floor(num * 2^32 / den)`: the 0.32 fraction just below `num / den`, exact.
///
/// Requires `num < den < 2^32` (so the result fits); callers validate that. Outside that
/// range the result is unspecified but the function never panics (`den = 0` gives 0). Used wherever a
/// construction places point `i` of `n` at `i / n` (Hammersley, strata, Latin hypercube).
///
/// ```
/// assert_eq!(qmckit::bits::fraction(1, 3), 0x5555_5555);
/// assert_eq!(qmckit::bits::fraction(3, 4), 0xC000_0000);
/// ```
#[inline]
pub const fn fraction(num: u64, den: u64) -> u32 {
    div_u64(num << 32, den) as u32
}

/// The point at relative position `u` (a 0.32 fraction) inside cell `cell` of `n` equal
/// cells of `[0, 1)`, such that the result `x` satisfies `cell / n <= x / 2^32 < (cell + 1) / n`
/// exactly, i.e. `floor(x n / 2^32) == cell`.
///
/// The cells are the integer ranges `[ceil(cell 2^32 / n), ceil((cell + 1) 2^32 / n))`, which
/// partition the `u32`s; `u` scales into the range. Two divisions and a multiplication.
/// Requires `cell < n <= 2^32` (callers validate); otherwise the result is unspecified but
/// the function never panics.
///
/// ```
/// use qmckit::bits::in_cell;
/// assert_eq!(in_cell(1, 4, 0x8000_0000), 0x6000_0000); // middle of the second quarter
/// let x = in_cell(1, 3, 0); // the first 0.32 fraction at or above 1/3
/// assert!(x as u64 * 3 >= 1 << 32 && (x as u64 - 1) * 3 < 1 << 32);
/// ```
#[inline]
pub const fn in_cell(cell: u64, n: u64, u: u32) -> u32 {
    if n == 0 || cell >= n || n > 1 << 32 {
        return 0;
    }
    let lo = (cell << 32).div_ceil(n);
    let hi = if cell + 1 == n {
        1 << 32
    } else {
        ((cell + 1) << 32).div_ceil(n)
    };
    (lo + (((hi - lo) * u as u64) >> 32)) as u32
}

/// `a / b`, or 0 when `b == 0`: division without a panic path, for divisors the caller
/// has validated (the compiler cannot always see that they are non-zero).
#[inline]
pub(crate) const fn div_u64(a: u64, b: u64) -> u64 {
    match a.checked_div(b) {
        Some(q) => q,
        None => 0,
    }
}

/// `a % b`, or 0 when `b == 0` (see [`div_u64`]).
#[inline]
pub(crate) const fn rem_u64(a: u64, b: u64) -> u64 {
    match a.checked_rem(b) {
        Some(r) => r,
        None => 0,
    }
}

/// `a / b`, or 0 when `b == 0` (see [`div_u64`]).
#[inline]
pub(crate) const fn div_u32(a: u32, b: u32) -> u32 {
    match a.checked_div(b) {
        Some(q) => q,
        None => 0,
    }
}

/// `a % b`, or 0 when `b == 0` (see [`div_u64`]).
#[inline]
pub(crate) const fn rem_u32(a: u32, b: u32) -> u32 {
    match a.checked_rem(b) {
        Some(r) => r,
        None => 0,
    }
}

/// `M x` over GF(2) for the 32x32 bit matrix with columns `cols`: the XOR of `cols[k]` over
/// the set bits `k` of `x`. A branch-free loop of 32 AND/XOR steps (which vectorizes).
///
/// This is how a base-2 digital construction maps an index to a point (Sobol' with its
/// direction numbers as columns) and how a linear scramble maps a point to a point.
///
/// ```
/// let identity: [u32; 32] = core::array::from_fn(|k| 1 << k);
/// assert_eq!(qmckit::bits::gf2_mul(&identity, 0xDEAD_BEEF), 0xDEAD_BEEF);
/// ```
// Not inlined on purpose: inlined into some loop shapes, LLVM re-vectorizes or branches the
// 32 masked XORs and the product gets 10-15x slower (measured: 6 ns as a call, up to 92 ns
// inlined into a dims-inner loop); the call costs about a nanosecond.
#[inline(never)]
pub const fn gf2_mul(cols: &[u32; 32], x: u32) -> u32 {
    let mut acc = 0u32;
    let mut k = 0;
    while k < 32 {
        // All ones when bit k of x is set: an arithmetic shift of that bit into the sign,
        // which compilers keep branch-free (a `0 - bit` mask may turn into a branch).
        let mask = (((x << (31 - k)) as i32) >> 31) as u32;
        acc ^= cols[k] & mask;
        k += 1;
    }
    acc
}

// ---------------------------------------------------------------------------------------
// Affine maps over GF(2): `x -> M x ^ c` on 0.32 fractions, the shape of the linear
// scrambles (digital shift, LMS, their compositions; `crate::randomize::Scrambler::AFFINE`
// marks the scramblers that have one). A sequence whose coordinates are GF(2)-linear in
// the index bits (Sobol', `x_i = C i`) folds such a map into its generator matrix:
// `M (C i) ^ c = (M C) i ^ c`, so the scrambled sequence costs what the plain one does
// (SciPy scrambles Sobol' this way); `crate::sampler::Base2Digital::fill_affine` is where a
// sequence takes it. Here, in the core, so that samplers and randomizers share it.

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

    /// The bit reversal `x -> reverse(x)` (`M 2^k = 2^(31 - k)`, no shift): linear over
    /// GF(2), so a digital construction folds it into its direction numbers.
    pub const REVERSE: Affine = {
        let mut images = [0u32; 32];
        let mut k = 0;
        while k < 32 {
            images[k] = 1 << (31 - k);
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
