//! Size report (c): Sobol' at a run-time dimension, so the whole direction-number table
//! (`SOBOL_MAX_DIMS` x 128 bytes: 64 by default, 1024 with the `sobol-dims-1024` feature)
//! is linked.
#![no_std]
#![no_main]

#[path = "../support.rs"]
mod support;

use core::hint::black_box;

use cortex_m_rt::entry;
use qmckit::SOBOL_MAX_DIMS;
use qmckit::digital::sobol::SobolDimension;

#[entry]
fn main() -> ! {
    support::stack::paint();
    let mut acc = 0u32;
    let mut ok = true;
    for i in 0..black_box(1000u32) {
        let dim = black_box(i as usize % SOBOL_MAX_DIMS);
        match SobolDimension::new(dim) {
            Ok(d) => acc ^= d.sample(black_box(i)),
            Err(_) => ok = false,
        }
    }
    black_box(acc);
    support::finish(ok)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    support::exit(false)
}
