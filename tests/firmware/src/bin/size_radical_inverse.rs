//! Size report (a): the radical inverse in base 3 only, built as a `const` (the README's
//! recipe), sampled at run-time indices.
#![no_std]
#![no_main]

#[path = "../support.rs"]
mod support;

use core::hint::black_box;

use cortex_m_rt::entry;
use qmckit::RadicalInverse;

const PHI3: RadicalInverse = match RadicalInverse::new(3) {
    Ok(r) => r,
    Err(_) => panic!(),
};

#[entry]
fn main() -> ! {
    support::stack::paint();
    let mut acc = 0u32;
    for i in 0..black_box(1000u32) {
        acc ^= PHI3.sample(black_box(i));
    }
    black_box(acc);
    support::finish(true)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    support::exit(false)
}
