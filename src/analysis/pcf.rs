//! The pair correlation function (PCF) of a 2D point set, in the definition of UTK's `PCF`
//! tool (Heck, Schlömer & Deussen, "Blue noise sampling with controlled aliasing", ACM TOG
//! 2013; Öztireli & Gross 2012):
//!
//! ```text
//! g(r) = sum_{i != j} k_s(r - |x_i - x_j|) / (N (N - 1) 2 pi r e(r)),
//! k_s(t) = exp(-t^2 / (2 s^2)) / (sqrt(2 pi) s),
//! ```
//!
//! with `e(r) = 1 - 4r/pi + r^2/pi` the edge correction of the unit square (the fraction of
//! pairs at distance `r` whose both ends lie in the square) for Euclidean distances, and
//! `e(r) = 1` with the toroidal (nearest-image) distance: on the torus no pair is lost, so
//! `2 pi r` is the exact normaliser (UTK keeps the square's factor there too; we do not).
//! `g = 1` for independent uniform points (up to noise), `g = 0` below the minimum
//! distance of a Poisson-disk set. Evaluated at the bin centres `r_b = r_max (b + 1/2) / B`.
//!
//! Its Fourier transform is the spectrum's: for an isotropic process of `N` points on the
//! unit area, `P(rho) = 1 + 2 pi N int_0^inf (g(r) - 1) J0(2 pi rho r) r dr`
//! ([`structure_factor`]), which the tests check against the mean periodogram.
//!
//! Cost: `N (N - 1) / 2` distances and, for the pairs closer than `r_max + 5s`, about
//! `10 s B / r_max + 1` kernel values each; split over threads in fixed chunks and summed
//! in chunk order (the result does not depend on the number of threads). Budgeted at
//! [`PCF_RATE`].

use rayon::prelude::*;

use super::Points;
use crate::work::Stop;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// Pair steps (one distance, or one kernel value) a second (two threads, conservative).
pub const PCF_RATE: Rate = Rate::per_second(3e8);

/// Options of [`pcf_2d`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PcfOptions {
    /// Largest radius, in `(0, 1/2]` (toroidal) or `(0, 1]`.
    pub r_max: f64,
    /// Number of bins `B`, at least 1, at most 1e6.
    pub bins: usize,
    /// Kernel width `s` (in `[1e-100, 1]`; default the bin width `r_max / B`).
    pub sigma: f64,
    /// Toroidal (nearest-image) distances.
    pub torus: bool,
}

impl PcfOptions {
    /// `r_max`, `bins`, the bin width as kernel width, and `torus`.
    pub fn new(r_max: f64, bins: usize, torus: bool) -> Self {
        PcfOptions {
            r_max,
            bins,
            sigma: r_max / bins.max(1) as f64,
            torus,
        }
    }
}

/// One bin of [`pcf_2d`]: `g(radius)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PcfBin {
    /// The bin centre `r_b`.
    pub radius: f64,
    /// `g(r_b)`.
    pub g: f64,
}

/// The smallest `r_max` and kernel width [`pcf_2d`] accepts: with both at least `1e-100`
/// the kernel's `1 / sigma` and `1 / sigma^2`, the bin radii and the normalization
/// `N (N - 1) 2 pi r` stay normal numbers, so no bin is NaN or infinite.
pub const PCF_MIN_LENGTH: f64 = 1e-100;

/// The largest kernel width [`pcf_2d`] accepts: 1, the side of the square (a wider kernel
/// is flat over every distance there is).
pub const PCF_MAX_SIGMA: f64 = 1.0;

impl PcfOptions {
    /// Checks the options' ranges: `r_max` in `[1e-100, 1/2]` on the torus or
    /// `[1e-100, 1]` in the square, `bins` in `1..=1e6`, `sigma` in `[1e-100, 1]`
    /// ([`PCF_MIN_LENGTH`], [`PCF_MAX_SIGMA`]). `O(1)`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] naming the first option out of range.
    ///
    /// ```
    /// use qmckit::analysis::pcf::PcfOptions;
    /// assert!(PcfOptions::new(0.15, 200, false).validate().is_ok());
    /// let mut o = PcfOptions::new(0.15, 200, false);
    /// o.sigma = 5e-324; // 1 / sigma^2 overflows: refused, not NaN bins
    /// assert!(o.validate().is_err());
    /// ```
    pub fn validate(&self) -> Result<()> {
        let limit = if self.torus { 0.5 } else { 1.0 };
        let bad = |what| Err(Error::InvalidParameter { what });
        if !(PCF_MIN_LENGTH..=limit).contains(&self.r_max) {
            return bad("r_max must lie in [1e-100, 0.5] on the torus, [1e-100, 1] in the square");
        }
        if self.bins == 0 || self.bins > 1_000_000 {
            return bad("the number of bins must lie in 1..=1000000");
        }
        if !(PCF_MIN_LENGTH..=PCF_MAX_SIGMA).contains(&self.sigma) {
            return bad("the kernel width sigma must lie in [1e-100, 1]");
        }
        Ok(())
    }
}

/// The estimated cost of [`pcf_2d`] for `n` points.
pub fn pcf_cost(n: usize, opts: &PcfOptions) -> Cost {
    let pairs = n as f64 * (n as f64 - 1.0) / 2.0;
    let reach = opts.r_max + 5.0 * opts.sigma;
    let near = pairs * (core::f64::consts::PI * reach * reach).min(1.0);
    let per = 10.0 * opts.sigma * opts.bins as f64 / opts.r_max + 2.0;
    Cost::steps(pairs + near * per, PCF_RATE)
}

/// The pair correlation function of a 2D point set, by the definition of the module
/// documentation, within `budget`.
///
/// # Errors
/// [`Error::Unsupported`] unless the points are 2-dimensional; [`Error::InvalidParameter`]
/// for fewer than two points, `r_max` outside `(0, 1/2]` (torus) or `(0, 1]`, `bins`
/// outside `1..=1e6`, or `r_max` or the kernel width outside their ranges
/// ([`PcfOptions::validate`]); [`Error::OverBudget`] past the budget; [`Error::OutOfTime`]
/// past its deadline (started here if it was not; read once per row of distances).
///
/// ```
/// use qmckit::{work::Budget, analysis::{Points, pcf::{PcfOptions, pcf_2d}}};
/// // The 4 x 4 grid on the torus: each point has 4 neighbours at 1/4, none nearer.
/// let pts: Vec<f64> = (0..16).flat_map(|i| [(i % 4) as f64 / 4.0, (i / 4) as f64 / 4.0]).collect();
/// let g = pcf_2d(Points::new(&pts, 2)?, &PcfOptions::new(0.3, 30, true), &Budget::DEFAULT)?;
/// assert!(g[..19].iter().all(|b| b.g == 0.0)); // r < 0.19: beyond the kernel's reach
/// assert!(g[24].g > 1.0); // r = 0.245
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn pcf_2d(points: Points<'_>, opts: &PcfOptions, budget: &Budget) -> Result<Vec<PcfBin>> {
    if points.dims() != 2 {
        return Err(Error::Unsupported {
            what: "a pair correlation function of points that are not 2-dimensional",
        });
    }
    if points.len() < 2 {
        return Err(Error::InvalidParameter {
            what: "a pair correlation function needs at least two points",
        });
    }
    opts.validate()?;
    budget.check(
        "the pair correlation function",
        pcf_cost(points.len(), opts),
    )?;
    let (b, s) = (opts.bins, opts.sigma);
    let width = opts.r_max / b as f64;
    let reach = opts.r_max + 5.0 * s;
    let norm = 1.0 / ((2.0 * core::f64::consts::PI).sqrt() * s);
    let data = points.as_slice();
    let n = points.len();
    let near = |d: f64| {
        if opts.torus {
            let a = d.abs() % 1.0;
            a.min(1.0 - a)
        } else {
            d
        }
    };
    const CHUNK: usize = 64;
    let stop = Stop::new(budget, "the pair correlation function");
    let partial: Vec<Vec<f64>> = (0..n.div_ceil(CHUNK))
        .into_par_iter()
        .map(|c| {
            let mut hist = vec![0.0f64; b];
            for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                // One clock reading per row of N - i - 1 distances.
                if stop.check() {
                    break;
                }
                let (xi, yi) = (data.get(2 * i).copied(), data.get(2 * i + 1).copied());
                let (Some(xi), Some(yi)) = (xi, yi) else {
                    continue;
                };
                for pj in data.get(2 * (i + 1)..).unwrap_or(&[]).chunks_exact(2) {
                    let (dx, dy) = (near(pj[0] - xi), near(pj[1] - yi));
                    let d2 = dx * dx + dy * dy;
                    if d2 >= reach * reach {
                        continue;
                    }
                    let d = d2.sqrt();
                    let lo = (((d - 5.0 * s) / width - 0.5).floor().max(0.0)) as usize;
                    let hi = ((((d + 5.0 * s) / width - 0.5).ceil().max(0.0)) as usize).min(b - 1);
                    for (k, h) in hist.iter_mut().enumerate().take(hi + 1).skip(lo) {
                        let t = (k as f64 + 0.5) * width - d;
                        *h += (-0.5 * t * t / (s * s)).exp();
                    }
                }
            }
            hist
        })
        .collect();
    stop.result()?;
    let mut hist = vec![0.0f64; b];
    for p in &partial {
        for (h, v) in hist.iter_mut().zip(p) {
            *h += v;
        }
    }
    let pairs = n as f64 * (n as f64 - 1.0);
    Ok(hist
        .iter()
        .enumerate()
        .map(|(k, &h)| {
            let r = (k as f64 + 0.5) * width;
            let edge = if opts.torus {
                1.0
            } else {
                let pi = core::f64::consts::PI;
                1.0 - 4.0 * r / pi + r * r / pi
            };
            // Each unordered pair once in `hist`: twice in the sum over i != j.
            PcfBin {
                radius: r,
                g: 2.0 * h * norm / (pairs * 2.0 * core::f64::consts::PI * r * edge),
            }
        })
        .collect())
}

/// The structure factor (expected periodogram) of an isotropic process of `n` points on
/// the unit area with pair correlation `g` (bins of equal width from [`pcf_2d`]):
/// `1 + 2 pi n sum_b (g_b - 1) J0(2 pi rho r_b) r_b dr`, at the frequency `rho` (in
/// cycles per unit length). The truncation at `r_max` is exact when `g = 1` beyond it.
pub fn structure_factor(g: &[PcfBin], n: usize, rho: f64) -> f64 {
    let dr = match g {
        [a, b, ..] => b.radius - a.radius,
        [a] => 2.0 * a.radius,
        [] => return 1.0,
    };
    let tau = 2.0 * core::f64::consts::PI;
    1.0 + tau
        * n as f64
        * g.iter()
            .map(|bin| (bin.g - 1.0) * libm::j0(tau * rho * bin.radius) * bin.radius * dr)
            .sum::<f64>()
}
