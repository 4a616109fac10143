//! The `qmckit` command: generate and judge sampling patterns (see the `qmckit_cli` library
//! for the commands themselves).

use std::process::ExitCode;

fn main() -> ExitCode {
    qmckit_cli::threads();
    qmckit_cli::on_termination();
    ExitCode::from(qmckit_cli::run_cli(std::env::args_os()))
}
