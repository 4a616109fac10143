//! Properties of the Halton and Stratified pixel samplers beyond pbrt's goldens: Halton's
//! pixel owns the cells of its first two coordinates and repeats every 128 pixels, its
//! exact fractions are the radical inverses (exact rationals), Stratified's samples fill
//! their strata, the floats round the fractions, and bad input is an error.

use qmckit::Error;
use qmckit::pixel::{HaltonSampler, PixelSampler, Randomization, StratifiedSampler};

/// The radical inverse of `a` in `base` as an exact rational `(num, den)`.
fn radical_inverse(mut a: u64, base: u64) -> (u128, u128) {
    let (mut num, mut den) = (0u128, 1u128);
    while a > 0 {
        num = num * base as u128 + (a % base) as u128;
        den *= base as u128;
        a /= base;
    }
    (num, den)
}

#[test]
fn halton_pixels_own_their_cells_and_fractions_are_exact() {
    let (w, h, spp) = (16u32, 9u32, 3u32);
    let s = HaltonSampler::new(w, h, spp, Randomization::None, 0).unwrap();
    let mut seen = std::collections::HashSet::new();
    for y in 0..h {
        for x in 0..w {
            for i in 0..spp {
                let mut p = s.start_pixel_sample(x, y, i).unwrap();
                let index = p.sample_index().unwrap();
                assert!(seen.insert(index), "index {index} twice");
                // The first two coordinates of the index fall in pixel (x, y) of the
                // 16 x 9 grid (2^4 x 3^2 cells).
                let (n0, d0) = radical_inverse(index, 2);
                let (n1, d1) = radical_inverse(index, 3);
                assert_eq!((n0 * 16 / d0, n1 * 9 / d1), (x as u128, y as u128));
                // Dimension d is the d-th prime's radical inverse, truncated to 0.32.
                for (d, base) in [(2usize, 5u64), (3, 7), (4, 11), (10, 31)] {
                    let (n, den) = radical_inverse(index, base);
                    let want = ((n << 32) / den) as u32;
                    let mut q = s.start_pixel_sample(x, y, i).unwrap().with_dimension(d);
                    assert_eq!(q.get_1d(), want, "({x}, {y}) {i} dim {d}");
                }
                // The position in the pixel: the same coordinates, scaled.
                let [u, v] = p.get_pixel_2d();
                let (pn0, pd0) = radical_inverse(index >> 4, 2);
                let (pn1, pd1) = radical_inverse(index / 9, 3);
                assert_eq!(u, ((pn0 << 32) / pd0) as u32);
                assert_eq!(v, ((pn1 << 32) / pd1) as u32);
                assert_eq!(p.dimension(), 0, "GetPixel2D leaves the counter");
            }
        }
    }
    assert_eq!(seen.len() as u32, w * h * spp);
}

#[test]
fn halton_repeats_every_128_pixels_and_floats_round_the_fractions() {
    for r in [
        Randomization::None,
        Randomization::PermuteDigits,
        Randomization::Owen,
    ] {
        let s = HaltonSampler::new(300, 200, 2, r, 3).unwrap();
        for (x, y) in [(0, 0), (5, 7), (127, 71)] {
            for d in [2usize, 3, 50, 998] {
                let a = s.start_pixel_sample(x, y, 1).unwrap().with_dimension(d);
                let b = s
                    .start_pixel_sample(x + 128, y + 128, 1)
                    .unwrap()
                    .with_dimension(d);
                assert_eq!(a.sample_index(), b.sample_index());
                let (mut a2, mut b2) = (a, b);
                assert_eq!(a2.get_2d(), b2.get_2d(), "{r:?} ({x}, {y}) {d}");
                let (mut a1, mut af) = (a, a);
                let (exact, float) = (a1.get_1d(), af.get_1d_f32());
                let err = (exact as f64 / 2f64.powi(32) - float as f64).abs();
                assert!(err < 1e-6, "{r:?} dim {d}: {exact} vs {float}");
            }
        }
    }
}

#[test]
fn stratified_samples_fill_their_strata() {
    for jitter in [true, false] {
        let s = StratifiedSampler::new(8, 8, 4, 3, jitter, 11).unwrap();
        for (x, y) in [(0, 0), (7, 3)] {
            for d in [0usize, 1, 6] {
                let mut ones = vec![0u32; 12];
                let mut cells = vec![0u32; 12];
                for i in 0..12 {
                    let start = || s.start_pixel_sample(x, y, i).unwrap().with_dimension(d);
                    let v = start().get_1d();
                    ones[((u64::from(v) * 12) >> 32) as usize] += 1;
                    let f = start().get_1d_f32();
                    assert!((f64::from(v) / 2f64.powi(32) - f64::from(f)).abs() < 1e-6);
                    let [a, b] = start().get_2d();
                    let (cx, cy) = ((u64::from(a) * 4) >> 32, (u64::from(b) * 3) >> 32);
                    cells[(cy * 4 + cx) as usize] += 1;
                    if !jitter {
                        // The centre of its stratum, exactly and as pbrt's float.
                        let stratum = (u64::from(v) * 12) >> 32;
                        assert_eq!(u64::from(v), ((stratum << 32) + (1 << 31)) / 12);
                        assert_eq!(f, (stratum as f32 + 0.5) / 12.0);
                    }
                }
                assert_eq!(ones, vec![1; 12], "jitter {jitter} dim {d}");
                assert_eq!(cells, vec![1; 12], "jitter {jitter} dim {d}");
            }
        }
    }
    // pbrt's split of a sample count: 12 = 4 x 3, 7 = 7 x 1, 16 = 4 x 4.
    for (spp, want) in [(12, (4, 3)), (7, (7, 1)), (16, (4, 4))] {
        let s = StratifiedSampler::with_spp(4, 4, spp, true, 0).unwrap();
        assert_eq!(s.strata(), want);
    }
}

#[test]
fn large_seeds_stay_distinct_and_bad_input_is_an_error() {
    let a = HaltonSampler::new(8, 8, 4, Randomization::PermuteDigits, 5).unwrap();
    let b = HaltonSampler::new(8, 8, 4, Randomization::PermuteDigits, 5 + (1 << 32)).unwrap();
    let draw = |s: &HaltonSampler| s.start_pixel_sample(1, 2, 3).unwrap().get_2d();
    assert_ne!(draw(&a), draw(&b));
    let a = StratifiedSampler::new(8, 8, 2, 2, true, 5).unwrap();
    let b = StratifiedSampler::new(8, 8, 2, 2, true, 5 + (1 << 32)).unwrap();
    let draw = |s: &StratifiedSampler| s.start_pixel_sample(1, 2, 3).unwrap().get_2d();
    assert_ne!(draw(&a), draw(&b));

    assert!(matches!(
        HaltonSampler::new(8, 8, 4, Randomization::FastOwen, 0),
        Err(Error::Unsupported { .. })
    ));
    assert!(matches!(
        HaltonSampler::new(0, 8, 4, Randomization::None, 0),
        Err(Error::ZeroPoints)
    ));
    assert!(matches!(
        StratifiedSampler::new(8, 8, 0, 2, true, 0),
        Err(Error::ZeroStrata { dim: 0 })
    ));
    assert!(matches!(
        StratifiedSampler::new(8, 8, 1 << 16, 1 << 16, true, 0),
        Err(Error::TooLarge { .. })
    ));
    assert!(StratifiedSampler::with_spp(8, 8, 0, true, 0).is_err());
    let h = HaltonSampler::new(8, 8, 4, Randomization::None, 0).unwrap();
    assert!(matches!(
        h.start_pixel_sample(0, 0, 4),
        Err(Error::IndexOutOfRange { .. })
    ));
    assert!(h.start_pixel_sample(8, 0, 0).is_err());
    // Any dimension is answered: past the table Halton starts again at dimension 2.
    let mut far = h
        .start_pixel_sample(1, 1, 1)
        .unwrap()
        .with_dimension(usize::MAX);
    let mut two = h.start_pixel_sample(1, 1, 1).unwrap().with_dimension(2);
    assert_eq!(far.get_2d(), two.get_2d());
    let s = StratifiedSampler::new(8, 8, 2, 2, true, 0).unwrap();
    let _ = s
        .start_pixel_sample(7, 7, 3)
        .unwrap()
        .with_dimension(usize::MAX)
        .get_2d();
}
