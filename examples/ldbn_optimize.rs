//! Produces `tables/ldbn-2x2.txt`, the look-up table of [`qmckit::blue_noise::Ldbn`]:
//!
//! ```text
//! cargo run --release --features analysis --example ldbn_optimize -- [MINUTES] > tables/ldbn-2x2.txt
//! ```
//!
//! Coordinate descent over the 256 entries (configuration -> exchanges, 16 choices each):
//! every choice of an entry is tried with the others fixed and kept when it lowers the
//! objective, sweeps repeated until one changes nothing (or the time budget, default 30
//! minutes, runs out). The objective is the Gaussian pair energy of Ahmed, Ren & Wonka's
//! Gaussian blue noise, `sum_(i<j) exp(-|x_i - x_j|^2 / (2 s^2))` on the torus, with
//! `s = SIGMA / sqrt(N)` (pairs farther than `3 s` ignored), per point, averaged over a
//! training batch of templates (seeds from 1000, disjoint from the seeds the tests use).
//! The table goes to stdout; the energies, and the mean radial power at low frequencies
//! on held-out seeds (template against table), go to stderr.

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::blue_noise::Ldbn;
use qmckit::blue_noise::ldbn::LdbnTable;
use qmckit::work::Budget;

/// The kernel width in units of the mean spacing `1/sqrt(N)`.
const SIGMA: f64 = 0.4;

/// Training templates: (N, how many seeds).
const TRAINING: [(u64, u64); 2] = [(1024, 24), (4096, 6)];

/// The Gaussian pair energy of `pts` (0.32 fractions, 2D, one point a cell of the
/// `side x side` grid), per point, on the torus.
fn energy(pts: &[u32], side: usize) -> f64 {
    let n = pts.len() / 2;
    let xy: Vec<(f64, f64)> = pts
        .chunks_exact(2)
        .map(|p| (qmckit::bits::to_f64(p[0]), qmckit::bits::to_f64(p[1])))
        .collect();
    let mut grid = vec![0usize; side * side];
    for (i, &(x, y)) in xy.iter().enumerate() {
        let (c, r) = ((x * side as f64) as usize, (y * side as f64) as usize);
        grid[c.min(side - 1) + side * r.min(side - 1)] = i;
    }
    let s = SIGMA / (n as f64).sqrt();
    let inv = 1.0 / (2.0 * s * s);
    let reach = ((3.0 * s * side as f64).ceil() as i64 + 1).min(side as i64 / 2);
    let wrap = |d: f64| d - d.round();
    let mut e = 0.0;
    for (i, &(x, y)) in xy.iter().enumerate() {
        let (c, r) = ((x * side as f64) as i64, (y * side as f64) as i64);
        for dr in -reach..=reach {
            for dc in -reach..=reach {
                let cc = (c + dc).rem_euclid(side as i64) as usize;
                let rr = (r + dr).rem_euclid(side as i64) as usize;
                let j = grid[cc + side * rr];
                if j <= i {
                    continue;
                }
                let (dx, dy) = (wrap(xy[j].0 - x), wrap(xy[j].1 - y));
                let d2 = dx * dx + dy * dy;
                if d2 < 9.0 * s * s {
                    e += (-d2 * inv).exp();
                }
            }
        }
    }
    e / n as f64
}

/// The mean training energy of `table`.
fn objective(table: LdbnTable) -> Result<f64, qmckit::Error> {
    let mut total = 0.0;
    let mut sets = 0.0;
    for (n, seeds) in TRAINING {
        let side = (n as f64).sqrt() as usize;
        for seed in 1000..1000 + seeds {
            let set = Ldbn::new(n, seed)?
                .table(table)
                .generate(&Budget::DEFAULT)?;
            total += energy(set.coords(), side);
            sets += 1.0;
        }
    }
    Ok(total / sets)
}

/// Mean radial power over the annuli `1 <= r <= sqrt(N)/2`, over held-out seeds.
fn low_power(n: u64, table: LdbnTable) -> Result<f64, qmckit::Error> {
    let half = ((n as f64).sqrt() / 2.0) as usize;
    let mut sum = 0.0;
    let seeds = 0..16u64;
    for seed in seeds.clone() {
        let set = Ldbn::new(n, seed)?
            .table(table)
            .generate(&Budget::DEFAULT)?;
        let xy = set.to_f64();
        let s = spectrum_2d(Points::new(&xy, 2)?, half, &Budget::DEFAULT)?;
        let radial = s.radial();
        sum += radial.iter().map(|b| b.mean).sum::<f64>() / radial.len() as f64;
    }
    Ok(sum / seeds.count() as f64)
}

fn main() -> Result<(), qmckit::Error> {
    let minutes: f64 = std::env::args()
        .nth(1)
        .map_or(Ok(30.0), |a| a.parse())
        .map_err(|_| qmckit::Error::InvalidParameter {
            what: "the argument is the time budget in minutes",
        })?;
    let budget = Budget::seconds(minutes * 60.0)?.started();
    let mut entries = [0u8; 256];
    let mut best = objective(LdbnTable::IDENTITY)?;
    eprintln!("template energy {best:.6}");
    'sweeps: for sweep in 0..8 {
        let mut changed = false;
        for e in 0..256 {
            for choice in 0..16u8 {
                if budget.check_deadline("the LDBN optimizer").is_err() {
                    eprintln!("time budget reached");
                    break 'sweeps;
                }
                if choice == entries[e] {
                    continue;
                }
                let mut trial = entries;
                trial[e] = choice;
                let f = objective(LdbnTable::new(trial)?)?;
                if f < best {
                    (best, entries, changed) = (f, trial, true);
                }
            }
        }
        eprintln!("sweep {sweep}: energy {best:.6}");
        if !changed {
            break;
        }
    }
    let table = LdbnTable::new(entries)?;
    for n in [1024u64, 4096] {
        let (t, o) = (low_power(n, LdbnTable::IDENTITY)?, low_power(n, table)?);
        eprintln!(
            "N {n}: mean radial power, r <= sqrt(N)/2, 16 held-out seeds: template {t:.4}, table {o:.4}"
        );
    }
    println!(
        "# LDBN look-up table, 2 x 2 tiles: configuration (0..255, row-major) -> exchanges (0..15)."
    );
    println!(
        "# Produced by examples/ldbn_optimize.rs (coordinate descent on the Gaussian pair energy,"
    );
    println!(
        "# sigma {SIGMA} / sqrt(N), training seeds from 1000 at N = 1024 and 4096); energy {best:.6}."
    );
    for row in entries.chunks(16) {
        let cells: Vec<String> = row.iter().map(|v| v.to_string()).collect();
        println!("{}", cells.join(" "));
    }
    Ok(())
}
