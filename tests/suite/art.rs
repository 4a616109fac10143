//! ART against what it claims: exactly `N` samples; at `N = 16^j` one in each tile of level
//! `j` (in the frame of the seed's shift); every prefix of a set is the set of that size
//! (progressive); the low-frequency power
//! (mean periodogram over `0 < |k| < sqrt(N)/2`, 8 seeds) is below white noise (1) and
//! below half of jittered sampling's on the same grid (drawn here independently); the
//! samples keep apart (mean nearest-neighbour distance far above white noise's closed form
//! and the jittered grid's, as the paper's relaxed offsets spread them); the star
//! discrepancy at 1024 points (the prefix between two complete levels, one sample in each
//! `1/32` square) is within a tenth of a jittered grid's (with the samples kept in the
//! middle of their squares it was 1.8 times the jittered grid's: one point a square and a
//! uniform profile in each, as jittering has, is what the axis term of the table's fit
//! restores); importance sampling puts about `N` times the
//! density's integral in each region (within Poisson-like bounds).

use qmckit::Error;
use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::analysis::star::star_exact;
use qmckit::blue_noise::Art;
use qmckit::blue_noise::art::{self, ArtTable};
use qmckit::work::Budget;

fn set(n: u64, seed: u64) -> Vec<f64> {
    Art::new(n)
        .unwrap()
        .seed(seed)
        .generate(&Budget::DEFAULT)
        .unwrap()
        .to_f64()
}

/// Mean periodogram over `0 < |k| < sqrt(N)/2` (white noise: 1).
fn low_power(x: &[f64]) -> f64 {
    let n = x.len() / 2;
    let kmax = (0.5 * (n as f64).sqrt()).ceil() as usize;
    let s = spectrum_2d(Points::new(x, 2).unwrap(), kmax, &Budget::DEFAULT).unwrap();
    let (mut sum, mut count) = (0.0, 0);
    for (kx, ky, p) in s.iter() {
        let r = ((kx * kx + ky * ky) as f64).sqrt();
        if r > 0.0 && r < kmax as f64 {
            sum += p;
            count += 1;
        }
    }
    sum / count as f64
}

/// A jittered `k x k` grid: one uniform point a cell (a 64-bit LCG, top 53 bits).
fn jittered(k: usize, seed: u64) -> Vec<f64> {
    let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    let mut u = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut out = Vec::with_capacity(2 * k * k);
    for y in 0..k {
        for x in 0..k {
            out.push((x as f64 + u()) / k as f64);
            out.push((y as f64 + u()) / k as f64);
        }
    }
    out
}

#[test]
fn one_sample_in_each_tile_at_powers_of_16() {
    for (j, seed) in [(1u32, 0u64), (2, 5), (3, 9)] {
        let n = 16u64.pow(j);
        let side = 4usize.pow(j);
        let a = Art::new(n).unwrap().seed(seed);
        let s = a.shift();
        let x = a.generate(&Budget::DEFAULT).unwrap().to_f64();
        assert_eq!(x.len() as u64, 2 * n);
        let mut cells = vec![0u32; side * side];
        for p in x.chunks_exact(2) {
            let c = |d: usize| {
                let v = (p[d] - s[d]).rem_euclid(1.0);
                ((v * side as f64) as usize).min(side - 1)
            };
            cells[c(0) + side * c(1)] += 1;
        }
        assert!(cells.iter().all(|&c| c == 1), "level {j}");
    }
}

#[test]
fn every_prefix_is_the_smaller_set() {
    let big = set(5000, 4);
    assert_eq!(big.len(), 10_000);
    for n in [1u64, 7, 16, 100, 256, 1000, 4096] {
        assert_eq!(set(n, 4), big[..2 * n as usize], "N {n}");
    }
}

#[test]
fn art_is_blue_noise() {
    for n in [1024u64, 4096] {
        let k = (n as f64).sqrt() as usize;
        let a = (0..8).map(|s| low_power(&set(n, s))).sum::<f64>() / 8.0;
        let jit = (0..8).map(|s| low_power(&jittered(k, s))).sum::<f64>() / 8.0;
        eprintln!("ART N {n}: low-frequency power {a:.4}, jittered {jit:.4} (white 1)");
        assert!(a < 0.5 * jit, "N {n}: ART {a} jittered {jit}");
    }
}

#[test]
fn art_has_low_star_discrepancy() {
    let star = |x: &[f64]| star_exact(Points::new(x, 2).unwrap(), &Budget::DEFAULT).unwrap();
    let a = (0..8).map(|s| star(&set(1024, s))).sum::<f64>() / 8.0;
    let jit = (0..8).map(|s| star(&jittered(32, s))).sum::<f64>() / 8.0;
    eprintln!("ART N 1024: star discrepancy {a:.5}, jittered {jit:.5}");
    assert!(a < 1.1 * jit, "ART {a} jittered {jit}");
}

/// The mean nearest-neighbour distance times `sqrt(N)`, on the torus, by brute force.
fn mean_nn(x: &[f64]) -> f64 {
    let n = x.len() / 2;
    let wrap = |d: f64| d - d.round();
    let sum: f64 = (0..n)
        .map(|i| {
            (0..n)
                .filter(|&j| j != i)
                .map(|j| wrap(x[2 * i] - x[2 * j]).hypot(wrap(x[2 * i + 1] - x[2 * j + 1])))
                .fold(f64::INFINITY, f64::min)
        })
        .sum();
    sum / n as f64 * (n as f64).sqrt()
}

#[test]
fn art_keeps_samples_apart() {
    for n in [256u64, 1024, 4096] {
        let k = (n as f64).sqrt() as usize;
        let a = (0..4).map(|s| mean_nn(&set(n, s))).sum::<f64>() / 4.0;
        let jit = (0..4).map(|s| mean_nn(&jittered(k, s))).sum::<f64>() / 4.0;
        eprintln!("ART N {n}: mean NN distance {a:.4}, jittered {jit:.4} (white 0.5)");
        // White noise of unit density on the torus: 1/2 exactly (Clark & Evans 1954).
        assert!(a > 0.8 && a > jit + 0.15, "N {n}: ART {a} jittered {jit}");
    }
}

#[test]
fn importance_follows_the_density() {
    // A step: 1000 points a unit area on the left half, 4000 on the right.
    let x = art::importance(
        |x, _| if x < 0.5 { 1000.0 } else { 4000.0 },
        4000.0,
        2,
        &Budget::DEFAULT,
    )
    .unwrap()
    .to_f64();
    let left = x.chunks_exact(2).filter(|p| p[0] < 0.5).count() as f64;
    let right = (x.len() / 2) as f64 - left;
    eprintln!("ART step: left {left} (500), right {right} (2000)");
    assert!((left - 500.0).abs() < 3.0 * 500f64.sqrt());
    assert!((right - 2000.0).abs() < 3.0 * 2000f64.sqrt());
    // A ramp 4000 x y: the count in each of 4 x 4 cells is N times the cell's integral.
    for seed in 0..3 {
        let x = art::importance(|x, y| 4000.0 * x * y, 4000.0, seed, &Budget::DEFAULT)
            .unwrap()
            .to_f64();
        let mut c = [0.0f64; 16];
        for p in x.chunks_exact(2) {
            let (i, j) = ((p[0] * 4.0) as usize, (p[1] * 4.0) as usize);
            c[i.min(3) + 4 * j.min(3)] += 1.0;
        }
        for i in 0..4 {
            for j in 0..4 {
                let f = |a: usize| (((a + 1) * (a + 1)) as f64 - (a * a) as f64) / 32.0;
                let want = 4000.0 * f(i) * f(j);
                let got = c[i + 4 * j];
                assert!(
                    (got - want).abs() <= 0.05 * want + 3.0 * want.sqrt() + 2.0,
                    "seed {seed} cell ({i}, {j}): {got} against {want}"
                );
            }
        }
    }
}

#[test]
fn art_refuses_bad_input() {
    assert!(matches!(Art::new(0), Err(Error::ZeroPoints)));
    assert!(matches!(
        Art::new((1 << 24) + 1),
        Err(Error::TooManyPoints { .. })
    ));
    let b = Budget::DEFAULT;
    assert!(art::importance(|_, _| 1.0, 0.5, 0, &b).is_err());
    assert!(art::importance(|_, _| 1.0, f64::NAN, 0, &b).is_err());
    assert!(art::importance(|_, _| f64::NAN, 100.0, 0, &b).is_err());
    assert!(art::importance(|_, _| -1.0, 100.0, 0, &b).is_err());
    assert!(art::importance(|_, _| 200.0, 100.0, 0, &b).is_err());
    let mut e = [[0.5; 2]; art::ART_IDS];
    e[7][0] = 1.0;
    assert!(ArtTable::new(e).is_err());
    let tight = Budget::seconds(1e-6).unwrap();
    assert!(matches!(
        Art::new(1 << 24).unwrap().generate(&tight),
        Err(Error::OverBudget { .. })
    ));
}
