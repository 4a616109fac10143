//! Power diagrams, the semi-discrete transport solve and the transport distance against
//! independent facts: the cells tile the domain (areas sum to 1), zero weights give the
//! nearest-site classification (brute force on a fine grid) and any weights the
//! least-power-distance one, cells of hand-solved configurations (bisectors moved by
//! `w / (2 d)`), the area derivatives of Aurenhammer, Hoffmann & Aronov against finite
//! differences, equal capacities after the solve, and the closed forms of the distance
//! (one point; the grid of cell centres, `1 / (6 N)`).

use qmckit::analysis::Points;
use qmckit::analysis::transport::{ot_cost, ot_distance};
use qmckit::blue_noise::power::PowerDiagram;
use qmckit::blue_noise::transport;
use qmckit::work::Budget;
use qmckit::{Independent, Sampler};

fn uniform(n: usize, seed: u64) -> Vec<f64> {
    let s = Independent::new(2, seed).unwrap();
    let mut v = vec![0u32; n * 2];
    s.fill(0, &mut v).unwrap();
    v.into_iter().map(qmckit::bits::to_f64).collect()
}

/// Weights spread over `[0, scale)`, from the independent generator.
fn weights(n: usize, scale: f64, seed: u64) -> Vec<f64> {
    uniform(n, seed).iter().take(n).map(|u| u * scale).collect()
}

const B: Budget = Budget::DEFAULT;

#[test]
fn areas_sum_to_one() {
    for n in [1usize, 2, 3, 7, 100, 1000, 5000] {
        let sites = uniform(n, n as u64);
        for torus in [false, true] {
            for scale in [0.0, 0.3 / n as f64, 3.0 / n as f64] {
                let w = weights(n, scale, 77);
                let d = PowerDiagram::new(&sites, &w, torus, &B).unwrap();
                let sum: f64 = d.areas().iter().sum();
                assert!(
                    (sum - 1.0).abs() < 1e-12,
                    "n {n} torus {torus} scale {scale}: {sum}"
                );
                assert!(d.areas().iter().all(|&a| a >= 0.0));
            }
        }
    }
}

/// Squared distance, periodic on the torus.
fn dist2(a: [f64; 2], b: [f64; 2], torus: bool) -> f64 {
    (0..2)
        .map(|k| {
            let t = (a[k] - b[k]).abs();
            let t = if torus { t.min(1.0 - t) } else { t };
            t * t
        })
        .sum()
}

/// `true` when `x` lies in the convex counter-clockwise polygon `poly` (closed).
fn inside(poly: &[[f64; 2]], x: [f64; 2]) -> bool {
    poly.len() >= 3
        && (0..poly.len()).all(|k| {
            let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
            (b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0]) >= -1e-12
        })
}

/// Every point of a fine grid lies in the cell of a site of least power distance (found
/// by brute force over all sites), and in no cell of a site that is worse by more than
/// rounding.
fn check_classification(sites: &[f64], w: &[f64], torus: bool) {
    let n = w.len();
    let d = PowerDiagram::new(sites, w, torus, &B).unwrap();
    let p = |i: usize| [sites[2 * i], sites[2 * i + 1]];
    let m = 160;
    let shifts: &[[f64; 2]] = if torus {
        &[
            [0.0, 0.0],
            [1.0, 0.0],
            [-1.0, 0.0],
            [0.0, 1.0],
            [0.0, -1.0],
            [1.0, 1.0],
            [1.0, -1.0],
            [-1.0, 1.0],
            [-1.0, -1.0],
        ]
    } else {
        &[[0.0, 0.0]]
    };
    for gy in 0..m {
        for gx in 0..m {
            let x = [(gx as f64 + 0.37) / m as f64, (gy as f64 + 0.61) / m as f64];
            let pow: Vec<f64> = (0..n).map(|i| dist2(x, p(i), torus) - w[i]).collect();
            let best = pow.iter().copied().fold(f64::INFINITY, f64::min);
            let mut found = 0;
            for (i, &pow_i) in pow.iter().enumerate() {
                let cell = d.cell(i);
                if shifts
                    .iter()
                    .any(|s| inside(cell, [x[0] + s[0], x[1] + s[1]]))
                {
                    found += 1;
                    assert!(
                        pow_i <= best + 1e-9,
                        "torus {torus}: {x:?} in cell {i} at power {pow_i} > {best}"
                    );
                }
            }
            assert!(found >= 1, "torus {torus}: {x:?} in no cell");
        }
    }
}

#[test]
fn zero_weights_give_the_voronoi_diagram() {
    for (n, seed) in [(1usize, 1u64), (2, 2), (9, 3), (60, 4)] {
        let sites = uniform(n, seed);
        for torus in [false, true] {
            check_classification(&sites, &vec![0.0; n], torus);
            let v = PowerDiagram::voronoi(&sites, torus, &B).unwrap();
            // A Voronoi cell holds its site.
            for i in 0..n {
                let s = [sites[2 * i], sites[2 * i + 1]];
                let c = v.cell(i);
                let shifted = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]];
                assert!(
                    shifted.iter().any(|t| inside(c, [s[0] + t[0], s[1] + t[1]])
                        || inside(c, [s[0] - t[0], s[1] - t[1]])),
                    "n {n} torus {torus}: site {i} outside its cell"
                );
            }
        }
    }
}

#[test]
fn weighted_cells_are_the_least_power_distance() {
    for (n, seed) in [(5usize, 5u64), (40, 6)] {
        let sites = uniform(n, seed);
        for torus in [false, true] {
            check_classification(&sites, &weights(n, 2.0 / n as f64, seed + 10), torus);
        }
    }
}

#[test]
fn hand_solved_cells() {
    // Four sites at the centres of the quarters: the quarters, each of second moment
    // about its centre s^4 / 6 with s = 1/2.
    let sites = [0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75];
    for torus in [false, true] {
        let d = PowerDiagram::voronoi(&sites, torus, &B).unwrap();
        for i in 0..4 {
            assert!((d.area(i) - 0.25).abs() < 1e-15);
            let c = d.centroid(i);
            assert!((c[0] - sites[2 * i]).abs() < 1e-15 && (c[1] - sites[2 * i + 1]).abs() < 1e-15);
            assert!((d.moment(i) - 1.0 / 96.0).abs() < 1e-16);
        }
    }
    // Two sites on the midline, weight w on the first. In the square the bisector moves
    // from x = 1/2 by w / (2 |p_1 - p_0|) = w towards the second: area 1/2 + w, centroid
    // x = (1/2 + w) / 2. On the torus both bisectors move (the second at x = 0 to -w):
    // area 1/2 + 2 w, centroid x = 1/4.
    for w in [0.0, 0.05, 0.2, -0.1] {
        let sites = [0.25, 0.5, 0.75, 0.5];
        let d = PowerDiagram::new(&sites, &[w, 0.0], false, &B).unwrap();
        assert!(
            (d.area(0) - (0.5 + w)).abs() < 1e-15,
            "w {w}: {}",
            d.area(0)
        );
        assert!((d.centroid(0)[0] - (0.5 + w) / 2.0).abs() < 1e-15);
        assert!((d.centroid(0)[1] - 0.5).abs() < 1e-15);
        let t = PowerDiagram::new(&sites, &[w, 0.0], true, &B).unwrap();
        assert!(
            (t.area(0) - (0.5 + 2.0 * w)).abs() < 1e-15,
            "w {w}: {}",
            t.area(0)
        );
        assert!((t.centroid(0)[0] - 0.25).abs() < 1e-15);
        // Its second moment about the site: the strip [-w, 1/2 + w] x [0, 1].
        let (a, b) = (-w - 0.25, 0.25 + w);
        let want = (b.powi(3) - a.powi(3)) / 3.0 + (b - a) / 12.0;
        assert!((t.moment(0) - want).abs() < 1e-15, "w {w}");
    }
    // A weight large enough empties the other cell.
    let d = PowerDiagram::new(&[0.25, 0.5, 0.75, 0.5], &[0.0, 1.0], false, &B).unwrap();
    assert_eq!(d.area(0), 0.0);
    assert!((d.area(1) - 1.0).abs() < 1e-15);
}

#[test]
fn area_derivatives_match_finite_differences() {
    let n = 30;
    let sites = uniform(n, 12);
    for torus in [false, true] {
        let w = weights(n, 0.5 / n as f64, 13);
        let d = PowerDiagram::new(&sites, &w, torus, &B).unwrap();
        let h = 1e-7;
        for j in [0usize, 7, 19] {
            let mut wp = w.clone();
            wp[j] += h;
            let dp = PowerDiagram::new(&sites, &wp, torus, &B).unwrap();
            for i in 0..n {
                let fd = (dp.area(i) - d.area(i)) / h;
                let exact: f64 = if i == j {
                    d.neighbours(i).iter().map(|&(_, c)| c).sum()
                } else {
                    -d.neighbours(i)
                        .iter()
                        .filter(|&&(k, _)| k as usize == j)
                        .map(|&(_, c)| c)
                        .sum::<f64>()
                };
                assert!(
                    (fd - exact).abs() < 1e-4 * (1.0 + exact.abs()),
                    "torus {torus} dA_{i}/dw_{j}: {fd} vs {exact}"
                );
            }
        }
    }
}

#[test]
fn bad_input_is_refused() {
    let b = &B;
    assert!(PowerDiagram::voronoi(&[], false, b).is_err());
    assert!(PowerDiagram::voronoi(&[0.5], false, b).is_err());
    assert!(PowerDiagram::voronoi(&[0.5, 1.5], false, b).is_err());
    assert!(PowerDiagram::voronoi(&[0.5, f64::NAN], false, b).is_err());
    assert!(PowerDiagram::new(&[0.5, 0.5], &[f64::INFINITY], false, b).is_err());
    assert!(PowerDiagram::new(&[0.5, 0.5], &[0.0, 0.0], false, b).is_err());
    // Equal sites (on the torus 0 and 1 are one point).
    assert!(PowerDiagram::voronoi(&[0.5, 0.5, 0.5, 0.5], false, b).is_err());
    assert!(PowerDiagram::voronoi(&[0.0, 0.5, 1.0, 0.5], true, b).is_err());
    assert!(transport::solve(&[0.2, 0.2, 0.2, 0.2], false, 1e-9, b).is_err());
    assert!(transport::solve(&[0.2, 0.2, 0.3, 0.2], false, 1e-13, b).is_err());
    assert!(transport::solve(&[0.2, 0.2, 0.3, 0.2], false, f64::NAN, b).is_err());
    let tight = Budget::seconds(1e-6).unwrap();
    let many = uniform(100_000, 3);
    assert!(matches!(
        transport::solve(&many, false, 1e-9, &tight),
        Err(qmckit::Error::OverBudget { .. })
    ));
    let p3 = Points::new(&[0.5, 0.5, 0.5], 3).unwrap();
    assert!(ot_distance(p3, b).is_err());
}

/// Areas of the diagram counted on an independent `m x m` grid by least power distance.
fn grid_areas(sites: &[f64], w: &[f64], torus: bool, m: usize) -> Vec<f64> {
    let n = w.len();
    let mut count = vec![0.0; n];
    for gy in 0..m {
        for gx in 0..m {
            let x = [(gx as f64 + 0.5) / m as f64, (gy as f64 + 0.5) / m as f64];
            let i = (0..n)
                .min_by(|&a, &b| {
                    let pa = dist2(x, [sites[2 * a], sites[2 * a + 1]], torus) - w[a];
                    let pb = dist2(x, [sites[2 * b], sites[2 * b + 1]], torus) - w[b];
                    pa.total_cmp(&pb)
                })
                .unwrap();
            count[i] += 1.0 / (m * m) as f64;
        }
    }
    count
}

#[test]
fn the_solve_gives_equal_capacities() {
    for (n, torus) in [
        (1usize, false),
        (2, true),
        (50, false),
        (50, true),
        (2000, false),
        (2000, true),
    ] {
        // Clustered sites: half of them in the left fifth, where Voronoi cells are small.
        let mut sites = uniform(n, 40 + n as u64);
        for x in sites.iter_mut().step_by(4) {
            *x *= 0.2;
        }
        let t = transport::solve(&sites, torus, 1e-9, &B).unwrap();
        let err = t
            .diagram()
            .areas()
            .iter()
            .map(|a| (a * n as f64 - 1.0).abs())
            .fold(0.0, f64::max);
        assert!(err <= 1e-9, "n {n} torus {torus}: {err}");
        assert_eq!(err, t.max_error());
        assert!(t.newton_steps() <= 30, "n {n}: {} steps", t.newton_steps());
        if n == 50 {
            // Independently: the areas by least power distance on a 400 x 400 grid
            // (boundary pixels: about perimeter / pixel, 4 sqrt(1/N) 400 of 160000).
            let counted = grid_areas(&sites, t.weights(), torus, 400);
            for a in counted {
                assert!(
                    (a * n as f64 - 1.0).abs() < 0.05,
                    "n {n} torus {torus}: {a}"
                );
            }
            // Zero weights (Voronoi) are far from equal here.
            let v = PowerDiagram::voronoi(&sites, torus, &B).unwrap();
            let spread = v
                .areas()
                .iter()
                .map(|a| (a * n as f64 - 1.0).abs())
                .fold(0.0, f64::max);
            assert!(spread > 0.5, "{spread}");
        }
    }
}

#[test]
fn ot_distance_closed_forms() {
    // One point: int over the square of |x - p|^2 = 2/3 - (p_x + p_y) + p_x^2 + p_y^2.
    for p in [[0.5, 0.5], [0.0, 0.0], [0.1, 0.9], [0.3, 1.0]] {
        let pts = Points::new(&p, 2).unwrap();
        let want = 2.0 / 3.0 - (p[0] + p[1]) + p[0] * p[0] + p[1] * p[1];
        let got = ot_cost(pts, &B).unwrap();
        assert!((got - want).abs() < 1e-15, "{p:?}: {got} vs {want}");
    }
    // The k x k grid of cell centres: N squares of side 1/k, W_2^2 = N (1/k)^4 / 6.
    for k in [1usize, 2, 3, 10, 32] {
        let pts: Vec<f64> = (0..k * k)
            .flat_map(|i| {
                [
                    ((i % k) as f64 + 0.5) / k as f64,
                    ((i / k) as f64 + 0.5) / k as f64,
                ]
            })
            .collect();
        let got = ot_distance(Points::new(&pts, 2).unwrap(), &B).unwrap();
        let want = (1.0 / (6.0 * (k * k) as f64)).sqrt();
        assert!((got - want).abs() < 1e-12 * want, "k {k}: {got} vs {want}");
    }
}

#[test]
fn the_catalog_measure_is_the_distance() {
    let e = qmckit::catalog::measure("wasserstein").unwrap();
    assert_eq!(e.name, "ot-distance");
    // One point at the centre: W_2^2 = 2/3 - 1 + 1/2 = 1/6.
    let p = Points::new(&[0.5, 0.5], 2).unwrap();
    let got = e.scalar(p, &B).unwrap();
    assert!((got - (1.0f64 / 6.0).sqrt()).abs() < 1e-15, "{got}");
    let p3 = Points::new(&[0.5, 0.5, 0.5], 3).unwrap();
    assert!(e.scalar(p3, &B).is_err());
}
