//! Low-discrepancy blue noise against what it claims, counted from the points: every
//! table (the shipped one, random permutation tables, the identity) gives one point in
//! each of the `K x K` cells and in each of the `N` columns and rows of width `1/N`, and a
//! `(3 - s, 2k, 2)`-net for its nesting `s` (t-value counted: 3 for random tables, 0 for
//! the identity, `3 - LDBN_NESTING` for the shipped one); the identity table the Hammersley set
//! `(i/N, rev_2k(i)/N)` (the 2D Sobol' net) up to a symmetry of the square. Its
//! low-frequency power (mean radial periodogram over `1 <= r <= sqrt(N)/2`, 16 seeds) is
//! below the white-noise level 1 (`E P(k) = 1` for independent uniform points) and below
//! the Owen-scrambled Sobol' net's; its mean nearest-neighbour distance above the
//! template's.

use qmckit::analysis::Points;
use qmckit::analysis::distance::mean_min_distance;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::analysis::tvalue::t_value_u32;
use qmckit::blue_noise::Ldbn;
use qmckit::blue_noise::ldbn::{LDBN_NESTING, LDBN_PERIOD, LDBN_TABLE, LdbnTable};
use qmckit::randomize::{ExactOwen, Scrambled};
use qmckit::work::Budget;
use qmckit::{Error, Sampler, Sobol};

/// The Owen-scrambled Sobol' net of `n` points, `seed`.
fn owen_sobol(n: u64, seed: u64) -> Vec<u32> {
    let s = Scrambled::new(Sobol::new(2).unwrap(), ExactOwen::new(seed));
    let mut out = vec![0u32; 2 * n as usize];
    s.fill(0, &mut out).unwrap();
    out
}

/// A table of random permutations (Fisher-Yates from a 64-bit LCG) of every aligned run
/// of 16: low nibbles down the columns, high nibbles along the rows.
fn random_table(seed: u64) -> LdbnTable {
    const P: usize = LDBN_PERIOD;
    let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    let mut below = |n: usize| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) % n as u64) as usize
    };
    let mut t = vec![0u8; P * P];
    for a in 0..P {
        for run in (0..P).step_by(16) {
            let mut lo: Vec<u8> = (0..16).collect();
            let mut hi: Vec<u8> = (0..16).collect();
            for i in (1..16).rev() {
                lo.swap(i, below(i + 1));
                hi.swap(i, below(i + 1));
            }
            for j in 0..16 {
                t[a + P * (run + j)] |= lo[j];
                t[run + j + P * a] |= hi[j] << 4;
            }
        }
    }
    LdbnTable::new(&t).unwrap()
}

/// The number of points in each of `parts` equal slices of coordinate `d`.
fn slice_counts(coords: &[u32], d: usize, bits: u32) -> Vec<u32> {
    let mut c = vec![0u32; 1 << bits];
    for p in coords.chunks_exact(2) {
        c[(p[d] >> (32 - bits)) as usize] += 1;
    }
    c
}

#[test]
fn every_table_stratifies_and_gives_a_net_of_its_nesting() {
    let tables = [
        ("shipped", LDBN_TABLE.clone()),
        ("identity", LdbnTable::IDENTITY),
        ("random 1", random_table(1)),
        ("random 2", random_table(2)),
    ];
    for k in 1..=6u32 {
        let n = 1u64 << (2 * k);
        for seed in [0u64, 5, 77] {
            for (name, table) in &tables {
                let set = Ldbn::new(n, seed)
                    .unwrap()
                    .generate_with(table, &Budget::DEFAULT)
                    .unwrap();
                let c = set.coords();
                // One point a column and a row of width 1/N.
                for d in 0..2 {
                    assert!(
                        slice_counts(c, d, 2 * k).iter().all(|&v| v == 1),
                        "{name} N {n}"
                    );
                }
                // One point a cell.
                let mut cells = vec![0u32; n as usize];
                for p in c.chunks_exact(2) {
                    cells[((p[0] >> (32 - k)) + ((p[1] >> (32 - k)) << k)) as usize] += 1;
                }
                assert!(cells.iter().all(|&v| v == 1), "{name} N {n}");
                let tv = t_value_u32(c, 2, 2 * k, &Budget::DEFAULT).unwrap();
                let bound = match *name {
                    "identity" => 0,
                    "shipped" => 3 - LDBN_NESTING,
                    _ => 3,
                };
                assert!(tv <= bound.min(k), "{name} N {n} seed {seed}: t = {tv}");
            }
        }
    }
}

#[test]
fn random_tables_do_break_the_finer_intervals() {
    // The nesting is what keeps the finer intervals: some random table (nesting 0) at
    // N = 1024 has t > 0.
    let worst = (1..4u64)
        .map(|s| {
            let set = Ldbn::new(1024, 0)
                .unwrap()
                .generate_with(&random_table(s), &Budget::DEFAULT)
                .unwrap();
            t_value_u32(set.coords(), 2, 10, &Budget::DEFAULT).unwrap()
        })
        .max()
        .unwrap();
    assert!(worst > 0);
    assert_eq!(LdbnTable::IDENTITY.nesting(), 3);
    assert!(LDBN_TABLE.nesting() >= LDBN_NESTING);
    assert_eq!(random_table(1).nesting(), 0);
}

#[test]
fn the_identity_table_gives_the_hammersley_net_up_to_a_symmetry() {
    for k in [2u32, 5] {
        let (n, m) = (1u32 << (2 * k), 2 * k);
        let hammersley: Vec<(u32, u32)> =
            (0..n).map(|i| (i, i.reverse_bits() >> (32 - m))).collect();
        for seed in 0..12u64 {
            let set = Ldbn::new(u64::from(n), seed)
                .unwrap()
                .generate_with(&LdbnTable::IDENTITY, &Budget::DEFAULT)
                .unwrap();
            let mut got: Vec<(u32, u32)> = set
                .coords()
                .chunks_exact(2)
                .map(|p| (p[0] >> (32 - m), p[1] >> (32 - m)))
                .collect();
            got.sort_unstable();
            let found = (0..8).any(|s| {
                let mut want: Vec<(u32, u32)> = hammersley
                    .iter()
                    .map(|&(x, y)| {
                        let x = if s & 1 == 1 { n - 1 - x } else { x };
                        let y = if s & 2 == 2 { n - 1 - y } else { y };
                        if s & 4 == 4 { (y, x) } else { (x, y) }
                    })
                    .collect();
                want.sort_unstable();
                want == got
            });
            assert!(found, "N {n} seed {seed}");
        }
    }
}

/// Mean radial power over `1 <= r <= sqrt(N)/2`.
fn low_power(coords: &[u32], n: u64) -> f64 {
    let xy: Vec<f64> = coords.iter().map(|&c| qmckit::bits::to_f64(c)).collect();
    let half = ((n as f64).sqrt() / 2.0) as usize;
    let s = spectrum_2d(Points::new(&xy, 2).unwrap(), half, &Budget::UNLIMITED).unwrap();
    let radial = s.radial();
    radial.iter().map(|b| b.mean).sum::<f64>() / radial.len() as f64
}

fn nn(coords: &[u32], n: u64) -> f64 {
    let xy: Vec<f64> = coords.iter().map(|&c| qmckit::bits::to_f64(c)).collect();
    mean_min_distance(Points::new(&xy, 2).unwrap(), false) * (n as f64).sqrt()
}

#[test]
fn blue_noise_against_white_noise_owen_sobol_and_the_template() {
    for n in [1024u64, 4096] {
        let seeds = 0..16u64;
        let count = seeds.clone().count() as f64;
        let (mut ours, mut owen, mut spacing, mut template) = (0.0, 0.0, 0.0, 0.0);
        for seed in seeds {
            let set = Ldbn::new(n, seed)
                .unwrap()
                .generate(&Budget::UNLIMITED)
                .unwrap();
            ours += low_power(set.coords(), n) / count;
            spacing += nn(set.coords(), n) / count;
            owen += low_power(&owen_sobol(n, seed), n) / count;
            let id = Ldbn::new(n, seed)
                .unwrap()
                .generate_with(&LdbnTable::IDENTITY, &Budget::UNLIMITED)
                .unwrap();
            template += nn(id.coords(), n) / count;
        }
        assert!(ours < 1.0, "N {n}: {ours}");
        assert!(
            ours < 0.5 * owen,
            "N {n}: ldbn {ours}, owen-scrambled sobol {owen}"
        );
        assert!(
            spacing > 1.1 * template,
            "N {n}: NN {spacing} against {template}"
        );
    }
}

#[test]
fn seeds_are_reproducible_and_differ() {
    let a = Ldbn::new(1024, 3)
        .unwrap()
        .generate(&Budget::DEFAULT)
        .unwrap();
    let b = Ldbn::new(1024, 3)
        .unwrap()
        .generate(&Budget::DEFAULT)
        .unwrap();
    let c = Ldbn::new(1024, 4)
        .unwrap()
        .generate(&Budget::DEFAULT)
        .unwrap();
    assert_eq!(a.coords(), b.coords());
    assert_ne!(a.coords(), c.coords());
}

#[test]
fn bad_input_and_budget() {
    for n in [0u64, 1, 2, 8, 32, 1000, 1 << 27, 1 << 28] {
        assert!(Ldbn::new(n, 0).is_err(), "{n}");
    }
    assert!(matches!(Ldbn::new(0, 0), Err(Error::ZeroPoints)));
    assert!(LdbnTable::new(&[0u8; 100]).is_err());
    // A run with a repeated low nibble.
    let mut bad = LdbnTable::IDENTITY.entries().to_vec();
    bad[LDBN_PERIOD] = bad[0];
    assert!(LdbnTable::new(&bad).is_err());
    assert!(LdbnTable::new(LDBN_TABLE.entries()).is_ok());
    let tiny = Budget::seconds(1e-9).unwrap();
    assert!(matches!(
        Ldbn::new(1 << 24, 0).unwrap().generate(&tiny),
        Err(Error::OverBudget { .. })
    ));
}
