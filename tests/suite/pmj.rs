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

#[test]
fn every_aligned_block_is_a_net_for_1000_seeds() {
    let n = 1 << 16;
    let failures: Vec<String> = std::thread::scope(|s| {
        let workers: Vec<_> = (0..2u64)
            .map(|w| {
                s.spawn(move || {
                    let mut pts = vec![[0u32; 2]; n];
                    let mut bad = Vec::new();
                    for seed in (w..1000).step_by(2) {
                        fill(seed, &mut pts).unwrap();
                        if let Some(f) = first_block_failure(&pts) {
                            bad.push(format!("seed {seed}: (m, k, index) {f:?}"));
                        }
                    }
                    bad
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

mod bn {
    use super::first_block_failure;
    use qmckit::pmj::bn::{self, DEFAULT_CANDIDATES, MAX_CANDIDATES, workspace_len};
    use qmckit::pmj::{XOR, fill as fill02};

    fn make(seed: u64, k: u32, n: usize) -> Vec<[u32; 2]> {
        let mut pts = vec![[0u32; 2]; n];
        let mut work = vec![0u32; workspace_len(n).unwrap()];
        bn::fill(seed, k, &mut pts, &mut work).unwrap();
        pts
    }

    fn nets_over_seeds(seeds: std::ops::Range<u64>, k: u32, n: usize) {
        let failures: Vec<String> = std::thread::scope(|s| {
            let workers: Vec<_> = (0..2u64)
                .map(|w| {
                    let seeds = seeds.clone();
                    s.spawn(move || {
                        let mut bad = Vec::new();
                        for seed in seeds.skip(w as usize).step_by(2) {
                            if let Some(f) = first_block_failure(&make(seed, k, n)) {
                                bad.push(format!("seed {seed}: (m, k, index) {f:?}"));
                            }
                        }
                        bad
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
        assert!(bn::fill(0, 0, &mut pts, &mut work).is_err());
        assert!(bn::fill(0, MAX_CANDIDATES + 1, &mut pts, &mut work).is_err());
        let short = work.len() - 1;
        assert!(bn::fill(0, 1, &mut pts, &mut work[..short]).is_err());
        assert!(workspace_len((1 << 30) + 1).is_err());
        assert!(bn::fill(0, 1, &mut [], &mut []).is_ok());
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

    #[test]
    #[ignore = "a study: prints mean and minimum NN distances at several prefixes"]
    fn nn_study() {
        for n in [256usize, 512, 1024, 2048, 3072, 4096] {
            let mut acc = [[0.0f64; 2]; 4];
            for s in 0..4u64 {
                let mut p = vec![[0u32; 2]; n];
                fill02(s, &mut p).unwrap();
                let sets = [
                    p,
                    make(s, 1, n),
                    make(s, 10, n),
                    make(s, DEFAULT_CANDIDATES, n),
                ];
                for (a, set) in acc.iter_mut().zip(&sets) {
                    let (m, lo) = nn_stats(set);
                    a[0] += m / 4.0;
                    a[1] += lo / 4.0;
                }
            }
            eprintln!(
                "N {n}: mean/min NN: stochastic {:.3}/{:.3} christensen {:.3}/{:.3} bn10 {:.3}/{:.3} bn100 {:.3}/{:.3}",
                acc[0][0],
                acc[0][1],
                acc[1][0],
                acc[1][1],
                acc[2][0],
                acc[2][1],
                acc[3][0],
                acc[3][1]
            );
        }
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

    /// Best candidate in a balanced PMJ02 has little room (see `qmckit::pmj::bn`): the mean
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
