//! The paths against each other and against a `u128` rational oracle.

use super::*;

/// Oracle: the textbook digit loop with exact `u128` rational arithmetic.
fn oracle(base: u32, index: u32) -> u32 {
    let (mut n, mut rev, mut den) = (index as u128, 0u128, 1u128);
    while n > 0 {
        rev = rev * base as u128 + n % base as u128;
        den *= base as u128;
        n /= base as u128;
    }
    ((rev << 32) / den) as u32
}

#[test]
fn exact_against_u128_oracle() {
    // Both random-access paths (nested floors up to b^c = 2^16, exact numerator above)
    // and their edges: b^c = 2^16 - 1, 2^16, 2^16 + 1.
    let edges = [
        97, 251, 255, 256, 257, 1000, 1625, 1626, 8161, 65_521, 65_535, 65_536,
    ];
    let big = [65_537, 100_003, 1 << 31, u32::MAX];
    for base in (2..=40).chain(edges).chain(big) {
        let ri = RadicalInverse::new(base).unwrap();
        let mut x = 0x9E37_79B9u32;
        // Indices around the digit-count changes b^k - 1, b^k.
        let mut powers = vec![];
        let mut p = base as u64;
        while p <= u32::MAX as u64 {
            powers.extend([p as u32 - 1, p as u32]);
            p *= base as u64;
        }
        for i in (0..2000).chain([u32::MAX - 1, u32::MAX]).chain(powers) {
            assert_eq!(ri.sample(i), oracle(base, i), "base {base} index {i}");
            x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
            assert_eq!(ri.sample(x), oracle(base, x), "base {base} index {x}");
        }
    }
}

/// The wide numerator for every Halton base (chunk counts 2 to 8, magics present or
/// zero) and the serial one for the composites with more than 8 chunks: the indices
/// around every power `b^j` (where a chunk quotient changes), the largest indices and
/// random ones, against the oracle.
#[test]
fn long_indices_against_oracle_for_every_halton_base() {
    let halton = crate::radical_inverse::halton::HALTON_BASES
        .iter()
        .map(|ri| ri.base());
    let mut x = 0x2545_F491u32;
    for base in halton.chain([4, 6, 8, 9, 10, 12, 14, 15, 16]) {
        let ri = RadicalInverse::new(base).unwrap();
        let mut edges = vec![u32::MAX, u32::MAX - 1, 1 << 31];
        let mut p = base as u64;
        while p <= u32::MAX as u64 {
            edges.extend([p - 1, p, p + 1].map(|v| v.min(u32::MAX as u64) as u32));
            p *= base as u64;
        }
        for i in edges {
            assert_eq!(ri.sample(i), oracle(base, i), "base {base} index {i}");
        }
        for _ in 0..300 {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            assert_eq!(ri.sample(x), oracle(base, x), "base {base} index {x}");
        }
    }
}

/// The wide numerator's tabled form sums six chunks: no tabled base has more.
#[cfg(target_pointer_width = "64")]
#[test]
fn tabled_bases_have_at_most_six_chunks() {
    for base in [3, 5, 7, 11, 13] {
        let ri = RadicalInverse::new(base).unwrap();
        assert!(
            ri.table != 0 && ri.weight[0] != 0 && ri.weight[6] == 0,
            "base {base}"
        );
    }
}

/// Every index through the end of the three-chunk (nested-floor) range and into the
/// long path, for bases with chunks from 3 to 2^16.
#[test]
fn short_indices_exhaustive_against_oracle() {
    for base in [
        3, 5, 7, 11, 13, 17, 31, 37, 40, 41, 131, 251, 255, 256, 257, 4093, 65_521,
    ] {
        let ri = RadicalInverse::new(base).unwrap();
        let q = ri.chunk as u64;
        let end = (q * q * q + 5000).min(1 << 21) as u32;
        for i in 0..end {
            assert_eq!(ri.sample(i), oracle(base, i), "base {base} index {i}");
        }
    }
}

#[test]
fn sequential_matches_random_access() {
    for base in [
        2,
        3,
        4,
        5,
        6,
        7,
        10,
        31,
        256,
        8161,
        65_536,
        1 << 31,
        u32::MAX,
    ] {
        let ri = RadicalInverse::new(base).unwrap();
        for start in [0, 1, base - 1, 12_345, u32::MAX - 3000] {
            let got: Vec<u32> = ri.iter_from(start).take(3000).collect();
            for (k, g) in got.iter().enumerate() {
                assert_eq!(
                    *g,
                    ri.sample(start + k as u32),
                    "base {base} at {start}+{k}"
                );
            }
        }
        assert_eq!(ri.iter_from(u32::MAX).count(), 1);
    }
}

#[test]
fn fill_matches_random_access() {
    let bases = [
        2,
        3,
        4,
        5,
        6,
        7,
        11,
        13,
        31,
        127,
        128,
        129,
        1000,
        1 << 31,
        u32::MAX,
    ];
    for base in bases {
        let ri = RadicalInverse::new(base).unwrap();
        let starts = [
            0,
            1,
            base - 1,
            base,
            base.wrapping_mul(base).wrapping_sub(3),
            12_345,
        ];
        for start in starts.into_iter().chain([u32::MAX - 700, 3u32.pow(12) - 5]) {
            for stride in [1, 3] {
                let mut out = vec![0u32; 2000];
                let n = 2000usize.div_ceil(stride) as u32;
                if (start as u64 + n as u64) > 1 << 32 {
                    assert!(ri.fill_strided(start, &mut out, stride).is_err());
                    continue;
                }
                ri.fill_strided(start, &mut out, stride).unwrap();
                for (k, x) in out.iter().step_by(stride).enumerate() {
                    assert_eq!(*x, ri.sample(start + k as u32), "b {base} {start}+{k}");
                }
                // Slots between the strided ones are untouched.
                assert!(
                    out.iter()
                        .skip(1)
                        .step_by(stride.max(2))
                        .all(|&x| stride == 1 || x == 0)
                );
            }
        }
        // The last index of the range.
        let mut last = [7u32; 1];
        ri.fill(u32::MAX, &mut last).unwrap();
        assert_eq!(last[0], ri.sample(u32::MAX));
    }
}

/// The run fills (bases up to `RUN_TABLE`, base 2 by its own table) and the bases just
/// above, against random access: starts at and around run boundaries (`L = b^k`, `L b`),
/// long carries (`b^12`), and a range ending exactly at `u32::MAX`.
#[test]
fn run_fill_every_small_base_against_random_access() {
    for base in 2..=(RUN_TABLE as u32 + 3) {
        let ri = RadicalInverse::new(base).unwrap();
        let mut run = base;
        while run * base <= RUN_TABLE as u32 {
            run *= base;
        }
        let deep = (base as u64).pow(12.min(31 / (32 - base.leading_zeros())));
        let starts = [
            0,
            1,
            run - 1,
            run,
            run * base - 2,
            (deep - 3) as u32,
            u32::MAX - 999,
        ];
        for start in starts {
            for stride in [1, 5] {
                let mut out = vec![0u32; 1000 * stride];
                ri.fill_strided(start, &mut out, stride).unwrap();
                for (k, &x) in out.iter().step_by(stride).enumerate() {
                    assert_eq!(x, ri.sample(start + k as u32), "b {base} {start}+{k}");
                }
            }
        }
        let mut over = [0u32; 1001];
        assert!(ri.fill(u32::MAX - 999, &mut over).is_err());
    }
}

#[test]
fn long_carries_past_the_cached_steps() {
    // 3^12 - 1 -> 3^12 carries through 12 digits (> STEPS).
    let ri = RadicalInverse::new(3).unwrap();
    let start = 3u32.pow(12) - 5;
    assert!(
        ri.iter_from(start)
            .take(10)
            .zip(start..)
            .all(|(x, i)| x == ri.sample(i))
    );
}

#[test]
fn inverse_round_trips() {
    for base in [2, 3, 5, 7, 16, 31, 65_536] {
        let ri = RadicalInverse::new(base).unwrap();
        let max = ri.inverse(0, 99).unwrap_err();
        let Error::TooManyDigits { max, .. } = max else {
            panic!()
        };
        assert!((base as u64).pow(max) <= 1 << 32);
        assert!((base as u64).pow(max + 1) > 1 << 32);
        for digits in 0..=max {
            let n = (base as u64).pow(digits).min(5000);
            for i in 0..n as u32 {
                assert_eq!(
                    ri.inverse(ri.sample(i), digits),
                    Ok(i),
                    "b {base} d {digits}"
                );
            }
        }
    }
}

#[test]
fn rejects_small_bases() {
    assert_eq!(RadicalInverse::new(0), Err(Error::BaseTooSmall { base: 0 }));
    assert_eq!(RadicalInverse::new(1), Err(Error::BaseTooSmall { base: 1 }));
}
