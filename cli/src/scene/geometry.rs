//! Rays, spheres (optionally moving), a ground plane and a rectangular area light, with
//! exact intersections.
//!
//! A ray is `o + t d` with a unit direction `d`. A sphere `|p - c| = r` is hit at the
//! smaller root `t = -b - sqrt(b^2 - q)` of `t^2 + 2 b t + q = 0` (`b = (o - c).d`,
//! `q = |o - c|^2 - r^2`) that lies in `(t_min, t_max)`, else the larger one; a plane
//! `y = h` at `t = (h - o_y) / d_y`; the quad `p_0 + u e_x + v e_y` (`u, v` in `[0, 1]`,
//! `e_x` perpendicular to `e_y`) at its plane's `t` when `u, v` fall inside. Each test is
//! O(1); a scene query is O(number of spheres).

use core::ops::{Add, Mul, Neg, Sub};

/// A 3-vector of `f64`s.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct V3 {
    /// x (to the right of the default camera).
    pub x: f64,
    /// y (up).
    pub y: f64,
    /// z (towards the default camera).
    pub z: f64,
}

impl V3 {
    /// `(x, y, z)`.
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        V3 { x, y, z }
    }

    /// The dot product.
    pub fn dot(self, o: V3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// The cross product `self x o`.
    pub fn cross(self, o: V3) -> V3 {
        V3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// The Euclidean length.
    pub fn length(self) -> f64 {
        self.dot(self).sqrt()
    }

    /// `self / |self|` (the zero vector stays zero).
    pub fn normalize(self) -> V3 {
        let l = self.length();
        if l > 0.0 { self * (1.0 / l) } else { self }
    }
}

impl Add for V3 {
    type Output = V3;
    fn add(self, o: V3) -> V3 {
        V3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl Sub for V3 {
    type Output = V3;
    fn sub(self, o: V3) -> V3 {
        V3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl Mul<f64> for V3 {
    type Output = V3;
    fn mul(self, s: f64) -> V3 {
        V3::new(self.x * s, self.y * s, self.z * s)
    }
}

impl Neg for V3 {
    type Output = V3;
    fn neg(self) -> V3 {
        V3::new(-self.x, -self.y, -self.z)
    }
}

/// A ray `origin + t dir`, `dir` of unit length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts.
    pub origin: V3,
    /// Unit direction.
    pub dir: V3,
}

impl Ray {
    /// A ray from `origin` along `dir` (normalized here).
    pub fn new(origin: V3, dir: V3) -> Self {
        Ray {
            origin,
            dir: dir.normalize(),
        }
    }

    /// The point at distance `t`.
    pub fn at(&self, t: f64) -> V3 {
        self.origin + self.dir * t
    }
}

/// A sphere whose center moves linearly over the shutter interval: `c(t) = c_0 + t v`,
/// `t` in `[0, 1)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Center at time 0.
    pub center: V3,
    /// Radius, `> 0`.
    pub radius: f64,
    /// Displacement of the center over the whole shutter interval.
    pub velocity: V3,
    /// Diffuse reflectance in `[0, 1]`.
    pub albedo: f64,
}

impl Sphere {
    /// A static sphere.
    pub const fn new(center: V3, radius: f64, albedo: f64) -> Self {
        Sphere {
            center,
            radius,
            velocity: V3::new(0.0, 0.0, 0.0),
            albedo,
        }
    }

    /// The center at shutter time `time`.
    pub fn center_at(&self, time: f64) -> V3 {
        self.center + self.velocity * time
    }

    /// The nearest hit distance in `(t_min, t_max)` at shutter time `time`, by the
    /// quadratic formula (see the [module documentation](self)).
    ///
    /// ```
    /// use qmckit_cli::scene::geometry::{Ray, Sphere, V3};
    /// let s = Sphere::new(V3::new(0.0, 0.0, -5.0), 1.0, 0.5);
    /// let r = Ray::new(V3::new(0.0, 0.0, 0.0), V3::new(0.0, 0.0, -1.0));
    /// assert_eq!(s.intersect(&r, 0.0, 0.0, f64::INFINITY), Some(4.0)); // |c| - r
    /// ```
    pub fn intersect(&self, ray: &Ray, time: f64, t_min: f64, t_max: f64) -> Option<f64> {
        let oc = ray.origin - self.center_at(time);
        let b = oc.dot(ray.dir);
        let q = oc.dot(oc) - self.radius * self.radius;
        let disc = b * b - q;
        if disc < 0.0 {
            return None;
        }
        let s = disc.sqrt();
        // The near root without cancellation: q / (-b + s) when b < 0.
        let (t0, t1) = if b < 0.0 {
            let far = -b + s;
            (q / far, far)
        } else {
            (-b - s, -b + s)
        };
        let (near, far) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
        if near > t_min && near < t_max {
            Some(near)
        } else if far > t_min && far < t_max {
            Some(far)
        } else {
            None
        }
    }
}

/// The horizontal plane `y = height` with a checkerboard reflectance (squares of side
/// `check`, reflectances `albedo.0` and `albedo.1`; `check = 0` for a uniform plane).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// Height of the plane.
    pub height: f64,
    /// Side of a checkerboard square (0: no checkerboard).
    pub check: f64,
    /// The two reflectances.
    pub albedo: (f64, f64),
}

impl Plane {
    /// The hit distance in `(t_min, t_max)`, `(height - o_y) / d_y`.
    ///
    /// ```
    /// use qmckit_cli::scene::geometry::{Plane, Ray, V3};
    /// let p = Plane { height: 0.0, check: 0.0, albedo: (0.5, 0.5) };
    /// let r = Ray::new(V3::new(0.0, 2.0, 0.0), V3::new(1.0, -1.0, 0.0));
    /// let t = p.intersect(&r, 0.0, f64::INFINITY).unwrap();
    /// assert!((t - 2.0 * 2f64.sqrt()).abs() < 1e-12);
    /// ```
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
        if ray.dir.y == 0.0 {
            return None;
        }
        let t = (self.height - ray.origin.y) / ray.dir.y;
        (t > t_min && t < t_max).then_some(t)
    }

    /// The reflectance at `p`.
    pub fn albedo_at(&self, p: V3) -> f64 {
        if self.check <= 0.0 {
            return self.albedo.0;
        }
        let i = (p.x / self.check).floor() as i64 + (p.z / self.check).floor() as i64;
        if i.rem_euclid(2) == 0 {
            self.albedo.0
        } else {
            self.albedo.1
        }
    }
}

/// A rectangle `p_0 + u e_x + v e_y`, `(u, v)` in `[0, 1]^2`, `e_x` perpendicular to `e_y`,
/// emitting uniform radiance from the side of `e_x x e_y`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quad {
    /// The corner at `(u, v) = (0, 0)`.
    pub corner: V3,
    /// The edge along `u`.
    pub ex: V3,
    /// The edge along `v`.
    pub ey: V3,
}

impl Quad {
    /// The point at `(u, v)`.
    pub fn point(&self, u: f64, v: f64) -> V3 {
        self.corner + self.ex * u + self.ey * v
    }

    /// Unit normal `e_x x e_y / |e_x x e_y|`, the emitting side.
    pub fn normal(&self) -> V3 {
        self.ex.cross(self.ey).normalize()
    }

    /// Area `|e_x x e_y|`.
    pub fn area(&self) -> f64 {
        self.ex.cross(self.ey).length()
    }

    /// The four corners in order `(0,0), (1,0), (1,1), (0,1)`.
    pub fn corners(&self) -> [V3; 4] {
        [
            self.corner,
            self.corner + self.ex,
            self.corner + self.ex + self.ey,
            self.corner + self.ey,
        ]
    }

    /// The hit distance in `(t_min, t_max)` and the hit's `(u, v)`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, f64, f64)> {
        let n = self.ex.cross(self.ey);
        let denom = n.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = n.dot(self.corner - ray.origin) / denom;
        if !(t > t_min && t < t_max) {
            return None;
        }
        let d = ray.at(t) - self.corner;
        let u = d.dot(self.ex) / self.ex.dot(self.ex);
        let v = d.dot(self.ey) / self.ey.dot(self.ey);
        ((0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v)).then_some((t, u, v))
    }
}

/// What a camera ray hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Surface {
    /// A diffuse surface: the point, its unit normal and its reflectance.
    Diffuse {
        /// Hit point.
        point: V3,
        /// Unit normal (facing the ray).
        normal: V3,
        /// Reflectance.
        albedo: f64,
    },
    /// The emitting side of the area light.
    Light,
    /// Nothing: the sky.
    Sky,
}

/// Spheres, a ground plane and one quad light.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The spheres.
    pub spheres: Vec<Sphere>,
    /// The ground plane (`None`: no ground).
    pub ground: Option<Plane>,
    /// The area light.
    pub light: Quad,
    /// The light's emitted radiance.
    pub radiance: f64,
    /// The radiance of rays that escape.
    pub sky: f64,
}

/// Relative offset of secondary-ray origins along the normal (against self-intersection).
pub const RAY_EPSILON: f64 = 1e-7;

impl Scene {
    /// The nearest surface along `ray` at shutter time `time`. Cost: one test per sphere,
    /// the plane and the light.
    pub fn intersect(&self, ray: &Ray, time: f64) -> Surface {
        let mut best = f64::INFINITY;
        let mut hit = Surface::Sky;
        for s in &self.spheres {
            if let Some(t) = s.intersect(ray, time, 0.0, best) {
                best = t;
                let point = ray.at(t);
                let mut normal = (point - s.center_at(time)).normalize();
                if normal.dot(ray.dir) > 0.0 {
                    normal = -normal;
                }
                hit = Surface::Diffuse {
                    point,
                    normal,
                    albedo: s.albedo,
                };
            }
        }
        if let Some(g) = &self.ground
            && let Some(t) = g.intersect(ray, 0.0, best)
        {
            best = t;
            let point = ray.at(t);
            let normal = if ray.dir.y < 0.0 {
                V3::new(0.0, 1.0, 0.0)
            } else {
                V3::new(0.0, -1.0, 0.0)
            };
            hit = Surface::Diffuse {
                point,
                normal,
                albedo: g.albedo_at(point),
            };
        }
        if let Some((t, _, _)) = self.light.intersect(ray, 0.0, best) {
            hit = if self.light.normal().dot(ray.dir) < 0.0 {
                Surface::Light
            } else {
                Surface::Diffuse {
                    point: ray.at(t),
                    normal: self.light.normal(),
                    albedo: 0.0,
                }
            };
        }
        hit
    }

    /// Whether a sphere or the ground blocks `ray` before distance `t_max` (the light does
    /// not occlude).
    pub fn occluded(&self, ray: &Ray, time: f64, t_max: f64) -> bool {
        self.spheres
            .iter()
            .any(|s| s.intersect(ray, time, 0.0, t_max).is_some())
            || self
                .ground
                .is_some_and(|g| g.intersect(ray, 0.0, t_max).is_some())
    }
}
