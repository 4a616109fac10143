//! Calibrates the time estimates of the analysis (see `docs/budgets.md`): runs a computation
//! on one thread and prints its CPU time next to the estimate's share of one core.
//!
//! Usage: `cargo run --release --all-features --example time_costs -- KIND ARGS`, with KIND
//!
//! * `star D N...`: the exact star discrepancy of the first `N` Sobol' points in `D`
//!   dimensions (the 2D sweep, or the decomposition from `D = 3`);
//! * `l2 METRIC D N...`: one L2 measure (`l2-star`, `cd`, `wd`, ...) of `N` Sobol' points;
//! * `level D M RHO...`: every shape of size `RHO` counted (listing the unbalanced
//!   intervals of `t = M - RHO`) for the first `2^M` Owen-scrambled Sobol' points;
//! * `tvalue D M...`: the t-value by counting of the first `2^M` Owen-scrambled Sobol'
//!   points, and of `2^M` uniform random points (`rnd`, t usually `M - 1` or `M`).
//!
//! Each line: `kind d n cpu_seconds estimate_seconds ratio`, where `cpu_seconds` is the least
//! CPU time of `REPS` runs (environment, default 3) of the computation alone (repeated
//! within a run when it is short) in a one-thread
//! rayon pool, read from the thread's scheduler statistics (Linux; elsewhere the wall
//! time), and `estimate_seconds` is the library's estimate times the parallel speed-up it
//! assumes ([`qmckit::work::CORES`]): the estimate for one core. A ratio near 1 means the
//! per-core rate is right; under load the CPU time grows a little (shared caches).

use qmckit::analysis::Points;
use qmckit::analysis::l2::L2Metric;
use qmckit::analysis::star;
use qmckit::analysis::tvalue::{
    elementary_interval_failures_u32, failures_cost, t_value_cost, t_value_u32,
};
use qmckit::work::{Budget, CORES};
use qmckit::{OwenSobol, Sampler, Sobol};
use std::time::Instant;

type Error = Box<dyn std::error::Error>;

/// CPU seconds of the calling thread (the wall clock where the statistics are missing).
fn thread_seconds(wall: Instant) -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or_else(|| wall.elapsed().as_secs_f64(), |ns| ns * 1e-9)
}

/// The least CPU time of `reps` runs of `f` on one thread. The scheduler's statistics lag
/// by up to a tick (a few milliseconds), so a short computation is repeated within each run
/// until the run takes about a fifth of a second, and the time divided.
fn least_cpu(reps: usize, mut f: impl FnMut()) -> f64 {
    let wall = Instant::now();
    f();
    let once = wall.elapsed().as_secs_f64();
    let inner = (0.2 / once.max(1e-6)).ceil().clamp(1.0, 1e4) as usize;
    let mut best = f64::INFINITY;
    for _ in 0..reps {
        let wall = Instant::now();
        let start = thread_seconds(wall);
        for _ in 0..inner {
            f();
        }
        best = best.min((thread_seconds(wall) - start) / inner as f64);
    }
    best
}

fn sobol(n: usize, d: usize) -> Result<Vec<f64>, Error> {
    let mut v = vec![0f64; n * d];
    Sobol::new(d)?.fill_as(0, &mut v)?;
    Ok(v)
}

fn row(kind: &str, d: usize, n: usize, cpu: f64, estimate: f64) {
    println!(
        "{kind} {d} {n} {cpu:.4} {estimate:.4} {:.2}",
        cpu / estimate
    );
}

fn main() -> Result<(), Error> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let reps: usize = std::env::var("REPS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(3);
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    let nums = |s: &[String]| -> Result<Vec<usize>, Error> {
        s.iter().map(|x| Ok(x.parse::<usize>()?)).collect()
    };
    match args.split_first() {
        Some((kind, rest)) if kind == "star" => {
            let v = nums(rest)?;
            let Some((&d, sizes)) = v.split_first() else {
                return Err("usage: time_costs star D N...".into());
            };
            for &n in sizes {
                let data = sobol(n, d)?;
                let p = Points::new(&data, d)?;
                let cpu = pool.install(|| {
                    least_cpu(reps, || {
                        let _ = star::star_exact(p, &Budget::UNLIMITED);
                    })
                });
                row("star", d, n, cpu, star::star_cost(n, d).seconds() * CORES);
            }
        }
        Some((kind, rest)) if kind == "l2" => {
            let Some((name, rest)) = rest.split_first() else {
                return Err("usage: time_costs l2 METRIC D N...".into());
            };
            let metric = L2Metric::ALL
                .into_iter()
                .find(|m| m.name() == name)
                .ok_or_else(|| format!("unknown metric {name}"))?;
            let v = nums(rest)?;
            let Some((&d, sizes)) = v.split_first() else {
                return Err("usage: time_costs l2 METRIC D N...".into());
            };
            for &n in sizes {
                let data = sobol(n, d)?;
                let p = Points::new(&data, d)?;
                let cpu = pool.install(|| {
                    least_cpu(reps, || {
                        let _ = metric.eval(p, &Budget::UNLIMITED);
                    })
                });
                row(name, d, n, cpu, metric.cost(n, d).seconds() * CORES);
            }
        }
        Some((kind, rest)) if kind == "tvalue" => {
            let v = nums(rest)?;
            let Some((&d, ms)) = v.split_first() else {
                return Err("usage: time_costs tvalue D M...".into());
            };
            for &m in ms {
                let m = u32::try_from(m)?;
                let n = 1usize << m;
                let mut owen = vec![0u32; n * d];
                OwenSobol::new(d, 1)?.fill(0, &mut owen)?;
                let mut state = 0x2545_F491_4F6C_DD1Du64;
                let rnd: Vec<u32> = (0..n * d)
                    .map(|_| {
                        state ^= state << 13;
                        state ^= state >> 7;
                        state ^= state << 17;
                        (state >> 32) as u32
                    })
                    .collect();
                let estimate = t_value_cost(1u64 << m, d, m, 2, None).seconds() * CORES;
                for (kind, pts) in [("owen", &owen), ("rnd", &rnd)] {
                    let mut t = 0;
                    let cpu = pool.install(|| {
                        least_cpu(reps, || {
                            t = t_value_u32(pts, d, m, &Budget::UNLIMITED).unwrap_or(u32::MAX);
                        })
                    });
                    row(&format!("tvalue-{kind}-t{t}"), d, n, cpu, estimate);
                }
            }
        }
        Some((kind, rest)) if kind == "level" => {
            let v = nums(rest)?;
            let [d, m, rhos @ ..] = v.as_slice() else {
                return Err("usage: time_costs level D M RHO...".into());
            };
            let (d, m) = (*d, u32::try_from(*m)?);
            let n = 1usize << m;
            let mut owen = vec![0u32; n * d];
            OwenSobol::new(d, 1)?.fill(0, &mut owen)?;
            for &rho in rhos {
                let rho = u32::try_from(rho)?;
                let mut found = 0;
                let cpu = pool.install(|| {
                    least_cpu(reps, || {
                        found = elementary_interval_failures_u32(
                            &owen,
                            d,
                            m,
                            m - rho,
                            usize::MAX,
                            &Budget::UNLIMITED,
                        )
                        .map_or(usize::MAX, |f| f.len());
                    })
                });
                let estimate = failures_cost(1u64 << m, d, rho, 2).seconds() * CORES;
                row(&format!("level-rho{rho}-fail{found}"), d, n, cpu, estimate);
            }
        }
        _ => return Err("usage: time_costs star|l2|tvalue ARGS (see the source)".into()),
    }
    Ok(())
}
