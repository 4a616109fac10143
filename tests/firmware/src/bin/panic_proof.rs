//! Link-time proof that qmckit's hot paths contain no panic.
//!
//! The panic handler calls `qmckit_panic_path_survived`, an `extern "C"` function that is
//! defined nowhere. After optimisation (fat LTO, `panic = "abort"`), a call to the panic
//! handler remains only if some panic path (a bounds check, an overflow check, an
//! `unwrap`, a division by zero, ...) is still reachable from `main`; the linker then
//! fails with `undefined symbol: qmckit_panic_path_survived` and names the function that
//! refers to it. So a successful link *is* the proof. `panic_proof.sh` builds this for
//! thumbv6m, thumbv7m and thumbv7em at opt-level "s" and 3, and runs it under QEMU.
//!
//! Every input is hidden from the optimiser (`black_box`): constructors validate run-time
//! parameters (their `Result` is matched, never unwrapped), and the hot functions are then
//! called with run-time indices and dimensions. This file itself must not panic either:
//! no slicing by index, no `core::fmt`, only `get`/iterators.
//!
//! Each check is one entry of `CHECKS`. At compile time, `QMCKIT_PROOF_ONLY=<a>,<b>,..`
//! keeps only those checks (`all`, or unset: every check but the `EXCLUDED` ones) (used by `panic_proof.sh` to find the culprit when the link fails), and
//! `EXCLUDED` lists checks known to keep a panic path (reported, kept out of the proof).
#![no_std]
#![no_main]

#[path = "../support.rs"]
mod support;

use core::hint::black_box;

use cortex_m_rt::entry;
use qmckit::bits;
use qmckit::digital::sobol::OwenSobol;
use qmckit::randomize::{FastOwen, ExactOwen};
use qmckit::digital::sobol::{Sobol, SobolDimension, SobolTable};
use qmckit::{Halton, Hammersley, LarcherPillichshammer, RadicalInverse, Sampler};

unsafe extern "C" {
    /// Defined nowhere, on purpose: see the module documentation.
    fn qmckit_panic_path_survived() -> !;
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    // SAFETY: never executed in a binary that links.
    unsafe { qmckit_panic_path_survived() }
}

/// Checks known to keep a panic path: none at present. Add a name here (with the linker's
/// message in a comment) to keep it out of the proof until the core is fixed.
const EXCLUDED: &[&str] = &[];

/// Whether check `name` is compiled in (evaluated at compile time, so the others vanish).
const fn enabled(name: &str) -> bool {
    match option_env!("QMCKIT_PROOF_ONLY") {
        Some(only) if !str_eq(only, "all") => list_contains(only.as_bytes(), name.as_bytes()),
        _ => {
            let mut k = 0;
            while k < EXCLUDED.len() {
                if str_eq(EXCLUDED[k], name) {
                    return false;
                }
                k += 1;
            }
            true
        }
    }
}

const fn str_eq(a: &str, b: &str) -> bool {
    bytes_eq(a.as_bytes(), 0, a.len(), b.as_bytes())
}

/// Whether `a[start..end] == b`.
const fn bytes_eq(a: &[u8], start: usize, end: usize, b: &[u8]) -> bool {
    if end - start != b.len() {
        return false;
    }
    let mut k = 0;
    while k < b.len() {
        if a[start + k] != b[k] {
            return false;
        }
        k += 1;
    }
    true
}

/// Whether the comma-separated `list` has the item `name`.
const fn list_contains(list: &[u8], name: &[u8]) -> bool {
    let mut start = 0;
    let mut k = 0;
    while k <= list.len() {
        if k == list.len() || list[k] == b',' {
            if bytes_eq(list, start, k, name) {
                return true;
            }
            start = k + 1;
        }
        k += 1;
    }
    false
}

/// The names of all checks, for `panic_proof.sh` (`grep '^    "'` between the markers).
// proof-checks-begin
#[allow(dead_code)]
const CHECKS: &[&str] = &[
    "RadicalInverse::sample",
    "RadicalInverse::fill",
    "Halton::sample",
    "SobolDimension::sample",
    "SobolTable::sample",
    "Sobol+Sampler::fill",
    "FastOwen::scramble",
    "ExactOwen::scramble",
    "OwenSobol::sample4",
    "bits::to_f32",
    "LarcherPillichshammer::sample",
    "Hammersley::sample",
];
// proof-checks-end

static SOBOL_TABLE_3: SobolTable = SobolTable::new(match SobolDimension::new(3) {
    Ok(d) => d,
    Err(_) => panic!(),
});

static OWEN_SOBOL4: OwenSobol = match OwenSobol::new(4, 0x5EED) {
    Ok(t) => t,
    Err(_) => panic!(),
};

/// Indices swept by every check (run-time values through `black_box`).
const COUNT: u32 = 64;
const STRIDE: u32 = 0x0100_0193; // reaches the top of the u32 range

/// Runs the enabled checks; false if a validated constructor or call returned an error.
fn run() -> (bool, u32) {
    let mut ok = true;
    let mut acc = 0u32;
    let mut buf = [0u32; 256];
    let idx = |k: u32| black_box(k.wrapping_mul(STRIDE));

    if const { enabled("RadicalInverse::sample") } {
        match RadicalInverse::new(black_box(3)) {
            Ok(ri) => (0..COUNT).for_each(|k| acc ^= ri.sample(idx(k))),
            Err(_) => ok = false,
        }
    }
    if const { enabled("RadicalInverse::fill") } {
        match RadicalInverse::new(black_box(7)) {
            Ok(ri) => {
                let len = black_box(200usize);
                match buf.get_mut(..len) {
                    Some(out) => ok &= ri.fill(black_box(1_000_000), out).is_ok(),
                    None => ok = false,
                }
                buf.iter().for_each(|&x| acc ^= x);
            }
            Err(_) => ok = false,
        }
    }
    if const { enabled("Halton::sample") } {
        match Halton::new(black_box(8)) {
            Ok(h) => {
                for k in 0..COUNT {
                    match h.sample(idx(k), black_box(k as usize % 8)) {
                        Ok(x) => acc ^= x,
                        Err(_) => ok = false,
                    }
                }
            }
            Err(_) => ok = false,
        }
    }
    if const { enabled("SobolDimension::sample") } {
        match SobolDimension::new(black_box(5)) {
            Ok(d) => (0..COUNT).for_each(|k| acc ^= d.sample(idx(k))),
            Err(_) => ok = false,
        }
    }
    if const { enabled("SobolTable::sample") } {
        (0..COUNT).for_each(|k| acc ^= SOBOL_TABLE_3.sample(idx(k)));
    }
    if const { enabled("Sobol+Sampler::fill") } {
        match Sobol::new(black_box(8)) {
            Ok(s) => {
                let len = black_box(32 * 8usize);
                match buf.get_mut(..len) {
                    Some(out) => ok &= Sampler::fill(&s, black_box(4096), out).is_ok(),
                    None => ok = false,
                }
                buf.iter().for_each(|&x| acc ^= x);
            }
            Err(_) => ok = false,
        }
    }
    if const { enabled("FastOwen::scramble") } {
        let o = FastOwen::new(black_box(0x5EED));
        (0..COUNT).for_each(|k| acc ^= o.scramble(idx(k), black_box(k as usize)));
    }
    if const { enabled("ExactOwen::scramble") } {
        let o = ExactOwen::new(black_box(0x5EED));
        (0..COUNT).for_each(|k| acc ^= o.scramble(idx(k), black_box(k as usize)));
    }
    if const { enabled("OwenSobol::sample4") } {
        for k in 0..COUNT {
            let p = OWEN_SOBOL4.sample4(idx(k));
            acc ^= p[0] ^ p[1] ^ p[2] ^ p[3];
        }
    }
    if const { enabled("bits::to_f32") } {
        (0..COUNT).for_each(|k| acc ^= bits::to_f32(idx(k)).to_bits());
    }
    if const { enabled("LarcherPillichshammer::sample") } {
        match LarcherPillichshammer::new(black_box(16)) {
            Ok(lp) => {
                for k in 0..COUNT {
                    match lp.sample(black_box(k * 1000), black_box(k as usize % 2)) {
                        Ok(x) => acc ^= x,
                        Err(_) => ok = false,
                    }
                }
            }
            Err(_) => ok = false,
        }
    }
    if const { enabled("Hammersley::sample") } {
        match Hammersley::new(black_box(100_000), black_box(4)) {
            Ok(h) => {
                for k in 0..COUNT {
                    match h.sample(black_box(k * 1500), black_box(k as usize % 4)) {
                        Ok(x) => acc ^= x,
                        Err(_) => ok = false,
                    }
                }
            }
            Err(_) => ok = false,
        }
    }
    (ok, acc)
}

#[entry]
fn main() -> ! {
    let (ok, acc) = run();
    black_box(acc);
    support::exit(ok)
}
