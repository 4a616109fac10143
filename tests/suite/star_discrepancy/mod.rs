//! Star discrepancy: known exact values (Larcher–Pillichshammer, Hammersley), agreement with
//! brute force over the critical grid written from the definition, the classic three 2D sets' values, and
//! bounds that bracket the exact value.
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::star::dem::star_dem;
use qmckit::analysis::star::{
    extreme_2d, star, star_1d, star_2d, star_exact, star_lower_bound, star_upper_bound,
};
use qmckit::work::{Budget, Limits};
use qmckit::{Hammersley, Independent, Jitter, LarcherPillichshammer, Sampler, Sobol, Stratified};

use crate::common;
use common::{Rng, sampler_points};

/// Brute force from the definition, `O(N^(d+1))`: every corner `y` of the critical grid
/// (each `y_k` in `{x_ik} ∪ {1}`), the half-open box `[0, y)` (`vol - open/N`) and the limit
/// of `[0, y + ε)` (`closed/N - vol`). A point with a coordinate equal to 1 lies in no box
/// `[0, y)`, `y <= 1`, and no `[0, y + ε)` stays inside the cube past 1, so it is never
/// counted (it still counts in `N`).
fn brute_star(data: &[f64], d: usize) -> f64 {
    let n = data.len() / d;
    let pts: Vec<&[f64]> = data.chunks(d).collect();
    let grids: Vec<Vec<f64>> = (0..d)
        .map(|k| {
            let mut g: Vec<f64> = pts.iter().map(|p| p[k]).chain([1.0]).collect();
            g.sort_by(f64::total_cmp);
            g.dedup();
            g
        })
        .collect();
    let mut best = 0.0f64;
    let mut idx = vec![0usize; d];
    loop {
        let y: Vec<f64> = (0..d).map(|k| grids[k][idx[k]]).collect();
        let vol: f64 = y.iter().product();
        let open = pts.iter().filter(|p| (0..d).all(|k| p[k] < y[k])).count();
        let closed = pts
            .iter()
            .filter(|p| (0..d).all(|k| p[k] <= y[k] && p[k] < 1.0))
            .count();
        best = best
            .max(vol - open as f64 / n as f64)
            .max(closed as f64 / n as f64 - vol);
        // Next grid corner.
        let mut k = 0;
        loop {
            if k == d {
                return best;
            }
            idx[k] += 1;
            if idx[k] < grids[k].len() {
                break;
            }
            idx[k] = 0;
            k += 1;
        }
    }
}

/// Brute force extreme discrepancy in 2D, `O(N^5)`: every box with lower corner `a_k` in
/// `{0} ∪ {x_ik}` and upper `b_k` in `{x_ik} ∪ {1}`; the open box `(a, b)` (`vol - count/N`,
/// the limit of `[a + ε, b)`) and the closed `[a, b]` (`count/N - vol`, the limit of
/// `[a, b + ε)`); points with a coordinate 1 never counted.
fn brute_extreme_2d(data: &[f64]) -> f64 {
    let n = data.len() / 2;
    let pts: Vec<&[f64]> = data.chunks(2).collect();
    let grid = |k: usize| {
        let mut g: Vec<f64> = pts.iter().map(|p| p[k]).chain([0.0, 1.0]).collect();
        g.sort_by(f64::total_cmp);
        g.dedup();
        g
    };
    let (gx, gy) = (grid(0), grid(1));
    let mut best = 0.0f64;
    for &ax in &gx {
        for &bx in gx.iter().filter(|&&b| b >= ax) {
            for &ay in &gy {
                for &by in gy.iter().filter(|&&b| b >= ay) {
                    let vol = (bx - ax) * (by - ay);
                    let open = pts
                        .iter()
                        .filter(|p| ax < p[0] && p[0] < bx && ay < p[1] && p[1] < by)
                        .count();
                    let closed = pts
                        .iter()
                        .filter(|p| {
                            ax <= p[0] && p[0] <= bx && ay <= p[1] && p[1] <= by
                        } && p[0] < 1.0
                            && p[1] < 1.0)
                        .count();
                    best = best
                        .max(vol - open as f64 / n as f64)
                        .max(closed as f64 / n as f64 - vol);
                }
            }
        }
    }
    best
}

#[test]
fn larcher_pillichshammer_exact_dyadic() {
    // D* of the LP net for m = 2..6 (Larcher & Pillichshammer 2001; Kritzer 2006's table).
    let expected = [
        (2, 7.0 / 16.0),
        (3, 0.25),
        (4, 9.0 / 64.0),
        (5, 19.0 / 256.0),
    ];
    for (m, want) in expected.into_iter().chain([(6, 21.0 / 512.0)]) {
        let lp = LarcherPillichshammer::new(m).unwrap();
        let data = sampler_points(&lp, 1 << m);
        let p = Points::new(&data, 2).unwrap();
        assert_eq!(star_2d(p).unwrap(), want, "m = {m}");
        assert_eq!(star(p).unwrap(), want, "m = {m}");
        assert_eq!(star_exact(p, &Budget::DEFAULT).unwrap(), want, "m = {m}");
    }
}

#[test]
fn hammersley_de_clerck_formula() {
    // N D* = m/3 + 13/9 - (-1)^m 4/(9 2^m) for the 2D Hammersley set, N = 2^m (De Clerck 1986),
    // for m >= 2. At m = 1 it would give N D* = 2, i.e. D* = 1, but the two points (0, 0),
    // (1/2, 1/2) have D* = 3/4 by hand: the closed [0, 1/2]^2 holds both (1 - 1/4), and the
    // open boxes [0, 1) x [0, 1/2), [0, 1/2) x [0, 1) hold one point for volume 1/2 (0).
    let h1 = sampler_points(&Hammersley::with_m(1, 2).unwrap(), 2);
    assert_eq!(h1, [0.0, 0.0, 0.5, 0.5]);
    assert_eq!(star_2d(Points::new(&h1, 2).unwrap()).unwrap(), 0.75);
    for m in 2..=10u32 {
        let h = Hammersley::with_m(m, 2).unwrap();
        let data = sampler_points(&h, 1 << m);
        let p = Points::new(&data, 2).unwrap();
        let n = (1u64 << m) as f64;
        let sign = if m % 2 == 0 { 1.0 } else { -1.0 };
        let want = m as f64 / 3.0 + 13.0 / 9.0 - sign * 4.0 / (9.0 * n);
        let got = n * star_2d(p).unwrap();
        assert!((got - want).abs() < 1e-12, "m = {m}: {got} vs {want}");
    }
}

#[test]
fn one_dimension_closed_form_matches_brute_force() {
    let mut rng = Rng(1);
    for trial in 0..300 {
        let n = 1 + trial % 17;
        let q = if trial % 2 == 0 { Some(7) } else { None };
        let data = rng.set(n, 1, q);
        let p = Points::new(&data, 1).unwrap();
        let (got, want) = (star_1d(p).unwrap(), brute_star(&data, 1));
        assert!((got - want).abs() < 1e-14, "{data:?}: {got} vs {want}");
        assert_eq!(star(p).unwrap(), got);
        assert_eq!(star_exact(p, &Budget::DEFAULT).unwrap(), got);
    }
    // Hand-derived: the centered grid has the minimum 1/(2N); all points at 0 have D* = 1
    // (the closed [0, 0] holds them all), all at 1 have D* = 1 (no box holds them).
    let grid = [0.1, 0.3, 0.5, 0.7, 0.9];
    assert!((star_1d(Points::new(&grid, 1).unwrap()).unwrap() - 0.1).abs() < 1e-15);
    assert_eq!(star_1d(Points::new(&[0.0, 0.0], 1).unwrap()).unwrap(), 1.0);
    assert_eq!(star_1d(Points::new(&[1.0, 1.0], 1).unwrap()).unwrap(), 1.0);
}

#[test]
fn two_dimensions_match_brute_force_with_ties_and_boundaries() {
    let mut rng = Rng(2);
    for trial in 0..400 {
        let n = 1 + trial % 23;
        let q = match trial % 3 {
            0 => Some(4),
            1 => Some(16),
            _ => None,
        };
        let data = rng.set(n, 2, q);
        let p = Points::new(&data, 2).unwrap();
        let (got, want) = (star_2d(p).unwrap(), brute_star(&data, 2));
        assert!((got - want).abs() < 1e-14, "{data:?}: {got} vs {want}");
        let exact = star_exact(p, &Budget::DEFAULT).unwrap();
        assert!((exact - want).abs() < 1e-14, "{data:?}: {exact} vs {want}");
    }
}

#[test]
fn points_on_the_upper_boundary_are_never_counted() {
    // (1, 0), (1, 0), (0, 0): only (0, 0) is ever inside a box [0, y), so
    // D* = max(1 - 1/3 (open [0,1)^2), 1/3 - 0 (closed [0,0]^2)) = 2/3. Counting x <= 1 at
    // y = (1, 0) would give 3/3 - 0 = 1.
    let data = [1.0, 0.0, 1.0, 0.0, 0.0, 0.0];
    let p = Points::new(&data, 2).unwrap();
    assert!((star_2d(p).unwrap() - 2.0 / 3.0).abs() < 1e-15);
    assert!((star_exact(p, &Budget::DEFAULT).unwrap() - 2.0 / 3.0).abs() < 1e-15);
    // One point at the origin: the closed [0, 0]^2 holds it, 1 - 0; D* = 1.
    assert_eq!(star_2d(Points::new(&[0.0, 0.0], 2).unwrap()).unwrap(), 1.0);
}

#[test]
fn higher_dimensions_match_brute_force() {
    let mut rng = Rng(3);
    for (d, trials, max_n) in [(3, 150, 14), (4, 60, 9), (5, 20, 6)] {
        for trial in 0..trials {
            let n = 1 + trial % max_n;
            let q = match trial % 3 {
                0 => Some(3),
                1 => Some(8),
                _ => None,
            };
            let data = rng.set(n, d, q);
            let p = Points::new(&data, d).unwrap();
            let (got, want) = (
                star_exact(p, &Budget::DEFAULT).unwrap(),
                brute_star(&data, d),
            );
            assert!(
                (got - want).abs() < 1e-14,
                "d = {d}, {data:?}: {got} vs {want}"
            );
            assert_eq!(star(p).unwrap(), got);
        }
    }
}

#[test]
fn star_exact_agrees_with_star_2d_on_larger_sets() {
    let mut rng = Rng(4);
    for n in [50, 200, 500] {
        let data = rng.set(n, 2, None);
        let p = Points::new(&data, 2).unwrap();
        assert_eq!(
            star_exact(p, &Budget::DEFAULT).unwrap(),
            star_2d(p).unwrap()
        );
    }
    // A 3D set whose last coordinate is 0 for every point: boxes with y_3 = 1 are the 2D
    // boxes (D*_2 of the first two coordinates), and the closed boxes with y_3 = 0 have
    // volume 0 and hold, at most, every point with x, y < 1. Other y_3 do not occur.
    let data2 = rng.set(300, 2, Some(64));
    let data3: Vec<f64> = data2.chunks(2).flat_map(|p| [p[0], p[1], 0.0]).collect();
    let d2 = star_2d(Points::new(&data2, 2).unwrap()).unwrap();
    let inside = data2.chunks(2).filter(|p| p[0] < 1.0 && p[1] < 1.0).count() as f64 / 300.0;
    let d3 = star_exact(Points::new(&data3, 3).unwrap(), &Budget::DEFAULT).unwrap();
    assert_eq!(d3, d2.max(inside));
}

#[test]
fn textbook_table_n64() {
    const SETS: u64 = 200;
    let mean = |f: &dyn Fn(u64) -> f64| (0..SETS).map(f).sum::<f64>() / SETS as f64;
    let star_of = |s: &dyn Sampler| {
        let data = sampler_points(s, 64);
        star_2d(Points::new(&data, 2).unwrap()).unwrap()
    };
    let independent = mean(&|seed| star_of(&Independent::new(2, seed).unwrap()));
    let jittered = mean(&|seed| star_of(&Stratified::uniform(8, 2, Jitter::Random(seed)).unwrap()));
    let lp = star_of(&LarcherPillichshammer::new(6).unwrap());
    eprintln!(
        "N = 64, D* (mean of {SETS} sets): independent {independent:.4}, \
         jittered 8x8 {jittered:.4}, Larcher-Pillichshammer {lp}"
    );
    assert!((0.12..=0.18).contains(&independent), "{independent}");
    assert!((0.06..=0.10).contains(&jittered), "{jittered}");
    assert_eq!(lp, 0.041015625);
}

#[test]
fn refuses_infeasible_requests() {
    let data = vec![0.5; 200_001 * 2];
    let p = Points::new(&data, 2).unwrap();
    assert!(matches!(
        star_2d(p),
        Err(qmckit::Error::TooManyPoints { .. })
    ));
    // One 2D limit for every exact entry point: the largest N with (N + 1)^2 cells within
    // ten seconds at 6.5e8 cells a second on each of two cores, 1.3e10 cells
    // (114017^2 = 12_999_876_289, 114018^2 = 13_000_104_324).
    let data = vec![0.5; 114_017 * 2];
    let p = Points::new(&data, 2).unwrap();
    let refused = qmckit::Error::TooManyPoints {
        requested: 114_017,
        max: 114_016,
    };
    assert_eq!(star_2d(p), Err(refused));
    assert_eq!(star(p), Err(refused));
    assert_eq!(star_exact(p, &Budget::DEFAULT), Err(refused));
    assert_eq!(qmckit::analysis::star::STAR_2D_MAX_POINTS, 114_016);
    let data = vec![0.25; 100_000 * 6];
    let mut rng = Rng(5);
    let data: Vec<f64> = data.iter().map(|_| rng.uniform()).collect();
    let p = Points::new(&data, 6).unwrap();
    assert!(star_exact(p, &Budget::DEFAULT).is_err());
    assert!(star_1d(p).is_err());
    assert!(star_2d(p).is_err());
}

#[test]
fn extreme_2d_matches_brute_force() {
    let mut rng = Rng(6);
    for trial in 0..200 {
        let n = 1 + trial % 11;
        let q = match trial % 3 {
            0 => Some(4),
            1 => Some(10),
            _ => None,
        };
        let data = rng.set(n, 2, q);
        let p = Points::new(&data, 2).unwrap();
        let (got, want) = (
            extreme_2d(p, &Budget::DEFAULT).unwrap(),
            brute_extreme_2d(&data),
        );
        assert!((got - want).abs() < 1e-14, "{data:?}: {got} vs {want}");
        // D* <= D <= 4 D* in 2D, and D >= 1/N.
        let s = star_2d(p).unwrap();
        assert!(s <= got + 1e-15 && got <= 4.0 * s + 1e-15 && got >= 1.0 / n as f64);
    }
    let big = vec![0.5; 2 * 2001];
    assert!(extreme_2d(Points::new(&big, 2).unwrap(), &Budget::DEFAULT).is_err());
}

#[test]
fn bounds_bracket_the_exact_value() {
    let mut rng = Rng(7);
    for (d, n) in [(1, 20), (2, 30), (2, 64), (3, 25), (4, 12)] {
        for trial in 0..6 {
            let q = if trial % 2 == 0 { Some(8) } else { None };
            let data = rng.set(n, d, q);
            let p = Points::new(&data, d).unwrap();
            let exact = star(p).unwrap();
            let lower = star_lower_bound(p, trial, 3000, &Budget::UNLIMITED).unwrap();
            // Both are exact up to the rounding of the volumes (a few ulps).
            assert!(
                lower <= exact + 1e-14,
                "d = {d}: lower {lower} > exact {exact}"
            );
            assert!(
                lower >= 0.5 * exact,
                "d = {d}: lower {lower} far below {exact}"
            );
            for delta in [0.2, 0.1] {
                let upper = star_upper_bound(p, delta).unwrap();
                assert!(exact <= upper, "d = {d}: upper {upper} < exact {exact}");
                assert!(
                    upper <= exact + delta + 1e-12,
                    "d = {d}, delta = {delta}: {upper}"
                );
            }
        }
    }
    // On the 64-point LP net the search gets close to the exact 21/512, never above it.
    let lp = sampler_points(&LarcherPillichshammer::new(6).unwrap(), 64);
    let p = Points::new(&lp, 2).unwrap();
    let lower = star_lower_bound(p, 1, 20_000, &Budget::UNLIMITED).unwrap();
    assert!((0.035..=21.0 / 512.0).contains(&lower), "{lower}");
    assert!(star_upper_bound(p, 0.0).is_err());
}

/// The DEM algorithm (Dobkin, Eppstein & Mitchell 1996) against brute force and by hand.
mod dem;

/// Huge dimensions, refusals and budgets.
mod limits;

/// Deadlines that stop every super-linear loop.
mod deadlines;
