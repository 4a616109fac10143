//! Uniform directions over spherical polygons, for sampling area lights by solid angle:
//! spherical rectangles (Ureña, Fajardo & King 2013, "An area-preserving parametrization for
//! spherical rectangles") and spherical triangles (Arvo 1995, "Stratified sampling of
//! spherical triangles"), with inverses. The density is `1 / solid angle`.
//!
//! [`SphericalRectangle::new`] and [`SphericalTriangle::new`] validate the geometry once and
//! return [`Error::InvalidParameter`] for what cannot be computed to `f32` accuracy; the
//! prepared values then sample and invert without failing, and every output is finite. The
//! free functions (`sample_spherical_rectangle`, ...) build the prepared value on each call.
//!
//! Accepted geometry (`R` is the distance scale: the largest coordinate of the polygon's
//! vertices relative to the viewpoint):
//!
//! * every coordinate finite, with magnitude at most [`MAX_COORDINATE`] (`2^64`), so that
//!   every intermediate product stays far inside the `f64` range and every point of the
//!   polygon is a finite `f32`;
//! * a rectangle's edges of length at least [`RELATIVE_TOLERANCE`]` R` (`2^-20 R`) and
//!   perpendicular within [`PERPENDICULAR_TOLERANCE`] (`|ex . ey| <= 2^-16 |ex| |ey|`, about
//!   the rounding of a rotated frame to `f32`; within it the map treats the edges as
//!   perpendicular, so hit points stay on the parallelogram `corner + s ex + t ey` and the
//!   density is exact to about `2^-16` relative); a triangle whose doubled area is at least
//!   `2^-20` of its longest edge squared;
//! * the viewpoint off the polygon's plane by at least `2^-20 R`;
//! * a solid angle of at least [`MIN_SOLID_ANGLE`] (`2^-24` sr): both maps compute it as a
//!   sum of angles near `pi / 2` minus `2 pi`, so its relative error is about `1e-16 / S`;
//!   at `S >= 2^-24` that is below the `f32` rounding. Smaller lights are better sampled by
//!   area.
//!
//! Inputs and outputs are `f32`; the trigonometry runs in `f64` (through `libm`) because the
//! maps subtract nearly equal angles for small or distant lights. Cost: a rectangle's set-up
//! is 4 normalizations and 4 `acos`, a sample about 10 `f64` square roots and 2 `sin`/`cos`; a
//! triangle's set-up 3 normalizations and an `atan2`, a sample about 6 `sin`/`cos` and
//! square roots.

use libm::{acos, atan2, cos, sin, sqrt};

use super::MAX_COORDINATE;
use crate::error::{Error, Result};

type V = [f64; 3];

/// Relative tolerance of the degeneracy checks: `2^-20`.
pub const RELATIVE_TOLERANCE: f64 = 1.0 / 1_048_576.0;

/// Largest accepted `|cos|` of the angle between a rectangle's edges: `2^-16`.
pub const PERPENDICULAR_TOLERANCE: f64 = 1.0 / 65_536.0;

/// Smallest accepted solid angle, in steradians: `2^-24`.
pub const MIN_SOLID_ANGLE: f64 = 1.0 / 16_777_216.0;

fn v64(a: [f32; 3]) -> V {
    [a[0] as f64, a[1] as f64, a[2] as f64]
}
fn v32(a: V) -> [f32; 3] {
    [a[0] as f32, a[1] as f32, a[2] as f32]
}
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn scale(a: V, s: f64) -> V {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn length(a: V) -> f64 {
    sqrt(dot(a, a))
}
fn normalize(a: V) -> V {
    let l = length(a);
    if l > 0.0 { scale(a, 1.0 / l) } else { a }
}
fn max_abs(a: V) -> f64 {
    a[0].abs().max(a[1].abs()).max(a[2].abs())
}

/// `Err` unless every coordinate is finite and at most [`MAX_COORDINATE`] in magnitude.
fn check_coordinates(points: &[[f32; 3]]) -> Result<()> {
    if points
        .iter()
        .flatten()
        .all(|x| x.is_finite() && x.abs() <= MAX_COORDINATE)
    {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            what: "a coordinate is not finite or is larger than 2^64 in magnitude",
        })
    }
}

/// `Err` unless the solid angle is finite and at least [`MIN_SOLID_ANGLE`].
fn check_solid_angle(s: f64) -> Result<()> {
    if s.is_finite() && s >= MIN_SOLID_ANGLE {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            what: "the solid angle seen from the viewpoint is below 2^-24 sr",
        })
    }
}

/// A fraction computed in `f64` as an `f32` in `[0, 1]` (NaN, from a point off the domain,
/// reads as 0).
fn fraction(x: f64) -> f32 {
    if x > 0.0 { x.min(1.0) as f32 } else { 0.0 }
}

/// A rectangle seen from a point, in the rectangle's frame (Ureña et al. 2013, §3).
#[derive(Clone, Copy, Debug)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
struct RectFrame {
    x: V,
    y: V,
    x0: f64,
    y0: f64,
    z0: f64,
    x1: f64,
    y1: f64,
    /// Solid angle, and the constants of the parametrization.
    solid_angle: f64,
    k: f64,
    b0: f64,
    b1: f64,
}

impl RectFrame {
    /// `corner`, edges `ex`, `ey`, seen from `o`, validated (see the module docs).
    fn new(o: V, s: V, ex: V, ey: V) -> Result<Self> {
        let (lx, ly) = (length(ex), length(ey));
        if lx == 0.0 || ly == 0.0 {
            return Err(Error::InvalidParameter {
                what: "a rectangle edge has zero length",
            });
        }
        if dot(ex, ey).abs() > PERPENDICULAR_TOLERANCE * lx * ly {
            return Err(Error::InvalidParameter {
                what: "the rectangle's edges are not perpendicular (|cos| above 2^-16)",
            });
        }
        let (x, y) = (scale(ex, 1.0 / lx), scale(ey, 1.0 / ly));
        let d = sub(s, o);
        let (x0, y0) = (dot(d, x), dot(d, y));
        // The depth, with the normal x cross y turned away from the viewpoint: z0 < 0.
        let z0 = -dot(d, cross(x, y)).abs();
        let (x1, y1) = (x0 + lx, y0 + ly);
        let r = x0.abs().max(x1.abs()).max(y0.abs()).max(y1.abs()).max(-z0);
        if lx < RELATIVE_TOLERANCE * r || ly < RELATIVE_TOLERANCE * r {
            return Err(Error::InvalidParameter {
                what: "a rectangle edge is shorter than 2^-20 of its distance",
            });
        }
        if -z0 < RELATIVE_TOLERANCE * r {
            return Err(Error::InvalidParameter {
                what: "the viewpoint lies in (or within 2^-20 of) the rectangle's plane",
            });
        }
        let (solid_angle, k, b0, b1) = Self::angles(x0, y0, x1, y1, z0);
        check_solid_angle(solid_angle)?;
        Ok(RectFrame {
            x,
            y,
            x0,
            y0,
            z0,
            x1,
            y1,
            solid_angle,
            k,
            b0,
            b1,
        })
    }

    /// Solid angle `S` of `[x0, x1] x [y0, y1]` at depth `z0`, with Ureña's `k`, `b0`, `b1`.
    fn angles(x0: f64, y0: f64, x1: f64, y1: f64, z0: f64) -> (f64, f64, f64, f64) {
        let (v00, v01, v10, v11) = ([x0, y0, z0], [x0, y1, z0], [x1, y0, z0], [x1, y1, z0]);
        let n0 = normalize(cross(v00, v10));
        let n1 = normalize(cross(v10, v11));
        let n2 = normalize(cross(v11, v01));
        let n3 = normalize(cross(v01, v00));
        let angle = |a: V, b: V| acos((-dot(a, b)).clamp(-1.0, 1.0));
        let (g0, g1, g2, g3) = (angle(n0, n1), angle(n1, n2), angle(n2, n3), angle(n3, n0));
        let k = 2.0 * core::f64::consts::PI - g2 - g3;
        (g0 + g1 - k, k, n0[2], n2[2])
    }
}

/// The rectangle `corner + s ex + t ey`, `s, t in [0, 1]`, seen from a viewpoint `o`,
/// prepared for uniform sampling by solid angle (Ureña, Fajardo & King 2013).
///
/// `u0` picks a column `x` of the rectangle by inverting the solid angle of `[x0, x] x
/// [y0, y1]` in closed form; `u1` a point on the column, uniform in `h = y / sqrt(d^2 +
/// y^2)` (`d` the column's distance). The hit point is rebuilt from the rectangle's own
/// corner and edges, so it lies on the rectangle (to `f32` rounding) however far the
/// viewpoint is. Density `1 / S`, `S` the solid angle.
///
/// ```
/// use qmckit::warp::spherical::SphericalRectangle;
/// let light = SphericalRectangle::new(
///     [0.0, 0.0, 0.0], [-0.5, -0.5, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
/// )?;
/// let (p, pdf) = light.sample([0.5, 0.5]);
/// assert!(p[0].abs() < 1e-6 && p[1].abs() < 1e-6 && p[2] == 1.0);
/// assert_eq!(pdf, light.pdf());
/// let u = light.invert(p);
/// assert!((u[0] - 0.5).abs() < 1e-6 && (u[1] - 0.5).abs() < 1e-6);
/// // Edges that are not perpendicular, a viewpoint in the plane: refused.
/// let (ex, ey) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// assert!(SphericalRectangle::new([0.0, 0.0, 1.0], [0.0; 3], ex, [1.0, 1.0, 0.0]).is_err());
/// assert!(SphericalRectangle::new([2.0, 0.0, 0.0], [0.0; 3], ex, ey).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct SphericalRectangle {
    o: V,
    corner: V,
    ex: V,
    ey: V,
    f: RectFrame,
}

impl SphericalRectangle {
    /// The rectangle `corner + s ex + t ey` seen from `o`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for geometry outside the rules of the
    /// [module docs](self): a coordinate not finite or past `2^64`, a zero or too short
    /// edge, edges not perpendicular within `2^-16`, the viewpoint within `2^-20 R` of the
    /// plane, a solid angle below `2^-24` sr.
    pub fn new(o: [f32; 3], corner: [f32; 3], ex: [f32; 3], ey: [f32; 3]) -> Result<Self> {
        check_coordinates(&[o, corner, ex, ey])?;
        let (o, corner, ex, ey) = (v64(o), v64(corner), v64(ex), v64(ey));
        let f = RectFrame::new(o, corner, ex, ey)?;
        Ok(SphericalRectangle {
            o,
            corner,
            ex,
            ey,
            f,
        })
    }

    /// The solid angle of the rectangle seen from the viewpoint, in steradians.
    pub fn solid_angle(&self) -> f32 {
        self.f.solid_angle as f32
    }

    /// The density of [`sample`](Self::sample): `1 / solid angle` (at most `2^24`).
    pub fn pdf(&self) -> f32 {
        (1.0 / self.f.solid_angle) as f32
    }

    /// The point hit on the rectangle by a uniform direction (by solid angle) from `u` in
    /// `[0, 1)^2`, and the density [`pdf`](Self::pdf). Finite for every `u` in `[0, 1]^2`.
    pub fn sample(&self, u: [f32; 2]) -> ([f32; 3], f32) {
        let f = &self.f;
        let (u0, u1) = (u[0] as f64, u[1] as f64);
        // Column: invert the solid angle of [x0, xu] x [y0, y1].
        let au = u0 * f.solid_angle + f.k;
        let fu = (cos(au) * f.b0 - f.b1) / sin(au);
        let cu = (1.0 / sqrt(fu * fu + f.b0 * f.b0))
            .copysign(fu)
            .clamp(-1.0, 1.0);
        let xu = (-(cu * f.z0) / sqrt((1.0 - cu * cu).max(1e-300))).clamp(f.x0, f.x1);
        let xu = if xu.is_nan() { f.x0 } else { xu };
        // Row: uniform in h = y / sqrt(d^2 + y^2) along the column.
        let d = sqrt(xu * xu + f.z0 * f.z0);
        let h0 = f.y0 / sqrt(d * d + f.y0 * f.y0);
        let h1 = f.y1 / sqrt(d * d + f.y1 * f.y1);
        let hv = h0 + u1 * (h1 - h0);
        let hv2 = hv * hv;
        let yv = if hv2 < 1.0 - 1e-12 {
            hv * d / sqrt(1.0 - hv2)
        } else {
            f.y1
        };
        // The hit point from the rectangle's own corner and edges: on the rectangle.
        let (lx, ly) = (f.x1 - f.x0, f.y1 - f.y0);
        let s = fraction((xu - f.x0) / lx) as f64;
        let t = fraction((yv - f.y0) / ly) as f64;
        let p = add(self.corner, add(scale(self.ex, s), scale(self.ey, t)));
        (v32(p), self.pdf())
    }

    /// Inverse of [`sample`](Self::sample): the `u` whose sample hits point `p` of the
    /// rectangle (points off it are projected onto its plane and clamped to its edges).
    /// `u0` is the solid angle of the part of the rectangle left of `p` (divided by the
    /// whole), `u1` the position of `p` in `h = y / sqrt(d^2 + y^2)` along its column.
    pub fn invert(&self, p: [f32; 3]) -> [f32; 2] {
        let f = &self.f;
        let q = sub(v64(p), self.o);
        let (xu, yv) = (dot(q, f.x).clamp(f.x0, f.x1), dot(q, f.y).clamp(f.y0, f.y1));
        let (xu, yv) = (
            if xu.is_nan() { f.x0 } else { xu },
            if yv.is_nan() { f.y0 } else { yv },
        );
        let u0 = if xu <= f.x0 {
            0.0
        } else {
            RectFrame::angles(f.x0, f.y0, xu, f.y1, f.z0).0 / f.solid_angle
        };
        let d = sqrt(xu * xu + f.z0 * f.z0);
        let h = |y: f64| y / sqrt(d * d + y * y);
        let (h0, h1) = (h(f.y0), h(f.y1));
        let u1 = if h1 > h0 {
            (h(yv) - h0) / (h1 - h0)
        } else {
            0.0
        };
        [fraction(u0), fraction(u1)]
    }
}

/// [`SphericalRectangle::new`]`(o, corner, ex, ey)?.`[`sample`](SphericalRectangle::sample)`(u)`:
/// the point hit on the rectangle `corner + s ex + t ey` by a uniform direction (by solid
/// angle) from `o`, and the density `1 / solid angle`.
///
/// ```
/// use qmckit::warp::spherical::sample_spherical_rectangle;
/// let (p, pdf) = sample_spherical_rectangle(
///     [0.0, 0.0, 0.0], [-0.5, -0.5, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.5, 0.5],
/// )?;
/// assert!(p[0].abs() < 1e-6 && p[1].abs() < 1e-6 && (p[2] - 1.0).abs() < 1e-6);
/// assert!(pdf > 0.0);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// As [`SphericalRectangle::new`].
pub fn sample_spherical_rectangle(
    o: [f32; 3],
    corner: [f32; 3],
    ex: [f32; 3],
    ey: [f32; 3],
    u: [f32; 2],
) -> Result<([f32; 3], f32)> {
    Ok(SphericalRectangle::new(o, corner, ex, ey)?.sample(u))
}

/// The solid angle of the rectangle seen from `o`.
///
/// # Errors
/// As [`SphericalRectangle::new`].
pub fn spherical_rectangle_solid_angle(
    o: [f32; 3],
    corner: [f32; 3],
    ex: [f32; 3],
    ey: [f32; 3],
) -> Result<f32> {
    Ok(SphericalRectangle::new(o, corner, ex, ey)?.solid_angle())
}

/// Inverse of [`sample_spherical_rectangle`]: [`SphericalRectangle::invert`].
///
/// # Errors
/// As [`SphericalRectangle::new`].
pub fn invert_spherical_rectangle(
    o: [f32; 3],
    corner: [f32; 3],
    ex: [f32; 3],
    ey: [f32; 3],
    p: [f32; 3],
) -> Result<[f32; 2]> {
    Ok(SphericalRectangle::new(o, corner, ex, ey)?.invert(p))
}

/// Solid angle of the spherical triangle with unit vertices `a, b, c` (Van Oosterom &
/// Strackee 1983): `2 atan2(|a . (b x c)|, 1 + a.b + b.c + c.a)`.
fn triangle_solid_angle(a: V, b: V, c: V) -> f64 {
    let det = dot(a, cross(b, c)).abs();
    2.0 * atan2(det, 1.0 + dot(a, b) + dot(b, c) + dot(c, a))
}

/// The solid angle of triangle `v0 v1 v2` seen from `o` (Van Oosterom & Strackee 1983).
/// 0 when `o` is a vertex; NaN only for non-finite input (use [`SphericalTriangle::new`] to
/// validate).
pub fn spherical_triangle_solid_angle(v: [[f32; 3]; 3], o: [f32; 3]) -> f32 {
    let o = v64(o);
    let [a, b, c] = v.map(|p| normalize(sub(v64(p), o)));
    triangle_solid_angle(a, b, c) as f32
}

/// The triangle `v0 v1 v2` seen from a viewpoint `o`, prepared for uniform sampling of
/// directions by solid angle (Arvo 1995).
///
/// Arvo's construction: `u0` picks the sub-triangle `A B C'` (with `C'` on the arc `A C`)
/// of area `u0` times the whole, and `u1` a point on the arc `B C'`, uniform in `cos`.
/// Density `1 / S`, `S` the solid angle.
///
/// ```
/// use qmckit::warp::spherical::SphericalTriangle;
/// let v = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];
/// let tri = SphericalTriangle::new(v, [0.0; 3])?;
/// let (w, pdf) = tri.sample([0.3, 0.6]);
/// assert!(pdf > 0.0 && (w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - 1.0).abs() < 1e-6);
/// let u = tri.invert(w);
/// assert!((u[0] - 0.3).abs() < 1e-4 && (u[1] - 0.6).abs() < 1e-4);
/// // Collinear vertices, a viewpoint in the triangle's plane: refused.
/// let line = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [2.0, 0.0, 1.0]];
/// assert!(SphericalTriangle::new(line, [0.0; 3]).is_err());
/// assert!(SphericalTriangle::new(v, [5.0, 5.0, 1.0]).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct SphericalTriangle {
    a: V,
    b: V,
    c: V,
    area: f64,
    alpha: f64,
    c_perp: V,
}

impl SphericalTriangle {
    /// Triangle `v` seen from `o`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for geometry outside the rules of the
    /// [module docs](self): a coordinate not finite or past `2^64`, the viewpoint on a
    /// vertex or within `2^-20 R` of the triangle's plane, a triangle whose doubled area is
    /// below `2^-20` of its longest edge squared, a solid angle below `2^-24` sr.
    pub fn new(v: [[f32; 3]; 3], o: [f32; 3]) -> Result<Self> {
        check_coordinates(&[v[0], v[1], v[2], o])?;
        let o64 = v64(o);
        let rel = v.map(|p| sub(v64(p), o64));
        let r = max_abs(rel[0]).max(max_abs(rel[1])).max(max_abs(rel[2]));
        if rel.iter().any(|d| max_abs(*d) == 0.0) {
            return Err(Error::InvalidParameter {
                what: "the viewpoint is a vertex of the triangle",
            });
        }
        let (e1, e2) = (sub(rel[1], rel[0]), sub(rel[2], rel[0]));
        let n = cross(e1, e2);
        let longest = length(e1).max(length(e2)).max(length(sub(rel[2], rel[1])));
        if length(n) < RELATIVE_TOLERANCE * longest * longest {
            return Err(Error::InvalidParameter {
                what: "the triangle is degenerate (its vertices are collinear)",
            });
        }
        if dot(n, rel[0]).abs() < RELATIVE_TOLERANCE * length(n) * r {
            return Err(Error::InvalidParameter {
                what: "the viewpoint lies in (or within 2^-20 of) the triangle's plane",
            });
        }
        let [a, b, c] = rel.map(normalize);
        let area = triangle_solid_angle(a, b, c);
        check_solid_angle(area)?;
        // Internal angle at A, between the planes (A, B) and (A, C).
        let (nab, nac) = (normalize(cross(a, b)), normalize(cross(a, c)));
        let alpha = acos(dot(nab, nac).clamp(-1.0, 1.0));
        let c_perp = normalize(sub(c, scale(a, dot(c, a))));
        Ok(SphericalTriangle {
            a,
            b,
            c,
            area,
            alpha,
            c_perp,
        })
    }

    /// The solid angle of the triangle seen from the viewpoint, in steradians.
    pub fn solid_angle(&self) -> f32 {
        self.area as f32
    }

    /// The density of [`sample`](Self::sample): `1 / solid angle` (at most `2^24`).
    pub fn pdf(&self) -> f32 {
        (1.0 / self.area) as f32
    }

    /// A uniform direction (by solid angle, a unit vector) toward the triangle from `u` in
    /// `[0, 1)^2`, and the density [`pdf`](Self::pdf). Finite for every `u` in `[0, 1]^2`.
    pub fn sample(&self, u: [f32; 2]) -> ([f32; 3], f32) {
        let (a, b, alpha) = (self.a, self.b, self.alpha);
        let cos_c = dot(a, b);
        // The sub-triangle's area, and its third vertex C' on the arc A C.
        let a_hat = u[0] as f64 * self.area;
        let (s, t) = (sin(a_hat - alpha), cos(a_hat - alpha));
        let (uu, vv) = (t - cos(alpha), s + sin(alpha) * cos_c);
        let q = ((vv * t - uu * s) * cos(alpha) - vv) / ((vv * s + uu * t) * sin(alpha));
        // 0 / 0 only where the sub-triangle is empty: C' = A.
        let q = if q.is_nan() { 1.0 } else { q.clamp(-1.0, 1.0) };
        let c1 = add(
            scale(a, q),
            scale(self.c_perp, sqrt((1.0 - q * q).max(0.0))),
        );
        // A point on the arc B C', uniform in z = w . B.
        let z = 1.0 - u[1] as f64 * (1.0 - dot(c1, b));
        let c1_perp = normalize(sub(c1, scale(b, dot(c1, b))));
        let w = normalize(add(
            scale(b, z),
            scale(c1_perp, sqrt((1.0 - z * z).max(0.0))),
        ));
        (v32(w), self.pdf())
    }

    /// Inverse of [`sample`](Self::sample): for a direction `w` inside the triangle, `C'`
    /// is where the great circle through `B` and `w` meets the arc `A C`; then `u0` is the
    /// area of `A B C'` over the whole and `u1 = (1 - w.B) / (1 - C'.B)`.
    pub fn invert(&self, w: [f32; 3]) -> [f32; 2] {
        let (a, b, c, area) = (self.a, self.b, self.c, self.area);
        let w = normalize(v64(w));
        let mut c1 = normalize(cross(cross(b, w), cross(c, a)));
        if dot(c1, add(a, c)) < 0.0 {
            c1 = scale(c1, -1.0);
        }
        let u0 = if dot(a, c1) > 1.0 - 1e-14 {
            0.0
        } else {
            triangle_solid_angle(a, b, c1) / area
        };
        let denom = 1.0 - dot(c1, b);
        let u1 = if denom > 1e-14 {
            (1.0 - dot(w, b)) / denom
        } else {
            0.0
        };
        [fraction(u0), fraction(u1)]
    }
}

/// [`SphericalTriangle::new`]`(v, o)?.`[`sample`](SphericalTriangle::sample)`(u)`: a
/// uniform direction (by solid angle) toward triangle `v` seen from `o`, and the density
/// `1 / solid angle`.
///
/// ```
/// use qmckit::warp::spherical::{invert_spherical_triangle, sample_spherical_triangle};
/// let tri = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];
/// let (w, pdf) = sample_spherical_triangle(tri, [0.0; 3], [0.3, 0.6])?;
/// let u = invert_spherical_triangle(tri, [0.0; 3], w)?;
/// assert!((u[0] - 0.3).abs() < 1e-4 && (u[1] - 0.6).abs() < 1e-4);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// As [`SphericalTriangle::new`].
pub fn sample_spherical_triangle(
    v: [[f32; 3]; 3],
    o: [f32; 3],
    u: [f32; 2],
) -> Result<([f32; 3], f32)> {
    Ok(SphericalTriangle::new(v, o)?.sample(u))
}

/// Inverse of [`sample_spherical_triangle`]: [`SphericalTriangle::invert`].
///
/// # Errors
/// As [`SphericalTriangle::new`].
pub fn invert_spherical_triangle(v: [[f32; 3]; 3], o: [f32; 3], w: [f32; 3]) -> Result<[f32; 2]> {
    Ok(SphericalTriangle::new(v, o)?.invert(w))
}
