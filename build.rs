//! Build-time tables.
//!
//! * `primes.rs`: the first [`HALTON_MAX_DIMS`] primes, the bases of the Halton sequence.
//!   Stored as `u16` (the 1024th prime is 8161), so the table costs 2 KiB of flash when a
//!   program indexes it at run time.
//! * `sobol.rs` + `sobol_directions.bin`: the 32 direction numbers `V_1 .. V_32` of the first
//!   `SOBOL_MAX_DIMS` Sobol' dimensions (64, or 1024 / 21201 with the `sobol-dims-1024` /
//!   `sobol-dims-21201` features; the largest enabled wins), computed from Joe & Kuo's
//!   `tables/new-joe-kuo-6.21201` as little-endian bytes, 128 bytes a dimension.

use std::env;
use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;

/// How many Halton dimensions (prime bases) are compiled in.
const HALTON_MAX_DIMS: usize = 1024;

fn first_primes(count: usize) -> Vec<u32> {
    let mut primes: Vec<u32> = Vec::with_capacity(count);
    let mut candidate = 2u32;
    while primes.len() < count {
        if primes
            .iter()
            .take_while(|&&p| p * p <= candidate)
            .all(|&p| !candidate.is_multiple_of(p))
        {
            primes.push(candidate);
        }
        candidate += 1;
    }
    primes
}

/// One row of Joe & Kuo's table: degree `s`, inner coefficients `a`, initial numbers `m`.
struct Row {
    s: u32,
    a: u32,
    m: Vec<u32>,
}

/// Parses `d s a m_1 .. m_s` rows (the header line is skipped), checking that the rows are
/// consecutive from d = 2 and that each `m_k` is odd and below `2^k`.
fn parse_joe_kuo(text: &str, count: usize) -> Vec<Row> {
    let mut rows = Vec::with_capacity(count);
    for (line_no, line) in text.lines().enumerate().skip(1) {
        if rows.len() + 1 >= count {
            break;
        }
        let f: Vec<u32> = line
            .split_whitespace()
            .map(|x| {
                x.parse()
                    .unwrap_or_else(|_| panic!("tables: line {}: {x:?}", line_no + 1))
            })
            .collect();
        let (d, s, a) = (f[0], f[1], f[2]);
        assert_eq!(
            d as usize,
            rows.len() + 2,
            "tables: line {}: dimension order",
            line_no + 1
        );
        let m = f[3..].to_vec();
        assert_eq!(
            m.len(),
            s as usize,
            "tables: line {}: s = {s} numbers",
            line_no + 1
        );
        for (k, &mk) in m.iter().enumerate() {
            assert!(
                mk % 2 == 1 && mk < 1 << (k + 1),
                "tables: line {}: m_{}",
                line_no + 1,
                k + 1
            );
        }
        rows.push(Row { s, a, m });
    }
    assert_eq!(
        rows.len() + 1,
        count,
        "tables: too few rows for {count} dimensions"
    );
    rows
}

/// The 32 direction numbers `V_k = m_k 2^(32-k)` of one dimension, extended past the
/// degree `s` by the recurrence of its primitive polynomial (Bratley & Fox 1988):
/// `V_k = V_(k-s) ^ (V_(k-s) >> s) ^ XOR_(j=1..s-1) a_j V_(k-j)`, with `a_j` the bits of
/// `a` from the most significant.
fn directions(row: &Row) -> [u32; 32] {
    let s = row.s as usize;
    let mut v = [0u32; 32];
    for k in 0..32 {
        v[k] = if k < s {
            row.m[k] << (31 - k)
        } else {
            let mut x = v[k - s] ^ (v[k - s] >> s);
            for j in 1..s {
                if (row.a >> (s - 1 - j)) & 1 == 1 {
                    x ^= v[k - j];
                }
            }
            x
        };
    }
    v
}

fn sobol_dims() -> usize {
    if env::var_os("CARGO_FEATURE_SOBOL_DIMS_21201").is_some() {
        21201
    } else if env::var_os("CARGO_FEATURE_SOBOL_DIMS_1024").is_some() {
        1024
    } else {
        64
    }
}

fn write_sobol(out: &std::path::Path) {
    let dims = sobol_dims();
    let text = fs::read_to_string("tables/new-joe-kuo-6.21201").expect("read tables/");
    let rows = parse_joe_kuo(&text, dims);
    let mut src = String::with_capacity(dims * 32 * 12 + 256);
    writeln!(
        src,
        "/// Number of Sobol' dimensions compiled in (the `sobol-dims-*` features)."
    )
    .unwrap();
    writeln!(src, "pub const SOBOL_MAX_DIMS: usize = {dims};").unwrap();
    writeln!(
        src,
        "/// Direction numbers `[V_1, .., V_32]` of each compiled-in dimension."
    )
    .unwrap();
    writeln!(
        src,
        "pub static SOBOL_DIRECTIONS: [[u32; 32]; SOBOL_MAX_DIMS] = ["
    )
    .unwrap();
    // Dimension 1: the identity matrix (van der Corput), V_k = 2^(32-k).
    let first: [u32; 32] = core::array::from_fn(|k| 1u32 << (31 - k));
    for v in std::iter::once(first).chain(rows.iter().map(directions)) {
        src.push('[');
        for x in v {
            write!(src, "{x:#x},").unwrap();
        }
        src.push_str("],\n");
    }
    src.push_str("];\n");
    fs::write(out.join("sobol.rs"), src).expect("write sobol.rs");
}

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=tables/new-joe-kuo-6.21201");
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    write_sobol(&out);

    let primes = first_primes(HALTON_MAX_DIMS);
    assert!(*primes.last().unwrap() <= u32::from(u16::MAX));
    let mut src = String::new();
    writeln!(
        src,
        "/// Number of prime bases compiled in (Halton dimensions)."
    )
    .unwrap();
    writeln!(src, "pub const HALTON_MAX_DIMS: usize = {HALTON_MAX_DIMS};").unwrap();
    writeln!(src, "/// The first `HALTON_MAX_DIMS` primes, ascending.").unwrap();
    writeln!(
        src,
        "pub(crate) static PRIMES: [u16; {HALTON_MAX_DIMS}] = ["
    )
    .unwrap();
    for chunk in primes.chunks(16) {
        let line: Vec<String> = chunk.iter().map(|p| p.to_string()).collect();
        writeln!(src, "    {},", line.join(", ")).unwrap();
    }
    writeln!(src, "];").unwrap();
    fs::write(out.join("primes.rs"), src).expect("write primes.rs");
}
