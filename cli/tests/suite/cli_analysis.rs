//! `qmckit discrepancy`, `spectrum`, `convergence` and `tvalue`: values, output format, one-line errors.

use std::path::PathBuf;

use crate::common;
use common::cli::{assert_usage_error, run as qmckit_with};

/// Standard output of a successful run with an empty stdin; stderr must be empty.
fn stdout(args: &[&str], input: &str) -> String {
    let out = qmckit_with(args, input);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty(), "{args:?}: stderr {:?}", out.stderr);
    String::from_utf8(out.stdout).unwrap()
}

/// A file in the temporary directory holding `text` (unique per test).
fn temp_file(name: &str, text: &str) -> PathBuf {
    let path =
        std::env::temp_dir().join(format!("qmckit-cli-analysis-{}-{name}", std::process::id()));
    std::fs::write(&path, text).unwrap();
    path
}

/// The `metric value` lines as pairs.
fn values(text: &str) -> Vec<(String, f64)> {
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let (name, value) = l.split_once(' ').expect("metric value");
            (name.to_owned(), value.parse().expect("a number"))
        })
        .collect()
}

#[test]
fn lp_net_star_discrepancy_is_21_over_512() {
    let csv = stdout(&["points", "lp", "-n", "64", "--format", "csv"], "");
    let text = stdout(&["discrepancy", "--metric", "star"], &csv);
    // Exact for the 64-point Larcher–Pillichshammer net (see analysis::star).
    assert_eq!(values(&text), [("star".to_owned(), 21.0 / 512.0)]);
    assert_eq!(text, "star 4.1015625000000000e-2\n");
}

#[test]
fn one_point_in_1d() {
    let path = temp_file("one-point", "0.5\n");
    let text = stdout(
        &[
            "discrepancy",
            "--metric",
            "star,l2-star",
            path.to_str().unwrap(),
        ],
        "",
    );
    let v = values(&text);
    // Star: [0, 1/2) is empty (1/2 - 0) and [0, 1/2] holds the point (1 - 1/2): 1/2.
    assert_eq!(v[0], ("star".to_owned(), 0.5));
    // Warnock's formula for n = 1, d = 1:
    //   D^2 = 1/3 - 2^(1-1) (1 - x^2) + (1 - max(x, x)) = 1/3 - (1 - x^2) + (1 - x)
    //       = x^2 - x + 1/3,   at x = 1/2: 1/4 - 1/2 + 1/3 = 1/12,
    // and l2-star is the square root (SciPy's convention): sqrt(1/12).
    assert_eq!(v[1].0, "l2-star");
    assert!(
        (v[1].1 - (1.0f64 / 12.0).sqrt()).abs() < 1e-16,
        "{}",
        v[1].1
    );
    // At least 15 significant digits: 17 in scientific notation.
    let mantissa = text.lines().nth(1).unwrap().split(' ').nth(1).unwrap();
    let digits = mantissa.split('e').next().unwrap().replace('.', "");
    assert!(digits.len() >= 15, "{mantissa}");
    std::fs::remove_file(path).ok();
}

#[test]
fn all_metrics_by_default_in_order() {
    let text = stdout(&["discrepancy"], "0.25 0.25\n0.75, 0.75\n");
    let names: Vec<String> = values(&text).into_iter().map(|(n, _)| n).collect();
    assert_eq!(
        names,
        [
            "star", "l2-star", "cd", "wd", "md", "sl2", "ul2", "gl2", "diaphony"
        ]
    );
    for (name, v) in values(&text) {
        assert!(v.is_finite() && v >= 0.0, "{name} {v}");
    }
}

#[test]
fn several_sets_get_headers_and_stdin_dash_works() {
    let input = "# two sets\n0.5\n#\n0.125\n0.375 # comment\n0.625\n0.875\n";
    let text = stdout(&["discrepancy", "--metric", "star", "-"], input);
    assert_eq!(
        text,
        "# set 1\nstar 5.0000000000000000e-1\n# set 2\nstar 1.2500000000000000e-1\n"
    );
    // No header with a single set.
    assert_eq!(
        stdout(&["discrepancy", "--metric", "star"], "0.5\n"),
        "star 5.0000000000000000e-1\n"
    );
}

#[test]
fn extreme_in_2d() {
    let input = "0.25 0.25\n0.75 0.25\n0.25 0.75\n0.75 0.75\n";
    let text = stdout(&["discrepancy", "--metric", "extreme"], input);
    assert_eq!(values(&text), [("extreme".to_owned(), 0.75)]);
    assert_usage_error(
        &["discrepancy", "--metric", "extreme"],
        "0.5\n",
        "2-dimensional points only",
    );
}

#[test]
fn star_is_refused_when_too_large_and_skipped_by_all() {
    let csv = stdout(
        &["points", "sobol", "-n", "600", "-d", "6", "--format", "csv"],
        "",
    );
    assert_usage_error(
        &["discrepancy", "--metric", "star"],
        &csv,
        "too many for the exact star",
    );
    let text = stdout(&["discrepancy"], &csv);
    assert!(text.starts_with("# star skipped: 600 points"), "{text}");
    assert_eq!(values(&text).len(), 8);
}

#[test]
fn max_seconds_sets_the_star_budget() {
    let csv_of = |n: &str, d: &str| {
        stdout(
            &["points", "sobol", "-n", n, "-d", d, "--format", "csv"],
            "",
        )
    };
    // 2000 3D points are within the default budget (64517) but not within a hundredth of a
    // second: 25.3 N^1.85 nanoseconds of one core, within 2e7 on two cores up to N = 1541.
    let small = csv_of("2000", "3");
    assert_usage_error(
        &["discrepancy", "--metric", "star", "--max-seconds", "0.01"],
        &small,
        "(at most 1541 within --max-seconds 0.01)",
    );
    // 'inf' is no limit; zero, negatives and NaN are refused.
    assert_eq!(
        values(&stdout(
            &["discrepancy", "--metric", "cd", "--max-seconds=inf"],
            "0.5\n"
        ))
        .len(),
        1
    );
    for bad in ["0", "-1", "nan"] {
        assert_usage_error(
            &[
                "discrepancy",
                "--metric",
                "cd",
                &format!("--max-seconds={bad}"),
            ],
            "0.5\n",
            "--max-seconds must be a positive number of seconds",
        );
    }
    // 42 12D points: refused within a second (0.0123 N^7 nanoseconds of one core, within
    // 2e9 on two cores up to N = 40), computed with 20 seconds (about 1.4 s estimated).
    let large = csv_of("42", "12");
    assert_usage_error(
        &["discrepancy", "--metric", "star", "--max-seconds", "1"],
        &large,
        "(at most 40 within --max-seconds 1)",
    );
    let text = stdout(
        &["discrepancy", "--metric", "star", "--max-seconds", "20"],
        &large,
    );
    let got = values(&text)[0].1;
    let coords: Vec<f64> = large
        .lines()
        .flat_map(|l| l.split(',').map(|v| v.parse::<f64>().unwrap()))
        .collect();
    let p = qmckit::analysis::Points::new(&coords, 12).unwrap();
    let lower =
        qmckit::analysis::star::star_lower_bound(p, 1, 20_000, &qmckit::work::Budget::UNLIMITED)
            .unwrap();
    assert!(lower <= got + 1e-12 && got < lower + 0.01, "{lower} {got}");
    let want = qmckit::analysis::star::star_exact(p, &qmckit::work::Budget::UNLIMITED).unwrap();
    assert_eq!(got, want);
}

#[test]
fn bad_input_is_one_line_with_the_line_number() {
    let cases = [
        (
            "0.5 0.5\n0.5 1.5\n",
            "<stdin>: line 2: \"1.5\" is outside [0, 1]",
        ),
        (
            "0.5\n\nNaN\n",
            "<stdin>: line 3: \"NaN\" is not a finite number",
        ),
        ("0.1 0.2\n0.3\n", "<stdin>: line 2: 1 coordinate(s)"),
        ("0.5 abc\n", "<stdin>: line 1: \"abc\" is not a number"),
        ("", "<stdin>: line 1: set 1 has no points"),
        ("0.5\n#\n#\n0.5\n", "line 3: set 2 has no points"),
    ];
    for (input, needle) in cases {
        assert_usage_error(&["discrepancy"], input, needle);
    }
    let path = temp_file("bad", "0.5\n-0.5\n");
    let name = path.to_str().unwrap();
    assert_usage_error(&["discrepancy", name], "", &format!("{name}: line 2: "));
    std::fs::remove_file(path).ok();
}

#[test]
fn missing_file_and_bad_metric() {
    assert_usage_error(
        &["discrepancy", "/nonexistent/points.txt"],
        "",
        "/nonexistent/points.txt: ",
    );
    assert_usage_error(&["discrepancy", "--metric", "l3"], "0.5\n", "l3");
}

#[test]
fn help_states_the_conventions() {
    let help = stdout(&["discrepancy", "--help"], "");
    for needle in [
        "cd        centered L2, squared (SciPy",
        "l2-star   L2-star (Warnock), square root taken (SciPy",
        "diaphony  Zinterhof's diaphony, square root taken",
        "all       star, then the eight L2 measures",
        "'# NAME skipped: REASON'",
    ] {
        assert!(help.contains(needle), "{needle:?} not in\n{help}");
    }
}

/// The `t` line of tvalue's output.
fn t_of(args: &[&str]) -> u32 {
    let text = stdout(args, "");
    let line = text
        .lines()
        .find(|l| l.starts_with("t "))
        .unwrap_or_else(|| panic!("{args:?}: no t line in {text:?}"));
    line[2..].parse().unwrap()
}

#[test]
fn tvalue_of_sobol_by_rank() {
    let text = stdout(&["tvalue", "sobol", "-m", "10", "-d", "2"], "");
    assert_eq!(
        text,
        "sampler sobol\nscramble none\nm 10\nd 2\nmethod rank\nt 0\n"
    );
    assert_eq!(t_of(&["tvalue", "sobol", "-d", "3", "-m", "10"]), 1);
    assert_eq!(t_of(&["tvalue", "hammersley", "-m", "12"]), 0);
    assert_eq!(t_of(&["tvalue", "vdc", "-m", "32"]), 0);
}

#[test]
fn tvalue_of_scrambled_points_by_counting() {
    let args = [
        "tvalue",
        "lp",
        "-m",
        "8",
        "-d",
        "2",
        "--scramble",
        "owen",
        "--seed",
        "3",
    ];
    assert_eq!(t_of(&args), 0);
    assert!(stdout(&args, "").contains("method count\n"));
    // Owen scrambling keeps the t-value of 3D Sobol'.
    assert_eq!(
        t_of(&[
            "tvalue",
            "sobol",
            "-m",
            "10",
            "-d",
            "3",
            "--scramble",
            "fast-owen"
        ]),
        1
    );
}

#[test]
fn tvalue_explain_names_failing_intervals() {
    let text = stdout(&["tvalue", "sobol", "-m", "10", "-d", "3", "--explain"], "");
    let fails: Vec<&str> = text.lines().filter(|l| l.starts_with("fail ")).collect();
    assert!(!fails.is_empty() && fails.len() <= 5, "{text}");
    assert!(fails[0].contains("expected"), "{}", fails[0]);
}

#[test]
fn tvalue_refusals() {
    assert_usage_error(&["tvalue", "sobol", "-m", "33"], "", "-m 33");
    assert_usage_error(&["tvalue", "sobol", "-m", "x"], "", "x");
    assert_usage_error(
        &["tvalue", "sobol", "-m", "25", "--scramble", "owen"],
        "",
        "too many",
    );
    assert_usage_error(
        &["tvalue", "halton", "-m", "4"],
        "",
        "halton: tvalue judges sobol, lp, vdc, hammersley, faure, pmj02 and pmj02bn",
    );
    assert_usage_error(&["tvalue", "lp", "-m", "4", "-d", "3"], "", "-d must be 2");
    assert_usage_error(&["tvalue", "sobol", "-m", "4", "-d", "0"], "", "-d");
    assert_usage_error(
        &["tvalue", "sobol", "-m", "8", "--scramble", "perm"],
        "",
        "does not apply",
    );
}

#[test]
fn star_bounds_bracket_the_exact_value() {
    // LP, N = 64: D* = 21/512 exactly; the bounds must hold it, at most delta apart.
    let csv = stdout(&["points", "lp", "-n", "64", "--format", "csv"], "");
    let text = stdout(
        &["discrepancy", "--metric", "star-bounds", "--delta", "0.01"],
        &csv,
    );
    let v = values(&text);
    assert_eq!(v.len(), 2, "{text}");
    assert_eq!(
        (v[0].0.as_str(), v[1].0.as_str()),
        ("star-lower", "star-upper")
    );
    let exact = 21.0 / 512.0;
    assert!(v[0].1 <= exact && exact <= v[1].1, "{text}");
    assert!(v[1].1 - v[0].1 <= 0.01 + 1e-12, "{text}");
    // A set too large for the exact value in 8D still gets bounds.
    let csv = stdout(
        &[
            "points", "sobol", "-n", "2000", "-d", "8", "--format", "csv",
        ],
        "",
    );
    let v = values(&stdout(
        &["discrepancy", "--metric", "star-bounds", "--delta", "0.5"],
        &csv,
    ));
    assert!(0.0 < v[0].1 && v[0].1 <= v[1].1 && v[1].1 <= 1.0, "{v:?}");
    // A bad delta is a one-line usage error.
    assert_usage_error(
        &["discrepancy", "--metric", "star-bounds", "--delta", "0"],
        &csv,
        "delta",
    );
}

#[test]
fn spectrum_of_the_four_point_sobol_net_lies_on_its_dual_lattice() {
    // (0, 0), (1/2, 1/2), (3/4, 1/4), (1/4, 3/4): x + y is an integer for every point, so
    // P(±1, ±1) = 16 / 4 = 4 with equal signs; the other non-zero frequencies in [-1, 1]^2
    // sum four phasors 1, -1, ±i, ∓i to 0.
    let csv = stdout(
        &["points", "sobol", "-n", "4", "-d", "2", "--format", "csv"],
        "",
    );
    let text = stdout(&["spectrum", "--k-max", "1"], &csv);
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("# kx ky power"));
    let rows: Vec<(i64, i64, f64)> = lines
        .map(|l| {
            let f: Vec<&str> = l.split(' ').collect();
            (
                f[0].parse().unwrap(),
                f[1].parse().unwrap(),
                f[2].parse().unwrap(),
            )
        })
        .collect();
    assert_eq!(rows.len(), 9);
    for (kx, ky, p) in rows {
        let want = if kx == ky { 4.0 } else { 0.0 };
        assert!((p - want).abs() < 1e-12, "({kx}, {ky}): {p}");
    }
    // One point: every annulus has mean 1; two sets, each with its header.
    let text = stdout(
        &["spectrum", "--k-max", "2", "--radial"],
        "0.3 0.6\n#\n0.1 0.2\n",
    );
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "# set 1");
    assert_eq!(lines[1], "# radius count mean anisotropy");
    assert!(
        lines[2].starts_with("1 8 1.0000000000000000e0 "),
        "{}",
        lines[2]
    );
    assert!(
        lines[3].starts_with("2 12 1.0000000000000000e0 "),
        "{}",
        lines[3]
    );
    assert_eq!(lines.len(), 8);
    assert_eq!(lines[4], "# set 2");
}

#[test]
fn spectrum_refuses_bad_input_in_one_line() {
    assert_usage_error(
        &["spectrum"],
        "0.5 0.5 0.5\n",
        "needs 2-dimensional points, not 3",
    );
    assert_usage_error(&["spectrum", "--k-max", "abc"], "", "--k-max");
    assert_usage_error(&["spectrum", "--k-max", "5000"], "0.5 0.5\n", "2048");
    assert_usage_error(&["spectrum"], "0.5 1.5\n", "outside [0, 1]");
    let many = "0.25 0.75\n".repeat(1192);
    assert_usage_error(
        &["spectrum", "--k-max", "2048", "--method", "direct"],
        &many,
        "1192 points are too many for --k-max 2048 (at most 1191 within --max-seconds 10)",
    );
}

#[test]
fn convergence_reports_the_error_of_each_power_of_two() {
    let text = stdout(&["convergence", "sobol", "--max-m", "4"], "");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "# n rmse");
    let rows: Vec<(u64, f64)> = lines[1..]
        .iter()
        .map(|l| {
            let (n, e) = l.split_once(' ').unwrap();
            (n.parse().unwrap(), e.parse().unwrap())
        })
        .collect();
    assert_eq!(
        rows.iter().map(|r| r.0).collect::<Vec<_>>(),
        [1, 2, 4, 8, 16]
    );
    // N = 1: Sobol' point 0 is the origin, where the Gaussian peak exp(-16 |x - c|^2) is
    // e^-8; its integral is (sqrt(pi) erf(2) / 4)^2, erf(2) = 0.99532226501895273 (tables).
    let integral = (std::f64::consts::PI.sqrt() * 0.995_322_265_018_952_7 / 4.0).powi(2);
    assert!(
        (rows[0].1 - (integral - (-8.0f64).exp())).abs() < 1e-12,
        "{}",
        rows[0].1
    );
    // Stratified sets come in sizes k^d.
    let text = stdout(
        &[
            "convergence",
            "stratified",
            "--max-m",
            "6",
            "--integrand",
            "ball",
        ],
        "",
    );
    let sizes: Vec<&str> = text
        .lines()
        .skip(1)
        .map(|l| l.split(' ').next().unwrap())
        .collect();
    assert_eq!(sizes, ["1", "4", "16", "64"]);
}

#[test]
fn convergence_refuses_bad_requests_in_one_line() {
    assert_usage_error(&["convergence", "sobol", "--max-m", "25"], "", "at most 24");
    assert_usage_error(&["convergence", "sobol", "--seeds", "0"], "", "--seeds");
    assert_usage_error(
        &["convergence", "sobol", "--integrand", "nosuch"],
        "",
        "nosuch",
    );
    assert_usage_error(
        &[
            "convergence",
            "independent",
            "--seeds",
            "100",
            "--max-m",
            "24",
        ],
        "",
        "lower --seeds, --max-m or -d",
    );
    assert_usage_error(&["convergence", "lp", "-d", "3"], "", "lp");
}

/// Runs the CLI and returns (exit code, stdout, stderr, seconds).
fn timed(args: &[&str], input: &str) -> (i32, String, String, f64) {
    let start = std::time::Instant::now();
    let out = qmckit_with(args, input);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        start.elapsed().as_secs_f64(),
    )
}

#[test]
fn star_in_huge_dimensions_answers_or_refuses_at_once() {
    let row = |d: usize, x: &str| vec![x; d].join(" ");
    // One point in 10000 dimensions (about 40 KB): star is 1 - 2^-10000 = 1.
    let one = row(10_000, "0.5") + "\n";
    let text = stdout(&["discrepancy", "--metric", "star"], &one);
    assert_eq!(values(&text), vec![("star".to_owned(), 1.0)]);
    let text = stdout(&["discrepancy"], &one);
    assert!(text.starts_with("star 1.0000000000000000e0\n"), "{text}");
    // Two points in 1000 and 20000 dimensions: star and star-bounds refused in well under a
    // second, with one line.
    for d in [1000, 20_000] {
        let two = row(d, "0.5") + "\n" + &row(d, "0.25") + "\n";
        for metric in ["star", "star-bounds"] {
            let (code, out, err, secs) = timed(&["discrepancy", "--metric", metric], &two);
            assert_eq!((code, out.as_str()), (2, ""), "{metric} d = {d}: {err}");
            assert_eq!(err.lines().count(), 1, "{err}");
            assert!(!err.contains("panicked"), "{err}");
            assert!(secs < 1.0, "{metric} d = {d}: {secs} s");
        }
    }
}

#[test]
fn star_upper_never_exceeds_one() {
    // delta = 1: the whole cube is one bracket, worth exactly 1 = the largest possible D*.
    let text = stdout(
        &["discrepancy", "--metric", "star-bounds", "--delta", "1"],
        "0.25 0.75\n0.5 0.5\n",
    );
    let v = values(&text);
    assert_eq!(v[1], ("star-upper".to_owned(), 1.0), "{text}");
    assert!(v[0].1 <= v[1].1);
}

#[test]
fn tvalue_in_huge_dimensions_and_past_the_budget() {
    // m = 2 in 10057 and 21201 dimensions: t = 1 (see tests/tvalue.rs), at once.
    for d in ["10057", "21201"] {
        let (code, out, err, secs) = timed(&["tvalue", "sobol", "-m", "2", "-d", d], "");
        assert_eq!(code, 0, "{err}");
        assert!(out.contains("\nt 1\n"), "{out}");
        assert!(secs < 2.0, "{secs} s");
    }
    // Minutes or more by the estimate: refused in well under a second.
    for (m, d) in [("32", "50"), ("20", "1000")] {
        let (code, _, err, secs) = timed(&["tvalue", "sobol", "-m", m, "-d", d], "");
        assert_eq!(code, 2, "{err}");
        assert!(err.contains("time budget"), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(secs < 1.0, "-m {m} -d {d}: {secs} s");
    }
    assert_usage_error(
        &["tvalue", "sobol", "-m", "4", "--max-seconds", "0"],
        "",
        "--max-seconds must be a positive number of seconds",
    );
    // A larger budget admits what the default refuses (counting 2^21 points in 4D, about
    // 18 s by the estimate for t = 3, the t-value of the unscrambled net).
    assert_usage_error(
        &[
            "tvalue",
            "sobol",
            "-m",
            "21",
            "-d",
            "4",
            "--scramble",
            "owen",
        ],
        "",
        "--max-seconds",
    );
}

#[test]
fn every_listed_blue_noise_sampler_converges_with_default_options() {
    for sampler in ["poisson", "gaussian-blue-noise"] {
        let text = stdout(&["convergence", sampler], "");
        assert!(text.starts_with("# n rmse\n"), "{sampler}: {text}");
        assert!(text.lines().count() > 8, "{sampler}: {text}");
    }
}
