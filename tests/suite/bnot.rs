//! BNOT (de Goes, Breeden, Ostromoukhov & Desbrun 2012) against its defining properties:
//! every power cell of the result has capacity `1/N` (recomputed from the returned sites
//! and weights, and counted on an independent grid), the transport energy does not
//! increase over the iterations, the points end near their cells' centroids, and the
//! spectrum is blue (low-frequency power far below white noise's 1). The transport
//! distance falls from white noise to jittered to BNOT. CCVT's Voronoi cells, measured
//! exactly, have the equal areas its discrete capacities can give.

use qmckit::analysis::Points;
use qmckit::analysis::transport::ot_distance;
use qmckit::blue_noise::power::PowerDiagram;
use qmckit::blue_noise::{Bnot, Lloyd};
use qmckit::work::Budget;
use qmckit::{Independent, Sampler};

const B: Budget = Budget::DEFAULT;

fn uniform(n: usize, seed: u64) -> Vec<f64> {
    let s = Independent::new(2, seed).unwrap();
    let mut v = vec![0u32; n * 2];
    s.fill(0, &mut v).unwrap();
    v.into_iter().map(qmckit::bits::to_f64).collect()
}

/// `max_i |N A_i - 1|`.
fn capacity_error(areas: &[f64]) -> f64 {
    let n = areas.len() as f64;
    areas
        .iter()
        .map(|a| (a * n - 1.0).abs())
        .fold(0.0, f64::max)
}

#[test]
fn bnot_cells_have_equal_capacity() {
    for (n, torus) in [
        (1u64, false),
        (3, true),
        (100, false),
        (100, true),
        (1000, true),
    ] {
        let t = Bnot::new(n)
            .unwrap()
            .torus(torus)
            .iterations(20)
            .unwrap()
            .seed(n)
            .run(&B)
            .unwrap();
        // Stated tolerance 1e-9 (the solve's default); recomputed from scratch.
        assert!(t.max_error <= 1e-9, "n {n} torus {torus}: {}", t.max_error);
        let d = PowerDiagram::new(&t.sites, &t.weights, torus, &B).unwrap();
        let err = capacity_error(d.areas());
        assert!(err <= 1e-9, "n {n} torus {torus}: {err}");
        assert!(t.sites.iter().all(|x| (0.0..=1.0).contains(x)));
    }
}

#[test]
fn bnot_energy_decreases() {
    for torus in [false, true] {
        let t = Bnot::new(256)
            .unwrap()
            .torus(torus)
            .iterations(40)
            .unwrap()
            .seed(5)
            .run(&B)
            .unwrap();
        assert_eq!(t.energy.len(), 41);
        // Non-increasing up to the solves' tolerance: a capacity error of 1e-9 / N a cell
        // moves the optimal cost by the weights (about the squared spacing, 1/N) times it,
        // 1e-9 / N in all, 2.6e-7 of E ~ 1 / (6 N) here; allowed 1e-6 relative.
        for w in t.energy.windows(2) {
            assert!(w[1] <= w[0] * (1.0 + 1e-6), "torus {torus}: {:?}", t.energy);
        }
        // And markedly: the random start's W2^2 is several times the final.
        let (first, last) = (t.energy[0], *t.energy.last().unwrap());
        assert!(last < 0.5 * first, "torus {torus}: {first} -> {last}");
        // Below the square cells of a grid of N = 256, 1 / (6 N): hexagonal-like cells
        // have a smaller moment (Fejes Tóth: 5 / (18 sqrt 3) / N = 0.1604 / N < 1/6 / N).
        if torus {
            assert!(last < 1.0 / (6.0 * 256.0), "{last}");
            assert!(last > 5.0 / (18.0 * 3f64.sqrt() * 256.0), "{last}");
        }
    }
}

#[test]
fn bnot_points_are_their_cells_centroids() {
    let n = 144;
    let t = Bnot::new(n)
        .unwrap()
        .torus(true)
        .iterations(200)
        .unwrap()
        .seed(9)
        .run(&B)
        .unwrap();
    let d = PowerDiagram::new(&t.sites, &t.weights, true, &B).unwrap();
    let spacing = 1.0 / (n as f64).sqrt();
    let mut worst: f64 = 0.0;
    for i in 0..n as usize {
        let c = d.centroid(i);
        let dx = c[0] - t.sites[2 * i];
        let dy = c[1] - t.sites[2 * i + 1];
        worst = worst.max(dx.hypot(dy));
    }
    assert!(worst < 0.02 * spacing, "{worst} vs spacing {spacing}");
}

/// The mean periodogram `|sum_j exp(-2 pi i k.x_j)|^2 / N` over integer `k` with
/// `0 < |k| <= r` (white noise: 1 on average).
fn low_power(pts: &[f64], r: i64) -> f64 {
    let n = pts.len() / 2;
    let (mut sum, mut count) = (0.0, 0);
    for kx in -r..=r {
        for ky in -r..=r {
            if (kx, ky) == (0, 0) || kx * kx + ky * ky > r * r {
                continue;
            }
            let (mut re, mut im) = (0.0, 0.0);
            for p in pts.chunks(2) {
                let a = -std::f64::consts::TAU * (kx as f64 * p[0] + ky as f64 * p[1]);
                re += a.cos();
                im += a.sin();
            }
            sum += (re * re + im * im) / n as f64;
            count += 1;
        }
    }
    sum / count as f64
}

#[test]
fn bnot_is_blue_noise() {
    let n = 1024;
    // |k| <= 8, a quarter of the blue-noise peak near sqrt(N) = 32.
    let white = low_power(&uniform(n, 3), 8);
    let torus = Bnot::new(n as u64)
        .unwrap()
        .torus(true)
        .seed(1)
        .run(&B)
        .unwrap();
    let square = Bnot::new(n as u64).unwrap().seed(1).run(&B).unwrap();
    let (pt, ps) = (low_power(&torus.sites, 8), low_power(&square.sites, 8));
    assert!(white > 0.7, "white {white}");
    assert!(pt < 0.01, "torus {pt}");
    // In the square the boundary (a jump of the periodized density) leaves power along
    // the axes; still far below white.
    assert!(ps < 0.1, "square {ps}");
}

#[test]
fn ot_distance_falls_from_white_to_jittered_to_bnot() {
    let k = 16;
    let n = k * k;
    let white = uniform(n, 21);
    let u = uniform(n, 22);
    let jittered: Vec<f64> = (0..n)
        .flat_map(|i| {
            [
                ((i % k) as f64 + u[2 * i]) / k as f64,
                ((i / k) as f64 + u[2 * i + 1]) / k as f64,
            ]
        })
        .collect();
    let bnot = Bnot::new(n as u64)
        .unwrap()
        .seed(3)
        .generate(&B)
        .unwrap()
        .to_f64();
    let w = |p: &[f64]| ot_distance(Points::new(p, 2).unwrap(), &B).unwrap();
    let (ww, wj, wb) = (w(&white), w(&jittered), w(&bnot));
    assert!(ww > wj && wj > wb, "{ww} {wj} {wb}");
    // BNOT in the square comes near the grid of cell centres' sqrt(1 / (6 N)) and not
    // below the hexagonal cells' bound sqrt(5 / (18 sqrt 3 N)) by more than boundary
    // effects allow.
    let grid = (1.0 / (6.0 * n as f64)).sqrt();
    assert!(wb < 1.05 * grid && wb > 0.95 * grid, "{wb} vs {grid}");
}

/// CCVT's defining property measured with exact Voronoi cells: with `k` dense-sample
/// points a site, a cell's capacity is `k` of `M = k N` uniform points, so its true area
/// `A_i` is known to about one binomial standard deviation, `sqrt(k) / (k N)`: the
/// spread of `N A_i - 1` can be about `1 / sqrt(k)`. Allowed: standard deviation below
/// `1.5 / sqrt(k)` and maximum below `5 / sqrt(k)` at `k = 64` and `256` (measured 0.095
/// and 0.074, maxima 0.24 and 0.15), smaller at 256 than at 64. Past that the swap pass
/// (which visits only the pairs of a point's owner and nearest site) does not keep up:
/// measured 0.051 at `k = 1024` after 40 iterations and 0.042 after 200, 0.044 at 4096,
/// so the larger `k` are not asserted to scale. Random sites (Poisson–Voronoi, area
/// spread about 0.53) are the contrast; BNOT's capacities (1e-9) are the exact version.
#[test]
fn ccvt_cells_have_equal_areas_measured_exactly() {
    let n = 64;
    let mut spreads = Vec::new();
    for k in [64u32, 256] {
        let t = Lloyd::new(n, 2)
            .unwrap()
            .torus(true)
            .capacity_constrained(true)
            .samples_per_site(k)
            .unwrap()
            .iterations(40)
            .unwrap()
            .seed(11)
            .run(&B)
            .unwrap();
        let d = PowerDiagram::voronoi(&t.sites, true, &B).unwrap();
        let dev: Vec<f64> = d.areas().iter().map(|a| a * n as f64 - 1.0).collect();
        let sd = (dev.iter().map(|x| x * x).sum::<f64>() / n as f64).sqrt();
        let max = dev.iter().map(|x| x.abs()).fold(0.0, f64::max);
        let scale = 1.0 / f64::from(k).sqrt();
        assert!(sd < 1.5 * scale, "k {k}: sd {sd}");
        assert!(max < 5.0 * scale, "k {k}: max {max}");
        spreads.push(sd);
    }
    assert!(spreads[1] < spreads[0], "{spreads:?}");
    let random = PowerDiagram::voronoi(&uniform(n as usize, 5), true, &B).unwrap();
    let dev: Vec<f64> = random.areas().iter().map(|a| a * n as f64 - 1.0).collect();
    let sd = (dev.iter().map(|x| x * x).sum::<f64>() / n as f64).sqrt();
    assert!(sd > 0.3, "random {sd}");
}

#[test]
fn bnot_refuses_bad_parameters() {
    assert!(Bnot::new(0).is_err());
    assert!(Bnot::new(1 << 19).is_err());
    assert!(Bnot::new(10).unwrap().iterations(20_000).is_err());
    assert!(Bnot::new(10).unwrap().tolerance(0.0).is_err());
    assert!(Bnot::new(10).unwrap().tolerance(f64::NAN).is_err());
    let tight = Budget::seconds(1e-6).unwrap();
    assert!(matches!(
        Bnot::new(1 << 18).unwrap().generate(&tight),
        Err(qmckit::Error::OverBudget { .. })
    ));
}

/// On random Heavisides in 2D, BNOT's error falls as fast as jittered sampling's
/// (`N^-(1/2 + 1/(2d)) = N^-0.75` for a set whose cells each hold one point and are cut by
/// the edge in about `sqrt N` of them), against white noise's `N^-0.5`: over
/// `N = 16 .. 256` and 48 integrands the fitted slope is steeper than -0.6 and the error at
/// 256 points below half white noise's. Each integrand gets its own random BNOT set (seed
/// `j`), as the benchmark's factory builds them.
#[test]
fn bnot_integrates_heavisides_at_the_jittered_rate() {
    use qmckit::analysis::integrate::{BenchmarkOptions, Family, benchmark};
    let opts = BenchmarkOptions {
        family: Family::Heaviside,
        dims: 2,
        sizes: vec![16, 32, 64, 128, 256],
        integrands: 48,
        seed: 0,
    };
    let bnot = |n: u64, seed: u64| -> qmckit::Result<Box<dyn Sampler>> {
        Ok(Box::new(Bnot::new(n)?.seed(seed).generate(&B)?))
    };
    let white = |_n: u64, seed: u64| -> qmckit::Result<Box<dyn Sampler>> {
        Ok(Box::new(Independent::new(2, seed)?))
    };
    let b = benchmark(&bnot, &opts, &Budget::UNLIMITED).unwrap();
    let w = benchmark(&white, &opts, &Budget::UNLIMITED).unwrap();
    let (sb, sw) = (b.slope.unwrap(), w.slope.unwrap());
    assert!(sb < -0.6, "BNOT slope {sb}");
    assert!((sw + 0.5).abs() < 0.1, "white-noise slope {sw}");
    let (eb, ew) = (b.rmse[4].1, w.rmse[4].1);
    assert!(eb < 0.5 * ew, "RMSE at 256: BNOT {eb}, white noise {ew}");
}

/// The final regularization: the sites end at the centroids of their own equal-capacity
/// cells. Recomputed from the returned sites and weights: every cell has capacity `1/N`
/// within the solve's tolerance, and the centroidal residual
/// `sqrt(N sum_i A_i |x_i - c_i|^2)` is the last one reported, at most the tolerance asked
/// for, and far below the residual the fixed iterations left.
#[test]
fn bnot_regularization_reaches_capacity_constrained_centroids() {
    for (n, torus) in [(64u64, false), (256, true), (256, false)] {
        let tol = 1e-3;
        let t = Bnot::new(n)
            .unwrap()
            .torus(torus)
            .iterations(10)
            .unwrap()
            .regularize(2000, tol)
            .unwrap()
            .seed(3)
            .run(&B)
            .unwrap();
        let before = t.residual[10];
        let after = *t.residual.last().unwrap();
        assert_eq!(t.residual.len(), t.energy.len());
        assert_eq!(t.residual.len(), 11 + t.regularization_steps as usize);
        let d = PowerDiagram::new(&t.sites, &t.weights, torus, &B).unwrap();
        let err = capacity_error(d.areas());
        assert!(err <= 1e-9, "n {n} torus {torus}: capacity {err}");
        let rho = (0..n as usize)
            .map(|i| {
                let c = d.centroid(i);
                let mut dx = c[0] - t.sites[2 * i];
                let mut dy = c[1] - t.sites[2 * i + 1];
                if torus {
                    dx -= dx.round();
                    dy -= dy.round();
                }
                d.areas()[i] * (dx * dx + dy * dy)
            })
            .sum::<f64>();
        let rho = (n as f64 * rho).sqrt();
        assert!((rho - after).abs() <= 1e-9, "n {n}: {rho} vs {after}");
        assert!(
            after <= tol && after < 0.1 * before,
            "n {n} torus {torus}: residual {before} -> {after} in {} steps",
            t.regularization_steps
        );
        // The energy keeps falling through the regularization (up to the solve's tolerance).
        for w in t.energy[10..].windows(2) {
            assert!(w[1] <= w[0] * (1.0 + 1e-6), "{w:?}");
        }
    }
    assert!(Bnot::new(4).unwrap().regularize(10_001, 1e-3).is_err());
    assert!(Bnot::new(4).unwrap().regularize(10, 0.0).is_err());
    assert!(Bnot::new(4).unwrap().regularize(10, f64::NAN).is_err());
}
