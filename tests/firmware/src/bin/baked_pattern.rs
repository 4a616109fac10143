//! Example for firmware authors: a sampling pattern that costs no start-up time and no RAM.
//!
//! - `PATTERN`: 64 points of 2D Sobol' with hash-based Owen scrambling, computed by the
//!   compiler (every qmckit call below is a `const fn`) and stored in flash as 512 bytes.
//!   Change the seed and rebuild for another scramble; a bad parameter is a build error.
//! - `buffer::points` (feature `heapless`): the same points computed at run time into a
//!   fixed-capacity `heapless::Vec` on the stack, for patterns whose seed is only known at
//!   run time.
//!
//! The program checks that both agree and that the pattern is a (0,6,2)-net (every
//! elementary interval of area 1/64 holds exactly one point), prints the points (the
//! integer `x / 2^32` and its `f32`), and exits 0 on success. `run.sh` runs it on every
//! board and requires the same output from all of them.
#![no_std]
#![no_main]

use core::fmt::Write;
use core::hint::black_box;

use cortex_m_rt::entry;
use cortex_m_semihosting::debug::{self, EXIT_FAILURE, EXIT_SUCCESS};
use cortex_m_semihosting::hio;
use qmckit::bits::to_f32;
use qmckit::buffer::points;
use qmckit::randomize::{FastOwen, Scrambled};
use qmckit::digital::sobol::{Sobol, SobolDimension};

const SEED: u64 = 0x5EED;
const OWEN: FastOwen = FastOwen::new(SEED);
const N: usize = 64;

/// 64 Owen-scrambled 2D Sobol' points, evaluated by rustc and placed in `.rodata`.
static PATTERN: [[u32; 2]; N] = {
    let (x, y) = match (SobolDimension::new(0), SobolDimension::new(1)) {
        (Ok(x), Ok(y)) => (x, y),
        _ => panic!("Sobol' dimensions 0 and 1 are always compiled in"),
    };
    let mut p = [[0u32; 2]; N];
    let mut i = 0;
    while i < N {
        p[i] = [
            OWEN.scramble(x.sample(i as u32), 0),
            OWEN.scramble(y.sample(i as u32), 1),
        ];
        i += 1;
    }
    p
};

/// Whether every elementary interval `[a/2^k, (a+1)/2^k) x [b/2^(6-k), (b+1)/2^(6-k))`
/// holds exactly one point: the (0,6,2)-net property, which Owen scrambling keeps.
fn is_net(p: &[[u32; 2]]) -> bool {
    (0..=6u32).all(|k| {
        let mut seen = 0u64; // one bit a cell: 64 cells
        for &[x, y] in p {
            let cx = if k == 0 { 0 } else { x >> (32 - k) };
            let cy = if k == 6 { 0 } else { y >> (32 - (6 - k)) };
            seen |= 1 << ((cx << (6 - k)) | cy);
        }
        seen == u64::MAX
    })
}

fn run<W: Write>(out: &mut W) -> Result<bool, core::fmt::Error> {
    // The same scramble at run time, into a stack buffer of capacity 64.
    let sampler = match Sobol::new(black_box(2)) {
        Ok(s) => Scrambled::new(s, FastOwen::new(black_box(SEED))),
        Err(_) => return Ok(false),
    };
    let buf = match points::<_, 2, N>(&sampler, black_box(0), N) {
        Ok(buf) => buf,
        Err(e) => {
            writeln!(out, "buffer error: {e}")?;
            return Ok(false);
        }
    };
    let pattern = black_box(&PATTERN);
    let same = buf.as_slice() == &pattern[..];
    let net = is_net(pattern);
    writeln!(
        out,
        "pattern {N} points, flash {} bytes",
        core::mem::size_of_val(pattern)
    )?;
    for (i, &[x, y]) in pattern.iter().enumerate() {
        writeln!(
            out,
            "{i:2} {x:10} {y:10} {:08x} {:08x}",
            to_f32(x).to_bits(),
            to_f32(y).to_bits()
        )?;
    }
    writeln!(out, "const == heapless buffer: {same}")?;
    writeln!(out, "(0,6,2)-net: {net}")?;
    Ok(same && net)
}

#[entry]
fn main() -> ! {
    let ok = match hio::hstdout() {
        Ok(mut out) => run(&mut out).unwrap_or(false),
        Err(()) => false,
    };
    debug::exit(if ok { EXIT_SUCCESS } else { EXIT_FAILURE });
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
