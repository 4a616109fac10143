//! Times `l2_star_fast` (divide and conquer) against `l2_star_direct` (pair sum) on one
//! thread, on uniform random points (SplitMix64, fixed seed), for the crossover table of
//! `qmckit::analysis::l2::l2_star`.
//!
//! Usage: `cargo run --release --features analysis --example time_l2_star -- DIMS DIRECT_MAX_LOG2 LOG2_N...`
//!
//! For each `n = 2^LOG2_N` prints `d n fast_seconds direct_seconds relative_difference`;
//! the pair sum is only run for `LOG2_N <= DIRECT_MAX_LOG2` (else `-`). Each timing is
//! the best of as many runs as fit in about a second (at least one).

use qmckit::analysis::Points;
use qmckit::analysis::l2::{l2_star_direct, l2_star_fast};
use std::time::Instant;

fn uniform(len: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..len)
        .map(|_| {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            (z >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

/// Best time of `f` and its value.
fn best(f: impl Fn() -> f64) -> (f64, f64) {
    let mut best = f64::INFINITY;
    let mut value = f64::NAN;
    let start = Instant::now();
    while best.is_infinite() || start.elapsed().as_secs_f64() < 1.0 {
        let t = Instant::now();
        value = f();
        best = best.min(t.elapsed().as_secs_f64());
    }
    (best, value)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse())
        .collect::<Result<_, _>>()?;
    let [dims, direct_max, logs @ ..] = args.as_slice() else {
        return Err("usage: time_l2_star DIMS DIRECT_MAX_LOG2 LOG2_N...".into());
    };
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    for &m in logs {
        let n = 1usize << m;
        let data = uniform(n * dims, 12345 + m as u64);
        let p = Points::new(&data, *dims)?;
        let (tf, vf) = pool.install(|| best(|| l2_star_fast(p).unwrap_or(f64::NAN)));
        if m <= *direct_max {
            let (td, vd) = pool.install(|| best(|| l2_star_direct(p).unwrap_or(f64::NAN)));
            let r = (vf - vd).abs() / vd;
            println!("{dims} {n} {tf:.6} {td:.6} {r:.2e}");
        } else {
            println!("{dims} {n} {tf:.6} - -");
        }
    }
    Ok(())
}
