//! Times Thiémard's bounds (`star::thiemard::bounds`, no time limit) on the first `N`
//! Sobol' points or `N` uniform random points in `d` dimensions, and whether the default
//! budget accepts them, for calibrating `star::THIEMARD_RATE`.
//!
//! Usage: `cargo run --release --features analysis --example time_thiemard -- sobol|random DIMS DELTA N...`
//!
//! For each `N` prints `d N delta lower upper seconds accepted-by-default`.

use qmckit::analysis::Points;
use qmckit::analysis::star::thiemard::bounds;
use qmckit::work::Budget;
use qmckit::{Independent, Sampler, Sobol};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [kind, d, delta, sizes @ ..] = args.as_slice() else {
        return Err("usage: time_thiemard sobol|random DIMS DELTA N...".into());
    };
    let d: usize = d.parse()?;
    let delta: f64 = delta.parse()?;
    for n in sizes {
        let n: usize = n.parse()?;
        let mut values = vec![0f64; n * d];
        match kind.as_str() {
            "sobol" => Sobol::new(d)?.fill_as(0, &mut values)?,
            _ => Independent::new(d, 1)?.fill_as(0, &mut values)?,
        }
        let points = Points::new(&values, d)?;
        let accepted = bounds(points, delta, &Budget::DEFAULT).is_ok();
        let start = Instant::now();
        let b = bounds(points, delta, &Budget::UNLIMITED)?;
        println!(
            "{d} {n} {delta} {:.6} {:.6} {:.2} {accepted}",
            b.lower,
            b.upper,
            start.elapsed().as_secs_f64()
        );
    }
    Ok(())
}
