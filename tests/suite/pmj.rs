//! PMJ02 against its definition: every aligned block of 2^m points is a (0, m, 2)-net
//! (Christensen, Kensler & Kilpatrick 2018), for m <= 16 and 1000 seeds; the xor values of
//! Helmer, Christensen & Kensler 2021 (their published listing, and OpenQMC's table); the
//! buffer fill and the random access agree.

use qmckit::Sampler;
use qmckit::pmj::{Pmj02, XOR, fill};

/// Every aligned block of `2^m` points, for every `m <= log2(n)`, is a (0, m, 2)-net: for
/// each `m` and split `k + (m - k)`, the key (block, x cell, y cell) never repeats.
fn first_block_failure(pts: &[[u32; 2]]) -> Option<(u32, u32, usize)> {
    let n = pts.len();
    let log_n = n.trailing_zeros();
    let mut seen = vec![false; n];
    for m in 0..=log_n {
        for k in 0..=m {
            seen.iter_mut().for_each(|s| *s = false);
            for (idx, p) in pts.iter().enumerate() {
                let a = if k == 0 {
                    0
                } else {
                    (p[0] >> (32 - k)) as usize
                };
                let b = if k == m {
                    0
                } else {
                    (p[1] >> (32 - (m - k))) as usize
                };
                let key = ((idx >> m) << m) | (a << (m - k)) | b;
                if std::mem::replace(&mut seen[key], true) {
                    return Some((m, k, idx));
                }
            }
        }
    }
    None
}

#[test]
fn xor_values_match_the_published_ones() {
    // Helmer et al. 2021, from the Stirling-number matrices (pmj02 x and y).
    assert_eq!(XOR[0][..10], [0, 0, 2, 6, 6, 0xe, 0x36, 0x4e, 0x16, 0x2e]);
    assert_eq!(XOR[1][..10], [0, 1, 3, 3, 7, 0x1b, 0x27, 0xb, 0x17, 0x13b]);
    // All 16 levels as OpenQMC's stochastic.h tabulates them (its PMJ_XORS).
    let x16 = [
        0, 0, 2, 6, 6, 0xe, 0x36, 0x4e, 0x16, 0x2e, 0x276, 0x6ce, 0x716, 0xc2e, 0x3076, 0x40ce,
    ];
    let y16 = [
        0, 1, 3, 3, 7, 0x1b, 0x27, 0xb, 0x17, 0x13b, 0x367, 0x38b, 0x617, 0x183b, 0x2067, 0x8b,
    ];
    assert_eq!(XOR[0][..16], x16);
    assert_eq!(XOR[1][..16], y16);
    for (d, row) in XOR.iter().enumerate() {
        for (l, &x) in row.iter().enumerate() {
            assert!(
                (x as u64) < 1 << l,
                "xor[{d}][{l}] must only pair earlier points"
            );
        }
    }
}

/// Every aligned block is a net for each seed of `seeds` (two threads); `make` builds the
/// sequence of a seed.
fn nets_over_seeds(seeds: std::ops::Range<u64>, make: impl Fn(u64) -> Vec<[u32; 2]> + Sync) {
    let make = &make;
    let failures: Vec<String> = std::thread::scope(|s| {
        let workers: Vec<_> = (0..2usize)
            .map(|w| {
                let seeds = seeds.clone();
                s.spawn(move || {
                    seeds
                        .skip(w)
                        .step_by(2)
                        .filter_map(|seed| {
                            first_block_failure(&make(seed))
                                .map(|f| format!("seed {seed}: (m, k, index) {f:?}"))
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });
    assert!(failures.is_empty(), "{failures:?}");
}

#[test]
fn every_aligned_block_is_a_net_for_1000_seeds() {
    nets_over_seeds(0..1000, |seed| {
        let mut pts = vec![[0u32; 2]; 1 << 16];
        fill(seed, &mut pts).unwrap();
        pts
    });
}

#[test]
fn fill_and_random_access_agree() {
    for seed in [0u64, 1, 99, u64::MAX] {
        let mut pts = vec![[0u32; 2]; 3000];
        fill(seed, &mut pts).unwrap();
        let p = Pmj02::new(seed);
        for (k, q) in pts.iter().enumerate() {
            assert_eq!(
                *q,
                [
                    p.sample(k as u32, 0).unwrap(),
                    p.sample(k as u32, 1).unwrap()
                ]
            );
        }
        let mut flat = vec![0u32; 6000];
        p.fill(0, &mut flat).unwrap();
        assert!(flat.chunks(2).zip(&pts).all(|(a, b)| a == b));
        let mut tail = vec![0u32; 10];
        p.fill(2990, &mut tail).unwrap();
        assert_eq!(tail[..2], pts[2990]);
        // Deep indices: the chain is at most 32 parents long.
        let last = p.sample(u32::MAX, 1).unwrap();
        assert_eq!(last, p.sample(u32::MAX, 1).unwrap());
    }
    assert!(Pmj02::new(0).sample(0, 2).is_err());
}

#[test]
fn seeds_give_different_sequences() {
    let mut a = vec![[0u32; 2]; 64];
    let mut b = vec![[0u32; 2]; 64];
    fill(1, &mut a).unwrap();
    fill(2, &mut b).unwrap();
    assert!(a.iter().zip(&b).filter(|(x, y)| x == y).count() < 2);
}

mod christensen {
    use qmckit::pmj::christensen::{self, DEFAULT_CANDIDATES, MAX_CANDIDATES, workspace_len};
    use qmckit::pmj::{XOR, fill as fill02};
    use qmckit::work::Budget;

    fn make(seed: u64, k: u32, n: usize) -> Vec<[u32; 2]> {
        let mut pts = vec![[0u32; 2]; n];
        let mut work = vec![0u32; workspace_len(n).unwrap()];
        christensen::fill(seed, k, &mut pts, &mut work, &Budget::UNLIMITED).unwrap();
        pts
    }

    fn nets_over_seeds(seeds: std::ops::Range<u64>, k: u32, n: usize) {
        super::nets_over_seeds(seeds, |seed| make(seed, k, n));
    }

    #[test]
    fn aligned_blocks_are_nets_1000_seeds_2_10() {
        // The strata constraint holds for every candidate, so few candidates suffice to
        // exercise it; the default count is checked on fewer seeds below.
        nets_over_seeds(0..1000, 4, 1 << 10);
        nets_over_seeds(1000..1020, DEFAULT_CANDIDATES, 1 << 10);
    }

    #[test]
    fn aligned_blocks_are_nets_2_16_few_seeds() {
        nets_over_seeds(0..2, DEFAULT_CANDIDATES, 1 << 16);
        nets_over_seeds(2..4, 1, 1 << 16);
    }

    #[test]
    #[ignore = "1000 seeds x 2^16 points: minutes; run with --ignored"]
    fn aligned_blocks_are_nets_2_16_1000_seeds() {
        nets_over_seeds(0..1000, 8, 1 << 16);
    }

    #[test]
    fn a_shorter_fill_is_a_prefix_and_seeds_differ() {
        let long = make(5, 10, 5000);
        for n in [1, 2, 3, 7, 16, 100, 1024, 3001] {
            assert_eq!(make(5, 10, n)[..], long[..n], "n = {n}");
        }
        let other = make(6, 10, 64);
        assert!(other.iter().zip(&long).filter(|(a, b)| a == b).count() < 2);
        assert_eq!(make(5, 10, 5000), long);
    }

    #[test]
    fn bad_input_is_an_error() {
        let mut pts = vec![[0u32; 2]; 100];
        let mut work = vec![0u32; workspace_len(100).unwrap()];
        assert!(christensen::fill(0, 0, &mut pts, &mut work, &Budget::UNLIMITED).is_err());
        assert!(
            christensen::fill(
                0,
                MAX_CANDIDATES + 1,
                &mut pts,
                &mut work,
                &Budget::UNLIMITED
            )
            .is_err()
        );
        let short = work.len() - 1;
        assert!(christensen::fill(0, 1, &mut pts, &mut work[..short], &Budget::UNLIMITED).is_err());
        assert!(workspace_len((1 << 30) + 1).is_err());
        assert!(christensen::fill(0, 1, &mut [], &mut [], &Budget::UNLIMITED).is_ok());
    }

    /// Mean toroidal nearest-neighbour distance divided by the hexagonal-lattice spacing
    /// `sqrt(2 / (sqrt(3) N))` (brute force).
    pub(crate) fn mean_nn(pts: &[[u32; 2]]) -> f64 {
        nn_stats(pts).0
    }

    /// (mean, minimum) toroidal nearest-neighbour distance over the hexagonal spacing.
    pub(crate) fn nn_stats(pts: &[[u32; 2]]) -> (f64, f64) {
        let f: Vec<[f64; 2]> = pts
            .iter()
            .map(|p| [p[0] as f64 / 2f64.powi(32), p[1] as f64 / 2f64.powi(32)])
            .collect();
        let mut sum = 0.0;
        let mut min = f64::MAX;
        for (i, a) in f.iter().enumerate() {
            let mut best = f64::MAX;
            for (j, b) in f.iter().enumerate() {
                if i != j {
                    let dx = (a[0] - b[0]).abs();
                    let dy = (a[1] - b[1]).abs();
                    let (dx, dy) = (dx.min(1.0 - dx), dy.min(1.0 - dy));
                    best = best.min(dx * dx + dy * dy);
                }
            }
            sum += best.sqrt();
            min = min.min(best.sqrt());
        }
        let n = pts.len() as f64;
        let hex = (2.0 / (3f64.sqrt() * n)).sqrt();
        (sum / n / hex, min / hex)
    }

    /// The stochastic PMJ02 (Helmer et al.) with best candidate on the jitter only: the
    /// strata are forced, `k` jitters tried, the farthest (brute force) kept.
    fn stochastic_jitter_bn(seed: u64, k: u32, n: usize) -> Vec<[u32; 2]> {
        let mut pts: Vec<[u32; 2]> = Vec::with_capacity(n);
        let u = |i: usize, s: u64| qmckit::hash::uniform(seed, i as u32, s);
        pts.push([u(0, 0), u(0, 1)]);
        for idx in 1..n {
            let level = usize::BITS - 1 - idx.leading_zeros();
            let i = idx - (1 << level);
            let mut best = ([0u32; 2], -1.0f64);
            for c in 0..k as u64 {
                let mut p = [0u32; 2];
                for (d, v) in p.iter_mut().enumerate() {
                    let parent = pts[i ^ XOR[d][level as usize] as usize][d];
                    let shift = 31 - level;
                    let stratum = (parent >> shift) ^ 1;
                    let jitter = u(idx, 2 + 2 * c + d as u64);
                    *v = (stratum << shift) | jitter.checked_shr(level + 1).unwrap_or(0);
                }
                let d = pts
                    .iter()
                    .map(|q| {
                        let dx = (p[0].wrapping_sub(q[0]) as i32).unsigned_abs() as f64;
                        let dy = (p[1].wrapping_sub(q[1]) as i32).unsigned_abs() as f64;
                        dx * dx + dy * dy
                    })
                    .fold(f64::MAX, f64::min);
                if d > best.1 {
                    best = (p, d);
                }
            }
            pts.push(best.0);
        }
        pts
    }

    /// Best candidate in a balanced PMJ02 has little room (see `qmckit::pmj::christensen`): the mean
    /// nearest-neighbour distance stays at PMJ02's (pmj-cpp's own pmj02bn measures the same,
    /// 0.600 against 0.610), the jitter-only variant of the stochastic construction too.
    /// This pins those facts: a change that made the spacing worse, or a construction that
    /// left the strata free for real, would fail it.
    #[test]
    fn best_candidate_spacing_against_pmj02() {
        let n = 4096;
        let seeds = 0..4u64;
        let mean = |f: &dyn Fn(u64) -> Vec<[u32; 2]>| {
            seeds.clone().map(|s| mean_nn(&f(s))).sum::<f64>() / seeds.clone().count() as f64
        };
        let stochastic = mean(&|s| {
            let mut p = vec![[0u32; 2]; n];
            fill02(s, &mut p).unwrap();
            p
        });
        let christensen = mean(&|s| make(s, 1, n));
        let bn10 = mean(&|s| make(s, 10, n));
        let bn = mean(&|s| make(s, DEFAULT_CANDIDATES, n));
        let jitter_bn = mean(&|s| stochastic_jitter_bn(s, 10, n));
        eprintln!(
            "mean NN / hex spacing, N = {n}, 4 seeds: pmj02 (stochastic) {stochastic:.4}, \
             pmj02 (Christensen, K = 1) {christensen:.4}, stochastic + jitter best candidate \
             (K = 10) {jitter_bn:.4}, pmj02bn K = 10 {bn10:.4}, pmj02bn K = 100 {bn:.4}"
        );
        // White noise: 0.5 / sqrt(N) = 0.465 hex spacings; PMJ02 is well above it.
        for v in [stochastic, christensen, bn10, bn, jitter_bn] {
            assert!((0.57..0.65).contains(&v), "{v}");
        }
        // No candidate count loses spacing, none gains more than 5%.
        for v in [bn10, bn, jitter_bn] {
            assert!(
                v > 0.98 * stochastic && v < 1.05 * stochastic,
                "{v} vs {stochastic}"
            );
        }
    }

    #[test]
    fn prefixes_of_a_long_sequence_are_nets() {
        // 2^20 points (any length up to 2^30 is accepted): every prefix 2^m, m <= 20, is a
        // (0, m, 2)-net; checked on the prefix cells of the finest two grids and the square.
        let n = 1 << 20;
        let pts = make(11, 4, n);
        for m in [18u32, 19, 20] {
            for k in [0, m / 2, m] {
                let mut seen = vec![false; 1 << m];
                for p in &pts[..1 << m] {
                    let a = if k == 0 {
                        0
                    } else {
                        (p[0] >> (32 - k)) as usize
                    };
                    let b = if k == m {
                        0
                    } else {
                        (p[1] >> (32 - (m - k))) as usize
                    };
                    let key = (a << (m - k)) | b;
                    assert!(!std::mem::replace(&mut seen[key], true), "m {m} k {k}");
                }
            }
        }
    }
}

/// PMJ02BN: PMJ02 spread by nested flips. The nets survive every flip (checked over seeds
/// and lengths, on the stochastic and on Christensen's base), and the spacing of every
/// prefix rises clearly above PMJ02's, measured by brute force.
mod bn {
    use super::christensen::{mean_nn, nn_stats};
    use super::first_block_failure;
    use qmckit::pmj::{bn, christensen, fill as fill02, spread};
    use qmckit::work::Budget;

    fn make(seed: u64, n: usize) -> Vec<[u32; 2]> {
        let mut pts = vec![[0u32; 2]; n];
        let mut work = vec![0u32; bn::workspace_len(n).unwrap()];
        bn::fill(seed, &mut pts, &mut work, &Budget::UNLIMITED).unwrap();
        pts
    }

    fn nets_over_seeds(seeds: std::ops::Range<u64>, n: usize) {
        super::nets_over_seeds(seeds, |seed| make(seed, n));
    }

    #[test]
    fn aligned_blocks_are_nets_1000_seeds_2_10() {
        nets_over_seeds(0..1000, 1 << 10);
    }

    #[test]
    fn aligned_blocks_are_nets_at_other_lengths() {
        // Lengths that are not powers of two keep their partial last block stratified too.
        for n in [2usize, 3, 5, 100, 1000, 3000, 1 << 16] {
            nets_over_seeds(7..9, n);
        }
    }

    #[test]
    #[ignore = "1000 seeds x 2^16 points: minutes; run with --ignored"]
    fn aligned_blocks_are_nets_2_16_1000_seeds() {
        nets_over_seeds(0..1000, 1 << 16);
    }

    #[test]
    fn spreading_christensens_sequence_keeps_its_nets() {
        let n = 1 << 12;
        let mut pts = vec![[0u32; 2]; n];
        let mut work = vec![0u32; christensen::workspace_len(n).unwrap()];
        christensen::fill(4, 10, &mut pts, &mut work, &Budget::UNLIMITED).unwrap();
        let before = pts.clone();
        let mut work = vec![0u32; spread::workspace_len(n).unwrap()];
        spread::spread(&mut pts, &mut work, &Budget::UNLIMITED).unwrap();
        assert_eq!(first_block_failure(&pts), None);
        assert!(pts.iter().zip(&before).filter(|(a, b)| a != b).count() > n / 2);
        assert!(mean_nn(&pts) > 1.08 * mean_nn(&before));
    }

    /// The bar: at every power-of-two prefix of a 4096-point sequence and at 3/4 of it, the
    /// mean nearest-neighbour distance (over the hexagonal spacing, 4 seeds) against PMJ02's
    /// and Christensen's best candidate (100 trials). Prints the table of `qmckit::pmj::bn`.
    #[test]
    fn spacing_is_clearly_above_pmj02() {
        let n = 4096;
        let prefixes = [256usize, 512, 1024, 2048, 4096, 3072];
        let mut rows = [[0.0f64; 6]; 3];
        let mut min = [0.0f64; 3];
        for seed in 0..4u64 {
            let mut pmj02 = vec![[0u32; 2]; n];
            fill02(seed, &mut pmj02).unwrap();
            let mut best = vec![[0u32; 2]; n];
            let mut work = vec![0u32; christensen::workspace_len(n).unwrap()];
            christensen::fill(seed, 100, &mut best, &mut work, &Budget::UNLIMITED).unwrap();
            let sets = [pmj02, best, make(seed, n)];
            for (r, set) in sets.iter().enumerate() {
                for (c, &p) in prefixes.iter().enumerate() {
                    rows[r][c] += mean_nn(&set[..p]) / 4.0;
                }
                min[r] += nn_stats(set).1 / 4.0;
            }
        }
        for (name, (row, lo)) in ["pmj02", "best candidate 100", "pmj02bn"]
            .iter()
            .zip(rows.iter().zip(min))
        {
            eprintln!("{name:>20}: prefixes {prefixes:?}: {row:.3?}, min NN at 4096 {lo:.3}");
        }
        let (base, bn) = (rows[0], rows[2]);
        for c in 0..prefixes.len() {
            // Never worse; from 1024 points on, at least 8% farther apart.
            let gain = if prefixes[c] >= 1024 { 1.08 } else { 1.0 };
            assert!(
                bn[c] > gain * base[c] && bn[c] > gain * rows[1][c],
                "prefix {}: {} vs {} / {}",
                prefixes[c],
                bn[c],
                base[c],
                rows[1][c]
            );
        }
        assert!(min[2] > min[0], "{min:?}");
    }

    #[test]
    fn bad_input_is_an_error_and_leaves_the_points() {
        let mut work = vec![0u32; spread::workspace_len(8).unwrap()];
        // Two points in one cell of the 2 x 2 grid: not a (0, 2)-sequence.
        let mut pts = [[0u32; 2], [1 << 30, 1 << 30], [1 << 31, 0], [0, 1 << 31]];
        let before = pts;
        assert!(spread::spread(&mut pts, &mut work, &Budget::UNLIMITED).is_err());
        assert_eq!(pts, before);
        let mut pts = vec![[0u32; 2]; 100];
        let short = bn::workspace_len(100).unwrap() - 1;
        assert!(bn::fill(0, &mut pts, &mut vec![0; short], &Budget::UNLIMITED).is_err());
        assert!(spread::spread(&mut pts, &mut vec![0; short], &Budget::UNLIMITED).is_err());
        assert!(bn::workspace_len((1 << 30) + 1).is_err());
        assert!(bn::fill(0, &mut [], &mut [], &Budget::UNLIMITED).is_ok());
        let mut one = [[0u32; 2]];
        assert!(bn::fill(0, &mut one, &mut [], &Budget::UNLIMITED).is_ok());
        // Deterministic, and seeds differ.
        assert_eq!(make(3, 500), make(3, 500));
        assert!(make(4, 64).iter().zip(&make(3, 64)).all(|(a, b)| a != b));
    }
}

/// The deadline of a started budget stops the PMJ constructions inside their loops.
mod deadline {
    use qmckit::Error;
    use qmckit::pmj::{bn, christensen};
    use qmckit::work::Budget;
    use std::time::{Duration, Instant};

    /// Times `job(n)` without a limit, doubling `n` until it takes 0.1 s; then runs it
    /// under a budget of that time started `1.15` of it earlier, so the deadline falls a
    /// tenth of the way in: it must stop with [`Error::OutOfTime`] near the deadline (a
    /// loop that never reads the clock would finish instead).
    fn stops_at_the_deadline(what: &str, job: impl Fn(usize, &Budget) -> qmckit::Result<()>) {
        let mut n = 1 << 12;
        let seconds = loop {
            let t = Instant::now();
            job(n, &Budget::UNLIMITED).unwrap();
            let s = t.elapsed().as_secs_f64();
            if s >= 0.1 || n >= 1 << 22 {
                break s;
            }
            n *= 2;
        };
        let budget = Budget::seconds(seconds).unwrap().started();
        let start = Instant::now();
        std::thread::sleep(Duration::from_secs_f64(1.15 * seconds));
        let got = job(n, &budget);
        let took = start.elapsed().as_secs_f64();
        assert!(
            matches!(got, Err(Error::OutOfTime { .. })),
            "{what}: {got:?} for {n} points after {took:.3} s of {seconds:.3} s"
        );
        assert!(
            took < 1.25 * seconds + 0.25,
            "{what}: stopped {took:.3} s after the start of a {seconds:.3} s budget"
        );
    }

    #[test]
    fn pmj02bn_and_best_candidate_pmj_stop_at_the_deadline() {
        stops_at_the_deadline("PMJ02BN", |n, budget| {
            let mut pts = vec![[0u32; 2]; n];
            let mut work = vec![0u32; bn::workspace_len(n)?];
            bn::fill(3, &mut pts, &mut work, budget)
        });
        stops_at_the_deadline("Christensen PMJ02", |n, budget| {
            let mut pts = vec![[0u32; 2]; n];
            let mut work = vec![0u32; christensen::workspace_len(n)?];
            christensen::fill(3, 100, &mut pts, &mut work, budget)
        });
    }

    #[test]
    fn an_unlimited_budget_changes_no_bit() {
        let n = 3000;
        let mut a = vec![[0u32; 2]; n];
        let mut b = vec![[0u32; 2]; n];
        let mut work = vec![0u32; bn::workspace_len(n).unwrap()];
        bn::fill(5, &mut a, &mut work, &Budget::UNLIMITED).unwrap();
        let far = Budget::seconds(1e6).unwrap().started();
        bn::fill(5, &mut b, &mut work, &far).unwrap();
        assert_eq!(a, b);
    }
}
