//! Sobol' against SciPy's `qmc.Sobol(d, scramble=False, bits=32)` (Gray-code order) and
//! against Joe & Kuo's published direction numbers. Files made by tests/golden/gen.py.

use crate::common;

use common::{first_net_failure, points_2d};
use qmckit::digital::sobol::{Order, Sobol, SobolDimension, SobolTable, directions};
use qmckit::{SOBOL_MAX_DIMS, Sampler};

fn golden(name: &str) -> String {
    let path = format!("{}/tests/golden/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// FNV-1a 64 over the little-endian bytes of the values (as tests/golden/gen.py does).
fn fnv1a64(values: impl IntoIterator<Item = u32>) -> u64 {
    let mut h = 0xCBF2_9CE4_8422_2325u64;
    for v in values {
        for byte in v.to_le_bytes() {
            h = (h ^ byte as u64).wrapping_mul(0x0100_0000_01B3);
        }
    }
    h
}

fn fields(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}

#[test]
fn first_64_dimensions_match_scipy_for_65536_points() {
    let text = golden("scipy_sobol_d64_n65536.txt");
    let n = 1usize << 16;
    let s = Sobol::with_order(64, Order::Gray).unwrap();
    let mut pts = vec![0u32; n * 64];
    s.fill(0, &mut pts).unwrap();
    let (mut digests, mut points) = (0, 0);
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let f = fields(line);
        match f[0] {
            "digest" => {
                let dim: usize = f[1].parse().unwrap();
                let want = u64::from_str_radix(f[2], 16).unwrap();
                let got = fnv1a64(pts.iter().skip(dim).step_by(64).copied());
                assert_eq!(got, want, "dimension {dim}: 2^16 points differ from SciPy");
                digests += 1;
            }
            "point" => {
                let i: u32 = f[1].parse().unwrap();
                for (dim, v) in f[2..].iter().enumerate() {
                    let want: u32 = v.parse().unwrap();
                    assert_eq!(pts[i as usize * 64 + dim], want, "point {i} dim {dim}");
                    // Random access in Gray order agrees with the sequential fill.
                    assert_eq!(s.sample(i, dim).unwrap(), want);
                }
                points += 1;
            }
            other => panic!("unknown line {other}"),
        }
    }
    assert_eq!((digests, points), (64, 64));
}

#[cfg(feature = "sobol-dims-21201")]
#[test]
fn all_21201_dimensions_match_scipy_for_1024_points() {
    assert_eq!(SOBOL_MAX_DIMS, 21201);
    let text = golden("scipy_sobol_d21201_n1024.txt");
    let (n, d) = (1024usize, 21201usize);
    let s = Sobol::with_order(d, Order::Gray).unwrap();
    let mut pts = vec![0u32; n * d];
    s.fill(0, &mut pts).unwrap();
    let (mut blocks, mut columns) = (0, 0);
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let f = fields(line);
        match f[0] {
            "block" => {
                let (lo, hi): (usize, usize) = (f[1].parse().unwrap(), f[2].parse().unwrap());
                let want = u64::from_str_radix(f[3], 16).unwrap();
                let got = fnv1a64((0..n).flat_map(|i| pts[i * d + lo..i * d + hi].iter().copied()));
                assert_eq!(got, want, "dimensions {lo}..{hi} differ from SciPy");
                blocks += 1;
            }
            "column" => {
                let dim: usize = f[1].parse().unwrap();
                let dimension = SobolDimension::new(dim).unwrap();
                for (i, v) in f[2..].iter().enumerate() {
                    let want: u32 = v.parse().unwrap();
                    assert_eq!(pts[i * d + dim], want, "dim {dim} point {i}");
                    let g = (i ^ (i >> 1)) as u32;
                    assert_eq!(
                        dimension.sample(g),
                        want,
                        "random access dim {dim} point {i}"
                    );
                }
                columns += 1;
            }
            other => panic!("unknown line {other}"),
        }
    }
    assert_eq!((blocks, columns), (213, 9));
}

/// Rows d = 2..16 of Joe & Kuo's published `new-joe-kuo-6.21201` (d s a m_1 .. m_s).
const PUBLISHED: [&[u32]; 15] = [
    &[2, 1, 0, 1],
    &[3, 2, 1, 1, 3],
    &[4, 3, 1, 1, 3, 1],
    &[5, 3, 2, 1, 1, 1],
    &[6, 4, 1, 1, 1, 3, 3],
    &[7, 4, 4, 1, 3, 5, 13],
    &[8, 5, 2, 1, 1, 5, 5, 17],
    &[9, 5, 4, 1, 1, 5, 5, 5],
    &[10, 5, 7, 1, 1, 7, 11, 19],
    &[11, 5, 11, 1, 1, 5, 1, 1],
    &[12, 5, 13, 1, 1, 1, 3, 11],
    &[13, 5, 14, 1, 3, 5, 5, 31],
    &[14, 6, 1, 1, 3, 3, 9, 7, 49],
    &[15, 6, 13, 1, 1, 1, 15, 21, 21],
    &[16, 6, 16, 1, 3, 1, 13, 27, 49],
];

#[test]
fn table_rows_match_the_published_ones() {
    let text = std::fs::read_to_string(format!(
        "{}/tables/new-joe-kuo-6.21201",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let rows: Vec<Vec<u32>> = text
        .lines()
        .skip(1)
        .take(15)
        .map(|l| l.split_whitespace().map(|x| x.parse().unwrap()).collect())
        .collect();
    for (row, want) in rows.iter().zip(PUBLISHED) {
        assert_eq!(row.as_slice(), want);
        // The compiled direction numbers start with m_k 2^(32-k).
        let v = directions(row[0] as usize - 1).unwrap();
        for (k, &m) in row[3..].iter().enumerate() {
            assert_eq!(v[k], m << (31 - k), "d {} m_{}", row[0], k + 1);
        }
    }
    assert_eq!(text.lines().count(), 21201); // header + d = 2..21201
}

#[test]
fn two_dimensional_sobol_is_a_0m2_net_in_both_orders() {
    for m in 1..=16 {
        for order in [Order::Natural, Order::Gray] {
            let s = Sobol::with_order(2, order).unwrap();
            let pts = points_2d(&s, 1 << m, (0, 1));
            assert_eq!(first_net_failure(&pts, m), None, "{order:?} m = {m}");
        }
    }
}

#[test]
fn natural_and_gray_orders_hold_the_same_first_2m_points() {
    let nat = Sobol::new(8).unwrap();
    let gray = Sobol::with_order(8, Order::Gray).unwrap();
    for m in [0, 1, 5, 12] {
        let n = 1usize << m;
        let (mut a, mut b) = (vec![0u32; n * 8], vec![0u32; n * 8]);
        nat.fill(0, &mut a).unwrap();
        gray.fill(0, &mut b).unwrap();
        let mut a: Vec<&[u32]> = a.chunks(8).collect();
        let mut b: Vec<&[u32]> = b.chunks(8).collect();
        a.sort();
        b.sort();
        assert_eq!(a, b, "m = {m}");
    }
}

#[test]
fn byte_tables_match_the_matrix_product() {
    for dim in [0, 1, 5, 40, SOBOL_MAX_DIMS - 1] {
        let d = SobolDimension::new(dim).unwrap();
        let t = SobolTable::new(d);
        let mut i = 0x1234_5678u32;
        for _ in 0..100_000 {
            i = i.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
            assert_eq!(t.sample(i), d.sample(i), "dim {dim} index {i}");
        }
        for i in [0, 1, 255, 256, u32::MAX] {
            assert_eq!(t.sample(i), d.sample(i));
        }
    }
}

/// `OwenSobol` (reversed byte tables, keys per seed) against the generic path
/// (`FastOwen` over `SobolDimension::sample`, direction numbers and bit reversals): random
/// access, f32, the free functions, reseeding, and `Scrambled<Sobol, FastOwen>`.
#[test]
fn owen_sobol_matches_the_generic_scramble() {
    use qmckit::digital::sobol::{OwenSobol, owen_sobol, owen_sobol_f32};
    use qmckit::randomize::{FastOwen, OwenHash, Scrambled};
    let dims = SOBOL_MAX_DIMS.min(70);
    for (seed, hash) in [(1u64, OwenHash::Vegdahl), (0xFEED, OwenHash::LaineKarras)] {
        let owen = FastOwen::with_hash(seed, hash);
        let fast = OwenSobol::with_hash(dims, seed, hash).unwrap();
        let generic = Scrambled::new(Sobol::new(dims).unwrap(), owen);
        let mut i = 99u32;
        for _ in 0..20_000 {
            i = i.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
            for dim in [0, 1, 2, 3, 4, 5, dims - 1] {
                let want = owen.scramble(SobolDimension::new(dim).unwrap().sample(i), dim);
                assert_eq!(
                    fast.sample(i, dim).unwrap(),
                    want,
                    "{hash:?} dim {dim} index {i}"
                );
                assert_eq!(generic.sample(i, dim).unwrap(), want);
                assert_eq!(
                    fast.sample_f32(i, dim).unwrap().to_bits(),
                    qmckit::bits::to_f32(want).to_bits()
                );
                if hash == OwenHash::Vegdahl {
                    assert_eq!(owen_sobol(i, dim, seed).unwrap(), want);
                    assert_eq!(
                        owen_sobol_f32(i, dim, seed).unwrap().to_bits(),
                        qmckit::bits::to_f32(want).to_bits()
                    );
                }
            }
            let four: [u32; 4] = core::array::from_fn(|d| {
                owen.scramble(SobolDimension::new(d).unwrap().sample(i), d)
            });
            assert_eq!(fast.sample4(i), four);
        }
        // A fill matches random access; reseeding equals building with the seed.
        let (mut a, mut b) = (vec![0u32; 64 * dims], vec![0u32; 64 * dims]);
        fast.fill(1000, &mut a).unwrap();
        generic.fill(1000, &mut b).unwrap();
        assert_eq!(a, b);
        assert_eq!(a[5 * dims + 3], generic.sample(1005, 3).unwrap());
        let mut re = fast;
        re.reseed(seed + 1);
        assert_eq!(re, OwenSobol::with_hash(dims, seed + 1, hash).unwrap());
        assert_ne!(re.sample(7, 0), fast.sample(7, 0));
        assert_eq!(fast.with_seed(seed + 1), re);
    }
    assert!(owen_sobol(0, SOBOL_MAX_DIMS, 0).is_err());
    assert!(OwenSobol::new(0, 0).is_err());
    assert!(OwenSobol::new(SOBOL_MAX_DIMS + 1, 0).is_err());
    assert!(OwenSobol::new(2, 0).unwrap().sample(0, 2).is_err());
}

/// `fill_f32` (dispatching to the widest build) and the portable build against
/// `sample4_f32` and the generic path point by point.
#[test]
fn owen_sobol_fill_f32_matches_the_scalar_paths() {
    use qmckit::digital::sobol::OwenSobol;
    use qmckit::randomize::FastOwen;
    let s = OwenSobol::new(4, 31).unwrap();
    let owen = FastOwen::new(31);
    let indices: Vec<u32> = (0..20_003u32)
        .map(|k| k.wrapping_mul(2_654_435_761))
        .chain([0, 1, u32::MAX])
        .collect();
    let (mut a, mut b) = (
        vec![[0f32; 4]; indices.len()],
        vec![[0f32; 4]; indices.len()],
    );
    s.fill_f32(&indices, &mut a).unwrap();
    s.fill_f32_portable(&indices, &mut b).unwrap();
    for (k, &i) in indices.iter().enumerate() {
        let want: [u32; 4] = core::array::from_fn(|d| {
            qmckit::bits::to_f32(owen.scramble(SobolDimension::new(d).unwrap().sample(i), d))
                .to_bits()
        });
        assert_eq!(a[k].map(f32::to_bits), want, "dispatching fill at {i}");
        assert_eq!(b[k].map(f32::to_bits), want, "portable fill at {i}");
    }
    // Mismatched lengths are an error and leave `out` untouched.
    let mut short = vec![[-1f32; 4]; 3];
    for fill in [OwenSobol::fill_f32, OwenSobol::fill_f32_portable] {
        assert_eq!(
            fill(&s, &indices[..4], &mut short),
            Err(qmckit::Error::BufferLength {
                expected: 4,
                got: 3
            })
        );
        assert!(short.iter().all(|o| *o == [-1f32; 4]));
    }
}

/// Van der Corput in base 2 (the radical inverse) is Sobol's dimension 0, bit for bit: the
/// command builds `vdc` base 2 as `Sobol` so that base-2 randomizers apply to it.
#[test]
fn van_der_corput_base_2_is_sobol_dimension_0() {
    let vdc = qmckit::VanDerCorput::new(2).unwrap();
    let sobol = Sobol::new(1).unwrap();
    let mut i = 5u32;
    for _ in 0..100_000 {
        i = i.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
        assert_eq!(
            vdc.sample(i, 0).unwrap(),
            sobol.sample(i, 0).unwrap(),
            "index {i}"
        );
        assert_eq!(sobol.sample(i, 0).unwrap(), i.reverse_bits());
    }
    let (mut a, mut b) = (vec![0u32; 4096], vec![0u32; 4096]);
    vdc.fill(u32::MAX - 4095, &mut a).unwrap();
    sobol.fill(u32::MAX - 4095, &mut b).unwrap();
    assert_eq!(a, b);
    assert_eq!(vdc.len(), sobol.len());
}

#[test]
fn fills_and_iterators_match_random_access() {
    for dim in [0, 1, 2, 7, SOBOL_MAX_DIMS - 1] {
        let d = SobolDimension::new(dim).unwrap();
        for start in [0u32, 1, 255, 1 << 20, u32::MAX - 600] {
            let mut out = vec![0u32; 1200];
            if start as u64 + 1200 > 1 << 32 {
                assert!(d.fill_strided(start, &mut out, 1).is_err());
                let mut out = vec![0u32; 601];
                d.fill_strided(start, &mut out, 1).unwrap();
                assert_eq!(out[600], d.sample(u32::MAX));
                continue;
            }
            d.fill_strided(start, &mut out, 1).unwrap();
            for (k, &x) in out.iter().enumerate() {
                assert_eq!(x, d.sample(start + k as u32), "dim {dim} at {start}+{k}");
            }
            for (k, x) in d.gray_from(start).take(1200).enumerate() {
                let i = start + k as u32;
                assert_eq!(x, d.sample(i ^ (i >> 1)), "gray dim {dim} at {i}");
            }
        }
        assert_eq!(d.gray_from(u32::MAX).count(), 1);
    }
    assert!(SobolDimension::new(SOBOL_MAX_DIMS).is_err());
    assert!(Sobol::new(SOBOL_MAX_DIMS + 1).is_err());
    assert!(Sobol::new(0).is_err());
}

/// `Sobol::fill` (rows in aligned groups plus one-step head and tail rows) and the fills of
/// its scrambled forms (the direction numbers with a folded reversal or affine map, and the
/// converting fills) equal random access, which multiplies the generator matrices by the
/// index bit by bit: both orders, point widths that fill one, several and partial blocks of
/// lanes, starts on and off a group boundary, and lengths that end inside a group.
#[test]
fn multi_dimensional_fills_match_random_access() {
    use qmckit::bits::to_f64;
    use qmckit::randomize::{DigitalShift, FastOwen, Randomizer, Scrambled};
    for order in [Order::Natural, Order::Gray] {
        for dims in [1usize, 2, 3, 5, 8, 9, 16, 17, 33, 40] {
            let s = Sobol::with_order(dims, order).unwrap();
            let owen = Scrambled::new(s, FastOwen::new(9));
            let shift = Scrambled::new(s, DigitalShift::new(9));
            for start in [
                0u32,
                1,
                5,
                7,
                8,
                13,
                1000,
                4093,
                (1 << 31) - 3,
                u32::MAX - 70,
            ] {
                for rows in [1usize, 7, 8, 9, 16, 17, 71] {
                    if start as u64 + rows as u64 > 1 << 32 {
                        continue;
                    }
                    let mut plain = vec![0u32; rows * dims];
                    let mut scrambled = vec![0u32; rows * dims];
                    let mut shifted = vec![0u32; rows * dims];
                    let mut as_f64 = vec![0f64; rows * dims];
                    s.fill(start, &mut plain).unwrap();
                    owen.fill(start, &mut scrambled).unwrap();
                    shift.fill(start, &mut shifted).unwrap();
                    owen.fill_as(start, &mut as_f64).unwrap();
                    for k in 0..rows {
                        let i = start + k as u32;
                        for dim in 0..dims {
                            let at = k * dims + dim;
                            let x = s.sample(i, dim).unwrap();
                            let what =
                                format!("{order:?} d {dims} start {start} row {k} dim {dim}");
                            assert_eq!(plain[at], x, "{what}");
                            let y = FastOwen::new(9).apply(x, dim);
                            assert_eq!(scrambled[at], y, "owen {what}");
                            assert_eq!(as_f64[at].to_bits(), to_f64(y).to_bits(), "f64 {what}");
                            assert_eq!(shifted[at], DigitalShift::new(9).apply(x, dim), "{what}");
                        }
                    }
                }
            }
        }
    }
}
