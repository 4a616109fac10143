//! The pair correlation function (`qmckit::analysis::pcf`) against exact pair counts (the
//! grid), the level 1 of independent points (Euclidean with the square's edge correction,
//! and toroidal), and against the spectrum: the Hankel transform of the mean PCF of
//! hard-disk sets against their mean radial periodogram.
#![cfg(feature = "analysis")]

use qmckit::Independent;
use qmckit::analysis::Points;
use qmckit::analysis::pcf::{PcfOptions, pcf_2d, structure_factor};
use qmckit::analysis::spectrum::{Method, SpectrumMean, periodogram_2d};
use qmckit::work::Budget;

use crate::common::sampler_points;

#[test]
fn the_grid_has_exactly_four_neighbours_per_point() {
    // 32 x 32 grid on the torus: sum_{i != j} over the pairs at 1/32 is 4N, so
    // N (N - 1) int g 2 pi r dr over the first peak is 4N.
    let n = 32usize;
    let pts: Vec<f64> = (0..n * n)
        .flat_map(|i| [(i % n) as f64 / n as f64, (i / n) as f64 / n as f64])
        .collect();
    let opts = PcfOptions {
        r_max: 0.05,
        bins: 500,
        sigma: 0.0005,
        torus: true,
    };
    let g = pcf_2d(Points::new(&pts, 2).unwrap(), &opts, &Budget::DEFAULT).unwrap();
    let dr = 0.05 / 500.0;
    let mass: f64 = g
        .iter()
        .filter(|b| b.radius < 0.038)
        .map(|b| b.g * 2.0 * std::f64::consts::PI * b.radius * dr)
        .sum();
    let want = 4.0 / (n * n - 1) as f64;
    assert!((mass / want - 1.0).abs() < 1e-6, "{mass} vs {want}");
    // Nothing below the spacing (minus the kernel's reach); the diagonal at sqrt(2)/32.
    assert!(g.iter().filter(|b| b.radius < 0.028).all(|b| b.g < 1e-12));
    let diag = 2f64.sqrt() / 32.0;
    let peak = g
        .iter()
        .filter(|b| b.radius > 0.038)
        .max_by(|a, b| a.g.total_cmp(&b.g))
        .unwrap();
    assert!((peak.radius - diag).abs() < 2e-4, "{}", peak.radius);
}

#[test]
fn independent_points_have_g_one_on_the_torus_and_in_the_square() {
    for torus in [true, false] {
        let opts = PcfOptions::new(0.2, 20, torus);
        let mut mean = [0.0; 20];
        for seed in 0..20 {
            let pts = sampler_points(&Independent::new(2, 50 + seed).unwrap(), 2000);
            let g = pcf_2d(Points::new(&pts, 2).unwrap(), &opts, &Budget::DEFAULT).unwrap();
            for (m, b) in mean.iter_mut().zip(&g) {
                *m += b.g / 20.0;
            }
        }
        // Without the edge factor the square's g would fall to 1 - 4r/pi: 0.75 at 0.195.
        for (k, m) in mean.iter().enumerate().skip(2) {
            assert!((m - 1.0).abs() < 0.02, "torus {torus} bin {k}: {m}");
        }
    }
}

/// A hard-disk set by random sequential addition: uniform darts (a fixed hash stream),
/// each kept when no kept point is within `r` on the torus, until `n` are kept.
fn hard_disks(n: usize, r: f64, seed: u64) -> Vec<f64> {
    let mut pts: Vec<f64> = Vec::with_capacity(2 * n);
    let mut i = 0u32;
    while pts.len() < 2 * n {
        let x = qmckit::bits::to_f64(qmckit::hash::uniform(seed, i, 0));
        let y = qmckit::bits::to_f64(qmckit::hash::uniform(seed, i, 1));
        i += 1;
        let near = |a: f64| {
            let a = a.abs();
            a.min(1.0 - a)
        };
        if pts.chunks_exact(2).all(|p| {
            let (dx, dy) = (near(p[0] - x), near(p[1] - y));
            dx * dx + dy * dy >= r * r
        }) {
            pts.extend([x, y]);
        }
    }
    pts
}

#[test]
fn spectrum_and_pcf_agree_on_hard_disk_sets() {
    let (n, sets) = (400usize, 60u64);
    let r = 0.6 / (n as f64).sqrt();
    let opts = PcfOptions {
        r_max: 0.25,
        bins: 500,
        sigma: 0.001,
        torus: true,
    };
    let mut g_mean = vec![0.0; 500];
    let mut spectra = SpectrumMean::new();
    let mut grid = Vec::new();
    for seed in 0..sets {
        let pts = hard_disks(n, r, seed);
        let p = Points::new(&pts, 2).unwrap();
        let g = pcf_2d(p, &opts, &Budget::DEFAULT).unwrap();
        for (m, b) in g_mean.iter_mut().zip(&g) {
            *m += b.g / sets as f64;
        }
        grid = g;
        let s = periodogram_2d(p, 40, Method::Auto, 1e-9, &Budget::DEFAULT).unwrap();
        spectra.add(&s).unwrap();
    }
    for (b, m) in grid.iter_mut().zip(&g_mean) {
        b.g = *m;
    }
    let radial = spectra.mean().unwrap().radial();
    // Frequencies from 0.25 sqrt(N) = 5 to 2 sqrt(N) = 40: the hole at low k, the peak.
    let mut worst: f64 = 0.0;
    for bin in radial.iter().filter(|b| b.radius >= 5) {
        let from_g = structure_factor(&grid, n, bin.radius as f64);
        worst = worst.max((from_g - bin.mean).abs());
        assert!(
            (from_g - bin.mean).abs() < 0.12,
            "|k| = {}: PCF gives {from_g}, spectrum {}",
            bin.radius,
            bin.mean
        );
    }
    // The low-frequency hole is real on both sides.
    assert!(structure_factor(&grid, n, 6.0) < 0.6);
    assert!(worst > 0.0);
}

#[test]
fn pcf_refuses_bad_arguments() {
    let p = Points::new(&[0.1, 0.2, 0.3, 0.4], 2).unwrap();
    let b = Budget::DEFAULT;
    for (r, bins, torus) in [
        (0.0, 10, true),
        (0.6, 10, true),
        (1.5, 10, false),
        (0.1, 0, false),
    ] {
        assert!(pcf_2d(p, &PcfOptions::new(r, bins, torus), &b).is_err());
    }
    let mut o = PcfOptions::new(0.1, 10, true);
    o.sigma = f64::NAN;
    assert!(pcf_2d(p, &o, &b).is_err());
    let one = Points::new(&[0.1, 0.2], 2).unwrap();
    assert!(pcf_2d(one, &PcfOptions::new(0.1, 10, true), &b).is_err());
    let p3 = Points::new(&[0.1, 0.2, 0.3], 3).unwrap();
    assert!(pcf_2d(p3, &PcfOptions::new(0.1, 10, true), &b).is_err());
    let many = vec![0.5; 2 * 200_000];
    let tiny = Budget::seconds(0.01).unwrap();
    assert!(matches!(
        pcf_2d(
            Points::new(&many, 2).unwrap(),
            &PcfOptions::new(0.1, 10, true),
            &tiny
        ),
        Err(qmckit::Error::OverBudget { .. })
    ));
}

/// Parameters that would underflow or overflow the kernel are refused; the deadline stops
/// the pair loop.
mod checks {
    use qmckit::Error;
    use qmckit::analysis::Points;
    use qmckit::analysis::pcf::{PcfOptions, pcf_2d};
    use qmckit::work::Budget;

    fn grid() -> Vec<f64> {
        (0..400)
            .flat_map(|i| [(i % 20) as f64 / 20.0, (i / 20) as f64 / 20.0])
            .collect()
    }

    #[test]
    fn tiny_or_huge_lengths_are_refused_not_nan() {
        let data = grid();
        let p = Points::new(&data, 2).unwrap();
        for sigma in [
            5e-324,
            1e-200,
            1e308,
            f64::INFINITY,
            f64::NAN,
            -1.0,
            0.0,
            2.0,
        ] {
            let mut o = PcfOptions::new(0.15, 50, false);
            o.sigma = sigma;
            let r = pcf_2d(p, &o, &Budget::UNLIMITED);
            assert!(
                matches!(r, Err(Error::InvalidParameter { .. })),
                "{sigma}: {r:?}"
            );
        }
        let mut o = PcfOptions::new(1e-200, 10, true);
        o.sigma = 0.01;
        assert!(pcf_2d(p, &o, &Budget::UNLIMITED).is_err());
        // At the edges of the ranges every bin is a number.
        let mut o = PcfOptions::new(0.15, 50, false);
        o.sigma = 1e-100;
        let g = pcf_2d(p, &o, &Budget::UNLIMITED).unwrap();
        assert!(g.iter().all(|b| b.g.is_finite()));
        o.sigma = 1.0;
        let g = pcf_2d(p, &o, &Budget::UNLIMITED).unwrap();
        assert!(g.iter().all(|b| b.g.is_finite()));
    }

    #[test]
    fn an_expired_deadline_stops_the_pairs() {
        let data = grid();
        let p = Points::new(&data, 2).unwrap();
        let b = Budget::seconds(0.02).unwrap().started();
        std::thread::sleep(std::time::Duration::from_millis(40));
        let r = pcf_2d(p, &PcfOptions::new(0.15, 50, false), &b);
        assert!(matches!(r, Err(Error::OutOfTime { .. })), "{r:?}");
    }
}
