//! qmckit's Sobol' sequence against `sobol_burley` (0.5), `sobol` (1.0.2), `sobol-qmc`
//! (2.5.1) and `openqmc-rs` (0.2.4), plus naive loops written here, side by side in each
//! group.
//!
//! Every benchmark produces `N` points of several values per iteration and reports
//! per-value throughput. Inputs and outputs go through `black_box`.
//!
//! Index sets for random access:
//! * `full32`: `k * 2_654_435_761` wrapping over `u32` (full-width indices, all 32 bits);
//! * `idx16`: the same masked to 16 bits (still 4096 distinct indices, since the multiplier
//!   is odd), for peers limited to 2^16 indices (`sobol_burley`, `openqmc-rs`). Both qmckit
//!   and the naive loops also run on it, so the `idx16` rows compare like for like.
//!
//! Groups:
//! 1. `sobol_random_u32`: unscrambled random access, 4 dimensions per index, exact `u32`.
//! 2. `sobol_sequential_u32`: Gray-code order from index 0, `N` points x `d` dimensions,
//!    row-major. The `sobol` crate's iterator allocates a `Vec` per point (its only API);
//!    `sobol-qmc`'s `update` + `render_next` does not. Both peers are stateful, so each
//!    iteration starts from a fresh clone made outside the timed region (`iter_batched_ref`).
//! 3. `sobol_owen_random_f32`: Owen-scrambled random access, 4 dimensions per index, `f32`.
//!    The peers also shuffle the index (Burley 2020), one extra hash per index; the
//!    `qmckit_shuffled_fastowen_table` row adds qmckit's own index shuffle for a like-for-like
//!    comparison. `openqmc-rs` is timed both through its core function
//!    (`owen::shuffled_scrambled_sobol`, sample `i` of a 4D pattern) and through its
//!    domain-tree API (a root sampler per index, one `new_domain`, `draw_sample_f32::<4>`).
//!
//! Before timing, `check_agreement` asserts that the peers agree with qmckit where they
//! should (see its comments).

use std::hint::black_box;
use std::time::Duration;

use criterion::{BatchSize, BenchmarkGroup, BenchmarkId, Criterion, Throughput};
use criterion::{criterion_group, criterion_main, measurement::WallTime};
use qmckit::Sampler;
use qmckit::bits::{gray, reverse_bits, to_f32};
use qmckit::digital::sobol::{Order, OwenSobol, Sobol, SobolDimension, SobolTable};
use qmckit::hash::vegdahl;
use qmckit::randomize::{FastOwen, FastOwenScrambler, Scrambled, dimension_seed, shuffle::shuffle};

/// Points (indices) per iteration.
const N: usize = 4096;
/// Dimensions per index in the random-access groups.
const D: usize = 4;
/// Scramble seed (qmckit) and its 32-bit form (peers).
const SEED: u64 = 0x5EED_0123_4567_89AB;
const SEED32: u32 = 0x89AB_CDEF;

/// The two random-access index sets, labelled.
fn index_sets() -> [(&'static str, Vec<u32>); 2] {
    let full: Vec<u32> = (0..N as u32)
        .map(|k| k.wrapping_mul(2_654_435_761))
        .collect();
    let lo: Vec<u32> = full.iter().map(|&i| i & 0xFFFF).collect();
    [("full32", full), ("idx16", lo)]
}

fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .sample_size(20);
}

fn dimensions(d: usize) -> Vec<SobolDimension> {
    (0..d)
        .map(|k| SobolDimension::new(k).expect("dimension in table"))
        .collect()
}

fn direction_arrays(d: usize) -> Vec<[u32; 32]> {
    dimensions(d).iter().map(|s| *s.directions()).collect()
}

/// Reference: one test and one conditional XOR per bit of the index, stopping at its
/// highest set bit.
#[inline]
fn naive_bit_loop(v: &[u32; 32], mut i: u32) -> u32 {
    let mut x = 0;
    let mut k = 0;
    while i != 0 {
        if i & 1 == 1 {
            x ^= v[k];
        }
        i >>= 1;
        k += 1;
    }
    x
}

/// Reference: one XOR per set bit of the index, found by a trailing-zero count.
#[inline]
fn naive_ctz_loop(v: &[u32; 32], mut i: u32) -> u32 {
    let mut x = 0;
    while i != 0 {
        x ^= v[i.trailing_zeros() as usize];
        i &= i - 1;
    }
    x
}

/// `sobol_burley`'s unscrambled Sobol' (16 direction numbers, 16-bit indices).
#[inline]
fn burley_unscrambled(i: u32, dim: u32) -> u32 {
    sobol_burley::parts::sobol_rev(i.reverse_bits(), dim).reverse_bits()
}

/// The Gray-code reference loop: `N` points of `v.len()` dimensions, row-major, from 0.
#[inline]
fn naive_gray(v: &[[u32; 32]], x: &mut [u32], out: &mut [u32]) {
    x.fill(0);
    let d = v.len();
    for (i, row) in out.chunks_exact_mut(d).enumerate() {
        row.copy_from_slice(x);
        let k = (i as u32 + 1).trailing_zeros() as usize;
        for (xd, vd) in x.iter_mut().zip(v) {
            *xd ^= vd[k];
        }
    }
}

type SobolQmc = sobol_qmc::Sobol<u32>;
type SobolRs = sobol::Sobol<u32>;

fn sobol_qmc_new(d: usize) -> SobolQmc {
    sobol_qmc::Sobol::<u32>::new(d, &sobol_qmc::params::JoeKuoD6::STANDARD).expect("dims")
}

fn sobol_rs_new(d: usize, params: &sobol::params::JoeKuoD6) -> SobolRs {
    sobol::Sobol::<u32>::new(d, params)
}

/// Checks, outside the timed loops, that everything that should agree does.
fn check_agreement() {
    // qmckit's three unscrambled paths and the two naive loops, over both index sets.
    let dims = dimensions(32);
    for (_, idx) in index_sets() {
        for d in &dims {
            let t = SobolTable::new(*d);
            for &i in &idx {
                let x = d.sample(i);
                assert_eq!(t.sample(i), x);
                assert_eq!(naive_bit_loop(d.directions(), i), x);
                assert_eq!(naive_ctz_loop(d.directions(), i), x);
            }
        }
    }

    // Gray order, first 64 points (and the whole benchmarked range), 32 dimensions:
    // qmckit's fill, the naive loop, sobol-qmc and sobol all give the same u32s: the same
    // Joe-Kuo direction numbers, the same Gray order, and all start at the point 0.
    let d = 32;
    let mut q = vec![0u32; N * d];
    Sobol::with_order(d, Order::Gray)
        .expect("dims")
        .fill(0, &mut q)
        .expect("range");
    let mut naive = vec![0u32; N * d];
    naive_gray(&direction_arrays(d), &mut vec![0; d], &mut naive);
    assert_eq!(naive, q, "naive Gray loop");
    let mut g = sobol_qmc_new(d);
    for (k, row) in q.chunks_exact(d).enumerate() {
        g.update();
        let p: Vec<u32> = g.render_next().collect();
        assert_eq!(p, row, "sobol-qmc point {k}");
    }
    let params = sobol::params::JoeKuoD6::standard();
    for (k, (row, p)) in q.chunks_exact(d).zip(sobol_rs_new(d, &params)).enumerate() {
        assert_eq!(p, row, "sobol point {k}");
    }
    // Natural order on the first 64 points is the Gray order permuted within each power
    // of two, point by point through gray(i).
    let s = Sobol::new(d).expect("dims");
    for (k, row) in q.chunks_exact(d).take(64).enumerate() {
        for (dim, &x) in row.iter().enumerate() {
            assert_eq!(s.sample(gray(k as u32), dim).expect("in range"), x);
        }
    }
    // The sobol crate's f64 output (53-bit resolution) is the same fractions.
    for (row, p) in q
        .chunks_exact(d)
        .zip(sobol::Sobol::<f64>::new(d, &params))
        .take(64)
    {
        for (&x, &y) in row.iter().zip(&p) {
            assert_eq!(qmckit::bits::to_f64(x), y);
        }
    }

    // sobol_burley's unscrambled core: the same Joe-Kuo numbers, for indices below 2^16.
    for i in 0..1u32 << 16 {
        for (dim, dd) in dims.iter().enumerate() {
            assert_eq!(burley_unscrambled(i, dim as u32), dd.sample(i));
        }
    }

    // sobol_burley's Owen hash is qmckit's `vegdahl`, bit for bit; and its sample() and
    // sample_4d() agree. (Its seeding and index shuffle differ from qmckit's FastOwen, so
    // the scrambled values themselves are not expected to match.)
    for x in (0..1u32 << 16).map(|k| k.wrapping_mul(0x9E37_79B9)) {
        for key in [0u32, 1, SEED32, 0xDEAD_BEEF] {
            assert_eq!(
                sobol_burley::parts::owen_scramble_rev(x, key),
                vegdahl(x, key)
            );
        }
    }
    for i in 0..4096u32 {
        let a: [f32; 4] = core::array::from_fn(|dd| sobol_burley::sample(i, dd as u32, SEED32));
        assert_eq!(a, sobol_burley::sample_4d(i, 0, SEED32));
    }

    // qmckit's table Owen path is its generic Scrambled path, bit for bit.
    let owen = FastOwen::new(SEED);
    let scrambled = Scrambled::new(Sobol::new(D).expect("dims"), owen);
    let tables: Vec<SobolTable> = dimensions(D).into_iter().map(SobolTable::new).collect();
    for (_, idx) in index_sets() {
        for &i in &idx {
            for (dim, t) in tables.iter().enumerate() {
                let fast = reverse_bits(
                    owen.scrambler(dim)
                        .scramble_reversed(reverse_bits(t.sample(i))),
                );
                assert_eq!(fast, scrambled.sample(i, dim).expect("in range"));
            }
        }
    }

    // openqmc-rs: the domain-tree sampler is the core seeded with its pattern id (constant
    // below 2^16 indices). Its Sobol' core uses 16 direction numbers (16-bit values) copied
    // from OpenQMC; they are Joe-Kuo's for dimensions 0..4 (the top 16 bits of qmckit's
    // points for every index below 2^16).
    for i in 0..4096 {
        let st = openqmc::State64Bit::new(0, 0, 0, i)
            .pixel_decorrelate()
            .new_domain(0);
        let core = openqmc::owen::shuffled_scrambled_sobol::<4>(
            u32::from(st.sample_id),
            openqmc::pcg::output(st.pattern_id),
        );
        let root = openqmc::SobolSampler::new(0, 0, 0, i);
        assert_eq!(root.new_domain(0).draw_sample::<4>(), core);
    }
    for i in 0..=u16::MAX {
        for (dim, dd) in dims.iter().take(4).enumerate() {
            let r = openqmc::owen::sobol_reversed_index(i.reverse_bits(), dim);
            assert_eq!(u32::from(r.reverse_bits()) << 16, dd.sample(u32::from(i)));
        }
    }
    eprintln!("agreement checks passed");
}

/// 1. Unscrambled random access, `D` dimensions per index, `u32` out.
fn sobol_random_u32(c: &mut Criterion) {
    check_agreement();
    let mut group = c.benchmark_group("sobol_random_u32");
    configure(&mut group);
    group.throughput(Throughput::Elements((N * D) as u64));
    let dims = dimensions(D);
    let tables: Vec<SobolTable> = dims.iter().map(|&d| SobolTable::new(d)).collect();
    let v = direction_arrays(D);
    let mut out = vec![0u32; N * D];

    for (label, idx) in &index_sets() {
        group.bench_with_input(
            BenchmarkId::new("qmckit_dimension_sample", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let dims = black_box(dims.as_slice());
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        for (slot, d) in row.iter_mut().zip(dims) {
                            *slot = d.sample(i);
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("qmckit_table_sample", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let tables = black_box(tables.as_slice());
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        for (slot, t) in row.iter_mut().zip(tables) {
                            *slot = t.sample(i);
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("naive_bit_loop", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let v = black_box(v.as_slice());
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        for (slot, vd) in row.iter_mut().zip(v) {
                            *slot = naive_bit_loop(vd, i);
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("naive_ctz_loop", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let v = black_box(v.as_slice());
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        for (slot, vd) in row.iter_mut().zip(v) {
                            *slot = naive_ctz_loop(vd, i);
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        if *label == "idx16" {
            group.bench_with_input(
                BenchmarkId::new("sobol_burley_parts_sobol_rev", label),
                idx,
                |bch, idx| {
                    bch.iter(|| {
                        for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                            for (dim, slot) in row.iter_mut().enumerate() {
                                *slot = burley_unscrambled(i, black_box(dim as u32));
                            }
                        }
                        black_box(&mut out);
                    })
                },
            );
        }
    }
    group.finish();
}

/// 2. Sequential Gray-code order, `N` points x `d` dimensions from index 0, row-major.
fn sobol_sequential_u32(c: &mut Criterion) {
    let mut group = c.benchmark_group("sobol_sequential_u32");
    configure(&mut group);
    let params = sobol::params::JoeKuoD6::standard();
    for d in [4usize, 32] {
        group.throughput(Throughput::Elements((N * d) as u64));
        let s = Sobol::with_order(d, Order::Gray).expect("dims");
        let v = direction_arrays(d);
        let qmc = sobol_qmc_new(d);
        let srs = sobol_rs_new(d, &params);
        let mut out = vec![0u32; N * d];
        let mut x = vec![0u32; d];

        group.bench_function(BenchmarkId::new("qmckit_gray_fill", d), |bch| {
            bch.iter(|| {
                black_box(s).fill(black_box(0), &mut out).expect("range");
                black_box(&mut out);
            })
        });
        group.bench_function(BenchmarkId::new("naive_gray_loop", d), |bch| {
            bch.iter(|| {
                naive_gray(black_box(v.as_slice()), &mut x, &mut out);
                black_box(&mut out);
            })
        });
        group.bench_function(BenchmarkId::new("sobol_qmc_update_render", d), |bch| {
            bch.iter_batched_ref(
                || qmc.clone(),
                |g| {
                    for row in out.chunks_exact_mut(d) {
                        g.update();
                        for (slot, y) in row.iter_mut().zip(g.render_next()) {
                            *slot = y;
                        }
                    }
                    black_box(&mut out);
                },
                BatchSize::SmallInput,
            )
        });
        group.bench_function(BenchmarkId::new("sobol_qmc_iter_vec", d), |bch| {
            bch.iter_batched_ref(
                || qmc.clone(),
                |g| {
                    for (row, p) in out.chunks_exact_mut(d).zip(g) {
                        row.copy_from_slice(&p);
                    }
                    black_box(&mut out);
                },
                BatchSize::SmallInput,
            )
        });
        group.bench_function(BenchmarkId::new("sobol_iter_vec", d), |bch| {
            bch.iter_batched_ref(
                || srs.clone(),
                |g| {
                    for (row, p) in out.chunks_exact_mut(d).zip(g) {
                        row.copy_from_slice(&p);
                    }
                    black_box(&mut out);
                },
                BatchSize::SmallInput,
            )
        });
    }
    group.finish();
}

/// 3. Owen-scrambled random access, `D` dimensions per index, `f32` out.
fn sobol_owen_random_f32(c: &mut Criterion) {
    let mut group = c.benchmark_group("sobol_owen_random_f32");
    configure(&mut group);
    group.throughput(Throughput::Elements((N * D) as u64));
    let owen = FastOwen::new(SEED);
    let tables: Vec<SobolTable> = dimensions(D).into_iter().map(SobolTable::new).collect();
    let keys: [FastOwenScrambler; D] = core::array::from_fn(|d| owen.scrambler(d));
    let shuffle_key = dimension_seed(SEED ^ 0x5F, 0);
    let scrambled = Scrambled::new(Sobol::new(D).expect("dims"), owen);
    let oq_seed = openqmc::pcg::hash(SEED32);
    let mut out = vec![0f32; N * D];

    let owen4 = OwenSobol::new(D, SEED).expect("dims");
    let mut out4 = vec![[0f32; 4]; N];
    for (label, idx) in &index_sets() {
        // Four interleaved dimensions, batch fill (run-time AVX2 dispatch on x86-64).
        group.bench_with_input(
            BenchmarkId::new("qmckit_owen_sobol_fill", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    black_box(&owen4)
                        .fill_f32(black_box(idx.as_slice()), &mut out4)
                        .expect("equal lengths");
                    black_box(&mut out4);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("qmckit_owen_sobol_portable", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    black_box(&owen4)
                        .fill_f32_portable(black_box(idx.as_slice()), &mut out4)
                        .expect("equal lengths");
                    black_box(&mut out4);
                })
            },
        );
        // The dedicated path: reversed byte tables, one reversal, the key inside.
        group.bench_with_input(
            BenchmarkId::new("qmckit_owen_sobol_sample", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let s = black_box(&owen4);
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        for (dim, slot) in row.iter_mut().enumerate() {
                            *slot = s.sample_f32(i, dim).expect("in range");
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("qmckit_fastowen_table", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let tables = black_box(tables.as_slice());
                    let keys = black_box(&keys);
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        for ((slot, t), key) in row.iter_mut().zip(tables).zip(keys) {
                            let x = key.scramble_reversed(reverse_bits(t.sample(i)));
                            *slot = to_f32(reverse_bits(x));
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("qmckit_shuffled_fastowen_table", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let tables = black_box(tables.as_slice());
                    let keys = black_box(&keys);
                    let shuffle_key = black_box(shuffle_key);
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        let j = shuffle(i, 32, shuffle_key);
                        for ((slot, t), key) in row.iter_mut().zip(tables).zip(keys) {
                            let x = key.scramble_reversed(reverse_bits(t.sample(j)));
                            *slot = to_f32(reverse_bits(x));
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("qmckit_scrambled_sampler", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let s = black_box(&scrambled);
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        for (dim, slot) in row.iter_mut().enumerate() {
                            *slot = to_f32(s.sample(i, dim).expect("in range"));
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        if *label != "idx16" {
            continue;
        }
        group.bench_with_input(
            BenchmarkId::new("sobol_burley_sample", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let seed = black_box(SEED32);
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        for (dim, slot) in row.iter_mut().enumerate() {
                            *slot = sobol_burley::sample(i, dim as u32, seed);
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("sobol_burley_sample_4d", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let seed = black_box(SEED32);
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        row.copy_from_slice(&sobol_burley::sample_4d(i, 0, seed));
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("openqmc_core_shuffled_scrambled", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let seed = black_box(oq_seed);
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        let p = openqmc::owen::shuffled_scrambled_sobol::<4>(i, seed);
                        for (slot, &x) in row.iter_mut().zip(&p) {
                            *slot = openqmc::float::uint_to_float(x);
                        }
                    }
                    black_box(&mut out);
                })
            },
        );
        group.bench_with_input(
            BenchmarkId::new("openqmc_sampler_domain", label),
            idx,
            |bch, idx| {
                bch.iter(|| {
                    let key = black_box(0);
                    for (row, &i) in out.chunks_exact_mut(D).zip(black_box(idx.as_slice())) {
                        let root = openqmc::SobolSampler::new(0, 0, 0, i as i32);
                        row.copy_from_slice(&root.new_domain(key).draw_sample_f32::<4>());
                    }
                    black_box(&mut out);
                })
            },
        );
    }
    group.finish();
}

criterion_group!(
    benches,
    sobol_random_u32,
    sobol_sequential_u32,
    sobol_owen_random_f32
);
criterion_main!(benches);
