//! The test integrands of `qmckit::analysis::integrate`: their closed-form integrals
//! against midpoint-rule quadrature written here from the definitions and against the
//! textbook ball volumes, and the error rates the module promises: Monte Carlo's RMSE at
//! `sigma / sqrt(N)`, QMC far below it on the smooth integrands.
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::integrate::{Integrand, integration_error};
use qmckit::randomize::{FastOwen, Scrambled};
use qmckit::{Independent, Sampler, Sobol};

use crate::common;
use common::sampler_points;

/// The midpoint rule on the `m^d` grid of cell centres: `(mean of f, mean of f^2)`.
fn midpoint(f: Integrand, d: usize, m: usize) -> (f64, f64) {
    let cells = m.pow(d as u32);
    let (mut s, mut s2) = (0.0, 0.0);
    let mut x = vec![0.0; d];
    for c in 0..cells {
        let mut rest = c;
        for xk in x.iter_mut() {
            *xk = ((rest % m) as f64 + 0.5) / m as f64;
            rest /= m;
        }
        let v = f.eval(&x);
        s += v;
        s2 += v * v;
    }
    (s / cells as f64, s2 / cells as f64)
}

#[test]
fn closed_forms_match_quadrature() {
    // (d, grid side, tolerance for the smooth integrands, for the indicators).
    for (d, m, smooth, sharp) in [
        (1, 1_000_000, 1e-11, 1e-5),
        (2, 3000, 1e-6, 1e-3),
        (3, 200, 1e-4, 1e-2),
    ] {
        for f in Integrand::ALL {
            let (q, _) = midpoint(f, d, m);
            let tol = if matches!(f, Integrand::Ball | Integrand::Heaviside) {
                sharp
            } else {
                smooth
            };
            let exact = f.exact(d);
            assert!(
                (q - exact).abs() < tol,
                "{} d {d}: quadrature {q} vs {exact}",
                f.name()
            );
        }
    }
    // Ball volumes: 2r, pi r^2, 4/3 pi r^3, pi^2 r^4 / 2, 8/15 pi^2 r^5.
    let (r, pi) = (0.45f64, std::f64::consts::PI);
    let volumes = [
        2.0 * r,
        pi * r * r,
        4.0 / 3.0 * pi * r.powi(3),
        pi * pi * r.powi(4) / 2.0,
        8.0 / 15.0 * pi * pi * r.powi(5),
    ];
    for (k, v) in volumes.iter().enumerate() {
        let got = Integrand::Ball.exact(k + 1);
        assert!((got - v).abs() < 1e-15, "ball d {}: {got} vs {v}", k + 1);
    }
    assert_eq!(Integrand::Ball.exact(0), 1.0);
}

#[test]
fn monte_carlo_error_is_sigma_over_root_n_and_qmc_beats_it() {
    let n = 4096usize;
    for f in [Integrand::Gaussian, Integrand::Oscillatory, Integrand::Ball] {
        let (mean, mean2) = midpoint(f, 2, 3000);
        let sigma = (mean2 - mean * mean).sqrt();
        let rmse = |s: &dyn Fn(u64) -> Box<dyn Sampler>| {
            let seeds = 64;
            let total: f64 = (0..seeds)
                .map(|seed| {
                    let pts = sampler_points(s(seed).as_ref(), n as u32);
                    integration_error(Points::new(&pts, 2).unwrap(), f).powi(2)
                })
                .sum();
            (total / seeds as f64).sqrt()
        };
        let mc = rmse(&|seed| Box::new(Independent::new(2, seed).unwrap()));
        let expected = sigma / (n as f64).sqrt();
        assert!(
            mc > 0.7 * expected && mc < 1.3 * expected,
            "{}: MC RMSE {mc} vs sigma/sqrt(N) {expected}",
            f.name()
        );
        let qmc =
            rmse(&|seed| Box::new(Scrambled::new(Sobol::new(2).unwrap(), FastOwen::new(seed))));
        // Scrambled Sobol': O(N^-3/2) on smooth integrands, about O(N^-3/4) on the ball.
        let factor = if f == Integrand::Ball { 5.0 } else { 100.0 };
        assert!(qmc * factor < mc, "{}: QMC RMSE {qmc} vs MC {mc}", f.name());
    }
}

#[test]
fn half_space_weights_are_sqrt_k_plus_2() {
    // The quadrature above cannot see the weights (any plane through the centre halves the
    // cube), so pin them by hand: the sign of sum_k sqrt(k + 2) (x_k - 1/2).
    // 0.1 sqrt(2) - 0.05 sqrt(3) - 0.02 sqrt(4) = 0.0148 >= 0.
    assert_eq!(Integrand::Heaviside.eval(&[0.6, 0.45, 0.48]), 1.0);
    // 0.1 sqrt(2) - 0.05 sqrt(3) - 0.04 sqrt(4) = -0.0252 < 0.
    assert_eq!(Integrand::Heaviside.eval(&[0.6, 0.45, 0.46]), 0.0);
    // -0.01 sqrt(2) - 0.01 sqrt(3) + 0.02 sqrt(5) = 0.0133 >= 0.
    assert_eq!(Integrand::Heaviside.eval(&[0.49, 0.49, 0.5, 0.52]), 1.0);
    // -0.02 sqrt(2) - 0.01 sqrt(3) + 0.01 sqrt(4) + 0.005 sqrt(5) = -0.0144 < 0.
    assert_eq!(Integrand::Heaviside.eval(&[0.48, 0.49, 0.51, 0.505]), 0.0);
}

#[test]
fn error_is_the_signed_difference() {
    let e = integration_error(
        Points::new(&[0.5, 0.5, 0.99, 0.99], 2).unwrap(),
        Integrand::Ball,
    );
    assert!((e - (0.5 - Integrand::Ball.exact(2))).abs() < 1e-15);
    let names: Vec<&str> = Integrand::ALL.iter().map(|f| f.name()).collect();
    assert_eq!(names, ["gaussian", "oscillatory", "ball", "heaviside"]);
}
