//! The target spectra of [`SpectralBlueNoise`](super::SpectralBlueNoise) ([`Profile`]):
//! the step and the single peak, their realizability bound and the pair correlation each
//! implies (the Hankel transform of the module's documentation).

use super::SPECTRAL_MAX_DIMS;
use crate::blue_noise::bessel::bessel_j_half;
use crate::{Error, Result};

/// The default step's cutoff in units of the realizability bound `V_d^(-1/d)`.
const STEP_CUTOFF: f64 = 0.9995;

/// A target radial power spectrum, frequencies in units of `N^(1/d)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Profile {
    /// `P(u) = 0` for `u < cutoff`, 1 above.
    Step {
        /// The cutoff `u_0`.
        cutoff: f64,
    },
    /// `P = G_sigma * (energy delta(u - cutoff) + H(u - cutoff))`.
    SinglePeak {
        /// The peak's position `u_0`.
        cutoff: f64,
        /// The peak's energy `p_0` (power times frequency).
        energy: f64,
        /// The smoothing `sigma`.
        width: f64,
    },
}

/// The volume of the unit ball of `R^d`: `V_0 = 1`, `V_1 = 2`, `V_d = V_{d-2} 2 pi / d`.
pub fn ball_volume(d: usize) -> f64 {
    let mut v = if d.is_multiple_of(2) { 1.0 } else { 2.0 };
    let mut k = d % 2;
    while k + 2 <= d {
        k += 2;
        v *= 2.0 * core::f64::consts::PI / k as f64;
    }
    v
}

pub(super) fn check_dims(d: usize) -> Result<()> {
    if d == 0 {
        return Err(Error::ZeroDimensions);
    }
    if d > SPECTRAL_MAX_DIMS {
        return Err(Error::DimensionOutOfRange {
            dim: d,
            dims: SPECTRAL_MAX_DIMS,
        });
    }
    Ok(())
}

impl Profile {
    /// The step at `0.886 V_d^(-1/d)` (0.5 in 2D).
    ///
    /// # Errors
    /// As [`SpectralBlueNoise::new`](super::SpectralBlueNoise::new) for `d`.
    pub fn step(d: usize) -> Result<Self> {
        check_dims(d)?;
        Ok(Profile::Step {
            cutoff: STEP_CUTOFF * ball_volume(d).powf(-1.0 / d as f64),
        })
    }

    /// The single peak at `1.33 V_d^(-1/d)` (0.75 in 2D), energy 0.3, width 0.08.
    ///
    /// # Errors
    /// As [`SpectralBlueNoise::new`](super::SpectralBlueNoise::new) for `d`.
    pub fn single_peak(d: usize) -> Result<Self> {
        check_dims(d)?;
        Ok(Profile::SinglePeak {
            cutoff: 1.33 * ball_volume(d).powf(-1.0 / d as f64),
            energy: 0.3,
            width: 0.08,
        })
    }

    pub(super) fn validate(&self) -> Result<()> {
        let ok = match *self {
            Profile::Step { cutoff } => cutoff.is_finite() && cutoff > 0.0 && cutoff <= 4.0,
            Profile::SinglePeak {
                cutoff,
                energy,
                width,
            } => {
                cutoff.is_finite()
                    && cutoff > 0.0
                    && cutoff <= 4.0
                    && energy.is_finite()
                    && (0.0..=10.0).contains(&energy)
                    && width.is_finite()
                    && (0.005..=0.5).contains(&width)
            }
        };
        if ok {
            Ok(())
        } else {
            Err(Error::InvalidParameter {
                what: "a spectral profile needs a cutoff in (0, 4], an energy in [0, 10] and a width in [0.005, 0.5]",
            })
        }
    }

    /// The target power `P(u)` at `u > 0`.
    pub fn power(&self, u: f64) -> f64 {
        match *self {
            Profile::Step { cutoff } => {
                if u < cutoff {
                    0.0
                } else {
                    1.0
                }
            }
            Profile::SinglePeak {
                cutoff,
                energy,
                width,
            } => {
                let z = (u - cutoff) / width;
                let density = (-0.5 * z * z).exp() / (width * (2.0 * core::f64::consts::PI).sqrt());
                energy * density + 0.5 * (1.0 + libm::erf(z / core::f64::consts::SQRT_2))
            }
        }
    }

    /// The range `[0, end]` outside which `P = 1` (to below 1e-16), and the point inside
    /// where `P` jumps (the step's cutoff; the end for the smooth peak).
    pub(super) fn support(&self) -> (f64, f64) {
        match *self {
            Profile::Step { cutoff } => (cutoff, cutoff),
            Profile::SinglePeak { cutoff, width, .. } => {
                (cutoff + 9.0 * width, cutoff + 9.0 * width)
            }
        }
    }

    /// The target pair correlation `G_0(rho)` in `d` dimensions at `rho > 0` (in mean
    /// spacings), by Simpson's rule on the Hankel integral (2000 intervals).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a bad profile or `rho <= 0`; the dimension errors
    /// of [`SpectralBlueNoise::new`](super::SpectralBlueNoise::new); [`Error::InvalidParameter`] when the profile is not
    /// realizable (its `G_0` is negative somewhere in `[0, 4]`).
    pub fn target_pcf(&self, d: usize, rho: f64) -> Result<f64> {
        check_dims(d)?;
        self.validate()?;
        if !(rho.is_finite() && rho > 0.0) {
            return Err(Error::InvalidParameter {
                what: "the pair correlation is evaluated at a positive distance",
            });
        }
        self.realizable(d)?;
        Ok(self.pcf_unchecked(d, rho))
    }

    pub(super) fn realizable(&self, d: usize) -> Result<()> {
        let worst = (1..=400)
            .map(|k| self.pcf_unchecked(d, k as f64 * 0.01))
            .fold(f64::INFINITY, f64::min);
        if worst < -1e-6 {
            return Err(Error::InvalidParameter {
                what: "the spectral profile is not realizable: its pair correlation is negative",
            });
        }
        Ok(())
    }

    pub(super) fn pcf_unchecked(&self, d: usize, rho: f64) -> f64 {
        const M: usize = 2000;
        let (end, _) = self.support();
        let m = d as i32 - 2; // J_{m/2} = J_{d/2-1}
        let half = d as f64 / 2.0;
        let f = |u: f64| {
            if u <= 0.0 {
                // The limit u^(d/2) J_{d/2-1}(2 pi u rho) -> (pi rho)^(d/2-1) u^(d-1) / Gamma(d/2):
                // 1/(pi sqrt(rho)) in 1D, 0 above.
                return if d == 1 {
                    (self.power(0.0) - 1.0) / (core::f64::consts::PI * rho.sqrt())
                } else {
                    0.0
                };
            }
            u.powf(half)
                * (self.power(u) - 1.0)
                * bessel_j_half(m, 2.0 * core::f64::consts::PI * u * rho)
        };
        // For the step the integrand is -u^(d/2) J(..) on [0, cutoff), 0 above: the range
        // ends at the jump, where the left limit is taken.
        let step_at = matches!(self, Profile::Step { .. });
        let du = end / M as f64;
        let mut sum = 0.0;
        for i in 0..=M {
            let u = i as f64 * du;
            let v = if step_at && i == M {
                -(u.powf(half)) * bessel_j_half(m, 2.0 * core::f64::consts::PI * u * rho)
            } else {
                f(u)
            };
            let w = if i == 0 || i == M {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            sum += w * v;
        }
        let integral = sum * du / 3.0;
        1.0 + 2.0 * core::f64::consts::PI * rho.powf(1.0 - half) * integral
    }
}
