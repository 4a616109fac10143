//! Kernel-density blue noise with a target density (Fattal 2011's density adaptation):
//! the counts in strips follow the integrals of the density, and the points are blue noise
//! at the local spacing in sparse and dense regions alike.

use qmckit::blue_noise::{KDE_MAX_DENSITY_RATIO, KdeBlueNoise};
use qmckit::work::Budget;
use std::f64::consts::{PI, TAU};

/// `D(x, y) = 2 - cos(2 pi x)`: 1 at `x = 0`, 3 at `x = 1/2`, mean 2.
fn density(x: &[f64]) -> f64 {
    2.0 - (TAU * x[0]).cos()
}

/// The fraction of the mass of `D / 2` in `a <= x < b`:
/// `(b - a) - (sin 2 pi b - sin 2 pi a) / (4 pi)`.
fn mass(a: f64, b: f64) -> f64 {
    (b - a) - ((TAU * b).sin() - (TAU * a).sin()) / (4.0 * PI)
}

fn torus_dist2(p: &[f64], q: &[f64]) -> f64 {
    p.iter()
        .zip(q)
        .map(|(a, b)| {
            let d = (a - b).abs();
            let d = d.min(1.0 - d);
            d * d
        })
        .sum()
}

/// 1024 points, 60 sweeps: the counts in the four strips of width 1/4 are within 2.5% of
/// `N` of `N` times the density's mass there (174.5 and 337.5 of 1024; white noise's standard
/// deviation is 12 to 15 points); the nearest-neighbour distance in units of the local
/// spacing `(N D(x))^(-1/2)` is far above white noise's mean `1/2` in the sparsest and the
/// densest strip, and nearly the same in both (the kernels follow the local spacing).
#[test]
fn counts_follow_the_density_and_spacing_follows_the_local_density() {
    let n = 1024usize;
    let pts = KdeBlueNoise::new(n as u64, 2)
        .unwrap()
        .sweeps(60)
        .unwrap()
        .seed(5)
        .run_density(&density, &Budget::UNLIMITED)
        .unwrap();
    assert_eq!(pts.len(), 2 * n);
    assert!(pts.iter().all(|x| (0.0..1.0).contains(x)));
    for k in 0..4 {
        let (a, b) = (k as f64 / 4.0, (k + 1) as f64 / 4.0);
        let count = pts
            .chunks_exact(2)
            .filter(|p| a <= p[0] && p[0] < b)
            .count();
        let want = n as f64 * mass(a, b);
        assert!(
            (count as f64 - want).abs() <= 0.025 * n as f64,
            "strip {k}: {count} vs {want}"
        );
    }
    // Normalized nearest-neighbour distances in |x| < 1/8 (D 1 to 1.3) and
    // |x - 1/2| < 1/8 (D 2.7 to 3).
    let mut sums = [(0.0, 0usize); 2];
    for (i, p) in pts.chunks_exact(2).enumerate() {
        let strip = if !(0.125..0.875).contains(&p[0]) {
            0
        } else if (p[0] - 0.5).abs() < 0.125 {
            1
        } else {
            continue;
        };
        let nn = pts
            .chunks_exact(2)
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, q)| torus_dist2(p, q))
            .fold(f64::INFINITY, f64::min)
            .sqrt();
        sums[strip].0 += nn * (n as f64 * density(p)).sqrt();
        sums[strip].1 += 1;
    }
    let [sparse, dense] = sums.map(|(s, c)| s / c as f64);
    assert!(sparse > 0.7 && dense > 0.7, "{sparse} {dense}");
    assert!((sparse / dense - 1.0).abs() < 0.15, "{sparse} {dense}");
}

/// The constant density gives the uniform model's distribution of points: the same counts
/// test passes with equal quarters.
#[test]
fn a_constant_density_gives_equal_quarters() {
    let n = 512usize;
    let pts = KdeBlueNoise::new(n as u64, 2)
        .unwrap()
        .sweeps(30)
        .unwrap()
        .seed(2)
        .run_density(&|_| 7.0, &Budget::UNLIMITED)
        .unwrap();
    for k in 0..4 {
        let (a, b) = (k as f64 / 4.0, (k + 1) as f64 / 4.0);
        let count = pts
            .chunks_exact(2)
            .filter(|p| a <= p[1] && p[1] < b)
            .count();
        assert!((count as f64 - 128.0).abs() <= 0.025 * n as f64, "{count}");
    }
}

#[test]
fn bad_densities_are_refused() {
    let k = KdeBlueNoise::new(64, 2).unwrap().sweeps(2).unwrap();
    let b = Budget::DEFAULT;
    assert!(k.run_density(&|x| x[0] - 0.5, &b).is_err());
    assert!(k.run_density(&|_| 0.0, &b).is_err());
    assert!(k.run_density(&|_| f64::NAN, &b).is_err());
    assert!(k.run_density(&|_| f64::INFINITY, &b).is_err());
    let steep = |x: &[f64]| 1.0 + 2.0 * KDE_MAX_DENSITY_RATIO * x[0];
    assert!(k.run_density(&steep, &b).is_err());
    assert!(k.sample(&|x| 1.0 + x[0], &b).is_ok());
}
