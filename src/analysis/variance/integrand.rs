//! Test integrands on the unit torus with closed-form Fourier coefficients, for
//! [`super::predicted_variance`].
//!
//! Both are centred at `(1/2, 1/2)`; a random torus shift of the points moves them anywhere.
//! * Disk indicator of radius `R` (`0 < R <= 1/2`): `c_0 = pi R^2` and, for `k != 0`,
//!   `|c_k| = R J1(2 pi R |k|) / |k|` (the Fourier transform of a disk; `J1` the Bessel
//!   function of the first kind, from `libm`); `||f||^2 = pi R^2`.
//! * Periodized Gaussian `f(x) = sum_m exp(-|x - c + m|^2 / (2 s^2))` (`0 < s <= 0.15`):
//!   `c_k = 2 pi s^2 exp(-2 pi^2 s^2 |k|^2)` up to a phase, so
//!   `||f||^2 = (2 pi s^2)^2 theta^2`, `theta = sum_m exp(-4 pi^2 s^2 m^2)`; evaluated with
//!   the images `m` in `{-1, 0, 1}^2` (the others weigh below `exp(-50)`).
//!
//! Cost: one `J1` or one `exp` per coefficient; one evaluation is `O(1)` (nine `exp` for
//! the Gaussian).

use crate::{Error, Result};
use core::f64::consts::PI;

/// The smallest disk radius and Gaussian width: the fourth powers that the coefficients
/// and the squared errors hold (`1e-200`) stay normal `f64`s.
pub const MIN_SCALE: f64 = 1e-50;

/// A test integrand on the unit torus with known Fourier coefficients.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TorusIntegrand {
    /// The indicator of the disk of this radius around `(1/2, 1/2)`.
    Disk {
        /// `R`, in `(0, 1/2]`.
        radius: f64,
    },
    /// The periodized Gaussian of this standard deviation around `(1/2, 1/2)`.
    Gaussian {
        /// `s`, in `(0, 0.15]`.
        sigma: f64,
    },
}

impl TorusIntegrand {
    /// The disk indicator of radius `radius`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] unless `1e-50 <= radius <= 0.5` ([`MIN_SCALE`]: below
    /// it `|c_k|^2 ~ R^4` and the squared errors underflow, and the variance ratio would be
    /// `0 / 0`).
    pub fn disk(radius: f64) -> Result<Self> {
        if (MIN_SCALE..=0.5).contains(&radius) {
            Ok(TorusIntegrand::Disk { radius })
        } else {
            Err(Error::InvalidParameter {
                what: "the disk radius must lie in [1e-50, 0.5]",
            })
        }
    }

    /// The periodized Gaussian of standard deviation `sigma`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] unless `1e-50 <= sigma <= 0.15` ([`MIN_SCALE`]).
    pub fn gaussian(sigma: f64) -> Result<Self> {
        if (MIN_SCALE..=0.15).contains(&sigma) {
            Ok(TorusIntegrand::Gaussian { sigma })
        } else {
            Err(Error::InvalidParameter {
                what: "the Gaussian's sigma must lie in [1e-50, 0.15]",
            })
        }
    }

    /// The integral over the torus, `c_0`.
    pub fn integral(&self) -> f64 {
        match *self {
            TorusIntegrand::Disk { radius } => PI * radius * radius,
            TorusIntegrand::Gaussian { sigma } => 2.0 * PI * sigma * sigma,
        }
    }

    /// `|c_k|^2`, the squared modulus of the Fourier coefficient at `k = (kx, ky)`.
    ///
    /// ```
    /// use qmckit::analysis::variance::TorusIntegrand;
    /// let d = TorusIntegrand::disk(0.25)?;
    /// assert_eq!(d.coefficient_sq(0, 0), d.integral().powi(2));
    /// // R J1(2 pi R) at R = 1/4: J1(pi / 2) = 0.5668240889...
    /// assert!((d.coefficient_sq(1, 0).sqrt() - 0.25 * 0.566_824_088_9).abs() < 1e-9);
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn coefficient_sq(&self, kx: i64, ky: i64) -> f64 {
        let k2 = (kx as f64).powi(2) + (ky as f64).powi(2);
        match *self {
            TorusIntegrand::Disk { radius } => {
                if k2 == 0.0 {
                    return self.integral().powi(2);
                }
                let k = k2.sqrt();
                let c = radius * libm::j1(2.0 * PI * radius * k) / k;
                c * c
            }
            TorusIntegrand::Gaussian { sigma } => {
                let c0 = self.integral();
                c0 * c0 * (-4.0 * PI * PI * sigma * sigma * k2).exp()
            }
        }
    }

    /// `||f||^2 = sum_k |c_k|^2` (Parseval).
    pub fn norm_sq(&self) -> f64 {
        match *self {
            TorusIntegrand::Disk { radius } => PI * radius * radius,
            TorusIntegrand::Gaussian { sigma } => {
                let q = 4.0 * PI * PI * sigma * sigma;
                let theta: f64 =
                    1.0 + 2.0 * (1..200).map(|m| (-q * (m * m) as f64).exp()).sum::<f64>();
                (self.integral() * theta).powi(2)
            }
        }
    }

    /// The variance of one uniform random point's value, `||f||^2 - c_0^2`: `N` times the
    /// variance of the mean of `N` independent points.
    pub fn white_noise_variance(&self) -> f64 {
        self.norm_sq() - self.integral().powi(2)
    }

    /// `f(x, y)` for a point of the unit square (read on the torus).
    pub fn eval(&self, x: f64, y: f64) -> f64 {
        let (dx, dy) = (x - 0.5, y - 0.5);
        match *self {
            TorusIntegrand::Disk { radius } => {
                // |dx|, |dy| <= 1/2: already the toroidal offsets.
                if dx * dx + dy * dy < radius * radius {
                    1.0
                } else {
                    0.0
                }
            }
            TorusIntegrand::Gaussian { sigma } => {
                let inv = -0.5 / (sigma * sigma);
                let mut s = 0.0;
                for mx in [-1.0, 0.0, 1.0] {
                    for my in [-1.0, 0.0, 1.0] {
                        let (ax, ay) = (dx + mx, dy + my);
                        s += (inv * (ax * ax + ay * ay)).exp();
                    }
                }
                s
            }
        }
    }
}
