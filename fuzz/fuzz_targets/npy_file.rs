//! Fuzzes the `.npy` reader of the measuring commands (`discrepancy`, `spectrum`, `pcf`):
//! the input, after the NumPy magic bytes, is written to a private file that the command
//! reads in-process (its own reader, through `qmckit_cli::run_cli`). Any byte string must
//! end in exit code 0 or 2 (a refusal), never a panic or an allocation failure. The first
//! byte picks the command (and, for text, whether the magic is prefixed at all).
#![no_main]

use libfuzzer_sys::fuzz_target;

const COMMANDS: [&str; 3] = ["discrepancy", "spectrum", "pcf"];

/// The private input file of this fuzzing process (in /dev/shm when it exists).
fn input_path() -> &'static str {
    static PATH: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    PATH.get_or_init(|| {
        let dir = if std::path::Path::new("/dev/shm").is_dir() {
            "/dev/shm".to_owned()
        } else {
            std::env::temp_dir().to_string_lossy().into_owned()
        };
        format!("{dir}/qmckit-fuzz-npy-{}.npy", std::process::id())
    })
}

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let command = COMMANDS[first as usize % COMMANDS.len()];
    let mut bytes = Vec::with_capacity(rest.len() + 6);
    if first & 0x80 == 0 {
        bytes.extend_from_slice(b"\x93NUMPY");
    }
    bytes.extend_from_slice(rest);
    let path = input_path();
    std::fs::write(path, &bytes).expect("write the fuzz input");
    let args = ["qmckit", command, "--max-seconds", "0.25", path];
    let code = qmckit_cli::run_cli(args);
    assert!(code == 0 || code == 2, "exit code {code}");
});
