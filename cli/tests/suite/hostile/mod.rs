//! The hostile-input suite: one runner ([`runner`]), the cases as data ([`cases`]). Every
//! case runs `qmckit` under a 4 GiB address space and a wall-clock bound, and must either
//! answer (exit 0, finite output) or refuse in one line (exit 2), within its bound.
//!
//! The cases are grouped by what went wrong on main before (each name starts with its
//! class): `panic_` (panics and aborts), `hang_` (endless loops), `budget_` (an accepted
//! run that outlives `--max-seconds`), `read_` (unbounded reads), `loss_` (data loss),
//! `wrong_` (wrong answers presented as answers) and `listed_` (listed but broken). The
//! table covers every class and every command ([`cases::covers_every_class_and_command`]).
//!
//! Run one class with `cargo test --release --all-features hostile::cases::budget_`.
#![cfg(target_os = "linux")]

mod cases;
mod checks;
mod runner;
