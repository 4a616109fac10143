//! Times the exact star discrepancy (`star::dem::star_dem`) on the first `N` Sobol' points
//! in `d` dimensions, with no work limit, for the measured rows of `qmckit::analysis::star::dem`.
//!
//! Usage: `cargo run --release --features analysis --example time_dem -- DIMS N...`
//!
//! For each `N` prints `d N D* seconds`.

use qmckit::analysis::Points;
use qmckit::analysis::star::dem::star_dem;
use qmckit::work::Budget;
use qmckit::{Sampler, Sobol};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|s| s.parse())
        .collect::<Result<_, _>>()?;
    let Some((&d, sizes)) = args.split_first() else {
        return Err("usage: time_dem DIMS N...".into());
    };
    let sobol = Sobol::new(d)?;
    for &n in sizes {
        let mut values = vec![0f64; n * d];
        sobol.fill_as(0, &mut values)?;
        let points = Points::new(&values, d)?;
        let start = Instant::now();
        let value = star_dem(points, &Budget::UNLIMITED)?;
        println!("{d} {n} {value} {:.2}", start.elapsed().as_secs_f64());
    }
    Ok(())
}
