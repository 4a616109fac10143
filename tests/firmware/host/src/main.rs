//! Prints the firmware test vectors on the host (stdout), for `run.sh` to diff against
//! the output of the firmware under QEMU.

#[path = "../../src/vectors.rs"]
mod vectors;

use std::io::Write as _;

fn main() {
    let mut text = String::new();
    if let Err(e) = vectors::write_all(&mut text) {
        eprintln!("qmckit-firmware-host: formatting failed: {e}");
        std::process::exit(1);
    }
    let mut stdout = std::io::stdout().lock();
    if let Err(e) = stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        eprintln!("qmckit-firmware-host: {e}");
        std::process::exit(1);
    }
}
