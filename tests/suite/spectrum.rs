//! The periodogram of `qmckit::analysis::spectrum` against numpy's complex exponentials and
//! against closed forms: one point, two points, the regular grid (its dual lattice), and
//! the expected spectra of white noise (level 1, anisotropy 1) and of jittered sampling
//! (`1 - |sinc|^2`, near 0 at low frequencies).
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::{SPECTRUM_MAX_K, spectrum_2d};
use qmckit::work::Budget;
use qmckit::{Independent, Jitter, Stratified};

use crate::common;
use common::sampler_points;

#[test]
fn matches_numpy_on_random_points() {
    let text = include_str!("../golden/spectrum_random_n50_k7.txt");
    let (mut pts, mut want) = (Vec::new(), Vec::new());
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let f: Vec<&str> = line.split(' ').collect();
        match f[0] {
            "point" => pts.extend([f[1].parse::<f64>().unwrap(), f[2].parse().unwrap()]),
            _ => want.push((
                f[1].parse::<i64>().unwrap(),
                f[2].parse::<i64>().unwrap(),
                f[3].parse::<f64>().unwrap(),
            )),
        }
    }
    assert_eq!((pts.len(), want.len()), (100, 225));
    let s = spectrum_2d(Points::new(&pts, 2).unwrap(), 7, &Budget::DEFAULT).unwrap();
    for (kx, ky, p) in want {
        let got = s.get(kx, ky).unwrap();
        // Sums of 50 unit phasors: numpy's and ours round differently, by ~1e-14 of N.
        assert!((got - p).abs() <= 1e-12, "({kx}, {ky}): {got} vs numpy {p}");
    }
}

#[test]
fn one_point_is_flat_and_two_points_are_a_cosine() {
    let s = spectrum_2d(
        Points::new(&[0.123, 0.987], 2).unwrap(),
        9,
        &Budget::DEFAULT,
    )
    .unwrap();
    assert!(s.iter().all(|(_, _, p)| (p - 1.0).abs() < 1e-12));
    // |e^(-i a) + e^(-i b)|^2 / 2 = 1 + cos(a - b), a - b = 2 pi k . (x1 - x2).
    let (x1, x2) = ([0.1, 0.35], [0.72, 0.05]);
    let s = spectrum_2d(
        Points::new(&[x1[0], x1[1], x2[0], x2[1]], 2).unwrap(),
        11,
        &Budget::DEFAULT,
    )
    .unwrap();
    assert_eq!(s.iter().count(), 23 * 23);
    for (kx, ky, p) in s.iter() {
        let dot = kx as f64 * (x1[0] - x2[0]) + ky as f64 * (x1[1] - x2[1]);
        let want = 1.0 + (std::f64::consts::TAU * dot).cos();
        assert!((p - want).abs() < 1e-12, "({kx}, {ky}): {p} vs {want}");
    }
    assert_eq!(s.get(12, 0), None);
    assert_eq!(s.get(0, -12), None);
    assert_eq!(s.get(i64::MIN, 0), None);
    assert_eq!(s.get(0, i64::MAX), None);
}

#[test]
fn a_grid_has_power_on_its_dual_lattice_only() {
    // The n x n grid of cell centres: S(k) = sum over i, j of phases is n^2 times a phase
    // when n divides kx and ky, else a full geometric sum, 0.
    let n = 8usize;
    let pts: Vec<f64> = (0..n * n)
        .flat_map(|c| {
            [
                ((c % n) as f64 + 0.5) / n as f64,
                ((c / n) as f64 + 0.5) / n as f64,
            ]
        })
        .collect();
    let s = spectrum_2d(Points::new(&pts, 2).unwrap(), 20, &Budget::DEFAULT).unwrap();
    for (kx, ky, p) in s.iter() {
        let on = kx % n as i64 == 0 && ky % n as i64 == 0;
        let want = if on { (n * n) as f64 } else { 0.0 };
        assert!((p - want).abs() < 1e-9, "({kx}, {ky}): {p} vs {want}");
    }
    // Annulus 8 holds (±8, 0), (0, ±8) at 64 and the other frequencies of |k| in [7.5, 8.5) at 0.
    let ring = s.radial()[7];
    assert_eq!(ring.radius, 8);
    assert!((ring.mean - 4.0 * 64.0 / ring.count as f64).abs() < 1e-9);
    assert!(ring.anisotropy > 1.0);
}

#[test]
fn white_noise_is_flat_and_jittered_sampling_is_blue() {
    // Uniform random points: E P(k) = 1, and P(k) is about exponentially distributed, so an
    // annulus's variance / mean^2 is about 1 (averaged over 16 seeds to steady it).
    let (k_max, seeds) = (32usize, 16u64);
    let mut mean = vec![0.0; k_max];
    let mut aniso = vec![0.0; k_max];
    for seed in 0..seeds {
        let pts = sampler_points(&Independent::new(2, seed).unwrap(), 1024);
        let s = spectrum_2d(Points::new(&pts, 2).unwrap(), k_max, &Budget::DEFAULT).unwrap();
        for (r, b) in s.radial().iter().enumerate() {
            mean[r] += b.mean / seeds as f64;
            aniso[r] += b.anisotropy / seeds as f64;
        }
    }
    for r in 4..k_max {
        assert!(
            (mean[r] - 1.0).abs() < 0.1,
            "white r {}: {}",
            r + 1,
            mean[r]
        );
        assert!(
            (aniso[r] - 1.0).abs() < 0.25,
            "white r {}: {}",
            r + 1,
            aniso[r]
        );
    }
    // Jittered 32 x 32: E P(k) = 1 - |phi(k)|^2 off the dual lattice (|k| < 32 here), with
    // phi(k) = sinc(pi kx / 32) sinc(pi ky / 32) the characteristic function of a uniform
    // offset in a cell of side 1/32: about 3e-3 at |k| = 1, 0.05 at 4, 0.6 at 16. Each
    // annulus mean (averaged over 8 seeds) against the same average of the formula.
    let m = 32.0;
    let sinc = |t: f64| if t == 0.0 { 1.0 } else { t.sin() / t };
    let expect = |kx: i64, ky: i64| {
        let phi =
            sinc(std::f64::consts::PI * kx as f64 / m) * sinc(std::f64::consts::PI * ky as f64 / m);
        1.0 - phi * phi
    };
    let mut got = vec![0.0; k_max];
    let mut formula = vec![(0.0, 0usize); k_max];
    for seed in 0..8 {
        let pts = sampler_points(
            &Stratified::uniform(32, 2, Jitter::Random(seed)).unwrap(),
            1024,
        );
        let s = spectrum_2d(Points::new(&pts, 2).unwrap(), k_max, &Budget::DEFAULT).unwrap();
        for (r, b) in s.radial().iter().enumerate() {
            got[r] += b.mean / 8.0;
        }
        if seed == 0 {
            for (kx, ky, _) in s.iter() {
                let r = ((kx * kx + ky * ky) as f64).sqrt().round() as usize;
                if (1..=k_max).contains(&r) {
                    formula[r - 1].0 += expect(kx, ky);
                    formula[r - 1].1 += 1;
                }
            }
        }
    }
    for r in 0..k_max - 1 {
        let want = formula[r].0 / formula[r].1 as f64;
        assert!(
            (got[r] - want).abs() < 0.15 * want + 1e-3,
            "jittered r {}: {} vs {want}",
            r + 1,
            got[r]
        );
    }
    assert!(got[0] < 0.01 && got[3] < 0.1 && got[15] > 0.3);
}

#[test]
fn refuses_what_it_cannot_do() {
    let p3 = Points::new(&[0.5, 0.5, 0.5], 3).unwrap();
    assert!(matches!(
        spectrum_2d(p3, 4, &Budget::DEFAULT),
        Err(qmckit::Error::Unsupported { .. })
    ));
    let p = Points::new(&[0.5, 0.5], 2).unwrap();
    assert!(matches!(
        spectrum_2d(p, SPECTRUM_MAX_K + 1, &Budget::DEFAULT),
        Err(qmckit::Error::Unsupported { .. })
    ));
    // 1e10 multiply-adds: K = 2048 allows 1e10 / (2049 * 4097) = 1191 points.
    let many = vec![0.25; 2 * 1192];
    assert_eq!(
        spectrum_2d(
            Points::new(&many, 2).unwrap(),
            SPECTRUM_MAX_K,
            &Budget::DEFAULT
        ),
        Err(qmckit::Error::TooManyPoints {
            requested: 1192,
            max: 1191
        })
    );
    let s = spectrum_2d(p, 0, &Budget::DEFAULT).unwrap();
    assert_eq!((s.k_max(), s.points(), s.get(0, 0)), (0, 1, Some(1.0)));
    assert!(s.radial().is_empty());
}

/// `(kx, ky, P_numpy, P_finufft)`: one frequency of a golden file of `gen_nufft.py`.
type GoldenPower = (i64, i64, f64, f64);

/// The points and powers of a golden file of `gen_nufft.py`.
fn nufft_golden(text: &str) -> (Vec<f64>, Vec<GoldenPower>) {
    let (mut pts, mut want) = (Vec::new(), Vec::new());
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let f: Vec<&str> = line.split(' ').collect();
        match f[0] {
            "point" => pts.extend(f[1..3].iter().map(|v| v.parse::<u32>().unwrap())),
            _ => want.push((
                f[1].parse().unwrap(),
                f[2].parse().unwrap(),
                f[3].parse().unwrap(),
                f[4].parse().unwrap(),
            )),
        }
    }
    (Points::from_u32(&pts), want)
}

#[test]
fn nufft_holds_its_tolerance_against_numpy_and_finufft() {
    use qmckit::analysis::spectrum::{Method, periodogram_2d};
    use qmckit::work::Budget;
    for text in [
        include_str!("../golden/nufft_white_n4096_k256.txt"),
        include_str!("../golden/nufft_grid_n4096_k256.txt"),
    ] {
        let (pts, want) = nufft_golden(text);
        assert_eq!((pts.len(), want.len()), (8192, 3601));
        let p = Points::new(&pts, 2).unwrap();
        // The oracles agree with each other to 1e-14 of N = max P.
        let n = 4096.0;
        for &(kx, ky, a, b) in &want {
            assert!((a - b).abs() <= 1e-13 * n, "oracles differ at ({kx}, {ky})");
        }
        for tol in [1e-6, 1e-9, 1e-12] {
            let s = periodogram_2d(p, 256, Method::Nufft, tol, &Budget::DEFAULT).unwrap();
            let worst = want
                .iter()
                .map(|&(kx, ky, a, _)| (s.get(kx, ky).unwrap() - a).abs())
                .fold(0.0, f64::max);
            assert!(
                worst <= tol * n,
                "tolerance {tol}: error {:e} of N",
                worst / n
            );
            // Not far below it either: the kernel is sized for the tolerance, not wasted.
            if tol > 1e-12 {
                assert!(worst >= tol * n * 1e-4, "tolerance {tol}: {:e}", worst / n);
            }
        }
        // The automatic choice is the NUFFT here, the direct sum for small sets.
        assert_eq!(
            qmckit::analysis::spectrum::choose_method(4096, 256, 1e-9),
            Method::Nufft
        );
        assert_eq!(
            qmckit::analysis::spectrum::choose_method(50, 7, 1e-9),
            Method::Direct
        );
    }
}

#[test]
fn nufft_matches_the_direct_sum_everywhere_on_small_sets() {
    use qmckit::analysis::spectrum::{Method, periodogram_2d};
    use qmckit::work::Budget;
    // Edge coordinates 0 and 1 (the same point on the torus), K = 0 and tiny grids.
    let pts = [0.0, 1.0, 1.0, 0.0, 0.5, 0.999_999, 0.123, 0.456, 0.75, 0.25];
    let p = Points::new(&pts, 2).unwrap();
    for k in [0, 1, 2, 5, 17] {
        let exact = spectrum_2d(p, k, &Budget::DEFAULT).unwrap();
        let fast = periodogram_2d(p, k, Method::Nufft, 1e-10, &Budget::DEFAULT).unwrap();
        for ((kx, ky, a), (_, _, b)) in exact.iter().zip(fast.iter()) {
            assert!(
                (a - b).abs() <= 1e-10 * 5.0,
                "K {k} ({kx}, {ky}): {a} vs {b}"
            );
        }
    }
    let bad = |tol: f64| periodogram_2d(p, 4, Method::Nufft, tol, &Budget::DEFAULT);
    for tol in [0.0, 1e-15, 0.5, f64::NAN, -1.0] {
        assert!(
            matches!(bad(tol), Err(qmckit::Error::InvalidParameter { .. })),
            "{tol}"
        );
    }
    let tiny = Budget::seconds(1e-6).unwrap();
    assert!(matches!(
        periodogram_2d(p, 2048, Method::Nufft, 1e-9, &tiny),
        Err(qmckit::Error::OverBudget { .. })
    ));
}

/// The deadline and the estimate's totality.
mod deadlines {
    use qmckit::Error;
    use qmckit::analysis::Points;
    use qmckit::analysis::spectrum::{Method, estimated_cost, periodogram_2d, spectrum_2d};
    use qmckit::work::Budget;
    use std::time::{Duration, Instant};

    fn expired(seconds: f64) -> Budget {
        let b = Budget::seconds(seconds).unwrap().started();
        std::thread::sleep(Duration::from_secs_f64(seconds * 1.25 + 0.01));
        b
    }

    #[test]
    fn an_expired_deadline_stops_both_methods() {
        let data: Vec<f64> = (0..2 * 5000)
            .map(|i| (i as f64 * 0.618_033_988_749_895).fract())
            .collect();
        let p = Points::new(&data, 2).unwrap();
        let b = expired(0.05);
        let direct = spectrum_2d(Points::new(&data[..400], 2).unwrap(), 16, &b);
        assert!(matches!(direct, Err(Error::OutOfTime { .. })), "{direct:?}");
        let fast = periodogram_2d(p, 64, Method::Nufft, 1e-9, &b);
        assert!(matches!(fast, Err(Error::OutOfTime { .. })), "{fast:?}");
    }

    #[test]
    fn the_estimate_is_o1_and_total() {
        let clock = Instant::now();
        for k in [usize::MAX, usize::MAX / 2, 1 << 40, 2049] {
            for tol in [f64::NAN, 0.0, -1.0, 1e-300, 1e308, f64::INFINITY] {
                for m in [Method::Auto, Method::Direct, Method::Nufft] {
                    let s = estimated_cost(1, k, m, tol).seconds();
                    assert!(s > 0.0 && !s.is_nan(), "{k} {tol} {m:?}: {s}");
                    let s = estimated_cost(usize::MAX, k, m, tol).seconds();
                    assert!(!s.is_nan(), "{k} {tol} {m:?}: {s}");
                }
            }
        }
        assert!(clock.elapsed().as_secs_f64() < 1.0);
    }
}
