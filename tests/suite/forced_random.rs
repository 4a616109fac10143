//! Forced random sampling (Cornel et al. 2017) against its stated properties: counts in
//! regions follow `N` times the integral of the importance density (the integral by this
//! file's own fine midpoint rule), a constant density gives exactly `N` points whose
//! periodogram is far below white noise at low frequencies (independent points of the
//! same size as the reference), and bad densities are refused.

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::blue_noise::ForcedRandom;
use qmckit::work::Budget;
use qmckit::{Independent, Sampler};

/// An importance density on the unit square.
type Density = dyn Fn([f64; 2]) -> f64;

/// Mean periodogram over `1 <= |k| <= kmax`, averaged over the sets.
fn low_power(sets: &[Vec<f64>], kmax: i64) -> f64 {
    let (mut sum, mut count) = (0.0, 0usize);
    for pts in sets {
        let s = spectrum_2d(
            Points::new(pts, 2).unwrap(),
            kmax as usize,
            &Budget::DEFAULT,
        )
        .unwrap();
        for (kx, ky, p) in s.iter() {
            let r2 = kx * kx + ky * ky;
            if r2 >= 1 && r2 <= kmax * kmax {
                sum += p;
                count += 1;
            }
        }
    }
    sum / count as f64
}

/// The integral of `f` over `[x0, x1) x [y0, y1)` by the midpoint rule on 1000 x 1000.
fn integral(f: &Density, x0: f64, x1: f64, y0: f64, y1: f64) -> f64 {
    let m = 1000;
    let (hx, hy) = ((x1 - x0) / m as f64, (y1 - y0) / m as f64);
    let mut s = 0.0;
    for i in 0..m {
        for j in 0..m {
            s += f([x0 + (i as f64 + 0.5) * hx, y0 + (j as f64 + 0.5) * hy]);
        }
    }
    s * hx * hy
}

#[test]
fn counts_follow_the_density() {
    let ramp = |p: [f64; 2]| 0.2 + 1.6 * p[0];
    let bump = |p: [f64; 2]| {
        1.0 + 8.0 * (-((p[0] - 0.3).powi(2) + (p[1] - 0.6).powi(2)) / (2.0 * 0.1 * 0.1)).exp()
    };
    let densities: [(&Density, &str); 2] = [(&ramp, "ramp"), (&bump, "bump")];
    let n = 4000usize;
    for (f, name) in densities {
        let whole = integral(f, 0.0, 1.0, 0.0, 1.0);
        for seed in [1u64, 2] {
            let pts = ForcedRandom::new(n as u64)
                .unwrap()
                .seed(seed)
                .sample(f, &Budget::DEFAULT)
                .unwrap()
                .to_f64();
            let total = pts.len() / 2;
            // About N in all: within 1 per cent.
            assert!(
                (total as f64 - n as f64).abs() < 0.01 * n as f64,
                "{name}: {total}"
            );
            // Every cell of a 4 x 4 partition: within 3 per cent of N plus 3 standard
            // deviations of a Poisson count (independent points would meet the latter;
            // a sampler ignoring the density misses the ramp's corners by half).
            for a in 0..4 {
                for b in 0..4 {
                    let (x0, y0) = (a as f64 / 4.0, b as f64 / 4.0);
                    let p = integral(f, x0, x0 + 0.25, y0, y0 + 0.25) / whole;
                    let want = n as f64 * p;
                    let got = pts
                        .chunks(2)
                        .filter(|q| {
                            (x0..x0 + 0.25).contains(&q[0]) && (y0..y0 + 0.25).contains(&q[1])
                        })
                        .count() as f64;
                    assert!(
                        (got - want).abs() <= 0.03 * want + 3.0 * want.sqrt(),
                        "{name} seed {seed} cell ({a}, {b}): {got} vs {want:.1}"
                    );
                }
            }
        }
    }
}

#[test]
fn constant_density_is_blue_noise_of_exactly_n_points() {
    let n = 1024usize;
    let sets: Vec<Vec<f64>> = (0..4u64)
        .map(|seed| {
            let s = ForcedRandom::new(n as u64)
                .unwrap()
                .seed(seed)
                .generate(&Budget::DEFAULT)
                .unwrap();
            assert_eq!(s.count(), n);
            s.to_f64()
        })
        .collect();
    let white: Vec<Vec<f64>> = (0..4u64)
        .map(|seed| {
            let s = Independent::new(2, 50 + seed).unwrap();
            let mut v = vec![0u32; n * 2];
            s.fill(0, &mut v).unwrap();
            v.into_iter().map(qmckit::bits::to_f64).collect()
        })
        .collect();
    let kmax = ((n as f64).sqrt() / 2.0) as i64;
    let (blue, reference) = (low_power(&sets, kmax), low_power(&white, kmax));
    assert!((0.85..1.15).contains(&reference), "white {reference}");
    assert!(
        blue < 0.3 * reference,
        "forced random {blue} vs white {reference}"
    );
}

#[test]
fn bad_densities_are_refused() {
    let b = Budget::DEFAULT;
    let f = ForcedRandom::new(100).unwrap();
    assert!(f.sample(&|p| p[0] - 0.5, &b).is_err());
    assert!(f.sample(&|_| f64::NAN, &b).is_err());
    assert!(f.sample(&|_| 0.0, &b).is_err());
    assert!(f.sample(&|_| f64::INFINITY, &b).is_err());
    // All the mass at one point: too peaked for any grid.
    let spike = |p: [f64; 2]| if p[0] < 1e-4 && p[1] < 1e-4 { 1.0 } else { 0.0 };
    assert!(ForcedRandom::new(1000).unwrap().sample(&spike, &b).is_err());
    assert!(ForcedRandom::new(0).is_err());
    assert!(f.matrix_side(8).is_err());
    assert!(matches!(
        ForcedRandom::new(1 << 22)
            .unwrap()
            .generate(&Budget::seconds(1e-6).unwrap()),
        Err(qmckit::Error::OverBudget { .. })
    ));
}

/// The shipped forcing matrix is a rank matrix (a permutation of `0..R^2`), and the seed
/// moves it: different seeds give different sets of the same size.
#[test]
fn the_shipped_matrix_is_a_permutation_and_seeds_move_it() {
    use qmckit::blue_noise::{FORCING_MATRIX, FORCING_SIDE};
    let mut seen = vec![false; FORCING_SIDE * FORCING_SIDE];
    for &r in FORCING_MATRIX.iter() {
        assert!(!seen[r as usize], "rank {r} twice");
        seen[r as usize] = true;
    }
    let set = |seed| {
        ForcedRandom::new(2000)
            .unwrap()
            .seed(seed)
            .generate(&Budget::DEFAULT)
            .unwrap()
    };
    let (a, b) = (set(1), set(2));
    assert_eq!((a.count(), b.count()), (2000, 2000));
    assert_ne!(a, b);
    assert_eq!(a, set(1));
}

/// Toroidal distances, in cells, from each of `cells` to its nearest other: (min, mean).
fn spacing(side: usize, cells: &[usize]) -> (f64, f64) {
    let d = |a: usize, b: usize| {
        let (dx, dy) = ((a % side).abs_diff(b % side), (a / side).abs_diff(b / side));
        let (dx, dy) = (dx.min(side - dx) as f64, dy.min(side - dy) as f64);
        (dx * dx + dy * dy).sqrt()
    };
    let nn: Vec<f64> = cells
        .iter()
        .map(|&a| {
            cells
                .iter()
                .filter(|&&b| b != a)
                .map(|&b| d(a, b))
                .fold(f64::MAX, f64::min)
        })
        .collect();
    let min = nn.iter().copied().fold(f64::MAX, f64::min);
    (min, nn.iter().sum::<f64>() / nn.len() as f64)
}

/// Purgathofer et al.'s forced-random matrix: a permutation whose every threshold is
/// evenly spaced. At 1/64, 1/16 and 1/4 of the cells of a 64 x 64 matrix the mean
/// nearest-neighbour distance is at least 0.75 of the hexagonal lattice's spacing
/// `sqrt(2 / (sqrt 3 density))` and the closest pair at least 0.45 of it (random cells:
/// about 0.5 and near 0); the seed changes the matrix; bad sides and widths are refused.
#[test]
fn force_field_thresholds_are_evenly_spaced() {
    use qmckit::blue_noise::force_field::force_field_ranks;
    let side = 64;
    let ranks = force_field_ranks(side, 1.0, 3, &Budget::DEFAULT).unwrap();
    let mut sorted = ranks.clone();
    sorted.sort_unstable();
    assert!(sorted.iter().enumerate().all(|(i, &r)| r == i as u32));
    for frac in [64usize, 16, 4] {
        let count = side * side / frac;
        let cells: Vec<usize> = (0..side * side)
            .filter(|&c| (ranks[c] as usize) < count)
            .collect();
        let hex = (2.0 * frac as f64 / 3f64.sqrt()).sqrt();
        let (min, mean) = spacing(side, &cells);
        assert!(mean >= 0.75 * hex, "1/{frac}: mean NN {mean} of hex {hex}");
        assert!(min >= 0.45 * hex, "1/{frac}: min NN {min} of hex {hex}");
    }
    assert_ne!(
        ranks,
        force_field_ranks(side, 1.0, 4, &Budget::DEFAULT).unwrap()
    );
    for (s, w) in [
        (4usize, 1.0),
        (2048, 1.0),
        (64, 0.1),
        (64, f64::NAN),
        (64, 9.0),
    ] {
        assert!(force_field_ranks(s, w, 0, &Budget::DEFAULT).is_err());
    }
    // Refused by its estimate, at once.
    let t = std::time::Instant::now();
    assert!(force_field_ranks(1024, 1.0, 0, &Budget::seconds(1.0).unwrap()).is_err());
    assert!(t.elapsed().as_secs_f64() < 0.5);
}
