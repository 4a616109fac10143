//! Integration error on test integrands with known integrals over `[0, 1]^d`: how far the
//! point set's average `(1/N) sum_i f(x_i)` lies from `I(f) = integral of f`, the quantity
//! convergence plots show against `N`.
//!
//! | integrand | `f(x)` | `I(f)` | smoothness |
//! |---|---|---|---|
//! | [`Integrand::Gaussian`] | `exp(-a^2 sum_k (x_k - 1/2)^2)`, `a = 4` (Genz's Gaussian peak) | `(sqrt(pi) erf(a/2) / a)^d` | analytic |
//! | [`Integrand::Oscillatory`] | `cos(2 pi u + a sum_k x_k)`, `u = 0.3`, `a = 2` (Genz's oscillatory) | `Re(e^(2 pi i u) z^d)`, `z = (e^(i a) - 1) / (i a)` | analytic |
//! | [`Integrand::Ball`] | 1 inside the ball of radius `0.45` about the centre, else 0 | `V_d = V_(d-2) 2 pi r^2 / d`, `V_0 = 1`, `V_1 = 2r` | discontinuous, smooth boundary |
//! | [`Integrand::Heaviside`] | 1 where `sum_k w_k (x_k - 1/2) >= 0`, `w_k = sqrt(k + 2)`, else 0 | `1/2` (the cube is symmetric about its centre) | discontinuous, oblique plane |
//!
//! (A. Genz, "Testing multidimensional integration routines", 1984, for the smooth two;
//! the indicators after UTK's integration tests and Owen's "Practical QMC".) The smooth
//! integrands show QMC's near `O(N^-1)` (and, scrambled, `O(N^-3/2)` in RMSE) against Monte
//! Carlo's `O(N^-1/2)`; the discontinuous ones cap QMC near `O(N^-3/4)` in 2D.
//!
//! Cost `O(N d)`; no allocation.

use crate::analysis::Points;

/// A test integrand on `[0, 1]^d` with a closed-form integral (see the module table).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrand {
    /// Genz's Gaussian peak, `exp(-16 |x - c|^2)`, `c` the centre.
    Gaussian,
    /// Genz's oscillatory, `cos(0.6 pi + 2 sum_k x_k)`.
    Oscillatory,
    /// The indicator of the ball of radius 0.45 about the centre.
    Ball,
    /// The indicator of the half-space `sum_k sqrt(k + 2) (x_k - 1/2) >= 0`.
    Heaviside,
}

/// `a` of the Gaussian peak.
const PEAK: f64 = 4.0;
/// `u` and `a` of the oscillatory integrand.
const SHIFT: f64 = 0.3;
const FREQUENCY: f64 = 2.0;
/// Radius of the ball.
const RADIUS: f64 = 0.45;

impl Integrand {
    /// Every integrand, in the order of the module table.
    pub const ALL: [Integrand; 4] = [
        Integrand::Gaussian,
        Integrand::Oscillatory,
        Integrand::Ball,
        Integrand::Heaviside,
    ];

    /// `f(x)` for a point `x` in `[0, 1]^d`.
    ///
    /// ```
    /// use qmckit::analysis::integrate::Integrand;
    /// assert_eq!(Integrand::Gaussian.eval(&[0.5, 0.5]), 1.0);
    /// assert_eq!(Integrand::Ball.eval(&[0.5, 0.96]), 0.0);
    /// // sqrt(2) 0.1 - sqrt(3) 0.1 < 0 <= sqrt(2) 0.1:
    /// assert_eq!(Integrand::Heaviside.eval(&[0.6, 0.4]), 0.0);
    /// assert_eq!(Integrand::Heaviside.eval(&[0.6, 0.5]), 1.0);
    /// ```
    pub fn eval(self, x: &[f64]) -> f64 {
        match self {
            Integrand::Gaussian => {
                let r2: f64 = x.iter().map(|&t| (t - 0.5) * (t - 0.5)).sum();
                libm::exp(-PEAK * PEAK * r2)
            }
            Integrand::Oscillatory => {
                let s: f64 = x.iter().sum();
                libm::cos(core::f64::consts::TAU * SHIFT + FREQUENCY * s)
            }
            Integrand::Ball => {
                let r2: f64 = x.iter().map(|&t| (t - 0.5) * (t - 0.5)).sum();
                if r2 <= RADIUS * RADIUS { 1.0 } else { 0.0 }
            }
            Integrand::Heaviside => {
                let s: f64 = x
                    .iter()
                    .enumerate()
                    .map(|(k, &t)| libm::sqrt(k as f64 + 2.0) * (t - 0.5))
                    .sum();
                if s >= 0.0 { 1.0 } else { 0.0 }
            }
        }
    }

    /// `I(f)`, the integral over `[0, 1]^d` (closed forms of the module table).
    ///
    /// ```
    /// use qmckit::analysis::integrate::Integrand;
    /// let disk = core::f64::consts::PI * 0.45 * 0.45;
    /// assert!((Integrand::Ball.exact(2) - disk).abs() < 1e-15);
    /// assert_eq!(Integrand::Heaviside.exact(7), 0.5);
    /// ```
    pub fn exact(self, d: usize) -> f64 {
        match self {
            Integrand::Gaussian => {
                let one = libm::sqrt(core::f64::consts::PI) * libm::erf(PEAK / 2.0) / PEAK;
                libm::pow(one, d as f64)
            }
            Integrand::Oscillatory => {
                // z = (e^(ia) - 1) / (ia) = sin(a)/a + i (1 - cos(a))/a, then polar powers.
                let (s, c) = (libm::sin(FREQUENCY), libm::cos(FREQUENCY));
                let (re, im) = (s / FREQUENCY, (1.0 - c) / FREQUENCY);
                let (modulus, arg) = (libm::hypot(re, im), libm::atan2(im, re));
                let phase = core::f64::consts::TAU * SHIFT + d as f64 * arg;
                libm::pow(modulus, d as f64) * libm::cos(phase)
            }
            Integrand::Ball => {
                let step = core::f64::consts::TAU * RADIUS * RADIUS;
                let mut v = if d.is_multiple_of(2) {
                    1.0
                } else {
                    2.0 * RADIUS
                };
                let mut k = 2 + d % 2;
                while k <= d {
                    v *= step / k as f64;
                    k += 2;
                }
                v
            }
            Integrand::Heaviside => 0.5,
        }
    }

    /// The command-line name (`gaussian`, `oscillatory`, `ball`, `heaviside`).
    pub fn name(self) -> &'static str {
        match self {
            Integrand::Gaussian => "gaussian",
            Integrand::Oscillatory => "oscillatory",
            Integrand::Ball => "ball",
            Integrand::Heaviside => "heaviside",
        }
    }
}

/// The signed integration error `(1/N) sum_i f(x_i) - I(f)` of the set (0 points: `-I(f)`).
///
/// ```
/// use qmckit::analysis::{Points, integrate::{Integrand, integration_error}};
/// // The centre alone: the Gaussian peak's value 1 against its integral
/// // (sqrt(pi) erf(2) / 4)^2 = 0.4410...^2 = 0.1945...
/// let e = integration_error(Points::new(&[0.5, 0.5], 2)?, Integrand::Gaussian);
/// assert!((e - (1.0 - Integrand::Gaussian.exact(2))).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn integration_error(points: Points<'_>, f: Integrand) -> f64 {
    let sum: f64 = points.iter().map(|x| f.eval(x)).sum();
    sum / points.len().max(1) as f64 - f.exact(points.dims())
}
