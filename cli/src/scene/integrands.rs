//! The per-pixel integrands of the studies, and the closed forms they are checked against.
//!
//! Every integrand maps a point `u` of `[0, 1)^d` to a pixel value; the pixel is its
//! integral over the cube, estimated by the mean over a pixel's `spp` samples.
//!
//! | integrand | `d` | dimensions | value |
//! |---|---|---|---|
//! | [`Integrand::PixelArea`] | 2 | film position in the pixel | unshadowed direct light at the first hit, `rho / pi E(x)` ([`lambert_irradiance`]) |
//! | [`Integrand::SoftShadow`] | 2 | a point on the quad light (pixel center fixed) | the area estimator `rho / pi L_e A V cos(theta_x) cos(theta_l) / r^2` |
//! | [`Integrand::MotionDefocus`] | 5 | film (2), lens (2), shutter time (1) | as `PixelArea`, the spheres moving |
//! | [`Integrand::PixelLight`] | 4 | film (2), light (2) | the area estimator at the hit of the film sample |
//! | [`Integrand::AmbientOcclusion`] | 2 | a cosine-weighted direction (pixel center fixed) | `V(x, w)`, so the pixel is `(1/pi) int V cos(theta) dw` |
//!
//! Rays that escape see the sky radiance (ambient occlusion: 1), rays that reach the
//! light's emitting side its radiance. Cost: O(spheres) a sample (one camera ray and at
//! most one shadow ray), plus the O(1) polygon formula for the unshadowed integrands.

use super::camera::Camera;
use super::geometry::{Plane, Quad, RAY_EPSILON, Ray, Scene, Sphere, Surface, V3};
use core::f64::consts::PI;

/// Irradiance at `x` (unit normal `n`) from the polygon `poly` of uniform radiance
/// `radiance`, unoccluded, by Lambert's formula `E = (L / 2) sum_i Theta_i (n . Gamma_i)`:
/// `Theta_i` the angle the edge `(v_i, v_{i+1})` subtends at `x`, `Gamma_i` the unit normal of
/// the plane through `x` and that edge. The polygon is first clipped to the half-space
/// above `x`'s tangent plane (Sutherland–Hodgman), so partly hidden lights are exact too.
/// A one-sided emitter is the caller's business (see [`light_irradiance`]). O(vertices).
///
/// ```
/// use qmckit_cli::scene::geometry::V3;
/// use qmckit_cli::scene::integrands::lambert_irradiance;
/// // A huge square far above: nearly the whole hemisphere, E -> pi L.
/// let s = 1e6;
/// let sq = [V3::new(-s, 1.0, -s), V3::new(s, 1.0, -s), V3::new(s, 1.0, s), V3::new(-s, 1.0, s)];
/// let e = lambert_irradiance(V3::new(0.0, 0.0, 0.0), V3::new(0.0, 1.0, 0.0), &sq, 1.0);
/// assert!((e - std::f64::consts::PI).abs() < 1e-5);
/// ```
pub fn lambert_irradiance(x: V3, n: V3, poly: &[V3], radiance: f64) -> f64 {
    // Clip against n . (v - x) >= 0.
    let mut clipped: Vec<V3> = Vec::with_capacity(poly.len() + 2);
    for (i, &a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        let (da, db) = (n.dot(a - x), n.dot(b - x));
        if da >= 0.0 {
            clipped.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            let t = da / (da - db);
            clipped.push(a + (b - a) * t);
        }
    }
    if clipped.len() < 3 {
        return 0.0;
    }
    let mut sum = 0.0;
    for (i, &a) in clipped.iter().enumerate() {
        let b = clipped[(i + 1) % clipped.len()];
        let (ra, rb) = ((a - x).normalize(), (b - x).normalize());
        let c = ra.cross(rb);
        let len = c.length();
        if len == 0.0 {
            continue;
        }
        let theta = len.atan2(ra.dot(rb));
        sum += theta * n.dot(c) / len;
    }
    0.5 * radiance * sum.abs()
}

/// Irradiance at `x` (normal `n`) from the scene's quad light without shadows: zero behind
/// the emitting side, else [`lambert_irradiance`] of its corners.
pub fn light_irradiance(scene: &Scene, x: V3, n: V3) -> f64 {
    if scene.light.normal().dot(x - scene.light.corner) <= 0.0 {
        return 0.0;
    }
    lambert_irradiance(x, n, &scene.light.corners(), scene.radiance)
}

/// One area sample of the irradiance at `x` (normal `n`) from the quad light: the point
/// `y = p_0 + u_0 e_x + u_1 e_y` (density `1 / A`) gives `L_e A V(x, y) cos(theta_x)
/// cos(theta_y) / |y - x|^2`, an unbiased estimator of the (shadowed) irradiance.
/// `shadows = false` skips the visibility test. One shadow ray.
pub fn light_sample(scene: &Scene, x: V3, n: V3, u: [f64; 2], time: f64, shadows: bool) -> f64 {
    let q: &Quad = &scene.light;
    let y = q.point(u[0], u[1]);
    let d = y - x;
    let r2 = d.dot(d);
    if r2 == 0.0 {
        return 0.0;
    }
    let r = r2.sqrt();
    let w = d * (1.0 / r);
    let cos_x = n.dot(w);
    let cos_y = -q.normal().dot(w);
    if cos_x <= 0.0 || cos_y <= 0.0 {
        return 0.0;
    }
    if shadows {
        let ray = Ray {
            origin: x + n * RAY_EPSILON,
            dir: w,
        };
        if scene.occluded(&ray, time, r * (1.0 - 1e-9)) {
            return 0.0;
        }
    }
    scene.radiance * q.area() * cos_x * cos_y / r2
}

/// An orthonormal basis `(t, b)` completing the unit vector `n` (Duff et al. 2017).
pub fn basis(n: V3) -> (V3, V3) {
    let sign = 1f64.copysign(n.z);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    (
        V3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        V3::new(b, sign + n.y * n.y * a, -n.y),
    )
}

/// The cosine-weighted direction around `n` for `u` (the crate's
/// [`qmckit::warp::sphere::sample_cosine_hemisphere`], rotated to `n`).
pub fn cosine_direction(n: V3, u: [f64; 2]) -> V3 {
    let w = qmckit::warp::sphere::sample_cosine_hemisphere([u[0] as f32, u[1] as f32]);
    let (t, b) = basis(n);
    (t * w[0] as f64 + b * w[1] as f64 + n * w[2] as f64).normalize()
}

/// One ambient-occlusion sample at `x` (normal `n`): 1 when the cosine-weighted direction
/// for `u` escapes every sphere and the ground, else 0. Its mean is
/// `(1 / pi) int_Omega V(w) cos(theta) dw` (1 for an unoccluded point, exactly).
pub fn ao_sample(scene: &Scene, x: V3, n: V3, u: [f64; 2], time: f64) -> f64 {
    let ray = Ray {
        origin: x + n * RAY_EPSILON,
        dir: cosine_direction(n, u),
    };
    if scene.occluded(&ray, time, f64::INFINITY) {
        0.0
    } else {
        1.0
    }
}

/// The integrand of a study (see the [module documentation](self)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Integrand {
    /// Film position (2D), unshadowed analytic direct light.
    PixelArea,
    /// Light position (2D) at the pixel center's hit.
    SoftShadow,
    /// Film (2D), lens (2D), time (1D): motion blur and defocus, unshadowed direct light.
    MotionDefocus,
    /// Film (2D) x light (2D).
    PixelLight,
    /// Cosine-weighted direction (2D) at the pixel center's hit: ambient occlusion.
    AmbientOcclusion,
}

impl Integrand {
    /// Dimensions of `u`.
    pub const fn dims(self) -> usize {
        match self {
            Integrand::PixelArea | Integrand::SoftShadow | Integrand::AmbientOcclusion => 2,
            Integrand::PixelLight => 4,
            Integrand::MotionDefocus => 5,
        }
    }

    /// The value for pixel `(x, y)` at `u` (`u.len() >= dims()`).
    pub fn eval(self, scene: &Scene, camera: &Camera, x: u32, y: u32, u: &[f64]) -> f64 {
        let (fx, fy) = (x as f64, y as f64);
        let center = [fx + 0.5, fy + 0.5];
        let (film, lens, time) = match self {
            Integrand::PixelArea | Integrand::PixelLight => ([fx + u[0], fy + u[1]], [0.5; 2], 0.0),
            Integrand::MotionDefocus => ([fx + u[0], fy + u[1]], [u[2], u[3]], u[4]),
            Integrand::SoftShadow | Integrand::AmbientOcclusion => (center, [0.5; 2], 0.0),
        };
        let ray = camera.ray(film[0], film[1], lens);
        let ao = self == Integrand::AmbientOcclusion;
        match scene.intersect(&ray, time) {
            Surface::Sky => {
                if ao {
                    1.0
                } else {
                    scene.sky
                }
            }
            Surface::Light => {
                if ao {
                    1.0
                } else {
                    scene.radiance
                }
            }
            Surface::Diffuse {
                point,
                normal,
                albedo,
            } => match self {
                Integrand::PixelArea | Integrand::MotionDefocus => {
                    albedo / PI * light_irradiance(scene, point, normal)
                }
                Integrand::SoftShadow => {
                    albedo / PI * light_sample(scene, point, normal, [u[0], u[1]], time, true)
                }
                Integrand::PixelLight => {
                    albedo / PI * light_sample(scene, point, normal, [u[2], u[3]], time, true)
                }
                Integrand::AmbientOcclusion => ao_sample(scene, point, normal, [u[0], u[1]], time),
            },
        }
    }
}

/// The studies' scene: three spheres (the left one moving to the right over the shutter)
/// on a checkerboard ground, lit by a 1.5 x 1 quad light of radiance 4 at height 2.6
/// (above the top of the frame), sky radiance 0.1.
pub fn standard_scene() -> Scene {
    let mut moving = Sphere::new(V3::new(-1.5, 0.45, 0.9), 0.45, 0.7);
    moving.velocity = V3::new(0.6, 0.0, 0.0);
    Scene {
        spheres: vec![
            Sphere::new(V3::new(0.0, 0.6, 0.0), 0.6, 0.8),
            moving,
            Sphere::new(V3::new(1.4, 0.5, -1.3), 0.5, 0.6),
        ],
        ground: Some(Plane {
            height: 0.0,
            check: 0.5,
            albedo: (0.75, 0.35),
        }),
        light: Quad {
            corner: V3::new(-0.5, 2.6, -0.5),
            ex: V3::new(1.5, 0.0, 0.0),
            ey: V3::new(0.0, 0.0, 1.0),
        },
        radiance: 4.0,
        sky: 0.1,
    }
}

/// The studies' camera for a `width x height` image: from `(0, 1.6, 5)` towards
/// `(0, 0.5, 0)`, 35 degrees vertical field of view; `lens` adds a thin lens of radius 0.12
/// focused on the center sphere (for the motion-blur and defocus study).
///
/// # Errors
/// As [`Camera::look_at`].
pub fn standard_camera(width: u32, height: u32, lens: bool) -> qmckit::Result<Camera> {
    let eye = V3::new(0.0, 1.6, 5.0);
    let target = V3::new(0.0, 0.5, 0.0);
    let cam = Camera::look_at(eye, target, 35.0, width, height)?;
    if lens {
        cam.with_lens(0.12, (target - eye).length())
    } else {
        Ok(cam)
    }
}
