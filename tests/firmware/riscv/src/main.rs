//! qmckit's no_std core on RISC-V (riscv32imac) under QEMU `virt`: prints the test vectors
//! of `vectors.rs` over RISC-V semihosting, then exits QEMU with success (or, on any panic
//! or write failure, with failure). `run.sh` diffs the output with the host's.
#![no_std]
#![no_main]

#[macro_use]
#[path = "../../src/semihost.rs"]
mod semihost;
#[path = "../../src/vectors.rs"]
mod vectors;

vector_firmware!(riscv_rt::entry, riscv_semihosting, riscv::asm::wfi());
