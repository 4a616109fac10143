//! What the Cortex-M and RISC-V vector firmware share (`#[path]`-included by both): a line
//! buffer in front of a semihosting stream (one host call a line instead of one a fragment;
//! semihosting calls are slow under QEMU), and `vector_firmware!`, which writes the entry
//! point and the panic handler for a semihosting crate (`cortex_m_semihosting` and
//! `riscv_semihosting` have the same `hio` and `debug` API).

use core::fmt::{self, Write};

pub struct LineBuffered<F: FnMut(&[u8]) -> bool> {
    sink: F,
    buf: [u8; 256],
    len: usize,
}

impl<F: FnMut(&[u8]) -> bool> LineBuffered<F> {
    pub fn new(sink: F) -> Self {
        LineBuffered {
            sink,
            buf: [0; 256],
            len: 0,
        }
    }

    /// Sends what is buffered.
    pub fn flush(&mut self) -> fmt::Result {
        let ok = match self.buf.get(..self.len) {
            Some(bytes) => (self.sink)(bytes),
            None => false,
        };
        self.len = 0;
        if ok { Ok(()) } else { Err(fmt::Error) }
    }
}

impl<F: FnMut(&[u8]) -> bool> Write for LineBuffered<F> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        for &byte in s.as_bytes() {
            if self.len == self.buf.len() {
                self.flush()?;
            }
            if let Some(slot) = self.buf.get_mut(self.len) {
                *slot = byte;
                self.len += 1;
            }
            if byte == b'\n' {
                self.flush()?;
            }
        }
        Ok(())
    }
}

/// The firmware's `main` (print `vectors::write_all` to semihosting stdout, exit 0 on
/// success) and its panic handler (message to stderr, exit 1), for the runtime's `entry`
/// attribute `$entry`, the semihosting crate `$sh` and an instruction `$halt` that stops.
macro_rules! vector_firmware {
    ($entry:path, $sh:ident, $halt:expr) => {
        #[$entry]
        fn main() -> ! {
            let ok = match $sh::hio::hstdout() {
                Ok(mut stream) => {
                    let mut out =
                        semihost::LineBuffered::new(|b: &[u8]| stream.write_all(b).is_ok());
                    vectors::write_all(&mut out).is_ok() && out.flush().is_ok()
                }
                Err(()) => false,
            };
            $sh::debug::exit(if ok {
                $sh::debug::EXIT_SUCCESS
            } else {
                $sh::debug::EXIT_FAILURE
            });
            loop {
                $halt;
            }
        }

        #[panic_handler]
        fn panic(info: &core::panic::PanicInfo) -> ! {
            use core::fmt::Write;
            if let Ok(mut err) = $sh::hio::hstderr() {
                let _ = writeln!(err, "firmware panic: {info}");
            }
            $sh::debug::exit($sh::debug::EXIT_FAILURE);
            loop {
                $halt;
            }
        }
    };
}
