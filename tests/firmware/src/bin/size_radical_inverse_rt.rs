//! Size report (a'): the radical inverse with its base chosen at run time
//! (`RadicalInverse::new` in the firmware, the general path of `sample`).
#![no_std]
#![no_main]

#[path = "../support.rs"]
mod support;

use core::hint::black_box;

use cortex_m_rt::entry;
use qmckit::RadicalInverse;

#[entry]
fn main() -> ! {
    support::stack::paint();
    let ok = match RadicalInverse::new(black_box(3)) {
        Ok(phi) => {
            let mut acc = 0u32;
            for i in 0..black_box(1000u32) {
                acc ^= phi.sample(black_box(i));
            }
            black_box(acc);
            true
        }
        Err(_) => false,
    };
    support::finish(ok)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    support::exit(false)
}
