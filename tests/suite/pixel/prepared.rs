//! The prepared per-pixel fills (`fill_1d`, `fill_2d` and their `f32` forms) against the
//! handle's draws, which the goldens tie to pbrt-v4: every value of every sample, over
//! pixels spread across the image, dimensions from 0 past the wrap points, every
//! randomization, sample counts that are and are not powers of two (and longer than a
//! fill's chunk), and short buffers.

use qmckit::Error;
use qmckit::pixel::{
    BlueNoiseLattice, BlueNoiseSobol, HaltonSampler, ImageSobol, IndependentPixels, PaddedSobol,
    PixelSampler, Pmj02BnTables, Pmj02Pixels, Randomization, StratifiedSampler, ZSobol,
};

const RANDOMIZATIONS: [Randomization; 4] = [
    Randomization::None,
    Randomization::PermuteDigits,
    Randomization::FastOwen,
    Randomization::Owen,
];

/// Dimensions to try: the start, both parities, past ImageSobol's 64-dimension default
/// table and Halton's 1000, and one whose low 32 bits wrap.
const DIMS: [usize; 9] = [0, 1, 2, 3, 7, 63, 64, 999, 1 << 33 | 5];

/// Every fill of `s` at pixel `(x, y)` and each dimension equals the handle, for the
/// full sample count and a short buffer.
fn check<S: PixelSampler>(s: &S, x: u32, y: u32, what: &str) {
    let spp = s.grid().spp;
    for &d in &DIMS {
        for n in [spp, spp.div_ceil(3)] {
            let n = n as usize;
            let (mut a, mut af, mut b, mut bf) =
                (vec![[0; 2]; n], vec![[0.0; 2]; n], vec![0; n], vec![0.0; n]);
            s.fill_2d(x, y, d, &mut a).unwrap();
            s.fill_2d_f32(x, y, d, &mut af).unwrap();
            s.fill_1d(x, y, d, &mut b).unwrap();
            s.fill_1d_f32(x, y, d, &mut bf).unwrap();
            for i in 0..n {
                let h = s
                    .start_pixel_sample(x, y, i as u32)
                    .unwrap()
                    .with_dimension(d);
                let ctx = format!("{what} pixel ({x}, {y}) sample {i} dim {d}");
                assert_eq!(a[i], h.clone().get_2d(), "{ctx} 2d");
                let f = h.clone().get_2d_f32();
                assert_eq!(af[i].map(f32::to_bits), f.map(f32::to_bits), "{ctx} 2d f32");
                assert_eq!(b[i], h.clone().get_1d(), "{ctx} 1d");
                assert_eq!(
                    bf[i].to_bits(),
                    h.clone().get_1d_f32().to_bits(),
                    "{ctx} 1d f32"
                );
            }
        }
    }
}

/// Pixels across a `w x h` image: corners, edges and a hashed spread.
fn pixels(w: u32, h: u32) -> Vec<(u32, u32)> {
    let mut p = vec![(0, 0), (w - 1, 0), (0, h - 1), (w - 1, h - 1)];
    for k in 0..12u64 {
        let r = qmckit::hash::mix64(k + 17);
        p.push(((r as u32) % w, ((r >> 32) as u32) % h));
    }
    p
}

#[test]
fn zsobol_fills_equal_the_handle() {
    // Even and odd log2(spp), one sample, more samples than a chunk; a non-square image.
    for (w, h, spp) in [(37, 21, 16), (16, 16, 8), (9, 5, 1), (6, 7, 2), (5, 3, 256)] {
        for r in RANDOMIZATIONS {
            for seed in [0, 7, 1 << 40] {
                let s = ZSobol::new(w, h, spp, r, seed).unwrap();
                for (x, y) in pixels(w, h) {
                    check(
                        &s,
                        x,
                        y,
                        &format!("zsobol {w}x{h} spp {spp} {r:?} seed {seed}"),
                    );
                }
            }
        }
    }
}

#[test]
fn padded_sobol_fills_equal_the_handle() {
    for (w, h, spp) in [(37, 21, 16), (8, 8, 6), (5, 3, 100), (4, 4, 1)] {
        for r in RANDOMIZATIONS {
            for seed in [0, 3, 1 << 40] {
                let s = PaddedSobol::new(w, h, spp, r, seed).unwrap();
                for (x, y) in pixels(w, h) {
                    check(
                        &s,
                        x,
                        y,
                        &format!("padded {w}x{h} spp {spp} {r:?} seed {seed}"),
                    );
                }
            }
        }
    }
}

#[test]
fn image_sobol_fills_equal_the_handle() {
    for (w, h, spp) in [(37, 21, 16), (8, 8, 6), (5, 3, 100), (1, 1, 4), (300, 3, 2)] {
        for r in RANDOMIZATIONS {
            for seed in [0, 3, 1 << 40] {
                let s = ImageSobol::new(w, h, spp, r, seed).unwrap();
                for (x, y) in pixels(w, h) {
                    check(
                        &s,
                        x,
                        y,
                        &format!("image {w}x{h} spp {spp} {r:?} seed {seed}"),
                    );
                }
            }
        }
    }
}

#[test]
fn pmj_fills_equal_the_handle() {
    for spp in [16, 6, 1] {
        let tables = Pmj02BnTables::new(spp, 3).unwrap();
        for (w, h) in [(37, 21), (130, 2)] {
            for seed in [0, 5, 1 << 40] {
                let s = tables.sampler(w, h, seed).unwrap();
                for (x, y) in pixels(w, h) {
                    check(&s, x, y, &format!("pmj02bn {w}x{h} spp {spp} seed {seed}"));
                }
            }
        }
        let s = Pmj02Pixels::new(37, 21, spp, 9).unwrap();
        for (x, y) in pixels(37, 21) {
            check(&s, x, y, &format!("pmj02 spp {spp}"));
        }
    }
    // Several passes of 16, a short last pass, and the whole table.
    for spp in [256, 257, 300, 1 << 16] {
        let s = Pmj02Pixels::new(5, 3, spp, 9).unwrap();
        for (x, y) in [(0, 0), (4, 2)] {
            check(&s, x, y, &format!("pmj02 spp {spp}"));
        }
    }
}

#[test]
fn halton_stratified_independent_fills_equal_the_handle() {
    for (w, h, spp) in [(37, 21, 16), (200, 130, 3), (4, 4, 1)] {
        for r in [
            Randomization::None,
            Randomization::PermuteDigits,
            Randomization::Owen,
        ] {
            for seed in [0, 3, 1 << 40] {
                let s = HaltonSampler::new(w, h, spp, r, seed).unwrap();
                for (x, y) in pixels(w, h) {
                    check(
                        &s,
                        x,
                        y,
                        &format!("halton {w}x{h} spp {spp} {r:?} seed {seed}"),
                    );
                }
            }
        }
    }
    for (xs, ys) in [(4, 4), (3, 2), (1, 1), (5, 1)] {
        for jitter in [true, false] {
            for seed in [0, 3, 1 << 40] {
                let s = StratifiedSampler::new(37, 21, xs, ys, jitter, seed).unwrap();
                for (x, y) in pixels(37, 21) {
                    check(
                        &s,
                        x,
                        y,
                        &format!("stratified {xs}x{ys} {jitter} seed {seed}"),
                    );
                }
            }
        }
    }
    let s = IndependentPixels::new(37, 21, 16, 3).unwrap();
    for (x, y) in pixels(37, 21) {
        check(&s, x, y, "independent");
    }
}

#[test]
fn blue_noise_fills_equal_the_handle() {
    for spp in [1, 5, 16, 100] {
        let s = BlueNoiseSobol::new(70, 33, spp, 9).unwrap();
        let l = BlueNoiseLattice::new(70, 33, spp, 9).unwrap();
        for (x, y) in pixels(70, 33) {
            check(&s, x, y, "bn-sobol");
            check(&l, x, y, "bn-lattice");
        }
    }
}

#[test]
fn fills_check_the_pixel_and_the_length() {
    let s = ZSobol::new(16, 9, 4, Randomization::FastOwen, 0).unwrap();
    let mut out = [[0u32; 2]; 5];
    assert!(matches!(
        s.fill_2d(0, 0, 0, &mut out),
        Err(Error::BufferLength {
            expected: 4,
            got: 5
        })
    ));
    assert!(s.fill_2d(16, 0, 0, &mut out[..4]).is_err());
    assert!(s.fill_2d(0, 9, 0, &mut out[..4]).is_err());
    let p = PaddedSobol::new(16, 9, 4, Randomization::FastOwen, 0).unwrap();
    assert!(p.fill_1d(0, 0, 0, &mut [0u32; 5]).is_err());
    assert!(p.fill_1d(0, 0, 0, &mut []).is_ok());
}

/// Every catalog pixel sampler, boxed as the command and the Python package build it: its
/// fills (forwarded to the prepared paths, or the trait's defaults) equal its handle.
#[test]
fn boxed_catalog_samplers_fill_as_their_handles() {
    use qmckit::catalog::{self, PixelParams};
    for entry in catalog::PIXEL_SAMPLERS {
        let p = PixelParams {
            width: 8,
            height: 4,
            spp: 16,
            seed: 5,
        };
        let s = catalog::build_pixel(entry, None, &p).unwrap();
        for (x, y) in [(0, 0), (7, 3), (3, 1)] {
            check(&s, x, y, entry.name);
        }
    }
}
