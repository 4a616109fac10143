//! `qmckit integration-test`: the rates against theory (papers' stated rates, not our own
//! output) and the one-line refusals.

use crate::common::cli::run;

/// The `(label, slope)` pairs of the command's output.
fn slopes(args: &[&str]) -> Vec<(String, f64)> {
    let out = run(args, "");
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("# n rmse\n"), "{text}");
    let mut v = Vec::new();
    let mut label = None;
    for line in text.lines() {
        if let Some(l) = line.strip_prefix("# label: ") {
            label = Some(l.to_string());
        } else if let Some(s) = line.strip_prefix("# slope: ") {
            v.push((label.take().unwrap(), s.parse().unwrap()));
        }
    }
    v
}

/// Monte Carlo's -0.5 on every family; jittered -1 on smooth integrands and -0.75 on a
/// Heaviside in 2D (-(1/2 + 1/(2d))); Owen-scrambled Sobol' clearly faster than jittered on
/// smooth integrands (-1.5 asymptotically, with (log N)^(d-1) factors) and -0.75 on a
/// Heaviside. Bands of +-0.1 around the theory (512 integrands give slopes within a few
/// hundredths).
#[test]
fn rates_follow_theory() {
    let smooth = slopes(&[
        "integration-test",
        "independent",
        "stratified",
        "sobol+owen",
        "--integrands",
        "256",
        "--max-m",
        "12",
    ]);
    let step = slopes(&[
        "integration-test",
        "independent",
        "stratified",
        "sobol+owen",
        "--family",
        "heaviside",
        "--integrands",
        "256",
        "--max-m",
        "12",
    ]);
    let get = |v: &[(String, f64)], l: &str| v.iter().find(|(n, _)| n == l).unwrap().1;
    for v in [&smooth, &step] {
        assert!((get(v, "independent") + 0.5).abs() < 0.1, "{v:?}");
    }
    assert!((get(&smooth, "stratified") + 1.0).abs() < 0.1, "{smooth:?}");
    assert!(get(&smooth, "sobol + owen") < -1.25, "{smooth:?}");
    assert!((get(&step, "stratified") + 0.75).abs() < 0.1, "{step:?}");
    assert!((get(&step, "sobol + owen") + 0.75).abs() < 0.1, "{step:?}");
}

/// Rotated Gaussians are as smooth as the axis-aligned ones: Monte Carlo's -0.5, jittered
/// -1, Owen-scrambled Sobol' clearly faster than jittered (the reference integrals, to
/// 1e-13, are far below the errors measured).
#[test]
fn rotated_gaussians_follow_the_smooth_rates() {
    let v = slopes(&[
        "integration-test",
        "independent",
        "stratified",
        "sobol+owen",
        "--family",
        "rotated-gaussian",
        "--integrands",
        "256",
        "--max-m",
        "12",
    ]);
    let get = |l: &str| v.iter().find(|(n, _)| n == l).unwrap().1;
    assert!((get("independent") + 0.5).abs() < 0.1, "{v:?}");
    assert!((get("stratified") + 1.0).abs() < 0.1, "{v:?}");
    assert!(get("sobol + owen") < -1.25, "{v:?}");
}

#[test]
fn bad_requests_are_refused_in_one_line() {
    for args in [
        &["integration-test", "nosuch"][..],
        &["integration-test", "sobol+nosuch"],
        &["integration-test", "halton+xor"],
        &["integration-test", "--family", "heaviside", "-d", "9"],
        &[
            "integration-test",
            "--family",
            "rotated-gaussian",
            "-d",
            "3",
        ],
        &["integration-test", "--max-m", "21"],
        &["integration-test", "--integrands", "0"],
        &[
            "integration-test",
            "--integrands",
            "1048576",
            "--max-m",
            "20",
        ],
        &["integration-test", "lp", "-d", "3"],
    ] {
        let out = run(args, "");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
}
