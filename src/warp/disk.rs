//! The unit disk: polar and concentric (Shirley & Chiu 1997) maps, density `1 / pi`.

use super::{PI, turn_fraction};

/// Density of a uniform point on the unit disk, per unit area: `1 / pi`.
pub const UNIFORM_DISK_PDF: f32 = 1.0 / PI;

/// The polar map: `theta = 2 pi u0`, `r = sqrt(u1)`, `(r cos theta, r sin theta)`.
/// Simple, but it stretches strata near the centre and splits them across the seam
/// `theta = 0`.
///
/// ```
/// use qmckit::warp::disk::{invert_uniform_disk_polar, sample_uniform_disk_polar};
/// let p = sample_uniform_disk_polar([0.25, 0.81]);
/// assert!((p[0]).abs() < 1e-6 && (p[1] - 0.9).abs() < 1e-6); // a quarter turn, r = 0.9
/// let u = invert_uniform_disk_polar(p);
/// assert!((u[0] - 0.25).abs() < 1e-6 && (u[1] - 0.81).abs() < 1e-6);
/// ```
#[inline]
pub fn sample_uniform_disk_polar(u: [f32; 2]) -> [f32; 2] {
    let r = libm::sqrtf(u[1]);
    let (s, c) = libm::sincosf(2.0 * PI * u[0]);
    [r * c, r * s]
}

/// Inverse of [`sample_uniform_disk_polar`]: `u0 = atan2(y, x) / 2 pi` in `[0, 1)`,
/// `u1 = x^2 + y^2`. Undefined angle at the centre (returns `u0 = 0`).
#[inline]
pub fn invert_uniform_disk_polar(p: [f32; 2]) -> [f32; 2] {
    [turn_fraction(p[1], p[0]), p[0] * p[0] + p[1] * p[1]]
}

/// The concentric map: squares of `[-1, 1]^2` (from `2u - 1`) to circles, with the angle
/// proportional to the position along the square's edge. Area-preserving and low-distortion:
/// neighbouring strata stay neighbours and compact.
///
/// ```
/// use qmckit::warp::disk::{invert_uniform_disk_concentric, sample_uniform_disk_concentric};
/// assert_eq!(sample_uniform_disk_concentric([0.5, 0.5]), [0.0, 0.0]);
/// let p = sample_uniform_disk_concentric([1.0, 0.5]); // the middle of the right edge
/// assert!((p[0] - 1.0).abs() < 1e-6 && p[1].abs() < 1e-6);
/// let u = invert_uniform_disk_concentric(sample_uniform_disk_concentric([0.3, 0.9]));
/// assert!((u[0] - 0.3).abs() < 1e-5 && (u[1] - 0.9).abs() < 1e-5);
/// ```
#[inline]
pub fn sample_uniform_disk_concentric(u: [f32; 2]) -> [f32; 2] {
    let (a, b) = (2.0 * u[0] - 1.0, 2.0 * u[1] - 1.0);
    if a == 0.0 && b == 0.0 {
        return [0.0, 0.0];
    }
    let (r, theta) = if a.abs() > b.abs() {
        (a, PI / 4.0 * (b / a))
    } else {
        (b, PI / 2.0 - PI / 4.0 * (a / b))
    };
    let (s, c) = libm::sincosf(theta);
    [r * c, r * s]
}

/// Inverse of [`sample_uniform_disk_concentric`]: find the square's edge from the angle
/// octant, then the position along it.
#[inline]
pub fn invert_uniform_disk_concentric(p: [f32; 2]) -> [f32; 2] {
    let r = libm::sqrtf(p[0] * p[0] + p[1] * p[1]);
    let mut phi = libm::atan2f(p[1], p[0]);
    if phi < -PI / 4.0 {
        phi += 2.0 * PI;
    }
    let k = 4.0 / PI;
    let (a, b) = if phi < PI / 4.0 {
        (r, phi * k * r)
    } else if phi < 3.0 * PI / 4.0 {
        (-(phi - PI / 2.0) * k * r, r)
    } else if phi < 5.0 * PI / 4.0 {
        (-r, -(phi - PI) * k * r)
    } else {
        ((phi - 3.0 * PI / 2.0) * k * r, -r)
    };
    [(a + 1.0) / 2.0, (b + 1.0) / 2.0]
}
