//! The optimizer of the correction table of [`Penrose`](super::Penrose): Lloyd
//! relaxation carried out in the leaves' own frames and averaged over each structural
//! class and band, as Ostromoukhov, Donohue & Jodoin 2004 learn their correction vectors
//! offline by relaxation, one table row for each of 21 positions of the threshold in a
//! level's period (the procedure here is ours).
//!
//! A leaf's class is its index among the leaves of its ancestor five levels up (233
//! classes: 89 under a thin, 144 under a thick triangle); its band is the threshold
//! fraction `t` of the set, `(phi^-2, 1]` cut into 21 bands equal in `log t`. An iteration,
//! for each band, at [`SUBS`] values of `t` spread over the band (the middles of its equal
//! thirds in `log t`, so that every leaf a set of that band can keep is trained), and each
//! seed, takes the first `t` of the square's leaves by rank, places them with the current
//! table, and measures each sample's Lloyd displacement `d` (its Voronoi cell's centroid
//! minus the sample; the cells found on a raster of 48 pixels a sample, nearest sample by
//! k-d tree). Samples within `2 / sqrt n` of the border are left out (their cells are cut
//! by it). `d` is written in the leaf's frame, `d = alpha (b - a) + beta (c - a)` (legs of
//! the leaf), and the mean `(alpha, beta)` of each class and band is added to its table
//! entry. The table starts at zero, so the result depends only on the arguments. The
//! squares trained on are those of seeds `2^32 + s`, apart from the seeds of ordinary use.
//!
//! Cost: `iterations x bands x SUBS x seeds x (48 n log n)` for `n` samples (a
//! nearest-sample search a pixel); estimated against the budget and stopped at its
//! deadline.
//!
//! `examples/gen_penrose_table.rs` runs it and writes `tables/penrose_corrections.rs`.

use super::kdtree::KdTree;
use super::penrose::{BANDS, CLASSES, NO_CLASS, Table, depth_for, leg, place, ranked};
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// Raster pixels a sample.
const PIXELS: f64 = 48.0;

/// Nearest-sample searches, each counted as `log2 n` steps, a second (one core, release:
/// the table of `examples/gen_penrose_table.rs`, 5.2e10 such steps, took 441 s on a loaded
/// machine, 1.2e8 a second; taken at a quarter of that).
const SEARCHES: Rate = Rate::per_second(3e7);

/// The golden ratio.
const PHI: f64 = 1.618_033_988_749_895;

/// Values of the threshold fraction trained in each band.
pub const SUBS: usize = 3;

/// The seed of the first square trained on.
const FIRST_SEED: u64 = 1 << 32;

/// A trained table and, per iteration, the mean squared Lloyd displacement over the
/// interior samples, in units of the squared hexagonal spacing `2 / (sqrt 3 n)`.
#[derive(Clone, Debug)]
pub struct Trained {
    /// The table.
    pub table: Table,
    /// The displacement energy before each iteration's update.
    pub energy: Vec<f64>,
}

/// Trains a table on sets of about `points` samples (64 to 2^16), `iterations` (1 to
/// 1000) Lloyd steps, `seeds` (1 to 64) squares a band and step.
///
/// # Errors
/// [`Error::InvalidParameter`] outside those ranges; [`Error::OverBudget`],
/// [`Error::OutOfTime`].
pub fn train(points: u64, iterations: u32, seeds: u64, budget: &Budget) -> Result<Trained> {
    if !(64..=1 << 16).contains(&points)
        || !(1..=1000).contains(&iterations)
        || !(1..=64).contains(&seeds)
    {
        return Err(Error::InvalidParameter {
            what: "penrose training takes 64 to 2^16 points, 1 to 1000 iterations, 1 to 64 seeds",
        });
    }
    let budget = budget.started();
    let n = points as f64 * PHI * PHI;
    let searches = f64::from(iterations) * (BANDS as u64 * SUBS as u64 * seeds) as f64 * PIXELS * n;
    budget.check(
        "penrose training",
        Cost::steps(searches * n.log2(), SEARCHES),
    )?;
    let levels = depth_for(points as f64)?;
    let sets = (0..seeds)
        .map(|s| ranked(levels, FIRST_SEED + s, &budget))
        .collect::<Result<Vec<_>>>()?;
    let mut table: Table = [[[0.0; 2]; CLASSES]; BANDS];
    let mut energy = Vec::new();
    let leg = leg(levels);
    for _ in 0..iterations {
        let mut sum = [[[0.0f64; 2]; CLASSES]; BANDS];
        let mut count = [[0u64; CLASSES]; BANDS];
        let (mut e_sum, mut e_count) = (0.0, 0u64);
        for bs in 0..BANDS * SUBS {
            // Band b = bs / SUBS at the middle of its third: t = phi^(-2 (bs + 1/2) / (3 BANDS)).
            let b = bs / SUBS;
            let (sum, count) = (&mut sum[b], &mut count[b]);
            let t = PHI.powf(-2.0 * (bs as f64 + 0.5) / (BANDS * SUBS) as f64);
            for (leaves, frame, _) in &sets {
                let k = ((t * leaves.len() as f64).round() as usize).clamp(1, leaves.len());
                let chosen = &leaves[..k];
                let mut xy = crate::size::vec_with_capacity::<f64>(2 * k)?;
                for l in chosen {
                    xy.extend(place(l, frame, leg, b, &table));
                }
                let d = lloyd_displacements(&xy, &budget)?;
                let margin = 2.0 / (k as f64).sqrt();
                let hex2 = 2.0 / (3f64.sqrt() * k as f64);
                for (i, l) in chosen.iter().enumerate() {
                    let (x, y) = (xy[2 * i], xy[2 * i + 1]);
                    if l.class == NO_CLASS
                        || !(margin..1.0 - margin).contains(&x)
                        || !(margin..1.0 - margin).contains(&y)
                    {
                        continue;
                    }
                    let di = d[i];
                    e_sum += (di[0] * di[0] + di[1] * di[1]) / hex2;
                    e_count += 1;
                    let [e1, e2] = l.dirs.map(|q| {
                        let a = f64::from(q) * core::f64::consts::PI / 10.0;
                        frame.rotate([leg * a.cos(), leg * a.sin()])
                    });
                    let det = e1[0] * e2[1] - e1[1] * e2[0];
                    let alpha = (di[0] * e2[1] - di[1] * e2[0]) / det;
                    let beta = (e1[0] * di[1] - e1[1] * di[0]) / det;
                    let c = usize::from(l.class);
                    sum[c][0] += alpha;
                    sum[c][1] += beta;
                    count[c] += 1;
                }
            }
        }
        energy.push(e_sum / e_count.max(1) as f64);
        for b in 0..BANDS {
            for c in 0..CLASSES {
                if count[b][c] > 0 {
                    let m = count[b][c] as f64;
                    table[b][c][0] += sum[b][c][0] / m;
                    table[b][c][1] += sum[b][c][1] / m;
                }
            }
        }
    }
    Ok(Trained { table, energy })
}

/// The Lloyd displacement of each of the samples `xy` (row-major, 2D, in the square):
/// its Voronoi cell's centroid (on a raster of [`PIXELS`] pixels a sample, clipped to the
/// square) minus the sample.
fn lloyd_displacements(xy: &[f64], budget: &Budget) -> Result<Vec<[f64; 2]>> {
    let k = xy.len() / 2;
    let tree = KdTree::new(xy, 2, false)?;
    let side = (PIXELS * k as f64).sqrt().ceil() as usize;
    let mut acc = crate::size::vec_zeroed::<[f64; 3]>(k)?;
    let (mut lo, mut hi) = ([0.0; 2], [0.0; 2]);
    let mut pacer = budget.pacer("penrose training");
    for j in 0..side {
        for i in 0..side {
            pacer.tick()?;
            let q = [
                (i as f64 + 0.5) / side as f64,
                (j as f64 + 0.5) / side as f64,
            ];
            let (s, _) = tree.nearest(&q, &mut lo, &mut hi);
            if let Some(a) = acc.get_mut(s as usize) {
                a[0] += q[0];
                a[1] += q[1];
                a[2] += 1.0;
            }
        }
    }
    Ok(acc
        .iter()
        .enumerate()
        .map(|(i, a)| {
            if a[2] > 0.0 {
                [a[0] / a[2] - xy[2 * i], a[1] / a[2] - xy[2 * i + 1]]
            } else {
                [0.0, 0.0]
            }
        })
        .collect())
}

/// The table as the Rust array literal `tables/penrose_corrections.rs` holds: a band a
/// block, four entries a line, five decimals (a hundred-thousandth of a leg).
pub fn table_source(table: &Table) -> String {
    let mut s = String::from("[\n");
    for row in table {
        s.push_str("[\n");
        for line in row.chunks(4) {
            for [a, b] in line {
                s.push_str(&format!("[{a:.5},{b:.5}],"));
            }
            s.push('\n');
        }
        s.push_str("],\n");
    }
    s.push_str("]\n");
    s
}
