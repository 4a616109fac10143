//! Instructions per sample on Cortex-M, measured under QEMU with `-icount shift=0`.
//!
//! With `-icount shift=0,sleep=off` QEMU's virtual clock advances exactly 1 ns per guest
//! instruction executed, and SysTick (clocked by the core clock, `CLKSOURCE = 1`) counts
//! that virtual time: elapsed SysTick ticks are proportional to instructions executed.
//! The factor (instructions a tick: the board's core clock period in ns, e.g. 83.3 at
//! 12 MHz) is not assumed but calibrated here, with a hand-written two-instruction
//! `subs`/`bne` loop run for two lengths (the difference cancels the cost of reading the
//! timer). QEMU does not model the DWT cycle counter (checked at run time and printed),
//! and QEMU does not model pipeline timing anyway: these are instruction counts, not
//! cycles.
//!
//! Each workload runs `N` times in the same loop shape as an empty reference loop
//! (`black_box`ed index, XOR-accumulated result); the firmware prints raw tick counts and
//! `size_report.sh` turns them into instructions a sample, with and without the empty
//! loop's cost. Output lines: `dwt <0|1>`, `calib <iterations> <ticks>`, and
//! `work <name> <samples> <ticks>`.
#![no_std]
#![no_main]

use core::arch::asm;
use core::fmt::Write;
use core::hint::black_box;
use core::panic::PanicInfo;
use core::ptr::{read_volatile, write_volatile};

use cortex_m_rt::entry;
use cortex_m_semihosting::debug::{self, EXIT_FAILURE, EXIT_SUCCESS};
use cortex_m_semihosting::hio;
use qmckit::digital::sobol::OwenSobol;
use qmckit::randomize::FastOwen;
use qmckit::digital::sobol::{Sobol, SobolDimension, SobolTable};
use qmckit::{RadicalInverse, Sampler};

const SYST_CSR: *mut u32 = 0xE000_E010 as *mut u32;
const SYST_RVR: *mut u32 = 0xE000_E014 as *mut u32;
const SYST_CVR: *mut u32 = 0xE000_E018 as *mut u32;
const DEMCR: *mut u32 = 0xE000_EDFC as *mut u32;
const DWT_CTRL: *mut u32 = 0xE000_1000 as *mut u32;
const DWT_CYCCNT: *mut u32 = 0xE000_1004 as *mut u32;

/// Samples a workload: 4096 keeps the slowest one (~1000 instructions a sample on the M0)
/// inside SysTick's 24 bits at any clock QEMU uses.
const N: u32 = 4096;

fn systick_start() {
    // SAFETY: the SysTick registers of the Armv6-M/Armv7-M system control space.
    unsafe {
        write_volatile(SYST_CSR, 0);
        write_volatile(SYST_RVR, 0x00FF_FFFF);
        write_volatile(SYST_CVR, 0);
        write_volatile(SYST_CSR, 0b101); // CLKSOURCE = core clock, no interrupt, ENABLE
    }
}

#[inline(always)]
fn now() -> u32 {
    // SAFETY: SysTick's current-value register.
    unsafe { read_volatile(SYST_CVR) }
}

/// Ticks between two `now()` readings (SysTick counts down, 24 bits).
#[inline(always)]
fn elapsed(start: u32, end: u32) -> u32 {
    start.wrapping_sub(end) & 0x00FF_FFFF
}

/// Whether the DWT cycle counter counts (only on Armv7-M; QEMU 7.2 does not model it).
#[cfg(not(feature = "board-microbit"))]
fn dwt_counts() -> bool {
    // SAFETY: DEMCR and the DWT registers exist on every Armv7-M core; on QEMU they read
    // as zero (RAZ/WI) when not modelled.
    unsafe {
        write_volatile(DEMCR, read_volatile(DEMCR) | (1 << 24)); // TRCENA
        write_volatile(DWT_CYCCNT, 0);
        write_volatile(DWT_CTRL, read_volatile(DWT_CTRL) | 1); // CYCCNTENA
        let a = read_volatile(DWT_CYCCNT);
        for _ in 0..black_box(100u32) {
            cortex_m::asm::nop();
        }
        read_volatile(DWT_CYCCNT) != a
    }
}

#[cfg(feature = "board-microbit")]
fn dwt_counts() -> bool {
    false // Armv6-M has no DWT cycle counter.
}

/// Ticks of `n` iterations of a two-instruction loop (`subs`, `bne`).
#[inline(never)]
fn calibrate(n: u32) -> u32 {
    let start = now();
    // SAFETY: a counted loop on one register.
    unsafe {
        asm!(
            "2:",
            "subs {n}, #1",
            "bne 2b",
            n = inout(reg) n => _,
            options(nomem, nostack),
        );
    }
    elapsed(start, now())
}

/// Ticks of `N` calls of `f` on indices `0, step, 2 step, ...`, results XORed.
#[inline(always)]
fn run(step: u32, f: impl Fn(u32) -> u32) -> u32 {
    let mut acc = 0u32;
    let mut i = 0u32;
    let start = now();
    for _ in 0..N {
        acc ^= f(black_box(i));
        i = i.wrapping_add(step);
    }
    let end = now();
    black_box(acc);
    elapsed(start, end)
}

/// Like `run` for a batch fill of `pts` 2D points, `N / pts` times: ticks per `N` points.
#[inline(always)]
fn run_fill<const LEN: usize>(sobol: &Sobol) -> u32 {
    let mut buf = [0u32; LEN];
    let pts = (LEN / 2) as u32;
    let mut ok = true;
    let start = now();
    for block in 0..N / pts {
        ok &= Sampler::fill(sobol, black_box(block * pts), &mut buf).is_ok();
        black_box(&mut buf);
    }
    let end = now();
    black_box(ok);
    elapsed(start, end)
}

const PHI3: RadicalInverse = match RadicalInverse::new(3) {
    Ok(r) => r,
    Err(_) => panic!(),
};
const X: SobolDimension = match SobolDimension::new(0) {
    Ok(d) => d,
    Err(_) => panic!(),
};
const Y: SobolDimension = match SobolDimension::new(1) {
    Ok(d) => d,
    Err(_) => panic!(),
};
/// Byte tables (4 KiB a dimension) baked into flash.
static TX: SobolTable = SobolTable::new(X);
static TY: SobolTable = SobolTable::new(Y);
static OWEN_SOBOL4: OwenSobol = match OwenSobol::new(4, 0x5EED) {
    Ok(t) => t,
    Err(_) => panic!(),
};

/// 16-bit indices: `N` = 4096 samples spread over 0..65536.
const STEP16: u32 = 16;
/// 32-bit indices: a Weyl sequence over the whole range.
const STEP32: u32 = 0x9E37_79B9;

fn measure<W: Write>(out: &mut W) -> core::fmt::Result {
    systick_start();
    writeln!(out, "dwt {}", dwt_counts() as u32)?;
    for n in [20_000u32, 120_000] {
        writeln!(out, "calib {n} {}", calibrate(black_box(n)))?;
    }
    let owen = black_box(FastOwen::new(0x5EED));
    let sobol2 = match Sobol::new(black_box(2)) {
        Ok(s) => s,
        Err(_) => return Err(core::fmt::Error),
    };
    for (bits, step) in [(16u32, STEP16), (32, STEP32)] {
        let w = [
            ("empty-loop", run(step, |i| i)),
            ("radical-inverse-3", run(step, |i| PHI3.sample(i))),
            ("sobol-2d", run(step, |i| X.sample(i) ^ Y.sample(i))),
            ("sobol-2d-table", run(step, |i| TX.sample(i) ^ TY.sample(i))),
            (
                "sobol-2d-owen",
                run(step, |i| {
                    owen.scramble(X.sample(i), 0) ^ owen.scramble(Y.sample(i), 1)
                }),
            ),
            (
                "owen-sobol4-4d",
                run(step, |i| {
                    let p = OWEN_SOBOL4.sample4(i);
                    p[0] ^ p[1] ^ p[2] ^ p[3]
                }),
            ),
        ];
        for (name, ticks) in w {
            writeln!(out, "work {name}-{bits}bit {N} {ticks}")?;
        }
    }
    // Sequential: Sampler::fill of 2D Sobol' (natural order) in blocks of 64 points.
    writeln!(out, "work sobol-2d-fill64 {N} {}", run_fill::<128>(&sobol2))?;
    Ok(())
}

#[entry]
fn main() -> ! {
    let ok = match hio::hstdout() {
        Ok(mut out) => measure(&mut out).is_ok(),
        Err(()) => false,
    };
    debug::exit(if ok { EXIT_SUCCESS } else { EXIT_FAILURE });
    loop {
        cortex_m::asm::udf();
    }
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    debug::exit(EXIT_FAILURE);
    loop {
        cortex_m::asm::udf();
    }
}
