//! t-values: the rank test on generator matrices against published facts, the elementary
//! interval counter on generated (and scrambled) points, and the two against each other.
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::tvalue::{
    IntervalFailure, elementary_interval_failures, elementary_interval_failures_u32,
    t_value_points, t_value_u32,
};
use qmckit::digital::DigitalNet2;
use qmckit::digital::rank::{dependent_shape, t_value};
use qmckit::randomize::{
    CranleyPatterson, DigitalShift, ExactOwen, FastOwen, Lms, OwenHash, Randomizer, Scrambled,
};
use qmckit::work::{Budget, Limits};
use qmckit::{Base2Digital, Error, Hammersley, Independent, LarcherPillichshammer, Sampler, Sobol};

/// Points `start .. start + 2^m` of a sampler, row-major.
fn block(s: &dyn Sampler, start: u32, m: u32) -> Vec<u32> {
    let mut out = vec![0u32; s.dims() << m];
    s.fill(start, &mut out).unwrap();
    out
}

/// A deterministic 64-bit mix (splitmix64) for random generator matrices.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

// ---- the rank test against published facts ----

#[test]
fn sobol_2d_is_a_0m2_net_for_every_m_up_to_20() {
    // Dimensions 0 and 1 of Sobol' (van der Corput and the x + 1 polynomial) form a
    // (0, 2)-sequence in base 2: every 2^m prefix is a (0, m, 2)-net.
    for m in 0..=20 {
        let net = DigitalNet2::from_sobol(2, m).unwrap();
        assert_eq!(t_value(&net, &Budget::DEFAULT).unwrap(), 0, "m = {m}");
        assert_eq!(dependent_shape(&net, &Budget::DEFAULT).unwrap(), None);
    }
}

#[test]
fn sobol_3d_joe_kuo_has_t_1_from_m_2() {
    // Sobol' in 3D is a (1, 3)-sequence (t = sum of (deg p_j - 1) = 0 + 0 + 1 for the
    // polynomials x, x + 1, x^2 + x + 1), so every 2^m prefix has t <= 1; with Joe & Kuo's
    // initial numbers it is exactly 1 for m >= 2 (t = 0 for m = 1: each first row is
    // nonzero). The counting test below checks the same values independently.
    assert_eq!(
        t_value(&DigitalNet2::from_sobol(3, 1).unwrap(), &Budget::DEFAULT).unwrap(),
        0
    );
    for m in 2..=20 {
        let net = DigitalNet2::from_sobol(3, m).unwrap();
        assert_eq!(t_value(&net, &Budget::DEFAULT).unwrap(), 1, "m = {m}");
        let shape = dependent_shape(&net, &Budget::DEFAULT).unwrap().unwrap();
        assert_eq!(shape.iter().sum::<u32>(), m, "m = {m}: shape {shape:?}");
    }
}

#[test]
fn lp_hammersley_and_van_der_corput_have_t_0_up_to_m_20() {
    for m in 1..=20 {
        assert_eq!(
            t_value(
                &DigitalNet2::larcher_pillichshammer(m).unwrap(),
                &Budget::DEFAULT
            )
            .unwrap(),
            0,
            "LP m = {m}"
        );
        assert_eq!(
            t_value(&DigitalNet2::hammersley(m).unwrap(), &Budget::DEFAULT).unwrap(),
            0,
            "Hammersley m = {m}"
        );
        assert_eq!(
            t_value(&DigitalNet2::van_der_corput(m).unwrap(), &Budget::DEFAULT).unwrap(),
            0
        );
    }
    // m = 32, the full range.
    assert_eq!(
        t_value(
            &DigitalNet2::larcher_pillichshammer(32).unwrap(),
            &Budget::DEFAULT
        )
        .unwrap(),
        0
    );
}

#[test]
fn the_rank_test_can_fail() {
    // Two copies of the same invertible matrix, points (x, x) on the diagonal: by hand, the
    // boxes [0, 1/2) x [1/2, 1) are empty (shape (1, 1) fails) while every 1D shape is
    // balanced, so t = m - 1 for m >= 2 (and t = 0 for m = 1: (0, 0), (1/2, 1/2)).
    let c = *qmckit::digital::sobol::directions(1).unwrap();
    assert_eq!(
        t_value(&DigitalNet2::new(1, vec![c, c]).unwrap(), &Budget::DEFAULT).unwrap(),
        0
    );
    for m in 2..=12 {
        let net = DigitalNet2::new(m, vec![c, c]).unwrap();
        assert_eq!(t_value(&net, &Budget::DEFAULT).unwrap(), m - 1, "m = {m}");
        assert_eq!(
            dependent_shape(&net, &Budget::DEFAULT).unwrap(),
            Some(vec![1, 1])
        );
    }
    // A zero matrix: no point leaves [0, 1/2), t = m.
    let net = DigitalNet2::new(5, vec![[0; 32]]).unwrap();
    assert_eq!(t_value(&net, &Budget::DEFAULT).unwrap(), 5);
}

#[test]
fn generator_points_are_the_samplers_points() {
    for m in [0, 1, 5, 10] {
        let lp = LarcherPillichshammer::new(m).unwrap();
        assert_eq!(
            DigitalNet2::larcher_pillichshammer(m)
                .unwrap()
                .points()
                .unwrap(),
            block(&lp, 0, m)
        );
        let h = Hammersley::with_m(m, 2).unwrap();
        assert_eq!(
            DigitalNet2::hammersley(m).unwrap().points().unwrap(),
            block(&h, 0, m)
        );
        let s = Sobol::new(5).unwrap();
        assert_eq!(
            DigitalNet2::from_sobol(5, m).unwrap().points().unwrap(),
            block(&s, 0, m)
        );
    }
}

// ---- counting elementary intervals ----

#[test]
fn sobol_2d_blocks_are_0m2_nets_by_counting() {
    // Every aligned block k 2^m .. (k + 1) 2^m of a (0, 2)-sequence is a (0, m, 2)-net.
    let s = Sobol::new(2).unwrap();
    for m in [1, 4, 8, 11, 14] {
        for k in [0u32, 1, 2, 7, 37, 200] {
            let pts = block(&s, k << m, m);
            assert_eq!(
                t_value_u32(&pts, 2, m, &Budget::DEFAULT).unwrap(),
                0,
                "m = {m}, block {k}"
            );
        }
    }
}

#[test]
fn sobol_3d_counting_agrees_with_the_rank_test_up_to_m_12() {
    let s = Sobol::new(3).unwrap();
    for m in 1..=12 {
        let want = t_value(&DigitalNet2::from_sobol(3, m).unwrap(), &Budget::DEFAULT).unwrap();
        assert_eq!(want, u32::from(m >= 2), "published t, m = {m}");
        let pts = block(&s, 0, m);
        assert_eq!(
            t_value_u32(&pts, 3, m, &Budget::DEFAULT).unwrap(),
            want,
            "m = {m}"
        );
        // And a later aligned block ((1, 3)-sequence: t <= 1 there too).
        let later = block(&s, 5 << m, m);
        assert!(
            t_value_u32(&later, 3, m, &Budget::DEFAULT).unwrap() <= 1,
            "m = {m}"
        );
    }
}

#[test]
fn lp_and_hammersley_have_t_0_by_counting_up_to_m_14() {
    for m in 1..=14 {
        let lp = block(&LarcherPillichshammer::new(m).unwrap(), 0, m);
        assert_eq!(
            t_value_u32(&lp, 2, m, &Budget::DEFAULT).unwrap(),
            0,
            "LP m = {m}"
        );
        let h = block(&Hammersley::with_m(m, 2).unwrap(), 0, m);
        assert_eq!(
            t_value_u32(&h, 2, m, &Budget::DEFAULT).unwrap(),
            0,
            "Hammersley m = {m}"
        );
    }
}

#[test]
fn the_f64_counter_agrees_with_the_u32_counter() {
    let s = Sobol::new(4).unwrap();
    for m in [3, 6, 9] {
        let pts = block(&s, 0, m);
        let f = Points::from_u32(&pts);
        let p = Points::new(&f, 4).unwrap();
        assert_eq!(
            t_value_points(p, 2, m, &Budget::DEFAULT).unwrap(),
            t_value_u32(&pts, 4, m, &Budget::DEFAULT).unwrap()
        );
    }
}

#[test]
fn base_3_hammersley_is_a_0m2_net() {
    // (i / 3^m, phi_3(i)) is a (0, m, 2)-net in base 3; cell midpoints avoid boundaries.
    for m in 1..=6u32 {
        let n = 3usize.pow(m);
        let mut data = Vec::with_capacity(2 * n);
        for i in 0..n {
            let (mut rev, mut k) = (0usize, i);
            for _ in 0..m {
                rev = rev * 3 + k % 3;
                k /= 3;
            }
            let half = 0.5 / n as f64;
            data.push(i as f64 / n as f64 + half);
            data.push(rev as f64 / n as f64 + half);
        }
        let p = Points::new(&data, 2).unwrap();
        assert_eq!(
            t_value_points(p, 3, m, &Budget::DEFAULT).unwrap(),
            0,
            "m = {m}"
        );
        // In base 2 the set is not even the right size.
        assert!(t_value_points(p, 2, m, &Budget::DEFAULT).is_err());
    }
}

// ---- scrambling keeps t ----

fn scrambled_t(sampler: &dyn Base2Digital, r: &dyn Randomizer, m: u32) -> u32 {
    let s = Scrambled::new(sampler, r);
    t_value_u32(&block(&s, 0, m), s.dims(), m, &Budget::DEFAULT).unwrap()
}

#[test]
fn nested_scrambles_keep_the_t_value() {
    let sobol2 = Sobol::new(2).unwrap();
    let sobol3 = Sobol::new(3).unwrap();
    let lp = LarcherPillichshammer::new(10).unwrap();
    for seed in 0..6u64 {
        let randomizers: Vec<(&str, Box<dyn Randomizer>)> = vec![
            ("shift", Box::new(DigitalShift::new(seed))),
            ("owen", Box::new(ExactOwen::new(seed))),
            ("fast owen", Box::new(FastOwen::new(seed))),
            (
                "laine-karras",
                Box::new(FastOwen::with_hash(seed, OwenHash::LaineKarras)),
            ),
            ("lms", Box::new(Lms::new(seed))),
            (
                "lms + shift",
                Box::new((Lms::new(seed), DigitalShift::new(seed + 1))),
            ),
        ];
        for (name, r) in &randomizers {
            assert_eq!(scrambled_t(&sobol2, &**r, 10), 0, "2D Sobol' {name} {seed}");
            assert_eq!(scrambled_t(&sobol3, &**r, 9), 1, "3D Sobol' {name} {seed}");
            assert_eq!(scrambled_t(&lp, &**r, 10), 0, "LP {name} {seed}");
        }
    }
}

#[test]
fn cranley_patterson_rotation_breaks_the_net() {
    // A toroidal rotation is not a digital randomization: a rotated elementary interval
    // straddles two, so the set loses its net property (the crate documents it).
    let sobol2 = Sobol::new(2).unwrap();
    for seed in 0..4u64 {
        assert!(scrambled_t(&sobol2, &CranleyPatterson::new(seed), 10) > 0);
    }
}

// ---- negative tests: failing intervals are named ----

fn assert_is_a_real_failure(pts: &[u32], dims: usize, m: u32, f: &IntervalFailure) {
    // Recount the named interval by hand.
    let mut count = 0u64;
    for p in pts.chunks_exact(dims) {
        let inside = f
            .shape
            .iter()
            .zip(&f.cell)
            .zip(p)
            .all(|((&d, &a), &x)| d == 0 || u64::from(x) >> (32 - d) == a);
        count += u64::from(inside);
    }
    assert_eq!(count, f.count, "{f}");
    let size: u32 = f.shape.iter().sum();
    assert_eq!(f.expected, 1 << (m - size));
    assert_ne!(f.count, f.expected);
}

#[test]
fn independent_points_are_not_a_net_and_the_interval_is_named() {
    let m = 10;
    let pts = block(&Independent::new(2, 7).unwrap(), 0, m);
    let t = t_value_u32(&pts, 2, m, &Budget::DEFAULT).unwrap();
    assert!(t >= 5, "t = {t}"); // random points are far from a net
    let failures =
        elementary_interval_failures_u32(&pts, 2, m, t - 1, 5, &Budget::DEFAULT).unwrap();
    // m - t + 1 may be as small as 1 (shapes (1, 0), (0, 1): at most 4 cells).
    assert!(!failures.is_empty() && failures.len() <= 5);
    for f in &failures {
        assert_eq!(f.shape.iter().sum::<u32>(), m - t + 1);
        assert_is_a_real_failure(&pts, 2, m, f);
    }
    assert!(
        elementary_interval_failures_u32(&pts, 2, m, t, 5, &Budget::DEFAULT)
            .unwrap()
            .is_empty()
    );
}

#[test]
fn sobol_with_one_point_moved_is_not_a_0m2_net() {
    let m = 8;
    let mut pts = block(&Sobol::new(2).unwrap(), 0, m);
    // Flip bit 8 (weight 2^-8) of point 5's x: it moves to the neighbouring x-cell of width
    // 1/256, which already holds a point. Only shape (8, 0) sees the change (coarser cells
    // are unchanged), so t = 1, and exactly two intervals fail: one with 2 points, one empty.
    let old = u64::from(pts[10] >> 24);
    pts[10] ^= 1 << 24;
    let new = u64::from(pts[10] >> 24);
    assert_eq!(t_value_u32(&pts, 2, m, &Budget::DEFAULT).unwrap(), 1);
    let failures = elementary_interval_failures_u32(&pts, 2, m, 0, 100, &Budget::DEFAULT).unwrap();
    for f in &failures {
        assert_is_a_real_failure(&pts, 2, m, f);
    }
    let named: Vec<(Vec<u32>, Vec<u64>, u64)> = failures
        .iter()
        .map(|f| (f.shape.clone(), f.cell.clone(), f.count))
        .collect();
    let mut want = vec![(vec![8, 0], vec![old, 0], 0), (vec![8, 0], vec![new, 0], 2)];
    want.sort_by_key(|w| w.1.clone());
    assert_eq!(named, want);
    // Display names the box.
    let s = failures[0].to_string();
    assert!(s.contains("shape") && s.contains("expected"), "{s}");
    // The f64 path names the same intervals.
    let f = Points::from_u32(&pts);
    let p = Points::new(&f, 2).unwrap();
    assert_eq!(
        elementary_interval_failures(p, 2, m, 0, 100, &Budget::DEFAULT).unwrap(),
        failures
    );
}

// ---- the rank test and counting agree ----

#[test]
fn rank_test_agrees_with_counting_on_sobol_projections_and_random_matrices() {
    let mut checked_positive_t = 0;
    // Sobol' projections with nonzero t, and prefixes of several dimension counts.
    let sets: Vec<Vec<usize>> = vec![
        vec![0],
        vec![0, 1, 2, 3],
        vec![2, 3],
        vec![3, 17],
        vec![5, 9, 13],
        vec![10, 20, 30, 40, 50],
    ];
    for dims in &sets {
        for m in [1, 4, 7, 10] {
            let net = DigitalNet2::from_sobol_dimensions(dims, m).unwrap();
            let t = t_value(&net, &Budget::DEFAULT).unwrap();
            let pts = net.points().unwrap();
            assert_eq!(
                t_value_u32(&pts, dims.len(), m, &Budget::DEFAULT).unwrap(),
                t,
                "{dims:?} m {m}"
            );
            checked_positive_t += usize::from(t > 0);
        }
    }
    // Random generator matrices (random columns): t anywhere in 0..=m.
    for seed in 0..60u64 {
        let s = 1 + (seed % 4) as usize;
        let m = 1 + (mix(seed) % 9) as u32;
        let columns: Vec<[u32; 32]> = (0..s)
            .map(|j| core::array::from_fn(|k| mix(seed * 1000 + j as u64 * 40 + k as u64) as u32))
            .collect();
        let net = DigitalNet2::new(m, columns).unwrap();
        let t = t_value(&net, &Budget::DEFAULT).unwrap();
        let pts = net.points().unwrap();
        assert_eq!(
            t_value_u32(&pts, s, m, &Budget::DEFAULT).unwrap(),
            t,
            "seed {seed} s {s} m {m}"
        );
        checked_positive_t += usize::from(t > 0);
        // The dependent shape is among the intervals that break t - 1.
        if let Some(shape) = dependent_shape(&net, &Budget::DEFAULT).unwrap() {
            let failures =
                elementary_interval_failures_u32(&pts, s, m, t - 1, usize::MAX, &Budget::DEFAULT)
                    .unwrap();
            assert!(failures.iter().any(|f| f.shape == shape), "seed {seed}");
        } else {
            assert_eq!(t, 0);
        }
    }
    assert!(checked_positive_t > 20, "{checked_positive_t}");
}

// ---- validation ----

#[test]
fn invalid_requests_are_errors() {
    assert_eq!(
        DigitalNet2::from_sobol(2, 33),
        Err(Error::MTooLarge { m: 33, max: 32 })
    );
    assert_eq!(DigitalNet2::from_sobol(0, 3), Err(Error::ZeroDimensions));
    assert!(matches!(
        DigitalNet2::from_sobol_dimensions(&[usize::MAX], 3),
        Err(Error::DimensionOutOfRange { .. })
    ));
    assert_eq!(
        t_value_u32(&[0; 6], 2, 2, &Budget::DEFAULT),
        Err(Error::BufferLength {
            expected: 8,
            got: 6
        })
    );
    assert_eq!(
        t_value_u32(&[0; 8], 0, 2, &Budget::DEFAULT),
        Err(Error::ZeroDimensions)
    );
    assert_eq!(
        t_value_u32(&[0; 8], 2, 40, &Budget::DEFAULT),
        Err(Error::MTooLarge { m: 40, max: 32 })
    );
    assert!(elementary_interval_failures_u32(&[0; 8], 2, 2, 3, 1, &Budget::DEFAULT).is_err());
    let d = [0.25, 0.75];
    let p = Points::new(&d, 1).unwrap();
    assert_eq!(
        t_value_points(p, 0, 1, &Budget::DEFAULT),
        Err(Error::BaseTooSmall { base: 0 })
    );
    assert_eq!(t_value_points(p, 2, 1, &Budget::DEFAULT), Ok(0));
    assert!(t_value_points(p, 2, 60, &Budget::DEFAULT).is_err());
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
fn rank_test_in_thousands_of_dimensions_needs_no_deep_stack() {
    for d in [10_000usize, 10_057, 21_201] {
        let (t, shape, net) = on_small_stack(move || {
            let net = DigitalNet2::from_sobol(d, 2).unwrap();
            (
                t_value(&net, &Budget::DEFAULT).unwrap(),
                dependent_shape(&net, &Budget::DEFAULT).unwrap(),
                net,
            )
        });
        // With m = 2 a dimension's first row is one of three non-zero 2-bit vectors (no
        // generator matrix of a Sobol' dimension has a zero first row, checked here on the
        // points: every top bit is balanced), so among thousands of dimensions two share it
        // (pigeonhole): a dependent shape of size 2, none of size 1, t = 1.
        let pts = net.points().unwrap();
        for j in 0..d {
            let ones: u32 = (0..4).map(|i| pts[i * d + j] >> 31).sum();
            assert_eq!(ones, 2, "d = {d}, dimension {j}");
        }
        assert_eq!(t, 1, "d = {d}");
        let shape = shape.unwrap();
        assert_eq!(shape.iter().sum::<u32>(), 2);
        // The two dimensions of the shape fail the (0, 2, 2)-net property when counted.
        let dims: Vec<usize> = (0..d).filter(|&j| shape[j] > 0).collect();
        assert_eq!(dims.len(), 2, "{dims:?}");
        let proj: Vec<u32> = (0..4)
            .flat_map(|i| [pts[i * d + dims[0]], pts[i * d + dims[1]]])
            .collect();
        assert!(
            !elementary_interval_failures_u32(&proj, 2, 2, 0, 1, &Budget::DEFAULT)
                .unwrap()
                .is_empty()
        );
    }
}

#[test]
fn rank_tests_past_the_budget_are_refused_at_once() {
    use qmckit::digital::rank::t_value;
    use qmckit::work::Budget;
    for (d, m) in [(50usize, 32u32), (1000, 20), (16, 32)] {
        let net = DigitalNet2::from_sobol(d, m).unwrap();
        let start = std::time::Instant::now();
        let got = t_value(&net, &Budget::DEFAULT);
        let secs = start.elapsed().as_secs_f64();
        assert!(
            matches!(got, Err(Error::OverBudget { .. })),
            "d = {d}, m = {m}: {got:?}"
        );
        assert!(secs < 1.0, "d = {d}, m = {m}: {secs} s");
        // A smaller budget refuses at least as soon.
        let tiny = Budget::seconds(0.001).unwrap();
        assert!(t_value(&net, &tiny).is_err());
    }
    // Within the budget, with progress: the same t as counting the points (an independent
    // algorithm) on 5D Sobol' with m = 12.
    use qmckit::analysis::tvalue::t_value_u32;
    let net = DigitalNet2::from_sobol(5, 12).unwrap();
    let reports = std::sync::Mutex::new(Vec::new());
    let t = t_value(
        &net,
        Limits::DEFAULT.with_progress(&|done, total| reports.lock().unwrap().push((done, total))),
    )
    .unwrap();
    let pts = net.points().unwrap();
    assert_eq!(t, t_value_u32(&pts, 5, 12, &Budget::UNLIMITED).unwrap());
    let reports = reports.into_inner().unwrap();
    assert_eq!(reports.last(), Some(&(1000, 1000)));
    assert!(reports.iter().all(|&(d, t)| d <= t));
}

#[test]
fn generated_points_and_counting_are_checked_in_size_and_time() {
    use qmckit::analysis::tvalue::t_value_u32;
    use qmckit::work::Budget;
    // 2^32 points in 2D are 32 GiB: an error, not an allocation.
    let net = DigitalNet2::from_sobol(2, 32).unwrap();
    assert!(matches!(net.points(), Err(Error::TooLarge { .. })));
    assert!(matches!(
        DigitalNet2::from_sobol(1, 29).unwrap().points(),
        Err(Error::TooLarge { .. })
    ));
    assert_eq!(
        DigitalNet2::from_sobol(3, 4)
            .unwrap()
            .points()
            .unwrap()
            .len(),
        48
    );
    // Counting 2^16 points in 8D: about C(23, 7) shapes a level, refused at once by the
    // default budget, computed without one.
    let pts = DigitalNet2::from_sobol(8, 16).unwrap().points().unwrap();
    let start = std::time::Instant::now();
    assert!(matches!(
        t_value_u32(&pts, 8, 16, &Budget::DEFAULT),
        Err(Error::OverBudget { .. })
    ));
    assert!(start.elapsed().as_secs_f64() < 0.5);
    let small = DigitalNet2::from_sobol(3, 8).unwrap();
    let want = t_value(&small, &Budget::DEFAULT).unwrap();
    let pts = small.points().unwrap();
    assert_eq!(t_value_u32(&pts, 3, 8, &Budget::UNLIMITED).unwrap(), want);
}

/// The deadline stops the counting search.
mod deadlines {
    use qmckit::analysis::tvalue::t_value_u32;
    use qmckit::work::Budget;
    use qmckit::{Error, Sampler, Sobol};

    #[test]
    fn an_expired_deadline_stops_counting() {
        let s = Sobol::new(4).unwrap();
        let mut pts = vec![0u32; 4 << 10];
        s.fill(0, &mut pts).unwrap();
        let b = Budget::seconds(0.5).unwrap().started();
        std::thread::sleep(std::time::Duration::from_millis(700));
        let r = t_value_u32(&pts, 4, 10, &b);
        assert!(matches!(r, Err(Error::OutOfTime { .. })), "{r:?}");
        assert_eq!(t_value_u32(&pts, 4, 10, &Budget::DEFAULT).ok(), Some(2));
    }
}
