//! `qmckit variance`: predicted against measured variance, and one-line refusals.

use qmckit::analysis::variance::TorusIntegrand;
use std::f64::consts::PI;

use crate::common::cli::{assert_usage_error, run};

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

#[test]
fn cli_variance_prints_predicted_and_measured() {
    let out = run(&["variance", "jittered", "-n", "64", "--sets", "4000"], "");
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let get = |key: &str| -> String {
        text.lines()
            .find_map(|l| l.strip_prefix(key).and_then(|r| r.strip_prefix(' ')))
            .unwrap_or_else(|| panic!("{key} missing in {text}"))
            .to_owned()
    };
    assert_eq!(get("sampler"), "stratified");
    assert_eq!(get("scramble"), "none");
    assert_eq!(get("integrand"), "torus-disk");
    let predicted: f64 = get("predicted").parse().unwrap();
    let want = jittered_closed_form(8, &TorusIntegrand::disk(0.25).unwrap(), 32);
    assert!(
        (predicted / want - 1.0).abs() < 0.03,
        "{predicted} vs {want}"
    );
    let ratio: f64 = get("ratio").parse().unwrap();
    assert!((ratio - 1.0).abs() < 0.1, "{ratio}");
    let white: f64 = get("white").parse().unwrap();
    assert!((white - 0.157_796_398_657_606_75 / 64.0).abs() < 1e-15);
    for sampler in ["independent", "halton", "sobol", "owen-sobol"] {
        let out = run(&["variance", sampler, "-n", "256", "--sets", "50"], "");
        assert_eq!(out.status.code(), Some(0), "{sampler}");
    }
    assert_usage_error(&["variance", "jittered", "-n", "50"], "", "square number");
    assert_usage_error(&["variance", "sobol", "-n", "0"], "", "at least 1");
    assert_usage_error(
        &["variance", "sobol", "-n", "64", "--radius", "0.7"],
        "",
        "radius",
    );
    // Blue-noise sets: measured within 4 standard errors of the prediction, both well below
    // white noise; Poisson sets have about N points.
    for (sampler, n, sets) in [
        ("poisson", "256", "400"),
        ("gaussian-blue-noise", "64", "30"),
    ] {
        let out = run(
            &[
                "variance",
                sampler,
                "-n",
                n,
                "--sets",
                sets,
                "--max-seconds",
                "600",
            ],
            "",
        );
        assert_eq!(out.status.code(), Some(0), "{sampler}");
        let text = String::from_utf8(out.stdout).unwrap();
        let kv = |key: &str| -> f64 {
            text.lines()
                .find_map(|l| l.strip_prefix(key).and_then(|r| r.strip_prefix(' ')))
                .unwrap_or_else(|| panic!("{key} missing in {text}"))
                .parse()
                .unwrap()
        };
        let n: f64 = n.parse().unwrap();
        assert!((kv("n_mean") / n - 1.0).abs() < 0.03, "{sampler}: {text}");
        let (p, m, se) = (kv("predicted"), kv("measured"), kv("std_error"));
        assert!((m - p).abs() < 4.0 * se, "{sampler}: {text}");
        assert!(p < 0.3 * kv("white"), "{sampler}: {text}");
    }
    assert_usage_error(
        &[
            "variance",
            "gaussian-blue-noise",
            "-n",
            "4096",
            "--sets",
            "100",
        ],
        "",
        "raise it",
    );
    assert_usage_error(
        &[
            "variance",
            "independent",
            "-n",
            "1000000",
            "--sets",
            "100000",
        ],
        "",
        "raise it",
    );
}

/// Parameters where they enter: radii and widths that underflow, `--k-max`, `--sets`.
mod checks {
    use crate::common::cli::{assert_usage_error, run};

    #[test]
    fn a_radius_that_underflows_is_refused() {
        assert_usage_error(
            &["variance", "halton", "-n", "64", "--radius", "1e-200"],
            "",
            "radius",
        );
    }

    #[test]
    fn k_max_is_honoured_or_refused() {
        assert_usage_error(
            &["variance", "halton", "-n", "64", "--k-max", "0"],
            "",
            "--k-max 0",
        );
        let out = run(
            &[
                "variance", "halton", "-n", "64", "--sets", "4", "--k-max", "8",
            ],
            "",
        );
        assert_eq!(out.status.code(), Some(0));
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(text.lines().any(|l| l == "k_max 8"), "{text}");
    }

    #[test]
    fn a_huge_set_count_is_an_error_not_an_abort() {
        assert_usage_error(
            &[
                "variance",
                "halton",
                "-n",
                "1",
                "--sets",
                "536870912",
                "--max-seconds",
                "inf",
            ],
            "",
            "too many bytes",
        );
    }
}
