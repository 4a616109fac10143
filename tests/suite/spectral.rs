//! Spectrum-controlled blue noise (Heck, Schlömer & Deussen 2013) and kernel-density blue
//! noise (Fattal 2011) against the properties their papers state: the target pair
//! correlation of the step is the closed-form Hankel transform `1 - (u_0/rho)^(d/2)
//! J_{d/2}(2 pi u_0 rho)` and is realizable only up to `u_0 = V_d^(-1/d)` (in 2D
//! `1/sqrt(pi)`); the measured mean radial spectrum over several seeds follows the step
//! and the single peak; the Gibbs samples of the kernel-density model have less
//! low-frequency power at a lower temperature, below white noise (`E P = 1`).
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::blue_noise::spectral::{Profile, ball_volume};
use qmckit::blue_noise::{KdeBlueNoise, PointSet, SpectralBlueNoise};
use qmckit::work::Budget;
use qmckit::{Error, Sampler};

use std::f64::consts::PI;

/// The mean radial spectrum (bins `r = 1..=k_max`, index `r - 1`) over the sets.
fn mean_radial(sets: &[PointSet], k_max: usize) -> Vec<f64> {
    let mut acc = vec![0.0; k_max];
    for s in sets {
        let x = s.to_f64();
        let sp = spectrum_2d(Points::new(&x, 2).unwrap(), k_max, &Budget::DEFAULT).unwrap();
        for b in sp.radial() {
            acc[b.radius - 1] += b.mean / sets.len() as f64;
        }
    }
    acc
}

fn budget() -> Budget {
    Budget::seconds(600.0).unwrap()
}

#[test]
fn step_target_is_the_closed_form_hankel_transform() {
    // 2D: G_0 = 1 - u_0 J_1(2 pi u_0 rho) / rho.
    let u0 = 0.5;
    let p = Profile::Step { cutoff: u0 };
    for &rho in &[0.02, 0.1, 0.3, 0.6, 1.0, 1.7, 2.5, 4.0] {
        let want = 1.0 - u0 * libm::j1(2.0 * PI * u0 * rho) / rho;
        let got = p.target_pcf(2, rho).unwrap();
        assert!((got - want).abs() < 1e-6, "2D rho {rho}: {got} vs {want}");
    }
    // 3D: J_{3/2}(x) = sqrt(2/(pi x)) (sin x / x - cos x).
    let u0 = 0.5;
    let p = Profile::Step { cutoff: u0 };
    for &rho in &[0.05, 0.3, 0.8, 1.5, 3.0] {
        let x = 2.0 * PI * u0 * rho;
        let j32 = (2.0 / (PI * x)).sqrt() * (x.sin() / x - x.cos());
        let want = 1.0 - (u0 / rho).powf(1.5) * j32;
        let got = p.target_pcf(3, rho).unwrap();
        assert!((got - want).abs() < 1e-6, "3D rho {rho}: {got} vs {want}");
    }
    // 1D: the cosine transform, G_0 = 1 - sin(2 pi u_0 rho) / (pi rho).
    let p = Profile::Step { cutoff: 0.4 };
    for &rho in &[0.05, 0.5, 1.2] {
        let want = 1.0 - (2.0 * PI * 0.4 * rho).sin() / (PI * rho);
        assert!((p.target_pcf(1, rho).unwrap() - want).abs() < 1e-6);
    }
}

#[test]
fn step_is_realizable_up_to_the_unit_ball_bound() {
    assert!((ball_volume(2) - PI).abs() < 1e-15);
    assert!((ball_volume(3) - 4.0 * PI / 3.0).abs() < 1e-15);
    assert!((ball_volume(5) - 8.0 * PI * PI / 15.0).abs() < 1e-14);
    for d in 1..=4usize {
        let bound = ball_volume(d).powf(-1.0 / d as f64);
        let below = Profile::Step {
            cutoff: 0.99 * bound,
        };
        let above = Profile::Step {
            cutoff: 1.02 * bound,
        };
        assert!(below.target_pcf(d, 0.5).is_ok(), "d = {d}");
        assert!(above.target_pcf(d, 0.5).is_err(), "d = {d}");
        // G_0(0+) = 1 - V_d u_0^d.
        let u0 = 0.8 * bound;
        let g = Profile::Step { cutoff: u0 }.target_pcf(d, 1e-4).unwrap();
        assert!(
            (g - (1.0 - ball_volume(d) * u0.powi(d as i32))).abs() < 1e-3,
            "d = {d}: {g}"
        );
    }
    // 2D: the paper's bound 1/sqrt(pi).
    assert!(Profile::Step { cutoff: 0.56 }.target_pcf(2, 1.0).is_ok());
    assert!(Profile::Step { cutoff: 0.575 }.target_pcf(2, 1.0).is_err());
}

#[test]
fn step_spectrum_follows_the_step() {
    let n = 512u64;
    let root = (n as f64).sqrt();
    let profile = Profile::step(2).unwrap();
    let Profile::Step { cutoff } = profile else {
        unreachable!()
    };
    let k0 = cutoff * root;
    let sets: Vec<PointSet> = (0..4)
        .map(|seed| {
            SpectralBlueNoise::new(n, 2, profile)
                .unwrap()
                .seed(seed)
                .generate(&budget())
                .unwrap()
        })
        .collect();
    let k_max = (2.0 * root).ceil() as usize;
    let p = mean_radial(&sets, k_max);
    for (i, &v) in p.iter().enumerate() {
        let k = (i + 1) as f64;
        if k + 0.5 < 0.9 * k0 {
            assert!(v < 0.1, "|k| = {k} below the cutoff {k0}: power {v}");
        }
        if k - 0.5 > 1.2 * k0 && k + 0.5 < 2.0 * root {
            assert!(
                (v - 1.0).abs() < 0.25,
                "|k| = {k} above the cutoff: power {v}"
            );
        }
    }
}

#[test]
fn single_peak_spectrum_has_its_zero_region_and_peak() {
    let n = 512u64;
    let root = (n as f64).sqrt();
    let profile = Profile::single_peak(2).unwrap();
    let Profile::SinglePeak { cutoff, width, .. } = profile else {
        unreachable!()
    };
    let sets: Vec<PointSet> = (0..4)
        .map(|seed| {
            SpectralBlueNoise::new(n, 2, profile)
                .unwrap()
                .seed(seed)
                .generate(&budget())
                .unwrap()
        })
        .collect();
    let k_max = (2.0 * root).ceil() as usize;
    let p = mean_radial(&sets, k_max);
    let mut peak: f64 = 0.0;
    for (i, &v) in p.iter().enumerate() {
        let u = (i + 1) as f64 / root;
        let half_bin = 0.5 / root;
        // A looser bound than the step's: the target's oscillating pair correlation is
        // harder to match.
        if u + half_bin < cutoff - 3.0 * width {
            assert!(v < 0.15, "u = {u}: power {v} in the zero region");
        }
        if (u - cutoff).abs() <= width {
            peak = peak.max(v);
        }
        if u - half_bin > cutoff + 4.0 * width && u < 2.0 {
            assert!((v - 1.0).abs() < 0.25, "u = {u}: power {v} above the peak");
        }
    }
    // The target there: p_0 / (sigma sqrt(2 pi)) + 1/2 = 2.0 at the centre, white noise
    // 1.
    assert!(peak > 1.6, "peak {peak}");
}

#[test]
fn kde_lower_temperature_less_low_frequency_power() {
    let n = 512u64;
    let root = (n as f64).sqrt();
    let k_max = (0.4 * root).floor() as usize;
    let low = |t: f64| {
        let sets: Vec<PointSet> = (0..3)
            .map(|seed| {
                KdeBlueNoise::new(n, 2)
                    .unwrap()
                    .temperature(t)
                    .unwrap()
                    .seed(seed)
                    .generate(&budget())
                    .unwrap()
            })
            .collect();
        let p = mean_radial(&sets, k_max);
        p.iter().sum::<f64>() / p.len() as f64
    };
    let (cold, default, warm, hot) = (low(0.002), low(0.01), low(0.1), low(2.0));
    // White noise has E P = 1 at every frequency.
    assert!(
        hot < 1.0 && warm < 0.5 && default < 0.1,
        "{hot} {warm} {default}"
    );
    assert!(
        cold < default && default < warm && warm < hot,
        "{cold} {default} {warm} {hot}"
    );
}

/// Fattal's multi-scale scheme relaxes the long wavelengths that local updates at one scale
/// arrange only slowly (the paper's "critical slowing down"): at equal sweeps a level, three
/// levels leave far less low-frequency power than one, and as much repulsion at a spacing.
#[test]
fn kde_multiscale_relaxes_long_wavelengths() {
    let n = 4096u64;
    let k_max = 16;
    let stats = |levels: u32| {
        let sets: Vec<PointSet> = (1..3)
            .map(|seed| {
                KdeBlueNoise::new(n, 2)
                    .unwrap()
                    .levels(levels)
                    .unwrap()
                    .seed(seed)
                    .generate(&budget())
                    .unwrap()
            })
            .collect();
        let p = mean_radial(&sets, k_max);
        p.iter().sum::<f64>() / p.len() as f64
    };
    let (one, three) = (stats(1), stats(3));
    assert!(three < 0.25 * one, "3 levels {three}, 1 level {one}");
    assert!(three < 0.005, "3 levels {three}");
}

/// Sizes that are not `2^d` times the coarser level's come out exact (surplus children
/// removed), in 1 to 3 dimensions.
#[test]
fn kde_multiscale_keeps_the_count() {
    for (d, n) in [(1usize, 77u64), (2, 1000), (3, 999)] {
        let s = KdeBlueNoise::new(n, d)
            .unwrap()
            .sweeps(4)
            .unwrap()
            .levels(3)
            .unwrap()
            .seed(2)
            .generate(&budget())
            .unwrap();
        assert_eq!((s.count(), s.dims()), (n as usize, d));
    }
}

#[test]
fn bad_input_is_an_error() {
    let step = Profile::step(2).unwrap();
    assert!(matches!(
        SpectralBlueNoise::new(0, 2, step),
        Err(Error::ZeroPoints)
    ));
    assert!(SpectralBlueNoise::new(1000, 0, step).is_err());
    assert!(SpectralBlueNoise::new(1 << 30, 2, step).is_err());
    assert!(Profile::step(7).is_err());
    assert!(SpectralBlueNoise::new(1, 2, step).is_err());
    assert!(SpectralBlueNoise::new(16, 2, step).is_ok()); // a shorter correlation range
    assert!(SpectralBlueNoise::new(1000, 2, Profile::Step { cutoff: 0.7 }).is_err());
    assert!(SpectralBlueNoise::new(1000, 2, Profile::Step { cutoff: f64::NAN }).is_err());
    let bad_peak = Profile::SinglePeak {
        cutoff: 0.75,
        energy: 0.0,
        width: 0.05,
    };
    assert!(SpectralBlueNoise::new(1000, 2, bad_peak).is_err()); // a step past the bound
    assert!(
        SpectralBlueNoise::new(1000, 2, step)
            .unwrap()
            .iterations(200_000)
            .is_err()
    );
    assert!(matches!(
        SpectralBlueNoise::new(1 << 22, 2, step)
            .unwrap()
            .generate(&Budget::seconds(0.01).unwrap()),
        Err(Error::OverBudget { .. })
    ));
    assert!(KdeBlueNoise::new(0, 2).is_err());
    assert!(KdeBlueNoise::new(1000, 6).is_err());
    assert!(KdeBlueNoise::new(1, 2).is_err());
    let k = KdeBlueNoise::new(1000, 2).unwrap();
    assert!(k.temperature(f64::NAN).is_err());
    assert!(k.temperature(-0.1).is_err());
    assert!(k.sigma(3.0).is_err());
    assert!(k.sweeps(1 << 20).is_err());
    assert!(k.levels(0).is_err());
    assert!(k.levels(9).is_err());
    assert!(matches!(
        KdeBlueNoise::new(1 << 22, 2)
            .unwrap()
            .generate(&Budget::seconds(0.01).unwrap()),
        Err(Error::OverBudget { .. })
    ));
}

#[test]
fn spectral_and_kde_run_in_other_dimensions() {
    // 1D and 3D: the sets are on the torus, the right size, and reproducible.
    for (d, n) in [(1usize, 64u64), (3, 2000)] {
        let s = SpectralBlueNoise::new(n, d, Profile::step(d).unwrap())
            .unwrap()
            .iterations(5)
            .unwrap()
            .generate(&budget())
            .unwrap();
        assert_eq!((s.count(), s.dims()), (n as usize, d));
    }
    let a = KdeBlueNoise::new(2000, 3)
        .unwrap()
        .sweeps(3)
        .unwrap()
        .seed(4);
    let (x, y) = (
        a.generate(&budget()).unwrap(),
        a.generate(&budget()).unwrap(),
    );
    assert_eq!(x, y);
}
