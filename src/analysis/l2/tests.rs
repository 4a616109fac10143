//! Unit tests of the pair-sum kernels, their builds, and the fast and wide paths.

use super::Points;
use super::kernel::{Blocked, Build, GROUP, LANES, Loop, Ticker, off_diagonal};
use super::measures::*;
use super::*;
use crate::work::no_progress;

/// A ticker that reports nowhere.
fn quiet(n: usize) -> Ticker<'static> {
    Ticker::new(&no_progress, n)
}

/// The reference pair sum `sum_{i<j} prod_k kernel(x_ik, x_jk)`: a plain double loop
/// with Neumaier's compensation, sharing nothing with the blocked kernels.
fn neumaier_pair_sum(p: Points<'_>, kernel: impl Fn(f64, f64) -> f64) -> f64 {
    let (mut plain, mut comp) = (0.0f64, 0.0f64);
    for i in 0..p.len() {
        for j in i + 1..p.len() {
            let (a, b) = (p.point(i), p.point(j));
            let x: f64 = a.iter().zip(b).map(|(&x, &y)| kernel(x, y)).product();
            let t = plain + x;
            comp += if plain.abs() >= x.abs() {
                (plain - t) + x
            } else {
                (x - t) + plain
            };
            plain = t;
        }
    }
    plain + comp
}

/// The pair sum over `i < j` with rows long enough for the groups of [`GROUP`] blocks,
/// their remainders and the masked first and last blocks (every `n mod LANES`, both
/// specialized dimensions and the generic loop with odd and even `d`, and both loops
/// in 8D: rows and tiles, with the row blocks' masked diagonal and last blocks),
/// against a double loop over the pairs summed with Neumaier compensation.
#[test]
fn grouped_pair_sum_equals_plain_loop() {
    let kernel = |x: f64, y: f64| 1.5 - (x - y).abs() * (1.0 - (x - y).abs());
    let ns = (1..=3 * GROUP * LANES + 9)
        .step_by(5)
        .chain([LANES * (GROUP + 2) + 1]);
    for n in ns {
        for (d, lp) in [
            (1, Loop::Rows),
            (2, Loop::Rows),
            (3, Loop::Rows),
            (8, Loop::Rows),
            (8, Loop::Tiles),
        ] {
            let data: Vec<f64> = (0..n * d)
                .map(|i| ((i as f64) * 0.754_877_666_246_692_7).fract())
                .collect();
            let p = Points::new(&data, d).unwrap();
            let plain = neumaier_pair_sum(p, kernel);
            let s = Blocked::new(p, |x| [x]);
            let k1 = |a: [f64; 1], b: [f64; 1]| kernel(a[0], b[0]);
            let portable = off_diagonal(&s, &k1, Build::Portable, lp, &mut quiet(n))
                .dd()
                .value();
            assert!(
                (portable - plain).abs() <= 1e-14 * plain.max(1.0),
                "n={n} d={d} {lp:?}: {portable} vs {plain}"
            );
            for build in [Build::Avx2, Build::Avx512] {
                let wide = off_diagonal(&s, &k1, build, lp, &mut quiet(n)).dd().value();
                assert_eq!(
                    portable.to_bits(),
                    wide.to_bits(),
                    "n={n} d={d} {lp:?} {build:?}"
                );
            }
        }
    }
}

/// Every measure by the pair sum in the given build.
fn direct_with(m: L2Metric, p: Points<'_>, build: Build) -> crate::Result<f64> {
    let t = &mut quiet(p.len());
    match m {
        L2Metric::L2Star => l2_star_direct_with(p, build, t),
        L2Metric::Centered => centered_with(p, build, t),
        L2Metric::WrapAround => wrap_around_with(p, build, t),
        L2Metric::Mixture => mixture_with(p, build, t),
        L2Metric::Symmetric => symmetric_with(p, build, t),
        L2Metric::Unanchored => unanchored_with(p, build, t),
        L2Metric::Generalized => generalized_with(p, build, t),
        L2Metric::Diaphony => diaphony_with(p, build, t),
    }
}

fn golden_ratio_points(len: usize) -> Vec<f64> {
    (0..len)
        .map(|i| ((i as f64) * 0.618_033_988_749_895).fract())
        .collect()
}

#[test]
fn every_build_gives_the_portable_bits() {
    // On an x86-64 CPU this compares the AVX2+FMA and AVX-512 builds of the pair sum (each
    // where the CPU has it, else the next narrower one: the log says which ran) with the
    // portable one; elsewhere all three are the portable build. The `f64::mul_add` of the
    // wrap-around, mixture and diaphony factors is a packed FMA instruction in the wide
    // builds and an `fma` call in the portable one; (300, 8) and (301, 2) run several
    // full 8D tile row blocks and 2D groups of blocks; (20, 700) and (11, 2100) the wide
    // path (tracked exponents) of every measure.
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        eprintln!(
            "avx2+fma: {}, avx512f+vl: {}",
            has!("avx2") && has!("fma"),
            has!("avx512f") && has!("avx512vl")
        );
    }
    for (n, d) in [
        (1, 1),
        (7, 3),
        (9, 2),
        (33, 2),
        (100, 8),
        (257, 5),
        (300, 8),
        (301, 2),
        (20, 700),
        (11, 2100),
    ] {
        let data = golden_ratio_points(n * d);
        let p = Points::new(&data, d).unwrap();
        for m in L2Metric::ALL {
            let portable = direct_with(m, p, Build::Portable);
            for build in [Build::Avx2, Build::Avx512] {
                let wide = direct_with(m, p, build);
                assert_eq!(
                    portable.map(f64::to_bits),
                    wide.map(f64::to_bits),
                    "{} n={n} d={d} {build:?}",
                    m.name()
                );
            }
        }
    }
}

#[test]
fn blocked_pair_sum_equals_plain_loop() {
    // Every n mod LANES and the masks of the first and last blocks, against a plain
    // double loop over i < j of the original kernel.
    let kernel = |x: f64, y: f64| 1.5 - (x - y).abs() * (1.0 - (x - y).abs());
    for n in 1..=2 * LANES + 3 {
        for d in [1, 3] {
            let data = golden_ratio_points(n * d);
            let p = Points::new(&data, d).unwrap();
            let plain = neumaier_pair_sum(p, kernel);
            let s = Blocked::new(p, |x| [x]);
            for build in [Build::Portable, Build::Avx2, Build::Avx512] {
                let got = off_diagonal(
                    &s,
                    &|a: [f64; 1], b: [f64; 1]| kernel(a[0], b[0]),
                    build,
                    Loop::Rows,
                    &mut quiet(n),
                )
                .dd()
                .value();
                assert!((got - plain).abs() <= 1e-14 * plain.max(1.0), "n={n} d={d}");
            }
        }
    }
}

#[test]
fn fast_equals_direct_small() {
    let data: Vec<f64> = (0..600)
        .map(|i| ((i as f64) * 0.618_033_988_749_895).fract())
        .collect();
    for d in [1, 2] {
        let p = Points::new(&data, d).unwrap();
        let (a, b) = (l2_star_fast(p).unwrap(), l2_star_direct(p).unwrap());
        assert!((a - b).abs() <= 1e-13 * b, "d={d}: {a} vs {b}");
    }
}

#[test]
fn names_round_trip() {
    for m in L2Metric::ALL {
        assert_eq!(
            L2Metric::ALL
                .iter()
                .filter(|x| x.name() == m.name())
                .count(),
            1
        );
    }
}

/// Where both paths can run (`d <= FAST_D`), the wide path (tracked exponents, products
/// in chunks of eight coordinates) gives the plain path's sums up to the rounding of the
/// products: the centered, mixture and unanchored kernels (two features), the diaphony's
/// (negative factors), every `n mod LANES`, odd and even `d`, chunk remainders.
#[test]
fn wide_path_equals_plain_path_where_both_run() {
    use super::arith::Wide;
    use super::sums::{combine, combine_wide, kernel_sums, wide_kernel_sums};
    const TWO_PI2: f64 = 2.0 * core::f64::consts::PI * core::f64::consts::PI;
    let rel = |a: f64, b: f64| if a == b { 0.0 } else { (a - b).abs() / b.abs() };
    for (n, d) in [
        (1, 3),
        (9, 1),
        (13, 2),
        (30, 8),
        (21, 17),
        (40, 100),
        (17, 301),
    ] {
        let data = golden_ratio_points(n * d);
        let p = Points::new(&data, d).unwrap();
        let cd_g1 = |x: f64| 1.0 + 0.5 * (x - 0.5).abs() - 0.5 * (x - 0.5) * (x - 0.5);
        let cd_feat = |x: f64| [0.5 * x, 0.5 + 0.5 * (x - 0.5).abs()];
        let cd_pair = |a: [f64; 2], b: [f64; 2]| a[1] + b[1] - (a[0] - b[0]).abs();
        let ul2_pair = |a: [f64; 2], b: [f64; 2]| min2(a[0], b[0]) * min2(a[1], b[1]);
        let dia_pair = |a: [f64; 1], b: [f64; 1]| {
            let t = (a[0] - b[0]).abs();
            TWO_PI2.mul_add((-t).mul_add(1.0 - t, 1.0 / 6.0), 1.0)
        };
        for build in [Build::Portable, Build::Avx512] {
            let plain = kernel_sums(p, cd_g1, cd_feat, cd_pair, build, Loop::Rows, &mut quiet(n));
            let wide = wide_kernel_sums(p, cd_g1, cd_feat, cd_pair, build, &mut quiet(n));
            // The sums alone (c = 0): -2 s1 / n + s2 / n^2, no cancellation of size.
            let c0 = super::arith::Dd { hi: 0.0, lo: 0.0 };
            let a = combine(c0, 2.0, 0.0, &plain, n);
            let b = combine(c0, 0.0, 1.0, &plain, n);
            let wa = combine_wide(Wide::ZERO, Wide::TWO, Wide::ZERO, &wide, n);
            let wb = combine_wide(Wide::ZERO, Wide::ZERO, Wide::ONE, &wide, n);
            assert!(
                rel(wa.to_f64("s1").unwrap(), a) <= 1e-13,
                "cd s1 n={n} d={d}"
            );
            assert!(
                rel(wb.to_f64("s2").unwrap(), b) <= 1e-13,
                "cd s2 n={n} d={d}"
            );
            let g = |x: f64| x * (1.0 - x);
            let f = |x: f64| [x, 1.0 - x];
            let plain = kernel_sums(p, g, f, ul2_pair, build, Loop::Rows, &mut quiet(n));
            let wide = wide_kernel_sums(p, g, f, ul2_pair, build, &mut quiet(n));
            let b = combine(c0, 0.0, 1.0, &plain, n);
            let wb = combine_wide(Wide::ZERO, Wide::ZERO, Wide::ONE, &wide, n);
            assert!(rel(wb.to_f64("s2").unwrap(), b) <= 1e-13, "ul2 n={n} d={d}");
            let (g, f) = (|_: f64| 0.0, |x: f64| [x]);
            let plain = kernel_sums(p, g, f, dia_pair, build, Loop::Rows, &mut quiet(n));
            let wide = wide_kernel_sums(p, g, f, dia_pair, build, &mut quiet(n));
            let b = combine(c0, 0.0, 1.0, &plain, n);
            let wb = combine_wide(Wide::ZERO, Wide::ZERO, Wide::ONE, &wide, n);
            assert!(
                rel(wb.to_f64("s2").unwrap(), b) <= 1e-13,
                "diaphony n={n} d={d}"
            );
        }
    }
}

fn min2(a: f64, b: f64) -> f64 {
    a.min(b)
}

// ---------------------------------------------------------------------------------------
// The divide and conquer of the L2-star discrepancy against the pair sum.
// ---------------------------------------------------------------------------------------

/// A stop that never fires.
static NEVER: crate::work::Stop = crate::work::Stop::never("test");

/// SplitMix64 uniforms in `[0, 1)`.
fn uniform(len: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..len)
        .map(|_| {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            (z >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

/// `|a - b| / |b|`.
fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn general_path_matches_pair_sum_d1_to_6() {
    for d in 1..=6 {
        for (n, seed) in [(1usize, 1u64), (50, 2), (700, 3), (2500, 4)] {
            let x = uniform(n * d, seed * 100 + d as u64);
            let p = Points::new(&x, d).unwrap();
            let (tree, direct) = (
                super::tree::l2_star_fast_with(p, false, &NEVER),
                l2_star_direct(p).unwrap(),
            );
            assert!(
                rel(tree, direct) <= 1e-13,
                "d={d} n={n}: {tree:e} vs {direct:e}"
            );
            if d <= 2 {
                let plane = super::tree::l2_star_fast_with(p, true, &NEVER);
                assert!(rel(tree, plane) <= 1e-13, "d={d} n={n}");
            }
        }
    }
}

#[test]
fn general_path_with_ties_zeros_and_ones() {
    // Coordinates on the grid k/8 (so many exactly 0 and 1, repeated points), and sets
    // where one coordinate is constant 0 or 1.
    for d in 3..=6 {
        let x: Vec<f64> = uniform(1500 * d, 7 + d as u64)
            .iter()
            .map(|&t| (t * 9.0).floor().min(8.0) / 8.0)
            .collect();
        let p = Points::new(&x, d).unwrap();
        let (tree, direct) = (l2_star_fast(p).unwrap(), l2_star_direct(p).unwrap());
        assert!(
            rel(tree, direct) <= 1e-13,
            "grid d={d}: {tree:e} vs {direct:e}"
        );
        for c in [0.0, 1.0] {
            let mut y = uniform(900 * d, 11 + d as u64);
            y.chunks_exact_mut(d).for_each(|r| r[1] = c);
            let p = Points::new(&y, d).unwrap();
            let (tree, direct) = (l2_star_fast(p).unwrap(), l2_star_direct(p).unwrap());
            assert!(rel(tree, direct) <= 1e-13, "const {c} d={d}");
        }
    }
    // All points at (1, ..., 1): D^2 = 3^-d exactly in the formula.
    let ones = vec![1.0; 300 * 4];
    let p = Points::new(&ones, 4).unwrap();
    assert!(rel(l2_star_fast(p).unwrap(), (1.0f64 / 81.0).sqrt()) <= 1e-15);
}

#[test]
fn parallel_recursion_matches_pair_sum() {
    // Above TREE_PARALLEL points, where the sub-problems are joined.
    let d = 3;
    let x = uniform(3 * super::tree::TREE_PARALLEL * d, 5);
    let p = Points::new(&x, d).unwrap();
    assert!(rel(l2_star_fast(p).unwrap(), l2_star_direct(p).unwrap()) <= 1e-13);
}
