//! Base-b digital sequences: Faure against QMCPy (tests/golden/gen_qmcpy_lattice.py) and
//! exact rationals, and the (0, m, s)-net property counted here from the definition
//! (elementary intervals in base b), unscrambled and scrambled.

use qmckit::Sampler;
use qmckit::analysis::tvalue::t_value_block;
use qmckit::digital::{DigitalNetB, output_digits};
use qmckit::randomize::digits::DigitScramble;
use qmckit::work::Budget;

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
    let (k, _) = output_digits(net.base()).unwrap();
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
        let scale = output_digits(base).unwrap().1 as f64;
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

/// The sequential fill (digits updated from the previous point's) gives random access's
/// bits: bases 2 to 65521, scrambled and not, starts on and off carries (`b^k - 1`, past
/// blocks of 1024), lengths across block edges; and QMCPy's Faure points through it.
#[test]
fn faure_fill_equals_random_access() {
    let scrambles = [
        DigitScramble::None,
        DigitScramble::Owen(7),
        DigitScramble::Permutations(3),
        DigitScramble::Faure,
    ];
    for (base, d) in [
        (2u32, 2usize),
        (2, 1),
        (3, 3),
        (5, 4),
        (7, 2),
        (257, 3),
        (65521, 2),
    ] {
        for scramble in scrambles {
            let f = DigitalNetB::faure(base, d).unwrap().with_scramble(scramble);
            let b = base as u64;
            let starts = [
                0u64,
                1,
                b - 1,
                b * b - 1,
                1023,
                1000,
                b.saturating_pow(3) - 2,
                70_000,
            ];
            for start in starts {
                for n in [1usize, 2, 5, 1024, 1025, 2100] {
                    if start + n as u64 > f.len() {
                        continue;
                    }
                    let mut got = vec![0u32; n * d];
                    f.fill(start as u32, &mut got).unwrap();
                    for (i, row) in got.chunks(d).enumerate() {
                        for (k, &v) in row.iter().enumerate() {
                            let want = f.sample(start as u32 + i as u32, k).unwrap();
                            assert_eq!(
                                v, want,
                                "b {base} {scramble:?} start {start} point {i} dim {k}"
                            );
                        }
                    }
                }
            }
        }
    }
    // The last points of base 2's full range, where the index has 32 digits.
    let f = DigitalNetB::faure(2, 2).unwrap();
    let mut tail = [0u32; 8];
    f.fill(u32::MAX - 3, &mut tail).unwrap();
    assert_eq!(
        tail[6..],
        [
            f.sample(u32::MAX, 0).unwrap(),
            f.sample(u32::MAX, 1).unwrap()
        ]
    );
    assert!(f.fill(u32::MAX - 2, &mut tail).is_err());
    // QMCPy's Faure in base 5 (unscrambled), read through the fill.
    let f = DigitalNetB::faure(5, 5).unwrap();
    let mut pts = vec![0u32; 625 * 5];
    f.fill(0, &mut pts).unwrap();
    let rows: Vec<Vec<f64>> = golden("qmcpy_faure_d5_n625.txt")
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split_whitespace().map(|t| t.parse().unwrap()).collect())
        .collect();
    for (i, row) in rows.iter().enumerate() {
        for (k, &want) in row.iter().enumerate() {
            let got = pts[i * 5 + k] as f64 / 2f64.powi(32);
            assert!((got - want).abs() < 1e-9, "point {i} dim {k}");
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
            assert_eq!(
                t_value_block(&f, start_of(n), m, &Budget::DEFAULT).unwrap(),
                0
            );
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
    assert_eq!(t_value_block(&twin, 0, 2, &Budget::DEFAULT).unwrap(), 1);
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
    assert!(t_value_block(&f, 0, 10, &tiny).is_err());
    assert!(t_value_block(&f, u32::MAX, 3, &Budget::DEFAULT).is_err());
}

/// Dick's interlaced Sobol' (order 2, digitally shifted) against Owen-scrambled Sobol' on
/// a smooth product, `f(x) = prod exp(x_j)` in 2D (exact `(e - 1)^2`): the least-squares
/// slope of log RMSE against log N over N = 2^6 .. 2^14 (32 seeds) is clearly steeper
/// (theory: up to -2 against -1.5).
#[test]
fn interlaced_sobol_converges_faster_on_smooth_integrands() {
    use qmckit::digital::sobol::interlaced::Interlaced;
    use qmckit::randomize::{DigitalShift, FastOwen, Lms, Scrambled};
    use qmckit::{Sobol, bits::to_f64};
    let exact = (std::f64::consts::E - 1.0).powi(2);
    let rmse = |s: &dyn Sampler, n: u32| {
        let mut buf = vec![0u32; 2 * n as usize];
        s.fill(0, &mut buf).unwrap();
        let mean = buf
            .chunks(2)
            .map(|p| (to_f64(p[0]) + to_f64(p[1])).exp())
            .sum::<f64>()
            / n as f64;
        (mean - exact).powi(2)
    };
    let slope = |make: &dyn Fn(u64) -> Box<dyn Sampler>| {
        let (mut xs, mut ys) = (vec![], vec![]);
        for m in 6..=14u32 {
            let n = 1u32 << m;
            let mse = (0..32u64).map(|seed| rmse(&*make(seed), n)).sum::<f64>() / 32.0;
            xs.push(f64::from(m) * 2f64.ln());
            ys.push(0.5 * mse.ln());
        }
        let (mx, my) = (xs.iter().sum::<f64>() / 9.0, ys.iter().sum::<f64>() / 9.0);
        let cov: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
        let var: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
        cov / var
    };
    let owen = slope(&|seed| Box::new(Scrambled::new(Sobol::new(2).unwrap(), FastOwen::new(seed))));
    let shifted = slope(&|seed| {
        Box::new(Scrambled::new(
            Interlaced::new(2, 2).unwrap(),
            DigitalShift::new(seed),
        ))
    });
    let lms = slope(&|seed| {
        // Dick's randomization: LMS + shift of each Sobol' component, then interlacing.
        let inner = Scrambled::new(
            Sobol::new(4).unwrap(),
            (Lms::new(seed), DigitalShift::new(seed)),
        );
        Box::new(Interlaced::over(inner, 2).unwrap())
    });
    eprintln!(
        "RMSE slopes: owen-sobol {owen:.2}, interlaced-2 + shift {shifted:.2}, + lms {lms:.2}"
    );
    assert!(owen > -1.8 && owen < -1.2, "owen {owen}");
    assert!(shifted < owen - 0.3, "shift {shifted} vs owen {owen}");
    assert!(lms < owen - 0.3, "lms {lms} vs owen {owen}");
}

#[test]
fn interlacing_is_the_digit_shuffle() {
    use qmckit::digital::sobol::interlaced::{Interlaced, interlace};
    assert_eq!(interlace(&[0xFFFF_0000, 0]), 0xAAAA_AAAA);
    assert_eq!(interlace(&[0, 0x8000_0000, 0]), 0x4000_0000);
    let h = Interlaced::new(3, 3).unwrap();
    let s = qmckit::Sobol::new(9).unwrap();
    let parts: Vec<u32> = (3..6).map(|k| s.sample(77, k).unwrap()).collect();
    assert_eq!(h.sample(77, 1).unwrap(), interlace(&parts));
    assert!(Interlaced::new(2, 4).is_err());
    assert!(Interlaced::new(0, 2).is_err());
    assert!(Interlaced::over(qmckit::Sobol::new(5).unwrap(), 2).is_err());
    assert!(h.sample(0, 3).is_err());
}

/// A Niederreiter–Xing net from the Magic Point Shop in LDData's format: its first 1024
/// points equal QMCPy's `DigitalNetB2` on the same matrices (`gen_qmcpy_dnet.py`), and its
/// leading `2^m` blocks are (1, m, 4)-nets, the published t of the 4-dimensional
/// Niederreiter–Xing sequence (Sobol' has t = 2 or 3 there).
#[test]
fn niederreiter_xing_file_matches_qmcpy() {
    use qmckit::digital::parse_dnet;
    let net = parse_dnet(&golden("mps.nx_b2_m30_s4_Cs.txt")).unwrap();
    assert_eq!((net.base(), net.dims(), net.len()), (2, 4, 1 << 30));
    let want: Vec<Vec<u32>> = golden("mps_nx_s4_qmcpy.txt")
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split_whitespace().map(|w| w.parse().unwrap()).collect())
        .collect();
    assert_eq!(want.len(), 1024);
    for (i, row) in want.iter().enumerate() {
        for (d, &w) in row.iter().enumerate() {
            assert_eq!(
                net.sample(i as u32, d).unwrap(),
                w << 2,
                "point {i} dim {d}"
            );
        }
    }
    for m in 2..=12 {
        let t = t_value_block(&net, 0, m, &Budget::DEFAULT).unwrap();
        assert_eq!(t, 1, "m={m}");
    }
}

#[test]
fn dnet_files_refuse_bad_input() {
    use qmckit::digital::parse_dnet;
    for bad in [
        "",
        "2\n2\n3\n3\n4 2 1\n1 2 4\n",         // no format line
        "# dnet\n2\n2\n3\n",                  // header too short
        "# dnet\n4\n2\n3\n3\n4 2 1\n1 2 4\n", // base not prime
        "# dnet\n2\n2\n3\n3\n4 2 1\n",        // a matrix line missing
        "# dnet\n2\n2\n3\n3\n4 2 1\n1 2\n",   // ragged columns
        "# dnet\n2\n2\n3\n3\n8 2 1\n1 2 4\n", // an entry with more than r digits
        "# dnet\n2\n2\n5\n3\n4 2 1\n1 2 4\n", // k does not match the lines
        "# dnet\n2\nx\n3\n3\n4 2 1\n1 2 4\n", // not a number
        "# dnet\n2\n2\n3\n0\n4 2 1\n1 2 4\n", // zero rows
    ] {
        assert!(parse_dnet(bad).is_err(), "{bad:?}");
    }
    // b^k in place of k is accepted.
    assert!(parse_dnet("# dnet\n2\n2\n8\n3\n4 2 1\n1 2 4\n").is_ok());
}

/// Primality by trial division in 64 bits (the reference; `O(sqrt n)`).
fn trial_division(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    let mut d = 2u64;
    while d * d <= n {
        if n.is_multiple_of(d) {
            return false;
        }
        d += 1;
    }
    true
}

#[test]
fn is_prime_is_exact_for_small_numbers() {
    // Sieve of Eratosthenes below 200 000.
    const N: usize = 200_000;
    let mut composite = vec![false; N];
    for p in 2..N {
        if !composite[p] {
            for q in (p * p..N).step_by(p) {
                composite[q] = true;
            }
        }
    }
    for (n, &c) in composite.iter().enumerate() {
        let want = n >= 2 && !c;
        assert_eq!(qmckit::digital::is_prime(n as u32), want, "{n}");
    }
}

#[test]
fn is_prime_is_exact_and_fast_near_2_pow_32() {
    use qmckit::digital::is_prime;
    // The primes of (2^32 - 200, 2^32), from trial division.
    let primes = [
        4294967111u32,
        4294967143,
        4294967161,
        4294967189,
        4294967197,
        4294967231,
        4294967279,
        4294967291,
    ];
    let start = std::time::Instant::now();
    for n in u32::MAX - 199..=u32::MAX {
        assert_eq!(is_prime(n), primes.contains(&n), "{n}");
    }
    // Trial division to 65536 would take about 30 000 steps a number; 200 numbers in far
    // less than a second either way, but the old loop's d * d overflowed near 2^32.
    assert!(start.elapsed().as_secs_f64() < 1.0, "{:?}", start.elapsed());
    // Carmichael numbers, strong pseudoprimes to single bases (2047, 3277, 4033, 4681, 8321
    // to base 2; 25, 325, 703, 2101, 2353 to base 7), the strong pseudoprime to bases
    // 2, 3, 5, 7 (3215031751), and squares and products of the primes next to 2^16.
    let composites = [
        561u32, 1105, 1729, 2465, 2821, 6601, 8911, 41041, 825265, 321197185, 2047, 3277, 4033,
        4681, 8321, 25, 325, 703, 2101, 2353, 3215031751, 25326001, 1194649, 12327121, 4293001441,
        4292870399, 4294967295, 4294967293,
    ];
    for n in composites {
        assert!(!is_prime(n), "{n}");
        assert!(!trial_division(n as u64), "{n} (the list itself)");
    }
    // Pseudo-random u32s against trial division.
    let mut x = 0x9e37_79b9_7f4a_7c15u64;
    for _ in 0..2000 {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let n = (x >> 32) as u32 | 1;
        assert_eq!(is_prime(n), trial_division(n as u64), "{n}");
    }
}

#[test]
fn output_digits_refuses_bases_below_2() {
    // Both used to loop for ever (1^K never reaches 2^32; 0 neither).
    for b in [0, 1] {
        assert_eq!(
            output_digits(b),
            Err(qmckit::Error::BaseTooSmall { base: b })
        );
    }
    assert_eq!(output_digits(2), Ok((32, 1 << 32)));
    assert_eq!(output_digits(3), Ok((21, 3u64.pow(21))));
    // Every base up to u32::MAX: b^K < 2^32 b stays in 64 bits.
    assert_eq!(output_digits(u32::MAX), Ok((2, (u32::MAX as u64).pow(2))));
    assert_eq!(output_digits(1 << 16), Ok((2, 1 << 32)));
}

#[test]
fn dnet_files_with_more_dimensions_than_lines_are_refused() {
    use qmckit::digital::parse_dnet;
    // A dimension count far beyond the lines given: refused, nothing allocated for it.
    let text = "# dnet\n2\n18446744073709551615\n3\n3\n4 2 1\n1 2 4\n";
    assert!(parse_dnet(text).is_err());
    // Lines past the declared dimensions are not read (a bad one there is harmless).
    let text = "# dnet\n2\n2\n3\n3\n4 2 1\n1 2 4\nnot numbers\n";
    assert_eq!(parse_dnet(text).unwrap().dims(), 2);
    // A line of more than K columns is refused without collecting it.
    let long = format!("# dnet\n2\n1\n3\n3\n{}\n", "1 ".repeat(100_000));
    assert!(parse_dnet(&long).is_err());
}
