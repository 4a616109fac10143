//! Writes `src/blue_noise/mask64.rs`, the 64×64 void-and-cluster mask as a static table
//! (`cargo run --release --features analysis --example gen_mask64 > src/blue_noise/mask64.rs`). The test
//! `mask::the_static_table_is_the_generated_mask` regenerates it and compares.

use qmckit::blue_noise::VoidAndCluster;
use qmckit::work::Budget;

fn main() -> Result<(), qmckit::Error> {
    let mask = VoidAndCluster::new(64, 64)?
        .seed(0)
        .generate(&Budget::DEFAULT)?;
    println!("{}", include_str!("mask64_header.txt").trim_end());
    println!("#[rustfmt::skip]");
    println!("pub static MASK64: [u16; 4096] = [");
    for row in mask.ranks().chunks(16) {
        let cells: Vec<String> = row.iter().map(|r| format!("{r}")).collect();
        println!("    {},", cells.join(", "));
    }
    println!("];");
    Ok(())
}
