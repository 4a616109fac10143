//! Variance predicted from spectra (`qmckit::analysis::variance`) against exact values and
//! against measured RQMC variance: white noise (exact `(pi R^2 - pi^2 R^4) / N` by
//! Parseval), jittered sampling (its closed-form expected periodogram
//! `1 - sinc^2(pi kx / n) sinc^2(pi ky / n)`, and the `N^1.5 Var -> 0.261` law for the disk
//! of radius 1/4), fitted slopes, and the `qmckit variance` command.
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::{Method, SpectrumMean, periodogram_2d, spectrum_2d};
use qmckit::analysis::variance::{
    Measured, TorusIntegrand, fit_slope, predicted_variance, shifted_error,
};
use qmckit::work::Budget;
use qmckit::{Independent, Jitter, Sampler, Stratified};

use crate::common::sampler_points;
use std::f64::consts::PI;

/// The closed-form prediction for jittered `n x n` sampling, summed over `[-K, K]^2` by
/// hand (not through `predicted_variance`), plus the white tail from Parseval.
fn jittered_closed_form(n: u32, f: &TorusIntegrand, k: i64) -> f64 {
    let m = n as f64;
    let sinc = |t: f64| if t == 0.0 { 1.0 } else { t.sin() / t };
    let (mut sum, mut weight) = (0.0, 0.0);
    for ky in -k..=k {
        for kx in -k..=k {
            if (kx, ky) != (0, 0) {
                let phi = sinc(PI * kx as f64 / m) * sinc(PI * ky as f64 / m);
                let c = f.coefficient_sq(kx, ky);
                sum += c * (1.0 - phi * phi);
                weight += c;
            }
        }
    }
    (sum + f.white_noise_variance() - weight) / (m * m)
}

/// Mean square error over `sets` randomly shifted sets of `make(s)`.
fn measure(f: &TorusIntegrand, sets: u32, make: impl Fn(u32) -> Vec<f64>) -> Measured {
    let errors: Vec<f64> = (0..sets)
        .map(|s| {
            let pts = make(s);
            let shift = [0, 1].map(|d| qmckit::bits::to_f64(qmckit::hash::uniform(99, s, d)));
            shifted_error(Points::new(&pts, 2).unwrap(), f, shift).unwrap()
        })
        .collect();
    Measured::from_errors(&errors).unwrap()
}

fn jittered(side: u32, seed: u64) -> Vec<f64> {
    let s = Stratified::uniform(side, 2, Jitter::Random(seed)).unwrap();
    sampler_points(&s, side * side)
}

#[test]
fn white_noise_prediction_is_parseval_and_measured_within_5_percent() {
    let disk = TorusIntegrand::disk(0.25).unwrap();
    let exact = PI * 0.0625 - PI * PI * 0.0625 * 0.0625;
    assert!((disk.white_noise_variance() - exact).abs() < 1e-15);
    assert!((exact - 0.157_796_398_657_606_75).abs() < 1e-15);
    let mut pairs = Vec::new();
    for n in [16u32, 64, 256, 1024, 4096] {
        let m = measure(&disk, 16000, |s| {
            sampler_points(&Independent::new(2, 1000 + s as u64).unwrap(), n)
        });
        let want = exact / n as f64;
        assert!(
            (m.variance / want - 1.0).abs() < 0.05,
            "N {n}: measured {} vs {want}",
            m.variance
        );
        pairs.push((n as f64, m.variance));
    }
    assert!((fit_slope(&pairs).unwrap() + 1.0).abs() < 0.03);
}

#[test]
fn jittered_disk_prediction_follows_n_to_the_minus_1_5() {
    let disk = TorusIntegrand::disk(0.25).unwrap();
    let mut pairs = Vec::new();
    for side in [4u32, 8, 16, 32, 64] {
        let n = side * side;
        let v = jittered_closed_form(side, &disk, 4 * side as i64);
        pairs.push((n as f64, v));
        if n == 4096 {
            let scaled = (n as f64).powf(1.5) * v;
            assert!((scaled - 0.261).abs() < 0.003, "N^1.5 Var = {scaled}");
        }
    }
    let slope = fit_slope(&pairs).unwrap();
    assert!((slope + 1.5).abs() < 0.01, "slope {slope}");
}

#[test]
fn prediction_from_a_measured_mean_spectrum_matches_the_closed_form() {
    // 100 jittered 32 x 32 sets: their NUFFT periodograms averaged, then the prediction.
    let disk = TorusIntegrand::disk(0.25).unwrap();
    let gauss = TorusIntegrand::gaussian(0.1).unwrap();
    let mut mean = SpectrumMean::new();
    for seed in 0..100 {
        let pts = jittered(32, seed);
        let p = Points::new(&pts, 2).unwrap();
        mean.add(&periodogram_2d(p, 64, Method::Nufft, 1e-9, &Budget::DEFAULT).unwrap())
            .unwrap();
    }
    let mean = mean.mean().unwrap();
    for f in [disk, gauss] {
        let got = predicted_variance(&mean, &f).variance;
        let want = jittered_closed_form(32, &f, 64);
        assert!((got / want - 1.0).abs() < 0.03, "{f:?}: {got} vs {want}");
    }
    // One point's spectrum is flat: the prediction is then the white-noise variance.
    let one = spectrum_2d(Points::new(&[0.2, 0.9], 2).unwrap(), 8, &Budget::DEFAULT).unwrap();
    let p = predicted_variance(&one, &gauss);
    assert!((p.variance - gauss.white_noise_variance()).abs() < 1e-15);
    assert!(p.tail > 0.0 && p.tail < p.variance);
}

#[test]
fn jittered_measured_within_3_percent_of_predicted_for_n_16_to_4096() {
    let disk = TorusIntegrand::disk(0.25).unwrap();
    for side in [4u32, 8, 16, 32, 64] {
        let want = jittered_closed_form(side, &disk, 4 * side as i64);
        let m = measure(&disk, 20000, |s| jittered(side, 7_000_000 + s as u64));
        let ratio = m.variance / want;
        assert!(
            (ratio - 1.0).abs() < 0.03,
            "N {}: measured {} +- {} vs predicted {want} (ratio {ratio})",
            side * side,
            m.variance,
            m.std_error
        );
    }
}

#[test]
fn integrands_check_their_arguments_and_coefficients() {
    for r in [0.0, -0.1, 0.51, f64::NAN] {
        assert!(TorusIntegrand::disk(r).is_err(), "{r}");
    }
    for s in [0.0, 0.2, f64::NAN] {
        assert!(TorusIntegrand::gaussian(s).is_err(), "{s}");
    }
    // Parseval for the Gaussian: the coefficients sum to ||f||^2 (both computed here in
    // different ways: a truncated double sum against the theta-function product).
    let g = TorusIntegrand::gaussian(0.1).unwrap();
    let sum: f64 = (-20..=20i64)
        .flat_map(|a| (-20..=20i64).map(move |b| (a, b)))
        .map(|(a, b)| g.coefficient_sq(a, b))
        .sum();
    assert!((sum / g.norm_sq() - 1.0).abs() < 1e-12);
    // ... and against a midpoint rule for the integral of f^2 over the torus.
    let m = 400;
    let mut quad = 0.0;
    for i in 0..m {
        for j in 0..m {
            let v = g.eval((i as f64 + 0.5) / m as f64, (j as f64 + 0.5) / m as f64);
            quad += v * v;
        }
    }
    assert!((quad / (m * m) as f64 / g.norm_sq() - 1.0).abs() < 1e-9);
    assert!(shifted_error(Points::new(&[0.5; 3], 3).unwrap(), &g, [0.0, 0.0]).is_err());
    assert!(fit_slope(&[(1.0, 1.0)]).is_err());
    assert!(fit_slope(&[(1.0, 1.0), (1.0, 2.0)]).is_err());
    assert!(Measured::from_errors(&[]).is_err());
    let _ = Independent::new(2, 0).unwrap().dims();
}

/// Radii and widths that underflow are refused where they enter.
mod checks {
    use qmckit::analysis::variance::TorusIntegrand;

    #[test]
    fn scales_that_underflow_are_refused() {
        for r in [
            1e-200,
            5e-324,
            1e-51,
            0.0,
            -0.1,
            0.6,
            f64::NAN,
            f64::INFINITY,
        ] {
            assert!(TorusIntegrand::disk(r).is_err(), "{r}");
        }
        for s in [1e-200, 5e-324, 0.2, f64::NAN] {
            assert!(TorusIntegrand::gaussian(s).is_err(), "{s}");
        }
        assert!(TorusIntegrand::disk(1e-50).is_ok() && TorusIntegrand::gaussian(1e-50).is_ok());
    }
}
