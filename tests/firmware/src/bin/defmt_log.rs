//! qmckit values logged through defmt (`defmt-semihosting`): `defmt_check.sh` runs this
//! under QEMU, decodes the binary log on the host with `defmt-print` and compares it with
//! the host's `Debug` rendering of the same values (`host/src/bin/defmt_expected.rs`).
#![no_std]
#![no_main]

use defmt_semihosting as _; // the global logger

/// One log line: `defmt::println!` (no level, never filtered out).
macro_rules! out {
    ($($t:tt)*) => { defmt::println!($($t)*) };
}

#[path = "../defmt_lines.rs"]
mod defmt_lines;

use cortex_m_rt::entry;
use cortex_m_semihosting::debug::{self, EXIT_FAILURE, EXIT_SUCCESS};

#[entry]
fn main() -> ! {
    let n = defmt_lines::log_all();
    defmt::println!("end {:?}", n);
    debug::exit(EXIT_SUCCESS);
    loop {
        cortex_m::asm::udf();
    }
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    debug::exit(EXIT_FAILURE);
    loop {
        cortex_m::asm::udf();
    }
}
