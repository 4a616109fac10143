//! `qmckit pcf`: bins, averages and one-line refusals.

use crate::common::cli::{assert_usage_error, run};

#[test]
fn cli_pcf_prints_bins_and_refuses_in_one_line() {
    let pts = "0.1 0.1\n0.5 0.5\n0.9 0.2\n0.3 0.8\n";
    let out = run(&["pcf", "--torus", "--r-max", "0.5", "--bins", "5"], pts);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), 6);
    assert!(text.starts_with("# radius g\n5.0000000000000"), "{text}");
    assert_usage_error(&["pcf", "--torus", "--r-max", "0.7"], pts, "--r-max 0.7");
    assert_usage_error(&["pcf", "--bins", "0"], pts, "--bins 0");
    assert_usage_error(&["pcf", "--sigma=-1"], pts, "--sigma -1");
    assert_usage_error(&["pcf"], "0.5 0.5 0.5\n", "2-dimensional");
    let avg = run(
        &["pcf", "--average", "--bins", "3"],
        "0.1 0.1\n0.2 0.2\n#\n0.3 0.3\n0.35 0.3\n",
    );
    assert!(
        String::from_utf8(avg.stdout)
            .unwrap()
            .starts_with("# mean of 2 sets\n")
    );
}

#[test]
fn the_command_refuses_a_subnormal_sigma() {
    assert_usage_error(
        &["pcf", "--sigma", "5e-324"],
        "0.1 0.2\n0.5 0.7\n",
        "--sigma 5e-324",
    );
}
