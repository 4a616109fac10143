//! Integration with an error estimate: exact values and Student-t quantiles against SciPy
//! (tests/golden/gen_integrate.py), interval coverage over the 20 test problems, and the
//! tolerance loop's stopping point against an oracle that knows the true variance.

use qmckit::Sampler;
use qmckit::analysis::integrate::{Options, Problem, integrate, t_quantile, test_suite};
use qmckit::randomize::{CranleyPatterson, FastOwen, Scrambled};
use qmckit::work::Budget;
use qmckit::{Sobol, lattice::Rank1Lattice};
use rayon::prelude::*;

fn golden(name: &str) -> String {
    let path = format!("{}/tests/golden/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn owen_sobol(d: usize) -> impl Fn(u64) -> qmckit::Result<Scrambled<Sobol, FastOwen>> {
    move |seed| Ok(Scrambled::new(Sobol::new(d)?, FastOwen::new(seed)))
}

#[test]
fn exact_values_match_scipy() {
    let want: Vec<(String, f64)> = golden("integrate_exact.txt")
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let (n, v) = l.split_once(' ').unwrap();
            (n.to_owned(), v.parse().unwrap())
        })
        .collect();
    let suite = test_suite();
    assert_eq!(suite.len(), 20);
    for (p, (name, value)) in suite.iter().zip(&want) {
        assert_eq!(&p.name, name);
        let got = p.exact();
        assert!(
            (got - value).abs() <= 1e-10 * value.abs().max(1.0),
            "{name}: {got} vs {value}"
        );
    }
}

#[test]
fn student_t_quantiles_match_scipy() {
    for line in golden("student_t.txt")
        .lines()
        .filter(|l| !l.starts_with('#'))
    {
        let v: Vec<f64> = line.split(' ').map(|t| t.parse().unwrap()).collect();
        let got = t_quantile(v[0], v[1] as u32).unwrap();
        assert!((got - v[2]).abs() < 1e-8 * v[2], "{line}: {got}");
    }
    assert!(t_quantile(0.95, 0).is_err());
    assert!(t_quantile(1.0, 3).is_err());
    assert!(t_quantile(f64::NAN, 3).is_err());
}

/// The interval of one fixed-size run (`n` points, `r` replications) covers the truth?
fn covers(p: &Problem, seed: u64, n: u64, r: u32) -> bool {
    let opts = Options {
        replications: r,
        abs_tol: 0.0,
        n_start: n,
        max_points: n * u64::from(r),
        seed,
        ..Options::default()
    };
    let est = integrate(
        |x| p.eval(x),
        p.dims,
        owen_sobol(p.dims),
        &opts,
        &Budget::UNLIMITED,
    )
    .unwrap();
    assert_eq!(est.n, n);
    let (lo, hi) = est.interval();
    lo <= p.exact() && p.exact() <= hi
}

fn coverage(reps: u64, r: u32) -> Vec<(String, f64)> {
    test_suite()
        .par_iter()
        .map(|p| {
            let hits = (0..reps).filter(|&k| covers(p, k * 1000, 256, r)).count();
            (p.name.clone(), hits as f64 / reps as f64)
        })
        .collect()
}

fn check_coverage(reps: u64, r: u32, floor_each: f64) {
    let cov = coverage(reps, r);
    let mean = cov.iter().map(|c| c.1).sum::<f64>() / cov.len() as f64;
    eprintln!("coverage over {reps} repetitions: mean {mean:.3}, {cov:?}");
    assert!(mean >= 0.90, "mean coverage {mean}: {cov:?}");
    for (name, c) in &cov {
        assert!(*c >= floor_each, "{name}: {c}");
    }
}

/// 95% intervals (8 Owen-scrambled Sobol' replications of 256 points) cover the truth in
/// at least 90% of the repetitions, averaged over the 20 problems (40 repetitions here).
#[test]
fn intervals_cover_the_truth() {
    check_coverage(40, 8, 0.7);
}

/// The full run: 1000 repetitions with the default 16 replications of 256 points: at least
/// 90% for every problem (and on average).
#[test]
#[ignore = "about a minute in release; CI runs it"]
fn intervals_cover_the_truth_1000_repetitions() {
    check_coverage(1000, Options::default().replications, 0.90);
}

/// The tolerance loop stops at most one doubling after an oracle that knows the true
/// standard error (measured over 100 independent replicate means at each n): in at
/// least 90% of 50 runs per problem, `n_stop <= 2 n_oracle`.
#[test]
fn tolerance_stops_within_twice_the_needed_points() {
    let problems: Vec<Problem> = test_suite()
        .into_iter()
        .filter(|p| {
            ["genz-gaussian-d5", "keister-d3", "asian-geometric-d4"].contains(&p.name.as_str())
        })
        .collect();
    let r = 8u32;
    let t = t_quantile(0.95, r - 1).unwrap();
    for p in &problems {
        let exact = p.exact();
        let tol = 1e-4 * exact.abs().max(1.0);
        // The oracle: the smallest n = 2^m whose true half-width t sigma_n / sqrt(r) <= tol.
        let mut n_oracle = 0;
        for m in 6..=18u32 {
            let n = 1u64 << m;
            let means: Vec<f64> = (0..100u64)
                .into_par_iter()
                .map(|k| {
                    let opts = Options {
                        replications: 2,
                        abs_tol: 0.0,
                        n_start: n,
                        max_points: 2 * n,
                        seed: 1_000_000 + 2 * k,
                        ..Options::default()
                    };
                    integrate(
                        |x| p.eval(x),
                        p.dims,
                        owen_sobol(p.dims),
                        &opts,
                        &Budget::UNLIMITED,
                    )
                    .unwrap()
                    .value
                })
                .collect();
            // Each value is the mean of 2 replications: its variance is sigma_n^2 / 2.
            let mse = means.iter().map(|v| (v - exact).powi(2)).sum::<f64>() / 100.0;
            let sigma = (2.0 * mse).sqrt();
            if t * sigma / f64::from(r).sqrt() <= tol {
                n_oracle = n;
                break;
            }
        }
        assert!(n_oracle > 0, "{}: the oracle needs more than 2^18", p.name);
        let within = (0..50u64)
            .into_par_iter()
            .filter(|&k| {
                let opts = Options {
                    replications: r,
                    abs_tol: tol,
                    n_start: 64,
                    seed: 7 + 100 * k,
                    ..Options::default()
                };
                let est = integrate(
                    |x| p.eval(x),
                    p.dims,
                    owen_sobol(p.dims),
                    &opts,
                    &Budget::UNLIMITED,
                )
                .unwrap();
                est.converged && est.n <= 2 * n_oracle
            })
            .count();
        eprintln!(
            "{}: oracle n {n_oracle}, {within}/50 stopped by 2 n",
            p.name
        );
        assert!(within >= 45, "{}: {within}/50", p.name);
    }
}

#[test]
fn works_with_shifted_lattices_and_reports_the_budget() {
    let p = &test_suite()[0];
    let make = |seed| {
        Ok(Scrambled::new(
            Rank1Lattice::kuo(p.dims)?,
            CranleyPatterson::new(seed),
        ))
    };
    let opts = Options {
        abs_tol: 1e-6,
        ..Options::default()
    };
    let est = integrate(|x| p.eval(x), p.dims, make, &opts, &Budget::UNLIMITED).unwrap();
    assert!(est.converged, "{est:?}");
    assert!((est.value - p.exact()).abs() < 1e-5);
    assert_eq!(est.points, est.n * 16);
    // A tolerance that cannot be met within the budget: not converged, budget respected.
    let opts = Options {
        abs_tol: 1e-15,
        max_points: 1 << 16,
        ..Options::default()
    };
    let est = integrate(|x| p.eval(x), p.dims, make, &opts, &Budget::UNLIMITED).unwrap();
    assert!(!est.converged && est.points <= 1 << 16);
}

#[test]
fn bad_options_are_refused() {
    let f = |x: &[f64]| x[0];
    let ok = Options::default();
    for bad in [
        Options {
            replications: 1,
            ..ok
        },
        Options {
            abs_tol: -1.0,
            ..ok
        },
        Options {
            rel_tol: f64::NAN,
            ..ok
        },
        Options { level: 1.0, ..ok },
        Options { n_start: 100, ..ok },
        Options {
            max_points: 10,
            ..ok
        },
    ] {
        assert!(
            integrate(f, 1, owen_sobol(1), &bad, &Budget::UNLIMITED).is_err(),
            "{bad:?}"
        );
    }
    assert!(integrate(f, 2, owen_sobol(1), &ok, &Budget::UNLIMITED).is_err()); // wrong dimension
    assert!(integrate(|_| f64::NAN, 1, owen_sobol(1), &ok, &Budget::UNLIMITED).is_err());
    let small = |_| Rank1Lattice::linear([1u32], 16);
    assert!(integrate(f, 1, small, &ok, &Budget::UNLIMITED).is_err()); // fewer points than n_start
    let _ = Sobol::new(1).unwrap().len();
}

/// Points used to reach the same absolute tolerance as QMCPy's CubQMCSobolG (median over
/// 10 seeds, tests/golden/compare_qmcpy_cubqmc.py), printed; ours (16 Owen-scrambled
/// Sobol' replications, Student-t interval) must converge and stay within 32x.
#[test]
fn points_used_against_qmcpy() {
    let suite = test_suite();
    for line in golden("qmcpy_cubqmc_points.txt")
        .lines()
        .filter(|l| !l.starts_with('#'))
    {
        let f: Vec<&str> = line.split(' ').collect();
        let (name, tol, theirs): (&str, f64, u64) =
            (f[0], f[1].parse().unwrap(), f[2].parse().unwrap());
        let p = suite.iter().find(|p| p.name == name).unwrap();
        let mut used: Vec<u64> = (0..10u64)
            .into_par_iter()
            .map(|k| {
                let opts = Options {
                    abs_tol: tol,
                    n_start: 64,
                    seed: 500 + 100 * k,
                    ..Options::default()
                };
                let est = integrate(
                    |x| p.eval(x),
                    p.dims,
                    owen_sobol(p.dims),
                    &opts,
                    &Budget::UNLIMITED,
                )
                .unwrap();
                assert!(est.converged, "{name}");
                est.points
            })
            .collect();
        used.sort_unstable();
        let ours = used[5];
        eprintln!("{name} tol {tol}: qmckit {ours} points (median), CubQMCSobolG {theirs}");
        assert!(ours <= 32 * theirs, "{name}: {ours} vs {theirs}");
    }
}

/// Overflowing values, huge replication counts and the deadline.
mod checks {
    use qmckit::Error;
    use qmckit::Sobol;
    use qmckit::analysis::integrate::{Options, integrate};
    use qmckit::randomize::{CranleyPatterson, Scrambled};
    use qmckit::work::Budget;

    fn make(seed: u64) -> qmckit::Result<Scrambled<Sobol, CranleyPatterson>> {
        Ok(Scrambled::new(Sobol::new(2)?, CranleyPatterson::new(seed)))
    }

    #[test]
    fn overflowing_sums_are_not_representable() {
        for v in [1e308, -1e308, f64::MAX] {
            let r = integrate(|_| v, 2, make, &Options::default(), &Budget::UNLIMITED);
            assert!(
                matches!(r, Err(Error::NotRepresentable { .. })),
                "{v}: {r:?}"
            );
        }
    }

    #[test]
    fn too_many_replications_are_refused() {
        let o = Options {
            replications: u32::MAX,
            max_points: u64::MAX,
            ..Options::default()
        };
        assert!(matches!(
            integrate(|_| 1.0, 2, make, &o, &Budget::UNLIMITED),
            Err(Error::InvalidParameter { .. })
        ));
    }

    #[test]
    fn an_expired_deadline_stops_the_loop() {
        let b = Budget::seconds(0.01).unwrap().started();
        std::thread::sleep(std::time::Duration::from_millis(20));
        let r = integrate(|x| x[0], 2, make, &Options::default(), &b);
        assert!(matches!(r, Err(Error::OutOfTime { .. })), "{r:?}");
    }
}
