//! The text `defmt_check.sh` expects from the defmt firmware: the same lines
//! (`../../../src/defmt_lines.rs`) printed with `Debug`, which agrees with qmckit's derived
//! `defmt::Format` for these values.

/// One line, `{:?}` being `Debug` here (and `defmt::Format` in the firmware).
macro_rules! out {
    ($($t:tt)*) => { println!($($t)*) };
}

#[path = "../../../src/defmt_lines.rs"]
mod defmt_lines;

fn main() {
    let n = defmt_lines::log_all();
    println!("end {n:?}");
}
