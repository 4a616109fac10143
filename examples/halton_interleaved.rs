//! Random-access Halton and radical inverse against the `halton` crate, interleaved: each
//! variant is timed `R` times in alternation with the others and its best time kept, so that
//! load from other processes on a shared machine hits all variants alike (criterion runs
//! them one after another, seconds apart). Complements `cargo bench --bench halton`.
//!
//! `cargo run --release --example halton_interleaved [-- ROUNDS]` (default 300).
//! Index sets as in the bench: `lo` = 0..4096, `spread` = k * 1_000_003 over the u32 range.
//! Last, sequential Halton: `Sampler::fill` (`u32`) and `Sampler::fill_as` (`f64`) against `halton::Sequence`.

use std::hint::black_box;
use std::time::Instant;

use qmckit::{Halton, RadicalInverse, Sampler};

const N: usize = 4096;

/// Seconds one call of `f` takes.
fn time(f: &mut dyn FnMut()) -> f64 {
    let t = Instant::now();
    f();
    t.elapsed().as_secs_f64()
}

/// Best times of the variants over `rounds` alternating rounds.
fn race(rounds: usize, variants: &mut [&mut dyn FnMut()]) -> Vec<f64> {
    let mut best = vec![f64::MAX; variants.len()];
    for _ in 0..rounds {
        for (b, f) in best.iter_mut().zip(variants.iter_mut()) {
            *b = b.min(time(*f));
        }
    }
    best
}

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .map_or(300, |s| s.parse().expect("ROUNDS is a number"));
    let lo: Vec<u32> = (0..N as u32).collect();
    let spread: Vec<u32> = (0..N as u32).map(|k| k.wrapping_mul(1_000_003)).collect();
    println!("ns per value, best of {rounds} interleaved rounds; ratio = peer / qmckit");
    for (label, idx) in [("lo", &lo), ("spread", &spread)] {
        for d in [2usize, 8, 32] {
            let h = Halton::new(d).expect("dims");
            let primes: Vec<u8> = (0..d)
                .map(|k| qmckit::radical_inverse::halton::prime(k).expect("prime") as u8)
                .collect();
            let (mut a, mut b, mut c) = (vec![0u32; N * d], vec![0u32; N * d], vec![0f64; N * d]);
            let t = race(
                rounds,
                &mut [
                    &mut || {
                        let h = black_box(h);
                        for (row, &i) in a.chunks_exact_mut(d).zip(black_box(idx.as_slice())) {
                            for (dim, slot) in row.iter_mut().enumerate() {
                                *slot = h.sample(i, dim).expect("dim in range");
                            }
                        }
                        black_box(&mut a);
                    },
                    &mut || {
                        let h = black_box(h);
                        for (row, &i) in b.chunks_exact_mut(d).zip(black_box(idx.as_slice())) {
                            h.point(i, row).expect("row of d values");
                        }
                        black_box(&mut b);
                    },
                    &mut || {
                        let p = black_box(primes.as_slice());
                        for (row, &i) in c.chunks_exact_mut(d).zip(black_box(idx.as_slice())) {
                            for (slot, &base) in row.iter_mut().zip(p) {
                                *slot = halton::number(base, i as usize);
                            }
                        }
                        black_box(&mut c);
                    },
                ],
            );
            report(
                &format!("halton d={d:<2} {label:<6}"),
                ["per coordinate", "per point"],
                &t,
                N * d,
            );
        }
        for base in [3u32, 7, 31] {
            let ri = RadicalInverse::new(base).expect("base");
            let (mut a, mut c) = (vec![0u32; N], vec![0f64; N]);
            let t = race(
                rounds,
                &mut [
                    &mut || {
                        let ri = black_box(ri);
                        for (slot, &i) in a.iter_mut().zip(black_box(idx.as_slice())) {
                            *slot = ri.sample(i);
                        }
                        black_box(&mut a);
                    },
                    &mut || {
                        let b = black_box(base as u8);
                        for (slot, &i) in c.iter_mut().zip(black_box(idx.as_slice())) {
                            *slot = halton::number(b, i as usize);
                        }
                        black_box(&mut c);
                    },
                ],
            );
            let ns = |s: f64| s * 1e9 / N as f64;
            println!(
                "radical inverse base {base:<2} {label:<6} qmckit {:6.2}  peer {:6.2}  ratio {:.2}x",
                ns(t[0]),
                ns(t[1]),
                t[1] / t[0]
            );
        }
    }
    sequential(rounds);
}

/// Sequential Halton, points 1..=N (the peer's `Sequence` starts at index 1): qmckit's
/// `Sampler::fill` (`u32`) and `Sampler::fill_as` (`f64`, converted as stored) against
/// `halton::Sequence` (`f64`) per dimension.
fn sequential(rounds: usize) {
    for d in [2usize, 8, 32] {
        let h = Halton::new(d).expect("dims");
        let primes: Vec<u8> = (0..d)
            .map(|k| qmckit::radical_inverse::halton::prime(k).expect("prime") as u8)
            .collect();
        let mut a = vec![0u32; N * d];
        let (mut b, mut c) = (vec![0f64; N * d], vec![0f64; N * d]);
        let t = race(
            rounds,
            &mut [
                &mut || {
                    black_box(h).fill(black_box(1), &mut a).expect("in range");
                    black_box(&mut a);
                },
                &mut || {
                    black_box(h)
                        .fill_as(black_box(1), &mut b)
                        .expect("in range");
                    black_box(&mut b);
                },
                &mut || {
                    for (dim, &p) in black_box(primes.as_slice()).iter().enumerate() {
                        let seq = halton::Sequence::new(p);
                        for (slot, x) in c[dim..].iter_mut().step_by(d).zip(seq) {
                            *slot = x;
                        }
                    }
                    black_box(&mut c);
                },
            ],
        );
        report(
            &format!("sequential halton d={d:<2}"),
            ["fill", "f64"],
            &t,
            N * d,
        );
    }
}

/// One result line: two qmckit variants and the peer (`t = [a, b, peer]`, seconds for
/// `values` values) in ns per value, and the ratios peer / a and peer / b.
fn report(prefix: &str, names: [&str; 2], t: &[f64], values: usize) {
    let ns = |s: f64| s * 1e9 / values as f64;
    println!(
        "{prefix} {} {:6.2}  {} {:6.2}  peer {:6.2}  ratio {:.2}x / {:.2}x",
        names[0],
        ns(t[0]),
        names[1],
        ns(t[1]),
        ns(t[2]),
        t[2] / t[0],
        t[2] / t[1]
    );
}
