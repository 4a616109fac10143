//! Rotated anisotropic Gaussians on the unit square and their reference integrals.
//!
//! `f(x) = exp(-(1/2) (x - c)^T P (x - c))` with the precision matrix
//! `P = R diag(1/s_1^2, 1/s_2^2) R^T`, `R` the rotation by `theta`: a Gaussian with a full
//! covariance `R diag(s_1^2, s_2^2) R^T`, clipped to `[0, 1]^2`. Its integral over the
//! square has no closed form once `theta` is not a multiple of `pi/2`; it is computed here
//! as a one-dimensional integral of a closed-form inner integral.
//!
//! ## The reference integral
//!
//! With `u = x - c_x`, `v = y - c_y` and `P = [[a, b], [b, e]]`, completing the square in
//! `v` gives `u^T P u = e (v + b u / e)^2 + (det P / e) u^2`, so the inner integral over
//! `v in [-c_y, 1 - c_y]` is exact:
//!
//! `g(u) = exp(-det P u^2 / (2 e)) sqrt(pi / (2 e)) [erf(sqrt(e/2) (1 - c_y + b u / e)) - erf(sqrt(e/2) (-c_y + b u / e))]`
//!
//! (the difference of `erf` taken as a difference of `erfc` in a tail, so it keeps its
//! relative accuracy there). The outer integral `int_(-c_x)^(1 - c_x) g(u) du` of this
//! analytic function is taken by adaptive 16-point Gauss–Legendre quadrature: an interval is
//! accepted when its rule and the sum of the rules on its halves differ by less than its
//! share of the tolerance (`1e-13` absolute, halved with each bisection), and the halves'
//! sum is kept. The reported error bound is the sum of those differences over the accepted
//! intervals; for an analytic integrand it overestimates the error of the halves' rules,
//! which is smaller by about `2^-32` (the rule is exact to degree 31). The Gauss–Legendre
//! nodes are the roots of `P_16` by Newton's method on the three-term recurrence, the
//! weights `2 / ((1 - x^2) P_16'(x)^2)`.
//!
//! Checked (tests) against what does not use this quadrature: `theta = 0` against the
//! product of `erf` differences, a Gaussian whose mass lies inside the square against
//! `2 pi s_1 s_2`, and a fine midpoint rule.
//!
//! Cost: a draw takes a few hundred to a few thousand evaluations of `g` (two `erf` and an
//! `exp` each); an evaluation of `f` a few multiplications and one `exp`.

use crate::error::{Error, Result};
use crate::hash::hash3;
use std::vec;

/// The absolute tolerance of the reference integral.
pub const ROTATED_TOLERANCE: f64 = 1e-13;

/// Bisections past which the quadrature gives up (an interval of `2^-40`).
const MAX_DEPTH: u32 = 40;

/// Gauss–Legendre points a rule.
const NODES: usize = 16;

/// A rotated anisotropic Gaussian on the unit square with its reference integral.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct RotatedGaussian {
    centre: [f64; 2],
    /// `P = [[a, b], [b, e]]` as `[a, b, e]`.
    precision: [f64; 3],
    integral: f64,
    error: f64,
}

impl RotatedGaussian {
    /// The Gaussian centred at `centre` with standard deviations `s` along the axes rotated
    /// by `theta`, its integral over the square by the quadrature (see the module).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for widths not positive and finite, a centre or an
    /// angle not finite, or a quadrature that does not meet its tolerance.
    pub(super) fn new(centre: [f64; 2], s: [f64; 2], theta: f64) -> Result<Self> {
        if !s.iter().all(|s| s.is_finite() && *s > 0.0)
            || !centre.iter().all(|c| c.is_finite())
            || !theta.is_finite()
        {
            return Err(Error::InvalidParameter {
                what: "rotated Gaussian: widths positive and finite, centre and angle finite",
            });
        }
        let (sn, cs) = libm::sincos(theta);
        let (p1, p2) = (1.0 / (s[0] * s[0]), 1.0 / (s[1] * s[1]));
        let precision = [
            cs * cs * p1 + sn * sn * p2,
            cs * sn * (p1 - p2),
            sn * sn * p1 + cs * cs * p2,
        ];
        let (integral, error) = square_integral(centre, precision)?;
        Ok(RotatedGaussian {
            centre,
            precision,
            integral,
            error,
        })
    }

    /// The Gaussian of `seed`: centre uniform in the square, widths uniform in
    /// `[0.05, 0.5]` (as the axis-aligned family), angle uniform in `[0, pi)`.
    pub(super) fn draw(seed: u64) -> Result<Self> {
        let u = |k: u64| super::families::unit(hash3(seed, k, 7));
        RotatedGaussian::new(
            [u(0), u(1)],
            [0.05 + 0.45 * u(2), 0.05 + 0.45 * u(3)],
            core::f64::consts::PI * u(4),
        )
    }

    /// `f(x)`.
    pub(super) fn eval(&self, x: &[f64]) -> f64 {
        let (u, v) = (x[0] - self.centre[0], x[1] - self.centre[1]);
        let [a, b, e] = self.precision;
        (-0.5 * (a * u * u + 2.0 * b * u * v + e * v * v)).exp()
    }

    /// The reference integral over the square.
    pub(super) fn integral(&self) -> f64 {
        self.integral
    }

    /// The quadrature's error bound (see the module).
    pub(super) fn error_bound(&self) -> f64 {
        self.error
    }
}

/// `erf(y) - erf(x)` for `x <= y`, as a difference of `erfc` when both are in one tail.
fn erf_diff(x: f64, y: f64) -> f64 {
    if x > 0.0 {
        libm::erfc(x) - libm::erfc(y)
    } else if y < 0.0 {
        libm::erfc(-y) - libm::erfc(-x)
    } else {
        libm::erf(y) - libm::erf(x)
    }
}

/// `(integral, error bound)` of `exp(-(1/2) z^T P z)`, `z = x - centre`, over the square.
fn square_integral(centre: [f64; 2], p: [f64; 3]) -> Result<(f64, f64)> {
    let [a, b, e] = p;
    let det = a * e - b * b;
    if !(det > 0.0 && e > 0.0) {
        return Err(Error::InvalidParameter {
            what: "rotated Gaussian: the precision matrix is not positive definite",
        });
    }
    let (v0, v1) = (-centre[1], 1.0 - centre[1]);
    let r = (e / 2.0).sqrt();
    let scale = (core::f64::consts::PI / (2.0 * e)).sqrt();
    let g = |u: f64| {
        let shift = b * u / e;
        (-0.5 * det / e * u * u).exp() * scale * erf_diff(r * (v0 + shift), r * (v1 + shift))
    };
    let rule = GaussLegendre::new();
    adaptive(&g, &rule, -centre[0], 1.0 - centre[0], ROTATED_TOLERANCE)
}

/// The 16-point Gauss–Legendre rule on `[-1, 1]`.
struct GaussLegendre {
    x: [f64; NODES],
    w: [f64; NODES],
}

impl GaussLegendre {
    /// Nodes by Newton's method from Tricomi's initial guesses `cos(pi (i + 3/4) / (n + 1/2))`.
    fn new() -> Self {
        let n = NODES;
        let mut x = [0.0; NODES];
        let mut w = [0.0; NODES];
        for i in 0..n {
            let mut t = libm::cos(core::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5));
            let mut dp = 1.0;
            for _ in 0..100 {
                // P_n(t) and P_n'(t) by (k+1) P_(k+1) = (2k+1) t P_k - k P_(k-1).
                let (mut p0, mut p1) = (1.0, t);
                for k in 1..n {
                    let k = k as f64;
                    let p2 = ((2.0 * k + 1.0) * t * p1 - k * p0) / (k + 1.0);
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (t * p1 - p0) / (t * t - 1.0);
                let step = p1 / dp;
                t -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            x[i] = t;
            w[i] = 2.0 / ((1.0 - t * t) * dp * dp);
        }
        GaussLegendre { x, w }
    }

    fn apply(&self, f: &impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
        let (m, h) = ((lo + hi) / 2.0, (hi - lo) / 2.0);
        h * self
            .x
            .iter()
            .zip(&self.w)
            .map(|(x, w)| w * f(m + h * x))
            .sum::<f64>()
    }
}

/// Adaptive Gauss–Legendre on `[lo, hi]` to the absolute tolerance `tol` (see the module).
fn adaptive(
    f: &impl Fn(f64) -> f64,
    rule: &GaussLegendre,
    lo: f64,
    hi: f64,
    tol: f64,
) -> Result<(f64, f64)> {
    // An explicit stack: (lo, hi, the rule on it, depth).
    let mut stack = vec![(lo, hi, rule.apply(f, lo, hi), 0u32)];
    let (mut sum, mut err) = (0.0, 0.0);
    while let Some((a, b, whole, depth)) = stack.pop() {
        let m = (a + b) / 2.0;
        let (l, r) = (rule.apply(f, a, m), rule.apply(f, m, b));
        let diff = (l + r - whole).abs();
        // Accepted within its share of the tolerance, or at the rounding of its sum.
        if diff <= tol / f64::from(1u32 << depth.min(31)) || diff <= 4e-16 * (l + r).abs() {
            sum += l + r;
            err += diff;
        } else if depth >= MAX_DEPTH {
            return Err(Error::InvalidParameter {
                what: "rotated Gaussian: the quadrature did not meet its tolerance",
            });
        } else {
            stack.push((a, m, l, depth + 1));
            stack.push((m, b, r, depth + 1));
        }
    }
    if !(sum.is_finite() && err <= tol) {
        return Err(Error::InvalidParameter {
            what: "rotated Gaussian: the quadrature did not meet its tolerance",
        });
    }
    Ok((sum, err))
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::{FRAC_PI_2, PI, SQRT_2};

    /// The closed form of the axis-aligned case: `prod_k s_k sqrt(pi/2) (erf((1 - c_k) /
    /// (s_k sqrt 2)) + erf(c_k / (s_k sqrt 2)))`.
    fn aligned(c: [f64; 2], s: [f64; 2]) -> f64 {
        (0..2)
            .map(|k| {
                let r = 1.0 / (s[k] * SQRT_2);
                s[k] * (PI / 2.0).sqrt() * (libm::erf((1.0 - c[k]) * r) + libm::erf(c[k] * r))
            })
            .product()
    }

    #[test]
    fn gauss_legendre_integrates_polynomials_to_degree_31() {
        let rule = GaussLegendre::new();
        for k in 0..=31 {
            let q = rule.apply(&|x: f64| x.powi(k), -1.0, 1.0);
            let exact = if k % 2 == 1 {
                0.0
            } else {
                2.0 / (k as f64 + 1.0)
            };
            assert!((q - exact).abs() < 1e-14, "x^{k}: {q} vs {exact}");
        }
        let q = rule.apply(&|x: f64| x.powi(32), -1.0, 1.0);
        assert!((q - 2.0 / 33.0).abs() > 1e-12, "degree 32 is not exact");
    }

    #[test]
    fn axis_aligned_matches_the_closed_form() {
        for seed in 0..50u64 {
            let u = |k| super::super::families::unit(hash3(seed, k, 9));
            let c = [u(0), u(1)];
            let s = [0.05 + 0.45 * u(2), 0.05 + 0.45 * u(3)];
            let want = aligned(c, s);
            for (theta, s) in [(0.0, s), (FRAC_PI_2, [s[1], s[0]]), (PI, s)] {
                let g = RotatedGaussian::new(c, s, theta).unwrap();
                assert!(
                    (g.integral() - want).abs() < 2e-13,
                    "seed {seed} theta {theta}: {} vs {want}",
                    g.integral()
                );
                assert!(g.error_bound() <= ROTATED_TOLERANCE);
            }
        }
    }

    /// Narrow Gaussians at the centre hold all but `exp(-0.5 (0.5 / 0.06)^2)`, about 1e-15,
    /// of their mass `2 pi s_1 s_2` in the square, at every angle.
    #[test]
    fn inner_gaussians_hold_their_whole_mass() {
        for k in 0..40 {
            let theta = PI * k as f64 / 40.0 + 0.01;
            let s = [0.02 + 0.001 * k as f64, 0.06 - 0.001 * k as f64];
            let g = RotatedGaussian::new([0.5, 0.5], s, theta).unwrap();
            let want = 2.0 * PI * s[0] * s[1];
            assert!(
                (g.integral() - want).abs() < 1e-13,
                "theta {theta}: {} vs {want}",
                g.integral()
            );
        }
    }

    /// A midpoint rule on a 2048 x 2048 grid (error about `h^2/24` times the Laplacian's
    /// integral, below 1e-6 for widths of at least 0.05) agrees with the drawn integrands.
    #[test]
    fn drawn_gaussians_match_a_fine_midpoint_rule() {
        let k = 2048;
        for seed in 0..12u64 {
            let g = RotatedGaussian::draw(seed).unwrap();
            let mut sum = 0.0;
            for i in 0..k {
                for j in 0..k {
                    let x = [(i as f64 + 0.5) / k as f64, (j as f64 + 0.5) / k as f64];
                    sum += g.eval(&x);
                }
            }
            let mid = sum / (k * k) as f64;
            assert!(
                (mid - g.integral()).abs() < 1e-6,
                "seed {seed}: {mid} vs {}",
                g.integral()
            );
        }
    }

    #[test]
    fn bad_parameters_are_refused() {
        assert!(RotatedGaussian::new([0.5, 0.5], [0.0, 0.1], 0.0).is_err());
        assert!(RotatedGaussian::new([0.5, f64::NAN], [0.1, 0.1], 0.0).is_err());
        assert!(RotatedGaussian::new([0.5, 0.5], [0.1, 0.1], f64::INFINITY).is_err());
    }
}
