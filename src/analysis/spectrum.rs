//! Fourier power spectrum of 2D point sets: the periodogram, its radial average and its
//! anisotropy, the plots by which blue-noise and low-discrepancy patterns are told apart.
//!
//! The points are Dirac impulses on the unit torus; at an integer frequency `k = (kx, ky)`
//!
//! ```text
//! P(k) = |sum_j exp(-2 pi i k . x_j)|^2 / N
//! ```
//!
//! (Ulichney, "Dithering with blue noise", Proc. IEEE 1988; Lagae & Dutré, "A comparison of
//! methods for generating Poisson disk distributions", CGF 2008; the `Fourier` tool of UTK).
//! `P(0) = N`, `P(-k) = P(k)`, and for `N` independent uniform points `E P(k) = 1` at every
//! `k != 0`: 1 is the white-noise level. Blue noise keeps `P` near 0 at low `|k|`; a lattice
//! concentrates it on its dual lattice (a regular `n x n` grid: `P = N` where `n` divides
//! both `kx` and `ky`, else 0).
//!
//! The radial average over the annulus `round(|k|) = r` (`k != 0`, `1 <= r <= K`, so the
//! annulus lies inside the computed square) is the radial power spectrum; its anisotropy is
//! the sample variance over the annulus divided by the squared mean (Ulichney 1988): 1 (0 dB)
//! for white noise, whose periodogram values are exponentially distributed, and below 1 for
//! radially uniform spectra.
//!
//! Cost: `N (3K + 2)` sines and cosines, then `N (K + 1)(2K + 1)` complex multiply-adds (the
//! half `ky >= 0`; the other half by symmetry), rows of frequencies split over threads.
//! Each row sums the points in index order, so the result does not depend on the number of
//! threads. Measured: 4096 points at `K = 128` (1.4e8 multiply-adds) in 0.13 s on two
//! cores, so the budget [`SPECTRUM_WORK_BUDGET`] of 1e10 is about ten seconds there.

use rayon::prelude::*;

use super::Points;
use super::budget::{Budget, Rate};
use crate::{Error, Result};

/// Complex multiply-adds above which [`spectrum_2d`] refuses: [`SPECTRUM_RATE`] times the
/// default budget of ten seconds.
pub const SPECTRUM_WORK_BUDGET: f64 = 1e10;

/// Complex multiply-adds a second of the direct sums (two threads; measured at 1.1e9 to
/// 1.6e9 for K = 32 to 512), the rate [`spectrum_2d_within`] turns its budget into work with.
pub const SPECTRUM_RATE: Rate = Rate::per_second(1e9);

/// Largest `K` [`spectrum_2d`] accepts: the `(2K + 1)^2` powers, the half plane of complex
/// sums and the phase tables then take about 300 MB.
pub const SPECTRUM_MAX_K: usize = 2048;

/// Points whose phase tables are computed at once (`2 * BLOCK * (2K + 1)` `f64`s each for
/// the `x` and `y` factors).
const BLOCK: usize = 256;

/// The periodogram of a 2D point set on the frequencies `[-K, K]^2`, from [`spectrum_2d`].
#[derive(Clone, Debug, PartialEq)]
pub struct Spectrum {
    k_max: usize,
    points: usize,
    /// `P(kx, ky)` at `(ky + K) (2K + 1) + kx + K`.
    power: Vec<f64>,
}

/// One annulus of the radial spectrum, from [`Spectrum::radial`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RadialBin {
    /// The integer radius `r`: frequencies with `round(|k|) = r`.
    pub radius: usize,
    /// How many frequencies the annulus holds (both of each pair `k`, `-k`).
    pub count: usize,
    /// Mean of `P(k)` over the annulus.
    pub mean: f64,
    /// Sample variance over the annulus divided by the squared mean (0 when the mean is 0);
    /// `10 log10` of it is Ulichney's anisotropy in dB.
    pub anisotropy: f64,
}

impl Spectrum {
    /// The largest frequency `K` along each axis.
    pub fn k_max(&self) -> usize {
        self.k_max
    }

    /// `N`, the number of points (also `P(0, 0)`).
    pub fn points(&self) -> usize {
        self.points
    }

    /// `P(kx, ky)`, or `None` outside `[-K, K]^2`.
    pub fn get(&self, kx: i64, ky: i64) -> Option<f64> {
        let k = self.k_max as i64;
        if kx.unsigned_abs() > k as u64 || ky.unsigned_abs() > k as u64 {
            return None;
        }
        let side = 2 * k + 1;
        self.power.get(((ky + k) * side + kx + k) as usize).copied()
    }

    /// `(kx, ky, P)` for every frequency, `ky` then `kx` ascending from `-K`.
    pub fn iter(&self) -> impl Iterator<Item = (i64, i64, f64)> + '_ {
        let (k, side) = (self.k_max as i64, 2 * self.k_max + 1);
        self.power
            .iter()
            .enumerate()
            .map(move |(at, &p)| ((at % side) as i64 - k, (at / side) as i64 - k, p))
    }

    /// The radial power spectrum and anisotropy for `r = 1 ..= K` (empty for `K = 0`).
    ///
    /// ```
    /// use qmckit::analysis::{Points, spectrum::spectrum_2d};
    /// // One point: P(k) = 1 everywhere but k = 0, so every annulus has mean 1 and
    /// // anisotropy 0.
    /// let s = spectrum_2d(Points::new(&[0.3, 0.7], 2)?, 3)?;
    /// let radial = s.radial();
    /// assert_eq!(radial.len(), 3);
    /// assert_eq!(radial[0].count, 8); // (±1, 0), (0, ±1), (±1, ±1): |k| rounds to 1
    /// assert!(radial.iter().all(|b| (b.mean - 1.0).abs() < 1e-12 && b.anisotropy < 1e-20));
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn radial(&self) -> Vec<RadialBin> {
        let bins = self.k_max + 1;
        let (mut count, mut sum) = (vec![0usize; bins], vec![0.0f64; bins]);
        let ring = |kx: i64, ky: i64| ((kx * kx + ky * ky) as f64).sqrt().round() as usize;
        for (kx, ky, p) in self.iter() {
            let r = ring(kx, ky);
            if r < bins && (kx, ky) != (0, 0) {
                count[r] += 1;
                sum[r] += p;
            }
        }
        let mut squares = vec![0.0f64; bins];
        for (kx, ky, p) in self.iter() {
            let r = ring(kx, ky);
            if r < bins && (kx, ky) != (0, 0) {
                let dev = p - sum[r] / count[r] as f64;
                squares[r] += dev * dev;
            }
        }
        (1..bins)
            .map(|r| {
                let mean = sum[r] / count[r] as f64;
                let variance = squares[r] / (count[r] - 1).max(1) as f64;
                RadialBin {
                    radius: r,
                    count: count[r],
                    mean,
                    anisotropy: if mean > 0.0 {
                        variance / (mean * mean)
                    } else {
                        0.0
                    },
                }
            })
            .collect()
    }
}

/// `(cos, sin)` of `-2 pi k x` for the frequencies `ks`, the phase reduced to `[0, 1)` turns
/// first (`k x` is rounded once, so the phase errs by about `|k|` ulps of 1).
fn phases(x: f64, ks: core::ops::RangeInclusive<i64>, re: &mut [f64], im: &mut [f64]) {
    for ((kk, r), i) in ks.zip(re.iter_mut()).zip(im.iter_mut()) {
        let turns = (kk as f64 * x).rem_euclid(1.0);
        let (s, c) = (core::f64::consts::TAU * turns).sin_cos();
        (*r, *i) = (c, -s);
    }
}

/// The periodogram of a 2D point set on the frequencies `[-K, K]^2` (`K = k_max`), exact
/// up to rounding (direct sums, no FFT: the points need not lie on a grid). See the module
/// documentation for the definition and the cost.
///
/// # Errors
/// [`Error::Unsupported`] unless `points.dims() == 2`, or for `k_max` above
/// [`SPECTRUM_MAX_K`]; [`Error::TooManyPoints`] when
/// `N (K + 1)(2K + 1)` exceeds [`SPECTRUM_WORK_BUDGET`] (`max`: the most points within it
/// for this `K`).
///
/// ```
/// use qmckit::analysis::{Points, spectrum::spectrum_2d};
/// // The 2 x 2 grid of cell centres: P = N = 4 where both frequencies are even, else 0.
/// let p = Points::new(&[0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75], 2)?;
/// let s = spectrum_2d(p, 2)?;
/// assert!((s.get(2, -2).unwrap() - 4.0).abs() < 1e-12);
/// assert!(s.get(1, 0).unwrap().abs() < 1e-12);
/// assert_eq!(s.get(0, 0), Some(4.0));
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn spectrum_2d(points: Points<'_>, k_max: usize) -> Result<Spectrum> {
    spectrum_2d_within(points, k_max, &Budget::DEFAULT)
}

/// [`spectrum_2d`] within a time budget: the `N (K + 1)(2K + 1)` complex multiply-adds at
/// [`SPECTRUM_RATE`] must fit in `budget`, checked before any work or allocation.
///
/// # Errors
/// As [`spectrum_2d`]; [`Error::TooManyPoints`] names the most points the budget admits for
/// this `K`.
///
/// ```
/// use qmckit::analysis::{Points, budget::Budget, spectrum::spectrum_2d_within};
/// let p = Points::new(&[0.5; 2000], 2)?; // 1000 points
/// assert!(spectrum_2d_within(p, 64, &Budget::seconds(10.0)?).is_ok());
/// assert!(spectrum_2d_within(p, 2048, &Budget::seconds(0.1)?).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn spectrum_2d_within(points: Points<'_>, k_max: usize, budget: &Budget) -> Result<Spectrum> {
    if points.dims() != 2 {
        return Err(Error::Unsupported {
            what: "a spectrum of points that are not 2-dimensional",
        });
    }
    if k_max > SPECTRUM_MAX_K {
        return Err(Error::Unsupported {
            what: "a spectrum with k_max above 2048",
        });
    }
    let n = points.len();
    let side = 2 * k_max + 1;
    let per_point = (k_max as f64 + 1.0) * side as f64;
    let work = budget.steps(SPECTRUM_RATE);
    if n as f64 * per_point > work {
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max: (work / per_point) as u64,
        });
    }
    // Rows ky = 0 ..= K of the sum S(k) = sum_j exp(-2 pi i k . x_j), as (re, im).
    let mut sums = vec![(0.0f64, 0.0f64); (k_max + 1) * side];
    // Per point of a block: x phases for kx = -K ..= K, y phases for ky = 0 ..= K.
    let (k, half) = (k_max as i64, k_max + 1);
    let (mut xr, mut xi) = (vec![0.0; BLOCK * side], vec![0.0; BLOCK * side]);
    let (mut yr, mut yi) = (vec![0.0; BLOCK * half], vec![0.0; BLOCK * half]);
    for block in points.as_slice().chunks(2 * BLOCK) {
        let m = block.len() / 2;
        for (j, p) in block.chunks_exact(2).enumerate() {
            let at = j * side..(j + 1) * side;
            phases(p[0], -k..=k, &mut xr[at.clone()], &mut xi[at]);
            let at = j * half..(j + 1) * half;
            phases(p[1], 0..=k, &mut yr[at.clone()], &mut yi[at]);
        }
        sums.par_chunks_mut(side).enumerate().for_each(|(ky, row)| {
            for j in 0..m {
                // exp(-2 pi i ky y_j): entry ky of point j's y phases.
                let (wr, wi) = (yr[j * half + ky], yi[j * half + ky]);
                let at = j * side..(j + 1) * side;
                for ((acc, &ar), &ai) in row.iter_mut().zip(&xr[at.clone()]).zip(&xi[at]) {
                    acc.0 += wr * ar - wi * ai;
                    acc.1 += wr * ai + wi * ar;
                }
            }
        });
    }
    let inv_n = 1.0 / n.max(1) as f64;
    let mut power = vec![0.0f64; side * side];
    for (ky, row) in sums.chunks_exact(side).enumerate() {
        for (kx, &(re, im)) in row.iter().enumerate() {
            let p = (re * re + im * im) * inv_n;
            // (kx - K, ky) and its mirror (K - kx, -ky).
            power[(k_max + ky) * side + kx] = p;
            power[(k_max - ky) * side + (side - 1 - kx)] = p;
        }
    }
    power[k_max * side + k_max] = n as f64; // exact: every phase is 1
    Ok(Spectrum {
        k_max,
        points: n,
        power,
    })
}
