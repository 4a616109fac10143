//! A pinhole camera with an optional thin lens (defocus) and a shutter interval.
//!
//! Pixel `(x, y)` (row 0 at the top) covers `[x, x + 1) x [y, y + 1)` of the film; the film
//! point `(p_x, p_y)` maps to the direction `f + s_x r + s_y u` with
//! `s_x = (2 p_x / W - 1) tan(fov / 2) W / H`, `s_y = (1 - 2 p_y / H) tan(fov / 2)`.
//! With a lens of radius `a` focused at distance `F` (along the view axis), the ray starts
//! at `e + a (d_x r + d_y u)`, `(d_x, d_y)` the lens sample warped to the unit disk by the
//! crate's concentric map ([`qmckit::warp::disk::sample_uniform_disk_concentric`]), and
//! passes through the point of the pinhole ray at depth `F`: points at depth `F` stay
//! sharp, others blur into discs. The shutter time `t` in `[0, 1)` is passed to the scene
//! (moving spheres). O(1) a ray.

use super::geometry::{Ray, V3};
use qmckit::{Error, Result};

/// A camera looking from `eye` at a target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    eye: V3,
    forward: V3,
    right: V3,
    up: V3,
    tan_half: f64,
    width: u32,
    height: u32,
    lens_radius: f64,
    focus_distance: f64,
}

impl Camera {
    /// A pinhole camera at `eye` looking at `target` (world up `+y`) with vertical field of
    /// view `vfov_degrees` in `(0, 180)`, for a `width x height` image.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`] for an empty image; [`Error::InvalidParameter`] for a field of
    /// view outside `(0, 180)` or a view direction along `y`.
    pub fn look_at(
        eye: V3,
        target: V3,
        vfov_degrees: f64,
        width: u32,
        height: u32,
    ) -> Result<Self> {
        if width == 0 || height == 0 {
            return Err(Error::ZeroPoints);
        }
        if !(vfov_degrees > 0.0 && vfov_degrees < 180.0) {
            return Err(Error::InvalidParameter {
                what: "the field of view must lie in (0, 180) degrees",
            });
        }
        let forward = (target - eye).normalize();
        let right = forward.cross(V3::new(0.0, 1.0, 0.0));
        if right.length() < 1e-9 {
            return Err(Error::InvalidParameter {
                what: "the camera cannot look straight up or down",
            });
        }
        let right = right.normalize();
        let up = right.cross(forward);
        Ok(Camera {
            eye,
            forward,
            right,
            up,
            tan_half: (vfov_degrees.to_radians() / 2.0).tan(),
            width,
            height,
            lens_radius: 0.0,
            focus_distance: (target - eye).length(),
        })
    }

    /// The same camera with a thin lens of radius `radius` focused at `focus_distance`
    /// (both `>= 0`, the distance `> 0`; radius 0 is the pinhole).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a negative radius or a non-positive distance.
    pub fn with_lens(self, radius: f64, focus_distance: f64) -> Result<Self> {
        if !(radius >= 0.0
            && focus_distance > 0.0
            && radius.is_finite()
            && focus_distance.is_finite())
        {
            return Err(Error::InvalidParameter {
                what: "a lens needs a radius >= 0 and a focus distance > 0",
            });
        }
        Ok(Camera {
            lens_radius: radius,
            focus_distance,
            ..self
        })
    }

    /// Image width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Image height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The eye point (the lens center).
    pub fn eye(&self) -> V3 {
        self.eye
    }

    /// The ray through film point `(px, py)` (pixel units, row 0 at the top) and lens
    /// sample `lens` in `[0, 1)^2` (ignored by a pinhole).
    pub fn ray(&self, px: f64, py: f64, lens: [f64; 2]) -> Ray {
        let aspect = self.width as f64 / self.height as f64;
        let sx = (2.0 * px / self.width as f64 - 1.0) * self.tan_half * aspect;
        let sy = (1.0 - 2.0 * py / self.height as f64) * self.tan_half;
        let dir = (self.forward + self.right * sx + self.up * sy).normalize();
        if self.lens_radius == 0.0 {
            return Ray {
                origin: self.eye,
                dir,
            };
        }
        let d =
            qmckit::warp::disk::sample_uniform_disk_concentric([lens[0] as f32, lens[1] as f32]);
        let origin =
            self.eye + (self.right * d[0] as f64 + self.up * d[1] as f64) * self.lens_radius;
        let focus = self.eye + dir * (self.focus_distance / dir.dot(self.forward));
        Ray::new(origin, focus - origin)
    }

    /// Where the pinhole projects the world point `p` on the film, in pixel units (row 0 at
    /// the top); `None` behind the camera.
    pub fn project(&self, p: V3) -> Option<[f64; 2]> {
        let d = p - self.eye;
        let z = d.dot(self.forward);
        if z <= 0.0 {
            return None;
        }
        let aspect = self.width as f64 / self.height as f64;
        let sx = d.dot(self.right) / z / (self.tan_half * aspect);
        let sy = d.dot(self.up) / z / self.tan_half;
        Some([
            (sx + 1.0) * 0.5 * self.width as f64,
            (1.0 - sy) * 0.5 * self.height as f64,
        ])
    }
}
