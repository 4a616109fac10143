//! Times the periodogram of `qmckit::analysis::spectrum` (direct sums and NUFFT), for
//! `scripts/time_spectrum.py` (which times finufft and numpy on the same points).
//!
//! Usage: `cargo run --release --features analysis --example time_spectrum -- FILE K REPS TOLERANCE METHOD...`
//!
//! `FILE` holds the 2D points as whitespace-separated decimal numbers, row-major. Each
//! method (`direct`, `nufft`) runs `REPS` times in the current rayon pool (set
//! `RAYON_NUM_THREADS=1` for one thread); the output is one line `method best_seconds
//! max_power` per method.

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::{Method, periodogram_2d};
use qmckit::work::Budget;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [file, k, reps, tol, names @ ..] = args.as_slice() else {
        return Err("usage: time_spectrum FILE K REPS TOLERANCE METHOD...".into());
    };
    let (k, reps, tol): (usize, usize, f64) = (k.parse()?, reps.parse()?, tol.parse()?);
    let text = std::fs::read_to_string(file)?;
    let data = text
        .split_whitespace()
        .map(str::parse::<f64>)
        .collect::<Result<Vec<f64>, _>>()?;
    let p = Points::new(&data, 2)?;
    for name in names {
        let method = match name.as_str() {
            "direct" => Method::Direct,
            "nufft" => Method::Nufft,
            other => return Err(format!("unknown method {other}").into()),
        };
        let mut best = f64::INFINITY;
        let mut max = 0.0f64;
        for _ in 0..reps.max(1) {
            let t = Instant::now();
            let s = periodogram_2d(p, k, method, tol, &Budget::UNLIMITED)?;
            best = best.min(t.elapsed().as_secs_f64());
            max = s.iter().map(|(_, _, v)| v).fold(max, f64::max);
        }
        println!("{name} {best:.6} {max:.6e}");
    }
    Ok(())
}
