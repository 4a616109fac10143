//! Deadlines: a budget started and left to expire (its estimate admits the work) stops
//! every super-linear loop of the star family and the L2 sums with `OutOfTime`; an
//! unexpired one gives the same value as no budget.

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
