//! Running the `qmckit` binary from the integration tests.

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Runs qmckit with `input` on its standard input.
pub fn run(args: &[&str], input: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_qmckit"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run qmckit");
    let mut stdin = child.stdin.take().unwrap();
    // A command that fails before reading its input (a missing file, a bad option) may
    // close the pipe first: that broken pipe is not the test's concern, its exit code is.
    if let Err(e) = stdin.write_all(input.as_bytes()) {
        assert_eq!(
            e.kind(),
            std::io::ErrorKind::BrokenPipe,
            "writing stdin: {e}"
        );
    }
    drop(stdin);
    child.wait_with_output().unwrap()
}

/// Bad usage or input: exit code 2, exactly one line on stderr naming `needle`, nothing
/// that looks like a panic, nothing on stdout.
pub fn assert_usage_error(args: &[&str], input: &str, needle: &str) {
    let out = run(args, input);
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{args:?}: {err:?}");
    assert!(err.starts_with("qmckit: error: "), "{err}");
    assert!(err.contains(needle), "{args:?}: {err:?} lacks {needle:?}");
    assert!(!err.contains("panicked") && !err.contains("RUST_BACKTRACE"));
    assert!(out.stdout.is_empty());
}
