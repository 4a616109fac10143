//! Helpers shared by the integration tests: independent checkers written from the
//! definitions (elementary intervals, star discrepancy), not from qmckit's code paths.
#![allow(dead_code)]

use qmckit::Sampler;

/// Points `0..n` of a sampler by random access, as `f64` coordinates (exact), row-major.
#[cfg(feature = "analysis")]
pub fn sampler_points(s: &dyn Sampler, n: u32) -> Vec<f64> {
    let d = s.dims();
    let mut raw = vec![0u32; n as usize * d];
    for i in 0..n {
        for k in 0..d {
            raw[i as usize * d + k] = s.sample(i, k).unwrap();
        }
    }
    qmckit::analysis::Points::from_u32(&raw)
}

/// Points `0..n` of dimensions `dims` of a sampler, as `Vec<[u32; 2]>` for 2D checks.
pub fn points_2d(s: &dyn Sampler, n: u32, dims: (usize, usize)) -> Vec<[u32; 2]> {
    (0..n)
        .map(|i| [s.sample(i, dims.0).unwrap(), s.sample(i, dims.1).unwrap()])
        .collect()
}

/// Is this set of `2^m` points a (0, m, 2)-net in base 2: does every elementary interval
/// `[a 2^-k, (a+1) 2^-k) x [b 2^-(m-k), (b+1) 2^-(m-k))` hold exactly one point?
/// Returns the first failing `(k, a, b, count)`.
pub fn first_net_failure(points: &[[u32; 2]], m: u32) -> Option<(u32, u64, u64, u32)> {
    assert_eq!(points.len() as u64, 1 << m);
    for k in 0..=m {
        let mut count = vec![0u32; 1 << m];
        for p in points {
            let a = if k == 0 { 0 } else { (p[0] >> (32 - k)) as u64 };
            let b = if k == m {
                0
            } else {
                (p[1] >> (32 - (m - k))) as u64
            };
            count[((a << (m - k)) | b) as usize] += 1;
        }
        if let Some(cell) = count.iter().position(|&c| c != 1) {
            let cell = cell as u64;
            return Some((
                k,
                cell >> (m - k),
                cell & ((1 << (m - k)) - 1),
                count[cell as usize],
            ));
        }
    }
    None
}

/// Exact star discrepancy of a 2D set of 0.32 fractions, by brute force over the critical
/// grid: D* = max over anchored boxes [0,a) x [0,b) with a, b in {x_i} u {1} of
/// max(ab - #open/N, #closed/N - ab), where open counts x < a, y < b and closed x <= a,
/// y <= b. Returned as the exact numerator over `N 2^64`.
pub fn star_discrepancy_2d_exact(points: &[[u32; 2]]) -> (i128, i128) {
    let n = points.len() as i128;
    let mut xs: Vec<u64> = points.iter().map(|p| p[0] as u64).collect();
    let mut ys: Vec<u64> = points.iter().map(|p| p[1] as u64).collect();
    xs.push(1 << 32);
    ys.push(1 << 32);
    xs.sort_unstable();
    xs.dedup();
    ys.sort_unstable();
    ys.dedup();
    let mut best = 0i128;
    for &a in &xs {
        for &b in &ys {
            let (mut open, mut closed) = (0i128, 0i128);
            for p in points {
                let (x, y) = (p[0] as u64, p[1] as u64);
                open += (x < a && y < b) as i128;
                closed += (x <= a && y <= b) as i128;
            }
            let vol = (a as i128) * (b as i128); // over 2^64
            best = best.max(vol * n - open * (1i128 << 64));
            best = best.max(closed * (1i128 << 64) - vol * n);
        }
    }
    (best, n << 64)
}

/// SplitMix64 (Steele, Lea & Flood 2014): a generator for test sets that shares no code
/// with qmckit.
pub struct Rng(pub u64);

impl Rng {
    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform double in [0, 1) (53 random bits).
    pub fn uniform(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A coordinate on the grid `k / q` (`0 <= k <= q`), so that ties, 0 and 1 occur.
    pub fn coarse(&mut self, q: u64) -> f64 {
        (self.next() % (q + 1)) as f64 / q as f64
    }

    /// `n d` coordinates: uniform, or on the grid `k/q` with `q = Some(q)`.
    pub fn set(&mut self, n: usize, d: usize, q: Option<u64>) -> Vec<f64> {
        (0..n * d)
            .map(|_| match q {
                Some(q) => self.coarse(q),
                None => self.uniform(),
            })
            .collect()
    }
}

/// `n` SplitMix64 uniform doubles in [0, 1) from `seed`.
pub fn uniform(n: usize, seed: u64) -> Vec<f64> {
    let mut rng = Rng(seed);
    (0..n).map(|_| rng.uniform()).collect()
}

/// `n` points of `d` coordinates of qmckit's `Independent` sampler (seed `seed`), as exact
/// `f64`s, row-major: the white-noise starting sets of the relaxation tests.
pub fn independent_set(n: usize, d: usize, seed: u64) -> Vec<f64> {
    let s = qmckit::Independent::new(d, seed).unwrap();
    let mut v = vec![0u32; n * d];
    s.fill(0, &mut v).unwrap();
    v.into_iter().map(qmckit::bits::to_f64).collect()
}
