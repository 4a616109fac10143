//! Size report (b'): the same 2D Owen-scrambled Sobol' as `size_sobol_owen2.rs`, but with
//! the two dimensions' direction numbers copied into firmware `const`s at compile time and
//! multiplied by `bits::gf2_mul` (the function `SobolDimension::sample` calls, so the same
//! bits): only 2 x 128 bytes of directions are linked instead of the whole table.
#![no_std]
#![no_main]

#[path = "../support.rs"]
mod support;

use core::hint::black_box;

use cortex_m_rt::entry;
use qmckit::bits::gf2_mul;
use qmckit::randomize::FastOwen;
use qmckit::digital::sobol::directions;

const VX: [u32; 32] = match directions(0) {
    Ok(v) => *v,
    Err(_) => panic!(),
};
const VY: [u32; 32] = match directions(1) {
    Ok(v) => *v,
    Err(_) => panic!(),
};
static V: [[u32; 32]; 2] = [VX, VY];

#[entry]
fn main() -> ! {
    support::stack::paint();
    let owen = FastOwen::new(black_box(0x5EED));
    let mut acc = 0u32;
    for i in 0..black_box(1000u32) {
        let i = black_box(i);
        acc ^= owen.scramble(gf2_mul(&V[0], i), 0);
        acc ^= owen.scramble(gf2_mul(&V[1], i), 1);
    }
    black_box(acc);
    support::finish(true)
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    support::exit(false)
}
