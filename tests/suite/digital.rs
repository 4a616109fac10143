//! Base-b digital sequences: Faure against QMCPy (tests/golden/gen_qmcpy_lattice.py) and
//! exact rationals, and the (0, m, s)-net property counted here from the definition
//! (elementary intervals in base b), unscrambled and scrambled.

use qmckit::Sampler;
use qmckit::analysis::budget::Budget;
use qmckit::digital::{DigitalNetB, output_digits, quality::t_value};
use qmckit::randomize::digits::DigitScramble;

fn golden(name: &str) -> String {
    let path = format!("{}/tests/golden/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Is the block `start .. start + b^m` a (0, m, s)-net: for every shape
/// `d_1 + .. + d_s = m`, does each elementary interval hold exactly one point? Counted with
/// the exact coordinates `v / b^K`. Returns the first failing shape.
fn first_failure(net: &DigitalNetB<Vec<u16>>, start: u32, m: u32) -> Option<Vec<u32>> {
    let b = net.base() as u64;
    let s = net.dims();
    let (k, _) = output_digits(net.base());
    let n = b.pow(m);
    let vals: Vec<Vec<u64>> = (0..n as u32)
        .map(|i| (0..s).map(|d| net.value(start + i, d).unwrap()).collect())
        .collect();
    // All compositions of m into s parts.
    let mut shape = vec![0u32; s];
    fn next(shape: &mut [u32], m: u32) -> bool {
        // Enumerate all vectors with entries <= m, keep those summing to m.
        for x in shape.iter_mut() {
            if *x < m {
                *x += 1;
                return true;
            }
            *x = 0;
        }
        false
    }
    loop {
        if shape.iter().sum::<u32>() == m {
            let mut seen = vec![false; n as usize];
            for p in &vals {
                let mut cell = 0u64;
                for (d, &v) in p.iter().enumerate() {
                    let digits = v / b.pow(k as u32 - shape[d]);
                    cell = cell * b.pow(shape[d]) + digits;
                }
                if std::mem::replace(&mut seen[cell as usize], true) {
                    return Some(shape);
                }
            }
        }
        if !next(&mut shape, m) {
            return None;
        }
    }
}

#[test]
fn faure_base3_first_points_are_the_published_rationals() {
    let f = DigitalNetB::faure(3, 3).unwrap();
    let ninths = [
        [0, 0, 0],
        [3, 3, 3],
        [6, 6, 6],
        [1, 4, 7],
        [4, 7, 1],
        [7, 1, 4],
        [2, 8, 5],
        [5, 2, 8],
        [8, 5, 2],
    ];
    let k = f.digits() as u32;
    for (i, p) in ninths.iter().enumerate() {
        for (d, &q) in p.iter().enumerate() {
            assert_eq!(f.value(i as u32, d).unwrap(), q * 3u64.pow(k - 2));
            assert_eq!(f.sample(i as u32, d).unwrap() as u64, (q << 32) / 9);
        }
    }
}

#[test]
fn faure_equals_qmcpy() {
    for (file, base, d) in [
        ("qmcpy_faure_d3_n243.txt", 3u32, 3usize),
        ("qmcpy_faure_d5_n625.txt", 5, 5),
    ] {
        let f = DigitalNetB::faure(base, d).unwrap();
        let scale = output_digits(base).1 as f64;
        let rows: Vec<Vec<f64>> = golden(file)
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| l.split_whitespace().map(|t| t.parse().unwrap()).collect())
            .collect();
        for (i, row) in rows.iter().enumerate() {
            for (k, &want) in row.iter().enumerate() {
                let got = f.value(i as u32, k).unwrap() as f64 / scale;
                assert!((got - want).abs() < 1e-12, "{file} point {i} dim {k}");
            }
        }
    }
}

#[test]
fn faure_blocks_are_0_m_s_nets_base_3_and_5() {
    for (base, s) in [(3u32, 2usize), (3, 3), (5, 3), (5, 5)] {
        let f = DigitalNetB::faure(base, s).unwrap();
        for m in 1..=4u32 {
            let n = (base as u64).pow(m) as u32;
            for start in [0, n, 7 * n] {
                assert_eq!(first_failure(&f, start, m), None, "b {base} s {s} m {m}");
            }
            assert_eq!(t_value(&f, start_of(n), m, &Budget::DEFAULT).unwrap(), 0);
        }
    }
}

fn start_of(n: u32) -> u32 {
    2 * n
}

#[test]
fn scrambles_keep_the_net_property() {
    for seed in 0..6u64 {
        for scramble in [
            DigitScramble::Owen(seed),
            DigitScramble::Permutations(seed),
            DigitScramble::Faure,
        ] {
            for (base, s) in [(3u32, 3usize), (5, 5)] {
                let f = DigitalNetB::faure(base, s).unwrap().with_scramble(scramble);
                for m in 1..=4u32 {
                    assert_eq!(first_failure(&f, 0, m), None, "{scramble:?} b {base} m {m}");
                }
            }
        }
    }
    // The scramble changes the points.
    let plain = DigitalNetB::faure(5, 3).unwrap();
    let owen = plain.clone().with_scramble(DigitScramble::Owen(1));
    assert_ne!(plain.sample(7, 1).unwrap(), owen.sample(7, 1).unwrap());
}

/// A set that is not a net is recognized (the counter can fail): the first 9 points of
/// Faure in base 3 with dimension 0 repeated have t = 2 (in the shape (1,1), cells hold 3).
#[test]
fn counting_detects_a_non_net() {
    let mut m = vec![0u16; 2 * 21 * 21];
    qmckit::digital::faure_matrices(3, 1, &mut m[..441]).unwrap();
    let copy = m[..441].to_vec();
    m[441..].copy_from_slice(&copy);
    let twin = DigitalNetB::new(3, 2, 21, m).unwrap();
    assert_eq!(t_value(&twin, 0, 2, &Budget::DEFAULT).unwrap(), 1);
    assert!(first_failure(&twin, 0, 2).is_some());
}

#[test]
fn digital_nets_refuse_bad_input() {
    assert!(DigitalNetB::faure(4, 2).is_err()); // not prime
    assert!(DigitalNetB::faure(3, 4).is_err()); // b < s
    assert!(DigitalNetB::faure(1, 1).is_err());
    assert!(DigitalNetB::faure(3, 0).is_err());
    assert!(DigitalNetB::new(3, 1, 2, vec![0u16; 5]).is_err()); // wrong length
    assert!(DigitalNetB::new(3, 1, 1, vec![3u16; 21]).is_err()); // not a digit
    let f = DigitalNetB::faure(3, 2).unwrap();
    assert!(f.sample(0, 2).is_err());
    let tiny = Budget::seconds(1e-9).unwrap();
    assert!(t_value(&f, 0, 10, &tiny).is_err());
    assert!(t_value(&f, u32::MAX, 3, &Budget::DEFAULT).is_err());
}
