//! A renderer's sampling workload: 256 x 256 pixels, 16 samples a pixel, 4 dimensions a
//! sample, `f32`, a seed per pixel (a hash of the pixel's index), random access by sample
//! index. One criterion group, one row per way of producing the same kind of samples:
//!
//! * `qmckit_owen_sobol_reseed`: [`OwenSobol`] reseeded per pixel (four hashes), then
//!   `fill_f32` of the pixel's 16 sample indices;
//! * `qmckit_scrambled_fill_as`: the generic `Scrambled<Sobol, FastOwen>` built per pixel,
//!   `fill_as::<f32>` of points `0..16` (the same bits as the row above);
//! * `sobol_burley_sample_4d`: `sobol_burley::sample_4d(i, 0, seed)` for `i` in `0..16`
//!   (it also shuffles the index, one extra hash a sample);
//! * `openqmc_sampler_domain`: openqmc-rs's sampler for pixel `(x, y)` and sample `i`, one
//!   domain, `draw_sample_f32::<4>()` (its own per-pixel decorrelation).
//!
//! Each row writes a pixel's 64 values into a stack buffer and passes it to `black_box`.
//!
//! A second group times long fills (4096 points); two more, `fill_vs_memset_65536x4_f32`
//! and `fill_vs_memset_1048576x4_f32`, time [`OwenSobol::fill_f32`] of 2^16 and 2^20
//! four-dimensional points (1 MiB of `f32` in the L2 cache; 16 MiB, the whole render, in
//! memory) next to a memset of the same bytes, with one seed, with a reseed every 16
//! points (`reseed` then `fill_f32`, and `fill_f32_reseeded` with 64 pixels' seeds a call),
//! and with runs that do not start at a multiple of 16.
//! Run: `cargo bench --bench render -- --measurement-time 2 --warm-up-time 1`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use qmckit::Sampler;
use qmckit::digital::sobol::{OwenSobol, Sobol};
use qmckit::hash::mix64;
use qmckit::randomize::{FastOwen, Scrambled};

/// Image side, samples a pixel, dimensions a sample.
const SIDE: u32 = 256;
const SPP: usize = 16;
const D: usize = 4;

/// The seed of pixel `p`.
#[inline]
fn pixel_seed(p: u32) -> u64 {
    mix64(p as u64 ^ 0x9E37_79B9_7F4A_7C15)
}

fn render(c: &mut Criterion) {
    let mut group = c.benchmark_group("render_256x256x16x4_f32");
    group.throughput(Throughput::Elements(
        (SIDE * SIDE) as u64 * (SPP * D) as u64,
    ));
    let indices: [u32; SPP] = core::array::from_fn(|k| k as u32);
    let base = OwenSobol::new(D, 0).expect("dims");
    let sobol = Sobol::new(D).expect("dims");

    // The fast type and the generic path give the same bits.
    for p in [0u32, 1, 12345, SIDE * SIDE - 1] {
        let mut a = [[0f32; D]; SPP];
        base.with_seed(pixel_seed(p))
            .fill_f32(&indices, &mut a)
            .expect("lengths");
        let mut b = [0f32; SPP * D];
        Scrambled::new(sobol, FastOwen::new(pixel_seed(p)))
            .fill_as(0, &mut b)
            .expect("in range");
        assert_eq!(a.as_flattened(), &b[..], "pixel {p}");
    }

    group.bench_function("qmckit_owen_sobol_reseed", |bch| {
        bch.iter(|| {
            let mut s = black_box(base);
            let mut px = [[0f32; D]; SPP];
            for p in 0..SIDE * SIDE {
                s.reseed(pixel_seed(p));
                s.fill_f32(black_box(&indices), &mut px).expect("lengths");
                black_box(&mut px);
            }
        })
    });
    group.bench_function("qmckit_scrambled_fill_as", |bch| {
        bch.iter(|| {
            let sobol = black_box(sobol);
            let mut px = [0f32; SPP * D];
            for p in 0..SIDE * SIDE {
                let s = Scrambled::new(sobol, FastOwen::new(pixel_seed(p)));
                s.fill_as(black_box(0), &mut px).expect("in range");
                black_box(&mut px);
            }
        })
    });
    group.bench_function("sobol_burley_sample_4d", |bch| {
        bch.iter(|| {
            let mut px = [[0f32; D]; SPP];
            for p in 0..SIDE * SIDE {
                let seed = (pixel_seed(p) >> 32) as u32;
                for (slot, &i) in px.iter_mut().zip(black_box(&indices)) {
                    *slot = sobol_burley::sample_4d(i, 0, seed);
                }
                black_box(&mut px);
            }
        })
    });
    group.bench_function("openqmc_sampler_domain", |bch| {
        bch.iter(|| {
            let mut px = [[0f32; D]; SPP];
            for p in 0..SIDE * SIDE {
                let (x, y) = ((p % SIDE) as i32, (p / SIDE) as i32);
                for (slot, &i) in px.iter_mut().zip(black_box(&indices)) {
                    let root = openqmc::SobolSampler::new(x, y, 0, i as i32);
                    *slot = root.new_domain(0).draw_sample_f32::<4>();
                }
                black_box(&mut px);
            }
        })
    });
    group.finish();

    // Long fills: the per-value cost without per-call setup (4096 points x 4 dimensions).
    let mut group = c.benchmark_group("fill_4096x4_f32");
    group.throughput(Throughput::Elements(4096 * D as u64));
    let seq: Vec<u32> = (0..4096).collect();
    let seeded = base.with_seed(pixel_seed(7));
    let scrambled = Scrambled::new(sobol, FastOwen::new(pixel_seed(7)));
    group.bench_function("qmckit_owen_sobol_fill_f32", |bch| {
        let mut out = vec![[0f32; D]; 4096];
        bch.iter(|| {
            black_box(&seeded)
                .fill_f32(black_box(&seq), &mut out)
                .expect("lengths");
            black_box(&mut out);
        })
    });
    group.bench_function("qmckit_scrambled_fill_as", |bch| {
        let mut out = vec![0f32; 4096 * D];
        bch.iter(|| {
            black_box(&scrambled)
                .fill_as(0, &mut out)
                .expect("in range");
            black_box(&mut out);
        })
    });
    group.finish();

    fill_vs_memset(c, &base, 1 << 16);
    fill_vs_memset(c, &base, 1 << 20);
}

/// `OwenSobol::fill_f32` against a memset of the same bytes: `n` points x 4 dimensions of
/// `f32` (2^16: 1 MiB, in the L2 cache; 2^20: 16 MiB, the 256 x 256 x 16 render, in
/// memory), with one seed for all points, with a reseed every 16 points (a pixel's
/// samples), and with the indices offset by 8 (runs of 16 that do not start at a multiple
/// of 16: the blocks-of-four path).
fn fill_vs_memset(c: &mut Criterion, base: &OwenSobol, n: usize) {
    let mut group = c.benchmark_group(format!("fill_vs_memset_{n}x4_f32"));
    group.throughput(Throughput::Bytes((n * D * 4) as u64));
    let seeded = base.with_seed(pixel_seed(7));
    let seq: Vec<u32> = (0..n as u32).collect();
    let shifted: Vec<u32> = (8..n as u32 + 8).collect();
    group.bench_function("memset", |bch| {
        let mut out = vec![[0f32; D]; n];
        bch.iter(|| {
            black_box(&mut out[..]).fill(black_box([0.0; D]));
            black_box(&mut out);
        })
    });
    group.bench_function("owen_sobol_fill_f32_one_seed", |bch| {
        let mut out = vec![[0f32; D]; n];
        bch.iter(|| {
            black_box(&seeded)
                .fill_f32(black_box(&seq), &mut out)
                .expect("lengths");
            black_box(&mut out);
        })
    });
    group.bench_function("owen_sobol_fill_f32_reseed_16", |bch| {
        let mut out = vec![[0f32; D]; n];
        bch.iter(|| {
            let mut s = black_box(*base);
            for (p, (idx, o)) in black_box(&seq)
                .chunks_exact(SPP)
                .zip(out.chunks_exact_mut(SPP))
                .enumerate()
            {
                s.reseed(pixel_seed(p as u32));
                s.fill_f32(idx, o).expect("lengths");
            }
            black_box(&mut out);
        })
    });
    group.bench_function("owen_sobol_fill_f32_reseeded_16", |bch| {
        // The same values as reseed_16, with the pixels' seeds handed over 64 at a time.
        let mut out = vec![[0f32; D]; n];
        bch.iter(|| {
            let s = black_box(*base);
            for (t, (idx, o)) in black_box(&seq)
                .chunks_exact(SPP * 64)
                .zip(out.chunks_exact_mut(SPP * 64))
                .enumerate()
            {
                let seeds: [u64; 64] = core::array::from_fn(|k| pixel_seed((64 * t + k) as u32));
                s.fill_f32_reseeded(&seeds, idx, o).expect("lengths");
            }
            black_box(&mut out);
        })
    });
    group.bench_function("owen_sobol_fill_f32_one_seed_offset_8", |bch| {
        let mut out = vec![[0f32; D]; n];
        bch.iter(|| {
            black_box(&seeded)
                .fill_f32(black_box(&shifted), &mut out)
                .expect("lengths");
            black_box(&mut out);
        })
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = render
}
criterion_main!(benches);
