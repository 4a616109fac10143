//! Run-time CPU-feature dispatch: the only module of the crate with `unsafe` code.
//!
//! A kernel is written once as safe, `#[inline(always)]` Rust and compiled here several
//! times inside `#[target_feature]` functions (the compiler vectorizes it to each build's
//! width). Calling a `#[target_feature]` function is `unsafe` because running it on a CPU
//! without those features is undefined behaviour; every call below is made only after
//! [`std::arch::is_x86_feature_detected!`] reported all of the function's features on the
//! running CPU, which is the whole safety condition (the functions take only safe,
//! bounds-checked slices). Without `std` or off x86-64 only the portable build exists.
//!
//! This module is a leaf: it knows none of its clients and imports nothing of the crate
//! (checked by `scripts/check_layers.py`). A kernel lives with its owner (the Owen-Sobol'
//! fill in `digital::sobol`, the scramblers' loops in `randomize`, the conversion in
//! `sampler`): a struct holding its arguments that implements [`Kernel`] (safe code,
//! `#[inline(always)]`), an entry point calling [`run`] / [`run_at`] (integer builds) or
//! [`run_float`] (floating-point builds), and a test next to it that runs every build the
//! CPU has ([`levels`]) against the portable one. The `#[target_feature]` wrappers and the
//! detection are written once, here, and so are the few instructions that plain Rust does
//! not produce, as methods of [`Avx512`], the proof value the AVX-512 build hands its
//! kernel ([`Kernel::run_avx512`]).
#![allow(unsafe_code)]

/// The widest build this CPU runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Level {
    /// The target's baseline (SSE2 on x86-64).
    Portable,
    /// AVX2.
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    Avx2,
    /// AVX-512 F, BW, VL, CD, DQ with GFNI.
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    Avx512Gfni,
}

/// The widest build this CPU runs, detected once per process and cached (one relaxed
/// atomic load a call after the first).
#[inline]
pub(crate) fn level() -> Level {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    {
        use core::sync::atomic::{AtomicU8, Ordering};
        // 0: not detected yet; 1 + the level's index otherwise.
        static CACHED: AtomicU8 = AtomicU8::new(0);
        match CACHED.load(Ordering::Relaxed) {
            1 => return Level::Portable,
            2 => return Level::Avx2,
            3 => return Level::Avx512Gfni,
            _ => {}
        }
        let detected = detect();
        let code = match detected {
            Level::Portable => 1,
            Level::Avx2 => 2,
            Level::Avx512Gfni => 3,
        };
        CACHED.store(code, Ordering::Relaxed);
        detected
    }
    #[cfg(not(all(feature = "std", target_arch = "x86_64")))]
    Level::Portable
}

/// The builds [`run_at`] can run on this CPU, narrowest first: what a kernel's test loops
/// over.
#[cfg(all(test, feature = "std"))]
pub(crate) fn levels() -> Vec<Level> {
    #[allow(unused_mut)]
    let mut levels = vec![Level::Portable];
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    {
        if level() != Level::Portable {
            levels.push(Level::Avx2);
        }
        if level() == Level::Avx512Gfni {
            levels.push(Level::Avx512Gfni);
        }
    }
    levels
}

/// Asks the CPU (the standard library caches the CPUID answers).
#[cfg(all(feature = "std", target_arch = "x86_64"))]
fn detect() -> Level {
    if std::arch::is_x86_feature_detected!("avx512f")
        && std::arch::is_x86_feature_detected!("avx512bw")
        && std::arch::is_x86_feature_detected!("avx512vl")
        && std::arch::is_x86_feature_detected!("avx512cd")
        && std::arch::is_x86_feature_detected!("avx512dq")
        && std::arch::is_x86_feature_detected!("gfni")
    {
        return Level::Avx512Gfni;
    }
    if std::arch::is_x86_feature_detected!("avx2") {
        return Level::Avx2;
    }
    Level::Portable
}

/// `k.run()` in the widest build this CPU runs.
#[inline]
pub(crate) fn run<K: Kernel>(k: K) -> K::Output {
    run_at(level(), k)
}

/// A computation compiled once per build: `run` must be `#[inline(always)]`, so that its
/// body is compiled inside each build's `#[target_feature]` function (and vectorized to
/// that width) rather than called from it. Integer kernels run through [`run_at`], float
/// kernels through [`run_float`].
pub(crate) trait Kernel {
    /// What the kernel returns.
    type Output;
    /// The computation (safe code; `#[inline(always)]`).
    fn run(self) -> Self::Output;
    /// The computation in the AVX-512 GFNI build of [`run_at`], handed the proof that the
    /// CPU has that build's features (for the instructions of [`Avx512`]); `run` unless the
    /// kernel says otherwise. `#[inline(always)]` too.
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    #[inline(always)]
    fn run_avx512(self, _cpu: Avx512) -> Self::Output
    where
        Self: Sized,
    {
        self.run()
    }
}

/// Proof that the running CPU has the features of the AVX-512 GFNI build (avx512f, bw, vl,
/// cd, dq, gfni): only `run_int_avx512` makes a value of this type (its field is private to
/// this module), and that function runs only after [`level`] detected those features. The
/// features belong to the CPU, not to the code, so the proof holds wherever the value goes.
/// Its methods are the few AVX-512 instructions that safe Rust does not produce from plain
/// code, as operations on arrays of lanes (which, inlined into the AVX-512 build, stay in
/// vector registers).
#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx512(());

#[cfg(all(feature = "std", target_arch = "x86_64"))]
impl Avx512 {
    /// Each lane `x` as the largest `f32` at most `x` (`x` converted rounding toward zero:
    /// its 24 leading significant bits, exact below 2^24): one `vcvtudq2ps` with the
    /// embedded rounding `{rz-sae}` for the sixteen lanes.
    #[inline(always)]
    pub(crate) fn u32_to_f32_toward_zero(self, x: [u32; 16]) -> [f32; 16] {
        use core::arch::x86_64::{
            __m512, __m512i, _MM_FROUND_NO_EXC, _MM_FROUND_TO_ZERO, _mm512_cvt_roundepu32_ps,
        };
        // SAFETY: `[u32; 16]` and `__m512i`, and `__m512` and `[f32; 16]`, are 64 bytes each
        // with every bit pattern valid, so both transmutes are sound. The intrinsic requires
        // avx512f, which `self` proves the CPU has (see the type); its rounding argument is
        // a valid constant (toward zero, exceptions suppressed).
        unsafe {
            let v = core::mem::transmute::<[u32; 16], __m512i>(x);
            let f = _mm512_cvt_roundepu32_ps::<{ _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC }>(v);
            core::mem::transmute::<__m512, [f32; 16]>(f)
        }
    }
}

#[cfg(all(feature = "std", target_arch = "x86_64"))]
impl Avx512 {
    /// `a == b`, lane by lane for all 16 lanes: one `vpcmpneqd` into a mask register and a
    /// test of the mask (the compiler's own form of the 16 comparisons gathers the lanes
    /// piecewise, about ten instructions).
    #[inline(always)]
    pub(crate) fn lanes_equal(self, a: [u32; 16], b: [u32; 16]) -> bool {
        use core::arch::x86_64::{__m512i, _mm512_cmpneq_epi32_mask};
        // SAFETY: `[u32; 16]` and `__m512i` are both 64 bytes with every bit pattern valid,
        // so the transmutes are sound. The intrinsic requires avx512f, which `self` proves
        // the CPU has (see the type).
        unsafe {
            let a = core::mem::transmute::<[u32; 16], __m512i>(a);
            let b = core::mem::transmute::<[u32; 16], __m512i>(b);
            _mm512_cmpneq_epi32_mask(a, b) == 0
        }
    }
}

/// `k.run()` in the widest build that is at most `want` and that the CPU runs. Inlined
/// into its caller, so the kernel's arguments are passed on without another copy.
#[inline(always)]
pub(crate) fn run_at<K: Kernel>(want: Level, k: K) -> K::Output {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    let detected = level();
    match want {
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        Level::Avx512Gfni if detected == Level::Avx512Gfni => {
            // SAFETY: `run_int_avx512` requires avx512f, avx512bw, avx512vl, avx512cd,
            // avx512dq and gfni; `level()` answers Avx512Gfni only when `detect()` found all
            // six on this CPU (the cache holds that answer, never another). The kernel
            // itself is safe code; the `Avx512` proof it receives states the same fact.
            unsafe { run_int_avx512(k) }
        }
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        Level::Avx2 | Level::Avx512Gfni if detected != Level::Portable => {
            // SAFETY: `run_int_avx2` requires avx2; `level()` returns Avx2 or Avx512Gfni
            // only when avx2 was detected on this CPU (every AVX-512 CPU has AVX2, and the
            // Avx2 answer is its own detection). The kernel itself is safe code.
            unsafe { run_int_avx2(k) }
        }
        _ => k.run(),
    }
}

#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx2")]
fn run_int_avx2<K: Kernel>(k: K) -> K::Output {
    k.run()
}

/// With AVX-512 the 16 lanes of a `u32` kernel are one vector, and a bit reversal is a GFNI
/// affine transform plus a byte shuffle. The one place that makes an [`Avx512`] proof: this
/// function is entered only from `run_at` after `level()` detected its features.
#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx512f,avx512bw,avx512vl,avx512cd,avx512dq,gfni")]
fn run_int_avx512<K: Kernel>(k: K) -> K::Output {
    k.run_avx512(Avx512(()))
}

/// The builds of a floating-point kernel ([`run_float`]). A build the CPU lacks falls back
/// to the next narrower one it has (detected at run time, x86-64 with `std` only; elsewhere
/// every build is the portable one).
#[cfg(feature = "analysis")]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FloatBuild {
    /// The baseline target features (SSE2 on x86-64). Only tests ask for it explicitly.
    #[cfg_attr(not(test), allow(dead_code))]
    Portable,
    /// AVX2 and FMA: 4 `f64` lanes a register.
    Avx2,
    /// AVX-512 (F, VL), AVX2 and FMA: 8 `f64` lanes a register.
    Avx512,
}

/// The build [`run_float`] runs for `want`: `want`, or the widest narrower one this CPU
/// runs (the cost models of the analysis ask it too).
#[cfg(feature = "analysis")]
#[inline]
pub(crate) fn float_build(want: FloatBuild) -> FloatBuild {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    {
        use std::arch::is_x86_feature_detected as has;
        let avx2 = has!("avx2") && has!("fma");
        if want == FloatBuild::Avx512 && avx2 && has!("avx512f") && has!("avx512vl") {
            return FloatBuild::Avx512;
        }
        if want != FloatBuild::Portable && avx2 {
            return FloatBuild::Avx2;
        }
    }
    let _ = want;
    FloatBuild::Portable
}

/// `k.run()` in the build `want`, or the widest narrower one this CPU runs
/// ([`float_build`]).
#[cfg(feature = "analysis")]
#[inline]
pub(crate) fn run_float<K: Kernel>(want: FloatBuild, k: K) -> K::Output {
    match float_build(want) {
        // SAFETY: `float_build` answers `Avx512` only after detecting AVX-512F, AVX-512VL,
        // AVX2 and FMA on this CPU, which `run_avx512` requires; the kernel is safe code.
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        FloatBuild::Avx512 => unsafe { run_avx512(k) },
        // SAFETY: `float_build` answers `Avx2` only after detecting AVX2 and FMA on this
        // CPU, which `run_avx2` requires; the kernel is safe code.
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        FloatBuild::Avx2 => unsafe { run_avx2(k) },
        _ => k.run(),
    }
}

#[cfg(all(feature = "analysis", target_arch = "x86_64"))]
#[target_feature(enable = "avx2,fma")]
fn run_avx2<K: Kernel>(k: K) -> K::Output {
    k.run()
}

#[cfg(all(feature = "analysis", target_arch = "x86_64"))]
#[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
fn run_avx512<K: Kernel>(k: K) -> K::Output {
    k.run()
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    /// A kernel whose result depends on every lane: bit reversal, rotation, multiplication
    /// and a horizontal XOR (what the integer kernels of the crate use).
    struct Mix<'a> {
        xs: &'a [u32],
        out: &'a mut [u32],
    }

    impl Kernel for Mix<'_> {
        type Output = u32;
        #[inline(always)]
        fn run(self) -> u32 {
            let mut acc = 0u32;
            for (o, &x) in self.out.iter_mut().zip(self.xs) {
                *o = x.reverse_bits().rotate_left(7).wrapping_mul(0x9E37_79B9) ^ (x >> 3);
                acc ^= *o;
            }
            acc
        }
    }

    /// Every build `run_at` can reach (each `unsafe` call above: the AVX2 and AVX-512 GFNI
    /// wrappers, reached only after detection) gives the portable build's values, and a
    /// request for a build the CPU lacks falls back to one it has.
    #[test]
    fn every_integer_build_gives_the_portable_values() {
        let xs: Vec<u32> = (0..1003u32).map(|k| k.wrapping_mul(0x85EB_CA6B)).collect();
        let mut want = vec![0u32; xs.len()];
        let want_acc = Mix {
            xs: &xs,
            out: &mut want,
        }
        .run();
        println!("builds run: {:?}", levels());
        #[allow(unused_mut)]
        let mut asked = vec![Level::Portable];
        #[cfg(target_arch = "x86_64")]
        asked.extend([Level::Avx2, Level::Avx512Gfni]);
        for lv in asked {
            let mut got = vec![0u32; xs.len()];
            let acc = run_at(
                lv,
                Mix {
                    xs: &xs,
                    out: &mut got,
                },
            );
            assert_eq!((acc, &got), (want_acc, &want), "{lv:?}");
        }
        let mut got = vec![0u32; xs.len()];
        assert_eq!(
            run(Mix {
                xs: &xs,
                out: &mut got
            }),
            want_acc
        );
        assert_eq!(got, want);
    }

    /// The AVX-512 build's conversion rounding toward zero (`Avx512`, reached only through
    /// `run_at` after detection) gives, lane by lane, the largest `f32` at most `x`: the
    /// round-to-nearest conversion, one step down where it rounded up. Inputs: every
    /// neighbourhood of a power of two and of a midpoint between floats, and a stride over
    /// all `u32`. Skipped (with a note) on CPUs without the build.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn the_avx512_conversion_rounds_toward_zero() {
        struct Conv<'a>(&'a [u32]);
        impl Kernel for Conv<'_> {
            type Output = Option<Vec<f32>>;
            #[inline(always)]
            fn run(self) -> Option<Vec<f32>> {
                None
            }
            #[inline(always)]
            fn run_avx512(self, cpu: Avx512) -> Option<Vec<f32>> {
                let mut out = Vec::with_capacity(self.0.len());
                for c in self.0.chunks_exact(16) {
                    let lanes: [u32; 16] = core::array::from_fn(|k| c[k]);
                    out.extend(cpu.u32_to_f32_toward_zero(lanes));
                }
                Some(out)
            }
        }
        let mut xs: Vec<u32> = vec![0, 1, 2, 3, u32::MAX, u32::MAX - 1];
        for b in 0..32u32 {
            for base in [
                1u32 << b,
                (1u32 << b) | (1u32 << b).checked_shr(24).unwrap_or(0),
            ] {
                for d in 0..8u32 {
                    xs.extend([base.wrapping_add(d), base.wrapping_sub(d)]);
                }
            }
        }
        xs.extend((0..=u32::MAX).step_by(9_973));
        xs.resize(xs.len().next_multiple_of(16), 7);
        let Some(got) = run_at(Level::Avx512Gfni, Conv(&xs)) else {
            println!("no AVX-512 GFNI build on this CPU: conversion not tested");
            return;
        };
        for (&x, &f) in xs.iter().zip(&got) {
            let nearest = x as f32;
            let want = if nearest as f64 > x as f64 {
                f32::from_bits(nearest.to_bits() - 1)
            } else {
                nearest
            };
            assert_eq!(f.to_bits(), want.to_bits(), "{x}");
            assert!(f as f64 <= x as f64);
        }
    }

    /// The AVX-512 build's lane comparison (`Avx512::lanes_equal`, reached only through
    /// `run_at` after detection) against `==` on the arrays: equal arrays, and arrays that
    /// differ in one lane only, in each of the 16 lanes and by each single bit. Skipped (with
    /// a note) on CPUs without the build.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn the_avx512_lane_comparison_is_array_equality() {
        struct Eq16<'a>(&'a [([u32; 16], [u32; 16])]);
        impl Kernel for Eq16<'_> {
            type Output = Option<Vec<bool>>;
            #[inline(always)]
            fn run(self) -> Option<Vec<bool>> {
                None
            }
            #[inline(always)]
            fn run_avx512(self, cpu: Avx512) -> Option<Vec<bool>> {
                Some(self.0.iter().map(|&(a, b)| cpu.lanes_equal(a, b)).collect())
            }
        }
        let a: [u32; 16] = core::array::from_fn(|k| (k as u32).wrapping_mul(0x9E37_79B9) ^ 0x55);
        let mut pairs = vec![(a, a), ([0; 16], [0; 16]), ([u32::MAX; 16], [u32::MAX; 16])];
        for lane in 0..16 {
            for bit in 0..32 {
                let mut b = a;
                b[lane] ^= 1 << bit;
                pairs.extend([(a, b), (b, a)]);
            }
        }
        let Some(got) = run_at(Level::Avx512Gfni, Eq16(&pairs)) else {
            println!("no AVX-512 GFNI build on this CPU: lane comparison not tested");
            return;
        };
        let want: Vec<bool> = pairs.iter().map(|(a, b)| a == b).collect();
        assert_eq!(got, want);
        assert_eq!(want.iter().filter(|&&e| e).count(), 3);
    }

    /// The cached level is the detected one, and stays so.
    #[test]
    fn the_cached_level_is_the_detected_one() {
        #[cfg(target_arch = "x86_64")]
        assert_eq!(level(), detect());
        assert_eq!(level(), level());
        assert_eq!(levels().last().copied(), Some(level()));
    }

    /// Every float build against the portable one on a kernel mixing `mul_add`, division
    /// and square roots (the operations whose rounding must not depend on the build).
    #[cfg(feature = "analysis")]
    #[test]
    fn every_float_build_gives_the_portable_bits() {
        struct Sum<'a>(&'a [f64]);
        impl Kernel for Sum<'_> {
            type Output = f64;
            #[inline(always)]
            fn run(self) -> f64 {
                let mut acc = [0f64; 8];
                for c in self.0.chunks_exact(8) {
                    for (a, &x) in acc.iter_mut().zip(c) {
                        *a = x.mul_add(1.0 - x, *a) + (x / (1.0 + x)).sqrt();
                    }
                }
                acc.iter().sum()
            }
        }
        let xs: Vec<f64> = (0..4096)
            .map(|k| (k as f64 * 0.618_033_988_749_895).fract())
            .collect();
        let portable = run_float(FloatBuild::Portable, Sum(&xs));
        for build in [FloatBuild::Avx2, FloatBuild::Avx512] {
            assert_eq!(
                run_float(build, Sum(&xs)).to_bits(),
                portable.to_bits(),
                "{build:?}"
            );
        }
        assert!(portable > 0.0);
    }
}
