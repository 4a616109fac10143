//! The PMJ02 pixel sampler against the paper's properties: its shared table is a
//! progressive multi-jittered (0, 2)-sequence (every aligned block of `2^m` points a
//! (0, m, 2)-net; Christensen, Kensler & Kilpatrick 2018), and every power-of-two prefix of
//! every pixel's points stays a (0, m, 2)-net in base 2, stratified in each coordinate,
//! through the index shuffle and the Owen scrambles (Owen 1995: each scrambled point is
//! uniform).

use super::Draw;
use crate::common::first_net_failure;
use qmckit::Error;
use qmckit::pixel::{PMJ02_TABLE_LEN, PixelSampler, Pmj02Pixels, pmj02_table_point};

/// The table's points as 0.32 fractions (their top 16 bits).
fn table() -> Vec<[u32; 2]> {
    (0..PMJ02_TABLE_LEN)
        .map(|k| pmj02_table_point(k as u16).map(|c| (c as u32) << 16))
        .collect()
}

/// The table is the crate's PMJ02 sequence of seed 0, truncated to 16 bits (what the file
/// says it is), and every aligned block of `2^m` of its points is a (0, m, 2)-net, for
/// every `m <= 16` (the property of a (0, 2)-sequence the sampler relies on).
#[test]
fn table_is_a_pmj02_sequence() {
    let t = table();
    let mut pts = vec![[0u32; 2]; PMJ02_TABLE_LEN];
    qmckit::pmj::fill(0, &mut pts).unwrap();
    for (k, (a, b)) in t.iter().zip(&pts).enumerate() {
        assert_eq!(*a, [b[0] & 0xffff_0000, b[1] & 0xffff_0000], "point {k}");
    }
    for m in 0..=16u32 {
        for (b, block) in t.chunks(1 << m).enumerate() {
            assert_eq!(first_net_failure(block, m), None, "block {b} of 2^{m}");
        }
    }
}

/// Whether the first coordinates of `v` (`2^m` of them) fall one in each interval
/// `[j 2^-m, (j + 1) 2^-m)`.
fn stratified(v: impl Iterator<Item = u32>, m: u32) -> bool {
    let mut seen = vec![false; 1 << m];
    for c in v {
        let j = if m == 0 { 0 } else { (c >> (32 - m)) as usize };
        if std::mem::replace(&mut seen[j], true) {
            return false;
        }
    }
    seen.iter().all(|&s| s)
}

/// Every power-of-two prefix of `2^m` samples of a pixel and dimension is a (0, m, 2)-net
/// (one point in every elementary interval of area `2^-m`, every shape), and the 1D fill's
/// prefixes are stratified: for sample counts that are and are not powers of two, seeds
/// below and above `2^32`, pixels across the image and dimensions past 32 bits.
#[test]
fn every_power_of_two_prefix_is_a_net() {
    for (spp, seed) in [(4096u32, 0u64), (1024, 1 << 40), (24, 3), (1000, 9)] {
        let s = Pmj02Pixels::new(64, 48, spp, seed).unwrap();
        for (x, y) in [(0, 0), (63, 47), (17, 5), (40, 30)] {
            for d in [0usize, 1, 2, 9, 1 << 33 | 3] {
                let n = spp as usize;
                let (mut pts, mut xs) = (vec![[0u32; 2]; n], vec![0u32; n]);
                s.fill_2d(x, y, d, &mut pts).unwrap();
                s.fill_1d(x, y, d, &mut xs).unwrap();
                let mut m = 0;
                while 1usize << m <= n {
                    let what = format!("spp {spp} seed {seed} ({x}, {y}) dim {d} 2^{m}");
                    assert_eq!(first_net_failure(&pts[..1 << m], m), None, "{what}");
                    assert!(stratified(xs[..1 << m].iter().copied(), m), "{what}");
                    assert!(stratified(pts[..1 << m].iter().map(|p| p[1]), m), "{what}");
                    m += 1;
                }
            }
        }
    }
    // Every pixel of an image at 16 spp, two dimensions.
    let s = Pmj02Pixels::new(40, 30, 16, 5).unwrap();
    for y in 0..30 {
        for x in 0..40 {
            for d in [0, 7] {
                let mut pts = [[0u32; 2]; 16];
                s.fill_2d(x, y, d, &mut pts).unwrap();
                for m in 0..=4 {
                    assert_eq!(first_net_failure(&pts[..1 << m], m), None, "({x}, {y}) {d}");
                }
            }
        }
    }
}

/// The whole table's worth: 65,536 samples of one pixel are a (0, 16, 2)-net, through the
/// handle as well as the fill.
#[test]
fn a_full_pixel_is_a_net() {
    let s = Pmj02Pixels::new(4, 4, 1 << 16, 11).unwrap();
    let mut pts = vec![[0u32; 2]; 1 << 16];
    s.fill_2d(3, 1, 5, &mut pts).unwrap();
    assert_eq!(first_net_failure(&pts, 16), None);
    for i in (0..1u32 << 16).step_by(997) {
        assert_eq!(s.get_2d(3, 1, i, 5).unwrap(), pts[i as usize]);
    }
}

/// Owen scrambling makes each point uniform in the square (Owen 1995), the digits past
/// the table's 16 bits included: sample 0 of 4800 pixel-dimension pairs, counted in 16
/// bins of its top 4 bits and of its bits 16 to 19, each against the uniform law by a
/// chi-square test (15 degrees of freedom; 45 is exceeded with probability about 1e-4).
#[test]
fn points_are_uniform() {
    let s = Pmj02Pixels::new(40, 60, 16, 2).unwrap();
    let mut bins = [[[0u32; 16]; 2]; 2];
    let mut n = 0;
    for y in 0..60 {
        for x in 0..40 {
            for d in [0, 3] {
                let p = s.get_2d(x, y, 0, d).unwrap();
                for c in 0..2 {
                    bins[c][0][(p[c] >> 28) as usize] += 1;
                    bins[c][1][((p[c] >> 12) & 15) as usize] += 1;
                }
                n += 1;
            }
        }
    }
    let e = n as f64 / 16.0;
    for (c, by) in bins.iter().enumerate() {
        for (w, b) in by.iter().enumerate() {
            let chi2: f64 = b.iter().map(|&o| (o as f64 - e).powi(2) / e).sum();
            assert!(chi2 < 45.0, "coordinate {c} bits {w}: chi2 {chi2} {b:?}");
        }
    }
}

/// Sample `i` does not depend on `spp` (the samples are progressive); dimensions and
/// pixels take different points; past the table, `new` refuses.
#[test]
fn progressive_keyed_and_bounded() {
    let (a, b) = (
        Pmj02Pixels::new(8, 8, 16, 4).unwrap(),
        Pmj02Pixels::new(8, 8, 64, 4).unwrap(),
    );
    let (mut p, mut q) = ([[0u32; 2]; 16], [[0u32; 2]; 64]);
    a.fill_2d(2, 3, 1, &mut p).unwrap();
    b.fill_2d(2, 3, 1, &mut q).unwrap();
    assert_eq!(p[..], q[..16]);
    b.fill_2d(2, 3, 2, &mut q).unwrap();
    assert_ne!(p[..], q[..16]);
    b.fill_2d(3, 2, 1, &mut q).unwrap();
    assert_ne!(p[..], q[..16]);
    assert!(Pmj02Pixels::new(8, 8, 1 << 16, 0).is_ok());
    assert!(matches!(
        Pmj02Pixels::new(8, 8, (1 << 16) + 1, 0),
        Err(Error::TooLarge { .. })
    ));
}
