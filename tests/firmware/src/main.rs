//! qmckit's no_std core on a Cortex-M under QEMU: prints the test vectors of
//! `vectors.rs` over semihosting, then exits QEMU with success (or, on any panic or write
//! failure, with failure). Built by `run.sh` for one board at a time (a `board-*` feature).
#![no_std]
#![no_main]

mod vectors;

use core::fmt::{self, Write};
use core::panic::PanicInfo;

use cortex_m_rt::entry;
use cortex_m_semihosting::debug::{self, EXIT_FAILURE, EXIT_SUCCESS};
use cortex_m_semihosting::hio::{self, HostStream};

/// A line-buffered semihosting stdout: one host call a line instead of one a fragment.
struct Semihost {
    stream: HostStream,
    buf: [u8; 256],
    len: usize,
}

impl Semihost {
    fn flush(&mut self) -> fmt::Result {
        let r = self
            .stream
            .write_all(&self.buf[..self.len])
            .map_err(|_| fmt::Error);
        self.len = 0;
        r
    }
}

impl Write for Semihost {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        for &byte in s.as_bytes() {
            if self.len == self.buf.len() {
                self.flush()?;
            }
            self.buf[self.len] = byte;
            self.len += 1;
            if byte == b'\n' {
                self.flush()?;
            }
        }
        Ok(())
    }
}

#[entry]
fn main() -> ! {
    let ok = match hio::hstdout() {
        Ok(stream) => {
            let mut out = Semihost {
                stream,
                buf: [0; 256],
                len: 0,
            };
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
