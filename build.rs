//! Build-time tables.
//!
//! * `primes.rs`: the first [`HALTON_MAX_DIMS`] primes, the bases of the Halton sequence.
//!   Stored as `u16` (the 1024th prime is 8161), so the table costs 2 KiB of flash when a
//!   program indexes it at run time.

use std::env;
use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;

/// How many Halton dimensions (prime bases) are compiled in.
const HALTON_MAX_DIMS: usize = 1024;

fn first_primes(count: usize) -> Vec<u32> {
    let mut primes: Vec<u32> = Vec::with_capacity(count);
    let mut candidate = 2u32;
    while primes.len() < count {
        if primes
            .iter()
            .take_while(|&&p| p * p <= candidate)
            .all(|&p| !candidate.is_multiple_of(p))
        {
            primes.push(candidate);
        }
        candidate += 1;
    }
    primes
}

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));

    let primes = first_primes(HALTON_MAX_DIMS);
    assert!(*primes.last().unwrap() <= u32::from(u16::MAX));
    let mut src = String::new();
    writeln!(
        src,
        "/// Number of prime bases compiled in (Halton dimensions)."
    )
    .unwrap();
    writeln!(src, "pub const HALTON_MAX_DIMS: usize = {HALTON_MAX_DIMS};").unwrap();
    writeln!(src, "/// The first `HALTON_MAX_DIMS` primes, ascending.").unwrap();
    writeln!(
        src,
        "pub(crate) static PRIMES: [u16; {HALTON_MAX_DIMS}] = ["
    )
    .unwrap();
    for chunk in primes.chunks(16) {
        let line: Vec<String> = chunk.iter().map(|p| p.to_string()).collect();
        writeln!(src, "    {},", line.join(", ")).unwrap();
    }
    writeln!(src, "];").unwrap();
    fs::write(out.join("primes.rs"), src).expect("write primes.rs");
}
