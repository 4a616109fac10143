//! AA patterns against what they claim: one point in each grid cell (for any table whose
//! entries are within half a cell); the zero table gives the cell centres; the automaton's
//! labels are equidistributed on the torus (Weyl: `1`, `cos theta`, `sin theta` are
//! rationally independent), so every table bin is read about equally often; the
//! low-frequency power (mean periodogram over `0 < |k| < sqrt(N)/2`, 8 seeds) is below
//! white noise (1) and below a jittered grid of the same cells, drawn here independently.

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::blue_noise::AaPattern;
use qmckit::blue_noise::aa::{AA_BINS, AA_TABLE, AaTable, bin, label};
use qmckit::work::Budget;
use qmckit::{Error, Sampler};

fn set(n: u64, seed: u64) -> Vec<f64> {
    AaPattern::new(n, seed)
        .unwrap()
        .generate(&Budget::DEFAULT)
        .unwrap()
        .to_f64()
}

/// Mean periodogram over `0 < |k| < sqrt(N)/2` (white noise: 1).
fn low_power(x: &[f64]) -> f64 {
    let n = x.len() / 2;
    let kmax = (0.5 * (n as f64).sqrt()).ceil() as usize;
    let s = spectrum_2d(Points::new(x, 2).unwrap(), kmax, &Budget::DEFAULT).unwrap();
    let (mut sum, mut count) = (0.0, 0);
    for (kx, ky, p) in s.iter() {
        let r = ((kx * kx + ky * ky) as f64).sqrt();
        if r > 0.0 && r < kmax as f64 {
            sum += p;
            count += 1;
        }
    }
    sum / count as f64
}

/// A jittered `k x k` grid: one uniform point a cell (a 64-bit LCG, top 53 bits).
fn jittered(k: usize, seed: u64) -> Vec<f64> {
    let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    let mut u = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut out = Vec::with_capacity(2 * k * k);
    for y in 0..k {
        for x in 0..k {
            out.push((x as f64 + u()) / k as f64);
            out.push((y as f64 + u()) / k as f64);
        }
    }
    out
}

#[test]
fn one_point_in_each_cell_for_any_table() {
    let mut state = 7u64;
    let mut entries = [[0.0; 2]; AA_BINS * AA_BINS];
    for e in entries.iter_mut().flatten() {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1);
        *e = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.999;
    }
    let tables = [AA_TABLE, AaTable::new(entries).unwrap(), AaTable::ZERO];
    for k in [1u64, 2, 7, 32, 100] {
        for (t, table) in tables.iter().enumerate() {
            let s = AaPattern::new(k * k, 11)
                .unwrap()
                .table(table.clone())
                .generate(&Budget::DEFAULT)
                .unwrap();
            let mut cells = vec![0u32; (k * k) as usize];
            for i in 0..k * k {
                let x = (u64::from(s.sample(i as _, 0).unwrap()) * k) >> 32;
                let y = (u64::from(s.sample(i as _, 1).unwrap()) * k) >> 32;
                // Point x + K y is in cell (x, y).
                assert_eq!(x + k * y, i, "K {k} table {t}");
                cells[(x + k * y) as usize] += 1;
            }
            assert!(cells.iter().all(|&c| c == 1));
        }
    }
}

#[test]
fn the_zero_table_gives_the_cell_centres() {
    let s = AaPattern::new(64, 5)
        .unwrap()
        .table(AaTable::ZERO)
        .generate(&Budget::DEFAULT)
        .unwrap()
        .to_f64();
    for (i, p) in s.chunks_exact(2).enumerate() {
        let (x, y) = ((i % 8) as f64, (i / 8) as f64);
        assert!((p[0] - (x + 0.5) / 8.0).abs() < 1e-9 && (p[1] - (y + 0.5) / 8.0).abs() < 1e-9);
    }
}

#[test]
fn labels_read_every_bin_about_equally() {
    let mut count = vec![0u32; AA_BINS * AA_BINS];
    for y in 0..256 {
        for x in 0..256 {
            count[bin(label([0x1234_5678, 0x9abc_def0], x, y))] += 1;
        }
    }
    // 64 a bin on average.
    let (lo, hi) = (count.iter().min().unwrap(), count.iter().max().unwrap());
    eprintln!("AA bin counts over a 256 x 256 patch: {lo} to {hi} (mean 64)");
    assert!(*lo >= 40 && *hi <= 88);
}

#[test]
fn aa_patterns_are_blue_noise() {
    let seeds = 0..8u64;
    let aa = seeds.clone().map(|s| low_power(&set(1024, s))).sum::<f64>() / 8.0;
    let jit = seeds.map(|s| low_power(&jittered(32, s))).sum::<f64>() / 8.0;
    eprintln!("AA low-frequency power {aa:.4}, jittered {jit:.4} (white 1)");
    assert!(aa < 0.5 * jit, "AA {aa} jittered {jit}");
    assert!(jit < 1.0);
}

#[test]
fn the_seed_moves_the_window() {
    assert_eq!(set(256, 3), set(256, 3));
    assert_ne!(set(256, 3), set(256, 4));
}

#[test]
fn aa_patterns_refuse_bad_input() {
    assert!(matches!(AaPattern::new(0, 0), Err(Error::ZeroPoints)));
    assert!(matches!(
        AaPattern::new(1000, 0),
        Err(Error::InvalidParameter { .. })
    ));
    assert!(matches!(
        AaPattern::new((1 << 24) + 1, 0),
        Err(Error::TooManyPoints { .. })
    ));
    let mut e = [[0.0; 2]; AA_BINS * AA_BINS];
    e[3][1] = 0.5;
    assert!(AaTable::new(e).is_err());
    e[3][1] = f64::NAN;
    assert!(AaTable::new(e).is_err());
    let tight = Budget::seconds(1e-6).unwrap();
    assert!(matches!(
        AaPattern::new(1 << 24, 0).unwrap().generate(&tight),
        Err(Error::OverBudget { .. })
    ));
}
