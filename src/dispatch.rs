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
//! To add a kernel: a safe dispatcher function, one `#[target_feature]` wrapper per build,
//! each call behind the matching detection, and a test that runs every build the CPU has
//! against the portable one.
#![allow(unsafe_code)]

use crate::randomize::Scrambler;
use crate::sobol::{OwenSobol, owen_fill_blocks};

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

/// [`OwenSobol::fill_f32`] with the widest build that is at most `want` and that the CPU
/// runs (for tests and benchmarks of each build).
#[inline]
pub(crate) fn owen_sobol4_fill_f32_at(
    want: Level,
    s: &OwenSobol,
    indices: &[u32],
    out: &mut [[f32; 4]],
) {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    let detected = level();
    match want {
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        Level::Avx512Gfni if detected == Level::Avx512Gfni => {
            // SAFETY: `owen_sobol4_avx512` requires avx512f, avx512bw, avx512vl and gfni;
            // `level()` detected all four on this CPU.
            unsafe { owen_sobol4_avx512(s, indices, out) }
        }
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        Level::Avx2 | Level::Avx512Gfni if detected != Level::Portable => {
            // SAFETY: `owen_sobol4_avx2` requires avx2; `level()` returns Avx2 or
            // Avx512Gfni only when avx2 was detected on this CPU (every AVX-512 CPU
            // has AVX2, and the Avx2 answer is its own detection).
            unsafe { owen_sobol4_avx2(s, indices, out) }
        }
        _ => owen_fill_blocks(s, indices, out),
    }
}

/// [`OwenSobol::fill_f32`]: the widest build this CPU runs.
#[inline]
pub(crate) fn owen_sobol4_fill_f32(s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]]) {
    owen_sobol4_fill_f32_at(level(), s, indices, out);
}

#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx2")]
fn owen_sobol4_avx2(s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]]) {
    owen_fill_blocks(s, indices, out);
}

/// With AVX-512 the 16 lanes are one vector, and the bit reversal is a GFNI affine
/// transform plus a byte shuffle.
#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx512f,avx512bw,avx512vl,gfni")]
fn owen_sobol4_avx512(s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]]) {
    owen_fill_blocks(s, indices, out);
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
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    let detected = level();
    match want {
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        Level::Avx512Gfni if detected == Level::Avx512Gfni => {
            // SAFETY: `scramble_slice_avx512` requires avx512f, avx512bw, avx512vl and gfni;
            // `level()` detected all four on this CPU.
            unsafe { scramble_slice_avx512(s, xs) }
        }
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        Level::Avx2 | Level::Avx512Gfni if detected != Level::Portable => {
            // SAFETY: `scramble_slice_avx2` requires avx2, which `level()` detected on this
            // CPU whenever it answers Avx2 or Avx512Gfni.
            unsafe { scramble_slice_avx2(s, xs) }
        }
        _ => scramble_slice_portable(s, xs),
    }
}

#[inline(always)]
fn scramble_slice_portable<S: Scrambler>(s: S, xs: &mut [u32]) {
    for x in xs {
        *x = s.scramble(*x);
    }
}

#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx2")]
fn scramble_slice_avx2<S: Scrambler>(s: S, xs: &mut [u32]) {
    scramble_slice_portable(s, xs);
}

#[cfg(all(feature = "std", target_arch = "x86_64"))]
#[target_feature(enable = "avx512f,avx512bw,avx512vl,gfni")]
fn scramble_slice_avx512<S: Scrambler>(s: S, xs: &mut [u32]) {
    scramble_slice_portable(s, xs);
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
}
