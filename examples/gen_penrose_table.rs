//! Writes `tables/penrose_corrections.rs`, the correction table of Penrose-tiling sampling,
//! by the optimizer of `qmckit::blue_noise::penrose_train` (Lloyd relaxation in the
//! leaves' frames, averaged by structural class):
//! `cargo run --release --features analysis --example gen_penrose_table > tables/penrose_corrections.rs`.
//! The energy of each iteration (mean squared Lloyd displacement over the squared
//! hexagonal spacing) goes to stderr.

use qmckit::blue_noise::penrose_train::{table_source, train};
use qmckit::work::Budget;

fn main() -> Result<(), qmckit::Error> {
    let trained = train(4096, 40, 6, &Budget::seconds(7200.0)?)?;
    for (i, e) in trained.energy.iter().enumerate() {
        eprintln!("iteration {i}: energy {e:.5}");
    }
    print!("{}", table_source(&trained.table));
    Ok(())
}
