//! The blue-noise pixel samplers on their optimized tables: per-pixel nets and lattices,
//! the lattice generator's stated quality, the dimensions as domains, and the screen-space
//! error against independent per-pixel Owen-Sobol' (PaddedSobol).

use crate::common::first_net_failure;
use qmckit::pixel::domain::Domain;
use qmckit::pixel::{
    BLUE_NOISE_LATTICE_GENERATOR, BLUE_NOISE_LATTICE_SHIFTS, BLUE_NOISE_SOBOL_KEYS,
    BlueNoiseLattice, BlueNoiseSobol, PixelSampler,
};

#[test]
fn blue_noise_sobol_pixels_are_nets_in_every_dimension() {
    for seed in [0u64, 5] {
        let s = BlueNoiseSobol::new(70, 50, 16, seed).unwrap();
        for (x, y) in [(0u32, 0u32), (69, 49), (13, 31)] {
            for dim in [0usize, 2, 3, 17, 1000] {
                let pts: Vec<[u32; 2]> = (0..16)
                    .map(|i| {
                        s.start_pixel_sample(x, y, i)
                            .unwrap()
                            .with_dimension(dim)
                            .get_2d()
                    })
                    .collect();
                assert_eq!(first_net_failure(&pts, 4), None, "{seed} {x} {y} {dim}");
            }
        }
    }
}

#[test]
fn sampler_dimensions_are_the_roots_children() {
    let s = BlueNoiseSobol::new(32, 32, 8, 9).unwrap();
    let l = BlueNoiseLattice::new(32, 32, 8, 9).unwrap();
    for (x, y, i) in [(0u32, 0u32, 0u32), (31, 7, 5)] {
        let mut p = s.start_pixel_sample(x, y, i).unwrap();
        let root = s.domain(x, y, i).unwrap();
        assert_eq!(p.get_pixel_2d(), root.new_domain(0).draw_2d());
        assert_eq!(p.get_1d(), root.new_domain(2).draw_1d());
        assert_eq!(p.get_2d(), root.new_domain(3).draw_2d());
        let mut q = l.start_pixel_sample(x, y, i).unwrap();
        let root: Domain = l.domain(x, y, i).unwrap();
        assert_eq!(q.get_pixel_2d(), root.new_domain(0).draw_2d());
        assert_eq!(q.get_2d(), root.new_domain(2).draw_2d());
    }
    assert!(s.domain(32, 0, 0).is_err());
    assert!(l.domain(0, 0, 8).is_err());
    assert!(BlueNoiseSobol::new(0, 4, 4, 0).is_err());
}

/// The tables are permutations of random pools: no repeated key or shift (a repeat in
/// 4096 uniform 32-bit keys has probability 0.2%; the optimizer's pool had none).
#[test]
fn tables_hold_distinct_cells() {
    let mut k = BLUE_NOISE_SOBOL_KEYS.to_vec();
    k.sort_unstable();
    k.dedup();
    assert_eq!(k.len(), 4096);
    let mut s = BLUE_NOISE_LATTICE_SHIFTS.to_vec();
    s.sort_unstable();
    s.dedup();
    assert_eq!(s.len(), 4096);
}

/// The lattice `(a / n, a g / n mod 1)`, `n = 2^m`: its shortest nonzero vector (over every
/// `a`, brute force) is at least 0.65 of the hexagonal lattice's `sqrt(2 / (sqrt(3) n))`
/// for `m = 2..14`.
#[test]
fn lattice_generator_is_good_at_every_power_of_two() {
    let g = BLUE_NOISE_LATTICE_GENERATOR as u64;
    assert_eq!(g % 2, 1);
    for m in 2..=14u32 {
        let n = 1u64 << m;
        let mut best = u64::MAX;
        for a in 1..n {
            let dx = a.min(n - a);
            let y = a * g % n;
            let dy = y.min(n - y);
            best = best.min(dx * dx + dy * dy);
        }
        let ratio = (best as f64).sqrt() / n as f64 / (2.0 / (3f64.sqrt() * n as f64)).sqrt();
        assert!(ratio >= 0.65, "m = {m}: {ratio}");
    }
}

/// The blue-noise samplers' error against the same per-pixel randomization without the
/// table (PaddedSobol: per-pixel, per-dimension hashed Owen-Sobol'): the low-band power
/// of the error image is at most half (0.65 for the step at 16 spp), the RMSE not larger
/// than 1.1x; the lattice's low band at most half, its RMSE at most 1.15x. 128 x 128 pixels,
/// 4 seeds, the Gaussian bump and the step of `analysis::screen_error` (not in the
/// optimizer's family, which draws its Heavisides at random).
#[cfg(feature = "analysis")]
#[test]
fn blue_noise_samplers_push_the_error_out_of_the_low_band() {
    use qmckit::analysis::screen_error::{PixelIntegrand, screen_error};
    use qmckit::pixel::{PaddedSobol, Randomization};
    use qmckit::work::Budget;
    const SEEDS: u64 = 4;
    let u = Budget::UNLIMITED;
    let mut report = String::new();
    for f in [PixelIntegrand::GaussianBump, PixelIntegrand::Step] {
        for spp in [1u32, 4, 16] {
            let mut acc = [[0.0f64; 2]; 3];
            for seed in 0..SEEDS {
                let p = PaddedSobol::new(128, 128, spp, Randomization::FastOwen, seed).unwrap();
                let b = BlueNoiseSobol::new(128, 128, spp, seed).unwrap();
                let l = BlueNoiseLattice::new(128, 128, spp, seed).unwrap();
                let e = [
                    screen_error(&p, f, &u).unwrap(),
                    screen_error(&b, f, &u).unwrap(),
                    screen_error(&l, f, &u).unwrap(),
                ];
                for (a, e) in acc.iter_mut().zip(e) {
                    a[0] += e.rmse * e.rmse;
                    a[1] += e.low_band_absolute;
                }
            }
            let low = |k: usize| acc[k][1] / acc[0][1];
            let rmse = |k: usize| (acc[k][0] / acc[0][0]).sqrt();
            report += &format!(
                "{f:?} spp {spp}: low band / padded: sobol {:.3} lattice {:.3}; RMSE / padded: \
                 sobol {:.3} lattice {:.3}\n",
                low(1),
                low(2),
                rmse(1),
                rmse(2)
            );
            // At 16 spp the step's per-key errors are the least alike over the optimizer's
            // family, and one key a pixel cancels less of them (measured 0.58).
            let bound = if f == PixelIntegrand::Step && spp == 16 {
                0.65
            } else {
                0.5
            };
            assert!(low(1) <= bound && rmse(1) <= 1.1, "{report}");
            // The lattice's RMSE is its own (a shifted lattice, not a scrambled net): up to
            // 8% above the nets' on the step at 4 spp, far below on the smooth bump.
            assert!(low(2) <= 0.5 && rmse(2) <= 1.15, "{report}");
        }
    }
    println!("{report}");
}
