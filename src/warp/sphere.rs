//! Directions: uniform sphere, uniform and cosine-weighted hemisphere (around +z), and the
//! uniform cone around +z. Densities are per unit solid angle.

use super::disk::{invert_uniform_disk_concentric, sample_uniform_disk_concentric};
use super::{PI, turn_fraction};

/// Density of a uniform direction on the sphere: `1 / 4 pi`.
pub const UNIFORM_SPHERE_PDF: f32 = 1.0 / (4.0 * PI);

/// Density of a uniform direction on the hemisphere: `1 / 2 pi`.
pub const UNIFORM_HEMISPHERE_PDF: f32 = 1.0 / (2.0 * PI);

/// A point `(r cos phi, r sin phi, z)` with `r = sqrt(1 - z^2)`, `phi = 2 pi u1`.
#[inline]
fn around_z(z: f32, u1: f32) -> [f32; 3] {
    // (1 - z)(1 + z) rather than 1 - z^2: no cancellation near the poles.
    let r = libm::sqrtf(((1.0 - z) * (1.0 + z)).max(0.0));
    let (s, c) = libm::sincosf(2.0 * PI * u1);
    [r * c, r * s, z]
}

/// Uniform direction: `z = 1 - 2 u0`, `phi = 2 pi u1` (Archimedes: `z` is uniform).
///
/// ```
/// use qmckit::warp::sphere::sample_uniform_sphere;
/// let w = sample_uniform_sphere([0.5, 0.0]);
/// assert!((w[0] - 1.0).abs() < 1e-6 && w[2].abs() < 1e-6);
/// ```
#[inline]
pub fn sample_uniform_sphere(u: [f32; 2]) -> [f32; 3] {
    around_z(1.0 - 2.0 * u[0], u[1])
}

/// Inverse of [`sample_uniform_sphere`].
#[inline]
pub fn invert_uniform_sphere(w: [f32; 3]) -> [f32; 2] {
    [(1.0 - w[2]) / 2.0, turn_fraction(w[1], w[0])]
}

/// Uniform direction on the hemisphere `z >= 0`: `z = u0`, `phi = 2 pi u1`.
#[inline]
pub fn sample_uniform_hemisphere(u: [f32; 2]) -> [f32; 3] {
    around_z(u[0], u[1])
}

/// Inverse of [`sample_uniform_hemisphere`].
#[inline]
pub fn invert_uniform_hemisphere(w: [f32; 3]) -> [f32; 2] {
    [w[2], turn_fraction(w[1], w[0])]
}

/// Cosine-weighted direction on the hemisphere `z >= 0` (density `cos theta / pi`): a
/// concentric-disk point lifted to the hemisphere (Malley's method), which keeps the disk
/// map's low distortion.
///
/// ```
/// use qmckit::warp::sphere::{cosine_hemisphere_pdf, sample_cosine_hemisphere};
/// let w = sample_cosine_hemisphere([0.5, 0.5]);
/// assert_eq!(w, [0.0, 0.0, 1.0]);
/// assert!((cosine_hemisphere_pdf(w[2]) - 1.0 / std::f32::consts::PI).abs() < 1e-7);
/// ```
#[inline]
pub fn sample_cosine_hemisphere(u: [f32; 2]) -> [f32; 3] {
    let d = sample_uniform_disk_concentric(u);
    // The disk point's radius is max(|2 u0 - 1|, |2 u1 - 1|), exact in f32: z from it keeps
    // full precision at the rim, where 1 - x^2 - y^2 would cancel.
    let r = (2.0 * u[0] - 1.0).abs().max((2.0 * u[1] - 1.0).abs());
    let z = libm::sqrtf(((1.0 - r) * (1.0 + r)).max(0.0));
    [d[0], d[1], z]
}

/// Density of [`sample_cosine_hemisphere`] at a direction with `cos theta = z`: `z / pi`.
#[inline]
pub fn cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    cos_theta.max(0.0) / PI
}

/// Inverse of [`sample_cosine_hemisphere`]: the concentric inverse of the direction's
/// projection onto the disk.
#[inline]
pub fn invert_cosine_hemisphere(w: [f32; 3]) -> [f32; 2] {
    invert_uniform_disk_concentric([w[0], w[1]])
}

/// `cos theta_max` clamped into `[-1, 1]`; NaN reads as 1 (the degenerate cone, +z).
#[inline]
fn cone_cos(cos_theta_max: f32) -> f32 {
    if cos_theta_max >= -1.0 {
        cos_theta_max.min(1.0)
    } else if cos_theta_max < -1.0 {
        -1.0
    } else {
        1.0
    }
}

/// Uniform direction in the cone of half-angle `theta_max` around +z (given as
/// `cos theta_max` in `[-1, 1]`): `cos theta = 1 - u0 (1 - cos theta_max)`, `phi = 2 pi u1`.
/// A unit vector for every `u` in `[0, 1]^2` and every `cos_theta_max`: values outside
/// `[-1, 1]` are clamped into it, NaN reads as 1 ([`UniformCone::new`] refuses both).
///
/// ```
/// use qmckit::warp::sphere::{sample_uniform_cone, uniform_cone_pdf};
/// let w = sample_uniform_cone([0.999, 0.25], 0.5);
/// assert!(w[2] >= 0.5 && w[2] <= 1.0);
/// assert!((uniform_cone_pdf(0.5) - 1.0 / std::f32::consts::PI).abs() < 1e-6); // 1/(2 pi 0.5)
/// ```
#[inline]
pub fn sample_uniform_cone(u: [f32; 2], cos_theta_max: f32) -> [f32; 3] {
    let z = 1.0 - u[0] * (1.0 - cone_cos(cos_theta_max));
    around_z(z, u[1])
}

/// Density of [`sample_uniform_cone`]: `1 / (2 pi (1 - cos theta_max))` (the cone's solid
/// angle inverted; infinite for a degenerate cone, `cos theta_max = 1`).
#[inline]
pub fn uniform_cone_pdf(cos_theta_max: f32) -> f32 {
    1.0 / (2.0 * PI * (1.0 - cone_cos(cos_theta_max)))
}

/// Inverse of [`sample_uniform_cone`]; `u0 = 0` for a degenerate cone.
#[inline]
pub fn invert_uniform_cone(w: [f32; 3], cos_theta_max: f32) -> [f32; 2] {
    let span = 1.0 - cone_cos(cos_theta_max);
    let u0 = if span > 0.0 { (1.0 - w[2]) / span } else { 0.0 };
    [u0, turn_fraction(w[1], w[0])]
}

/// The cone of directions within `theta_max` of +z, validated once: `cos theta_max`
/// finite and in `[-1, 1)`, so that the density `1 / (2 pi (1 - cos theta_max))` is finite
/// (at most `2^24 / 2 pi`; `-1` is the whole sphere).
///
/// ```
/// use qmckit::warp::sphere::UniformCone;
/// let cone = UniformCone::from_half_angle(60f32.to_radians())?;
/// let w = cone.sample([0.5, 0.0]);
/// assert!((w[2] - 0.75).abs() < 1e-6); // cos theta = 1 - 0.5 (1 - 0.5)
/// assert!(UniformCone::new(f32::NAN).is_err() && UniformCone::new(1.0).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct UniformCone {
    cos_theta_max: f32,
}

impl UniformCone {
    /// The cone with `cos theta_max = cos_theta_max`.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] unless `cos_theta_max` is in `[-1, 1)`.
    pub fn new(cos_theta_max: f32) -> crate::Result<Self> {
        if (-1.0..1.0).contains(&cos_theta_max) {
            Ok(UniformCone { cos_theta_max })
        } else if cos_theta_max == 1.0 {
            Err(crate::Error::InvalidParameter {
                what: "the cone is degenerate: cos(theta_max) rounds to 1 in f32 \
                       (a half-angle below about 2.5e-4 rad, 0.014 degrees)",
            })
        } else {
            Err(crate::Error::InvalidParameter {
                what: "the cone's cos(theta_max) must be in [-1, 1) (a half-angle in (0, pi])",
            })
        }
    }

    /// The cone of half-angle `theta_max` radians, in `(0, pi]`, through `cosf`.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] unless `theta_max` is in `(0, pi]` and large
    /// enough that `cos theta_max` rounds below 1 (about `2.5e-4` rad).
    pub fn from_half_angle(theta_max: f32) -> crate::Result<Self> {
        if theta_max > 0.0 && theta_max <= PI {
            Self::new(libm::cosf(theta_max))
        } else {
            Err(crate::Error::InvalidParameter {
                what: "the cone's half-angle must be in (0, pi]",
            })
        }
    }

    /// `cos theta_max`.
    pub fn cos_theta_max(&self) -> f32 {
        self.cos_theta_max
    }

    /// [`sample_uniform_cone`]: a unit vector within the cone.
    #[inline]
    pub fn sample(&self, u: [f32; 2]) -> [f32; 3] {
        sample_uniform_cone(u, self.cos_theta_max)
    }

    /// [`uniform_cone_pdf`]: finite.
    #[inline]
    pub fn pdf(&self) -> f32 {
        uniform_cone_pdf(self.cos_theta_max)
    }

    /// [`invert_uniform_cone`].
    #[inline]
    pub fn invert(&self, w: [f32; 3]) -> [f32; 2] {
        invert_uniform_cone(w, self.cos_theta_max)
    }
}
