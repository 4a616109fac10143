//! A line buffer in front of a semihosting stream: one host call a line instead of one a
//! fragment (semihosting calls are slow under QEMU). Shared by the Cortex-M and RISC-V
//! vector firmware (`#[path]`-included); the sink is any `FnMut(&[u8]) -> bool` (true on
//! success), e.g. a `HostStream::write_all`.

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
