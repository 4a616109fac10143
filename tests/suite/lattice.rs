//! Rank-1 lattices and Kronecker sequences against QMCPy (golden files from
//! tests/golden/gen_qmcpy_lattice.py), exact integer arithmetic and high-precision R_d.

use qmckit::Sampler;
use qmckit::lattice::kronecker::Kronecker;
use qmckit::lattice::{KUO_33002, Rank1Lattice, korobov, parse_lattice};
use qmckit::randomize::{CranleyPatterson, Scrambled, Shift, Tent};

fn golden(name: &str) -> String {
    let path = format!("{}/tests/golden/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The data rows of a golden file, as integers.
fn rows(name: &str) -> Vec<Vec<u64>> {
    golden(name)
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split_whitespace().map(|t| t.parse().unwrap()).collect())
        .collect()
}

fn points(s: &impl Sampler, n: u32) -> Vec<Vec<u64>> {
    let d = s.dims();
    let mut buf = vec![0u32; n as usize * d];
    s.fill(0, &mut buf).unwrap();
    // fill and sample agree
    for i in (0..n).step_by(7) {
        for k in 0..d {
            assert_eq!(buf[i as usize * d + k], s.sample(i, k).unwrap());
        }
    }
    buf.chunks(d)
        .map(|r| r.iter().map(|&x| x as u64).collect())
        .collect()
}

#[test]
fn radical_inverse_order_equals_qmcpy() {
    let l = Rank1Lattice::kuo(8).unwrap();
    assert_eq!(l.len(), 1 << 20);
    assert_eq!(points(&l, 1024), rows("qmcpy_lattice_natural_d8_n1024.txt"));
}

#[test]
fn linear_order_equals_qmcpy() {
    let l = Rank1Lattice::linear(&KUO_33002[..8], 256).unwrap();
    assert_eq!(points(&l, 256), rows("qmcpy_lattice_linear_d8_n256.txt"));
}

#[test]
fn shifted_lattice_equals_qmcpy() {
    let g = rows("qmcpy_lattice_shifted_d4_n64.txt");
    let shift: Vec<u32> = g[0].iter().map(|&x| x as u32).collect();
    let l = Scrambled::new(Rank1Lattice::kuo(4).unwrap(), Shift::new(shift));
    assert_eq!(points(&l, 64), g[1..].to_vec());
}

/// Every prefix of 2^m points of the extensible lattice is the linear lattice with
/// n = 2^m (as a set).
#[test]
fn extensible_prefixes_are_the_fixed_lattices() {
    let z = &KUO_33002[..6];
    let ext = Rank1Lattice::extensible(z, 20).unwrap();
    for m in [0u32, 1, 4, 7, 10, 12] {
        let n = 1u32 << m;
        let fixed = Rank1Lattice::linear(z, n as u64).unwrap();
        let mut a = points(&ext, n);
        let mut b = points(&fixed, n);
        a.sort();
        b.sort();
        assert_eq!(a, b, "m = {m}");
    }
}

/// The linear rule for n not a power of two, against exact integer arithmetic
/// `floor(((i z) mod n) 2^32 / n)` written out here, and the Fibonacci lattice's
/// published shape (n = F_k, z = (1, F_(k-1))).
#[test]
fn linear_rule_is_exact_for_any_n() {
    let z = [1u32, 610];
    let l = Rank1Lattice::linear(z, 987).unwrap();
    for i in 0..987u64 {
        for (k, &zk) in z.iter().enumerate() {
            let num = (i * zk as u64 % 987) as u128 * (1u128 << 32);
            assert_eq!(l.sample(i as u32, k).unwrap() as u128, num / 987);
        }
    }
    assert!(l.sample(987, 0).is_err());
    assert!(l.sample(0, 2).is_err());
}

#[test]
fn shipped_table_equals_its_text_file() {
    let text = std::fs::read_to_string(format!(
        "{}/tables/kuo.lattice-33002-1024-1048576.9125.txt",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let mut z = vec![0u32; 9125];
    let info = parse_lattice(&text, &mut z).unwrap();
    assert_eq!(info.modulus, Some(1 << 20));
    assert_eq!(info.declared_dims, Some(9125));
    assert_eq!(z, KUO_33002);
    // The published first components of this vector.
    assert_eq!(
        &z[..8],
        [1, 182667, 213731, 255351, 96013, 116671, 479315, 424089]
    );
}

#[test]
fn parser_accepts_kuo_two_columns_and_refuses_garbage() {
    let mut z = [0u32; 3];
    let info = parse_lattice("1 1\n2 182667\n3 469891\n4 498753\n", &mut z).unwrap();
    assert_eq!((info.read, z), (3, [1, 182667, 469891]));
    for bad in [
        "",
        "# dnet\n2\n4\n1\n1\n",
        "# lattice\n3\n",
        "# lattice\n3\n16\n1\n5\n",
        "# lattice\n2\n16\n1\nx\n",
        "# lattice\n1\n16\n4294967296\n",
        "# lattice\n1\n0\n1\n",
        "1 1\n3 5\n",
        "1 1 1\n",
    ] {
        assert!(parse_lattice(bad, &mut z).is_err(), "{bad:?}");
    }
}

#[test]
fn korobov_vectors_are_powers() {
    let mut z = [0u32; 5];
    korobov(76, 1021, &mut z).unwrap();
    let mut p = 1u64;
    for &zk in &z {
        assert_eq!(zk as u64, p);
        p = p * 76 % 1021;
    }
    assert!(korobov(3, 0, &mut z).is_err());
}

/// A shifted lattice rule with the tent transform integrates a smooth non-periodic
/// function with a much smaller error than without (second order against first).
#[test]
fn tent_transform_helps_non_periodic_integrands() {
    let f = |x: &[f64]| x.iter().map(|&t| t * t).product::<f64>(); // exact 1/3^d
    let exact = (1.0f64 / 3.0).powi(3);
    let err = |tent: bool| {
        let mut total = 0.0;
        for seed in 0..8 {
            let base = Rank1Lattice::linear(&KUO_33002[..3], 4096).unwrap();
            let mut buf = vec![0f64; 4096 * 3];
            if tent {
                Scrambled::new(base, (CranleyPatterson::new(seed), Tent))
                    .fill_as(0, &mut buf)
                    .unwrap();
            } else {
                Scrambled::new(base, CranleyPatterson::new(seed))
                    .fill_as(0, &mut buf)
                    .unwrap();
            }
            let mean = buf.chunks(3).map(f).sum::<f64>() / 4096.0;
            total += (mean - exact).powi(2);
        }
        (total / 8.0).sqrt()
    };
    let (plain, tent) = (err(false), err(true));
    assert!(tent * 20.0 < plain, "tent {tent:e}, plain {plain:e}");
}

#[test]
fn lattice_refuses_bad_parameters() {
    assert!(Rank1Lattice::linear([1u32], 0).is_err());
    assert!(Rank1Lattice::linear([0u32; 0], 8).is_err());
    assert!(Rank1Lattice::linear([1u32], (1 << 32) + 1).is_err());
    assert!(Rank1Lattice::extensible([1u32], 33).is_err());
    assert!(Rank1Lattice::kuo(0).is_err());
    assert!(Rank1Lattice::kuo(9126).is_err());
    assert!(Rank1Lattice::kuo(9125).is_ok());
    let l = Rank1Lattice::kuo(2).unwrap();
    assert!(l.sample(1 << 20, 0).is_err());
    assert!(l.fill((1 << 20) - 1, &mut [0; 4]).is_err());
}

#[test]
fn r_d_alpha_matches_high_precision() {
    for row in rows("rd_alpha.txt") {
        let (d, j, want) = (row[0] as usize, row[1] as usize, row[2] as u32);
        let k = Kronecker::r_d(d).unwrap();
        assert_eq!(k.alpha(j - 1), Some(want), "d = {d}, j = {j}");
    }
    // UTK's / Patel's fixed-point R2.
    let r2 = Kronecker::r_d(2).unwrap();
    assert_eq!(
        (r2.alpha(0), r2.alpha(1)),
        (Some(0xC13F_A9A9), Some(0x91E1_0DA5))
    );
}

#[test]
fn kronecker_equals_qmcpy() {
    let g = rows("qmcpy_kronecker_d3_n256.txt");
    let alpha: Vec<u32> = g[0].iter().map(|&x| x as u32).collect();
    let shift: Vec<u32> = g[1].iter().map(|&x| x as u32).collect();
    let k = Scrambled::new(Kronecker::with_alpha(alpha).unwrap(), Shift::new(shift));
    assert_eq!(points(&k, 256), g[2..].to_vec());
}

#[test]
fn kronecker_r_d_fill_matches_sample_in_many_dims() {
    let k = Kronecker::r_d(150).unwrap();
    let mut buf = vec![0u32; 150 * 5];
    k.fill(1000, &mut buf).unwrap();
    for i in 0..5u32 {
        for d in 0..150 {
            assert_eq!(buf[i as usize * 150 + d], k.sample(1000 + i, d).unwrap());
        }
    }
    assert!(Kronecker::r_d(0).is_err());
    assert!(Kronecker::with_alpha(Vec::<u32>::new()).is_err());
    assert!(k.sample(0, 150).is_err());
}

/// `n^2` times the squared minimum toroidal distance of `frac(i (1, a) / n)`, by brute force
/// over the difference vectors (the lattice's own points), not by basis reduction.
fn brute_min_sq(n: u64, a: u64) -> u64 {
    (1..n)
        .map(|i| {
            let (x, y) = (i, i * a % n);
            let (x, y) = (x.min(n - x), y.min(n - y));
            x * x + y * y
        })
        .min()
        .unwrap_or(0)
}

/// The reduction's shortest vector equals brute force for every generator of every
/// `n < 160`; the search returns the least generator of the largest distance (brute force
/// again); and no lattice beats the hexagonal packing, `lambda_1^2 <= 2 n / sqrt 3`.
#[test]
fn maximin_lattice_equals_brute_force_and_respects_the_packing_bound() {
    use qmckit::lattice::maximin::{max_min_distance, shortest_vector_sq};
    use qmckit::work::Budget;
    for n in 2u32..160 {
        let mut best = (1u64, 0u64);
        for a in 1..n {
            let want = brute_min_sq(n as u64, a as u64);
            assert_eq!(shortest_vector_sq(n, a), want, "n {n} a {a}");
            if a <= n / 2 && want > best.1 {
                best = (a as u64, want);
            }
        }
        if n >= 3 {
            let (a, d) = max_min_distance(n, &Budget::DEFAULT).unwrap();
            assert_eq!((a as u64, d), best, "n {n}");
        }
    }
    for n in [1000u32, 1024, 4096, 10007] {
        let (a, d) = max_min_distance(n, &Budget::DEFAULT).unwrap();
        assert_eq!(d, brute_min_sq(n as u64, a as u64));
        assert!((d as f64) <= 2.0 * n as f64 / 3f64.sqrt(), "n {n}");
        // Near the packing: at least 90% of the hexagonal lattice's distance.
        assert!(
            (d as f64).sqrt() >= 0.9 * (2.0 * n as f64 / 3f64.sqrt()).sqrt(),
            "n {n}"
        );
    }
    // The whole range refuses quickly, by its estimate.
    let t = std::time::Instant::now();
    let budget = Budget::seconds(1.0).unwrap();
    assert!(max_min_distance(u32::MAX, &budget).is_err());
    assert!(max_min_distance(0, &budget).is_err());
    assert!(t.elapsed().as_secs_f64() < 0.5);
}
