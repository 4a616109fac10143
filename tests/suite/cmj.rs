//! Correlated multi-jittered sampling (Kensler 2013) and the hexagonal grid against their
//! defining properties: CMJ's N-rooks and `m x n` strata (exactly one point each, counted
//! from the 0.32 fractions), the 1D strata of an odd dimension, the pairs' decorrelation;
//! the hex grid's equal nearest-neighbour distances on the torus (brute force, 1e-9
//! relative in `f64`, `2^-30` absolute in 0.32 fractions) and its spacing against the
//! hexagonal packing distance `sqrt(2 / (sqrt(3) N))`.

use qmckit::Sampler;
use qmckit::lattice::hex::HexGrid;
use qmckit::random::cmj::CorrelatedMultiJitter;

/// The cell of a 0.32 fraction among `k` equal cells.
fn cell(x: u32, k: u64) -> usize {
    ((x as u64 * k) >> 32) as usize
}

/// Exactly one point of `s` (dimensions `dx`, `dy`) in each N-rooks column and row and
/// in each cell of the `m x n` grid, when `N = m n`.
fn check_strata(s: &CorrelatedMultiJitter, dx: usize, dy: usize) {
    let n = s.len();
    let (m, rows) = s.grid();
    assert_eq!(m * rows, n);
    let (mut cols, mut lines, mut cells) = (
        vec![0; n as usize],
        vec![0; n as usize],
        vec![0; n as usize],
    );
    for i in 0..n as u32 {
        let (x, y) = (s.sample(i, dx).unwrap(), s.sample(i, dy).unwrap());
        cols[cell(x, n)] += 1;
        lines[cell(y, n)] += 1;
        cells[cell(x, m) + m as usize * cell(y, rows)] += 1;
    }
    assert!(cols.iter().all(|&c| c == 1), "columns {cols:?}");
    assert!(lines.iter().all(|&c| c == 1), "rows {lines:?}");
    assert!(cells.iter().all(|&c| c == 1), "cells {cells:?}");
}

#[test]
fn cmj_is_n_rooks_and_jittered_at_once() {
    for seed in [0u64, 1, 77, u64::MAX] {
        for n in [1u64, 4, 16, 64, 256, 1024] {
            check_strata(&CorrelatedMultiJitter::new(n, 2, seed).unwrap(), 0, 1);
        }
        // 8 x 4 and 4 x 8 grids (the paper's aspect), and the second pair of 4 dims.
        check_strata(
            &CorrelatedMultiJitter::with_grid(32, 8, 4, 2, seed).unwrap(),
            0,
            1,
        );
        check_strata(
            &CorrelatedMultiJitter::with_grid(32, 4, 8, 2, seed).unwrap(),
            0,
            1,
        );
        let four = CorrelatedMultiJitter::new(64, 4, seed).unwrap();
        check_strata(&four, 0, 1);
        check_strata(&four, 2, 3);
    }
}

#[test]
fn cmj_for_any_n_stretches_and_clips() {
    for n in [2u64, 3, 5, 10, 17, 50, 99, 1000] {
        let s = CorrelatedMultiJitter::new(n, 3, 5).unwrap();
        let (m, rows) = s.grid();
        assert_eq!(m, (n as f64).sqrt().floor() as u64);
        assert_eq!(rows, n.div_ceil(m));
        let cells = m * rows;
        let (mut xs, mut ys, mut zs) = (
            vec![0; cells as usize],
            vec![0; n as usize],
            vec![0; n as usize],
        );
        for i in 0..n as u32 {
            xs[cell(s.sample(i, 0).unwrap(), cells)] += 1;
            ys[cell(s.sample(i, 1).unwrap(), n)] += 1;
            // The odd last dimension: one point in each of N slabs.
            zs[cell(s.sample(i, 2).unwrap(), n)] += 1;
        }
        assert!(xs.iter().all(|&c| c <= 1), "{n}: x columns {xs:?}");
        assert!(ys.iter().all(|&c| c == 1), "{n}: y rows");
        assert!(zs.iter().all(|&c| c == 1), "{n}: the 1D dimension");
    }
}

#[test]
fn cmj_pairs_and_seeds_are_decorrelated() {
    let s = CorrelatedMultiJitter::new(256, 4, 9).unwrap();
    let t = CorrelatedMultiJitter::new(256, 2, 10).unwrap();
    let (mut same_pair, mut same_seed) = (0, 0);
    for i in 0..256 {
        let col = |s: &CorrelatedMultiJitter, d| cell(s.sample(i, d).unwrap(), 16);
        same_pair += usize::from(col(&s, 0) == col(&s, 2));
        same_seed += usize::from(col(&s, 0) == col(&t, 0));
    }
    // Independent columns of 16 agree for about 256 / 16 = 16 points; identical ones for all.
    assert!(same_pair < 48 && same_seed < 48, "{same_pair} {same_seed}");
    assert_ne!(s.pattern(0), s.pattern(1));
}

#[test]
fn cmj_refuses_bad_sizes() {
    assert!(CorrelatedMultiJitter::new(0, 2, 0).is_err());
    assert!(CorrelatedMultiJitter::new((1 << 32) + 1, 2, 0).is_err());
    assert!(CorrelatedMultiJitter::new(16, 0, 0).is_err());
    assert!(CorrelatedMultiJitter::with_grid(32, 4, 4, 2, 0).is_err());
    assert!(CorrelatedMultiJitter::with_grid(32, 0, 40, 2, 0).is_err());
    let big = CorrelatedMultiJitter::new(1 << 32, 2, 0).unwrap();
    assert_eq!(big.grid(), (1 << 16, 1 << 16));
    let _ = big.sample(u32::MAX, 1).unwrap();
    assert!(big.sample(0, 2).is_err());
}

fn torus2(a: [f64; 2], b: [f64; 2]) -> f64 {
    let g = |d: f64| {
        let d = d.abs();
        d.min(1.0 - d)
    };
    g(a[0] - b[0]).hypot(g(a[1] - b[1]))
}

/// Every point's nearest-neighbour distance on the torus, brute force.
fn nearest(points: &[[f64; 2]]) -> Vec<f64> {
    points
        .iter()
        .enumerate()
        .map(|(i, &a)| {
            points
                .iter()
                .enumerate()
                .filter(|&(k, _)| k != i)
                .map(|(_, &b)| torus2(a, b))
                .fold(f64::INFINITY, f64::min)
        })
        .collect()
}

#[test]
fn hex_nearest_distances_are_all_equal_on_the_torus() {
    for n in [2u64, 4, 6, 8, 14, 30, 56, 120, 210, 462, 1000, 1024] {
        let h = HexGrid::new(n).unwrap();
        let (r, c) = h.shape();
        assert_eq!(r * c, n);
        assert_eq!(r % 2, 0);
        let exact: Vec<[f64; 2]> = (0..n).map(|i| h.point_f64(i)).collect();
        let want = h.nearest_distance();
        for (i, d) in nearest(&exact).into_iter().enumerate() {
            assert!(
                (d - want).abs() <= 1e-9 * want,
                "{n} ({r} x {c}) point {i}: {d} vs {want}"
            );
        }
        // The 0.32 fractions: within 2^-30.
        let fixed: Vec<[f64; 2]> = (0..n as u32)
            .map(|i| [0, 1].map(|k| qmckit::bits::to_f64(h.sample(i, k).unwrap())))
            .collect();
        for d in nearest(&fixed) {
            assert!((d - want).abs() <= 2f64.powi(-30), "{n}: {d} vs {want}");
        }
    }
}

#[test]
fn hex_spacing_nears_the_packing_distance() {
    // Sizes whose best factorization has r / c within 2% of 2 / sqrt(3).
    for (n, shape, at_least) in [
        (56u64, (8, 7), 0.99),
        (120, (12, 10), 0.99),
        (30, (6, 5), 0.98),
        (986, (34, 29), 0.99),
    ] {
        let h = HexGrid::new(n).unwrap();
        assert_eq!(h.shape(), shape, "{n}");
        let hex = (2.0 / (3f64.sqrt() * n as f64)).sqrt();
        let ratio = h.nearest_distance() / hex;
        assert!((at_least..=1.0 + 1e-12).contains(&ratio), "{n}: {ratio}");
    }
    // The nearest distance never exceeds the packing bound.
    for n in (2..400u64).step_by(2) {
        let h = HexGrid::new(n).unwrap();
        assert!(
            h.nearest_distance() <= (2.0 / (3f64.sqrt() * n as f64)).sqrt() * (1.0 + 1e-12),
            "{n}"
        );
    }
}

#[test]
fn hex_refuses_odd_and_bad_sizes() {
    for n in [0u64, 1, 3, 15, 1001, (1 << 32) + 2] {
        assert!(HexGrid::new(n).is_err(), "{n}");
    }
    assert!(HexGrid::with_rows(30, 3).is_err());
    assert!(HexGrid::with_rows(30, 4).is_err());
    assert_eq!(HexGrid::with_rows(30, 10).unwrap().shape(), (10, 3));
    let h = HexGrid::new(8).unwrap();
    assert!(h.sample(8, 0).is_err() && h.sample(0, 2).is_err());
}
