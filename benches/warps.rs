//! Warp throughput: qmckit's `f32` warps (`warp`, through `libm`), its fixed-point warps
//! (`warp::fixed`, feature `fixed`), and disk points against the `lds-rs` crate (0.1.11).
//!
//! Every benchmark maps `N` points per iteration and reports per-point throughput
//! (`Throughput::Elements(N)`). Inputs are precomputed outside the timed loop: the first `N`
//! points of Owen-scrambled 2D Sobol' (`Scrambled<Sobol, FastOwen>`), as `f32` through
//! `bits::to_f32` or as `U0F32` (same bits). Inverses take the matching warp's outputs. Outputs
//! go to a buffer that is `black_box`ed after the loop; the input slice goes through
//! `black_box` every iteration.
//!
//! Groups:
//! * `warp_f32`: every `sample_*` of `qmckit::warp`, and the inverses of the disk (polar,
//!   concentric), hemisphere (uniform, cosine), sphere and triangle maps. The Gaussian
//!   entries both produce two normals a point: `box_muller` one pair, `normal_inv_cdf` the
//!   quantile of each coordinate. The spherical polygon warps go through the free functions,
//!   which validate and build their frame every call, and their geometry goes through
//!   `black_box` per point, as when the shading point moves, so the set-up cannot be hoisted
//!   out of the loop; the `_prepared` entries sample a `SphericalTriangle` /
//!   `SphericalRectangle` built once (a fixed light seen from a fixed point).
//! * `warp_fixed`: the same ids for the five fixed-point warps and their inverses (needs
//!   `--features fixed`; without it the group is skipped with a note).
//! * `disk_peers`: the polar and concentric maps on the same inputs; a "pbrt-style" textbook
//!   polar map with std's `f32::sin_cos` and `sqrt` (the cost of libm against the platform's
//!   math library); and end-to-end Halton disk points, bases (2, 3), indices `1..=N`:
//!   `lds_rs::Disk` (`f64`, `reseed(0)` then `N` `pop()`s) against qmckit (`Halton::fill`,
//!   `to_f32`, polar map), the latter also with the std polar map. A check at start-up
//!   asserts that the three end-to-end variants produce the same points (to `f32` accuracy).

use std::f32::consts::PI;
use std::hint::black_box;
use std::time::Duration;

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, Throughput, criterion_group, criterion_main};
use qmckit::bits::to_f32;
use qmckit::randomize::{FastOwen, Scrambled};
use qmckit::warp::{disk, gaussian, sphere, spherical, triangle};
use qmckit::{Halton, Sampler, Sobol};

/// Points mapped per iteration.
const N: usize = 4096;

/// Seed of the Owen scramble of the inputs.
const SEED: u64 = 0x5EED_0000_2D01;

/// The cone's `cos theta_max`.
const COS_THETA_MAX: f32 = 0.9;

/// The spherical triangle, seen from the origin.
const TRIANGLE: [[f32; 3]; 3] = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];

/// The spherical rectangle: the unit square centred above the origin at height 1.
const RECT_CORNER: [f32; 3] = [-0.5, -0.5, 1.0];
const RECT_EX: [f32; 3] = [1.0, 0.0, 0.0];
const RECT_EY: [f32; 3] = [0.0, 1.0, 0.0];

/// The first `N` points of Owen-scrambled 2D Sobol', as 0.32 fractions.
fn owen_sobol() -> Vec<[u32; 2]> {
    let s = Scrambled::new(Sobol::new(2).expect("2 dims"), FastOwen::new(SEED));
    let mut flat = vec![0u32; 2 * N];
    s.fill(0, &mut flat).expect("in range");
    flat.chunks_exact(2).map(|p| [p[0], p[1]]).collect()
}

fn configure(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .measurement_time(Duration::from_millis(1500))
        .warm_up_time(Duration::from_millis(500))
        .sample_size(20)
        .throughput(Throughput::Elements(N as u64));
}

/// Benchmarks `out[k] = f(inputs[k])` over all inputs.
fn bench_map<I: Copy, O: Copy + Default>(
    group: &mut BenchmarkGroup<'_, WallTime>,
    id: &str,
    inputs: &[I],
    f: impl Fn(I) -> O,
) {
    let mut out = vec![O::default(); inputs.len()];
    group.bench_function(id, |bch| {
        bch.iter(|| {
            for (slot, &x) in out.iter_mut().zip(black_box(inputs)) {
                *slot = f(x);
            }
            black_box(&mut out);
        })
    });
}

/// The textbook polar map (pbrt-v3's `UniformSampleDisk`) with std's `f32` math.
#[inline]
fn pbrt_polar(u: [f32; 2]) -> [f32; 2] {
    let r = u[1].sqrt();
    let theta = 2.0 * PI * u[0];
    let (s, c) = theta.sin_cos();
    [r * c, r * s]
}

/// 1. The `f32` warps.
fn warp_f32(c: &mut Criterion) {
    let u: Vec<[f32; 2]> = owen_sobol().into_iter().map(|p| p.map(to_f32)).collect();
    let mut group = c.benchmark_group("warp_f32");
    configure(&mut group);

    bench_map(
        &mut group,
        "sample/disk_polar",
        &u,
        disk::sample_uniform_disk_polar,
    );
    bench_map(
        &mut group,
        "sample/disk_concentric",
        &u,
        disk::sample_uniform_disk_concentric,
    );
    bench_map(
        &mut group,
        "sample/hemisphere_uniform",
        &u,
        sphere::sample_uniform_hemisphere,
    );
    bench_map(
        &mut group,
        "sample/hemisphere_cosine",
        &u,
        sphere::sample_cosine_hemisphere,
    );
    bench_map(
        &mut group,
        "sample/sphere",
        &u,
        sphere::sample_uniform_sphere,
    );
    let cos_max = black_box(COS_THETA_MAX);
    bench_map(&mut group, "sample/cone", &u, |x| {
        sphere::sample_uniform_cone(x, cos_max)
    });
    bench_map(
        &mut group,
        "sample/triangle",
        &u,
        triangle::sample_uniform_triangle,
    );
    bench_map(&mut group, "sample/spherical_triangle", &u, |x| {
        spherical::sample_spherical_triangle(black_box(TRIANGLE), black_box([0.0; 3]), x).ok()
    });
    bench_map(&mut group, "sample/spherical_rectangle", &u, |x| {
        spherical::sample_spherical_rectangle(
            black_box([0.0; 3]),
            black_box(RECT_CORNER),
            black_box(RECT_EX),
            black_box(RECT_EY),
            x,
        )
        .ok()
    });
    // The prepared values: validation and frame once, outside the loop.
    let tri = spherical::SphericalTriangle::new(TRIANGLE, [0.0; 3]).expect("valid triangle");
    bench_map(&mut group, "sample/spherical_triangle_prepared", &u, |x| {
        black_box(&tri).sample(x)
    });
    let rect = spherical::SphericalRectangle::new([0.0; 3], RECT_CORNER, RECT_EX, RECT_EY)
        .expect("valid rectangle");
    bench_map(&mut group, "sample/spherical_rectangle_prepared", &u, |x| {
        black_box(&rect).sample(x)
    });
    bench_map(
        &mut group,
        "sample/box_muller",
        &u,
        gaussian::sample_box_muller,
    );
    bench_map(&mut group, "sample/normal_inv_cdf", &u, |x| {
        x.map(gaussian::sample_normal)
    });

    let polar: Vec<_> = u
        .iter()
        .map(|&x| disk::sample_uniform_disk_polar(x))
        .collect();
    let conc: Vec<_> = u
        .iter()
        .map(|&x| disk::sample_uniform_disk_concentric(x))
        .collect();
    let hemi: Vec<_> = u
        .iter()
        .map(|&x| sphere::sample_uniform_hemisphere(x))
        .collect();
    let cosw: Vec<_> = u
        .iter()
        .map(|&x| sphere::sample_cosine_hemisphere(x))
        .collect();
    let sph: Vec<_> = u
        .iter()
        .map(|&x| sphere::sample_uniform_sphere(x))
        .collect();
    let tri: Vec<_> = u
        .iter()
        .map(|&x| triangle::sample_uniform_triangle(x))
        .collect();
    bench_map(
        &mut group,
        "invert/disk_polar",
        &polar,
        disk::invert_uniform_disk_polar,
    );
    bench_map(
        &mut group,
        "invert/disk_concentric",
        &conc,
        disk::invert_uniform_disk_concentric,
    );
    bench_map(
        &mut group,
        "invert/hemisphere_uniform",
        &hemi,
        sphere::invert_uniform_hemisphere,
    );
    bench_map(
        &mut group,
        "invert/hemisphere_cosine",
        &cosw,
        sphere::invert_cosine_hemisphere,
    );
    bench_map(
        &mut group,
        "invert/sphere",
        &sph,
        sphere::invert_uniform_sphere,
    );
    bench_map(
        &mut group,
        "invert/triangle",
        &tri,
        triangle::invert_uniform_triangle,
    );
    group.finish();
}

/// 2. The fixed-point warps, with the same ids as their `f32` counterparts.
#[cfg(feature = "fixed")]
fn warp_fixed(c: &mut Criterion) {
    use fixed::types::U0F32;
    use qmckit::warp::fixed as fw;

    let u: Vec<[U0F32; 2]> = owen_sobol()
        .into_iter()
        .map(|p| p.map(U0F32::from_bits))
        .collect();
    let mut group = c.benchmark_group("warp_fixed");
    configure(&mut group);

    bench_map(
        &mut group,
        "sample/disk_polar",
        &u,
        fw::sample_uniform_disk_polar,
    );
    bench_map(
        &mut group,
        "sample/disk_concentric",
        &u,
        fw::sample_uniform_disk_concentric,
    );
    bench_map(
        &mut group,
        "sample/hemisphere_uniform",
        &u,
        fw::sample_uniform_hemisphere,
    );
    bench_map(
        &mut group,
        "sample/hemisphere_cosine",
        &u,
        fw::sample_cosine_hemisphere,
    );
    bench_map(
        &mut group,
        "sample/triangle",
        &u,
        fw::sample_uniform_triangle,
    );

    let polar: Vec<_> = u
        .iter()
        .map(|&x| fw::sample_uniform_disk_polar(x))
        .collect();
    let conc: Vec<_> = u
        .iter()
        .map(|&x| fw::sample_uniform_disk_concentric(x))
        .collect();
    let hemi: Vec<_> = u
        .iter()
        .map(|&x| fw::sample_uniform_hemisphere(x))
        .collect();
    let cosw: Vec<_> = u.iter().map(|&x| fw::sample_cosine_hemisphere(x)).collect();
    let tri: Vec<_> = u.iter().map(|&x| fw::sample_uniform_triangle(x)).collect();
    bench_map(
        &mut group,
        "invert/disk_polar",
        &polar,
        fw::invert_uniform_disk_polar,
    );
    bench_map(
        &mut group,
        "invert/disk_concentric",
        &conc,
        fw::invert_uniform_disk_concentric,
    );
    bench_map(
        &mut group,
        "invert/hemisphere_uniform",
        &hemi,
        fw::invert_uniform_hemisphere,
    );
    bench_map(
        &mut group,
        "invert/hemisphere_cosine",
        &cosw,
        fw::invert_cosine_hemisphere,
    );
    bench_map(
        &mut group,
        "invert/triangle",
        &tri,
        fw::invert_uniform_triangle,
    );
    group.finish();
}

/// 2. (Skipped: the fixed-point warps need `--features fixed`.)
#[cfg(not(feature = "fixed"))]
fn warp_fixed(_c: &mut Criterion) {
    eprintln!("warp_fixed skipped: run with `--features fixed`");
}

/// `N` Halton (2, 3) disk points from index 1, qmckit end to end: fill, `to_f32`, `map`.
fn halton_disk(
    h: &Halton,
    buf: &mut [u32],
    out: &mut [[f32; 2]],
    map: impl Fn([f32; 2]) -> [f32; 2],
) {
    h.fill(1, buf).expect("in range");
    for (slot, p) in out.iter_mut().zip(buf.chunks_exact(2)) {
        *slot = map([to_f32(p[0]), to_f32(p[1])]);
    }
}

/// `N` points of `lds_rs::Disk` from its start (its indices `1..=N`).
fn lds_disk(d: &mut lds_rs::Disk, out: &mut [[f64; 2]]) {
    d.reseed(0);
    for slot in out.iter_mut() {
        *slot = d.pop();
    }
}

/// 3. Disk points against lds-rs and a std-math polar map.
fn disk_peers(c: &mut Criterion) {
    let u: Vec<[f32; 2]> = owen_sobol().into_iter().map(|p| p.map(to_f32)).collect();
    let h = Halton::new(2).expect("2 dims");
    let mut lds = lds_rs::Disk::new([2, 3]);
    let mut buf = vec![0u32; 2 * N];
    let mut out32 = vec![[0f32; 2]; N];
    let mut out64 = vec![[0f64; 2]; N];

    // The end-to-end variants compute the same points.
    let mut std32 = vec![[0f32; 2]; N];
    halton_disk(&h, &mut buf, &mut out32, disk::sample_uniform_disk_polar);
    halton_disk(&h, &mut buf, &mut std32, pbrt_polar);
    lds_disk(&mut lds, &mut out64);
    for ((a, b), e) in out32.iter().zip(&std32).zip(&out64) {
        for k in 0..2 {
            assert!(
                (a[k] as f64 - e[k]).abs() < 1e-6,
                "qmckit {a:?} vs lds-rs {e:?}"
            );
            assert!(
                (b[k] as f64 - e[k]).abs() < 1e-6,
                "std {b:?} vs lds-rs {e:?}"
            );
        }
    }

    let mut group = c.benchmark_group("disk_peers");
    configure(&mut group);
    bench_map(
        &mut group,
        "warp_only/qmckit_polar",
        &u,
        disk::sample_uniform_disk_polar,
    );
    bench_map(
        &mut group,
        "warp_only/qmckit_concentric",
        &u,
        disk::sample_uniform_disk_concentric,
    );
    bench_map(&mut group, "warp_only/pbrt_polar_std", &u, pbrt_polar);
    group.bench_function("halton_e2e/lds_rs_disk_f64", |bch| {
        bch.iter(|| {
            lds_disk(black_box(&mut lds), &mut out64);
            black_box(&mut out64);
        })
    });
    group.bench_function("halton_e2e/qmckit_polar", |bch| {
        bch.iter(|| {
            halton_disk(
                black_box(&h),
                &mut buf,
                &mut out32,
                disk::sample_uniform_disk_polar,
            );
            black_box(&mut out32);
        })
    });
    group.bench_function("halton_e2e/qmckit_polar_std", |bch| {
        bch.iter(|| {
            halton_disk(black_box(&h), &mut buf, &mut out32, pbrt_polar);
            black_box(&mut out32);
        })
    });
    group.finish();
}

criterion_group!(benches, warp_f32, warp_fixed, disk_peers);
criterion_main!(benches);
