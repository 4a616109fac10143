//! Writes `tables/aa_displacements.rs`, the displacement table of
//! `qmckit::blue_noise::AaPattern`: descent of the mismatch between the pair correlation of
//! a `192 x 192` patch of the pattern (cell units, unit density; around the cells at least
//! 3 from the border) and that of step blue noise with cutoff `U0` (Heck, Schlömer &
//! Deussen 2013), each step on a patch from a fresh start label, laid on the turned lattice
//! `G / K` of `qmckit::blue_noise::aa::lattice` for the sides `SIDES` in turn (the shapes
//! the sampler uses at `N = K^2`, each within 10% of a rotation). A bin's displacement moves
//! by the mean gradient of the cells that read it (the moves scaled to a root-mean-square of
//! 0.01 cell, shrinking to 0.001), and stays within `[-0.45, 0.45]` (the point in its cell).
//! The start is uniform in `[-INIT/2, INIT/2]`.
//!
//! With `W > 0` the objective also has a hard core: `W sum (R0 - r)^2` over the pairs
//! closer than `R0` mean spacings (the paper's blue-noise tables keep points apart; the
//! pair-correlation term alone leaves pairs as close as in jittered sampling). At the end
//! the table's 32 sets of 1024 points (seeds 1 to 32) are measured as
//! `scripts/utk_compare.sh` measures them and the means printed to standard error.
//!
//! `cargo run --release --features analysis --example aa_optimize [U0] [STEPS] [INIT] [R0] [W] [SIDES] > tables/aa_displacements.rs`
//! (defaults 0.5, 600, 0.9, 1.04, 20000, `16,32,64,128`).

#[path = "common/gauss.rs"]
mod gauss;
#[path = "common/set_stats.rs"]
mod set_stats;

use qmckit::blue_noise::aa::{AA_BINS, AaPattern, AaTable, bin, label, lattice};
use qmckit::work::Budget;

const PATCH: u32 = 192;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let u0: f64 = args.get(1).map_or(0.5, |s| s.parse().expect("U0"));
    let steps: usize = args.get(2).map_or(600, |s| s.parse().expect("STEPS"));
    let init: f64 = args.get(3).map_or(0.9, |s| s.parse().expect("INIT"));
    let r0: f64 = args.get(4).map_or(1.04, |s| s.parse().expect("R0"));
    let w: f64 = args.get(5).map_or(20000.0, |s| s.parse().expect("W"));
    let sides: Vec<u32> = args
        .get(6)
        .map_or("16,32,64,128", String::as_str)
        .split(',')
        .map(|k| k.parse().expect("SIDES"))
        .collect();
    // The lattice of each side, `G / K` (module `qmckit::blue_noise::aa`, "The lattice").
    let shapes: Vec<[f64; 3]> = sides
        .iter()
        .map(|&k| lattice(k).map(|v| f64::from(v) / f64::from(k)))
        .collect();
    let bins = AA_BINS * AA_BINS;
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    };
    let mut table: Vec<[f64; 2]> = (0..bins)
        .map(|_| {
            let mut u = || ((next() >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * init;
            [u(), u()]
        })
        .collect();
    let n = (PATCH * PATCH) as usize;
    let mut ids = vec![0usize; n];
    let mut p = vec![[0.0; 2]; n];
    let mut grad = vec![[0.0; 2]; n];
    for step in 0..steps {
        let s = [next() as u32, (next() >> 32) as u32];
        let [a, b, d] = shapes[step % shapes.len()];
        for y in 0..PATCH {
            for x in 0..PATCH {
                let i = (x + PATCH * y) as usize;
                ids[i] = bin(label(s, x, y));
                let e = table[ids[i]];
                let u = [f64::from(x) + 0.5 + e[0], f64::from(y) + 0.5 + e[1]];
                p[i] = [a * u[0] - b * u[1], b * u[0] + d * u[1]];
            }
        }
        grad.iter_mut().for_each(|g| *g = [0.0; 2]);
        let centres: Vec<bool> = (0..n)
            .map(|i| {
                let (x, y) = (i as u32 % PATCH, i as u32 / PATCH);
                x >= 3 && y >= 3 && x < PATCH - 3 && y < PATCH - 3
            })
            .collect();
        let e = gauss::pcf_mismatch(&p, &centres, None, &|r| gauss::step_pcf(r, u0), &mut grad);
        let mut hc = vec![[0.0; 2]; n];
        let h = if w > 0.0 {
            gauss::hard_core(&p, &centres, None, r0, &mut hc) / centres.len() as f64
        } else {
            0.0
        };
        for (g, d) in grad.iter_mut().zip(&hc) {
            g[0] += w * d[0] / n as f64;
            g[1] += w * d[1] / n as f64;
        }
        let mut g = vec![[0.0; 2]; bins];
        let mut count = vec![0u32; bins];
        for (i, &b) in ids.iter().enumerate() {
            // Interior cells only: the patch border has fewer neighbours.
            let (x, y) = (i as u32 % PATCH, i as u32 / PATCH);
            if x < 4 || y < 4 || x >= PATCH - 4 || y >= PATCH - 4 {
                continue;
            }
            g[b][0] += grad[i][0];
            g[b][1] += grad[i][1];
            count[b] += 1;
        }
        // Every entry moves by its mean gradient, scaled so that the root-mean-square move
        // is `MOVE` cells (shrinking over the run).
        let mean: Vec<[f64; 2]> = (0..bins)
            .map(|b| g[b].map(|v| v / f64::from(count[b].max(1))))
            .collect();
        let rms = (mean.iter().flatten().map(|v| v * v).sum::<f64>() / bins as f64).sqrt();
        let rate = 0.01 * (1.0 - step as f64 / steps as f64 * 0.9) / rms.max(1e-300);
        for b in 0..bins {
            if count[b] > 0 {
                for k in 0..2 {
                    let v = table[b][k] - rate * mean[b][k];
                    table[b][k] = v.clamp(-0.45, 0.45);
                }
            }
        }
        if step % 50 == 0 || step + 1 == steps {
            eprintln!("step {step}: PCF mismatch {e:.5}, hard core {h:.6}");
        }
    }
    let t = AaTable::new(table.clone().try_into().expect("AA_BINS^2 entries")).expect("table");
    let sets: Vec<Vec<f64>> = (1..=32)
        .map(|seed| {
            AaPattern::new(1024, seed)
                .expect("1024 points")
                .table(t.clone())
                .generate(&Budget::DEFAULT)
                .expect("set")
                .to_f64()
        })
        .collect();
    let (nn, low, mid) = set_stats::mean_nn_low_mid(&sets);
    let star = set_stats::mean_star(&sets);
    eprintln!(
        "32 sets of 1024: D* {star:.5}, NN {nn:.4}, low band {low:.4}, band sqrt(N)/2..sqrt(N) {mid:.3}"
    );
    println!(
        "// The displacement table of AA patterns (qmckit::blue_noise::aa), by bin\n\
         // u + {AA_BINS} v of the label torus, in cell units. Written by\n\
         // `cargo run --release --features analysis --example aa_optimize {u0} {steps} {init} {r0} {w} {}`.",
        args.get(6).map_or("16,32,64,128", String::as_str)
    );
    println!("[");
    for d in &table {
        println!("    [{:.6}, {:.6}],", d[0], d[1]);
    }
    println!("]");
}
