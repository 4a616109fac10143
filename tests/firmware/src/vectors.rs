//! The test vectors, written as plain text lines through any `core::fmt::Write` sink.
//!
//! This one file is compiled twice: into the firmware (`src/main.rs`, sink = semihosting,
//! run under QEMU on Cortex-M0/M3/M4F) and into the host generator (`host/src/main.rs`,
//! sink = stdout). `run.sh` diffs the two outputs, so both sides print the same list by
//! construction. Every line is a pure function of qmckit's public API: nothing here may
//! depend on the platform (no `size_of`, no pointer widths, no float formatting; floats
//! are printed as their bits).
//!
//! Inputs go through `black_box` so the target itself computes the values: without it
//! LLVM could fold calls with constant arguments at compile time, on the build machine.

use core::fmt::{self, Write};
use core::hint::black_box;

#[path = "pixel_vectors.rs"]
mod pixel_vectors;

use qmckit::bits;
use qmckit::hash;
use qmckit::digital::sobol::OwenSobol;
use qmckit::randomize::digits::DigitScramble;
use qmckit::randomize::shuffle::Shuffled;
use qmckit::randomize::{
    CranleyPatterson, DigitalShift, FastOwen, Lms, ExactOwen, OwenHash, Randomizer, Scrambled,
};
use qmckit::digital::sobol::{Order, Sobol, SobolDimension, SobolTable};
use qmckit::{
    Error, HALTON_MAX_DIMS, Halton, Hammersley, Independent, Jitter, LarcherPillichshammer,
    LatinHypercube, RadicalInverse, Sampler, Stratified, VanDerCorput,
};

/// Bases of the radical-inverse table: small primes, a composite-free large prime (the
/// 1024th prime, Halton's last base) and 65537 (> 2^16: only two digits of a u32 index).
const RI_BASES: [u32; 7] = [2, 3, 5, 7, 31, 8161, 65537];

/// Indices of the radical-inverse table: the edges of the `u32` range, carries in base 3
/// (2186 = 3^7 - 1, 2187 = 3^7), and a few arbitrary ones.
const RI_INDICES: [u32; 14] = [
    0,
    1,
    2,
    3,
    1000,
    2186,
    2187,
    65535,
    65536,
    123_456_789,
    2_147_483_648,
    3_735_928_559,
    4_294_967_294,
    4_294_967_295,
];

/// An order-sensitive digest of a stream of `u32`s: count, wrapping sum, xor, and a 64-bit
/// FNV-style hash (one multiply a word; 64-bit multiplies are library calls on Cortex-M0).
struct Digest {
    n: u32,
    sum: u64,
    xor: u32,
    hash: u64,
}

impl Digest {
    const fn new() -> Self {
        Digest {
            n: 0,
            sum: 0,
            xor: 0,
            hash: 0xCBF2_9CE4_8422_2325,
        }
    }

    fn push(&mut self, x: u32) {
        self.n = self.n.wrapping_add(1);
        self.sum = self.sum.wrapping_add(x as u64);
        self.xor ^= x;
        self.hash = (self.hash ^ x as u64).wrapping_mul(0x0000_0100_0000_01B3);
    }

    fn push_all(&mut self, xs: &[u32]) {
        for &x in xs {
            self.push(x);
        }
    }
}

impl fmt::Display for Digest {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "n={} sum={} xor={:08x} h={:016x}",
            self.n, self.sum, self.xor, self.hash
        )
    }
}

/// Prints `Ok(value)` as the value and an error as `err <Display>`.
struct Res<T>(Result<T, Error>);

impl<T: fmt::Display> fmt::Display for Res<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Ok(v) => write!(f, "{v}"),
            Err(e) => write!(f, "err {e}"),
        }
    }
}

/// A fixed-size text buffer: proves `Error`'s `Display` needs no allocation.
struct FixedBuf {
    buf: [u8; 128],
    len: usize,
}

impl Write for FixedBuf {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        let end = self.len + s.len();
        if end > self.buf.len() {
            return Err(fmt::Error);
        }
        self.buf[self.len..end].copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

impl FixedBuf {
    fn as_str(&self) -> &str {
        core::str::from_utf8(&self.buf[..self.len]).unwrap_or("<invalid utf-8>")
    }
}

/// Prints one error line: `error <what> len=<bytes> <message>`, formatted first into a
/// 128-byte stack buffer.
fn error_line<W: Write, T>(out: &mut W, what: &str, r: Result<T, Error>) -> fmt::Result {
    match r {
        Ok(_) => writeln!(out, "error {what} unexpectedly Ok"),
        Err(e) => {
            let mut b = FixedBuf {
                buf: [0; 128],
                len: 0,
            };
            match write!(b, "{e}") {
                Ok(()) => writeln!(out, "error {what} len={} {}", b.len, b.as_str()),
                Err(_) => writeln!(out, "error {what} does not fit 128 bytes"),
            }
        }
    }
}

/// A compile-time pattern: 16 points of the 3D Halton sequence, evaluated by rustc.
const H3: Halton = match Halton::new(3) {
    Ok(h) => h,
    Err(_) => panic!(),
};
const CONST_HALTON: [[u32; 3]; 16] = {
    let mut p = [[0u32; 3]; 16];
    let mut i = 0;
    while i < 16 {
        p[i] = match (
            H3.sample(i as u32, 0),
            H3.sample(i as u32, 1),
            H3.sample(i as u32, 2),
        ) {
            (Ok(x), Ok(y), Ok(z)) => [x, y, z],
            _ => panic!(),
        };
        i += 1;
    }
    p
};

/// The README's flash pattern: the 64-point LP net with a base-3 third coordinate.
const PHI3: RadicalInverse = match RadicalInverse::new(3) {
    Ok(r) => r,
    Err(_) => panic!(),
};
static CONST_LP: [[u32; 3]; 64] = {
    let lp = match LarcherPillichshammer::new(6) {
        Ok(n) => n,
        Err(_) => panic!(),
    };
    let mut p = [[0u32; 3]; 64];
    let mut i = 0;
    while i < 64 {
        p[i] = match (lp.sample(i as u32, 0), lp.sample(i as u32, 1)) {
            (Ok(x), Ok(y)) => [x, y, PHI3.sample(i as u32)],
            _ => panic!(),
        };
        i += 1;
    }
    p
};

/// Writes every vector line, then `end <lines>`.
pub fn write_all<W: Write>(out: &mut W) -> fmt::Result {
    let mut lines = Counter { inner: out, n: 0 };
    radical_inverse(&mut lines)?;
    sequential(&mut lines)?;
    halton(&mut lines)?;
    hammersley(&mut lines)?;
    larcher_pillichshammer(&mut lines)?;
    van_der_corput(&mut lines)?;
    bit_helpers(&mut lines)?;
    randomized(&mut lines)?;
    sobol(&mut lines)?;
    scramblers(&mut lines)?;
    const_patterns(&mut lines)?;
    warps(&mut lines)?;
    errors(&mut lines)?;
    pixel_vectors::pixel(&mut lines)?;
    pixel_vectors::pmj(&mut lines)?;
    let n = lines.n;
    writeln!(lines.inner, "end {n}")
}

/// Counts the lines written through it.
struct Counter<'a, W: Write> {
    inner: &'a mut W,
    n: u32,
}

impl<W: Write> Write for Counter<'_, W> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        self.n += s.bytes().filter(|&c| c == b'\n').count() as u32;
        self.inner.write_str(s)
    }
}

fn radical_inverse<W: Write>(out: &mut W) -> fmt::Result {
    for &base in &RI_BASES {
        let ri = match RadicalInverse::new(black_box(base)) {
            Ok(ri) => ri,
            Err(e) => return writeln!(out, "ri {base} err {e}"),
        };
        writeln!(out, "ri_digits {base} {}", ri.digits())?;
        for &i in &RI_INDICES {
            writeln!(out, "ri {base} {i} {}", ri.sample(black_box(i)))?;
        }
        // Inversion of the first values with the largest invertible digit count.
        let max = match ri.inverse(0, 99) {
            Err(Error::TooManyDigits { max, .. }) => max,
            _ => 0,
        };
        for i in [0u32, 1, 2, 1000, 65535] {
            let digits = max;
            let x = ri.sample(black_box(i));
            writeln!(
                out,
                "ri_inv {base} {i} {digits} {}",
                Res(ri.inverse(x, digits))
            )?;
        }
    }
    Ok(())
}

fn sequential<W: Write>(out: &mut W) -> fmt::Result {
    const COUNT: u32 = 3000;
    for &base in &[2u32, 3, 5, 7, 31, 8161, 65537] {
        let ri = match RadicalInverse::new(black_box(base)) {
            Ok(ri) => ri,
            Err(e) => return writeln!(out, "seq {base} err {e}"),
        };
        for &start in &[0u32, 12_345, 531_441 - 1500, u32::MAX - (COUNT - 1)] {
            let mut d = Digest::new();
            let mut mismatches = 0u32;
            for (k, x) in ri
                .iter_from(black_box(start))
                .take(COUNT as usize)
                .enumerate()
            {
                d.push(x);
                if x != ri.sample(start.wrapping_add(k as u32)) {
                    mismatches += 1;
                }
            }
            writeln!(out, "seq {base} {start} {d} mismatches={mismatches}")?;
        }
        // fill (sequential fast path) over the same first block.
        let mut buf = [0u32; 500];
        let r = ri.fill(black_box(77), &mut buf);
        let mut d = Digest::new();
        d.push_all(&buf);
        writeln!(out, "fill {base} 77 {} {d}", r.is_ok())?;
        // The iterator stops after index u32::MAX.
        writeln!(
            out,
            "seq_tail {base} {}",
            ri.iter_from(black_box(u32::MAX - 4)).count()
        )?;
    }
    Ok(())
}

fn halton<W: Write>(out: &mut W) -> fmt::Result {
    let h = match Halton::new(black_box(8)) {
        Ok(h) => h,
        Err(e) => return writeln!(out, "halton err {e}"),
    };
    // Random access, 64 points.
    let mut d = Digest::new();
    for i in 0..black_box(64u32) {
        for dim in 0..8 {
            d.push(h.sample(i, dim).unwrap_or(u32::MAX));
        }
    }
    writeln!(out, "halton8 sample 0..64 {d}")?;
    // Sequential paths: Sampler::fill and the point iterator.
    let mut buf = [0u32; 64 * 8];
    let r = Sampler::fill(&h, black_box(0), &mut buf);
    let mut d = Digest::new();
    d.push_all(&buf);
    writeln!(out, "halton8 fill 0..64 {} {d}", r.is_ok())?;
    let mut d = Digest::new();
    match h.points::<8>(black_box(0)) {
        Ok(it) => {
            for p in it.take(64) {
                d.push_all(&p);
            }
            writeln!(out, "halton8 points 0..64 {d}")?;
        }
        Err(e) => writeln!(out, "halton8 points err {e}")?,
    }
    for i in [0u32, 1, 2, 3, 17, 63] {
        let mut p = [0u32; 8];
        let r = h.point(black_box(i), &mut p);
        writeln!(
            out,
            "halton8 {i} {} {} {} {} {} {} {} {} {}",
            r.is_ok(),
            p[0],
            p[1],
            p[2],
            p[3],
            p[4],
            p[5],
            p[6],
            p[7]
        )?;
    }
    // The far end of the prime table, through a run-time dimension.
    let big = Halton::new(black_box(HALTON_MAX_DIMS));
    if let Ok(big) = big {
        for dim in [100usize, 511, 1023] {
            let p = qmckit::radical_inverse::halton::prime(dim).unwrap_or(0);
            for i in [1u32, 8161, 4_000_000_000] {
                writeln!(
                    out,
                    "halton_dim {dim} p={p} {i} {}",
                    Res(big.sample(black_box(i), black_box(dim)))
                )?;
            }
        }
    }
    // A block far into the sequence, via fill.
    let mut buf = [0u32; 100 * 8];
    let r = Sampler::fill(&h, black_box(1_000_000_000), &mut buf);
    let mut d = Digest::new();
    d.push_all(&buf);
    writeln!(out, "halton8 fill 1e9.. {} {d}", r.is_ok())
}

fn hammersley<W: Write>(out: &mut W) -> fmt::Result {
    // Power of two (first coordinate a shift) and not (an exact 64-bit division).
    for &(n, dims) in &[(64u64, 3usize), (100, 4), (1 << 32, 2)] {
        let h = match Hammersley::new(black_box(n), black_box(dims)) {
            Ok(h) => h,
            Err(e) => {
                writeln!(out, "hammersley {n} {dims} err {e}")?;
                continue;
            }
        };
        let count = n.min(64) as u32;
        let mut d = Digest::new();
        for i in 0..count {
            for dim in 0..dims {
                d.push(h.sample(black_box(i), dim).unwrap_or(u32::MAX));
            }
        }
        writeln!(out, "hammersley {n} {dims} sample 0..{count} {d}")?;
        let mut buf = [0u32; 64 * 4];
        let len = count as usize * dims;
        let r = Sampler::fill(&h, black_box(0), &mut buf[..len]);
        let mut d = Digest::new();
        d.push_all(&buf[..len]);
        writeln!(
            out,
            "hammersley {n} {dims} fill 0..{count} {} {d}",
            r.is_ok()
        )?;
        for i in [1u32, 3, 37, count - 1] {
            write!(out, "hammersley {n} {dims} {i}")?;
            for dim in 0..dims {
                write!(out, " {}", Res(h.sample(black_box(i), dim)))?;
            }
            writeln!(out)?;
        }
    }
    Ok(())
}

fn larcher_pillichshammer<W: Write>(out: &mut W) -> fmt::Result {
    let lp = match LarcherPillichshammer::new(black_box(6)) {
        Ok(lp) => lp,
        Err(e) => return writeln!(out, "lp err {e}"),
    };
    let mut d = Digest::new();
    for i in 0..64 {
        for dim in 0..2 {
            d.push(lp.sample(black_box(i), dim).unwrap_or(u32::MAX));
        }
    }
    writeln!(out, "lp6 sample 0..64 {d}")?;
    let mut buf = [0u32; 128];
    let r = Sampler::fill(&lp, 0, &mut buf);
    let mut d = Digest::new();
    d.push_all(&buf);
    writeln!(out, "lp6 fill 0..64 {} {d}", r.is_ok())?;
    for i in [0u32, 1, 2, 3, 21, 42, 63] {
        writeln!(
            out,
            "lp6 {i} {} {}",
            Res(lp.sample(black_box(i), 0)),
            Res(lp.sample(black_box(i), 1))
        )?;
    }
    for i in [64u32, 123_456_789, u32::MAX] {
        writeln!(out, "lp_y {i} {}", LarcherPillichshammer::y(black_box(i)))?;
    }
    match LarcherPillichshammer::with_points(black_box(1 << 32)) {
        Ok(lp) => writeln!(
            out,
            "lp32 m={} {} {}",
            lp.m(),
            Res(lp.sample(black_box(u32::MAX), 0)),
            Res(lp.sample(black_box(u32::MAX), 1))
        ),
        Err(e) => writeln!(out, "lp32 err {e}"),
    }
}

fn van_der_corput<W: Write>(out: &mut W) -> fmt::Result {
    for &base in &[2u32, 3, 10] {
        let v = match VanDerCorput::new(black_box(base)) {
            Ok(v) => v,
            Err(e) => {
                writeln!(out, "vdc {base} err {e}")?;
                continue;
            }
        };
        write!(out, "vdc {base} 0..8")?;
        for i in 0..8 {
            write!(out, " {}", v.value(black_box(i)))?;
        }
        writeln!(out)?;
        let mut buf = [0u32; 1000];
        let r = Sampler::fill(&v, black_box(999_000), &mut buf);
        let mut d = Digest::new();
        d.push_all(&buf);
        writeln!(out, "vdc {base} fill 999000.. {} {d}", r.is_ok())?;
    }
    Ok(())
}

fn bit_helpers<W: Write>(out: &mut W) -> fmt::Result {
    const INPUTS: [u32; 14] = [
        0,
        1,
        0xFF,
        0x00FF_FFFF,
        0x0100_0000,
        0x0100_0001,
        0x0123_4567,
        0x1234_5678,
        0x8000_0000,
        0x8000_00FF,
        0xFFFF_FF7F,
        0xFFFF_FF80,
        0xFFFF_FFFE,
        0xFFFF_FFFF,
    ];
    for &x in &INPUTS {
        let x = black_box(x);
        writeln!(
            out,
            "bits {x:08x} f32={:08x} f64={:016x} rev={:08x} gray={:08x} ginv={:08x}",
            bits::to_f32(x).to_bits(),
            bits::to_f64(x).to_bits(),
            bits::reverse_bits(x),
            bits::gray(x),
            bits::gray_inverse(x)
        )?;
    }
    // A sweep of to_f32 (the soft-float path on M0/M3, the FPU on M4F) over 2^16 inputs
    // spread over the whole range, with every exponent.
    let mut d = Digest::new();
    let mut x = black_box(0x9E37_79B9u32);
    for k in 0..65_536u32 {
        d.push(bits::to_f32(x >> (k & 31)).to_bits());
        x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    }
    writeln!(out, "to_f32 sweep {d}")?;
    let mut d = Digest::new();
    for i in 0..4096u32 {
        let i = black_box(i.wrapping_mul(0x0101_0101));
        d.push(bits::gray(i));
        d.push(bits::gray_inverse(i));
    }
    writeln!(out, "gray sweep {d}")?;
    for &(num, den) in &[
        (1u64, 3u64),
        (3, 4),
        (99, 100),
        (4_294_967_295, 4_294_967_296),
    ] {
        writeln!(
            out,
            "fraction {num}/{den} {}",
            bits::fraction(black_box(num), black_box(den))
        )?;
    }
    for &(cell, n, u) in &[
        (0u64, 3u64, 0u32),
        (1, 3, 0),
        (2, 3, u32::MAX),
        (5, 7, 1 << 31),
    ] {
        writeln!(
            out,
            "in_cell {cell} {n} {u} {}",
            bits::in_cell(black_box(cell), black_box(n), black_box(u))
        )?;
    }
    Ok(())
}

fn randomized<W: Write>(out: &mut W) -> fmt::Result {
    for x in [0u64, 1, 0xDEAD_BEEF_CAFE_F00D] {
        writeln!(out, "mix64 {x:016x} {:016x}", hash::mix64(black_box(x)))?;
    }
    let mut d = Digest::new();
    for i in 0..1000 {
        d.push(hash::permute(black_box(i), 1000, 42));
    }
    writeln!(out, "permute 1000 {d}")?;
    if let Ok(s) = Independent::new(black_box(3), black_box(2024)) {
        let mut d = Digest::new();
        for i in 0..256u32 {
            for dim in 0..3 {
                d.push(s.sample(black_box(i), dim).unwrap_or(u32::MAX));
            }
        }
        writeln!(out, "independent 3 seed=2024 {d}")?;
    }
    for jitter in [Jitter::Center, Jitter::Random(7)] {
        match Stratified::new(&[8, 4, 3], jitter) {
            Ok(s) => {
                let mut buf = [0u32; 96 * 3];
                let r = Sampler::fill(&s, 0, &mut buf);
                let mut d = Digest::new();
                d.push_all(&buf);
                writeln!(out, "stratified 8x4x3 {jitter:?} {} {d}", r.is_ok())?;
            }
            Err(e) => writeln!(out, "stratified err {e}")?,
        }
    }
    match LatinHypercube::new(black_box(100), 3, black_box(99)) {
        Ok(l) => {
            let mut buf = [0u32; 100 * 3];
            let r = Sampler::fill(&l, 0, &mut buf);
            let mut d = Digest::new();
            d.push_all(&buf);
            writeln!(out, "latin 100 3 seed=99 {} {d}", r.is_ok())
        }
        Err(e) => writeln!(out, "latin err {e}"),
    }
}

/// Byte tables of Sobol' dimension 1, built by the compiler and stored in flash.
static SOBOL_TABLE_1: SobolTable = SobolTable::new(match SobolDimension::new(1) {
    Ok(d) => d,
    Err(_) => panic!(),
});

/// Owen-scrambled Sobol' (the 16 KiB of interleaved tables are a shared static in flash).
static OWEN_SOBOL4: OwenSobol = match OwenSobol::new(4, 0x5EED) {
    Ok(t) => t,
    Err(_) => panic!(),
};

fn sobol<W: Write>(out: &mut W) -> fmt::Result {
    let mut d4 = Digest::new();
    let mut df = Digest::new();
    for k in 0..512u32 {
        let i = black_box(k.wrapping_mul(2_654_435_761));
        for x in OWEN_SOBOL4.sample4(i) {
            d4.push(x);
        }
        let mut f = [[0f32; 4]; 1];
        if let Err(e) = OWEN_SOBOL4.fill_f32(&[i], &mut f) {
            return writeln!(out, "owen_sobol4_f32 err {e}");
        }
        for x in f[0] {
            df.push(x.to_bits());
        }
    }
    writeln!(out, "owen_sobol4 512 {d4}")?;
    writeln!(out, "owen_sobol4_f32 512 {df}")?;
    for dim in 0..8usize {
        let Ok(d) = SobolDimension::new(black_box(dim)) else {
            return writeln!(out, "sobol dim {dim} missing");
        };
        for &i in &RI_INDICES {
            writeln!(out, "sobol {dim} {i} {}", d.sample(black_box(i)))?;
        }
    }
    for &i in &RI_INDICES {
        let d = SobolDimension::new(1).map(|d| d.sample(i)).unwrap_or(0);
        writeln!(
            out,
            "sobol_table 1 {i} {} {}",
            SOBOL_TABLE_1.sample(black_box(i)),
            d
        )?;
    }
    for order in [Order::Natural, Order::Gray] {
        match Sobol::with_order(black_box(8), order) {
            Ok(s) => {
                // 64-point blocks: the Cortex-M0 board has 16 KiB of RAM.
                let mut buf = [0u32; 64 * 8];
                let mut d = Digest::new();
                for block in 0..16u32 {
                    let r = Sampler::fill(&s, black_box(block * 64), &mut buf);
                    d.push_all(&buf);
                    d.push(r.is_ok() as u32);
                }
                writeln!(out, "sobol_fill 8 {order:?} 1024 {d}")?;
            }
            Err(e) => writeln!(out, "sobol err {e}")?,
        }
    }
    writeln!(out, "sobol_max_dims {}", qmckit::SOBOL_MAX_DIMS)
}

/// Warp inputs: 256 Owen-scrambled 2D Sobol' points and the corners of the unit square
/// (0 and the largest 0.32 fraction below 1).
fn warp_inputs() -> impl Iterator<Item = [u32; 2]> {
    let owen = FastOwen::new(black_box(0x3A7B));
    let sobol = (0..256u32).map(move |i| {
        let i = black_box(i);
        let x = SobolDimension::new(0).map(|d| d.sample(i)).unwrap_or(0);
        let y = SobolDimension::new(1).map(|d| d.sample(i)).unwrap_or(0);
        [owen.scramble(x, 0), owen.scramble(y, 1)]
    });
    let max = u32::MAX;
    [[0, 0], [0, max], [max, 0], [max, max]]
        .into_iter()
        .chain(sobol)
}

/// The fixed-point warps (integer arithmetic: the same bits everywhere by construction)
/// and the `f32` warps through `libm` (IEEE-754 basic operations are correctly rounded and
/// libm is portable Rust, so the same bits are expected on soft-float Cortex-M0/M3, the
/// M4F's FPU and the host's SSE): digests of outputs, pdfs and inverses.
fn warps<W: Write>(out: &mut W) -> fmt::Result {
    use qmckit::bits::{to_f32, to_fixed};
    use qmckit::warp::{self, fixed as fw};
    let (mut fixed, mut fixed_inv, mut float, mut float_inv) =
        (Digest::new(), Digest::new(), Digest::new(), Digest::new());
    for [x, y] in warp_inputs() {
        let u = [to_fixed(x), to_fixed(y)];
        let d = fw::sample_uniform_disk_polar(u);
        let c = fw::sample_uniform_disk_concentric(u);
        let h = fw::sample_uniform_hemisphere(u);
        let k = fw::sample_cosine_hemisphere(u);
        let t = fw::sample_uniform_triangle(u);
        for v in [d[0], d[1], c[0], c[1], h[0], h[1], h[2], k[0], k[1], k[2]] {
            fixed.push(v.to_bits() as u32);
        }
        for v in [t[0], t[1], t[2], fw::cosine_hemisphere_pdf(k[2])] {
            fixed.push(v.to_bits() as u32);
        }
        for v in [
            fw::invert_uniform_disk_polar(d),
            fw::invert_uniform_disk_concentric(c),
            fw::invert_uniform_hemisphere(h),
            fw::invert_cosine_hemisphere(k),
            fw::invert_uniform_triangle(t),
        ] {
            fixed_inv.push(v[0].to_bits());
            fixed_inv.push(v[1].to_bits());
        }

        let u = [to_f32(x), to_f32(y)];
        let d = warp::disk::sample_uniform_disk_concentric(u);
        let p = warp::disk::sample_uniform_disk_polar(u);
        let s = warp::sphere::sample_uniform_sphere(u);
        let k = warp::sphere::sample_cosine_hemisphere(u);
        let c = warp::sphere::sample_uniform_cone(u, black_box(0.9));
        let t = warp::triangle::sample_uniform_triangle(u);
        let g = warp::gaussian::sample_box_muller(u);
        for v in [d[0], d[1], p[0], p[1], s[0], s[1], s[2], k[0], k[1], k[2]] {
            float.push(v.to_bits());
        }
        for v in [c[0], c[1], c[2], t[0], t[1], t[2], g[0], g[1]] {
            float.push(v.to_bits());
        }
        float.push(warp::gaussian::sample_normal(u[0]).to_bits());
        for v in [
            warp::disk::invert_uniform_disk_concentric(d),
            warp::disk::invert_uniform_disk_polar(p),
            warp::sphere::invert_uniform_sphere(s),
            warp::sphere::invert_cosine_hemisphere(k),
        ] {
            float_inv.push(v[0].to_bits());
            float_inv.push(v[1].to_bits());
        }
    }
    writeln!(out, "fixed_warps 260 {fixed}")?;
    writeln!(out, "fixed_warps_inverse 260 {fixed_inv}")?;
    writeln!(out, "f32_warps 260 {float}")?;
    writeln!(out, "f32_warps_inverse 260 {float_inv}")?;
    // One point in full, for reading a difference.
    let u = [
        to_fixed(black_box(0x4000_0000)),
        to_fixed(black_box(0xC000_0000)),
    ];
    let c = fw::sample_uniform_disk_concentric(u);
    writeln!(
        out,
        "fixed_disk_concentric 1/4 3/4 {} {}",
        c[0].to_bits(),
        c[1].to_bits()
    )?;
    let c = warp::disk::sample_uniform_disk_concentric([0.25, black_box(0.75)]);
    writeln!(
        out,
        "f32_disk_concentric 1/4 3/4 {} {}",
        c[0].to_bits(),
        c[1].to_bits()
    )
}

fn scramblers<W: Write>(out: &mut W) -> fmt::Result {
    let seed = black_box(0x5EED_u64);
    let randomizers: [(&str, &dyn Randomizer); 7] = [
        ("xor", &DigitalShift::new(seed)),
        ("rotate", &CranleyPatterson::new(seed)),
        ("owen", &ExactOwen::new(seed)),
        ("fast-owen", &FastOwen::new(seed)),
        (
            "fast-owen-lk",
            &FastOwen::with_hash(seed, OwenHash::LaineKarras),
        ),
        ("lms", &Lms::new(seed)),
        ("lms+xor", &(Lms::new(seed), DigitalShift::new(seed))),
    ];
    let Ok(base) = Sobol::new(2) else {
        return writeln!(out, "scramble: no sobol");
    };
    for (name, r) in randomizers {
        let s = Scrambled::new(base, r);
        let mut d = Digest::new();
        for i in 0..256u32 {
            for dim in 0..2 {
                d.push(s.sample(black_box(i), dim).unwrap_or(u32::MAX));
            }
        }
        writeln!(out, "scramble {name} sobol2 256 {d}")?;
    }
    if let Ok(s) = Shuffled::new(Scrambled::new(base, FastOwen::new(seed)), seed, 0) {
        let mut d = Digest::new();
        for i in 0..256u32 {
            d.push(s.sample(black_box(i), 1).unwrap_or(u32::MAX));
        }
        writeln!(out, "scramble shuffle-owen sobol2 256 {d}")?;
    }
    for (name, scramble) in [
        ("perm", DigitScramble::Permutations(seed)),
        ("faure", DigitScramble::Faure),
        ("owen", DigitScramble::Owen(seed)),
    ] {
        match Halton::with_scramble(black_box(4), scramble) {
            Ok(h) => {
                let mut buf = [0u32; 64 * 4];
                let r = Sampler::fill(&h, 0, &mut buf);
                let mut d = Digest::new();
                d.push_all(&buf);
                writeln!(out, "scramble {name} halton4 64 {} {d}", r.is_ok())?;
            }
            Err(e) => writeln!(out, "scramble {name} err {e}")?,
        }
    }
    Ok(())
}

fn const_patterns<W: Write>(out: &mut W) -> fmt::Result {
    // Compile-time values (rustc's const evaluator) against run-time ones (the target).
    let h = black_box(H3);
    let mut mismatches = 0u32;
    let mut d = Digest::new();
    for (i, p) in black_box(&CONST_HALTON).iter().enumerate() {
        d.push_all(p);
        for (dim, &x) in p.iter().enumerate() {
            if h.sample(i as u32, dim) != Ok(x) {
                mismatches += 1;
            }
        }
    }
    writeln!(out, "const_halton3 16 {d} mismatches={mismatches}")?;
    for i in [1usize, 3, 15] {
        let p = CONST_HALTON[i];
        writeln!(out, "const_halton3 {i} {} {} {}", p[0], p[1], p[2])?;
    }
    let lp = LarcherPillichshammer::new(black_box(6));
    let phi3 = RadicalInverse::new(black_box(3));
    let mut mismatches = 0u32;
    let mut d = Digest::new();
    for (i, p) in black_box(&CONST_LP).iter().enumerate() {
        d.push_all(p);
        let run = match (&lp, &phi3) {
            (Ok(lp), Ok(phi3)) => [
                lp.sample(i as u32, 0).unwrap_or(0),
                lp.sample(i as u32, 1).unwrap_or(0),
                phi3.sample(i as u32),
            ],
            _ => [0; 3],
        };
        if run != *p {
            mismatches += 1;
        }
    }
    writeln!(out, "const_lp6 64 {d} mismatches={mismatches}")
}

fn errors<W: Write>(out: &mut W) -> fmt::Result {
    error_line(out, "Halton::new(0)", Halton::new(black_box(0)))?;
    error_line(out, "Halton::new(1025)", Halton::new(black_box(1025)))?;
    error_line(
        out,
        "RadicalInverse::new(1)",
        RadicalInverse::new(black_box(1)),
    )?;
    error_line(out, "VanDerCorput::new(0)", VanDerCorput::new(black_box(0)))?;
    error_line(
        out,
        "LarcherPillichshammer::new(33)",
        LarcherPillichshammer::new(black_box(33)),
    )?;
    error_line(
        out,
        "LarcherPillichshammer::with_points(48)",
        LarcherPillichshammer::with_points(black_box(48)),
    )?;
    error_line(
        out,
        "Hammersley::new(0,2)",
        Hammersley::new(black_box(0), 2),
    )?;
    error_line(
        out,
        "Hammersley::new(2^32+1,2)",
        Hammersley::new(black_box((1 << 32) + 1), 2),
    )?;
    error_line(
        out,
        "Stratified::new([4,0])",
        Stratified::new(black_box(&[4u32, 0][..]), Jitter::Center),
    )?;
    if let Ok(h) = Halton::new(2) {
        error_line(out, "Halton(2).sample(0,2)", h.sample(0, black_box(2)))?;
        let mut small = [0u32; 3];
        error_line(
            out,
            "Halton(2).fill(len 3)",
            Sampler::fill(&h, 0, &mut small),
        )?;
        let mut two = [0u32; 4];
        error_line(
            out,
            "Halton(2).fill(u32::MAX, 2 points)",
            Sampler::fill(&h, black_box(u32::MAX), &mut two),
        )?;
    }
    if let Ok(h) = Hammersley::new(64, 2) {
        error_line(
            out,
            "Hammersley(64,2).sample(64,0)",
            h.sample(black_box(64), 0),
        )?;
    }
    if let Ok(ri) = RadicalInverse::new(3) {
        error_line(
            out,
            "RadicalInverse(3).inverse(0,21)",
            ri.inverse(0, black_box(21)),
        )?;
    }
    Ok(())
}
