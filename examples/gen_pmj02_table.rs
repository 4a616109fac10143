//! Writes `tables/pmj02-65536.bin`, the shared table of `pixel::Pmj02Pixels`: the first
//! 65,536 points of this crate's stochastic PMJ02 sequence (`pmj::fill`, seed 0), each
//! coordinate's top 16 bits as a little-endian `u16`, `x` then `y`, in sequence order
//! (256 KiB).
//!
//! ```sh
//! cargo run --release --example gen_pmj02_table -- tables/pmj02-65536.bin
//! ```
//!
//! The first `2^16` points of a (0, 2)-sequence are a (0, 16, 2)-net: every coordinate's
//! top 16 bits take each value once, so 16 bits keep the points' whole stratification, and
//! the sampler's Owen scrambling supplies the digits past the 16th.

use qmckit::pmj::fill;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .ok_or("usage: gen_pmj02_table OUT.bin")?;
    let n = 1usize << 16;
    let mut pts = vec![[0u32; 2]; n];
    fill(0, &mut pts)?;
    let mut bytes = Vec::with_capacity(4 * n);
    for p in &pts {
        for c in p {
            bytes.extend_from_slice(&((c >> 16) as u16).to_le_bytes());
        }
    }
    std::fs::write(&out, &bytes)?;
    println!("{out}: {n} points");
    Ok(())
}
