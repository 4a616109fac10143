//! The command line: `points lattice|kronecker|faure`, `tvalue faure`, and its refusals.

use crate::common::cli::{assert_usage_error, run};

fn golden(name: &str) -> String {
    let path = format!("{}/../tests/golden/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The data rows of a golden file, as integers.
fn rows(name: &str) -> Vec<Vec<u64>> {
    golden(name)
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split_whitespace().map(|t| t.parse().unwrap()).collect())
        .collect()
}

fn stdout(args: &[&str]) -> String {
    let out = run(args, "");
    assert_eq!(out.status.code(), Some(0), "{args:?}: {:?}", out.stderr);
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn points_lattice_is_qmcpys() {
    let text = stdout(&[
        "points", "lattice", "-n", "1024", "-d", "8", "--format", "u32",
    ]);
    let golden = rows("qmcpy_lattice_natural_d8_n1024.txt");
    let got: Vec<Vec<u64>> = text
        .lines()
        .map(|l| l.split(' ').map(|t| t.parse().unwrap()).collect())
        .collect();
    assert_eq!(got, golden);
    let lin = stdout(&[
        "points", "lattice", "-n", "256", "-d", "8", "--total", "256", "--format", "u32",
    ]);
    assert_eq!(
        lin.lines().nth(5).unwrap(),
        rows("qmcpy_lattice_linear_d8_n256.txt")[5]
            .iter()
            .map(u64::to_string)
            .collect::<Vec<_>>()
            .join(" ")
    );
}

#[test]
fn points_lattice_reads_a_vector_file() {
    let path = std::env::temp_dir().join(format!("qmckit-lattice-{}.txt", std::process::id()));
    std::fs::write(&path, "# lattice\n2\n8 # n\n1\n3\n").unwrap();
    let p = path.to_str().unwrap();
    let text = stdout(&[
        "points", "lattice", "-n", "8", "-d", "2", "--vector", p, "--format", "u32",
    ]);
    // Extensible with n = 8, radical-inverse order: point 1 is (1/2, 3/2 mod 1).
    assert_eq!(text.lines().nth(1), Some("2147483648 2147483648"));
    assert_usage_error(
        &["points", "lattice", "-n", "8", "-d", "3", "--vector", p],
        "",
        "has 2 components",
    );
    assert_usage_error(
        &["points", "lattice", "-n", "9", "-d", "2", "--vector", p],
        "",
        "past the end",
    );
    std::fs::write(&path, "# lattice\n2\nx\n").unwrap();
    assert_usage_error(
        &["points", "lattice", "-n", "8", "-d", "2", "--vector", p],
        "",
        "lattice file",
    );
    std::fs::remove_file(&path).unwrap();
}

#[test]
fn points_korobov_kronecker_faure() {
    let k = stdout(&[
        "points",
        "lattice",
        "-n",
        "3",
        "-d",
        "2",
        "--total",
        "13",
        "--korobov",
        "5",
        "--format",
        "u32",
    ]);
    // z = (1, 5): point 2 is (2/13, 10/13).
    let want = format!("{} {}", (2u64 << 32) / 13, (10u64 << 32) / 13);
    assert_eq!(k.lines().nth(2), Some(want.as_str()));
    let r2 = stdout(&[
        "points",
        "kronecker",
        "-n",
        "2",
        "-d",
        "2",
        "--format",
        "u32",
    ]);
    assert_eq!(r2.lines().nth(1), Some("3242174889 2447445413"));
    let f = stdout(&["points", "faure", "-n", "4", "-d", "3", "--format", "u32"]);
    let want = format!(
        "{} {} {}",
        (1u64 << 32) / 9,
        (4u64 << 32) / 9,
        (7u64 << 32) / 9
    );
    assert_eq!(f.lines().nth(3), Some(want.as_str()));
    let a = stdout(&[
        "points",
        "kronecker",
        "-n",
        "4",
        "--scramble",
        "shift",
        "--seed",
        "3",
    ]);
    let b = stdout(&[
        "points",
        "kronecker",
        "-n",
        "4",
        "--scramble",
        "shift",
        "--seed",
        "4",
    ]);
    assert_ne!(a, b);
    stdout(&["points", "lattice", "-n", "4", "--scramble", "shift-tent"]);
    stdout(&[
        "points",
        "faure",
        "-n",
        "4",
        "-d",
        "5",
        "--scramble",
        "owen",
    ]);
}

#[test]
fn tvalue_faure_counts_in_base_b() {
    let out = stdout(&["tvalue", "faure", "-m", "4", "-d", "5"]);
    assert!(out.contains("base 5\n") && out.contains("t 0\n"), "{out}");
    let out = stdout(&[
        "tvalue",
        "faure",
        "-m",
        "3",
        "-d",
        "3",
        "--scramble",
        "perm",
        "--seed",
        "9",
    ]);
    assert!(out.contains("base 3\n") && out.contains("t 0\n"), "{out}");
    assert_usage_error(
        &["tvalue", "faure", "-m", "3", "-d", "3", "--base", "9"],
        "",
        "prime",
    );
    assert_usage_error(&["tvalue", "faure", "-m", "30", "-d", "3"], "", "32-bit");
    assert_usage_error(
        &[
            "tvalue",
            "faure",
            "-m",
            "9",
            "-d",
            "7",
            "--max-seconds",
            "0.001",
        ],
        "",
        "max-seconds",
    );
}

#[test]
fn refusals_are_one_line() {
    assert_usage_error(
        &["points", "halton", "-n", "2", "--scramble", "shift"],
        "",
        "shift",
    );
    assert_usage_error(
        &["points", "faure", "-n", "2", "--scramble", "xor"],
        "",
        "xor",
    );
    assert_usage_error(
        &["points", "sobol", "-n", "2", "--korobov", "3"],
        "",
        "--korobov",
    );
    assert_usage_error(
        &["points", "lattice", "-n", "2", "--korobov", "3"],
        "",
        "--total",
    );
    assert_usage_error(
        &["points", "kronecker", "-n", "2", "--total", "3"],
        "",
        "--total",
    );
    assert_usage_error(
        &["points", "faure", "-n", "2", "-d", "4", "--base", "3"],
        "",
        "prime",
    );
    assert_usage_error(&["points", "lattice", "-n", "2", "-d", "9126"], "", "9125");
    assert_usage_error(
        &["points", "lattice", "-n", "2", "--total", "0"],
        "",
        "point",
    );
}
