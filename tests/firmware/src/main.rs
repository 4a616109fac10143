//! qmckit's no_std core on a Cortex-M under QEMU: prints the test vectors of
//! `vectors.rs` over semihosting, then exits QEMU with success (or, on any panic or write
//! failure, with failure). Built by `run.sh` for one board at a time (a `board-*` feature).
#![no_std]
#![no_main]

mod line_buffer;
mod vectors;

use core::fmt::Write;
use core::panic::PanicInfo;

use cortex_m_rt::entry;
use cortex_m_semihosting::debug::{self, EXIT_FAILURE, EXIT_SUCCESS};
use cortex_m_semihosting::hio;

#[entry]
fn main() -> ! {
    let ok = match hio::hstdout() {
        Ok(mut stream) => {
            let mut out = line_buffer::LineBuffered::new(|b: &[u8]| stream.write_all(b).is_ok());
            vectors::write_all(&mut out).is_ok() && out.flush().is_ok()
        }
        Err(()) => false,
    };
    debug::exit(if ok { EXIT_SUCCESS } else { EXIT_FAILURE });
    loop {
        cortex_m::asm::udf();
    }
}

#[panic_handler]
fn panic(info: &PanicInfo) -> ! {
    if let Ok(mut err) = hio::hstderr() {
        let _ = writeln!(err, "firmware panic: {info}");
    }
    debug::exit(EXIT_FAILURE);
    loop {
        cortex_m::asm::udf();
    }
}
