//! `qmckit points poisson|best-candidate|gaussian-blue-noise`: the command writes the
//! library's sets, honours its deadline and refuses what would not fit, in one line.

use crate::common::cli::{assert_usage_error, run};
use qmckit::blue_noise::{BestCandidate, PoissonDisk};
use qmckit::work::Budget;

fn gap(a: f64, b: f64, torus: bool) -> f64 {
    let d = (a - b).abs();
    if torus { d.min(1.0 - d) } else { d }
}

fn dist2(a: &[f64], b: &[f64], torus: bool) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| gap(*x, *y, torus).powi(2))
        .sum()
}

/// The smallest pairwise distance, by brute force.
fn min_distance(x: &[f64], d: usize, torus: bool) -> f64 {
    let n = x.len() / d;
    let mut best = f64::INFINITY;
    for i in 0..n {
        for j in i + 1..n {
            best = best.min(dist2(&x[i * d..i * d + d], &x[j * d..j * d + d], torus));
        }
    }
    best.sqrt()
}

fn parse(stdout: Vec<u8>) -> Vec<u32> {
    String::from_utf8(stdout)
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect()
}

#[test]
fn points_poisson_writes_the_library_set() {
    let out = run(
        &[
            "points", "poisson", "--radius", "0.05", "--torus", "--seed", "4", "--format", "u32",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0));
    let got = parse(out.stdout);
    let lib = PoissonDisk::new(2, 0.05)
        .unwrap()
        .torus(true)
        .seed(4)
        .generate(&Budget::DEFAULT)
        .unwrap();
    assert_eq!(got, lib.coords());
    let x = qmckit::analysis::Points::from_u32(&got);
    assert!(min_distance(&x, 2, true) >= 0.05);
    assert!(dist2(&x[0..2], &x[2..4], true) >= 0.0025);
    let out = run(
        &[
            "points", "poisson", "-n", "600", "-d", "3", "--format", "csv",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0));
    let lines = String::from_utf8(out.stdout).unwrap().lines().count() as f64;
    assert!((lines / 600.0 - 1.0).abs() < 0.03, "{lines}");
    let out = run(
        &[
            "points",
            "best-candidate",
            "-n",
            "50",
            "--candidates",
            "3",
            "--seed",
            "2",
            "--format",
            "u32",
        ],
        "",
    );
    let lib = BestCandidate::new(50)
        .unwrap()
        .candidates(3)
        .unwrap()
        .seed(2)
        .generate(&Budget::DEFAULT)
        .unwrap();
    assert_eq!(parse(out.stdout), lib.coords());
    let out = run(
        &[
            "points",
            "gaussian-blue-noise",
            "-n",
            "40",
            "--iterations",
            "5",
            "--format",
            "u32",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(parse(out.stdout).len(), 80);
}

#[test]
fn points_blue_noise_usage_errors() {
    for (args, needle) in [
        (
            &["points", "poisson", "--radius", "1e-6"][..],
            "packing bound",
        ),
        (&["points", "poisson", "--radius", "0"][..], "radius"),
        (&["points", "poisson", "--radius", "nan"][..], "radius"),
        (&["points", "poisson"][..], "--radius R or -n N"),
        (
            &["points", "poisson", "--radius", "0.1", "-n", "10"][..],
            "not both",
        ),
        (&["points", "poisson", "-n", "0"][..], "at least 1"),
        (
            &["points", "poisson", "-n", "100", "-d", "9"][..],
            "dimension",
        ),
        (
            &["points", "poisson", "-n", "100", "--start", "3"][..],
            "--start",
        ),
        (
            &["points", "poisson", "-n", "100", "--scramble", "rotate"][..],
            "--scramble",
        ),
        (
            &["points", "poisson", "-n", "100", "--iterations", "3"][..],
            "--iterations",
        ),
        (
            &[
                "points",
                "poisson",
                "--radius",
                "0.0005",
                "--max-seconds",
                "0.001",
            ][..],
            "time budget",
        ),
        (&["points", "best-candidate"][..], "-n N"),
        (
            &["points", "best-candidate", "-n", "10", "-d", "3"][..],
            "two-dimensional",
        ),
        (
            &["points", "best-candidate", "-n", "10", "--torus"][..],
            "--torus",
        ),
        (
            &["points", "best-candidate", "-n", "200000"][..],
            "time budget",
        ),
        (
            &["points", "gaussian-blue-noise", "-n", "1"][..],
            "two points",
        ),
        (
            &[
                "points",
                "gaussian-blue-noise",
                "-n",
                "10",
                "--candidates",
                "2",
            ][..],
            "--candidates",
        ),
        (
            &["points", "sobol", "-n", "4", "--radius", "0.1"][..],
            "--radius",
        ),
        (&["points", "sobol"][..], "-n N"),
    ] {
        assert_usage_error(args, "", needle);
    }
}

/// The deadline and the sizes of the blue-noise commands.
mod budget {
    use crate::common::cli::{assert_usage_error, run};

    /// A maximal fill in 7D, whose cost no estimate bounds (the cubes multiply at each
    /// split): admitted, then stopped by the deadline with one line naming the budget.
    #[test]
    fn an_unbounded_maximal_fill_ends_at_the_deadline() {
        let start = std::time::Instant::now();
        let out = run(
            &[
                "points",
                "poisson",
                "--radius",
                "1",
                "-d",
                "7",
                "--torus",
                "--maximal",
                "--max-seconds",
                "1",
            ],
            "",
        );
        let took = start.elapsed().as_secs_f64();
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("time budget of 1.0 s"), "{err}");
        assert!(err.contains("stopped"), "{err}");
        assert!(took < 1.5 + 0.5, "took {took} s");
        assert!(out.stdout.is_empty());
    }

    /// `-d` sizes a table before any point is made: past one row of 2^27 coordinates it
    /// is refused where it enters, one line and exit 2, never a capacity-overflow panic.
    #[test]
    fn oversized_dimensions_are_refused_where_they_enter() {
        for sampler in ["stratified", "independent", "halton", "sobol"] {
            for d in ["18446744073709551615", "134217729"] {
                assert_usage_error(&["points", sampler, "-n", "1", "-d", d], "", "-d");
            }
        }
    }
}
