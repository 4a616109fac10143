//! Writes `tables/art_offsets.rs`, the offset table of `qmckit::blue_noise::Art`: descent
//! of the sum, over the prefix sizes `N = 2^LOG2` (`LOG2 SIZES`), of the mismatch between the
//! pair correlation of the `N`-point set on the torus (in units of its mean spacing) and
//! that of step blue noise with cutoff `U0` (Heck, Schlömer & Deussen 2013). A sample's
//! gradient goes to the table entry of the tile that placed it (times that tile's side); an
//! entry moves by the mean of its gradients (scaled to a root-mean-square move of 0.01
//! tile, shrinking to 0.001) and stays in `[0.02, 0.98]`.
//!
//! With `W > 0` each size's objective also has a hard core: `W sum (R0 - r)^2 / N` over
//! the pairs closer than `R0` mean spacings (the paper relaxes its offsets to spread the
//! samples of every level; the pair-correlation term alone leaves pairs as close as in
//! jittered sampling).
//!
//! With `V > 0` each size's objective also has an axis term, `V sum_(d, j <= 3 sqrt N)
//! |S_d(j)|^2 / (N j^2)`, `S_d(j)` the Fourier sum of the `d`-th coordinates at frequency
//! `j`: the squared `L2` discrepancy of the two projections on the axes (up to a constant;
//! Parseval), which the pair correlation and the hard core do not see. Without it the
//! 1024-point prefix, one sample in each `1/32` square, keeps its samples in the middle of
//! those squares (the projections' discrepancy is `0.015`, the star discrepancy 0.024).
//! `START`, a table file written by this program, replaces the random start.
//!
//! At the end the table's 32 sets (seeds 1 to 32) of 256, 1024 and
//! 4096 points are measured as `scripts/utk_compare.sh` measures them, the means printed to
//! standard error.
//!
//! `cargo run --release --features analysis --example art_optimize [U0] [STEPS] [R0] [W] [LOG2 SIZES] [V] [START] > tables/art_offsets.rs`
//! (defaults 0.5, 1200, 1.0, 2000, `8,10,10,10,10,10,10,10,12`: 256, 4096 and, seven
//! times, 1024, the size between two complete levels, where the tables are weakest; 100;
//! the random start). The shipped table is the second of
//!
//! ```sh
//! cargo run --release --features analysis --example art_optimize 0.5 1200 1.0 2000 8,10,10,10,10,10,10,10,12 0 > /tmp/art-start.rs
//! cargo run --release --features analysis --example art_optimize 0.5 1200 1.0 2000 8,10,10,10,10,10,10,10,12 100 /tmp/art-start.rs > tables/art_offsets.rs
//! ```

#[path = "common/gauss.rs"]
mod gauss;
#[path = "common/set_stats.rs"]
mod set_stats;

use qmckit::blue_noise::art::{ART_IDS, Art, ArtTable, tiles};
use qmckit::work::Budget;

/// The entries `[o_x, o_y],` of a table file as written by this program (a start).
fn read_table(path: &str) -> Vec<[f64; 2]> {
    let text = std::fs::read_to_string(path).expect("start table");
    let t: Vec<[f64; 2]> = text
        .lines()
        .filter_map(|l| {
            let l = l.trim().strip_prefix('[')?.strip_suffix("],")?;
            let (a, b) = l.split_once(',')?;
            Some([a.trim().parse().ok()?, b.trim().parse().ok()?])
        })
        .collect();
    assert_eq!(t.len(), ART_IDS, "512 entries");
    t
}

/// The weighted power of the two coordinate projections, `V sum_(d, j <= J) |S_d(j)|^2 /
/// (N j^2)` with `S_d(j) = sum_i exp(-2 pi i j x_(i,d))` (the squared `L2` discrepancy of
/// each projection up to a constant, by Parseval), its gradient added to `grad` in units of
/// `1/scale` (the spacing units of the other terms). `pts` in the unit torus.
fn axis_energy(pts: &[[f64; 2]], jmax: usize, v: f64, scale: f64, grad: &mut [[f64; 2]]) -> f64 {
    let n = pts.len() as f64;
    let tau = 2.0 * core::f64::consts::PI;
    let mut e = 0.0;
    for d in 0..2 {
        for j in 1..=jmax {
            let jf = j as f64;
            let (mut re, mut im) = (0.0, 0.0);
            for p in pts {
                let (s, c) = (tau * jf * p[d]).sin_cos();
                re += c;
                im -= s;
            }
            let w = v / (n * jf * jf);
            e += w * (re * re + im * im);
            // d|S|^2/dx_i = 4 pi j Im(conj(S) exp(-i theta_i)).
            for (p, g) in pts.iter().zip(grad.iter_mut()) {
                let (s, c) = (tau * jf * p[d]).sin_cos();
                let imag = re * (-s) - im * c;
                g[d] += w * 2.0 * tau * jf * imag / scale;
            }
        }
    }
    e
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let u0: f64 = args.get(1).map_or(0.5, |s| s.parse().expect("U0"));
    let steps: usize = args.get(2).map_or(1200, |s| s.parse().expect("STEPS"));
    let r0: f64 = args.get(3).map_or(1.0, |s| s.parse().expect("R0"));
    let w: f64 = args.get(4).map_or(2000.0, |s| s.parse().expect("W"));
    let log2_sizes = args
        .get(5)
        .map_or("8,10,10,10,10,10,10,10,12", String::as_str);
    let v: f64 = args.get(6).map_or(100.0, |s| s.parse().expect("V"));
    let mut state = 0x853c_49e6_748f_ea9bu64;
    let mut next = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) as f64 / 18_446_744_073_709_551_616.0
    };
    let mut table: Vec<[f64; 2]> = (0..ART_IDS)
        .map(|_| [0.2 + 0.6 * next(), 0.2 + 0.6 * next()])
        .collect();
    if let Some(path) = args.get(7) {
        table = read_table(path);
    }
    let sizes: Vec<u64> = log2_sizes
        .split(',')
        .map(|b| 1u64 << b.parse::<u32>().expect("LOG2 SIZES"))
        .collect();
    for step in 0..steps {
        let t = ArtTable::new(table.clone().try_into().expect("512 entries")).expect("table");
        let mut pacer = Budget::DEFAULT.started().pacer("art optimize");
        let all = tiles(3, 4096.0, &t, &mut pacer).expect("tiles");
        let mut sorted = all.clone();
        sorted.sort_unstable_by_key(|t| t.rank);
        let mut g = vec![[0.0; 2]; ART_IDS];
        let mut count = vec![0u32; ART_IDS];
        let mut total = 0.0;
        let mut axis_total = 0.0;
        for &n in &sizes {
            let scale = (n as f64).sqrt();
            let set = &sorted[..n as usize];
            let p: Vec<[f64; 2]> = set.iter().map(|t| t.point.map(|v| v * scale)).collect();
            let mut grad = vec![[0.0; 2]; p.len()];
            let centres = vec![true; p.len()];
            let target = |r: f64| gauss::step_pcf(r, u0);
            total += gauss::pcf_mismatch(&p, &centres, Some(scale), &target, &mut grad);
            if w > 0.0 {
                let mut hc = vec![[0.0; 2]; p.len()];
                let k = w / p.len() as f64;
                total += k * gauss::hard_core(&p, &centres, Some(scale), r0, &mut hc);
                for (g, d) in grad.iter_mut().zip(&hc) {
                    g[0] += k * d[0];
                    g[1] += k * d[1];
                }
            }
            if v > 0.0 {
                let pts: Vec<[f64; 2]> = set.iter().map(|t| t.point).collect();
                let e = axis_energy(&pts, 3 * scale as usize, v, scale, &mut grad);
                total += e;
                axis_total += e;
            }
            for (t, gr) in set.iter().zip(&grad) {
                let (id, level) = (usize::from(t.source.0), t.source.1);
                if level == 0 {
                    continue;
                }
                let side = 0.25f64.powi(level as i32) * scale;
                g[id][0] += gr[0] * side;
                g[id][1] += gr[1] * side;
                count[id] += 1;
            }
        }
        // Every entry moves by its mean gradient, scaled so that the root-mean-square move
        // is 0.01 tile (shrinking over the run).
        let mean: Vec<[f64; 2]> = (0..ART_IDS)
            .map(|b| g[b].map(|v| v / f64::from(count[b].max(1))))
            .collect();
        let rms = (mean.iter().flatten().map(|v| v * v).sum::<f64>() / ART_IDS as f64).sqrt();
        let rate = 0.01 * (1.0 - step as f64 / steps as f64 * 0.9) / rms.max(1e-300);
        for id in 0..ART_IDS {
            if count[id] > 0 {
                for k in 0..2 {
                    let v = table[id][k] - rate * mean[id][k];
                    table[id][k] = v.clamp(0.02, 0.98);
                }
            }
        }
        if step % 50 == 0 || step + 1 == steps {
            eprintln!(
                "step {step}: objective summed over sizes {total:.5} (axis term {axis_total:.5})"
            );
        }
    }
    let t = ArtTable::new(table.clone().try_into().expect("512 entries")).expect("table");
    for n in [256, 1024, 4096] {
        let sets: Vec<Vec<f64>> = (1..=32)
            .map(|seed| {
                Art::new(n)
                    .expect("points")
                    .seed(seed)
                    .table(t.clone())
                    .generate(&Budget::DEFAULT)
                    .expect("set")
                    .to_f64()
            })
            .collect();
        let (nn, low, mid) = set_stats::mean_nn_low_mid(&sets);
        let star = set_stats::mean_star(&sets);
        eprintln!(
            "32 sets of {n}: D* {star:.5}, NN {nn:.4}, low band {low:.4}, band sqrt(N)/2..sqrt(N) {mid:.3}"
        );
    }
    println!(
        "// The offset table of ART (qmckit::blue_noise::art), by word c + 16 i + 256 t,\n\
         // in tile units. Written by\n\
         // `cargo run --release --features analysis --example art_optimize {u0} {steps} {r0} {w} {log2_sizes} {v}{}`.",
        args.get(7).map_or(String::new(), |p| format!(" {p}"))
    );
    println!("[");
    for o in &table {
        println!("    [{:.6}, {:.6}],", o[0], o[1]);
    }
    println!("]");
}
