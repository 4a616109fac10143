//! Fuzzes the `qmckit` command line: any argument vector must end in exit code 0, 1 or 2
//! without a panic (a panic aborts the fuzzer and fails the run). The command runs in-process
//! (`qmckit_cli::run_cli`), so coverage guides the search through its parsers and checks.
//!
//! The input is split at NUL bytes into arguments after a command chosen by its first byte.
//! Standard input should be empty (`< /dev/null`) and standard output discarded. Arguments
//! naming absolute paths are skipped (no reading of devices), every budgeted command gets a
//! small `--max-seconds`, and `points` requests whose numbers multiply past 10^7 are skipped
//! (their output is linear but large; the refusals of huge counts are covered by the
//! hostile-input tests).
#![no_main]

use libfuzzer_sys::fuzz_target;

/// The commands, chosen by the first byte.
const COMMANDS: [&str; 6] = [
    "points",
    "discrepancy",
    "tvalue",
    "convergence",
    "spectrum",
    "--help",
];

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let command = COMMANDS[first as usize % COMMANDS.len()];
    let mut args: Vec<String> = vec!["qmckit".into(), command.into()];
    args.extend(
        rest.split(|&b| b == 0)
            .map(|a| String::from_utf8_lossy(a).into_owned()),
    );
    if args.iter().any(|a| a.starts_with('/') || a.contains("..")) {
        return;
    }
    if args.iter().any(|a| a.starts_with("--max-seconds")) {
        return;
    }
    if command == "points" {
        let work = args
            .iter()
            .filter_map(|a| a.parse::<f64>().ok())
            .filter(|x| x.is_finite() && *x >= 1.0)
            .fold(1.0, |p, x| p * x);
        if work > 1e7 {
            return;
        }
    } else if command != "--help" {
        args.push("--max-seconds".into());
        args.push("0.25".into());
    }
    let code = qmckit_cli::run_cli(args);
    assert!(code <= 2, "exit code {code}");
});
