//! Size report baseline: cortex-m-rt's reset handler and vector table, and a semihosting
//! exit — everything the `size-*` binaries share. `size_report.sh` subtracts its flash and
//! RAM from theirs, so what remains is the cost of the library calls.
#![no_std]
#![no_main]

#[path = "../support.rs"]
mod support;

use core::hint::black_box;

use cortex_m_rt::entry;

#[entry]
fn main() -> ! {
    support::stack::paint();
    // The same loop shape as the other size binaries, with nothing in it.
    let mut acc = 0u32;
    for i in 0..black_box(1000u32) {
        acc ^= black_box(i);
    }
    black_box(acc);
    support::finish(true)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    support::exit(false)
}
