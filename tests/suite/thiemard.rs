//! Thiémard's bounds on the star discrepancy: `D* - δ <= lower <= D* <= upper <= D* + δ`
//! against the exact value (`star_1d`, `star_2d`, `star_exact`, themselves checked against
//! brute force in `star_discrepancy.rs`) on many random sets, and against values known in
//! closed form.
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::star::thiemard::bounds;
use qmckit::analysis::star::{star, star_upper_bound};
use qmckit::work::Budget;
use qmckit::{Error, LarcherPillichshammer};

use crate::common;
use common::Rng;

/// Checks `exact - delta <= lower <= exact <= upper <= exact + delta` (up to rounding) and that
/// `star_upper_bound` returns the same upper bound.
fn check(data: &[f64], d: usize, delta: f64, exact: f64) {
    let p = Points::new(data, d).unwrap();
    let b = bounds(p, delta, &Budget::DEFAULT).unwrap();
    assert!(
        b.lower <= exact,
        "d = {d}, delta = {delta}: lower {} > exact {exact}",
        b.lower
    );
    assert!(
        exact <= b.upper,
        "d = {d}, delta = {delta}: upper {} < exact {exact}",
        b.upper
    );
    assert!(
        b.upper <= exact + delta + 1e-12,
        "d = {d}, delta = {delta}: upper {} > exact {exact} + delta",
        b.upper
    );
    // Every test box lies in a bracket whose corner is within delta of it in volume.
    assert!(
        exact - b.lower <= delta + 1e-12,
        "d = {d}, delta = {delta}: lower {} < exact {exact} - delta",
        b.lower
    );
    assert!(b.brackets > 0);
    assert_eq!(star_upper_bound(p, delta).unwrap(), b.upper);
}

#[test]
fn brackets_the_exact_value_on_random_sets() {
    let mut rng = Rng(2001);
    let cases: [(usize, usize, &[f64]); 6] = [
        (1, 40, &[0.1, 0.01, 0.003]),
        (2, 40, &[0.2, 0.05, 0.01]),
        (2, 200, &[0.02, 0.005]),
        (3, 30, &[0.2, 0.1, 0.05]),
        (4, 16, &[0.3, 0.15]),
        (5, 10, &[0.4, 0.25]),
    ];
    for (d, n, deltas) in cases {
        for trial in 0..8 {
            let q = match trial % 4 {
                0 => Some(4),
                1 => Some(10),
                _ => None,
            };
            let data = rng.set(n, d, q);
            let exact = star(Points::new(&data, d).unwrap()).unwrap();
            for &delta in deltas {
                check(&data, d, delta, exact);
            }
        }
    }
}

#[test]
fn larcher_pillichshammer_nets() {
    // Exact star discrepancies of the 2^m-point LP nets (Larcher & Pillichshammer 2001).
    let known = [
        (2, 7.0 / 16.0),
        (3, 1.0 / 4.0),
        (4, 9.0 / 64.0),
        (5, 19.0 / 256.0),
        (6, 21.0 / 512.0),
    ];
    for (m, value) in known {
        let lp = LarcherPillichshammer::new(m).unwrap();
        let n = 1u32 << m;
        let raw: Vec<u32> = (0..n)
            .flat_map(|i| [lp.sample(i, 0).unwrap(), lp.sample(i, 1).unwrap()])
            .collect();
        let data = Points::from_u32(&raw);
        for delta in [0.05, 0.01, 0.004] {
            check(&data, 2, delta, value);
        }
    }
}

#[test]
fn one_point_at_the_center() {
    // D* = 1 - 2^-d: the closed box [0, 1/2]^d holds the point with volume 2^-d. The best
    // corner is snapped onto that box, so the lower bound is D* up to the rounding margin.
    for d in 1..=6 {
        let data = vec![0.5; d];
        let exact = 1.0 - 0.5f64.powi(d as i32);
        for delta in [0.3, 0.1, 0.03] {
            if (d >= 5 && delta < 0.3) || (d == 4 && delta < 0.1) {
                continue;
            }
            check(&data, d, delta, exact);
            let b = bounds(Points::new(&data, d).unwrap(), delta, &Budget::DEFAULT).unwrap();
            assert!((b.lower - exact).abs() < 1e-14, "d = {d}: {}", b.lower);
        }
    }
}

#[test]
fn whole_cube_as_one_bracket() {
    // delta = 1: the single bracket [0, 1]^d gives max(A/N - 0, 1 - 0) = 1.
    let data = [0.25, 0.75, 0.5, 0.5];
    let b = bounds(Points::new(&data, 2).unwrap(), 1.0, &Budget::DEFAULT).unwrap();
    assert_eq!(b.brackets, 1);
    assert!((1.0..1.0 + 1e-14).contains(&b.upper));
}

#[test]
fn bad_delta_and_too_much_work() {
    let data = [0.1, 0.2, 0.3, 0.4];
    let p = Points::new(&data, 2).unwrap();
    for delta in [0.0, -0.1, 1.5, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(
                bounds(p, delta, &Budget::DEFAULT),
                Err(Error::Unsupported { .. })
            ),
            "{delta}"
        );
        assert!(star_upper_bound(p, delta).is_err());
    }
    // Ten dimensions at delta = 0.01 would need far more than the budget: refused at once.
    let ten = vec![0.5; 10];
    let p = Points::new(&ten, 10).unwrap();
    assert!(matches!(
        bounds(p, 0.01, &Budget::DEFAULT),
        Err(Error::TooManyPoints { requested: 1, .. })
    ));
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
fn huge_dimensions_are_refused_at_once_without_allocating() {
    // Two points in 1000 dimensions, one or two in 10000 and 20000: far beyond the budget at
    // any delta below 1 (the root chain alone costs about 2 d^2 per step). Refused in well
    // under a second, before the estimating pass allocates its 3 d^2 values (9.6 GB at
    // d = 20000).
    for (n, d) in [(2usize, 1000usize), (1, 10_000), (2, 20_000)] {
        for delta in [0.05, 0.5, 0.99] {
            let start = std::time::Instant::now();
            let got = on_small_stack(move || {
                let data = vec![0.5; n * d];
                bounds(Points::new(&data, d).unwrap(), delta, &Budget::DEFAULT)
            });
            let secs = start.elapsed().as_secs_f64();
            assert!(
                matches!(got, Err(Error::TooManyPoints { max: 0, .. })),
                "{n} {d} {delta}: {got:?}"
            );
            assert!(secs < 1.0, "{n} points, d = {d}, delta = {delta}: {secs} s");
        }
        // delta = 1: the whole cube is one bracket, worth max(A/N - 0, 1 - 0) = 1; D* = 1 in
        // f64 (the closed [0, 1/2]^d holds every point: 1 - 2^-d), and the only corner met,
        // the whole cube, gives the lower bound 0 (within delta of D*).
        let b = on_small_stack(move || {
            let data = vec![0.5; n * d];
            bounds(Points::new(&data, d).unwrap(), 1.0, &Budget::DEFAULT).unwrap()
        });
        assert_eq!((b.lower, b.upper, b.brackets), (0.0, 1.0, 1));
    }
}

#[test]
fn bounds_stay_in_the_unit_interval_and_in_order() {
    use qmckit::analysis::star::thiemard::bounds;
    use qmckit::work::Budget;
    // The whole-cube bracket is worth exactly 1, the largest possible D*: the rounding
    // margin must not lift the bound above it.
    for (data, d) in [
        (vec![0.25, 0.75, 0.5, 0.5], 2),
        (vec![0.0, 0.0, 0.0], 3),
        (vec![1.0, 1.0], 1),
    ] {
        let p = Points::new(&data, d).unwrap();
        for delta in [1.0, 0.5, 0.1] {
            let b = bounds(p, delta, &Budget::DEFAULT).unwrap();
            assert!(
                0.0 <= b.lower && b.lower <= b.upper && b.upper <= 1.0,
                "{data:?} {delta}: {b:?}"
            );
            let exact = star(p).unwrap();
            assert!(b.lower <= exact && exact <= b.upper, "{b:?} {exact}");
        }
    }
    // A point at the origin: D* = 1 (the closed box [0, 0] holds it with volume 0).
    let origin = [0.0, 0.0];
    let b = bounds(Points::new(&origin, 2).unwrap(), 0.3, &Budget::DEFAULT).unwrap();
    assert_eq!(b.upper, 1.0);
    assert!(star_upper_bound(Points::new(&origin, 2).unwrap(), 1.0).unwrap() <= 1.0);
}

#[test]
fn a_smaller_budget_refuses_sooner() {
    use qmckit::analysis::star::thiemard::bounds;
    use qmckit::work::Budget;
    // 1000 points in 5D at delta = 0.08 are accepted within ten seconds; a hundredth of a
    // second is far too little, and the refusal is immediate.
    let data: Vec<f64> = (0..5000)
        .map(|i| ((i * 7919) % 1000) as f64 / 1000.0)
        .collect();
    let p = Points::new(&data, 5).unwrap();
    let start = std::time::Instant::now();
    let tiny = Budget::seconds(0.01).unwrap();
    assert!(matches!(
        bounds(p, 0.08, &tiny),
        Err(Error::TooManyPoints { .. })
    ));
    assert!(start.elapsed().as_secs_f64() < 0.5);
}
