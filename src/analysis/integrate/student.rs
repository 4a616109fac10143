//! Student's t distribution: the two-sided quantile for integer degrees of freedom.

use crate::error::{Error, Result};

/// `P(|T| <= t)` for Student's `T` with `nu >= 1` degrees of freedom, by the finite series
/// of Abramowitz & Stegun 26.7.3-4 in `theta = atan(t / sqrt(nu))`:
/// odd `nu`: `(2/pi) (theta + sin theta (cos theta + (2/3) cos^3 theta + ..))`,
/// even `nu`: `sin theta (1 + (1/2) cos^2 theta + (1 3)/(2 4) cos^4 theta + ..)`,
/// `nu / 2` terms. `O(nu)`.
pub fn two_sided_cdf(t: f64, nu: u32) -> f64 {
    let theta = (t.abs() / f64::from(nu).sqrt()).atan();
    let (s, c) = theta.sin_cos();
    let c2 = c * c;
    if nu % 2 == 1 {
        if nu == 1 {
            return 2.0 * theta / core::f64::consts::PI;
        }
        // cos + (2/3) cos^3 + (2 4)/(3 5) cos^5 + .. up to cos^(nu-2).
        let (mut term, mut sum) = (c, c);
        let mut k = 1;
        while k + 2 < nu {
            term *= c2 * f64::from(k + 1) / f64::from(k + 2);
            sum += term;
            k += 2;
        }
        2.0 / core::f64::consts::PI * (theta + s * sum)
    } else {
        let (mut term, mut sum) = (1.0, 1.0);
        let mut k = 1;
        while k + 1 < nu {
            term *= c2 * f64::from(k) / f64::from(k + 1);
            sum += term;
            k += 2;
        }
        s * sum
    }
}

/// The two-sided Student-t quantile: the `t > 0` with `P(|T| <= t) = level`, by bisection on
/// [`two_sided_cdf`] to `1e-12` relative. `t_(0.95, 1) = 12.706`, `t_(0.95, 15) = 2.131`.
///
/// ```
/// use qmckit::analysis::integrate::t_quantile;
/// assert!((t_quantile(0.95, 15)? - 2.131_449_545_559_323).abs() < 1e-9);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for `nu = 0` or a level outside `(0, 1)`.
pub fn t_quantile(level: f64, nu: u32) -> Result<f64> {
    if nu == 0 || !(level > 0.0 && level < 1.0) {
        return Err(Error::InvalidParameter {
            what: "a Student-t quantile needs nu >= 1 and a level in (0, 1)",
        });
    }
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    while two_sided_cdf(hi, nu) < level {
        hi *= 2.0;
        if hi > 1e300 {
            return Err(Error::NotRepresentable {
                what: "Student-t quantile",
            });
        }
    }
    while hi - lo > 1e-12 * hi {
        let mid = 0.5 * (lo + hi);
        if two_sided_cdf(mid, nu) < level {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}
