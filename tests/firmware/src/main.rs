//! qmckit's no_std core on a Cortex-M under QEMU: prints the test vectors of
//! `vectors.rs` over semihosting, then exits QEMU with success (or, on any panic or write
//! failure, with failure). Built by `run.sh` for one board at a time (a `board-*` feature).
#![no_std]
#![no_main]

#[macro_use]
mod semihost;
mod vectors;

vector_firmware!(
    cortex_m_rt::entry,
    cortex_m_semihosting,
    cortex_m::asm::udf()
);
