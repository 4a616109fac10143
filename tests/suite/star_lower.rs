//! `star_lower_bound` (threshold accepting after Gnewuch, Wahlström & Winzen 2012): never
//! above the exact star discrepancy (`star_exact`, itself checked against brute force in
//! `star_discrepancy.rs`), usually equal to it on small sets, and in 20D close to the lower
//! bound of Thiémard's bracketing cover (`star::thiemard::bounds`), an independent algorithm.
#![cfg(feature = "analysis")]

use qmckit::Sobol;
use qmckit::analysis::Points;
use qmckit::analysis::star::thiemard::bounds;
use qmckit::analysis::star::{star, star_lower_bound};
use qmckit::work::Budget;

use crate::common;
use common::Rng;

#[test]
fn never_above_and_mostly_equal_to_the_exact_value() {
    let mut rng = Rng(2012);
    let (mut equal, mut total) = (0, 0);
    for d in 2..=5 {
        for trial in 0..25u64 {
            let n = 5 + (rng.next() % 36) as usize;
            let q = if trial % 3 == 0 { Some(6) } else { None };
            let data = rng.set(n, d, q);
            let p = Points::new(&data, d).unwrap();
            let exact = star(p).unwrap();
            let lower = star_lower_bound(p, trial, 4000, &Budget::UNLIMITED).unwrap();
            // Exact up to the rounding of the volume products (a few ulps).
            assert!(
                lower <= exact + 1e-14,
                "d = {d}, n = {n}: {lower} > {exact}"
            );
            assert!(lower >= 0.5 * exact, "d = {d}, n = {n}: {lower} << {exact}");
            total += 1;
            equal += usize::from(exact - lower <= 1e-14);
        }
    }
    // Measured: 93 of 100 (the misses are uniform sets in 4D and 5D, at most 0.03 below).
    eprintln!("equal to the exact value in {equal} of {total}");
    assert!(
        equal * 100 >= total * 85,
        "equal in only {equal} of {total}"
    );
}

#[test]
fn deterministic_for_a_seed() {
    let data = Rng(5).set(200, 6, None);
    let p = Points::new(&data, 6).unwrap();
    assert_eq!(
        star_lower_bound(p, 3, 3000, &Budget::UNLIMITED).unwrap(),
        star_lower_bound(p, 3, 3000, &Budget::UNLIMITED).unwrap()
    );
}

#[test]
fn sobol_20d_reaches_the_bracketing_lower_bound() {
    let (n, d) = (1000usize, 20usize);
    let s = Sobol::new(d).unwrap();
    let mut raw = vec![0u32; n * d];
    for (i, row) in raw.chunks_mut(d).enumerate() {
        for (k, c) in row.iter_mut().enumerate() {
            *c = s.sample(i as u32, k).unwrap();
        }
    }
    let data = Points::from_u32(&raw);
    let p = Points::new(&data, d).unwrap();
    let thiemard = bounds(p, 0.7, &Budget::DEFAULT).unwrap().lower;
    let lower = star_lower_bound(p, 1, 20_000, &Budget::UNLIMITED).unwrap();
    eprintln!("20D Sobol', N = {n}: threshold accepting {lower}, Thiémard lower {thiemard}");
    // Measured: 0.0612 against Thiémard's 0.0500; the uniform-neighbourhood search this
    // replaced found 0.0010 (= 1/N) at the same iteration count.
    assert!(lower >= thiemard, "{lower} vs {thiemard}");
}

#[test]
fn threshold_accepting_is_budgeted() {
    // The same value as without a budget when it fits.
    let data: Vec<f64> = (0..60).map(|i| ((i * 37) % 60) as f64 / 60.0).collect();
    let p = Points::new(&data, 3).unwrap();
    assert_eq!(
        star_lower_bound(p, 5, 4000, &Budget::DEFAULT).unwrap(),
        star_lower_bound(p, 5, 4000, &Budget::UNLIMITED).unwrap()
    );
    // One point in 20000 dimensions with a billion iterations: about 2e16 steps, refused at
    // once.
    let big = vec![0.5; 20_000];
    let p = Points::new(&big, 20_000).unwrap();
    let start = std::time::Instant::now();
    assert!(matches!(
        star_lower_bound(p, 0, 1_000_000_000, &Budget::DEFAULT),
        Err(qmckit::Error::OverBudget { .. })
    ));
    assert!(start.elapsed().as_secs_f64() < 0.5);
}
