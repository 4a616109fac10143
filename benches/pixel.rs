//! Pixel samplers on a renderer's workload: 256 x 256 pixels, 16 samples a pixel, 4
//! dimensions a sample, `f32`, random access by (pixel, sample index). One criterion group,
//! one row per way of producing a pixel's 64 values:
//!
//! * `qmckit_zsobol_handle`: [`ZSobol`] (pbrt-v4's blue-noise Sobol') the renderer's way:
//!   `start_pixel_sample(x, y, i)` per sample (the checks and the Morton index), then
//!   `get_2d_f32` twice (dimensions 0 and 2: two permuted indices, two hashes);
//! * `qmckit_zsobol_prepared`: the same values through [`ZSobol::pixel_dimension`], the
//!   pixel and dimension prepared once (the permuted high digits and the hashes), then
//!   `ceil(log4 spp)` MixBits a sample;
//! * `qmckit_padded_sobol`: [`PaddedSobol`], the handle, `get_2d_f32` twice;
//! * `qmckit_owen_sobol_reseed`: `OwenSobol` reseeded per pixel, `fill_f32` of the 16
//!   indices (per-pixel-seeded Owen-Sobol', the same as `benches/render.rs`);
//! * `sobol_burley_sample_4d`: `sobol_burley::sample_4d(i, 0, seed)`;
//! * `openqmc_sampler_domain`: openqmc-rs, `draw_sample_f32::<4>()` of one domain.
//!
//! A second group generates 65,536 points: PMJ02 ([`qmckit::pmj::fill`], stochastic),
//! PMJ02BN ([`qmckit::pmj::bn::fill`], PMJ02 then nested-flip spreading), and
//! Christensen's construction ([`qmckit::pmj::christensen::fill`]) with 1 and with 100
//! best-candidate trials a point (pmj-cpp's `GetPMJ02Samples` and
//! `GetPMJ02SamplesWithBlueNoise`).
//! Run: `cargo bench --bench pixel -- --measurement-time 2 --warm-up-time 1`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use qmckit::digital::sobol::OwenSobol;
use qmckit::hash::mix64;
use qmckit::pixel::{PaddedSobol, PixelSampler, Randomization, ZSobol, pbrt_f32};
use qmckit::work::Budget;

const SIDE: u32 = 256;
const SPP: usize = 16;
const D: usize = 4;

fn pixel_seed(p: u32) -> u64 {
    mix64(p as u64 ^ 0x9E37_79B9_7F4A_7C15)
}

fn pixels(c: &mut Criterion) {
    let mut group = c.benchmark_group("pixel_256x256x16x4_f32");
    group.throughput(Throughput::Elements(
        (SIDE * SIDE) as u64 * (SPP * D) as u64,
    ));
    let z = ZSobol::new(SIDE, SIDE, SPP as u32, Randomization::FastOwen, 0).expect("valid");
    let padded =
        PaddedSobol::new(SIDE, SIDE, SPP as u32, Randomization::FastOwen, 0).expect("valid");
    let indices: Vec<u32> = (0..SPP as u32).collect();
    group.bench_function("qmckit_zsobol_handle", |bch| {
        bch.iter(|| {
            let z = black_box(&z);
            let mut px = [[0f32; D]; SPP];
            for y in 0..SIDE {
                for x in 0..SIDE {
                    for (i, slot) in px.iter_mut().enumerate() {
                        let mut s = z.start_pixel_sample(x, y, i as u32).expect("in the image");
                        let [a, b] = s.get_2d_f32();
                        let [c, d] = s.get_2d_f32();
                        *slot = [a, b, c, d];
                    }
                    black_box(&mut px);
                }
            }
        })
    });
    group.bench_function("qmckit_zsobol_prepared", |bch| {
        bch.iter(|| {
            let z = black_box(&z);
            let mut px = [[0f32; D]; SPP];
            for y in 0..SIDE {
                for x in 0..SIDE {
                    let d0 = z.pixel_dimension(x, y, 0).expect("in the image");
                    let d2 = z.pixel_dimension(x, y, 2).expect("in the image");
                    for (i, slot) in px.iter_mut().enumerate() {
                        let [a, b] = d0.get_2d(i as u32);
                        let [c, d] = d2.get_2d(i as u32);
                        *slot = [pbrt_f32(a), pbrt_f32(b), pbrt_f32(c), pbrt_f32(d)];
                    }
                    black_box(&mut px);
                }
            }
        })
    });
    group.bench_function("qmckit_padded_sobol", |bch| {
        bch.iter(|| {
            let s = black_box(&padded);
            let mut px = [[0f32; D]; SPP];
            for y in 0..SIDE {
                for x in 0..SIDE {
                    for (i, slot) in px.iter_mut().enumerate() {
                        let mut h = s.start_pixel_sample(x, y, i as u32).expect("in range");
                        let [a, b] = h.get_2d_f32();
                        let [c, d] = h.get_2d_f32();
                        *slot = [a, b, c, d];
                    }
                    black_box(&mut px);
                }
            }
        })
    });
    let base = OwenSobol::new(D, 0).expect("4 dimensions");
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

    let mut group = c.benchmark_group("pmj02_65536");
    group.throughput(Throughput::Elements(65_536));
    group.bench_function("qmckit_pmj_fill", |bch| {
        let mut out = vec![[0u32; 2]; 65_536];
        bch.iter(|| {
            qmckit::pmj::fill(black_box(7), &mut out).expect("length");
            black_box(&mut out);
        })
    });
    let mut work = vec![0u32; qmckit::pmj::bn::workspace_len(65_536).expect("small")];
    group.bench_function("qmckit_pmj02bn", |bch| {
        let mut out = vec![[0u32; 2]; 65_536];
        bch.iter(|| {
            qmckit::pmj::bn::fill(black_box(7), &mut out, &mut work, &Budget::UNLIMITED)
                .expect("length");
            black_box(&mut out);
        })
    });
    let mut work = vec![0u32; qmckit::pmj::christensen::workspace_len(65_536).expect("small")];
    for (name, k) in [
        ("qmckit_pmj02_christensen_k1", 1),
        ("qmckit_pmj02_christensen_k100", 100),
    ] {
        group.bench_function(name, |bch| {
            let mut out = vec![[0u32; 2]; 65_536];
            bch.iter(|| {
                qmckit::pmj::christensen::fill(
                    black_box(7),
                    k,
                    &mut out,
                    &mut work,
                    &Budget::UNLIMITED,
                )
                .expect("length");
                black_box(&mut out);
            })
        });
    }
    group.finish();
}

criterion_group!(benches, pixels);
criterion_main!(benches);
