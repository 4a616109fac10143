//! Poisson-disk sampling, qmckit against the `fast_poisson` crate (1.0.2, Bridson with a
//! k-d tree), and void-and-cluster masks against the `blue-noise` crate (0.2.2), side by
//! side in each group. Both Poisson-disk sides use the unit square (not the torus), the
//! radius 0.01 and k = 30 candidates; throughput is per point produced by that side (the
//! densities differ slightly: each side's count at the seed is measured first).

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use qmckit::blue_noise::{PoissonDisk, VoidAndCluster};
use qmckit::work::Budget;

fn poisson(c: &mut Criterion) {
    let r = 0.01;
    let ours = PoissonDisk::new(2, r).unwrap().seed(1);
    let theirs = fast_poisson::Poisson2D::new()
        .with_dimensions([1.0, 1.0], r)
        .with_seed(1);
    let n_ours = ours.generate(&Budget::UNLIMITED).unwrap().count();
    let n_theirs = theirs.generate().len();
    let mut g = c.benchmark_group("poisson_2d_r0.01");
    g.measurement_time(Duration::from_secs(5));
    g.throughput(Throughput::Elements(n_ours as u64));
    g.bench_function("qmckit", |b| {
        b.iter(|| black_box(ours.generate(&Budget::UNLIMITED).unwrap()))
    });
    g.throughput(Throughput::Elements(n_theirs as u64));
    g.bench_function("fast_poisson", |b| b.iter(|| black_box(theirs.generate())));
    g.finish();
}

fn void_and_cluster(c: &mut Criterion) {
    let mut g = c.benchmark_group("void_and_cluster_64x64");
    g.sample_size(10);
    g.throughput(Throughput::Elements(64 * 64));
    let ours = VoidAndCluster::new(64, 64).unwrap();
    g.bench_function("qmckit", |b| {
        b.iter(|| black_box(ours.generate(&Budget::UNLIMITED).unwrap()))
    });
    g.bench_function("blue-noise", |b| {
        b.iter(|| {
            let config = blue_noise::BlueNoiseConfig {
                width: 64,
                height: 64,
                sigma: 1.5,
                initial_density: 0.1,
                seed: Some(1),
                verbose: false,
            };
            black_box(
                blue_noise::BlueNoiseGenerator::new(config)
                    .unwrap()
                    .generate()
                    .unwrap(),
            )
        })
    });
    g.finish();
}

criterion_group!(benches, poisson, void_and_cluster);
criterion_main!(benches);
