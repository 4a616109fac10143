//! `qmckit points --sets K`: K sets in one process, each the set its seed gives alone.

use std::process::Command;

use crate::common;

fn stdout(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_qmckit"))
        .args(args)
        .output()
        .expect("run qmckit");
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// `--seed S --sets K` writes what K runs with seeds S..S+K-1 write, `#` between them, for
/// a sequence with a randomizer, a randomized set, a set built whole and a blue-noise set.
#[test]
fn sets_are_the_single_runs_joined_by_separators() {
    let cases: [&[&str]; 4] = [
        &[
            "points",
            "sobol",
            "-n",
            "8",
            "-d",
            "3",
            "--scramble",
            "owen",
        ],
        &["points", "cmj", "-n", "16", "--total", "16"],
        &["points", "forced-random", "-n", "32"],
        &["points", "poisson", "-n", "40", "--torus"],
    ];
    for args in cases {
        let mut joined = String::new();
        for seed in 7..10 {
            if seed > 7 {
                joined.push_str("#\n");
            }
            let s = seed.to_string();
            joined.push_str(&stdout(&[args, &["--seed", &s]].concat()));
        }
        let together = stdout(&[args, &["--seed", "7", "--sets", "3"]].concat());
        assert_eq!(together, joined, "{args:?}");
        // The sets differ from each other, and the reader finds three of them.
        let sets = qmckit::analysis::pointfile::parse_point_sets(&together).unwrap();
        assert_eq!(sets.len(), 3, "{args:?}");
        assert_ne!(sets[0], sets[1], "{args:?}");
    }
}

/// What `--sets` cannot do is refused in one line, before anything is written.
#[test]
fn sets_refusals() {
    let refused: [(&[&str], &str); 5] = [
        (
            &["points", "sobol", "-n", "4", "--sets", "2"],
            "deterministic",
        ),
        (
            &["points", "halton", "-n", "4", "--sets", "3"],
            "deterministic",
        ),
        (
            &[
                "points",
                "independent",
                "-n",
                "4",
                "--sets",
                "2",
                "--format",
                "npy",
            ],
            "npy",
        ),
        (
            &["points", "independent", "-n", "4", "--sets", "0"],
            "at least 1",
        ),
        (
            &[
                "points",
                "independent",
                "-n",
                "4",
                "--seed",
                "18446744073709551615",
                "--sets",
                "2",
            ],
            "2^64",
        ),
    ];
    for (args, needle) in refused {
        common::cli::assert_usage_error(args, "", needle);
    }
}

/// `--max-seconds S` is shared: each of K sets gets S / K, so a set that fits S alone is
/// refused up front when K of them would not.
#[test]
fn sets_share_the_budget() {
    let out = Command::new(env!("CARGO_BIN_EXE_qmckit"))
        .args([
            "points",
            "lloyd",
            "-n",
            "2000",
            "--max-seconds",
            "0.05",
            "--sets",
            "4",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("0.013 s") || err.contains("0.012 s"), "{err}");
}
