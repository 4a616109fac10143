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
//! To add a kernel: a struct holding its arguments that implements [`Kernel`] (safe code,
//! `#[inline(always)]`), a dispatcher calling [`run_at`] (integer builds) or [`run_float`]
//! (floating-point builds), and a test that runs every build the CPU has against the
//! portable one. The `#[target_feature]` wrappers and the detection are written once.
#![allow(unsafe_code)]

use crate::bits::FromFraction;
use crate::digital::sobol::{OwenSobol, owen_fill_blocks};
use crate::randomize::Scrambler;

/// The widest build this CPU runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Level {
    /// The target's baseline (SSE2 on x86-64).
    Portable,
    /// AVX2.
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    Avx2,
    /// AVX-512 F, BW, VL with GFNI.
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    Avx512Gfni,
}

/// Detects the widest build (the standard library caches the CPUID answers).
#[inline]
pub(crate) fn level() -> Level {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    {
        if std::arch::is_x86_feature_detected!("avx512f")
            && std::arch::is_x86_feature_detected!("avx512bw")
            && std::arch::is_x86_feature_detected!("avx512vl")
            && std::arch::is_x86_feature_detected!("gfni")
        {
            return Level::Avx512Gfni;
        }
        if std::arch::is_x86_feature_detected!("avx2") {
            return Level::Avx2;
        }
    }
    Level::Portable
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
}

/// `k.run()` in the widest build that is at most `want` and that the CPU runs.
#[inline]
pub(crate) fn run_at<K: Kernel>(want: Level, k: K) -> K::Output {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    let detected = level();
    match want {
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        Level::Avx512Gfni if detected == Level::Avx512Gfni => {
            // SAFETY: `run_int_avx512` requires avx512f, avx512bw, avx512vl and gfni;
            // `level()` detected all four on this CPU. The kernel itself is safe code.
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
/// affine transform plus a byte shuffle.
#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx512f,avx512bw,avx512vl,gfni")]
fn run_int_avx512<K: Kernel>(k: K) -> K::Output {
    k.run()
}

/// The four-dimensional Owen-Sobol' `f32` fill.
struct OwenSobol4<'a> {
    s: &'a OwenSobol,
    indices: &'a [u32],
    out: &'a mut [[f32; 4]],
}

impl Kernel for OwenSobol4<'_> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        owen_fill_blocks(self.s, self.indices, self.out);
    }
}

/// [`OwenSobol::fill_f32`] with the widest build that is at most `want` and that the CPU
/// runs (for tests and benchmarks of each build).
#[inline]
pub(crate) fn owen_sobol4_fill_f32_at(
    want: Level,
    s: &OwenSobol,
    indices: &[u32],
    out: &mut [[f32; 4]],
) {
    run_at(want, OwenSobol4 { s, indices, out });
}

/// [`OwenSobol::fill_f32`]: the widest build this CPU runs.
#[inline]
pub(crate) fn owen_sobol4_fill_f32(s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]]) {
    owen_sobol4_fill_f32_at(level(), s, indices, out);
}

/// One prepared scrambler over a column.
struct ScrambleSlice<'a, S> {
    s: S,
    xs: &'a mut [u32],
}

impl<S: Scrambler> Kernel for ScrambleSlice<'_, S> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        for x in self.xs {
            *x = self.s.scramble(*x);
        }
    }
}

/// `x = s.scramble(x)` for every `x` in `xs`: one prepared scrambler over a contiguous
/// column (what `Scrambled`'s fills run), in the widest build this CPU runs, so the
/// scrambler's per-value arithmetic is vectorized (16 lanes with AVX-512, 8 with AVX2).
#[inline]
pub(crate) fn scramble_slice<S: Scrambler>(s: S, xs: &mut [u32]) {
    scramble_slice_at(level(), s, xs);
}

/// [`scramble_slice`] with the widest build that is at most `want` and that the CPU runs.
#[inline]
pub(crate) fn scramble_slice_at<S: Scrambler>(want: Level, s: S, xs: &mut [u32]) {
    run_at(want, ScrambleSlice { s, xs });
}

/// A row-major buffer scrambled lane by lane.
struct ScrambleLanes<'a, S> {
    lanes: &'a [S],
    xs: &'a mut [u32],
}

impl<S: Scrambler> Kernel for ScrambleLanes<'_, S> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        S::scramble_lanes(self.lanes, self.xs);
    }
}

/// `xs[j] = lanes[j % lanes.len()].scramble(xs[j])`: a row-major buffer whose rows hold one
/// coordinate per lane pattern (`lanes` repeats the dimensions' scramblers a whole number of
/// rows), each chunk of `lanes.len()` values scrambled element-wise, in the widest build this
/// CPU runs. `Scrambled`'s fill of low-dimensional points runs this: no gather or scatter.
#[inline]
pub(crate) fn scramble_lanes<S: Scrambler>(lanes: &[S], xs: &mut [u32]) {
    scramble_lanes_at(level(), lanes, xs);
}

/// [`scramble_lanes`] with the widest build that is at most `want` and that the CPU runs.
#[inline]
pub(crate) fn scramble_lanes_at<S: Scrambler>(want: Level, lanes: &[S], xs: &mut [u32]) {
    run_at(want, ScrambleLanes { lanes, xs });
}

/// Fractions to floats.
struct Convert<'a, T> {
    src: &'a [u32],
    dst: &'a mut [T],
}

impl<T: FromFraction> Kernel for Convert<'_, T> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        for (y, &x) in self.dst.iter_mut().zip(self.src) {
            *y = T::from_fraction(x);
        }
    }
}

/// `dst[j] = T::from_fraction(src[j])` (the shorter length), in the widest build this CPU
/// runs: what [`crate::Sampler::fill_as`] converts its `u32` buffer with.
#[inline]
pub(crate) fn convert<T: FromFraction>(src: &[u32], dst: &mut [T]) {
    convert_at(level(), src, dst);
}

/// [`convert`] with the widest build that is at most `want` and that the CPU runs.
#[inline]
pub(crate) fn convert_at<T: FromFraction>(want: Level, src: &[u32], dst: &mut [T]) {
    run_at(want, Convert { src, dst });
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

/// `k.run()` in the build `want`, or the widest narrower one this CPU runs.
#[cfg(feature = "analysis")]
#[inline]
pub(crate) fn run_float<K: Kernel>(want: FloatBuild, k: K) -> K::Output {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    {
        use std::arch::is_x86_feature_detected as has;
        let avx2 = has!("avx2") && has!("fma");
        if want == FloatBuild::Avx512 && avx2 && has!("avx512f") && has!("avx512vl") {
            // SAFETY: `run_avx512` requires AVX-512F, AVX-512VL, AVX2 and FMA, all
            // detected on this CPU just above; the kernel itself is safe code.
            return unsafe { run_avx512(k) };
        }
        if want != FloatBuild::Portable && avx2 {
            // SAFETY: `run_avx2` requires AVX2 and FMA, both detected on this CPU just
            // above; the kernel itself is safe code.
            return unsafe { run_avx2(k) };
        }
    }
    let _ = want;
    k.run()
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
    use crate::randomize::OwenHash;

    /// Every build the CPU runs, on lengths leaving 0 to 3 points past the blocks of four
    /// and on unequal lengths, for both hashes, against the scalar `sample4_f32`.
    #[test]
    fn every_build_matches_the_scalar_path() {
        let mut levels = vec![Level::Portable];
        #[cfg(target_arch = "x86_64")]
        {
            if level() != Level::Portable {
                levels.push(Level::Avx2);
            }
            if level() == Level::Avx512Gfni {
                levels.push(Level::Avx512Gfni);
            }
        }
        println!("builds run: {levels:?}");
        // Prepared scramblers over columns: every build against the one-value path.
        {
            use crate::randomize::{
                CranleyPatterson, DigitalShift, ExactOwen, FastOwen, Lms, Randomizer,
            };
            let xs: Vec<u32> = (0..1000u32).map(|k| k.wrapping_mul(0x9E37_79B9)).collect();
            let check = |name: &str,
                         r: &dyn Fn(usize, u32) -> u32,
                         run: &dyn Fn(Level, usize, &mut [u32])| {
                for &lv in &levels {
                    for dim in [0usize, 3] {
                        let mut got = xs.clone();
                        run(lv, dim, &mut got);
                        for (k, (&g, &x)) in got.iter().zip(&xs).enumerate() {
                            assert_eq!(g, r(dim, x), "{name} {lv:?} dim {dim} k {k}");
                        }
                    }
                }
            };
            let fo = FastOwen::with_hash(5, OwenHash::LaineKarras);
            check("fast-owen-lk", &|d, x| fo.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, fo.scrambler(d), v)
            });
            let fo = FastOwen::new(6);
            check("fast-owen", &|d, x| fo.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, fo.scrambler(d), v)
            });
            let ex = ExactOwen::new(7);
            check("exact-owen", &|d, x| ex.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, ex.scrambler(d), v)
            });
            let pair = (Lms::new(8), DigitalShift::new(8));
            check("lms+xor", &|d, x| pair.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, pair.scrambler(d), v)
            });
            let cp = CranleyPatterson::new(9);
            check("rotate", &|d, x| cp.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, cp.scrambler(d), v)
            });
        }
        // Scramblers laid over rows (lane patterns of 1 to 64, one with mixed hashes, a
        // buffer that ends mid-pattern): every build against the one-value path.
        {
            use crate::randomize::{ExactOwen, FastOwen, FastOwenScrambler, Lms, Randomizer};
            let xs: Vec<u32> = (0..1003u32).map(|k| k.wrapping_mul(0x85EB_CA6B)).collect();
            fn run<S: crate::randomize::Scrambler>(
                levels: &[Level],
                name: &str,
                lanes: &[S],
                xs: &[u32],
            ) {
                for &lv in levels {
                    let mut got = xs.to_vec();
                    scramble_lanes_at(lv, lanes, &mut got);
                    for (j, (&g, &x)) in got.iter().zip(xs).enumerate() {
                        let want = lanes[j % lanes.len()].scramble(x);
                        assert_eq!(g, want, "{name} {lv:?} width {} j {j}", lanes.len());
                    }
                }
            }
            for width in [1usize, 3, 4, 16, 20, 48, 64] {
                let fo = FastOwen::new(11);
                let lanes: Vec<_> = (0..width).map(|d| fo.scrambler(d % 5)).collect();
                run(&levels, "fast-owen", &lanes, &xs);
                let fo = FastOwen::with_hash(12, OwenHash::LaineKarras);
                let lanes: Vec<_> = (0..width).map(|d| fo.scrambler(d)).collect();
                run(&levels, "fast-owen-lk", &lanes, &xs);
                let mixed: Vec<_> = (0..width)
                    .map(|d| {
                        let hash = [OwenHash::Vegdahl, OwenHash::LaineKarras][d % 2];
                        FastOwenScrambler::from_key((d as u32).wrapping_mul(0x9E37_79B9), hash)
                    })
                    .collect();
                run(&levels, "fast-owen-mixed", &mixed, &xs);
                let ex = ExactOwen::new(13);
                let lanes: Vec<_> = (0..width).map(|d| ex.scrambler(d)).collect();
                run(&levels, "exact-owen", &lanes, &xs);
                let lms = Lms::new(14);
                let lanes: Vec<_> = (0..width).map(|d| lms.scrambler(d)).collect();
                run(&levels, "lms", &lanes, &xs);
            }
        }
        let indices: Vec<u32> = (0..4099u32)
            .map(|k| k.wrapping_mul(2_654_435_761) ^ (k >> 3))
            .chain([0, 1, 255, 256, u32::MAX])
            .collect();
        for hash in [OwenHash::Vegdahl, OwenHash::LaineKarras] {
            let s = OwenSobol::with_hash(4, 77, hash).unwrap();
            for len in [0, 1, 2, 3, 4, 5, 6, 7, 4101, 4103, indices.len()] {
                for &lv in &levels {
                    let mut out = vec![[-1f32; 4]; len];
                    owen_sobol4_fill_f32_at(lv, &s, &indices[..len], &mut out);
                    for (k, o) in out.iter().enumerate() {
                        let want = s.sample4_f32(indices[k]).map(f32::to_bits);
                        assert_eq!(o.map(f32::to_bits), want, "{lv:?} {hash:?} len {len} k {k}");
                    }
                }
            }
        }
    }

    /// Every build of the conversion against `from_fraction`, for `f32`, `f64` and `u32`,
    /// on the values where `f32` rounding changes (around powers of two) and a spread.
    #[test]
    fn every_conversion_build_matches_from_fraction() {
        let mut levels = vec![Level::Portable];
        #[cfg(target_arch = "x86_64")]
        {
            if level() != Level::Portable {
                levels.push(Level::Avx2);
            }
            if level() == Level::Avx512Gfni {
                levels.push(Level::Avx512Gfni);
            }
        }
        let mut xs: Vec<u32> = (0..32)
            .flat_map(|b| [1u32 << b, (1u32 << b).wrapping_sub(1), (1u32 << b) + 1])
            .collect();
        xs.extend((0..2000u32).map(|k| k.wrapping_mul(0x9E37_79B9)));
        xs.push(u32::MAX);
        for &lv in &levels {
            let mut f = vec![0f32; xs.len()];
            convert_at(lv, &xs, &mut f);
            let mut d = vec![0f64; xs.len()];
            convert_at(lv, &xs, &mut d);
            let mut u = vec![0u32; xs.len()];
            convert_at(lv, &xs, &mut u);
            for (j, &x) in xs.iter().enumerate() {
                assert_eq!(
                    f[j].to_bits(),
                    crate::bits::to_f32(x).to_bits(),
                    "{lv:?} f32 {x:#x}"
                );
                assert_eq!(
                    d[j].to_bits(),
                    crate::bits::to_f64(x).to_bits(),
                    "{lv:?} f64 {x:#x}"
                );
                assert_eq!(u[j], x, "{lv:?} u32");
            }
        }
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
