//! Size report (b): 2D Sobol' with hash-based Owen scrambling through the public API:
//! `SobolDimension` (built as a `const`) and `FastOwen::scramble` for dimensions 0 and 1.
#![no_std]
#![no_main]

#[path = "../support.rs"]
mod support;

use core::hint::black_box;

use cortex_m_rt::entry;
use qmckit::randomize::FastOwen;
use qmckit::digital::sobol::SobolDimension;

const X: SobolDimension = match SobolDimension::new(0) {
    Ok(d) => d,
    Err(_) => panic!(),
};
const Y: SobolDimension = match SobolDimension::new(1) {
    Ok(d) => d,
    Err(_) => panic!(),
};

#[entry]
fn main() -> ! {
    support::stack::paint();
    let owen = FastOwen::new(black_box(0x5EED));
    let mut acc = 0u32;
    for i in 0..black_box(1000u32) {
        let i = black_box(i);
        acc ^= owen.scramble(X.sample(i), 0);
        acc ^= owen.scramble(Y.sample(i), 1);
    }
    black_box(acc);
    support::finish(true)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    support::exit(false)
}
