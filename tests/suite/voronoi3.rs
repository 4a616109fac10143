//! The exact 3D Voronoi cells and Lloyd relaxation on exact cells, against stated
//! properties: the cells of any site set tile the domain (volumes sum to 1 to 1e-12),
//! known configurations (two sites halve the cube; a regular grid's cells are its cubes,
//! with the cube's centroid and second moment `a^5 / 4`), an independent Monte Carlo
//! estimate of the volumes and centroids (brute-force nearest site, 5 standard errors),
//! Lloyd's exact energy never increases and equalizes the cell volumes, and the budget and
//! deadline stop both.
// The coordinate loops index several arrays at once.
#![allow(clippy::needless_range_loop)]

use qmckit::Error;
use qmckit::blue_noise::Lloyd;
use qmckit::blue_noise::power::PowerDiagram;
use qmckit::blue_noise::voronoi3::Voronoi3;
use qmckit::work::Budget;
use std::time::{Duration, Instant};

const B: Budget = Budget::DEFAULT;

use crate::common::independent_set as uniform;

#[test]
fn two_sites_halve_the_cube() {
    for torus in [false, true] {
        let v = Voronoi3::new(&[0.25, 0.5, 0.5, 0.75, 0.5, 0.5], torus, &B).unwrap();
        for i in 0..2 {
            assert!((v.volume(i) - 0.5).abs() < 1e-15, "{torus} {}", v.volume(i));
            let c = v.centroid(i);
            let want = [0.25 + 0.5 * i as f64, 0.5, 0.5];
            for k in 0..3 {
                assert!((c[k] - want[k]).abs() < 1e-15, "{torus} {c:?}");
            }
            // [0, 1/2] x [0, 1]^2 about (1/4, 1/2, 1/2): 1/96 + 2 (1/2) (1/12) = 9/96; on
            // the torus each half is a slab of the same shape about its site.
            assert!((v.moment(i) - 9.0 / 96.0).abs() < 1e-15, "{}", v.moment(i));
        }
    }
    // Off-centre in the cube: sites at x = 0.1 and 0.3 split at x = 0.2.
    let v = Voronoi3::new(&[0.1, 0.2, 0.9, 0.3, 0.2, 0.9], false, &B).unwrap();
    assert!((v.volume(0) - 0.2).abs() < 1e-15);
    assert!((v.centroid(1)[0] - 0.6).abs() < 1e-15);
}

#[test]
fn grid_cells_are_cubes() {
    for k in [2usize, 3, 4, 5] {
        let a = 1.0 / k as f64;
        let mut sites = Vec::new();
        for z in 0..k {
            for y in 0..k {
                for x in 0..k {
                    sites.extend([x, y, z].map(|c| (c as f64 + 0.5) * a));
                }
            }
        }
        for torus in [false, true] {
            let v = Voronoi3::new(&sites, torus, &B).unwrap();
            for (i, s) in sites.chunks(3).enumerate() {
                assert!(
                    (v.volume(i) - a * a * a).abs() < 1e-14,
                    "k {k}: {}",
                    v.volume(i)
                );
                let c = v.centroid(i);
                for j in 0..3 {
                    assert!((c[j] - s[j]).abs() < 1e-13, "k {k} {torus}: {c:?} {s:?}");
                }
                assert!((v.moment(i) - a.powi(5) / 4.0).abs() < 1e-14 * a.powi(3));
            }
        }
    }
}

/// Brute-force nearest site (periodic on the torus) of `m` uniform points: each cell's
/// count and summed offset from its site.
fn monte_carlo(sites: &[f64], torus: bool, m: usize) -> (Vec<f64>, Vec<[f64; 3]>) {
    let n = sites.len() / 3;
    let (mut count, mut first) = (vec![0.0; n], vec![[0.0; 3]; n]);
    for y in uniform(m, 3, 777).chunks(3) {
        let mut best = (0, f64::INFINITY, [0.0; 3]);
        for (i, s) in sites.chunks(3).enumerate() {
            let d = [0, 1, 2].map(|k| {
                let t = y[k] - s[k];
                if torus { t - t.round() } else { t }
            });
            let e = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if e < best.1 {
                best = (i, e, d);
            }
        }
        count[best.0] += 1.0;
        for k in 0..3 {
            first[best.0][k] += best.2[k];
        }
    }
    (count, first)
}

#[test]
fn cells_tile_the_domain_and_match_monte_carlo() {
    for torus in [false, true] {
        for n in [1usize, 2, 7, 40, 1000] {
            let sites = uniform(n, 3, n as u64);
            let v = Voronoi3::new(&sites, torus, &B).unwrap();
            let total: f64 = v.volumes().iter().sum();
            assert!((total - 1.0).abs() < 1e-12, "n {n} torus {torus}: {total}");
            assert!(v.volumes().iter().all(|&x| x > 0.0));
        }
        // Volumes and centroids against 2^18 independent uniform points.
        let (n, m) = (20usize, 1usize << 18);
        let sites = uniform(n, 3, 99);
        let v = Voronoi3::new(&sites, torus, &B).unwrap();
        let (count, first) = monte_carlo(&sites, torus, m);
        for i in 0..n {
            let p = v.volume(i);
            let se = (p * (1.0 - p) / m as f64).sqrt();
            assert!((count[i] / m as f64 - p).abs() < 5.0 * se, "{torus} {i}");
            // The centroid offset: each coordinate's spread within a cell is below 1.
            for k in 0..3 {
                let mc = first[i][k] / count[i];
                let exact = v.centroid(i)[k] - sites[3 * i + k];
                assert!(
                    (mc - exact).abs() < 5.0 / count[i].sqrt(),
                    "{torus} {i} {k}"
                );
            }
        }
    }
}

#[test]
fn voronoi3_refuses_bad_input_and_honours_the_budget() {
    assert!(matches!(
        Voronoi3::new(&[], false, &B),
        Err(Error::ZeroPoints)
    ));
    assert!(Voronoi3::new(&[0.1, 0.2], false, &B).is_err());
    assert!(Voronoi3::new(&[0.1, 0.2, 1.5], false, &B).is_err());
    assert!(Voronoi3::new(&[0.1, f64::NAN, 0.5], false, &B).is_err());
    assert!(Voronoi3::new(&[0.1, 0.2, 0.3, 0.1, 0.2, 0.3], true, &B).is_err());
    let sites = uniform(20_000, 3, 1);
    let tight = Budget::seconds(1e-6).unwrap();
    assert!(matches!(
        Voronoi3::new(&sites, false, &tight),
        Err(Error::OverBudget { .. })
    ));
    let past = Budget::seconds(0.1).unwrap().started();
    std::thread::sleep(Duration::from_millis(130));
    assert!(matches!(
        Voronoi3::new(&sites[..3000], false, &past),
        Err(Error::OutOfTime { .. })
    ));
}

/// Relative standard deviation of the volumes.
fn spread(v: &[f64]) -> f64 {
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / v.len() as f64).sqrt() / mean
}

/// Lloyd on exact cells: the energy (the sum of the cells' second moments) never
/// increases (1e-12 relative), the cells tile the domain, and relaxation equalizes the
/// volumes: the random start's spread is about that of Poisson–Voronoi cells (0.42 in 3D,
/// 0.53 in 2D; allowed above 0.3), after 200 iterations below 0.1 (a centroidal Voronoi
/// tessellation of a local minimum; measured 0.02 to 0.05 for these seeds).
#[test]
fn exact_lloyd_descends_and_equalizes_the_cells() {
    for (d, torus) in [(2, false), (2, true), (3, false), (3, true)] {
        let run = |it| {
            Lloyd::new(128, d)
                .unwrap()
                .torus(torus)
                .iterations(it)
                .unwrap()
                .seed(3)
                .run(&B)
                .unwrap()
        };
        let (start, t) = (run(0), run(200));
        for w in t.energy.windows(2) {
            assert!(w[1] <= w[0] * (1.0 + 1e-12), "d {d} torus {torus}: {w:?}");
        }
        assert!(t.counts.is_empty() && t.volumes.len() == 128);
        assert!((t.volumes.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(
            spread(&start.volumes) > 0.3,
            "d {d}: {}",
            spread(&start.volumes)
        );
        assert!(
            spread(&t.volumes) < 0.1,
            "d {d} {torus}: {}",
            spread(&t.volumes)
        );
        // The volumes are those of an independent diagram of the returned sites.
        if d == 2 {
            let p = PowerDiagram::voronoi(&t.sites, torus, &B).unwrap();
            assert!(spread(p.areas()) < 0.1);
        }
    }
}

/// A started budget whose deadline falls inside the run stops exact Lloyd with
/// [`Error::OutOfTime`] soon after the deadline (a loop that never read the clock would
/// finish instead); a budget below the estimate refuses it before it starts.
#[test]
fn exact_lloyd_stops_at_the_deadline() {
    let l = Lloyd::new(2000, 3).unwrap().iterations(40).unwrap().seed(1);
    let t = Instant::now();
    l.run(&Budget::UNLIMITED).unwrap();
    let took = t.elapsed().as_secs_f64();
    // A budget the estimate fits in and at least the time taken, its deadline (GRACE =
    // 1.25 times the budget after the start) half way through the run.
    let seconds = l.cost().seconds().max(took);
    let budget = Budget::seconds(seconds).unwrap().started();
    let wait = 1.25 * seconds - 0.5 * took;
    std::thread::sleep(Duration::from_secs_f64(wait));
    let t = Instant::now();
    let got = l.run(&budget);
    let ran = t.elapsed().as_secs_f64();
    assert!(matches!(got, Err(Error::OutOfTime { .. })), "{got:?}");
    assert!(ran < 0.5 * took + 0.25, "stopped after {ran} s of {took} s");
    let tight = Budget::seconds(1e-6).unwrap();
    assert!(matches!(l.run(&tight), Err(Error::OverBudget { .. })));
}
