//! The DEM algorithm for the exact star discrepancy (Dobkin, Eppstein & Mitchell 1996)
//! against brute force from the definition, by hand, and under budgets.

use super::*;

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
