//! The 0.32 fixed-point conversions stay in [0, 1) and are faithful.

use qmckit::bits::{
    FromFraction, fraction, gray, gray_inverse, in_cell, reverse_bits, reversed_to_f32, to_f32,
    to_f32_lanes, to_f32_lz, to_f32_via_f64, to_f64,
};

fn check_f32(x: u32, prev: f32) -> f32 {
    let f = to_f32(x);
    assert_eq!(
        f.to_bits(),
        to_f32_via_f64(x).to_bits(),
        "the f64 path differs at {x}"
    );
    assert_eq!(
        f.to_bits(),
        to_f32_lanes(x).to_bits(),
        "the lanes path differs at {x}"
    );
    assert_eq!(
        f.to_bits(),
        to_f32_lz(x).to_bits(),
        "the leading-zero path differs at {x}"
    );
    assert_eq!(
        f.to_bits(),
        reversed_to_f32(reverse_bits(x)).to_bits(),
        "the reversed-domain path differs at {x}"
    );
    assert!(f < 1.0, "to_f32({x}) = 1");
    assert!(f >= prev, "not monotone at {x}");
    let exact = to_f64(x);
    assert!((f as f64) <= exact, "rounded up at {x}");
    // Within one f32 ulp below the exact value.
    assert!(exact - (f as f64) < (f as f64).max(f32::MIN_POSITIVE as f64) * f32::EPSILON as f64);
    f
}

#[test]
fn f32_spot_checks() {
    assert_eq!(to_f32(0), 0.0);
    assert_eq!(to_f32(1), 2f32.powi(-32));
    assert_eq!(to_f32(u32::MAX), 1.0 - 2f32.powi(-24));
    // A naive conversion rounds these up to 1.0.
    assert_eq!((u32::MAX as f32) / 4_294_967_296.0, 1.0);
    let mut prev = 0.0;
    for x in (0..=u32::MAX).step_by(65_521) {
        prev = check_f32(x, prev);
    }
}

/// All 2^32 inputs (a few seconds in release mode; CI runs it with `--ignored`).
#[test]
#[ignore = "exhaustive over 2^32 inputs; run with --release -- --ignored"]
fn f32_never_reaches_one_for_any_input() {
    let mut prev = 0.0;
    for x in 0..=u32::MAX {
        prev = check_f32(x, prev);
        // to_f64 builds 2^20 + x 2^-32 from bits and subtracts 2^20: the same bits as the
        // plain (exact) conversion and division by 2^32.
        assert_eq!(to_f64(x).to_bits(), (x as f64 / 4_294_967_296.0).to_bits());
    }
}

#[test]
fn f64_is_exact() {
    for x in [0u32, 1, 12345, 1 << 31, u32::MAX] {
        assert_eq!(to_f64(x) * 4_294_967_296.0, x as f64);
    }
    assert_eq!(to_f64(0).to_bits(), 0, "+0.0, not -0.0");
    for x in (0..=u32::MAX)
        .step_by(65_521)
        .chain([u32::MAX - 1, 1 << 20, 3])
    {
        assert_eq!(
            to_f64(x).to_bits(),
            (x as f64 / 4_294_967_296.0).to_bits(),
            "{x}"
        );
    }
}

/// The typed fills' conversions are the documented functions.
#[test]
fn from_fraction_is_the_conversions() {
    for x in (0..=u32::MAX).step_by(9_973).chain([u32::MAX]) {
        assert_eq!(u32::from_fraction(x), x);
        assert_eq!(f64::from_fraction(x).to_bits(), to_f64(x).to_bits());
        assert_eq!(f32::from_fraction(x).to_bits(), to_f32(x).to_bits());
    }
}

#[test]
fn gray_codes() {
    for i in 0..100_000u32 {
        assert_eq!((gray(i) ^ gray(i + 1)).count_ones(), 1);
        assert_eq!(gray(i) ^ gray(i + 1), 1 << (i + 1).trailing_zeros());
        assert_eq!(gray_inverse(gray(i)), i);
    }
    assert_eq!(gray_inverse(gray(u32::MAX)), u32::MAX);
}

#[test]
fn fractions_and_cells() {
    assert_eq!(fraction(0, 7), 0);
    assert_eq!(fraction(6, 7) as u64, (6u64 << 32) / 7);
    for n in [1u64, 2, 3, 10, 1000, 65_537, (1 << 32) - 1, 1 << 32] {
        for cell in [0, n / 2, n - 1] {
            for u in [0, 1, u32::MAX] {
                let x = in_cell(cell, n, u) as u128;
                assert!(x * n as u128 >= (cell as u128) << 32, "{cell}/{n} u {u}");
                assert!(
                    x * (n as u128) < ((cell + 1) as u128) << 32,
                    "{cell}/{n} u {u}"
                );
                assert_eq!((x * n as u128) >> 32, cell as u128);
            }
        }
    }
}

#[cfg(feature = "fixed")]
#[test]
fn fixed_keeps_the_bits() {
    let f = qmckit::bits::to_fixed(0xC000_0000);
    assert_eq!(f.to_bits(), 0xC000_0000);
    assert_eq!(f64::from(f), 0.75);
}
