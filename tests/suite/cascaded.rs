//! Cascaded Sobol' (Paulin et al. 2021) against the paper's defining properties: every
//! consecutive pair of dimensions is a `(0, m, 2)`-net (t-value counted from the points'
//! elementary intervals, not from the construction) and every dimension holds one point
//! in each interval of width `1/N`, for `m` from 0 to 12 and up to 8 dimensions; better
//! consecutive pairs than Sobol' itself (whose pairs, counted the same way, have t > 0);
//! the Pascal matrix against Sobol's second dimension (Joe & Kuo's table); bad input.

use qmckit::analysis::tvalue::t_value_u32;
use qmckit::bits::reverse_bits;
use qmckit::digital::cascaded::{CascadedSobol, pascal};
use qmckit::work::Budget;
use qmckit::{Error, Sampler, Sobol};

/// The points of `s`, row-major.
fn points(s: &impl Sampler) -> Vec<u32> {
    let mut out = vec![0u32; s.len() as usize * s.dims()];
    s.fill(0, &mut out).unwrap();
    out
}

/// Dimensions `a` and `b` of the row-major `pts` (`d` a point), as 2D points.
fn pair(pts: &[u32], d: usize, a: usize, b: usize) -> Vec<u32> {
    pts.chunks_exact(d).flat_map(|p| [p[a], p[b]]).collect()
}

#[test]
fn consecutive_pairs_are_0m2_nets_and_every_dimension_is_stratified() {
    for m in [0u32, 1, 2, 3, 4, 6, 8, 10, 12] {
        let n = 1u64 << m;
        for d in [1usize, 2, 3, 5, 8] {
            for seed in [0u64, 1, 0xDEAD_BEEF] {
                let s = CascadedSobol::new(n, d, seed).unwrap();
                let pts = points(&s);
                for j in 0..d {
                    let mut seen = vec![false; n as usize];
                    for p in pts.chunks_exact(d) {
                        let k = ((u64::from(p[j]) * n) >> 32) as usize;
                        assert!(
                            !seen[k],
                            "m {m} d {d} seed {seed}: dim {j} stratum {k} twice"
                        );
                        seen[k] = true;
                    }
                }
                for j in 0..d.saturating_sub(1) {
                    let t = t_value_u32(&pair(&pts, d, j, j + 1), 2, m, &Budget::DEFAULT);
                    assert_eq!(t.unwrap(), 0, "m {m} d {d} seed {seed}: pair ({j}, {j}+1)");
                }
            }
        }
    }
}

#[test]
fn consecutive_pairs_beat_sobol() {
    // Sobol' (Joe & Kuo) in 8 dimensions, 2^10 points: counted, some consecutive pair
    // is not a (0, 10, 2)-net; the cascade's pairs all are.
    let (m, d) = (10u32, 8usize);
    let sobol = Sobol::new(d).unwrap();
    let mut sob = vec![0u32; (1 << m) * d];
    sobol.fill(0, &mut sob).unwrap();
    let sobol_t: Vec<u32> = (0..d - 1)
        .map(|j| t_value_u32(&pair(&sob, d, j, j + 1), 2, m, &Budget::DEFAULT).unwrap())
        .collect();
    assert!(sobol_t.iter().any(|&t| t > 0), "{sobol_t:?}");
    let pts = points(&CascadedSobol::new(1 << m, d, 3).unwrap());
    let ours: Vec<u32> = (0..d - 1)
        .map(|j| t_value_u32(&pair(&pts, d, j, j + 1), 2, m, &Budget::DEFAULT).unwrap())
        .collect();
    assert_eq!(ours, vec![0; d - 1]);
    assert!(ours.iter().sum::<u32>() < sobol_t.iter().sum::<u32>());
}

#[test]
fn pascal_is_sobol_dimension_one() {
    let sobol = Sobol::new(2).unwrap();
    for k in (0..1u32 << 16).chain([u32::MAX, 0x8000_0001, 0x1234_5678]) {
        assert_eq!(pascal(k), sobol.sample(k, 1).unwrap(), "index {k}");
    }
}

#[test]
fn unscrambled_cascade_would_repeat_and_the_scrambles_break_it() {
    // P^2 = I over GF(2): chained twice without scrambles, phi_2(k) comes back.
    let m = 10;
    for k in 0..1u32 << m {
        let once = pascal(k); // x_1 = P rev_m(phi_2(k)) = P k
        let twice = pascal(reverse_bits(once) & ((1 << m) - 1));
        assert_eq!(twice, reverse_bits(k));
    }
    // Scrambled, x_2 is not x_0: few points share their top m digits in both.
    let s = CascadedSobol::new(1 << m, 3, 11).unwrap();
    let pts = points(&s);
    let same = pts
        .chunks_exact(3)
        .filter(|p| p[0] >> (32 - m) == p[2] >> (32 - m))
        .count();
    assert!(
        same < 16,
        "{same} of 1024 points have x_2 = x_0 to m digits"
    );
}

#[test]
fn sample_fill_seed_and_errors() {
    let s = CascadedSobol::new(64, 5, 9).unwrap();
    let pts = points(&s);
    for i in [0u32, 1, 17, 63] {
        for j in 0..5 {
            assert_eq!(s.sample(i, j).unwrap(), pts[i as usize * 5 + j]);
        }
    }
    let mut tail = vec![0u32; 2 * 5];
    s.fill(62, &mut tail).unwrap();
    assert_eq!(tail, pts[62 * 5..]);
    assert_ne!(points(&CascadedSobol::new(64, 5, 10).unwrap()), pts);
    assert!(matches!(
        CascadedSobol::new(12, 2, 0),
        Err(Error::NotPowerOfTwo { n: 12 })
    ));
    assert!(matches!(
        CascadedSobol::new(0, 2, 0),
        Err(Error::ZeroPoints)
    ));
    assert!(matches!(
        CascadedSobol::new(8, 0, 0),
        Err(Error::ZeroDimensions)
    ));
    assert!(CascadedSobol::new(1 << 33, 2, 0).is_err());
    assert!(CascadedSobol::new(8, (1 << 16) + 1, 0).is_err());
    assert!(s.sample(64, 0).is_err());
    assert!(s.sample(0, 5).is_err());
}
