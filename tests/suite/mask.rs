//! Void-and-cluster masks against their definition: a permutation of the ranks, toroidal
//! tiling, threshold patterns whose low-frequency power is far below the white level of a
//! random pattern with the same number of ones, the static 64×64 table equal to the
//! generated mask, and the `qmckit mask` command's formats and errors.
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::blue_noise::mask64::{MASK64, rank, threshold};
use qmckit::blue_noise::{RankMask, VoidAndCluster};
use qmckit::work::Budget;
use qmckit::{Error, Independent};

fn is_permutation(ranks: &[u32]) -> bool {
    let mut seen = vec![false; ranks.len()];
    for &r in ranks {
        match seen.get_mut(r as usize) {
            Some(s) if !*s => *s = true,
            _ => return false,
        }
    }
    true
}

/// The pixel centres of the pattern as points of the unit torus.
fn pattern_points(on: &[bool], w: usize, h: usize) -> Vec<f64> {
    let mut x = Vec::new();
    for (i, &b) in on.iter().enumerate() {
        if b {
            x.push(((i % w) as f64 + 0.5) / w as f64);
            x.push(((i / w) as f64 + 0.5) / h as f64);
        }
    }
    x
}

/// Mean periodogram over `0 < |k| < k_lim`, divided by the white level of `m` random
/// pixels out of `n` (sampling without replacement: `E P = (n - m) / (n - 1)`).
fn relative_low_power(x: &[f64], n: usize, k_lim: f64) -> f64 {
    let m = x.len() / 2;
    let s = spectrum_2d(
        Points::new(x, 2).unwrap(),
        k_lim.ceil() as usize,
        &Budget::DEFAULT,
    )
    .unwrap();
    let (sum, count) = s
        .iter()
        .filter(|&(kx, ky, _)| {
            let k2 = (kx * kx + ky * ky) as f64;
            k2 > 0.0 && k2 < k_lim * k_lim
        })
        .fold((0.0, 0usize), |(s, c), (_, _, p)| (s + p, c + 1));
    let white = (n - m) as f64 / (n - 1) as f64;
    sum / count as f64 / white
}

/// Low frequencies: below a quarter of Ulichney's principal frequency `M sqrt(g)`
/// (`g <= 1/2`), at least 3.
fn k_low(side: usize, g: f64) -> f64 {
    (0.25 * side as f64 * g.min(1.0 - g).sqrt()).max(3.0)
}

#[test]
fn masks_are_permutations_and_thresholds_are_blue() {
    let side = 128;
    let mask: RankMask = VoidAndCluster::new(side, side)
        .unwrap()
        .seed(4)
        .generate(&Budget::DEFAULT)
        .unwrap();
    assert!(is_permutation(mask.ranks()));
    let n = side * side;
    for g in [0.01, 0.10, 0.50] {
        let ones = (g * n as f64).round() as usize;
        let on = mask.threshold(ones);
        assert_eq!(on.iter().filter(|&&b| b).count(), ones);
        let x = pattern_points(&on, side, side);
        let p = relative_low_power(&x, n, k_low(side, g));
        // Bound: 0.3 of white noise at 1% (a sparse pattern: its spacing, ~10 px, is far
        // wider than the kernel, measured 0.17), 0.1 at 10% and 50%.
        let bound = if g < 0.05 { 0.3 } else { 0.1 };
        eprintln!("g {g}: relative low-frequency power {p:.4}");
        assert!(p < bound, "g {g}: relative low-frequency power {p}");
        // A random pattern of the same count is near 1: the check can fail.
        let s = Independent::new(1, 9).unwrap();
        let mut keys: Vec<(u32, usize)> = (0..n)
            .map(|i| (s.sample(i as u32, 0).unwrap(), i))
            .collect();
        keys.sort_unstable();
        let mut white = vec![false; n];
        for &(_, i) in keys.iter().take(ones) {
            white[i] = true;
        }
        let pw = relative_low_power(&pattern_points(&white, side, side), n, k_low(side, g));
        assert!(pw > 0.5, "white pattern: {pw}");
    }
}

#[test]
fn non_square_and_tiny_masks_are_permutations() {
    for (w, h) in [(1, 1), (1, 7), (3, 2), (5, 40), (17, 9), (33, 64)] {
        let m = VoidAndCluster::new(w, h)
            .unwrap()
            .seed(1)
            .generate(&Budget::DEFAULT)
            .unwrap();
        assert_eq!(m.ranks().len(), w * h);
        assert!(is_permutation(m.ranks()), "{w}x{h}");
    }
    let a = VoidAndCluster::new(32, 32)
        .unwrap()
        .seed(7)
        .generate(&Budget::DEFAULT)
        .unwrap();
    assert_eq!(
        a,
        VoidAndCluster::new(32, 32)
            .unwrap()
            .seed(7)
            .generate(&Budget::DEFAULT)
            .unwrap()
    );
    assert_ne!(
        a,
        VoidAndCluster::new(32, 32)
            .unwrap()
            .seed(8)
            .generate(&Budget::DEFAULT)
            .unwrap()
    );
}

#[test]
fn bad_mask_sizes_are_errors() {
    assert!(matches!(
        VoidAndCluster::new(0, 5),
        Err(Error::InvalidParameter { .. })
    ));
    assert!(VoidAndCluster::new(5000, 5).is_err());
    assert!(matches!(
        VoidAndCluster::new(4096, 4096),
        Err(Error::TooLarge { .. })
    ));
    assert!(VoidAndCluster::new(8, 8).unwrap().sigma(0.1).is_err());
    assert!(VoidAndCluster::new(8, 8).unwrap().sigma(f64::NAN).is_err());
    let tight = qmckit::work::Budget::seconds(1e-4).unwrap();
    assert!(matches!(
        VoidAndCluster::new(1024, 1024).unwrap().generate(&tight),
        Err(Error::OverBudget { .. })
    ));
}

#[test]
fn the_static_table_is_the_generated_mask() {
    let m = VoidAndCluster::new(64, 64)
        .unwrap()
        .seed(0)
        .generate(&Budget::DEFAULT)
        .unwrap();
    let table: Vec<u32> = MASK64.iter().map(|&r| u32::from(r)).collect();
    assert_eq!(table, m.ranks(), "regenerate with examples/gen_mask64.rs");
    assert_eq!(rank(64 + 3, 2 * 64 + 5), MASK64[5 * 64 + 3]);
    let lit = (0..4096)
        .filter(|&i| threshold(i % 64, i / 64, 0.1))
        .count();
    assert_eq!(lit, 410);
    assert_eq!(
        (0..4096)
            .filter(|&i| threshold(i % 64, i / 64, 0.0))
            .count(),
        0
    );
    assert_eq!(
        (0..4096)
            .filter(|&i| threshold(i % 64, i / 64, 1.0))
            .count(),
        4096
    );
}

#[test]
fn void_and_cluster_stops_at_its_deadline() {
    let side = (4..12)
        .map(|k| 1usize << k)
        .find(|&s| VoidAndCluster::new(s, s).unwrap().cost().seconds() >= 0.3)
        .unwrap_or(2048);
    let vc = VoidAndCluster::new(side, side).unwrap();
    crate::blue_noise::budget::stops_at_the_deadline(
        "void and cluster",
        vc.cost().seconds(),
        |b| vc.generate(b),
    );
    // The estimate grows with the pixels faster than linearly (cache misses of the trees).
    let s = |w: usize| VoidAndCluster::new(w, w).unwrap().cost().seconds();
    assert!(s(1024) > 4.0 * s(512) && s(512) > 4.0 * s(256));
}
