//! The `qmckit` command's contract: formats, exit codes, one-line errors.

use std::process::{Command, Output};

use crate::common;

fn qmckit(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_qmckit"))
        .args(args)
        .output()
        .expect("run qmckit")
}

fn stdout(args: &[&str]) -> String {
    let out = qmckit(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// Bad usage: exit code 2, exactly one line on stderr, nothing that looks like a panic.
fn assert_usage_error(args: &[&str], needle: &str) {
    common::cli::assert_usage_error(args, "", needle);
}

#[test]
fn halton_u32_matches_the_library() {
    let text = stdout(&["points", "halton", "-n", "5", "-d", "2", "--format", "u32"]);
    let h = qmckit::Halton::new(2).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 5);
    for (i, line) in lines.iter().enumerate() {
        let v: Vec<u32> = line.split(' ').map(|x| x.parse().unwrap()).collect();
        assert_eq!(
            v,
            [
                h.sample(i as u32, 0).unwrap(),
                h.sample(i as u32, 1).unwrap()
            ]
        );
    }
    assert_eq!(lines[1], "2147483648 1431655765"); // (1/2, 1/3) rounded down
}

#[test]
fn csv_round_trips_the_exact_values() {
    let ints = stdout(&[
        "points", "halton", "-n", "300", "-d", "5", "--start", "77", "--format", "u32",
    ]);
    let csv = stdout(&[
        "points", "halton", "-n", "300", "-d", "5", "--start", "77", "--format", "csv",
    ]);
    for (a, b) in ints.lines().zip(csv.lines()) {
        let a: Vec<u32> = a.split(' ').map(|x| x.parse().unwrap()).collect();
        let b: Vec<f64> = b.split(',').map(|x| x.parse().unwrap()).collect();
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(*x as f64, y * 4_294_967_296.0);
        }
    }
}

#[test]
fn npy_has_numpy_header_and_float64_rows() {
    let out = qmckit(&["points", "lp", "-n", "8", "--format", "npy"]);
    assert!(out.status.success());
    let bytes = out.stdout;
    assert_eq!(&bytes[..6], b"\x93NUMPY");
    let header_len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    let header = std::str::from_utf8(&bytes[10..10 + header_len]).unwrap();
    assert!(
        header.contains("'descr': '<f8'") && header.contains("(8, 2"),
        "{header}"
    );
    let data = &bytes[10 + header_len..];
    assert_eq!(data.len(), 8 * 2 * 8);
    let x: Vec<f64> = data
        .chunks(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    // LP with 8 points: x = i/8, y = 0, 1/2, 3/4, 1/4, ...
    assert_eq!(&x[..8], &[0.0, 0.0, 0.125, 0.5, 0.25, 0.75, 0.375, 0.25]);
}

#[test]
fn every_sampler_runs() {
    for s in [
        "independent",
        "stratified",
        "latin",
        "vdc",
        "halton",
        "hammersley",
        "lp",
        "sobol",
    ] {
        // --seed only where something is random.
        let seeded = ["independent", "stratified", "latin"].contains(&s);
        let args: &[&str] = if seeded { &["--seed", "3"] } else { &[] };
        let text = stdout(&[&["points", s, "-n", "16"], args].concat());
        assert_eq!(text.lines().count(), 16, "{s}");
    }
    let text = stdout(&[
        "points",
        "stratified",
        "-n",
        "32",
        "--strata",
        "8x4",
        "--centered",
        "--format",
        "u32",
    ]);
    assert_eq!(text.lines().next(), Some("268435456 536870912")); // (1/16, 1/8)
    let text = stdout(&[
        "points", "vdc", "-n", "4", "--base", "3", "--start", "1", "--format", "u32",
    ]);
    // phi_3(1..5) = 1/3, 2/3, 1/9, 4/9 rounded down to 0.32
    let want: Vec<String> = [1u64, 2, 1, 4]
        .iter()
        .zip([3u64, 3, 9, 9])
        .map(|(n, d)| ((n << 32) / d).to_string())
        .collect();
    assert_eq!(text.lines().collect::<Vec<_>>(), want);
}

#[test]
fn sobol_gray_order_is_scipys() {
    // scipy: qmc.Sobol(3, scramble=False, bits=32).random(4) * 2^32
    let text = stdout(&[
        "points", "sobol", "-n", "4", "-d", "3", "--order", "gray", "--format", "u32",
    ]);
    let want = "0 0 0\n2147483648 2147483648 2147483648\n\
                3221225472 1073741824 1073741824\n1073741824 3221225472 3221225472\n";
    assert_eq!(text, want);
    // Natural order swaps points 2 and 3.
    let text = stdout(&["points", "sobol", "-n", "4", "-d", "3", "--format", "u32"]);
    assert_eq!(
        text.lines().nth(3),
        Some("3221225472 1073741824 1073741824")
    );
    // All 21201 dimensions are there.
    let text = stdout(&["points", "sobol", "-n", "2", "-d", "21201", "--start", "1"]);
    assert_eq!(text.split(' ').count(), 2 * 21201 - 1);
}

#[test]
fn every_scramble_runs_and_base2_kinds_keep_the_net() {
    for kind in [
        "xor",
        "owen",
        "fast-owen",
        "fast-owen-lk",
        "lms",
        "shuffle-owen",
        "rotate",
    ] {
        let text = stdout(&[
            "points",
            "sobol",
            "-n",
            "256",
            "--scramble",
            kind,
            "--seed",
            "5",
            "--format",
            "u32",
        ]);
        let pts: Vec<Vec<u32>> = text
            .lines()
            .map(|l| l.split(' ').map(|x| x.parse().unwrap()).collect())
            .collect();
        // 16 x 16 cells, one point each (a (0,8,2)-net's square elementary intervals).
        let mut cells: Vec<u32> = pts
            .iter()
            .map(|p| (p[0] >> 28) * 16 + (p[1] >> 28))
            .collect();
        cells.sort_unstable();
        cells.dedup();
        if kind == "rotate" {
            assert!(cells.len() < 256, "rotation keeps the net by chance only");
        } else {
            assert_eq!(cells.len(), 256, "{kind}");
        }
        // A different seed gives different points.
        let other = stdout(&[
            "points",
            "sobol",
            "-n",
            "4",
            "--scramble",
            kind,
            "--seed",
            "6",
            "--format",
            "u32",
        ]);
        assert_ne!(
            text.lines().take(4).collect::<Vec<_>>(),
            other.lines().collect::<Vec<_>>()
        );
    }
    for kind in ["perm", "faure", "owen"] {
        for s in ["halton", "hammersley"] {
            let text = stdout(&["points", s, "-n", "9", "-d", "3", "--scramble", kind]);
            assert_eq!(text.lines().count(), 9);
        }
        let text = stdout(&[
            "points",
            "vdc",
            "-n",
            "9",
            "--base",
            "3",
            "--scramble",
            kind,
            "--format",
            "u32",
        ]);
        // Nine base-3 points: one in each ninth.
        let mut ninths: Vec<u64> = text
            .lines()
            .map(|l| (l.parse::<u64>().unwrap() * 9) >> 32)
            .collect();
        ninths.sort_unstable();
        // (Faure maps the zero digits to zero: exact multiples of 1/9 round down into the
        // cell below, so it is checked exactly in tests/randomize.rs instead.)
        if kind != "faure" {
            assert_eq!(ninths, (0..9).collect::<Vec<u64>>(), "{kind}");
        }
    }
}

#[test]
fn warps_write_real_coordinates_in_their_domains() {
    let rows = |args: &[&str]| -> Vec<Vec<f64>> {
        stdout(args)
            .lines()
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect()
    };
    for p in rows(&[
        "points", "sobol", "-n", "64", "--warp", "disk", "--format", "csv",
    ]) {
        assert_eq!(p.len(), 2);
        assert!(p[0] * p[0] + p[1] * p[1] <= 1.0 + 1e-6);
    }
    for warp in ["hemisphere", "cosine-hemisphere", "sphere", "cone"] {
        for p in rows(&[
            "points", "halton", "-n", "64", "--warp", warp, "--format", "csv",
        ]) {
            let n = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
            assert!((n - 1.0).abs() < 1e-5, "{warp}: {p:?}");
            if warp != "sphere" {
                assert!(p[2] >= 0.0);
            }
        }
    }
    let tri = rows(&[
        "points",
        "sobol",
        "-n",
        "3",
        "--warp",
        "triangle",
        "--vertices",
        "0,0;4,0;0,2",
        "--format",
        "csv",
    ]);
    assert_eq!(tri, [vec![0.0, 2.0], vec![1.0, 1.0], vec![2.5, 0.5]]);
    let rect = rows(&[
        "points",
        "sobol",
        "-n",
        "32",
        "--warp",
        "spherical-rectangle",
        "--rect",
        "-0.5,-0.5,1;1,0,0;0,1,0",
        "--format",
        "csv",
    ]);
    assert!(
        rect.iter()
            .all(|p| (p[2] - 1.0).abs() < 1e-6 && p[0].abs() <= 0.5 + 1e-6)
    );
    let normal = rows(&[
        "points", "sobol", "-n", "8", "-d", "3", "--warp", "normal", "--format", "csv",
    ]);
    assert_eq!(normal[1], vec![0.0, 0.0, 0.0]); // point 1 is (1/2, 1/2, 1/2)
    assert_usage_error(
        &[
            "points", "sobol", "-n", "2", "--warp", "disk", "--format", "u32",
        ],
        "csv or npy",
    );
    assert_usage_error(
        &[
            "points", "sobol", "-n", "2", "-d", "3", "--warp", "disk", "--format", "csv",
        ],
        "-d must be 2",
    );
    assert_usage_error(
        &[
            "points",
            "sobol",
            "-n",
            "2",
            "--warp",
            "cone",
            "--cone-angle",
            "200",
            "--format",
            "csv",
        ],
        "cone-angle",
    );
    assert_usage_error(
        &[
            "points",
            "sobol",
            "-n",
            "2",
            "--warp",
            "spherical-triangle",
            "--format",
            "csv",
        ],
        "--vertices",
    );
    assert_usage_error(
        &[
            "points",
            "sobol",
            "-n",
            "2",
            "--warp",
            "spherical-rectangle",
            "--rect",
            "0,0,0;1,0,0;0,1,0",
            "--format",
            "csv",
        ],
        "degenerate",
    );
    assert_usage_error(
        &[
            "points",
            "sobol",
            "-n",
            "2",
            "--warp",
            "triangle",
            "--vertices",
            "0,0;4,x;0,2",
            "--format",
            "csv",
        ],
        "not a number",
    );
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    assert_usage_error(
        &["points", "halton", "-n", "4", "--scramble", "xor"],
        "does not apply",
    );
    assert_usage_error(
        &["points", "sobol", "-n", "4", "--scramble", "perm"],
        "does not apply",
    );
    assert_usage_error(
        &["points", "latin", "-n", "4", "--scramble", "owen"],
        "does not apply",
    );
    assert_usage_error(
        &["points", "sobol", "-n", "4", "--scramble", "nope"],
        "nope",
    );
    assert_usage_error(
        &["points", "sobol", "-n", "4", "-d", "21202"],
        "out of range",
    );
    assert_usage_error(
        &["points", "halton", "-n", "4", "--order", "gray"],
        "only sobol",
    );
    assert_usage_error(&["points", "halton", "-n", "abc"], "abc");
    assert_usage_error(&["points", "nosuch", "-n", "4"], "nosuch");
    assert_usage_error(&["points", "halton", "-n", "0"], "at least 1");
    assert_usage_error(&["points", "halton", "-n", "4", "-d", "0"], "dimensions");
    assert_usage_error(
        &["points", "halton", "-n", "4", "-d", "2000"],
        "out of range",
    );
    assert_usage_error(
        &["points", "halton", "-n", "2", "--start", "4294967295"],
        "past the end",
    );
    assert_usage_error(
        &["points", "hammersley", "-n", "4", "--start", "2"],
        "--total",
    );
    assert_usage_error(&["points", "lp", "-n", "12"], "power of two");
    assert_usage_error(&["points", "lp", "-n", "8", "-d", "3"], "two-dimensional");
    assert_usage_error(&["points", "vdc", "-n", "8", "--base", "1"], "base 1");
    assert_usage_error(&["points", "stratified", "-n", "10"], "--strata");
    assert_usage_error(
        &["points", "stratified", "-n", "10", "--strata", "3xq"],
        "\"q\"",
    );
    assert_usage_error(&["points", "halton", "-n", "4", "--format", "xml"], "xml");
    assert_usage_error(&["points", "halton", "-n", "-3"], "-3");
    assert_usage_error(&["frobnicate"], "frobnicate");
}

/// Warp geometry that cannot be computed is refused in one line naming the flag and the
/// reason; geometry at the edge of what is accepted gives finite points on the domain.
#[test]
fn warp_geometry_is_validated() {
    let warp = |name: &str, extra: &[&str]| -> Vec<String> {
        let mut args = vec![
            "points", "sobol", "-n", "16", "--warp", name, "--format", "csv",
        ];
        args.extend_from_slice(extra);
        args.into_iter().map(String::from).collect()
    };
    let refused = |name: &str, extra: &[&str], needle: &str| {
        let args = warp(name, extra);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        assert_usage_error(&args, needle);
    };
    let rect = "spherical-rectangle";
    refused(rect, &["--rect", "-1e38,-1e38,1;2e38,0,0;0,2e38,0"], "2^64");
    refused(
        rect,
        &["--rect", "-0.5,-0.5,1;1,0,0;0.5,1,0"],
        "not perpendicular",
    );
    refused(
        rect,
        &["--rect", "-0.5,-0.5,1;1,0,0;0,1,0", "--origin", "0,0,1e38"],
        "2^64",
    );
    refused(
        rect,
        &["--rect", "-0.5,-0.5,1;1,0,0;0,1,0", "--origin", "0,0,1"],
        "plane",
    );
    refused(
        rect,
        &["--rect", "-0.5,-0.5,1;1,0,0;0,1,0", "--origin", "0,0,-1e6"],
        "solid angle",
    );
    refused(rect, &["--rect", "-0.5,-0.5,1;0,0,0;0,1,0"], "zero length");
    refused(rect, &["--rect", "-0.5,-0.5,nan;1,0,0;0,1,0"], "finite");
    let tri = "spherical-triangle";
    refused(tri, &["--vertices", "0,0,1;1,0,1;2,0,1"], "collinear");
    refused(
        tri,
        &["--vertices", "0,0,1;1,0,1;0,1,1", "--origin", "5,5,1"],
        "plane",
    );
    refused(
        tri,
        &["--vertices", "0,0,1;1,0,1;0,1,1", "--origin", "0,0,1"],
        "vertex",
    );
    refused(tri, &["--vertices", "0,0,3e38;1,0,1;0,1,1"], "2^64");
    refused("triangle", &["--vertices", "0,0;1,1;2,2"], "collinear");
    refused("triangle", &["--vertices", "-3e38,0;3e38,0;0,3e38"], "2^64");
    refused("cone", &["--cone-angle", "nan"], "cone-angle");
    refused("cone", &["--cone-angle", "0.001"], "degenerate");
    // Accepted: a unit light 1000 away, seen from below: every hit exactly on z = 1.
    let args = warp(
        rect,
        &[
            "--rect",
            "-0.5,-0.5,1;1,0,0;0,1,0",
            "--origin",
            "0.3,-0.2,-1000",
        ],
    );
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    for line in stdout(&args).lines() {
        let p: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        assert!(
            p[0].abs() <= 0.5 && p[1].abs() <= 0.5 && p[2] == 1.0,
            "{line}"
        );
    }
    // A cone of 180 degrees is the whole sphere; 0.02 degrees is still a cone.
    for angle in ["180", "0.02"] {
        let args = warp("cone", &["--cone-angle", angle]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        for line in stdout(&args).lines() {
            let w: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            let n = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
            assert!((n - 1.0).abs() < 1e-6, "{angle}: {line}");
        }
    }
}

/// The library's rules decide what `--scramble` takes: the rotation applies to any
/// construction, and `vdc` in base 2 takes the base-2 kinds (it is Sobol' dimension 0).
#[test]
fn scramble_rules_follow_the_library_types() {
    let lines = |args: &[&str]| -> Vec<u32> {
        stdout(args)
            .lines()
            .map(|l| l.trim().parse().unwrap())
            .collect()
    };
    // halton + rotate: the library's Cranley-Patterson rotation of Halton, point by point.
    use qmckit::randomize::{CranleyPatterson, FastOwen, Scrambled};
    use qmckit::{Halton, Sampler, Sobol};
    let text = stdout(&[
        "points",
        "halton",
        "-n",
        "16",
        "-d",
        "2",
        "--scramble",
        "rotate",
        "--seed",
        "3",
        "--format",
        "u32",
    ]);
    let h = Scrambled::new(Halton::new(2).unwrap(), CranleyPatterson::new(3));
    for (i, line) in text.lines().enumerate() {
        let want = format!(
            "{} {}",
            h.sample(i as u32, 0).unwrap(),
            h.sample(i as u32, 1).unwrap()
        );
        assert_eq!(line, want, "point {i}");
    }
    // vdc base 2 + fast-owen equals sobol -d 1 + fast-owen, and differs from plain vdc.
    let vdc = lines(&[
        "points",
        "vdc",
        "-n",
        "64",
        "--scramble",
        "fast-owen",
        "--seed",
        "9",
        "--format",
        "u32",
    ]);
    let sobol = lines(&[
        "points",
        "sobol",
        "-n",
        "64",
        "-d",
        "1",
        "--scramble",
        "fast-owen",
        "--seed",
        "9",
        "--format",
        "u32",
    ]);
    assert_eq!(vdc, sobol);
    let s = Scrambled::new(Sobol::new(1).unwrap(), FastOwen::new(9));
    assert_eq!(vdc[17], s.sample(17, 0).unwrap());
    assert_ne!(
        vdc,
        lines(&["points", "vdc", "-n", "64", "--format", "u32"])
    );
    // The base-2 kinds still refuse radical inverses in other bases.
    assert_usage_error(
        &[
            "points",
            "vdc",
            "--base",
            "3",
            "-n",
            "4",
            "--scramble",
            "fast-owen",
        ],
        "does not apply",
    );
}
