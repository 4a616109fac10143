//! The transport distance `W_2` to the uniform square of several 2D constructions, and the
//! running times of BNOT beside CCVT, one process (see `docs/blue-noise.md`).
//!
//! Usage: `cargo run --release --all-features --example transport_table -- N...` (default
//! 1024 4096). Each line: `construction n w2 w2*sqrt(6n)` (1 for the grid of cell centres)
//! for uniform random, jittered (one point in each of `k x k` cells, `n = k^2`), sobol
//! (unscrambled), ccvt, sot and bnot, then `time construction n seconds`.

use qmckit::analysis::Points;
use qmckit::analysis::transport::ot_distance;
use qmckit::blue_noise::{Bnot, Lloyd, Sot};
use qmckit::work::Budget;
use qmckit::{Independent, Sampler, Sobol};
use std::time::Instant;

fn main() -> Result<(), qmckit::Error> {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let sizes = if args.is_empty() {
        vec![1024, 4096]
    } else {
        args
    };
    let b = Budget::UNLIMITED;
    for &n in &sizes {
        let to_f64 = |v: Vec<u32>| v.into_iter().map(qmckit::bits::to_f64).collect::<Vec<_>>();
        let mut raw = vec![0u32; 2 * n];
        Independent::new(2, 1)?.fill(0, &mut raw)?;
        let white = to_f64(raw.clone());
        let k = (n as f64).sqrt().round() as usize;
        let jittered: Vec<f64> = (0..k * k)
            .flat_map(|i| {
                [
                    ((i % k) as f64 + white[2 * i]) / k as f64,
                    ((i / k) as f64 + white[2 * i + 1]) / k as f64,
                ]
            })
            .collect();
        Sobol::new(2)?.fill(0, &mut raw)?;
        let sobol = to_f64(raw.clone());
        let t = Instant::now();
        let ccvt = Lloyd::new(n as u64, 2)?
            .capacity_constrained(true)
            .seed(1)
            .generate(&b)?;
        let ccvt_s = t.elapsed().as_secs_f64();
        let sot = Sot::new(n as u64, 2)?.seed(1).generate(&b)?;
        let t = Instant::now();
        let bnot = Bnot::new(n as u64)?.seed(1).generate(&b)?;
        let bnot_s = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let _ = Bnot::new(n as u64)?.torus(true).seed(1).generate(&b)?;
        let torus_s = t.elapsed().as_secs_f64();
        let sets = [
            ("uniform", white),
            ("jittered", jittered),
            ("sobol", sobol),
            ("ccvt", ccvt.to_f64()),
            ("sot", sot.to_f64()),
            ("bnot", bnot.to_f64()),
        ];
        for (name, pts) in &sets {
            let m = pts.len() / 2;
            let w = ot_distance(Points::new(pts, 2)?, &b)?;
            println!("{name} {m} {w:.6e} {:.4}", w * (6.0 * m as f64).sqrt());
        }
        println!("time ccvt {n} {ccvt_s:.3}");
        println!("time bnot {n} {bnot_s:.3}");
        println!("time bnot-torus {n} {torus_s:.3}");
    }
    Ok(())
}
