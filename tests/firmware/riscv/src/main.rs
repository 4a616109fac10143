//! qmckit's no_std core on RISC-V (riscv32imac) under QEMU `virt`: prints the test vectors
//! of `vectors.rs` over RISC-V semihosting, then exits QEMU with success (or, on any panic
//! or write failure, with failure). `run.sh` diffs the output with the host's.
#![no_std]
#![no_main]

#[path = "../../src/line_buffer.rs"]
mod line_buffer;
#[path = "../../src/vectors.rs"]
mod vectors;

use core::fmt::Write;
use core::panic::PanicInfo;

use riscv_rt::entry;
use riscv_semihosting::debug::{self, EXIT_FAILURE, EXIT_SUCCESS};
use riscv_semihosting::hio;

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
        riscv::asm::wfi();
    }
}

#[panic_handler]
fn panic(info: &PanicInfo) -> ! {
    if let Ok(mut err) = hio::hstderr() {
        let _ = writeln!(err, "firmware panic: {info}");
    }
    debug::exit(EXIT_FAILURE);
    loop {
        riscv::asm::wfi();
    }
}
