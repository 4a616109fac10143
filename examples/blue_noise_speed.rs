//! Side-by-side timings of the blue-noise constructions in one run: qmckit's Poisson disk
//! against the `fast_poisson` crate (same radius, unit square, k = 30; qmckit also at k = 45,
//! where its density passes fast_poisson's), and qmckit's
//! void-and-cluster against the `blue-noise` crate (same size, sigma 1.5). One line per
//! run: `impl task points density seconds ns_per_point` (density: N r^2). Used by
//! `scripts/blue_noise_speed.py`, which adds SciPy's `qmc.PoissonDisk`.
//!
//! `cargo run --release --features analysis --example blue_noise_speed -- [R] [MASK_SIDE]`

use std::time::Instant;

use qmckit::blue_noise::{PoissonDisk, VoidAndCluster};
use qmckit::work::Budget;

fn line(name: &str, task: &str, n: usize, density: f64, secs: f64) {
    println!(
        "{name} {task} {n} {density:.4} {secs:.4} {:.1}",
        secs / n as f64 * 1e9
    );
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let r: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(0.00078);
    let side: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(256);
    let task = format!("poisson_r{r}");
    for seed in 1..=2 {
        let t = Instant::now();
        let s = PoissonDisk::new(2, r)
            .unwrap()
            .seed(seed)
            .generate(&Budget::UNLIMITED)
            .unwrap();
        let secs = t.elapsed().as_secs_f64();
        line("qmckit", &task, s.count(), s.count() as f64 * r * r, secs);
        // 45 candidates: at least fast_poisson's density (it draws the radius uniformly in
        // [r, 2r], which packs more points than Bridson's uniform annulus).
        let t = Instant::now();
        let s = PoissonDisk::new(2, r)
            .unwrap()
            .candidates(45)
            .unwrap()
            .seed(seed)
            .generate(&Budget::UNLIMITED)
            .unwrap();
        let secs = t.elapsed().as_secs_f64();
        line(
            "qmckit_k45",
            &task,
            s.count(),
            s.count() as f64 * r * r,
            secs,
        );
        let t = Instant::now();
        let p = fast_poisson::Poisson2D::new()
            .with_dimensions([1.0, 1.0], r)
            .with_seed(seed)
            .generate();
        let secs = t.elapsed().as_secs_f64();
        line("fast_poisson", &task, p.len(), p.len() as f64 * r * r, secs);
    }
    let task = format!("void_and_cluster_{side}x{side}");
    let t = Instant::now();
    let m = VoidAndCluster::new(side, side)
        .unwrap()
        .generate(&Budget::UNLIMITED)
        .unwrap();
    line(
        "qmckit",
        &task,
        m.ranks().len(),
        0.0,
        t.elapsed().as_secs_f64(),
    );
    if side <= 128 {
        let config = blue_noise::BlueNoiseConfig {
            width: side,
            height: side,
            sigma: 1.5,
            initial_density: 0.1,
            seed: Some(1),
            verbose: false,
        };
        let t = Instant::now();
        let b = blue_noise::BlueNoiseGenerator::new(config)
            .unwrap()
            .generate()
            .unwrap();
        line(
            "blue-noise",
            &task,
            b.data.len(),
            0.0,
            t.elapsed().as_secs_f64(),
        );
    }
}
