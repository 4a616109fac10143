//! Writes `tables/forcing-256.bin`, the forcing matrix of `blue_noise::ForcedRandom`: a
//! 256 x 256 void-and-cluster rank mask (Ulichney 1993, this crate's
//! `blue_noise::VoidAndCluster`, Gaussian `sigma = 5` cells, seed 0), row-major, each rank
//! as a little-endian `u16` (the ranks are a permutation of `0..65536`).
//!
//! ```sh
//! cargo run --release --all-features --example gen_forcing_matrix -- tables/forcing-256.bin
//! ```
//!
//! A `sigma` of 5 cells (instead of Ulichney's 1.5) spreads the sparse thresholds that
//! sets of a few thousand points take: at 1024 points (1/64 of the cells) the low-band
//! power of the sets falls from 0.12 (sigma 1.5) to 0.06 of white noise's.

use qmckit::blue_noise::VoidAndCluster;
use qmckit::work::Budget;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .ok_or("usage: gen_forcing_matrix OUT.bin")?;
    let side = 256;
    let mask = VoidAndCluster::new(side, side)?
        .sigma(5.0)?
        .seed(0)
        .generate(&Budget::UNLIMITED)?;
    let mut bytes = Vec::with_capacity(side * side * 2);
    for &r in mask.ranks() {
        let r = u16::try_from(r)?;
        bytes.extend_from_slice(&r.to_le_bytes());
    }
    std::fs::write(&out, &bytes)?;
    println!("{out}: {} ranks", side * side);
    Ok(())
}
