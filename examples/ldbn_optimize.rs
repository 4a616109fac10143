//! Produces `tables/ldbn-128.bin`, the look-up table of [`qmckit::blue_noise::Ldbn`]:
//!
//! ```text
//! cargo run --release --features analysis --example ldbn_optimize -- OUT [MOVES_MILLIONS] [START]
//! ```
//!
//! `tables/ldbn-128.bin` is `OUT = tables/ldbn-128.bin` at the defaults (120 million
//! moves, deterministic: rerun, it rewrote the file byte for byte in 100 s of CPU).
//!
//! The table is `128 x 128` bytes: for cell `(X, Y)` the permutation index `p_X(Y mod
//! 16)` of its `x` offset (low nibble) and `p_Y(X mod 16)` of its `y` offset (high
//! nibble); see the module documentation of `blue_noise::ldbn`. The training set is the
//! one the table gives at `K = 128` cells a side (`N = 16384`, the table read once, no
//! symmetry, no low bits), on the torus: cell `(X, Y)` holds
//! `(X + rev_7(16 floor(Y/16) + p_X)/128, Y + rev_7(16 floor(X/16) + p_Y)/128)` in cell
//! units.
//!
//! Simulated annealing (Kirkpatrick, Gelatt & Vecchi 1983) over the moves that keep a
//! table a table: exchange the low nibbles of two entries of one aligned run of 16 down
//! a column (two points of a tile column exchange their `x` offsets) or the high nibbles
//! of two entries of a run along a row (`y` offsets). A move is made only if the run
//! keeps its nesting `NEST` (default 3: each aligned group of 2, 4, 8 entries keeps
//! distinct low 1, 2, 3 bits), so the sets stay `(3 - NEST, 2k, 2)`-nets: at 3, the
//! `(0, 2k, 2)`-net of the template. The energy is the pair sum, on the torus, in cell
//! units,
//!
//! `E = sum_(i<j) exp(-r_ij^2 / (2 SIGMA^2)) + W max(0, R0 - r_ij)^2`,
//!
//! the Gaussian blue-noise energy (Ahmed, Huang & Wonka 2022's objective, for the
//! spectrum) plus a hard core on pairs closer than `R0` (for the nearest-neighbour
//! distance), over the pairs within 3 cells in each axis. A move's change is summed over
//! the two moved points' neighbourhoods (about 200 kernel evaluations); the Metropolis
//! rule accepts it with probability `min(1, exp(-dE / T))`, `T` falling geometrically
//! from `T0` (the mean `|dE|` of 10^4 random moves from the start, times `HEAT`) to
//! `T0 / 10^4` over `MOVES_MILLIONS` (default 120) million moves, the last tenth at
//! `T = 0` (descent). The start is the identity table (at `NEST = 0`, random
//! permutations from splitmix64 seed 1), or the table in the file `START`. The defaults,
//! `SIGMA = 0.8`, `R0 = 0.92`, `W = 8`, `HEAT = 1`, `NEST = 3` (environment variables of
//! those names override them), were chosen by trials of 8 to 120 million moves on the
//! statistics below: at `NEST = 1` or 2 the annealing has more freedom (at 120 million
//! moves, `NEST = 2`: low band 0.0107, NN 0.937) but the nets are coarser; `SIGMA` 0.5 to
//! 0.6 gave larger NN (0.95) and a higher low band (0.02).
//!
//! The table goes to `OUT`; the energy, and the statistics of the sets it gives at
//! `N = 1024` (seeds 1 to 16: the mean radial power over `1 <= |k| <= 16`, the mean
//! nearest-neighbour distance times `sqrt(N)`, the star discrepancy of 4 seeds), go to
//! stderr, for the template (the identity table) and the result.

use qmckit::analysis::Points;
use qmckit::analysis::distance::mean_min_distance;
use qmckit::analysis::spectrum::{DEFAULT_TOLERANCE, Method, periodogram_2d};
use qmckit::analysis::star::star_exact;
use qmckit::blue_noise::Ldbn;
use qmckit::blue_noise::ldbn::{LDBN_PERIOD, LDBN_TILE, LdbnTable};
use qmckit::work::Budget;

const P: usize = LDBN_PERIOD;
const T: usize = LDBN_TILE;

/// Kernel parameters, cell units; overridable by the environment variables of the same
/// names (for experiments).
fn param(name: &str, default: f64) -> f64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// splitmix64.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The offset, in cells, of permutation index `p` in the tile run starting at `start`.
fn offset(start: usize, p: u8) -> f64 {
    let i = (start & !(T - 1)) | p as usize;
    (i as u32).reverse_bits() as f64 / 2f64.powi(32)
}

struct State {
    table: Vec<u8>,
    x: Vec<f64>,
    y: Vec<f64>,
    sigma2: f64,
    r0: f64,
    w: f64,
}

impl State {
    fn new(table: Vec<u8>, sigma: f64, r0: f64, w: f64) -> Self {
        let mut s = State {
            table,
            x: vec![0.0; P * P],
            y: vec![0.0; P * P],
            sigma2: 2.0 * sigma * sigma,
            r0,
            w,
        };
        for c in 0..P * P {
            s.place(c);
        }
        s
    }

    fn place(&mut self, c: usize) {
        let (cx, cy) = (c % P, c / P);
        let e = self.table[c];
        self.x[c] = cx as f64 + offset(cy, e & 15);
        self.y[c] = cy as f64 + offset(cx, e >> 4);
    }

    fn kernel(&self, dx: f64, dy: f64) -> f64 {
        let wrap = |d: f64| d - (d / P as f64).round() * P as f64;
        let (dx, dy) = (wrap(dx), wrap(dy));
        let r2 = dx * dx + dy * dy;
        let mut f = (-r2 / self.sigma2).exp();
        if r2 < self.r0 * self.r0 {
            let d = self.r0 - r2.sqrt();
            f += self.w * d * d;
        }
        f
    }

    /// The energy of the point of cell `c` placed at `(px, py)` against its
    /// neighbourhood, leaving out cells `skip`.
    fn local(&self, c: usize, px: f64, py: f64, skip: [usize; 2]) -> f64 {
        let (cx, cy) = ((c % P) as i64, (c / P) as i64);
        let mut e = 0.0;
        for dy in -3..=3i64 {
            for dx in -3..=3i64 {
                let o = ((cx + dx).rem_euclid(P as i64) + P as i64 * (cy + dy).rem_euclid(P as i64))
                    as usize;
                if o == c || o == skip[0] || o == skip[1] {
                    continue;
                }
                e += self.kernel(px - self.x[o], py - self.y[o]);
            }
        }
        e
    }

    fn total(&self) -> f64 {
        (0..P * P)
            .map(|c| self.local(c, self.x[c], self.y[c], [c, c]))
            .sum::<f64>()
            / 2.0
    }

    /// A random move: (the two cells, whether it exchanges low nibbles).
    fn propose(&self, rng: &mut Rng) -> (usize, usize, bool) {
        let a = rng.below(P);
        let run = rng.below(P / T) * T;
        let i = rng.below(T);
        let j = (i + 1 + rng.below(T - 1)) % T;
        if rng.next() & 1 == 0 {
            (a + P * (run + i), a + P * (run + j), true)
        } else {
            (run + i + P * a, run + j + P * a, false)
        }
    }

    /// The energy change of a move, and the moved points' new positions.
    fn delta(&self, (c1, c2, low): (usize, usize, bool)) -> (f64, [f64; 4]) {
        let (e1, e2) = (self.table[c1], self.table[c2]);
        let (n1, n2) = if low {
            ((e1 & 0xF0) | (e2 & 15), (e2 & 0xF0) | (e1 & 15))
        } else {
            ((e1 & 15) | (e2 & 0xF0), (e2 & 15) | (e1 & 0xF0))
        };
        let pos = |c: usize, e: u8| {
            let (cx, cy) = (c % P, c / P);
            (
                cx as f64 + offset(cy, e & 15),
                cy as f64 + offset(cx, e >> 4),
            )
        };
        let (a, b) = (pos(c1, n1), pos(c2, n2));
        let skip = [c1, c2];
        let before = self.local(c1, self.x[c1], self.y[c1], skip)
            + self.local(c2, self.x[c2], self.y[c2], skip)
            + self.kernel(self.x[c1] - self.x[c2], self.y[c1] - self.y[c2]);
        let after = self.local(c1, a.0, a.1, skip)
            + self.local(c2, b.0, b.1, skip)
            + self.kernel(a.0 - b.0, a.1 - b.1);
        (after - before, [a.0, a.1, b.0, b.1])
    }

    /// Whether the move keeps, in the runs it touches, every aligned group of `2^s`
    /// entries (`s <= nest`) with distinct low `s` bits of its nibbles.
    fn keeps(&self, (c1, c2, low): (usize, usize, bool), nest: u32) -> bool {
        if nest == 0 {
            return true;
        }
        let mut t = [0u8; T];
        let (run_start, step, shift) = if low {
            (c1 - P * ((c1 / P) % T), P, 0)
        } else {
            (c1 - (c1 % P) % T, 1, 4)
        };
        for (i, v) in t.iter_mut().enumerate() {
            let c = run_start + step * i;
            let e = if c == c1 {
                self.table[c2]
            } else if c == c2 {
                self.table[c1]
            } else {
                self.table[c]
            };
            *v = (e >> shift) & 15;
        }
        (1..=nest).all(|s| {
            let g = 1usize << s;
            t.chunks(g).all(|chunk| {
                let mut seen = 0u32;
                chunk.iter().all(|&v| {
                    let bit = 1u32 << (v as u32 & (g as u32 - 1));
                    let fresh = seen & bit == 0;
                    seen |= bit;
                    fresh
                })
            })
        })
    }

    fn apply(&mut self, (c1, c2, low): (usize, usize, bool)) {
        let (e1, e2) = (self.table[c1], self.table[c2]);
        let mask = if low { 15 } else { 0xF0 };
        self.table[c1] = (e1 & !mask) | (e2 & mask);
        self.table[c2] = (e2 & !mask) | (e1 & mask);
        self.place(c1);
        self.place(c2);
    }
}

/// The statistics at `N` of `table`: mean low-band power, mean NN distance times
/// `sqrt(N)`, mean star discrepancy of 4 seeds.
fn stats(table: &LdbnTable, n: u64, seeds: u64) -> Result<(f64, f64, f64), qmckit::Error> {
    let budget = Budget::seconds(600.0)?;
    let root = (n as f64).sqrt();
    let (mut low, mut nn, mut star) = (0.0, 0.0, 0.0);
    for seed in 1..=seeds {
        let set = Ldbn::new(n, seed)?.generate_with(table, &budget)?;
        let xy = set.to_f64();
        let p = Points::new(&xy, 2)?;
        let s = periodogram_2d(
            p,
            root.ceil() as usize,
            Method::Auto,
            DEFAULT_TOLERANCE,
            &budget,
        )?;
        let bins: Vec<f64> = s
            .radial()
            .iter()
            .filter(|b| (b.radius as f64) > 0.5 && (b.radius as f64) <= root / 2.0)
            .map(|b| b.mean)
            .collect();
        low += bins.iter().sum::<f64>() / bins.len() as f64 / seeds as f64;
        nn += mean_min_distance(p, false) * root / seeds as f64;
        if seed <= 4 {
            star += star_exact(p, &budget)? / 4.0;
        }
    }
    Ok((low, nn, star))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let out = args
        .first()
        .ok_or("usage: ldbn_optimize OUT [MOVES_MILLIONS] [START]")?;
    let millions: f64 = args.get(1).map_or(Ok(120.0), |a| a.parse())?;
    let (sigma, r0, w, heat) = (
        param("SIGMA", 0.8),
        param("R0", 0.92),
        param("W", 8.0),
        param("HEAT", 1.0),
    );
    let nest = param("NEST", 3.0) as u32;
    let mut rng = Rng(1);
    let table = match args.get(2) {
        Some(path) => std::fs::read(path)?,
        None if nest > 0 => LdbnTable::IDENTITY.entries().to_vec(),
        None => {
            let mut t = LdbnTable::IDENTITY.entries().to_vec();
            // Random permutations of every run: Fisher-Yates on the nibbles.
            for a in 0..P {
                for run in (0..P).step_by(T) {
                    for i in (1..T).rev() {
                        let j = rng.below(i + 1);
                        let (c1, c2) = (a + P * (run + i), a + P * (run + j));
                        let (e1, e2) = (t[c1], t[c2]);
                        t[c1] = (e1 & 0xF0) | (e2 & 15);
                        t[c2] = (e2 & 0xF0) | (e1 & 15);
                        let (r1, r2) = (run + i + P * a, run + j + P * a);
                        let (e1, e2) = (t[r1], t[r2]);
                        t[r1] = (e1 & 15) | (e2 & 0xF0);
                        t[r2] = (e2 & 15) | (e1 & 0xF0);
                    }
                }
            }
            t
        }
    };
    LdbnTable::new(&table)?;
    let mut s = State::new(table, sigma, r0, w);
    eprintln!(
        "SIGMA {sigma} R0 {r0} W {w} HEAT {heat}; start energy {:.3}",
        s.total()
    );
    let t0 = heat
        * (0..10_000)
            .map(|_| s.delta(s.propose(&mut rng)).0.abs().min(50.0))
            .sum::<f64>()
        / 1e4;
    let moves = (millions * 1e6) as u64;
    let hot = moves - moves / 10;
    let mut accepted = 0u64;
    for m in 0..moves {
        let temp = if m < hot {
            t0 * 1e-4f64.powf(m as f64 / hot as f64)
        } else {
            0.0
        };
        let mv = s.propose(&mut rng);
        if s.keeps(mv, nest) {
            let (d, _) = s.delta(mv);
            if d < 0.0 || (temp > 0.0 && rng.unit() < (-d / temp).exp()) {
                s.apply(mv);
                accepted += 1;
            }
        }
        if (m + 1) % (moves / 10).max(1) == 0 {
            eprintln!(
                "{:.0}M moves, T {temp:.2e}: energy {:.3}, accepted {accepted}",
                (m + 1) as f64 / 1e6,
                s.total()
            );
            accepted = 0;
        }
    }
    let table = LdbnTable::new(&s.table)?;
    std::fs::write(out, table.entries())?;
    for (name, t) in [("template", &LdbnTable::IDENTITY), ("table", &table)] {
        let (low, nn, star) = stats(t, 1024, 16)?;
        eprintln!("N 1024, {name}: low band {low:.4}, NN {nn:.4}, D* {star:.5}");
    }
    Ok(())
}
