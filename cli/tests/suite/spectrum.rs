//! `qmckit spectrum`: averages, methods and refusals.

use crate::common::cli::{assert_usage_error, run};

/// `qmckit spectrum --average --method --tolerance`: the mean of the per-set values, the
/// NUFFT within its tolerance of the direct sums, one-line refusals.
#[test]
fn cli_averages_sets_and_switches_methods() {
    let sets = "0.1 0.2\n0.5 0.7\n0.9 0.35\n#\n0.3 0.3\n0.6 0.1\n0.2 0.8\n";
    let text = |args: &[&str]| {
        let out = run(args, sets);
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        String::from_utf8(out.stdout).unwrap()
    };
    let values = |t: &str| -> Vec<f64> {
        t.lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| l.rsplit(' ').next().unwrap().parse().unwrap())
            .collect()
    };
    let per_set = text(&["spectrum", "--k-max", "3", "--method", "direct"]);
    let blocks: Vec<&str> = per_set.split("# set 2\n").collect();
    let (a, b) = (values(blocks[0]), values(blocks[1]));
    let mean = values(&text(&["spectrum", "--k-max", "3", "--average"]));
    assert_eq!((a.len(), mean.len()), (49, 49));
    for ((x, y), m) in a.iter().zip(&b).zip(&mean) {
        assert!(((x + y) / 2.0 - m).abs() < 1e-12);
    }
    let fast = values(&text(&[
        "spectrum",
        "--k-max",
        "3",
        "--average",
        "--method",
        "nufft",
        "--tolerance",
        "1e-6",
    ]));
    for (f, m) in fast.iter().zip(&mean) {
        assert!((f - m).abs() <= 1e-6 * 3.0, "{f} vs {m}");
    }
    let radial = text(&["spectrum", "--k-max", "3", "--average", "--radial"]);
    assert!(radial.starts_with("# mean of 2 sets\n# radius count mean anisotropy\n"));
    assert_usage_error(&["spectrum", "--tolerance", "0"], sets, "--tolerance 0");
    assert_usage_error(&["spectrum", "--method", "fft"], sets, "--method");
    // Sets of different sizes average too (each periodogram normalized by its own N):
    // P(0) is the mean size, 1.5.
    let mixed = String::from_utf8(
        run(
            &["spectrum", "--average", "--k-max", "1"],
            "0.1 0.2\n#\n0.3 0.4\n0.5 0.6\n",
        )
        .stdout,
    )
    .unwrap();
    let dc = mixed
        .lines()
        .find_map(|l| l.strip_prefix("0 0 "))
        .unwrap_or_else(|| panic!("{mixed}"));
    assert_eq!(dc.trim().parse::<f64>().unwrap(), 1.5, "{mixed}");
    assert_usage_error(
        &[
            "spectrum",
            "--k-max",
            "2048",
            "--method",
            "nufft",
            "--max-seconds",
            "0.01",
        ],
        sets,
        "raise --max-seconds",
    );
}
