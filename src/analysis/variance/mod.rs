//! Integration variance predicted from a mean power spectrum, and measured beside it
//! (Pilleboue, Singh, Coeurjolly, Kazhdan & Ostromoukhov, "Variance analysis for Monte Carlo
//! integration", ACM TOG 2015; Durand 2011).
//!
//! For a sampler followed by one uniform random torus shift of the whole set, and `f` on
//! the unit torus with Fourier coefficients `c_k`, the mean `I_N = (1/N) sum_i f(x_i)` is
//! unbiased and
//!
//! ```text
//! Var I_N = (1/N) sum_{k != 0} |c_k|^2 E P(k),   P(k) = |sum_i exp(-2 pi i k.x_i)|^2 / N
//! ```
//!
//! (the shift kills every cross term; `P` is shift-invariant, so `E P` is the sampler's
//! mean periodogram, from [`crate::analysis::spectrum::SpectrumMean`]). White noise has
//! `E P = 1`, hence `Var = (||f||^2 - c_0^2) / N` by Parseval (`(pi R^2 - pi^2 R^4) / N` for
//! the disk). [`predicted_variance`] sums over the computed square `[-K, K]^2` and adds the
//! rest of Parseval's sum, `||f||^2 - sum_{|k|_inf <= K} |c_k|^2`, at the white level
//! `E P = 1` (exact for samplers whose spectrum is flat beyond `K`, e.g. jittered with
//! `K >= 2 sqrt(N)`); [`Prediction::tail`] reports that part.
//!
//! The measured side: [`shifted_error`] is `I_N - c_0` of one shifted set;
//! [`Measured::from_errors`] their mean square with its standard error, and
//! [`fit_slope`] the least-squares slope of `log Var` against `log N` (the convergence
//! rate: -1 for white noise and Poisson disk, -1.5 for jittered and for the disk, faster
//! for smooth integrands on blue noise and Owen-scrambled nets).

pub mod integrand;

pub use integrand::TorusIntegrand;

use super::Points;
use super::spectrum::Spectrum;
use crate::{Error, Result};

/// A predicted variance, from [`predicted_variance`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prediction {
    /// `Var I_N`.
    pub variance: f64,
    /// The part of it from frequencies outside `[-K, K]^2` (taken at `E P = 1`).
    pub tail: f64,
}

/// The variance of `I_N` for a randomly torus-shifted sampler whose mean periodogram is
/// `mean` (over `N = mean.points()` points), by the formula of the module documentation.
/// Cost: `(2K + 1)^2` coefficients.
///
/// ```
/// use qmckit::analysis::{Points, spectrum::spectrum_2d, variance::*};
/// // One point: P = 1 everywhere, so the prediction is the white-noise variance.
/// let s = spectrum_2d(Points::new(&[0.3, 0.6], 2)?, 16, &qmckit::work::Budget::DEFAULT)?;
/// let disk = TorusIntegrand::disk(0.25)?;
/// let p = predicted_variance(&s, &disk);
/// assert!((p.variance - 0.15779639865760675).abs() < 1e-14);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn predicted_variance(mean: &Spectrum, f: &TorusIntegrand) -> Prediction {
    let (mut inside, mut weight) = (0.0, 0.0);
    for (kx, ky, p) in mean.iter() {
        if (kx, ky) != (0, 0) {
            let c = f.coefficient_sq(kx, ky);
            inside += c * p;
            weight += c;
        }
    }
    let n = mean.points().max(1) as f64;
    let tail = (f.white_noise_variance() - weight).max(0.0);
    Prediction {
        variance: (inside + tail) / n,
        tail: tail / n,
    }
}

/// `I_N - c_0` for the points shifted by `shift` on the torus (`x + shift mod 1`).
/// Cost: `N` evaluations.
///
/// # Errors
/// [`Error::Unsupported`] unless the points are 2-dimensional.
pub fn shifted_error(points: Points<'_>, f: &TorusIntegrand, shift: [f64; 2]) -> Result<f64> {
    if points.dims() != 2 {
        return Err(Error::Unsupported {
            what: "a torus integrand of points that are not 2-dimensional",
        });
    }
    let wrap = |v: f64| {
        let w = v.rem_euclid(1.0);
        if w >= 1.0 { 0.0 } else { w }
    };
    let sum: f64 = points
        .iter()
        .map(|p| match *p {
            [x, y] => f.eval(wrap(x + shift[0]), wrap(y + shift[1])),
            _ => 0.0,
        })
        .sum();
    Ok(sum / points.len() as f64 - f.integral())
}

/// A measured variance: the mean square of errors of independent randomized sets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    /// How many sets.
    pub sets: usize,
    /// `(1/S) sum_s e_s^2`, an unbiased estimate of `Var I_N` (the exact mean is known).
    pub variance: f64,
    /// Its standard error, `sd(e_s^2) / sqrt(S)`.
    pub std_error: f64,
}

impl Measured {
    /// The mean square of `errors` and its standard error.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`] for no errors.
    ///
    /// ```
    /// use qmckit::analysis::variance::Measured;
    /// let m = Measured::from_errors(&[0.1, -0.1, 0.2, -0.2])?;
    /// assert!((m.variance - 0.025).abs() < 1e-15);
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn from_errors(errors: &[f64]) -> Result<Self> {
        if errors.is_empty() {
            return Err(Error::ZeroPoints);
        }
        let s = errors.len() as f64;
        let variance = errors.iter().map(|e| e * e).sum::<f64>() / s;
        let spread = errors
            .iter()
            .map(|e| (e * e - variance).powi(2))
            .sum::<f64>()
            / (s - 1.0).max(1.0);
        Ok(Measured {
            sets: errors.len(),
            variance,
            std_error: (spread / s).sqrt(),
        })
    }
}

/// The least-squares slope of `ln v` against `ln n` over the pairs `(n, v)` (at least two,
/// all positive): the exponent `a` of `v ~ n^a`.
///
/// # Errors
/// [`Error::InvalidParameter`] for fewer than two pairs, a non-positive value, or all `n`
/// equal.
///
/// ```
/// use qmckit::analysis::variance::fit_slope;
/// let s = fit_slope(&[(16.0, 1.0 / 64.0), (64.0, 1.0 / 512.0)])?;
/// assert!((s + 1.5).abs() < 1e-12);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn fit_slope(pairs: &[(f64, f64)]) -> Result<f64> {
    let bad = Error::InvalidParameter {
        what: "a slope needs two or more positive (n, value) pairs with distinct n",
    };
    if pairs.len() < 2 || pairs.iter().any(|&(n, v)| !(n > 0.0 && v > 0.0)) {
        return Err(bad);
    }
    let m = pairs.len() as f64;
    let (mx, my) = pairs.iter().fold((0.0, 0.0), |(a, b), &(n, v)| {
        (a + n.ln() / m, b + v.ln() / m)
    });
    let (sxy, sxx) = pairs.iter().fold((0.0, 0.0), |(a, b), &(n, v)| {
        let dx = n.ln() - mx;
        (a + dx * (v.ln() - my), b + dx * dx)
    });
    if sxx <= 0.0 {
        return Err(bad);
    }
    Ok(sxy / sxx)
}
