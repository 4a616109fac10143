//! Uniform directions over spherical polygons, for sampling area lights by solid angle:
//! spherical rectangles (Ureña, Fajardo & King 2013, "An area-preserving parametrization for
//! spherical rectangles") and spherical triangles (Arvo 1995, "Stratified sampling of
//! spherical triangles"), with inverses. The density is `1 / solid angle`.
//!
//! Inputs and outputs are `f32`; the trigonometry runs in `f64` (through `libm`) because the
//! maps subtract nearly equal angles for small or distant lights.

use libm::{acos, atan2, cos, sin, sqrt};

type V = [f64; 3];

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

/// A rectangle seen from a point, in the rectangle's frame (Ureña et al. 2013, §3).
#[derive(Clone, Copy, Debug)]
struct RectFrame {
    o: V,
    x: V,
    y: V,
    z: V,
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
    /// `corner`, edges `ex`, `ey` (perpendicular), seen from `o`. `None` when degenerate
    /// (zero-length edge, or `o` in the rectangle's plane).
    fn new(o: [f32; 3], corner: [f32; 3], ex: [f32; 3], ey: [f32; 3]) -> Option<Self> {
        let (o, s, ex, ey) = (v64(o), v64(corner), v64(ex), v64(ey));
        let (lx, ly) = (length(ex), length(ey));
        if lx == 0.0 || ly == 0.0 {
            return None;
        }
        let (x, y) = (scale(ex, 1.0 / lx), scale(ey, 1.0 / ly));
        let mut z = cross(x, y);
        let d = sub(s, o);
        let (x0, y0, mut z0) = (dot(d, x), dot(d, y), dot(d, z));
        if z0 > 0.0 {
            z0 = -z0;
            z = scale(z, -1.0);
        }
        if z0 == 0.0 {
            return None;
        }
        let (x1, y1) = (x0 + lx, y0 + ly);
        let (solid_angle, k, b0, b1) = Self::angles(x0, y0, x1, y1, z0);
        Some(RectFrame {
            o,
            x,
            y,
            z,
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

/// A uniform direction (by solid angle) toward the rectangle `corner + s ex + t ey`,
/// `s, t in [0, 1]`, seen from `o` (`ex` and `ey` perpendicular): the point hit on the
/// rectangle, and the density `1 / solid angle`. `None` for a degenerate configuration.
///
/// ```
/// use qmckit::warp::spherical::sample_spherical_rectangle;
/// let (p, pdf) = sample_spherical_rectangle(
///     [0.0, 0.0, 0.0], [-0.5, -0.5, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.5, 0.5],
/// ).unwrap();
/// assert!(p[0].abs() < 1e-6 && p[1].abs() < 1e-6 && (p[2] - 1.0).abs() < 1e-6);
/// assert!(pdf > 0.0);
/// ```
pub fn sample_spherical_rectangle(
    o: [f32; 3],
    corner: [f32; 3],
    ex: [f32; 3],
    ey: [f32; 3],
    u: [f32; 2],
) -> Option<([f32; 3], f32)> {
    let f = RectFrame::new(o, corner, ex, ey)?;
    let (u0, u1) = (u[0] as f64, u[1] as f64);
    // Column: invert the solid angle of [x0, xu] x [y0, y1].
    let au = u0 * f.solid_angle + f.k;
    let fu = (cos(au) * f.b0 - f.b1) / sin(au);
    let cu = (1.0 / sqrt(fu * fu + f.b0 * f.b0))
        .copysign(fu)
        .clamp(-1.0, 1.0);
    let xu = (-(cu * f.z0) / sqrt((1.0 - cu * cu).max(1e-300))).clamp(f.x0, f.x1);
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
    let p = add(
        f.o,
        add(add(scale(f.x, xu), scale(f.y, yv)), scale(f.z, f.z0)),
    );
    Some((v32(p), (1.0 / f.solid_angle) as f32))
}

/// The solid angle of the rectangle seen from `o` (`None` when degenerate).
pub fn spherical_rectangle_solid_angle(
    o: [f32; 3],
    corner: [f32; 3],
    ex: [f32; 3],
    ey: [f32; 3],
) -> Option<f32> {
    RectFrame::new(o, corner, ex, ey).map(|f| f.solid_angle as f32)
}

/// Inverse of [`sample_spherical_rectangle`]: the `u` whose sample hits point `p` of the
/// rectangle. `u0` is the solid angle of the part of the rectangle left of `p` (divided by
/// the whole), `u1` the position of `p` in `h = y / sqrt(d^2 + y^2)` along its column.
pub fn invert_spherical_rectangle(
    o: [f32; 3],
    corner: [f32; 3],
    ex: [f32; 3],
    ey: [f32; 3],
    p: [f32; 3],
) -> Option<[f32; 2]> {
    let f = RectFrame::new(o, corner, ex, ey)?;
    let q = sub(v64(p), f.o);
    let (xu, yv) = (dot(q, f.x).clamp(f.x0, f.x1), dot(q, f.y).clamp(f.y0, f.y1));
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
    Some([u0.clamp(0.0, 1.0) as f32, u1.clamp(0.0, 1.0) as f32])
}

/// Solid angle of the spherical triangle with unit vertices `a, b, c` (Van Oosterom &
/// Strackee 1983): `2 atan2(|a . (b x c)|, 1 + a.b + b.c + c.a)`.
fn triangle_solid_angle(a: V, b: V, c: V) -> f64 {
    let det = dot(a, cross(b, c)).abs();
    2.0 * atan2(det, 1.0 + dot(a, b) + dot(b, c) + dot(c, a))
}

/// The solid angle of triangle `v0 v1 v2` seen from `o`.
pub fn spherical_triangle_solid_angle(v: [[f32; 3]; 3], o: [f32; 3]) -> f32 {
    let o = v64(o);
    let [a, b, c] = v.map(|p| normalize(sub(v64(p), o)));
    triangle_solid_angle(a, b, c) as f32
}

/// A uniform direction (by solid angle) toward triangle `v` seen from `o` (Arvo 1995): the
/// unit direction and the density `1 / solid angle`. `None` for a degenerate triangle.
///
/// Arvo's construction: `u0` picks the sub-triangle `A B C'` (with `C'` on the arc `A C`)
/// of area `u0` times the whole, and `u1` a point on the arc `B C'`, uniform in `cos`.
///
/// ```
/// use qmckit::warp::spherical::{invert_spherical_triangle, sample_spherical_triangle};
/// let tri = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];
/// let (w, pdf) = sample_spherical_triangle(tri, [0.0; 3], [0.3, 0.6]).unwrap();
/// assert!(pdf > 0.0 && (w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - 1.0).abs() < 1e-6);
/// let u = invert_spherical_triangle(tri, [0.0; 3], w).unwrap();
/// assert!((u[0] - 0.3).abs() < 1e-4 && (u[1] - 0.6).abs() < 1e-4);
/// ```
pub fn sample_spherical_triangle(
    v: [[f32; 3]; 3],
    o: [f32; 3],
    u: [f32; 2],
) -> Option<([f32; 3], f32)> {
    let o64 = v64(o);
    let [a, b, c] = v.map(|p| normalize(sub(v64(p), o64)));
    let area = triangle_solid_angle(a, b, c);
    if area.is_nan() || area <= 1e-12 {
        return None;
    }
    // Internal angle at A, between the planes (A, B) and (A, C).
    let (nab, nac) = (normalize(cross(a, b)), normalize(cross(a, c)));
    let alpha = acos(dot(nab, nac).clamp(-1.0, 1.0));
    let cos_c = dot(a, b);
    // The sub-triangle's area, and its third vertex C' on the arc A C.
    let a_hat = u[0] as f64 * area;
    let (s, t) = (sin(a_hat - alpha), cos(a_hat - alpha));
    let (uu, vv) = (t - cos(alpha), s + sin(alpha) * cos_c);
    let q =
        (((vv * t - uu * s) * cos(alpha) - vv) / ((vv * s + uu * t) * sin(alpha))).clamp(-1.0, 1.0);
    let c_perp = normalize(sub(c, scale(a, dot(c, a))));
    let c1 = add(scale(a, q), scale(c_perp, sqrt((1.0 - q * q).max(0.0))));
    // A point on the arc B C', uniform in z = w . B.
    let z = 1.0 - u[1] as f64 * (1.0 - dot(c1, b));
    let c1_perp = normalize(sub(c1, scale(b, dot(c1, b))));
    let w = normalize(add(
        scale(b, z),
        scale(c1_perp, sqrt((1.0 - z * z).max(0.0))),
    ));
    Some((v32(w), (1.0 / area) as f32))
}

/// Inverse of [`sample_spherical_triangle`]: for a direction `w` inside the triangle, `C'`
/// is where the great circle through `B` and `w` meets the arc `A C`; then `u0` is the area
/// of `A B C'` over the whole and `u1 = (1 - w.B) / (1 - C'.B)`.
pub fn invert_spherical_triangle(v: [[f32; 3]; 3], o: [f32; 3], w: [f32; 3]) -> Option<[f32; 2]> {
    let o64 = v64(o);
    let [a, b, c] = v.map(|p| normalize(sub(v64(p), o64)));
    let w = normalize(v64(w));
    let area = triangle_solid_angle(a, b, c);
    if area.is_nan() || area <= 1e-12 {
        return None;
    }
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
    Some([u0.clamp(0.0, 1.0) as f32, u1.clamp(0.0, 1.0) as f32])
}
