//! qmckit against the `halton` crate (0.2.1), side by side in each group.
//!
//! Every benchmark produces `N` values (or `N` points of `d` values) per iteration and
//! reports per-value throughput. qmckit returns exact 0.32 fixed-point `u32`s; the `halton`
//! crate returns `f64`, so the `*_f64` variants add qmckit's conversion for a like-for-like
//! comparison. Bases are passed through `black_box` on both sides (a run-time base), so
//! neither side gets constant-folded divisions that a table-driven Halton would not get.
//!
//! Index sets for random access:
//! * `lo`: the block `0..N` (small indices, few digits);
//! * `spread`: `k * 1_000_003` wrapping over `u32` (full-width indices, all digits).
//!
//! Random-access Halton is measured per coordinate (`Halton::sample(i, dim)`, the
//! `qmckit_u32` rows) and per point (`Sampler::point(i, row)`, the `qmckit_point_*` rows);
//! the peer has no point call, so it composes `halton::number` over the bases.
//!
//! Note on indexing: `halton::number(b, i)` is `phi_b(i)` like qmckit's `sample(i)`;
//! `halton::Sequence::new(b)` yields `phi_b(1), phi_b(2), ...`, so the qmckit sequential
//! benchmarks start at index 1 to produce the same values.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkGroup, BenchmarkId, Criterion, Throughput, criterion_group};
use criterion::{criterion_main, measurement::WallTime};
use qmckit::bits::to_f64;
use qmckit::{Halton, RadicalInverse, Sampler, VanDerCorput};

/// Values (or points) produced per iteration.
const N: usize = 4096;

/// The two random-access index sets, labelled.
fn index_sets() -> [(&'static str, Vec<u32>); 2] {
    let lo: Vec<u32> = (0..N as u32).collect();
    let spread: Vec<u32> = (0..N as u32).map(|k| k.wrapping_mul(1_000_003)).collect();
    [("lo", lo), ("spread", spread)]
}

/// The first `d` Halton primes, as the `u8` bases the `halton` crate takes.
fn primes_u8(d: usize) -> Vec<u8> {
    (0..d)
        .map(|k| {
            let p = qmckit::radical_inverse::halton::prime(k).expect("prime in table");
            u8::try_from(p).expect("halton crate bases are u8")
        })
        .collect()
}

fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .sample_size(25);
}

/// 1. Random-access radical inverse, one base at a time.
fn radical_inverse(c: &mut Criterion) {
    let mut group = c.benchmark_group("radical_inverse");
    configure(&mut group);
    group.throughput(Throughput::Elements(N as u64));
    let sets = index_sets();
    for base in [2u32, 3, 5, 7, 31] {
        for (label, idx) in &sets {
            let ri = RadicalInverse::new(base).expect("valid base");
            let mut out_u32 = vec![0u32; N];
            group.bench_with_input(
                BenchmarkId::new(format!("qmckit_u32/{label}"), base),
                idx,
                |bch, idx| {
                    bch.iter(|| {
                        let ri = black_box(ri);
                        for (slot, &i) in out_u32.iter_mut().zip(black_box(idx.as_slice())) {
                            *slot = ri.sample(i);
                        }
                        black_box(&mut out_u32);
                    })
                },
            );
            let mut out_f64 = vec![0f64; N];
            group.bench_with_input(
                BenchmarkId::new(format!("qmckit_f64/{label}"), base),
                idx,
                |bch, idx| {
                    bch.iter(|| {
                        let ri = black_box(ri);
                        for (slot, &i) in out_f64.iter_mut().zip(black_box(idx.as_slice())) {
                            *slot = to_f64(ri.sample(i));
                        }
                        black_box(&mut out_f64);
                    })
                },
            );
            let b8 = u8::try_from(base).expect("u8 base");
            group.bench_with_input(
                BenchmarkId::new(format!("halton_number/{label}"), base),
                idx,
                |bch, idx| {
                    bch.iter(|| {
                        let b8 = black_box(b8);
                        for (slot, &i) in out_f64.iter_mut().zip(black_box(idx.as_slice())) {
                            *slot = halton::number(b8, i as usize);
                        }
                        black_box(&mut out_f64);
                    })
                },
            );
        }
    }
    group.finish();
}

/// 2. Sequential base-2 van der Corput, `N` consecutive values.
fn van_der_corput(c: &mut Criterion) {
    let mut group = c.benchmark_group("van_der_corput");
    configure(&mut group);
    group.throughput(Throughput::Elements(N as u64));

    let ri = RadicalInverse::new(2).expect("base 2");
    let vdc = VanDerCorput::new(2).expect("base 2");
    let mut out_u32 = vec![0u32; N];
    let mut out_f64 = vec![0f64; N];

    group.bench_function("qmckit_ri_fill_u32", |bch| {
        bch.iter(|| {
            black_box(ri)
                .fill(black_box(1), &mut out_u32)
                .expect("in range");
            black_box(&mut out_u32);
        })
    });
    group.bench_function("qmckit_vdc_sampler_fill_u32", |bch| {
        bch.iter(|| {
            black_box(vdc)
                .fill(black_box(1), &mut out_u32)
                .expect("in range");
            black_box(&mut out_u32);
        })
    });
    group.bench_function("qmckit_ri_iter_f64", |bch| {
        bch.iter(|| {
            let it = black_box(ri).iter_from(black_box(1));
            for (slot, x) in out_f64.iter_mut().zip(it) {
                *slot = to_f64(x);
            }
            black_box(&mut out_f64);
        })
    });
    group.bench_function("halton_sequence_f64", |bch| {
        bch.iter(|| {
            let seq = halton::Sequence::new(black_box(2));
            for (slot, x) in out_f64.iter_mut().zip(seq) {
                *slot = x;
            }
            black_box(&mut out_f64);
        })
    });
    group.finish();
}

/// Writes `N` points of `D` coordinates from `Halton::points` into `out` (row-major).
fn points_into<const D: usize>(h: &Halton, out: &mut [u32]) {
    let it = h.points::<D>(black_box(1)).expect("D == dims");
    for (row, p) in out.chunks_exact_mut(D).zip(it) {
        row.copy_from_slice(&p);
    }
}

/// 3. Sequential Halton, `N` consecutive points in `d` dimensions, row-major.
fn halton_sequential(c: &mut Criterion) {
    let mut group = c.benchmark_group("halton_sequential");
    configure(&mut group);
    for d in [2usize, 8, 32] {
        group.throughput(Throughput::Elements((N * d) as u64));
        let h = Halton::new(d).expect("dims");
        let primes = primes_u8(d);
        let mut out_u32 = vec![0u32; N * d];
        let mut out_f64 = vec![0f64; N * d];

        group.bench_function(BenchmarkId::new("qmckit_fill_u32", d), |bch| {
            bch.iter(|| {
                black_box(h)
                    .fill(black_box(1), &mut out_u32)
                    .expect("in range");
                black_box(&mut out_u32);
            })
        });
        group.bench_function(BenchmarkId::new("qmckit_fill_f64", d), |bch| {
            bch.iter(|| {
                black_box(h)
                    .fill_as(black_box(1), &mut out_f64)
                    .expect("in range");
                black_box(&mut out_f64);
            })
        });
        if d == 2 || d == 8 {
            group.bench_function(BenchmarkId::new("qmckit_points_u32", d), |bch| {
                bch.iter(|| {
                    let h = black_box(h);
                    match d {
                        2 => points_into::<2>(&h, &mut out_u32),
                        _ => points_into::<8>(&h, &mut out_u32),
                    }
                    black_box(&mut out_u32);
                })
            });
        }
        group.bench_function(BenchmarkId::new("halton_sequence_f64", d), |bch| {
            bch.iter(|| {
                for (dim, &p) in black_box(primes.as_slice()).iter().enumerate() {
                    let seq = halton::Sequence::new(p);
                    for (slot, x) in out_f64[dim..].iter_mut().step_by(d).zip(seq) {
                        *slot = x;
                    }
                }
                black_box(&mut out_f64);
            })
        });
    }
    group.finish();
}

/// 4. Random-access Halton: every coordinate of `N` points by index.
fn halton_random(c: &mut Criterion) {
    let mut group = c.benchmark_group("halton_random");
    configure(&mut group);
    let sets = index_sets();
    for d in [2usize, 8, 32] {
        group.throughput(Throughput::Elements((N * d) as u64));
        let h = Halton::new(d).expect("dims");
        let primes = primes_u8(d);
        for (label, idx) in &sets {
            let id = |name: &str| BenchmarkId::new(format!("{name}/{label}"), d);
            bench_rows(&mut group, id("qmckit_u32"), idx, d, &h, |h, i, row| {
                for (dim, slot) in row.iter_mut().enumerate() {
                    *slot = h.sample(i, dim).expect("dim in range");
                }
            });
            bench_rows(
                &mut group,
                id("qmckit_point_u32"),
                idx,
                d,
                &h,
                |h, i, row| {
                    h.point(i, row).expect("row of d values");
                },
            );
            bench_rows(
                &mut group,
                id("qmckit_point_f64"),
                idx,
                d,
                &h,
                |h, i, row| {
                    let mut p = [0u32; 32];
                    let p = &mut p[..row.len()];
                    h.point(i, p).expect("row of d values");
                    for (slot, &x) in row.iter_mut().zip(p.iter()) {
                        *slot = to_f64(x);
                    }
                },
            );
            bench_rows(&mut group, id("qmckit_f64"), idx, d, &h, |h, i, row| {
                for (dim, slot) in row.iter_mut().enumerate() {
                    *slot = to_f64(h.sample(i, dim).expect("dim in range"));
                }
            });
            bench_rows(
                &mut group,
                id("halton_number"),
                idx,
                d,
                &primes,
                |p, i, row| {
                    for (slot, &b) in row.iter_mut().zip(p) {
                        *slot = halton::number(b, i as usize);
                    }
                },
            );
        }
    }
    group.finish();
}

/// One random-access benchmark: `fill(state, i, row)` writes the `d` values of point `i`,
/// for every index of `idx`; `state` goes through `black_box` once per iteration.
fn bench_rows<S: ?Sized, T: Copy + Default>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    id: BenchmarkId,
    idx: &[u32],
    d: usize,
    state: &S,
    fill: impl Fn(&S, u32, &mut [T]),
) {
    let mut out = vec![T::default(); idx.len() * d];
    group.bench_with_input(id, idx, |bch, idx| {
        bch.iter(|| {
            let s = black_box(state);
            for (row, &i) in out.chunks_exact_mut(d).zip(black_box(idx)) {
                fill(s, i, row);
            }
            black_box(&mut out);
        })
    });
}

criterion_group!(
    benches,
    radical_inverse,
    van_der_corput,
    halton_sequential,
    halton_random
);
criterion_main!(benches);
