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

#[test]
fn dem_matches_brute_force() {
    let mut rng = Rng(8);
    for (d, trials, max_n) in [
        (1, 100, 20),
        (2, 150, 20),
        (3, 200, 14),
        (4, 80, 9),
        (5, 30, 6),
        (6, 12, 5),
    ] {
        for trial in 0..trials {
            let n = 1 + trial % max_n;
            let q = match trial % 4 {
                0 => Some(2),
                1 => Some(3),
                2 => Some(8),
                _ => None,
            };
            let data = rng.set(n, d, q);
            let p = Points::new(&data, d).unwrap();
            let (got, want) = (star_dem(p, &Budget::DEFAULT).unwrap(), brute_star(&data, d));
            assert!(
                (got - want).abs() < 1e-14,
                "d = {d}, {data:?}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn dem_matches_brute_force_on_large_coarse_sets() {
    // On the grid k/q the critical grid has at most (q + 1)^d corners, so the brute force
    // stays cheap for hundreds of points, while the decomposition sees many ties, points at
    // 0 and 1, and deep cuts.
    let mut rng = Rng(9);
    for (d, q, n) in [
        (3, 7, 400),
        (3, 16, 300),
        (4, 5, 300),
        (5, 3, 300),
        (6, 3, 240),
        (6, 2, 240),
    ] {
        for _ in 0..2 {
            let data = rng.set(n, d, Some(q));
            let p = Points::new(&data, d).unwrap();
            let (got, want) = (star_dem(p, &Budget::DEFAULT).unwrap(), brute_star(&data, d));
            assert!(
                (got - want).abs() < 1e-14,
                "d = {d}, q = {q}: {got} vs {want}"
            );
            assert_eq!(star_exact(p, &Budget::DEFAULT).unwrap(), got);
        }
    }
}

#[test]
fn dem_one_point_by_hand() {
    // One point x with every coordinate below 1: the closed box [0, x] holds it
    // (1 - prod x_k); a box missing it needs some y_k <= x_k, so the largest empty box is
    // [0, 1)^d with one side cut to x_k: volume max_k x_k. Boxes holding it are at most
    // 1 - prod x_k. So D* = max(1 - prod x_k, max_k x_k). With a coordinate equal to 1 the
    // point is never counted and the empty [0, 1)^d gives D* = 1. Dyadic: exact.
    let mut rng = Rng(10);
    for d in 1..=6 {
        for _ in 0..40 {
            let x: Vec<f64> = (0..d).map(|_| rng.coarse(64)).collect();
            let want = if x.contains(&1.0) {
                1.0
            } else {
                let prod: f64 = x.iter().product();
                (1.0 - prod).max(x.iter().copied().fold(0.0, f64::max))
            };
            let got = star_dem(Points::new(&x, d).unwrap(), &Budget::DEFAULT).unwrap();
            assert_eq!(got, want, "{x:?}");
        }
    }
    assert_eq!(
        star_exact(Points::new(&[0.5; 3], 3).unwrap(), &Budget::DEFAULT).unwrap(),
        0.875
    );
}

#[test]
fn dem_padded_with_zero_coordinates_reduces_to_2d() {
    // Extra coordinates equal to 0 for every point: corners with all extra y_k = 1 are the
    // 2D boxes; a corner with some extra y_k = 0 has volume 0, and its closed limit holds
    // every point with x, y < 1 (the open box is empty). So D*_d = max(D*_2, inside / N),
    // for N far past the brute force.
    let mut rng = Rng(11);
    for (d, n, q) in [
        (3, 600, None),
        (4, 400, Some(64)),
        (5, 300, None),
        (6, 200, Some(16)),
    ] {
        let data2 = rng.set(n, 2, q);
        let d2 = star_2d(Points::new(&data2, 2).unwrap()).unwrap();
        let inside = data2.chunks(2).filter(|p| p[0] < 1.0 && p[1] < 1.0).count() as f64;
        let padded: Vec<f64> = data2
            .chunks(2)
            .flat_map(|p| {
                [p[0], p[1]]
                    .into_iter()
                    .chain(std::iter::repeat_n(0.0, d - 2))
            })
            .collect();
        let got = star_dem(Points::new(&padded, d).unwrap(), &Budget::DEFAULT).unwrap();
        assert_eq!(got, d2.max(inside / n as f64), "d = {d}");
    }
}

#[test]
fn dem_on_nets_matches_brute_force() {
    // Sobol' and Hammersley nets (first 2^m points), the low-discrepancy case in which
    // the decomposition prunes least.
    for (d, m) in [(3, 5), (4, 4), (5, 3), (6, 3)] {
        let sobol = sampler_points(&Sobol::new(d).unwrap(), 1 << m);
        let hammersley = sampler_points(&Hammersley::with_m(m, d).unwrap(), 1 << m);
        for data in [sobol, hammersley] {
            let p = Points::new(&data, d).unwrap();
            let (got, want) = (star_dem(p, &Budget::DEFAULT).unwrap(), brute_star(&data, d));
            assert!(
                (got - want).abs() < 1e-14,
                "d = {d}, m = {m}: {got} vs {want}"
            );
        }
    }
    // The first two Sobol' points in 3D, (0, 0, 0) and (1/2, 1/2, 1/2): the closed
    // [0, 1/2]^3 holds both, 1 - 1/8 = 7/8; a box holding only the origin has volume at most
    // 1/2 (one side at 1/2): 1/2 - 1/2 = 0 for the open one, and the closed ones holding only
    // the origin have some side 0: 1/2 - 0.
    let s = sampler_points(&Sobol::new(3).unwrap(), 2);
    assert_eq!(s, [0.0, 0.0, 0.0, 0.5, 0.5, 0.5]);
    assert_eq!(
        star_dem(Points::new(&s, 3).unwrap(), &Budget::DEFAULT).unwrap(),
        0.875
    );
}

#[test]
fn dem_refuses_beyond_its_budget() {
    use qmckit::analysis::star::dem::{max_points, work_estimate};
    use qmckit::analysis::star::{STAR_RATE, star_cost};
    use qmckit::work::CORES;
    // The default budget: ten seconds on two cores, 2e10 nanoseconds of one core (the
    // units of work_estimate, STAR_RATE 1e9 of them a second).
    let steps = 2e10;
    assert_eq!(STAR_RATE.steps_per_second() * CORES * 10.0, steps);
    for d in 3..=8 {
        let max = max_points(d, &Budget::DEFAULT) as usize;
        assert!(work_estimate(max, d) <= steps);
        assert!(work_estimate(max + 1, d) > steps);
        // The estimate in seconds is the same model.
        assert!(star_cost(max, d).seconds() <= 10.0 && star_cost(max + 1, d).seconds() > 10.0);
        let data = vec![0.5; (max + 1) * d];
        let err = star_dem(Points::new(&data, d).unwrap(), &Budget::DEFAULT).unwrap_err();
        assert_eq!(
            err,
            qmckit::Error::TooManyPoints {
                requested: max as u64 + 1,
                max: max as u64
            }
        );
        assert_eq!(
            star_exact(Points::new(&data, d).unwrap(), &Budget::DEFAULT).unwrap_err(),
            err
        );
    }
}

#[test]
fn dem_within_a_budget_reports_progress() {
    use qmckit::analysis::star::dem::{max_points, star_dem, work_estimate};
    use qmckit::analysis::star::{STAR_RATE, star_exact};
    use qmckit::work::Budget;
    use std::sync::Mutex;
    // Budgets in steps of work_estimate: STAR_RATE on each of two cores.
    let within = |steps: f64| {
        Budget::seconds(steps / (STAR_RATE.steps_per_second() * qmckit::work::CORES)).unwrap()
    };
    // A larger budget admits more points; the refusal names the largest N within it.
    for (d, steps) in [(3, 1e5), (4, 2e11), (6, 1.2e12)] {
        let budget = within(steps);
        let max = max_points(d, &budget) as usize;
        assert!(work_estimate(max, d) <= steps && work_estimate(max + 1, d) > steps);
        let data = vec![0.25; (max + 1) * d];
        let p = Points::new(&data, d).unwrap();
        let err = star_dem(p, &budget).unwrap_err();
        assert_eq!(
            err,
            qmckit::Error::TooManyPoints {
                requested: max as u64 + 1,
                max: max as u64
            }
        );
        assert_eq!(star_exact(p, &budget).unwrap_err(), err);
    }
    // 120 3D Sobol' points: more than the budget of 1e5 steps admits (88: 25.3 N^1.85 <=
    // 1e5); with a budget, the value is brute force's, and every slab of the first cut is
    // reported once.
    let sobol = qmckit::Sobol::new(3).unwrap();
    let mut u = vec![0u32; 120 * 3];
    qmckit::Sampler::fill(&sobol, 0, &mut u).unwrap();
    let data = Points::from_u32(&u);
    let p = Points::new(&data, 3).unwrap();
    assert!(star_dem(p, &within(1e5)).is_err());
    let calls = Mutex::new(Vec::new());
    // Admitted with room to spare: the deadline (1.25 times the budget) must not end a run
    // slowed by a loaded machine; this part checks the value and the progress reports.
    let got = star_dem(
        p,
        Limits::new(Budget::seconds(60.0).unwrap())
            .with_progress(&|done, total| calls.lock().unwrap().push((done, total))),
    )
    .unwrap();
    let want = brute_star(&data, 3);
    assert!((got - want).abs() < 1e-14, "{got} vs {want}");
    // Weighted progress in PROGRESS_STEPS, one report per slab and a last one at the total.
    let calls = calls.into_inner().unwrap();
    let total = qmckit::analysis::star::dem::PROGRESS_STEPS;
    assert!(calls.len() > 5, "{calls:?}");
    assert!(calls.iter().all(|&(done, t)| t == total && done <= total));
    assert_eq!(calls.last(), Some(&(total, total)));
    for bad in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            Budget::seconds(bad),
            Err(qmckit::Error::InvalidParameter { .. })
        ));
    }
}

/// Runs `f` on a thread with a 256 KiB stack: recursion that grew with the input would
/// overflow it.
fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(f)
        .unwrap()
        .join()
        .unwrap()
}

#[test]
fn star_of_one_point_in_huge_dimensions_needs_no_deep_stack() {
    use qmckit::analysis::star::dem::DEM_MAX_DIMS;
    use qmckit::analysis::star::star_exact;
    use qmckit::work::Budget;
    for d in [DEM_MAX_DIMS + 1, 10_000, 21_201] {
        let got = on_small_stack(move || {
            // Three points, two with a coordinate 1 (never counted); the third is 1/2 in
            // every coordinate but the last, 0.8. The box [0, 1)^(d-1) x [0, 0.8) misses it
            // (volume 0.8); the whole cube holds one point (1 - 1/3); the smallest closed
            // box holding it has volume 0.8 / 2^(d-1) (1/3 minus that): D* = 0.8.
            let mut data = vec![0.5; 3 * d];
            data[d - 1] = 0.8;
            data[d] = 1.0;
            data[3 * d - 1] = 1.0;
            // (The default budget counts all three points: 0.005 * 3^((d + 3) / 2) steps.)
            let p = Points::new(&data, d).unwrap();
            let three = star_exact(p, &Budget::UNLIMITED).unwrap();
            // The counted point alone: 1 - 0.8 / 2^(d - 1), i.e. 1 in f64.
            let one = star_exact(Points::new(&data[..d], d).unwrap(), &Budget::DEFAULT).unwrap();
            (three, one)
        });
        assert!((got.0 - 0.8).abs() < 1e-15, "d = {d}: {got:?}");
        assert_eq!(got.1, 1.0);
        // All three points with a coordinate 1: the empty open box [0, 1)^d gives 1.
        let none = on_small_stack(move || {
            let mut data = vec![0.25; 3 * d];
            for i in 0..3 {
                data[i * d + i] = 1.0;
            }
            let p = Points::new(&data, d).unwrap();
            star_exact(p, &Budget::UNLIMITED).unwrap()
        });
        assert_eq!(none, 1.0);
    }
}

#[test]
fn single_point_closed_form_agrees_with_the_decomposition() {
    // The decomposition in d <= 255 dimensions and the closed form above it compute the
    // same function; check the closed form's formula against the decomposition on random
    // points, then the closed-form path against the formula.
    let formula = |x: &[f64], n: f64| {
        let largest = x.iter().copied().fold(0.0, f64::max);
        let vol: f64 = x.iter().product();
        (n - 1.0).max(n * largest).max(1.0 - n * vol) / n
    };
    use qmckit::analysis::star::star_exact;
    use qmckit::work::Budget;
    let mut rng = Rng(17);
    for d in [3usize, 7, 40, 200, 255, 256, 600] {
        for extra in 0..3 {
            // Coordinates in [0.6, 1) for large d, anywhere in [0, 1) for small d, so that each
            // of the three terms wins somewhere.
            let lo = if d < 10 { 0.0 } else { 0.6 };
            let x: Vec<f64> = (0..d).map(|_| lo + (1.0 - lo) * rng.uniform()).collect();
            let mut data = x.clone();
            for _ in 0..extra {
                data.extend((0..d).map(|k| if k == 1 { 1.0 } else { 0.1 }));
            }
            let p = Points::new(&data, d).unwrap();
            let got = star_exact(p, &Budget::UNLIMITED).unwrap();
            let want = formula(&x, (1 + extra) as f64);
            assert!((got - want).abs() < 1e-14, "d = {d}: {got} vs {want}");
        }
    }
}

#[test]
fn two_points_in_huge_dimensions_are_refused_at_once() {
    use qmckit::analysis::star::star_exact;
    use qmckit::work::Budget;
    for d in [1000usize, 10_000, 21_201] {
        let data = vec![0.5; 2 * d];
        let p = Points::new(&data, d).unwrap();
        let start = std::time::Instant::now();
        // Two points cost little in any dimension (the estimate admits them), but past
        // the decomposition's dimension limit they are refused, with or without a budget.
        let refused = qmckit::Error::TooLarge {
            what: "dimensions for the exact star discrepancy of two or more points",
            requested: d as u64,
            max: 255,
        };
        assert_eq!(star_exact(p, &Budget::DEFAULT), Err(refused));
        let unlimited = star_exact(p, &Budget::UNLIMITED);
        assert_eq!(unlimited, Err(refused));
        assert!(start.elapsed().as_secs_f64() < 1.0);
    }
}

#[test]
fn decomposition_at_its_dimension_limit_runs_on_a_small_stack() {
    use qmckit::analysis::star::dem::{DEM_MAX_DIMS, star_dem};
    use qmckit::work::Budget;
    let got = on_small_stack(|| {
        // Two points: the origin and (1/2, .., 1/2). The closed box [0, 1/2]^d holds both
        // (1 - 2^-d); a box holding only the origin has some side at most 1/2.
        let d = DEM_MAX_DIMS;
        let mut data = vec![0.0; d];
        data.extend(vec![0.5; d]);
        star_dem(Points::new(&data, d).unwrap(), &Budget::UNLIMITED).unwrap()
    });
    assert_eq!(got, 1.0 - 0.5f64.powi(DEM_MAX_DIMS as i32));
}

#[test]
fn exact_refusals_report_the_largest_set_within_the_budget() {
    use qmckit::analysis::star::max_points;
    use qmckit::work::Budget;
    // 2D: floor(sqrt(1.3e9 s)) - 1 for s seconds ((N + 1)^2 cells at 6.5e8 a second on
    // each of two cores).
    assert_eq!(max_points(2, &Budget::DEFAULT), 114_016);
    assert_eq!(
        max_points(2, &Budget::seconds(0.01).unwrap()),
        3604 // sqrt(1.3e7) = 3605.55
    );
    assert_eq!(max_points(1, &Budget::DEFAULT), u64::MAX);
    assert_eq!(max_points(2, &Budget::UNLIMITED), u64::MAX);
    // d >= 3: 25.3 N^1.85 nanoseconds of one core, within 2e10 in 3D (N = 64517, as the
    // CLI documents).
    assert_eq!(max_points(3, &Budget::DEFAULT), 64_517);
}

#[test]
fn extreme_within_a_budget() {
    use qmckit::analysis::star::extreme_2d;
    use qmckit::work::Budget;
    // N^3 / 2 steps at 1.7e8 a second: 1503 points within ten seconds (1503^3 / 2 =
    // 1.698e9 <= 1.7e9 < 1504^3 / 2), refused at once past it.
    let data = vec![0.5; 2 * 1504];
    let p = Points::new(&data, 2).unwrap();
    let start = std::time::Instant::now();
    assert_eq!(
        extreme_2d(p, &Budget::DEFAULT),
        Err(qmckit::Error::TooManyPoints {
            requested: 1504,
            max: 1503
        })
    );
    assert!(start.elapsed().as_secs_f64() < 0.5);
    // Within it, the same value as extreme_2d: one point, the degenerate closed box on it
    // holds it with volume 0, so D = 1.
    let one = Points::new(&[0.5, 0.5], 2).unwrap();
    assert_eq!(
        extreme_2d(one, &Budget::DEFAULT),
        extreme_2d(one, &Budget::UNLIMITED)
    );
    assert_eq!(extreme_2d(one, &Budget::DEFAULT), Ok(1.0));
}

/// Deadlines: a budget started and left to expire (its estimate admits the work) stops
/// every super-linear loop of the star family and the L2 sums with `OutOfTime`; an
/// unexpired one gives the same value as no budget.
mod deadlines {
    use qmckit::Error;
    use qmckit::analysis::Points;
    use qmckit::analysis::l2::L2Metric;
    use qmckit::analysis::star::{extreme_2d, star_exact, star_lower_bound, thiemard};
    use qmckit::work::Budget;
    use std::time::{Duration, Instant};

    use crate::common::Rng;

    /// A budget of `seconds` whose deadline has passed.
    fn expired(seconds: f64) -> Budget {
        let b = Budget::seconds(seconds).unwrap().started();
        std::thread::sleep(Duration::from_secs_f64(seconds * 1.25 + 0.01));
        b
    }

    fn out_of_time<T: std::fmt::Debug>(r: qmckit::Result<T>) -> bool {
        matches!(r, Err(Error::OutOfTime { .. }))
    }

    #[test]
    fn an_expired_deadline_stops_every_loop() {
        let b = expired(0.02);
        let s2 = Rng(1).set(1000, 2, None);
        let p2 = Points::new(&s2, 2).unwrap();
        assert!(out_of_time(star_exact(p2, &b)));
        let s3 = Rng(2).set(300, 3, None);
        let p3 = Points::new(&s3, 3).unwrap();
        assert!(out_of_time(star_exact(p3, &b)));
        let small = Points::new(&s2[..200], 2).unwrap();
        assert!(out_of_time(extreme_2d(small, &b)));
        assert!(out_of_time(star_lower_bound(small, 1, 1000, &b)));
        assert!(out_of_time(thiemard::bounds(p2, 0.1, &b)));
        let s8 = Rng(3).set(600, 8, None);
        let p8 = Points::new(&s8, 8).unwrap();
        assert!(out_of_time(L2Metric::Centered.eval(p8, &b)));
        // The divide and conquer of L2-star (3D, past its crossover).
        let s3b = Rng(4).set(8192, 3, None);
        let p3b = Points::new(&s3b, 3).unwrap();
        assert!(out_of_time(L2Metric::L2Star.eval(p3b, &expired(0.3))));
    }

    #[test]
    fn a_live_deadline_changes_nothing() {
        let b = Budget::seconds(60.0).unwrap().started();
        let s3 = Rng(5).set(200, 3, None);
        let p3 = Points::new(&s3, 3).unwrap();
        assert_eq!(
            star_exact(p3, &b).unwrap().to_bits(),
            star_exact(p3, &Budget::DEFAULT).unwrap().to_bits()
        );
        let p2 = Points::new(&s3[..300], 3).unwrap();
        assert_eq!(
            star_lower_bound(p2, 3, 2000, &b).unwrap().to_bits(),
            star_lower_bound(p2, 3, 2000, &Budget::UNLIMITED)
                .unwrap()
                .to_bits()
        );
    }

    #[test]
    fn one_started_budget_bounds_a_chain_of_computations() {
        // Each exact 2D discrepancy of 3000 points is admitted (0.007 s estimated) under a
        // budget of 0.2 s; repeated, the shared deadline (0.25 s) stops the chain.
        let b = Budget::seconds(0.2).unwrap().started();
        let s = Rng(6).set(3000, 2, None);
        let p = Points::new(&s, 2).unwrap();
        let clock = Instant::now();
        let err = loop {
            if let Err(e) = star_exact(p, &b) {
                break e;
            }
            assert!(clock.elapsed().as_secs_f64() < 30.0, "never stopped");
        };
        assert!(matches!(err, Error::OutOfTime { .. }), "{err:?}");
        let took = clock.elapsed().as_secs_f64();
        assert!(took < 0.25 + 1.0, "stopped after {took} s");
    }
}
