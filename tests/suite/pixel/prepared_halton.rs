//! `PreparedHalton` (the Halton pixel sampler with tabulated digit groups) against the
//! plain `HaltonSampler`, whose draws the goldens tie to pbrt-v4: fills and handles, every
//! randomization, seeds below and above `2^32`, dimensions inside, at the edge of and past
//! the tabulated ones, and Halton indices past `2^32` (the quotients by division).

use qmckit::Error;
use qmckit::pixel::{HaltonSampler, PixelSampler, PreparedHalton, Randomization};

/// Fills and handles of `p` equal the handle of its sampler at pixel `(x, y)`, dimension
/// `d`, for the first `n` samples.
fn same(p: &PreparedHalton, x: u32, y: u32, d: usize, n: usize, what: &str) {
    let s = p.sampler();
    let (mut a, mut af, mut b, mut bf) =
        (vec![[0; 2]; n], vec![[0.0; 2]; n], vec![0; n], vec![0.0; n]);
    p.fill_2d(x, y, d, &mut a).unwrap();
    p.fill_2d_f32(x, y, d, &mut af).unwrap();
    p.fill_1d(x, y, d, &mut b).unwrap();
    p.fill_1d_f32(x, y, d, &mut bf).unwrap();
    for i in 0..n {
        let want = s
            .start_pixel_sample(x, y, i as u32)
            .unwrap()
            .with_dimension(d);
        let got = p
            .start_pixel_sample(x, y, i as u32)
            .unwrap()
            .with_dimension(d);
        let ctx = format!("{what} pixel ({x}, {y}) sample {i} dim {d}");
        let w2 = want.clone().get_2d();
        let w2f = want.clone().get_2d_f32().map(f32::to_bits);
        let w1 = want.clone().get_1d();
        let w1f = want.clone().get_1d_f32().to_bits();
        assert_eq!(a[i], w2, "{ctx} fill 2d");
        assert_eq!(af[i].map(f32::to_bits), w2f, "{ctx} fill 2d f32");
        assert_eq!(b[i], w1, "{ctx} fill 1d");
        assert_eq!(bf[i].to_bits(), w1f, "{ctx} fill 1d f32");
        assert_eq!(got.clone().get_2d(), w2, "{ctx} handle 2d");
        assert_eq!(
            got.clone().get_2d_f32().map(f32::to_bits),
            w2f,
            "{ctx} handle 2d f32"
        );
        assert_eq!(got.clone().get_1d(), w1, "{ctx} handle 1d");
        assert_eq!(
            got.clone().get_1d_f32().to_bits(),
            w1f,
            "{ctx} handle 1d f32"
        );
        assert_eq!(
            got.clone().get_pixel_2d_f32().map(f32::to_bits),
            want.clone().get_pixel_2d_f32().map(f32::to_bits),
            "{ctx} pixel 2d"
        );
    }
}

#[test]
fn prepared_halton_equals_the_sampler() {
    // Dimensions: the start, the last tabulated (40 tables: 2 ..= 39), the pair across the
    // edge, past it, the wrap at 1000.
    let dims = [0, 1, 2, 5, 38, 39, 40, 170, 999, 1 << 33 | 5];
    for (w, h, spp) in [(37, 21, 16), (200, 130, 3), (4, 4, 1), (128, 243, 70)] {
        for r in [
            Randomization::None,
            Randomization::PermuteDigits,
            Randomization::Owen,
        ] {
            for seed in [0, 3, 1 << 40] {
                let p = PreparedHalton::new(HaltonSampler::new(w, h, spp, r, seed).unwrap(), 40)
                    .unwrap();
                for (x, y) in [(0, 0), (w - 1, h - 1), (w / 3, h / 2)] {
                    for &d in &dims {
                        let what = format!("{w}x{h} spp {spp} {r:?} seed {seed}");
                        same(&p, x, y, d, spp as usize, &what);
                    }
                }
            }
        }
    }
}

#[test]
fn prepared_halton_tabulates_every_dimension() {
    // All 1000 dimensions, the largest bases included (groups of one digit, b > 4096).
    for r in [Randomization::PermuteDigits, Randomization::Owen] {
        let p = PreparedHalton::new(HaltonSampler::new(64, 64, 4, r, 11).unwrap(), 1000).unwrap();
        for d in [2, 100, 171, 172, 563, 564, 997, 998] {
            same(&p, 9, 50, d, 4, &format!("{r:?}"));
        }
    }
}

#[test]
fn prepared_halton_past_2_32() {
    // 128 x 243 pixels: stride 2^7 3^5 = 31104, so sample 140000 has a Halton index past
    // 2^32 and the fill takes the division path.
    let spp = 140_000;
    for r in [Randomization::PermuteDigits, Randomization::Owen] {
        let s = HaltonSampler::new(128, 243, spp, r, 5).unwrap();
        let p = PreparedHalton::new(s, 8).unwrap();
        let n = spp as usize;
        let (mut a, mut af) = (vec![[0; 2]; n], vec![[0.0f32; 2]; n]);
        p.fill_2d(3, 7, 4, &mut a).unwrap();
        p.fill_2d_f32(3, 7, 4, &mut af).unwrap();
        for i in [0, 1, 138_000, 138_100, 139_999] {
            let key = s
                .start_pixel_sample(3, 7, i)
                .unwrap()
                .sample_index()
                .unwrap();
            let want = s.start_pixel_sample(3, 7, i).unwrap().with_dimension(4);
            assert_eq!(
                a[i as usize],
                want.clone().get_2d(),
                "{r:?} sample {i} ({key})"
            );
            assert_eq!(
                af[i as usize].map(f32::to_bits),
                want.clone().get_2d_f32().map(f32::to_bits),
                "{r:?} sample {i}"
            );
            let got = p.start_pixel_sample(3, 7, i).unwrap().with_dimension(4);
            assert_eq!(got.clone().get_2d(), want.clone().get_2d());
        }
        assert!(
            s.start_pixel_sample(3, 7, 139_999)
                .unwrap()
                .sample_index()
                .unwrap()
                > 1 << 32
        );
    }
}

#[test]
fn prepared_halton_refuses_too_many_dimensions_and_checks_fills() {
    let s = HaltonSampler::new(8, 8, 4, Randomization::PermuteDigits, 0).unwrap();
    assert!(matches!(
        PreparedHalton::new(s, 1001),
        Err(Error::TooLarge { max: 1000, .. })
    ));
    let p = PreparedHalton::new(s, 0).unwrap();
    same(&p, 1, 1, 3, 4, "no tables");
    let p = PreparedHalton::new(s, 10).unwrap();
    assert!(p.fill_2d(8, 0, 2, &mut [[0; 2]; 4]).is_err());
    assert!(p.fill_1d_f32(0, 0, 2, &mut [0.0; 5]).is_err());
    assert!(p.fill_1d_f32(0, 0, 2, &mut []).is_ok());
}
