//! Shared by the small firmware binaries in `src/bin/` (size report, panic proof,
//! instruction counts): a semihosting exit and a few output helpers that do not pull in
//! `core::fmt` (so they cost a few dozen bytes and contain no panic path), and, with the
//! `stack-probe` feature, a stack high-water mark.
//!
//! Included with `#[path = "../support.rs"] mod support;`; not every binary uses every item.
#![allow(dead_code)]

use cortex_m_semihosting::debug::{self, EXIT_FAILURE, EXIT_SUCCESS};
use cortex_m_semihosting::hio;

/// Ends the QEMU run with exit code 0 (`ok`) or 1.
pub fn exit(ok: bool) -> ! {
    debug::exit(if ok { EXIT_SUCCESS } else { EXIT_FAILURE });
    loop {
        cortex_m::asm::udf();
    }
}

/// Writes `bytes` to the host's stdout; false on failure.
pub fn write(bytes: &[u8]) -> bool {
    match hio::hstdout() {
        Ok(mut out) => out.write_all(bytes).is_ok(),
        Err(()) => false,
    }
}

/// `x` in decimal into the end of `buf`; returns the first digit's position. Indexing is
/// by iterator so that no bounds check (and no panic path) is generated.
pub fn decimal(mut x: u32, buf: &mut [u8; 10]) -> usize {
    let mut start = buf.len();
    for slot in buf.iter_mut().rev() {
        *slot = b'0' + (x % 10) as u8;
        x /= 10;
        start -= 1;
        if x == 0 {
            break;
        }
    }
    start
}

/// Writes `label`, a space, `x` in decimal and a newline; false on failure.
pub fn write_labeled(label: &[u8], x: u32) -> bool {
    let mut buf = [0u8; 10];
    let start = decimal(x, &mut buf);
    write(label) && write(b" ") && buf.get(start..).is_some_and(write) && write(b"\n")
}

/// Stack high-water mark: `paint` fills the free stack below the current stack pointer with
/// a pattern, `peak` finds the deepest word that no longer holds it. cortex-m-rt gives the
/// stack all RAM above `.bss` (`_stack_end` .. `_stack_start`), so this measures the real
/// use, including the frames of the reset handler and `main`.
#[cfg(feature = "stack-probe")]
pub mod stack {
    use core::ptr::{addr_of, addr_of_mut, read_volatile, write_volatile};

    const PAINT: u32 = 0x5AC3_3CA5;

    unsafe extern "C" {
        /// Lowest stack address (the end of `.bss`), from cortex-m-rt's `link.x`.
        static mut _stack_end: u32;
        /// Initial stack pointer (the top of RAM).
        static _stack_start: u32;
    }

    /// Paints `_stack_end .. sp`. Inlined into the caller, whose loop makes no calls, so
    /// nothing below `sp` is live while it runs.
    #[inline(always)]
    pub fn paint() {
        let sp = cortex_m::register::msp::read() as usize;
        let mut p = addr_of_mut!(_stack_end);
        while (p as usize) < sp {
            // SAFETY: `p` is word-aligned, in RAM, below the stack pointer: unused stack.
            unsafe {
                write_volatile(p, PAINT);
                p = p.add(1);
            }
        }
    }

    /// Bytes of stack used since the reset (at most), after `paint`.
    pub fn peak() -> u32 {
        let top = addr_of!(_stack_start) as usize;
        let mut p = addr_of!(_stack_end);
        while (p as usize) < top {
            // SAFETY: `p` is word-aligned and in RAM.
            if unsafe { read_volatile(p) } != PAINT {
                break;
            }
            p = p.wrapping_add(1);
        }
        (top - p as usize) as u32
    }
}

/// Without `stack-probe`: no painting, nothing reported.
#[cfg(not(feature = "stack-probe"))]
pub mod stack {
    #[inline(always)]
    pub fn paint() {}
}

/// Ends a size-report binary: with `stack-probe`, prints `stack <bytes>` first.
pub fn finish(ok: bool) -> ! {
    #[cfg(feature = "stack-probe")]
    let ok = ok && write_labeled(b"stack", stack::peak());
    exit(ok)
}
