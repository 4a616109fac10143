//! Puts the chosen board's `memory.x` where cortex-m-rt's `link.x` looks for it.

use std::env;
use std::fs;
use std::path::PathBuf;

const BOARDS: [&str; 3] = ["microbit", "lm3s6965evb", "mps2-an386"];

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let chosen: Vec<&str> = BOARDS
        .iter()
        .copied()
        .filter(|b| {
            let var = format!("CARGO_FEATURE_BOARD_{}", b.to_uppercase().replace('-', "_"));
            env::var_os(var).is_some()
        })
        .collect();
    let board = match chosen.as_slice() {
        [b] => *b,
        _ => panic!(
            "enable exactly one of the features board-{}",
            BOARDS.join(", board-")
        ),
    };
    let src = format!("memory/{board}.x");
    println!("cargo:rerun-if-changed={src}");
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    fs::copy(&src, out.join("memory.x")).expect("copy memory.x");
    println!("cargo:rustc-link-search={}", out.display());
    // The defmt variant also needs defmt's linker script (found on the search path that
    // the defmt crate's build script adds).
    if env::var_os("CARGO_FEATURE_DEFMT").is_some() {
        println!("cargo:rustc-link-arg-bin=defmt-log=-Tdefmt.x");
    }
}
