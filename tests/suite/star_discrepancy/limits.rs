//! Huge dimensions on small stacks, refusals that name the largest feasible set, and
//! budgets.

use super::*;

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
