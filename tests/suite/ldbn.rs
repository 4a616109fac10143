//! Low-discrepancy blue noise against what it claims: the output is a `(0, 2k, 2)`-net
//! (t-value counted from the points, for the optimized table and for arbitrary tables,
//! since the argument is about the exchanges, not the entries); its low-frequency power
//! (mean radial periodogram over `1 <= r <= sqrt(N)/2`, averaged over 16 seeds) is below
//! the white-noise level 1 (`E P(k) = 1` for independent uniform points) and below the
//! Owen-scrambled Sobol' net it starts from; the identity table gives that net itself.

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::analysis::tvalue::t_value_u32;
use qmckit::blue_noise::Ldbn;
use qmckit::blue_noise::ldbn::{LDBN_TABLE, LdbnTable};
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

/// A table of pseudo-random entries (a 64-bit LCG, top bits).
fn random_table(seed: u64) -> LdbnTable {
    let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    let mut entries = [0u8; 256];
    for e in &mut entries {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        *e = (state >> 60) as u8;
    }
    LdbnTable::new(entries).unwrap()
}

#[test]
fn the_output_is_a_0m2_net_for_any_table() {
    let tables = [
        LDBN_TABLE,
        random_table(1),
        random_table(2),
        LdbnTable::new([15; 256]).unwrap(),
    ];
    for k in 1..=6u32 {
        let n = 1u64 << (2 * k);
        for seed in [0u64, 5, 77] {
            for (t, table) in tables.iter().enumerate() {
                let set = Ldbn::new(n, seed)
                    .unwrap()
                    .table(*table)
                    .generate(&Budget::DEFAULT)
                    .unwrap();
                let tv = t_value_u32(set.coords(), 2, 2 * k, &Budget::DEFAULT).unwrap();
                assert_eq!(tv, 0, "N {n} seed {seed} table {t}");
            }
        }
    }
}

#[test]
fn the_identity_table_gives_the_owen_scrambled_template() {
    for seed in [0u64, 9] {
        let set = Ldbn::new(256, seed)
            .unwrap()
            .table(LdbnTable::IDENTITY)
            .generate(&Budget::DEFAULT)
            .unwrap();
        assert_eq!(set.coords(), owen_sobol(256, seed).as_slice());
        // The optimized table moves points.
        let opt = Ldbn::new(256, seed)
            .unwrap()
            .generate(&Budget::DEFAULT)
            .unwrap();
        assert_ne!(opt.coords(), set.coords());
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

#[test]
fn low_frequency_power_is_below_white_noise_and_owen_sobol() {
    for n in [1024u64, 4096] {
        let seeds = 0..16u64;
        let count = seeds.clone().count() as f64;
        let (mut ours, mut owen) = (0.0, 0.0);
        for seed in seeds {
            let set = Ldbn::new(n, seed)
                .unwrap()
                .generate(&Budget::UNLIMITED)
                .unwrap();
            ours += low_power(set.coords(), n) / count;
            owen += low_power(&owen_sobol(n, seed), n) / count;
        }
        assert!(ours < 1.0, "N {n}: {ours}");
        assert!(
            ours < 0.9 * owen,
            "N {n}: ldbn {ours}, owen-scrambled sobol {owen}"
        );
    }
}

#[test]
fn bad_input_and_budget() {
    for n in [0u64, 1, 2, 8, 32, 1000, 1 << 27, 1 << 28] {
        assert!(Ldbn::new(n, 0).is_err(), "{n}");
    }
    assert!(matches!(Ldbn::new(0, 0), Err(Error::ZeroPoints)));
    let mut bad = [0u8; 256];
    bad[17] = 16;
    assert!(LdbnTable::new(bad).is_err());
    let tiny = Budget::seconds(1e-9).unwrap();
    assert!(matches!(
        Ldbn::new(1 << 24, 0).unwrap().generate(&tiny),
        Err(Error::OverBudget { .. })
    ));
}
