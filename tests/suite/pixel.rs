//! The pixel samplers against pbrt-v4's definitions: the check values pbrt gives, the golden
//! file tests/golden/pbrt_samplers.txt (made by tests/golden/gen_pbrt_samplers.py, an
//! independent Python reading of pbrt's code that brute-forces SobolIntervalToIndex), and
//! the properties pbrt's own tests state (aligned, unique index blocks; per-pixel nets).
//! `compiled` checks every draw of the goldens printed by pbrt-v4's own sampler classes
//! (tests/golden/pbrt_samplers_compiled.txt, tests/golden/pbrt_harness/).

// pbrt's check values are quoted as published, with 9 significant digits.
#![allow(clippy::excessive_precision)]

mod blue_noise;
mod compiled;
mod domain;
mod halton_stratified;
mod pmj02bn_pixels;
mod pmj_pixels;
mod prepared;
mod prepared_halton;

use crate::common::first_net_failure;
use qmckit::Error;
use qmckit::hash::pbrt::{hash2, hash4, mix_bits, permutation_element};
use qmckit::pixel::{
    ImageSobol, IndependentPixels, PaddedSobol, PixelSample, PixelSampler, Pmj02Pixels,
    Randomization, ZSobol, pbrt_f32,
};
use qmckit::randomize::{FastOwenScrambler, OwenHash, PbrtOwenScrambler};

const ALL: [Randomization; 4] = [
    Randomization::None,
    Randomization::PermuteDigits,
    Randomization::FastOwen,
    Randomization::Owen,
];

fn randomization(name: &str) -> Randomization {
    match name {
        "none" => Randomization::None,
        "xor" => Randomization::PermuteDigits,
        "fastowen" => Randomization::FastOwen,
        "owen" => Randomization::Owen,
        _ => panic!("unknown randomization {name}"),
    }
}

/// The tests' shorthand for one draw at a given counter: `start_pixel_sample(x, y, i)`, then
/// `with_dimension(d)`, then the draw (the `Result` is the start's).
pub(crate) trait Draw {
    fn at(&self, x: u32, y: u32, i: u32, d: usize) -> Result<PixelSample<'_, Self>, Error>
    where
        Self: PixelSampler;
    fn get_1d(&self, x: u32, y: u32, i: u32, d: usize) -> Result<u32, Error>
    where
        Self: PixelSampler,
    {
        Ok(self.at(x, y, i, d)?.get_1d())
    }
    fn get_2d(&self, x: u32, y: u32, i: u32, d: usize) -> Result<[u32; 2], Error>
    where
        Self: PixelSampler,
    {
        Ok(self.at(x, y, i, d)?.get_2d())
    }
    fn get_pixel_2d(&self, x: u32, y: u32, i: u32, d: usize) -> Result<[u32; 2], Error>
    where
        Self: PixelSampler,
    {
        Ok(self.at(x, y, i, d)?.get_pixel_2d())
    }
    fn get_1d_f32(&self, x: u32, y: u32, i: u32, d: usize) -> Result<f32, Error>
    where
        Self: PixelSampler,
    {
        Ok(self.at(x, y, i, d)?.get_1d_f32())
    }
    fn get_2d_f32(&self, x: u32, y: u32, i: u32, d: usize) -> Result<[f32; 2], Error>
    where
        Self: PixelSampler,
    {
        Ok(self.at(x, y, i, d)?.get_2d_f32())
    }
    fn get_pixel_2d_f32(&self, x: u32, y: u32, i: u32, d: usize) -> Result<[f32; 2], Error>
    where
        Self: PixelSampler,
    {
        Ok(self.at(x, y, i, d)?.get_pixel_2d_f32())
    }
    fn index_at(&self, x: u32, y: u32, i: u32, d: usize) -> Result<Option<u64>, Error>
    where
        Self: PixelSampler,
    {
        Ok(self.at(x, y, i, d)?.sample_index())
    }
}

impl<S: PixelSampler> Draw for S {
    fn at(&self, x: u32, y: u32, i: u32, d: usize) -> Result<PixelSample<'_, Self>, Error> {
        Ok(self.start_pixel_sample(x, y, i)?.with_dimension(d))
    }
}

fn hex(s: &str) -> u64 {
    u64::from_str_radix(s, 16).unwrap_or_else(|e| panic!("{s}: {e}"))
}

#[test]
fn pbrt_hash_check_values() {
    assert_eq!(hash2(0, 0), 0x7208_f7fa_198a_2d81);
    assert_eq!(hash2(1, 0), 0x8fbb_8d81_5c9e_092e);
    assert_eq!(hash2(3, 7), 0x7ddd_e854_6997_7f6a);
    assert_eq!(hash4(3, 5, 0, 0), 0xd539_d46e_d315_9a89);
    assert_eq!(mix_bits(1), 0xccde_22c1_faa4_d20f);
    assert_eq!(permutation_element(3, 16, 0x1234_5678), 12);
    assert_eq!(permutation_element(5, 7, 42), 3);
    let fast = FastOwenScrambler::from_key(0x1234_5678, OwenHash::Vegdahl);
    assert_eq!(fast.scramble(0x8000_0000), 0x87e3_2b06);
    assert_eq!(
        PbrtOwenScrambler::new(0x1234_5678).scramble(0x8000_0000),
        0xbf7f_d854
    );
}

#[test]
fn zsobol_pbrt_check_values() {
    let z = ZSobol::new(16, 9, 1, Randomization::FastOwen, 0).unwrap();
    assert_eq!(z.index_at(1, 0, 0, 0).unwrap(), Some(1));
    assert_eq!(z.get_1d_f32(1, 0, 0, 0).unwrap(), 0.570_228_934);
    assert_eq!(
        z.get_2d_f32(1, 0, 0, 0).unwrap(),
        [0.702_183_783, 0.853_890_479]
    );
    let z = ZSobol::new(16, 9, 4, Randomization::FastOwen, 0).unwrap();
    assert_eq!(z.index_at(1, 0, 3, 0).unwrap(), Some(4));
    assert_eq!(z.get_1d_f32(1, 0, 3, 0).unwrap(), 0.336_978_048);
}

#[test]
fn padded_sobol_pbrt_check_values() {
    let p = PaddedSobol::new(16, 16, 16, Randomization::None, 0).unwrap();
    assert_eq!(p.get_1d_f32(3, 5, 0, 0).unwrap(), 0.5625);
    assert_eq!(p.get_2d_f32(3, 5, 0, 0).unwrap(), [0.5625, 0.4375]);
    assert_eq!(p.get_2d_f32(3, 5, 1, 2).unwrap(), [0.75, 0.25]);
    assert_eq!(p.get_2d_f32(3, 5, 15, 7).unwrap(), [0.0625, 0.9375]);
    let p = PaddedSobol::new(16, 16, 16, Randomization::FastOwen, 0).unwrap();
    assert_eq!(p.get_1d_f32(3, 5, 0, 0).unwrap(), 0.773_123_562);
    assert_eq!(
        p.get_2d_f32(3, 5, 0, 0).unwrap(),
        [0.172_279, 0.043_057_885]
    );
    assert_eq!(p.get_1d_f32(3, 5, 5, 2).unwrap(), 0.537_301_898);
    assert_eq!(
        p.get_2d_f32(3, 5, 5, 2).unwrap(),
        [0.243_017_271, 0.191_734_999]
    );
}

/// Every line of the golden file, value for value and float bit for float bit.
#[test]
fn golden_pbrt_samplers() {
    let path = format!(
        "{}/tests/golden/pbrt_samplers.txt",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut counts = [0usize; 3];
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let f: Vec<&str> = line.split_whitespace().collect();
        let n = |k: usize| f[k].parse::<u32>().unwrap();
        let (w, h, spp, seed, r) = (n(1), n(2), n(3), n(4) as u64, randomization(f[5]));
        let (px, py, i, dim) = (n(6), n(7), n(8), n(9) as usize);
        let index = hex(f[10]);
        let want: Vec<u32> = f[11..].iter().map(|s| hex(s) as u32).collect();
        let s: Box<dyn PixelSampler> = match f[0] {
            "zsobol" => Box::new(ZSobol::new(w, h, spp, r, seed).unwrap()),
            "padded" => Box::new(PaddedSobol::new(w, h, spp, r, seed).unwrap()),
            "sobol" => Box::new(ImageSobol::new(w, h, spp, r, seed).unwrap()),
            other => panic!("unknown sampler {other}"),
        };
        let got_1d = s.get_1d(px, py, i, dim).unwrap();
        let got_2d = s.get_2d(px, py, i, dim).unwrap();
        assert_eq!([got_1d, got_2d[0], got_2d[1]], want[..3], "{line}");
        match f[0] {
            "sobol" => {
                counts[2] += 1;
                assert_eq!(s.index_at(px, py, i, dim).unwrap(), Some(index), "{line}");
                let pix = s.get_pixel_2d_f32(px, py, i, dim).unwrap();
                assert_eq!([pix[0].to_bits(), pix[1].to_bits()], want[3..5], "{line}");
            }
            kind => {
                if kind == "zsobol" {
                    counts[0] += 1;
                    assert_eq!(s.index_at(px, py, i, dim).unwrap(), Some(index), "{line}");
                } else {
                    counts[1] += 1;
                }
                let f1 = s.get_1d_f32(px, py, i, dim).unwrap().to_bits();
                let f2 = s.get_2d_f32(px, py, i, dim).unwrap().map(f32::to_bits);
                assert_eq!([f1, f2[0], f2[1]], want[3..6], "{line}");
            }
        }
    }
    assert!(counts.iter().all(|&c| c >= 100), "{counts:?}");
}

/// pbrt's quirk: Get1D at dimension d uses the index of d but the scramble of Hash(d + 1).
#[test]
fn zsobol_get1d_hashes_the_incremented_dimension() {
    let z = ZSobol::new(8, 8, 4, Randomization::PermuteDigits, 3).unwrap();
    let none = ZSobol::new(8, 8, 4, Randomization::None, 3).unwrap();
    for d in 0..6 {
        let plain = none.get_1d(2, 5, 1, d).unwrap();
        let key = hash2(d as u32 + 1, 3) as u32;
        assert_eq!(z.get_1d(2, 5, 1, d).unwrap(), plain ^ key);
        let idx = none.index_at(2, 5, 1, d).unwrap().unwrap();
        assert_eq!(plain, (idx as u32).reverse_bits());
    }
}

/// pbrt's `ZSobolSampler.ValidIndices`-style check: each pixel's spp indices are one aligned
/// block, and the blocks of distinct pixels are distinct.
#[test]
fn zsobol_blocks_are_aligned_and_unique() {
    for log2_spp in 0..=10u32 {
        let spp = 1 << log2_spp;
        let (w, h) = (16u32, 9u32);
        let z = ZSobol::new(w, h, spp, Randomization::FastOwen, 0).unwrap();
        for dim in [0usize, 3, 6] {
            let mut blocks = std::collections::HashSet::new();
            for y in 0..h {
                for x in 0..w {
                    let idx: Vec<u64> = (0..spp)
                        .map(|i| z.index_at(x, y, i, dim).unwrap().unwrap())
                        .collect();
                    let block = idx[0] >> log2_spp;
                    let mut low: Vec<u64> = idx
                        .iter()
                        .map(|&v| {
                            assert_eq!(v >> log2_spp, block, "spp {spp} dim {dim} ({x},{y})");
                            v & (spp as u64 - 1)
                        })
                        .collect();
                    low.sort_unstable();
                    assert!(low.iter().enumerate().all(|(k, &v)| v == k as u64));
                    assert!(blocks.insert(block), "block reused: spp {spp} ({x},{y})");
                }
            }
        }
    }
}

/// Unscrambled or XOR-scrambled, every pixel's spp pixel samples are a (0, m, 2)-net
/// (pbrt's `ZSobolSampler.ElementaryIntervals`); PaddedSobol's too, for every scramble,
/// and PMJ02 pixels'.
#[test]
fn per_pixel_samples_are_nets() {
    for seed in [0u64, 1, 5, 6, 10, 15] {
        for m in 2..=8u32 {
            let spp = 1 << m;
            for r in [Randomization::None, Randomization::PermuteDigits] {
                let z = ZSobol::new(10, 10, spp, r, seed).unwrap();
                for (x, y) in [(0, 0), (3, 7), (9, 9), (5, 2)] {
                    let pts: Vec<[u32; 2]> =
                        (0..spp).map(|i| z.get_2d(x, y, i, 0).unwrap()).collect();
                    assert_eq!(first_net_failure(&pts, m), None, "{r:?} seed {seed} m {m}");
                }
            }
            for r in ALL {
                let p = PaddedSobol::new(10, 10, spp, r, seed).unwrap();
                let d = 2 * m as usize;
                let pts: Vec<[u32; 2]> = (0..spp).map(|i| p.get_2d(4, 6, i, d).unwrap()).collect();
                assert_eq!(first_net_failure(&pts, m), None, "padded {r:?} seed {seed}");
            }
            let q = Pmj02Pixels::new(10, 10, spp, seed).unwrap();
            let d = m as usize;
            let pts: Vec<[u32; 2]> = (0..spp).map(|i| q.get_2d(7, 1, i, d).unwrap()).collect();
            assert_eq!(first_net_failure(&pts, m), None, "pmj02 pixels seed {seed}");
        }
    }
}

/// SobolIntervalToIndex by the computed matrices equals the brute-force search, and the
/// indices tile the image: frame f holds exactly one index per pixel of the 2^m grid.
#[test]
fn image_sobol_index_is_the_brute_force_one() {
    for (w, h) in [(1u32, 1u32), (2, 2), (5, 3), (16, 9), (33, 20)] {
        let s = ImageSobol::new(w, h, 4, Randomization::None, 0).unwrap();
        let side = w.max(h).next_power_of_two();
        let m = side.trailing_zeros();
        for frame in 0..4u32 {
            let mut seen = std::collections::HashMap::new();
            for l in 0..(1u64 << (2 * m)) {
                let i = ((frame as u64) << (2 * m)) | l;
                let x = if m == 0 {
                    0
                } else {
                    (i as u32).reverse_bits() >> (32 - m)
                };
                let y = if m == 0 {
                    0
                } else {
                    qmckit::pixel::sobol1(i) >> (32 - m)
                };
                assert!(seen.insert((x, y), i).is_none(), "two indices in one pixel");
            }
            for y in 0..h {
                for x in 0..w {
                    assert_eq!(
                        s.index_at(x, y, frame, 0).unwrap(),
                        Some(seen[&(x, y)]),
                        "{w}x{h} frame {frame} ({x},{y})"
                    );
                    let [u, v] = s.get_pixel_2d_f32(x, y, frame, 0).unwrap();
                    assert!((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v));
                }
            }
        }
    }
}

#[test]
fn handle_consumes_dimensions_like_pbrt() {
    let z = ZSobol::new(16, 9, 4, Randomization::FastOwen, 0).unwrap();
    let mut s = z.start_pixel_sample(1, 0, 3).unwrap();
    let p = s.get_pixel_2d();
    let a = s.get_1d();
    let b = s.get_2d();
    assert_eq!(p, z.get_2d(1, 0, 3, 0).unwrap());
    assert_eq!(a, z.get_1d(1, 0, 3, 2).unwrap());
    assert_eq!(b, z.get_2d(1, 0, 3, 3).unwrap());
    assert_eq!(s.dimension(), 5);
    let img = ImageSobol::new(16, 9, 4, Randomization::FastOwen, 0).unwrap();
    let mut s = img.start_pixel_sample(1, 0, 3).unwrap();
    s.get_pixel_2d();
    assert_eq!(s.dimension(), 0); // the image-plane dimensions are outside the counter
    assert_eq!(s.get_1d(), img.get_1d(1, 0, 3, 2).unwrap());
    assert_eq!(s.dimension(), 3); // the counter read as 2, then moved past it
}

#[test]
fn bad_input_is_an_error() {
    assert_eq!(
        ZSobol::new(16, 9, 3, Randomization::None, 0),
        Err(Error::NotPowerOfTwo { n: 3 })
    );
    assert_eq!(
        ZSobol::new(0, 9, 4, Randomization::None, 0),
        Err(Error::ZeroPoints)
    );
    assert!(matches!(
        ZSobol::new(1 << 30, 1 << 30, 1 << 8, Randomization::None, 0),
        Err(Error::TooLarge { .. })
    ));
    assert!(ZSobol::new(1 << 30, 1 << 30, 1 << 4, Randomization::None, 0).is_ok());
    assert!(matches!(
        ImageSobol::new(1 << 16, 1, 2, Randomization::None, 0),
        Err(Error::TooLarge { .. })
    ));
    let z = ZSobol::new(16, 9, 4, Randomization::None, 0).unwrap();
    assert!(matches!(
        z.get_1d(16, 0, 0, 0),
        Err(Error::InvalidParameter { .. })
    ));
    assert!(matches!(
        z.get_1d(0, 9, 0, 0),
        Err(Error::InvalidParameter { .. })
    ));
    assert_eq!(
        z.get_2d(0, 0, 4, 0),
        Err(Error::IndexOutOfRange { index: 4, len: 4 })
    );
    let p = PaddedSobol::new(4, 4, 6, Randomization::None, 0).unwrap();
    assert!(p.get_1d(0, 0, 5, 0).is_ok()); // any spp for the padded sampler
    let s = ImageSobol::new(16, 9, 4, Randomization::None, 0).unwrap();
    // Every dimension is answered: past the table the counter wraps to 2, as in pbrt.
    assert_eq!(
        s.get_1d(0, 0, 0, 1_000_000).unwrap(),
        s.get_1d(0, 0, 0, 2).unwrap()
    );
}

#[test]
fn independent_pixels_are_uniform_and_decorrelated() {
    let s = IndependentPixels::new(64, 64, 4, 9).unwrap();
    let mut sum = 0.0;
    let mut n = 0.0;
    for y in 0..64 {
        for x in 0..64 {
            for i in 0..4 {
                sum += pbrt_f32(s.get_1d(x, y, i, 0).unwrap()) as f64;
                n += 1.0;
            }
        }
    }
    assert!((sum / n - 0.5).abs() < 0.01, "{}", sum / n);
    assert_ne!(s.get_2d(0, 0, 0, 0).unwrap(), s.get_2d(0, 0, 0, 1).unwrap());
}

/// ZSobol's error is blue: at 1, 4 and 16 spp, its low-frequency error power (below a
/// quarter of Nyquist) against per-pixel independently scrambled Sobol' (PaddedSobol, the
/// same per-pixel nets without the Morton ordering), averaged over 16 seeds, 128 x 128
/// pixels. Measured (ratio of low-band power, ratio of RMSE): Gaussian 0.26/1.00,
/// 0.20/1.11, 0.10/0.79; step 0.28/1.00, 0.39/0.99, 0.41/1.03 at 1, 4, 16 spp. The bound is
/// 0.35 except for the step at 4 and 16 spp, where pbrt's ZSobol reaches about 0.4; the
/// RMSE within 15%. Independent pixels are white (normalized low band near 1). Against
/// independent random samples in every pixel (pbrt's IndependentSampler) ZSobol's low band
/// is at most 0.35 at every spp, with an RMSE no larger (printed, asserted).
#[cfg(feature = "analysis")]
#[test]
fn zsobol_error_is_blue_noise() {
    use qmckit::analysis::screen_error::{PixelIntegrand, screen_error};
    use qmckit::work::Budget;
    const SEEDS: u32 = 16;
    let mut report = String::new();
    for f in [PixelIntegrand::GaussianBump, PixelIntegrand::Step] {
        for spp in [1u32, 4, 16] {
            let (mut z, mut p, mut ind) = ([0.0; 3], [0.0; 3], [0.0; 3]);
            for seed in 0..SEEDS {
                let seed = seed as u64;
                let zs = ZSobol::new(128, 128, spp, Randomization::FastOwen, seed).unwrap();
                let ps = PaddedSobol::new(128, 128, spp, Randomization::FastOwen, seed).unwrap();
                let is = IndependentPixels::new(128, 128, spp, seed).unwrap();
                for (acc, e) in [
                    (&mut z, screen_error(&zs, f, &Budget::UNLIMITED).unwrap()),
                    (&mut p, screen_error(&ps, f, &Budget::UNLIMITED).unwrap()),
                    (&mut ind, screen_error(&is, f, &Budget::UNLIMITED).unwrap()),
                ] {
                    acc[0] += e.rmse * e.rmse / SEEDS as f64;
                    acc[1] += e.low_band_absolute / SEEDS as f64;
                    acc[2] += e.low_band / SEEDS as f64;
                }
            }
            let ratio = z[1] / p[1];
            let rmse = (z[0] / p[0]).sqrt();
            report += &format!(
                "{f:?} spp {spp}: low-band power ZSobol/PaddedSobol {ratio:.3}, RMSE ratio \
                 {rmse:.3}, normalized low band z {:.3} padded {:.3} independent {:.3}\n",
                z[2], p[2], ind[2]
            );
            let bound = if f == PixelIntegrand::Step && spp > 1 {
                0.45
            } else {
                0.35
            };
            assert!(ratio <= bound, "{report}");
            assert!(rmse <= 1.15, "{report}");
            // The bar, against independent per-pixel sampling (pbrt's
            // IndependentSampler): at most 0.35 of its low band, its RMSE or better.
            let (vs_ind, rmse_ind) = (z[1] / ind[1], (z[0] / ind[0]).sqrt());
            report += &format!("  against independent: low band {vs_ind:.3}, RMSE {rmse_ind:.3}\n");
            assert!(vs_ind <= 0.35, "{report}");
            assert!(rmse_ind <= 1.02, "{report}");
            assert!((0.8..1.2).contains(&ind[2]), "{report}");
            assert!((0.8..1.2).contains(&p[2]), "{report}");
        }
    }
    println!("{report}");
}

/// The fixed-size hashes equal MurmurHash64A of their packed bytes.
#[test]
fn word_hashes_equal_the_byte_hash() {
    use qmckit::hash::pbrt::murmur_hash64a;
    for (a, b, c, d) in [
        (0u32, 0u32, 0u32, 0u32),
        (3, 5, 7, 11),
        (u32::MAX, 1, 1 << 31, 99),
    ] {
        let mut bytes = [0u8; 16];
        for (k, v) in [a, b, c, d].into_iter().enumerate() {
            bytes[4 * k..4 * k + 4].copy_from_slice(&v.to_le_bytes());
        }
        assert_eq!(hash2(a, b), murmur_hash64a(&bytes[..8], 0));
        assert_eq!(hash4(a, b, c, d), murmur_hash64a(&bytes, 0));
    }
}

/// Sobol' dimension 1 by the 5-step subset-XOR transform equals the Pascal-matrix product
/// column by column (`bits::gf2_mul` with columns `c_{k+1} = c_k ^ (c_k >> 1)`).
#[test]
fn sobol1_is_the_pascal_matrix_product() {
    use qmckit::bits::gf2_mul;
    use qmckit::pixel::sobol1;
    let mut cols = [0u32; 32];
    let mut c = 1u32 << 31;
    for col in cols.iter_mut() {
        *col = c;
        c ^= c >> 1;
    }
    let mut x = 0x1234_5678_9abc_def0u64;
    for k in 0..100_000u64 {
        x = qmckit::hash::mix64(x ^ k);
        let want = gf2_mul(&cols, x as u32) ^ gf2_mul(&cols, (x >> 32) as u32);
        assert_eq!(sobol1(x), want, "{x:#x}");
        assert_eq!(sobol1(k), gf2_mul(&cols, k as u32));
    }
}

/// The prepared pixel-and-dimension path of ZSobol is bit-identical to the random-access
/// one (odd and even log2 spp, an image whose indices pass 2^32, all randomizations).
#[test]
fn zsobol_prepared_dimension_is_identical() {
    for (w, h, spp) in [
        (16u32, 9u32, 1u32),
        (16, 9, 2),
        (256, 256, 16),
        (3840, 2160, 1024),
        (7, 5, 8),
    ] {
        for r in ALL {
            let z = ZSobol::new(w, h, spp, r, 5).unwrap();
            for (x, y) in [(0, 0), (w - 1, h - 1), (w / 2, h / 3)] {
                for dim in [0usize, 1, 2, 5, 1000, (1 << 32) + 5] {
                    let d = z.pixel_dimension(x, y, dim).unwrap();
                    for i in (0..spp).step_by((spp as usize / 64).max(1)) {
                        assert_eq!(Some(d.sample_index(i)), z.index_at(x, y, i, dim).unwrap());
                        assert_eq!(d.get_1d(i), z.get_1d(x, y, i, dim).unwrap());
                        assert_eq!(d.get_2d(i), z.get_2d(x, y, i, dim).unwrap());
                    }
                }
            }
        }
    }
}

/// The screen-space error study behind docs/pixel-samplers.md (one run, numbers printed):
/// image sides 64, 128 and 256, 16 seeds (8 at 256), the Gaussian, the fixed step and the
/// moving "visibility" step, ZSobol against PaddedSobol (per-pixel independent Owen-Sobol'),
/// independent random pixels and the PMJ02BN pixel sampler. Run with
/// `cargo test --release --all-features --test suite screen_error_study -- --ignored --nocapture`.
#[cfg(feature = "analysis")]
#[test]
#[ignore = "a study: about a minute; prints the table of docs/pixel-samplers.md"]
fn screen_error_study() {
    use qmckit::analysis::screen_error::{PixelIntegrand, screen_error};
    use qmckit::pixel::Pmj02BnTables;
    use qmckit::work::Budget;
    println!(
        "side f spp | low Z/P  low Z/I  low B/P | rmse Z/P rmse Z/I rmse B/P | norm low Z P I B"
    );
    for side in [64u32, 128, 256] {
        let seeds: u32 = if side == 256 { 8 } else { 16 };
        for spp in [1u32, 4, 16] {
            let tables: Vec<Pmj02BnTables> = (0..seeds)
                .map(|s| Pmj02BnTables::new(spp, s as u64).unwrap())
                .collect();
            for f in [
                PixelIntegrand::GaussianBump,
                PixelIntegrand::Step,
                PixelIntegrand::Visibility,
            ] {
                // [rmse^2, absolute low band, normalized low band] for Z, P, I, B.
                let mut acc = [[0.0f64; 3]; 4];
                for seed in 0..seeds {
                    let seed = seed as u64;
                    let r = Randomization::FastOwen;
                    let z = ZSobol::new(side, side, spp, r, seed).unwrap();
                    let p = PaddedSobol::new(side, side, spp, r, seed).unwrap();
                    let i = IndependentPixels::new(side, side, spp, seed).unwrap();
                    let b = tables[seed as usize].sampler(side, side, seed).unwrap();
                    let u = Budget::UNLIMITED;
                    let errors = [
                        screen_error(&z, f, &u).unwrap(),
                        screen_error(&p, f, &u).unwrap(),
                        screen_error(&i, f, &u).unwrap(),
                        screen_error(&b, f, &u).unwrap(),
                    ];
                    for (a, e) in acc.iter_mut().zip(errors) {
                        a[0] += e.rmse * e.rmse / seeds as f64;
                        a[1] += e.low_band_absolute / seeds as f64;
                        a[2] += e.low_band / seeds as f64;
                    }
                }
                let r = |a: usize, b: usize| acc[a][1] / acc[b][1];
                let q = |a: usize, b: usize| (acc[a][0] / acc[b][0]).sqrt();
                println!(
                    "{side} {f:?} {spp} | {:.3} {:.4} {:.3} | {:.3} {:.3} {:.3} | {:.3} {:.3} {:.3} {:.3}",
                    r(0, 1),
                    r(0, 2),
                    r(3, 1),
                    q(0, 1),
                    q(0, 2),
                    q(3, 1),
                    acc[0][2],
                    acc[1][2],
                    acc[2][2],
                    acc[3][2]
                );
            }
        }
    }
}

#[test]
fn image_sobol_pads_past_its_table_as_pbrt_does() {
    use qmckit::pixel::{IMAGE_SOBOL_DIMS, PBRT_SOBOL_DIMS};
    // pbrt's rule on the compiled table: min(table, 1024) (1024 with the CLI's features).
    let table = qmckit::digital::sobol::SOBOL_MAX_DIMS.min(PBRT_SOBOL_DIMS);
    assert_eq!(IMAGE_SOBOL_DIMS, table);
    let last = IMAGE_SOBOL_DIMS - 1;
    for r in ALL {
        let s = ImageSobol::new(16, 9, 4, r, 7).unwrap();
        let (x, y, i) = (3, 5, 2);
        let at = |d| s.get_1d(x, y, i, d).unwrap();
        let pair = |d| s.get_2d(x, y, i, d).unwrap();
        // Get1D: `if (dimension >= NSobolDimensions) dimension = 2`.
        assert_ne!(at(last), at(2));
        for d in [IMAGE_SOBOL_DIMS, IMAGE_SOBOL_DIMS + 1, 100_000, usize::MAX] {
            assert_eq!(at(d), at(2), "{r:?} 1D at {d}");
        }
        // Get2D: `if (dimension + 1 >= NSobolDimensions) dimension = 2`, so the pair at the
        // last dimension wraps too, and a counter of usize::MAX neither overflows nor fails.
        assert_eq!(pair(last - 1), [at(last - 1), at(last)]);
        for d in [last, IMAGE_SOBOL_DIMS, usize::MAX - 1, usize::MAX] {
            assert_eq!(pair(d), pair(2), "{r:?} 2D at {d}");
        }
        assert_eq!(pair(2), [at(2), at(3)]);
    }
}

#[test]
fn image_sobol_handle_counts_like_pbrt() {
    use qmckit::pixel::IMAGE_SOBOL_DIMS;
    let s = ImageSobol::new(16, 9, 4, Randomization::FastOwen, 0).unwrap();
    // StartPixelSample sets dimension = max(2, dim): two Get1D calls read 2, then 3.
    let mut st = s.start_pixel_sample(1, 0, 3).unwrap().with_dimension(0);
    assert_eq!(st.get_1d(), s.get_1d(1, 0, 3, 2).unwrap());
    assert_eq!(st.get_1d(), s.get_1d(1, 0, 3, 3).unwrap());
    assert_eq!(st.dimension(), 4);
    // At the end of the table the counter wraps to 2 and counts on from there.
    let last = IMAGE_SOBOL_DIMS - 1;
    let mut st = s.start_pixel_sample(1, 0, 3).unwrap().with_dimension(last);
    assert_eq!(st.get_1d(), s.get_1d(1, 0, 3, last).unwrap());
    assert_eq!(st.get_1d(), s.get_1d(1, 0, 3, 2).unwrap());
    assert_eq!(st.get_2d(), s.get_2d(1, 0, 3, 3).unwrap());
    assert_eq!(st.dimension(), 5);
    // A pair that would straddle the end wraps whole.
    let mut st = s.start_pixel_sample(1, 0, 3).unwrap().with_dimension(last);
    assert_eq!(st.get_2d(), s.get_2d(1, 0, 3, 2).unwrap());
    assert_eq!(st.dimension(), 4);
    // The padded samplers reuse Sobol' (0, 1) under hashes: no wrap, every counter answers.
    let z = ZSobol::new(16, 9, 4, Randomization::FastOwen, 0).unwrap();
    let p = PaddedSobol::new(16, 9, 4, Randomization::FastOwen, 0).unwrap();
    for d in [IMAGE_SOBOL_DIMS, 1 << 20, u32::MAX as usize, usize::MAX] {
        assert_eq!(z.counter_dimension(d, 2), d);
        assert_eq!(p.counter_dimension(d, 1), d);
        // The hashes read the dimension's low 32 bits (pbrt's int); the counter wraps.
        let mut h = z.start_pixel_sample(1, 0, 3).unwrap().with_dimension(d);
        assert_eq!(h.get_2d(), z.get_2d(1, 0, 3, d as u32 as usize).unwrap());
        assert_eq!(h.dimension(), d.wrapping_add(2));
    }
}

/// pbrt's PMJ02BNSampler starts the counter at `max(2, dim)`: a handle started at 0 reads
/// dimensions 2, 3, 4.. in turn, and the pixel position leaves the counter where it is.
#[test]
fn pmj02bn_handle_counts_like_pbrt() {
    let tables = qmckit::pixel::Pmj02BnTables::new(16, 1).unwrap();
    let s = tables.sampler(20, 20, 1).unwrap();
    let mut h = s.start_pixel_sample(3, 4, 5).unwrap();
    h.get_pixel_2d();
    assert_eq!(h.dimension(), 0);
    assert_eq!(h.get_1d(), s.get_1d(3, 4, 5, 2).unwrap());
    assert_eq!(h.get_1d(), s.get_1d(3, 4, 5, 3).unwrap());
    assert_eq!(h.get_2d(), s.get_2d(3, 4, 5, 4).unwrap());
    assert_eq!(h.dimension(), 6);
}

/// A seed past 2^32 is hashed whole: it differs from its low 32 bits, and seeds below 2^32
/// keep pbrt's values.
#[test]
fn seeds_are_u64() {
    let r = Randomization::FastOwen;
    let lo = ZSobol::new(16, 16, 4, r, 7).unwrap();
    let hi = ZSobol::new(16, 16, 4, r, 7 | (1 << 32)).unwrap();
    assert_ne!(
        lo.get_1d(3, 5, 1, 0).unwrap(),
        hi.get_1d(3, 5, 1, 0).unwrap()
    );
    let lo = PaddedSobol::new(16, 16, 4, r, 7).unwrap();
    let hi = PaddedSobol::new(16, 16, 4, r, 7 | (1 << 32)).unwrap();
    assert_ne!(
        lo.get_2d(3, 5, 1, 0).unwrap(),
        hi.get_2d(3, 5, 1, 0).unwrap()
    );
    let lo = Pmj02Pixels::new(16, 16, 4, 7).unwrap();
    let hi = Pmj02Pixels::new(16, 16, 4, 7 | (1 << 32)).unwrap();
    assert_ne!(
        lo.get_2d(3, 5, 1, 0).unwrap(),
        hi.get_2d(3, 5, 1, 0).unwrap()
    );
}
