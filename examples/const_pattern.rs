//! A scrambled sample pattern baked into a `const` by the compiler, with the public API:
//! 64 Owen-scrambled 2D Sobol' points (hash-based Owen scrambling, [`FastOwen`]), and the
//! same pattern from the Owen-scrambled Sobol' type ([`OwenSobol`]). In firmware the arrays
//! land in flash; no scrambling code runs on the device.
//!
//! Run: `cargo run --example const_pattern`.

use qmckit::digital::sobol::{OwenSobol, SobolDimension};
use qmckit::randomize::FastOwen;

/// The scramble, fixed at build time.
const OWEN: FastOwen = FastOwen::new(0x5EED);

/// 64 points, `[x, y]` as 0.32 fractions: `scrambler(d).scramble(sobol_d(i))`.
const PATTERN: [[u32; 2]; 64] = {
    let (x, y) = match (SobolDimension::new(0), SobolDimension::new(1)) {
        (Ok(x), Ok(y)) => (x, y),
        _ => panic!(), // evaluated by the compiler: a build error, never a run-time panic
    };
    let (sx, sy) = (OWEN.scrambler(0), OWEN.scrambler(1));
    let mut p = [[0u32; 2]; 64];
    let mut i = 0;
    while i < 64 {
        p[i] = [
            sx.scramble(x.sample(i as u32)),
            sy.scramble(y.sample(i as u32)),
        ];
        i += 1;
    }
    p
};

/// The same points from `OwenSobol` (its tables are read by the compiler).
const FROM_TYPE: [[u32; 2]; 64] = {
    let s = match OwenSobol::new(2, 0x5EED) {
        Ok(s) => s,
        Err(_) => panic!(),
    };
    let mut p = [[0u32; 2]; 64];
    let mut i = 0;
    while i < 64 {
        p[i] = match (s.sample(i as u32, 0), s.sample(i as u32, 1)) {
            (Ok(x), Ok(y)) => [x, y],
            _ => panic!(),
        };
        i += 1;
    }
    p
};

fn main() {
    assert_eq!(PATTERN, FROM_TYPE);
    // A (0, 6, 2)-net: each of the 64 cells of an 8 x 8 grid holds exactly one point.
    let mut cells = [0u8; 64];
    for [x, y] in PATTERN {
        cells[((x >> 29) * 8 + (y >> 29)) as usize] += 1;
    }
    assert!(cells.iter().all(|&c| c == 1));
    for [x, y] in &PATTERN[..4] {
        println!(
            "{:.6} {:.6}",
            qmckit::bits::to_f64(*x),
            qmckit::bits::to_f64(*y)
        );
    }
}
