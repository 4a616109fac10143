//! Times the L2-type discrepancies of `qmckit::analysis::l2` on one thread, for
//! `scripts/time_discrepancy.py` (which times SciPy on the same points).
//!
//! Usage: `cargo run --release --features analysis --example time_l2 -- FILE DIMS REPS [METRIC...]`
//!
//! `FILE` holds the points as whitespace-separated decimal numbers, row-major, `DIMS` to a
//! point. Each metric (command-line names `l2-star`, `cd`, `wd`, `md`, ...; default the
//! four of SciPy) runs `REPS` times in a one-thread rayon pool; the output is one line
//! `metric best_seconds value` per metric, the value printed with 17 significant digits.

use qmckit::analysis::Points;
use qmckit::analysis::l2::L2Metric;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [file, dims, reps, names @ ..] = args.as_slice() else {
        return Err("usage: time_l2 FILE DIMS REPS [METRIC...]".into());
    };
    let dims: usize = dims.parse()?;
    let reps: usize = reps.parse::<usize>()?.max(1);
    let text = std::fs::read_to_string(file)?;
    let data = text
        .split_whitespace()
        .map(str::parse::<f64>)
        .collect::<Result<Vec<f64>, _>>()?;
    let p = Points::new(&data, dims)?;
    let metrics: Vec<L2Metric> = if names.is_empty() {
        L2Metric::ALL[..4].to_vec()
    } else {
        names
            .iter()
            .map(|n| {
                L2Metric::ALL
                    .iter()
                    .copied()
                    .find(|m| m.name() == n)
                    .ok_or_else(|| format!("unknown metric {n}"))
            })
            .collect::<Result<_, _>>()?
    };
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    for m in metrics {
        let (best, value) = pool.install(|| {
            let mut best = f64::INFINITY;
            let mut value = Ok(f64::NAN);
            for _ in 0..reps {
                let start = Instant::now();
                value = m.eval(p, &qmckit::work::Budget::UNLIMITED);
                best = best.min(start.elapsed().as_secs_f64());
            }
            (best, value)
        });
        match value {
            Ok(v) => println!("{} {best:.9} {v:.16e}", m.name()),
            Err(e) => println!("{} {best:.9} error: {e}", m.name()),
        }
    }
    Ok(())
}
