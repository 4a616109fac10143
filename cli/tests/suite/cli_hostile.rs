//! Hostile input for the `qmckit` command: every invocation below either answers correctly
//! (exit 0, finite output of the right shape) or refuses in one line (exit 2, a reason, no
//! panic text), within a 4 GiB address space and, for refusals, within 5 seconds.
#![cfg(target_os = "linux")]

use std::io::{Read, Write};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// The address-space limit every case runs under (KiB), as `ulimit -v` takes it.
const ADDRESS_SPACE_KIB: u64 = 4 << 20;

/// Longest a refusal may take.
const REFUSAL_TIME: Duration = Duration::from_secs(5);

/// qmckit `args` under an address-space limit of `kib` KiB (`ulimit -v`), all three
/// streams piped; `stderr_to` replaces stderr by a file (e.g. `/dev/full`).
fn limited(kib: u64, args: &[&str], stderr_to: Option<&str>) -> Command {
    let redirect = stderr_to
        .map(|path| format!(" 2>{path}"))
        .unwrap_or_default();
    let mut command = Command::new("sh");
    command
        .arg("-c")
        .arg(format!("ulimit -v {kib} && exec \"$0\" \"$@\"{redirect}"))
        .arg(env!("CARGO_BIN_EXE_qmckit"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    command
}

/// Longest any run here may take before it is killed and the test fails.
const RUN_TIME: Duration = Duration::from_secs(60);

/// Runs qmckit under the address-space limit with `input` on stdin; `stderr_to` replaces
/// stderr by a file (e.g. `/dev/full`). A run past [`RUN_TIME`] is killed and fails.
fn run_limited(args: &[&str], input: &[u8], stderr_to: Option<&str>) -> (Output, Duration) {
    let clock = Instant::now();
    let mut child = limited(ADDRESS_SPACE_KIB, args, stderr_to)
        .spawn()
        .expect("run qmckit");
    let mut stdin = child.stdin.take().unwrap();
    let input = input.to_vec();
    let writer = std::thread::spawn(move || {
        // A command that refuses before reading closes the pipe: not the test's concern.
        let _ = stdin.write_all(&input);
    });
    let drain = |mut pipe: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            let _ = pipe.read_to_end(&mut bytes);
            bytes
        })
    };
    let stdout = drain(Box::new(child.stdout.take().unwrap()));
    let stderr = drain(Box::new(child.stderr.take().unwrap()));
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if clock.elapsed() > RUN_TIME {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{args:?}: still running after {RUN_TIME:?} (killed)");
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let out = Output {
        status,
        stdout: stdout.join().unwrap(),
        stderr: stderr.join().unwrap(),
    };
    writer.join().unwrap();
    (out, clock.elapsed())
}

/// No panic message, backtrace or allocator abort in `stderr`.
fn assert_no_crash(args: &[&str], out: &Output) {
    let err = String::from_utf8_lossy(&out.stderr);
    for bad in [
        "panicked",
        "RUST_BACKTRACE",
        "memory allocation",
        "overflow",
        "stack",
    ] {
        // "overflows" is a word our refusals use; the abort texts are "has overflowed its
        // stack" and "memory allocation of N bytes failed".
        if bad == "overflow" || bad == "stack" {
            assert!(!err.contains("has overflowed its stack"), "{args:?}: {err}");
            continue;
        }
        assert!(!err.contains(bad), "{args:?}: {err}");
    }
    assert!(
        out.status.code().is_some(),
        "{args:?}: killed by a signal: {:?}",
        out.status
    );
}

/// Exit 2 with exactly one `qmckit: error:` line holding `needle`, nothing on stdout, in
/// under [`REFUSAL_TIME`].
fn refuses(args: &[&str], input: &str, needle: &str) {
    let (out, took) = run_limited(args, input.as_bytes(), None);
    assert_no_crash(args, &out);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err:?}");
    assert!(err.starts_with("qmckit: error: "), "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: {err:?} lacks {needle:?}");
    assert!(
        out.stdout.is_empty(),
        "{args:?}: wrote {} bytes",
        out.stdout.len()
    );
    assert!(took < REFUSAL_TIME, "{args:?}: refused after {took:?}");
}

/// Exit 0, nothing on stderr; returns stdout.
fn answers(args: &[&str], input: &str) -> String {
    let (out, _) = run_limited(args, input.as_bytes(), None);
    assert_no_crash(args, &out);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty(), "{args:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The `metric value` lines of a discrepancy run, every value finite.
fn finite_values(args: &[&str], text: &str) -> Vec<(String, f64)> {
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let (k, v) = l.split_once(' ').unwrap();
            let v: f64 = v.parse().unwrap();
            assert!(v.is_finite(), "{args:?}: {l}");
            (k.to_owned(), v)
        })
        .collect()
}

/// The text of `qmckit points ARGS`.
fn points(args: &[&str]) -> String {
    answers(&[&["points"], args].concat(), "")
}

#[test]
fn counts_that_overflow_or_truncate_are_refused() {
    let max = "18446744073709551615";
    refuses(
        &["points", "sobol", "--start", "1", "-n", max],
        "",
        "overflows",
    );
    refuses(
        &[
            "points", "sobol", "--start", "1", "-n", max, "--format", "npy",
        ],
        "",
        "overflows",
    );
    refuses(
        &[
            "points",
            "independent",
            "-n",
            "2",
            "-d",
            "9223372036854775808",
        ],
        "",
        "too large",
    );
    refuses(
        &["points", "independent", "-n", "1", "-d", max],
        "",
        "too large",
    );
    refuses(
        &[
            "points",
            "stratified",
            "-d",
            "1",
            "-n",
            "1",
            "--total",
            "4294967296",
        ],
        "",
        "4294967296",
    );
    refuses(&["points", "latin", "-n", "4294967301"], "", "4294967301");
    refuses(
        &["points", "hammersley", "-n", "4294967301"],
        "",
        "4294967301",
    );
    refuses(
        &["points", "sobol", "--start", "4294967296", "-n", "1"],
        "",
        "past the end",
    );
    refuses(
        &["points", "halton", "--start", "4294967295", "-n", "2"],
        "",
        "past the end",
    );
    // The last index of the sequence is fine.
    let last = points(&["sobol", "--start", "4294967295", "-n", "1"]);
    assert_eq!(last.lines().count(), 1);
    refuses(
        &["points", "latin", "-n", "1", "-d", "1000000000"],
        "",
        "too large",
    );
}

#[test]
fn streaming_output_has_bounded_memory() {
    // Aborted allocating 6.5 GB, then 1.4 GB for the second: now written in small batches.
    for args in [
        &[
            "points",
            "independent",
            "-n",
            "16384",
            "-d",
            "100000",
            "--format",
            "u32",
        ][..],
        &[
            "points",
            "sobol",
            "-n",
            "100000",
            "-d",
            "21201",
            "--scramble",
            "lms",
            "--format",
            "u32",
        ][..],
    ] {
        let mut child = limited(1 << 20, args, None).spawn().unwrap(); // 1 GiB
        let mut head = vec![0u8; 4 << 20];
        child.stdout.take().unwrap().read_exact(&mut head).unwrap();
        // Closing the pipe ends the command (a broken pipe is a normal end).
        let out = child.wait_with_output().unwrap();
        assert_no_crash(args, &out);
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        let first = String::from_utf8_lossy(&head[..1000]);
        assert!(first.split(' ').next().unwrap().parse::<u32>().is_ok());
    }
}

#[test]
fn deep_inputs_do_not_overflow_the_stack() {
    // One point in 10000 dimensions: 50 KB of input.
    let one = vec!["0.5"; 10_000].join(" ") + "\n";
    for metric in ["star", "star-bounds", "all"] {
        let (out, took) = run_limited(&["discrepancy", "--metric", metric], one.as_bytes(), None);
        assert_no_crash(&[metric], &out);
        assert!(matches!(out.status.code(), Some(0 | 2)), "{metric}");
        if out.status.code() == Some(0) {
            finite_values(&[metric], &String::from_utf8(out.stdout).unwrap());
        } else {
            assert!(took < REFUSAL_TIME, "{metric}: {took:?}");
            assert_eq!(String::from_utf8_lossy(&out.stderr).lines().count(), 1);
        }
    }
    for d in ["10057", "21201"] {
        let text = answers(&["tvalue", "sobol", "-m", "2", "-d", d], "");
        assert!(text.contains("\nt "), "{text}");
    }
}

#[test]
fn super_linear_work_is_refused_before_it_starts() {
    refuses(
        &["tvalue", "sobol", "-m", "32", "-d", "50"],
        "",
        "--max-seconds",
    );
    refuses(
        &["tvalue", "sobol", "-m", "20", "-d", "1000"],
        "",
        "--max-seconds",
    );
    let two = |d: usize| {
        format!(
            "{}\n{}\n",
            vec!["0.25"; d].join(" "),
            vec!["0.75"; d].join(" ")
        )
    };
    for d in [1000, 20000] {
        let (out, took) = run_limited(
            &["discrepancy", "--metric", "star-bounds"],
            two(d).as_bytes(),
            None,
        );
        assert_no_crash(&["star-bounds"], &out);
        match out.status.code() {
            Some(0) => {
                let v = finite_values(&["star-bounds"], &String::from_utf8(out.stdout).unwrap());
                assert!(v.iter().all(|(_, x)| (0.0..=1.0).contains(x)), "{v:?}");
            }
            Some(2) => assert!(took < REFUSAL_TIME, "d = {d}: {took:?}"),
            other => panic!("d = {d}: {other:?}"),
        }
    }
    refuses(
        &[
            "convergence",
            "halton",
            "-d",
            "32",
            "--scramble",
            "owen",
            "--max-m",
            "20",
            "--seeds",
            "4",
        ],
        "",
        "--max-seconds",
    );
    refuses(
        &["discrepancy", "--max-seconds", "0"],
        "0.5\n",
        "--max-seconds",
    );
    refuses(
        &["discrepancy", "--max-seconds", "nan"],
        "0.5\n",
        "--max-seconds",
    );
}

#[test]
fn l2_measures_are_refused_past_the_budget() {
    // 10^6 points: about half an hour for each O(N^2 d) measure.
    let dir = std::env::temp_dir().join(format!("qmckit-hostile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("million.npy");
    let (out, _) = run_limited(
        &["points", "sobol", "-n", "1000000", "--format", "npy"],
        b"",
        None,
    );
    assert_eq!(out.status.code(), Some(0));
    std::fs::write(&file, &out.stdout).unwrap();
    let path = file.to_str().unwrap();
    for metric in ["cd", "wd", "md", "sl2", "ul2", "gl2", "diaphony"] {
        refuses(
            &["discrepancy", "--metric", metric, path],
            "",
            "--max-seconds",
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn high_dimensional_l2_values_are_finite_or_refused() {
    for d in ["600", "1000", "2000", "4000"] {
        let csv = points(&[
            "sobol",
            "-n",
            "64",
            "-d",
            d,
            "--scramble",
            "owen",
            "--format",
            "csv",
        ]);
        let (out, _) = run_limited(&["discrepancy"], csv.as_bytes(), None);
        assert_no_crash(&[d], &out);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            matches!(out.status.code(), Some(0 | 2)),
            "d = {d}: {:?}",
            out.status
        );
        assert!(!err.contains("NaN"), "d = {d}: {err}");
        let text = String::from_utf8(out.stdout).unwrap();
        for (metric, v) in finite_values(&[d], &text) {
            // Every measure of 64 points in many dimensions is far from zero.
            assert!(v > 0.0, "d = {d}: {metric} {v}");
        }
    }
}

#[test]
fn star_bounds_stay_in_the_unit_interval() {
    let text = points(&["sobol", "-n", "256", "-d", "3", "--format", "csv"]);
    let v = finite_values(
        &["star-bounds"],
        &answers(&["discrepancy", "--metric", "star-bounds"], &text),
    );
    let (lower, upper) = (v[0].1, v[1].1);
    assert!(0.0 <= lower && lower <= upper && upper <= 1.0, "{v:?}");
    // One point at the origin: D* = 1 exactly, and the bound may not pass it.
    let v = finite_values(
        &["star-bounds"],
        &answers(&["discrepancy", "--metric", "star-bounds"], "0 0 0\n"),
    );
    assert!(v.iter().all(|(_, x)| *x <= 1.0), "{v:?}");
}

#[test]
fn input_is_read_as_written() {
    // CR-only line ends: two 2-D points, not one 4-D point.
    let v = finite_values(
        &["cr"],
        &answers(&["discrepancy", "--metric", "star"], "0.1 0.2\r0.3 0.4\r"),
    );
    // Exact D* of {(0.1, 0.2), (0.3, 0.4)}: the closed box [0, 0.3] x [0, 0.4] holds both,
    // 1 - 0.12 = 0.88.
    assert!((v[0].1 - 0.88).abs() < 1e-12, "{v:?}");
    for sep in ["\u{a0}", "\u{b}", "\u{c}"] {
        refuses(
            &["discrepancy"],
            &format!("0.1{sep}0.2\n"),
            "does not separate numbers",
        );
    }
    refuses(&["discrepancy"], "x,y\n0.1,0.2\n", "header");
}

#[test]
fn the_tool_reads_its_own_output() {
    let u32s = points(&["sobol", "-n", "64", "--format", "u32"]);
    let csv = points(&["sobol", "-n", "64", "--format", "csv"]);
    let a = answers(&["discrepancy"], &u32s);
    let b = answers(&["discrepancy"], &csv);
    assert_eq!(a, b);
    assert_eq!(finite_values(&["u32"], &a).len(), 9);
    let spectrum_u32 = answers(&["spectrum", "--k-max", "4"], &u32s);
    assert_eq!(spectrum_u32, answers(&["spectrum", "--k-max", "4"], &csv));
    // The default output (decimals, space-separated) reads back the same, with default
    // options, in every measuring command.
    let decimals = points(&["sobol", "-n", "64"]);
    assert_eq!(decimals.lines().nth(1), Some("0.5 0.5"));
    assert_eq!(answers(&["discrepancy"], &decimals), a);
    assert_eq!(
        answers(&["spectrum", "--k-max", "4"], &decimals),
        spectrum_u32
    );
    for cmd in [&["pcf"][..], &["pcf", "--torus"], &["spectrum", "--radial"]] {
        assert_eq!(answers(cmd, &decimals), answers(cmd, &u32s), "{cmd:?}");
    }
    // npy files read back, from a file and from stdin.
    let dir = std::env::temp_dir().join(format!("qmckit-npy-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("p.npy");
    let (out, _) = run_limited(
        &["points", "sobol", "-n", "64", "--format", "npy"],
        b"",
        None,
    );
    std::fs::write(&file, &out.stdout).unwrap();
    assert_eq!(answers(&["discrepancy", file.to_str().unwrap()], ""), a);
    let (piped, _) = run_limited(&["discrepancy"], &out.stdout, None);
    assert_eq!(String::from_utf8(piped.stdout).unwrap(), a);
    // A truncated npy file is an error, not a huge allocation.
    std::fs::write(&file, &out.stdout[..out.stdout.len() - 8]).unwrap();
    refuses(&["discrepancy", file.to_str().unwrap()], "", "npy");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn options_that_do_not_apply_are_named() {
    for (args, needle) in [
        (&["points", "sobol", "-n", "2", "--base", "3"][..], "--base"),
        (
            &["points", "sobol", "-n", "2", "--strata", "2x1"][..],
            "--strata",
        ),
        (
            &["points", "sobol", "-n", "2", "--total", "8"][..],
            "--total",
        ),
        (
            &["points", "sobol", "-n", "2", "--centered"][..],
            "--centered",
        ),
        (
            &["points", "halton", "-n", "2", "--seed", "1"][..],
            "--seed",
        ),
        (
            &[
                "points",
                "stratified",
                "-n",
                "4",
                "--centered",
                "--seed",
                "1",
            ][..],
            "--seed",
        ),
        (
            &["points", "halton", "-n", "2", "--order", "gray"][..],
            "--order",
        ),
        (
            &[
                "points",
                "sobol",
                "-n",
                "2",
                "--warp",
                "disk",
                "--vertices",
                "0,0;1,0;0,1",
            ][..],
            "--vertices",
        ),
        (
            &[
                "points",
                "sobol",
                "-n",
                "2",
                "--warp",
                "disk",
                "--cone-angle",
                "10",
            ][..],
            "--cone-angle",
        ),
        (
            &["points", "sobol", "-n", "2", "--vertices", "0,0;1,0;0,1"][..],
            "--vertices",
        ),
    ] {
        refuses(args, "", needle);
    }
    let text = answers(
        &["discrepancy", "--metric", "all,extreme,star-bounds"],
        &points(&["sobol", "-n", "16", "--format", "csv"]),
    );
    let names: Vec<String> = finite_values(&["all"], &text)
        .into_iter()
        .map(|(k, _)| k)
        .collect();
    assert_eq!(names.len(), 12, "{names:?}");
    for name in ["extreme", "star-lower", "star-upper", "diaphony"] {
        assert!(names.iter().any(|n| n == name), "{names:?}");
    }
}

#[test]
fn help_lists_only_what_applies() {
    let help = answers(&["tvalue", "--help"], "");
    assert!(
        !help.contains("independent") && !help.contains("latin"),
        "{help}"
    );
    let help = answers(&["convergence", "--help"], "");
    assert!(
        !help.contains("--base") && !help.contains("--strata"),
        "{help}"
    );
    for command in ["discrepancy", "tvalue", "convergence", "spectrum"] {
        assert!(
            answers(&[command, "--help"], "").contains("--max-seconds"),
            "{command}"
        );
    }
    let (out, _) = run_limited(&["spectrum", "--k-max", "5000"], b"0.5 0.5\n", None);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        !err.contains("SPECTRUM_MAX_K") && !err.contains('_'),
        "{err}"
    );
}

#[test]
fn warp_geometry_is_validated() {
    for (args, needle) in [
        (
            &[
                "--warp",
                "spherical-rectangle",
                "--rect",
                "-1e38,-1e38,1;2e38,0,0;0,2e38,0",
            ][..],
            "rect",
        ),
        (
            &[
                "--warp",
                "spherical-rectangle",
                "--rect",
                "0,0,1;1,0,0;1,1,0",
            ][..],
            "perpendicular",
        ),
        (&["--warp", "cone", "--cone-angle", "NaN"][..], "cone"),
        (&["--warp", "cone", "--cone-angle", "0"][..], "cone"),
        (
            &["--warp", "triangle", "--vertices", "0,0;1,1;2,2"][..],
            "triangle",
        ),
    ] {
        let full = [&["points", "sobol", "-n", "4", "--format", "csv"][..], args].concat();
        refuses(&full, "", needle);
    }
    // A far origin: finite points on the rectangle, or a refusal; never z = 0 by underflow.
    let (out, _) = run_limited(
        &[
            "points",
            "sobol",
            "-n",
            "4",
            "--format",
            "csv",
            "--warp",
            "spherical-rectangle",
            "--rect",
            "0,0,1;1,0,0;0,1,0",
            "--origin",
            "0,0,1e38",
        ],
        b"",
        None,
    );
    assert_no_crash(&["origin"], &out);
    if out.status.code() == Some(0) {
        for line in String::from_utf8(out.stdout).unwrap().lines() {
            let p: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            assert!(p.iter().all(|x| x.is_finite()), "{line}");
            assert!(
                (p[2] - 1.0).abs() < 1e-6,
                "{line}: off the rectangle's plane"
            );
        }
    } else {
        assert_eq!(out.status.code(), Some(2));
    }
}

#[test]
fn an_unwritable_stderr_is_no_panic() {
    let (out, _) = run_limited(&["points", "sobol", "-n", "x"], b"", Some("/dev/full"));
    assert_eq!(out.status.code(), Some(2));
    let (out, _) = run_limited(
        &["points", "sobol", "-n", "4", "--base", "3"],
        b"",
        Some("/dev/full"),
    );
    assert_eq!(out.status.code(), Some(2));
}
