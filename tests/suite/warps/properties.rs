//! Property tests at the edges: inputs 0, the smallest subnormal and normal, 1/2, the largest
//! `f32` below 1 (and random ones); parameters at and past their limits (NaN, infinities,
//! huge and tiny magnitudes). Every output must be finite and on its domain, and inverses
//! must return the input where the map is invertible. Reference values are closed forms in
//! `f64` (disk radius, unit norm, plane equation, solid angle of a rectangle by the corner
//! formula `sum +- atan(x y / (z r))`), never the library's own output.

use super::*;
use proptest::prelude::*;
use qmckit::warp::spherical::{SphericalRectangle, SphericalTriangle};

fn unit_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        prop::sample::select(vec![
            0.0f32,
            f32::from_bits(1),
            f32::MIN_POSITIVE,
            1e-30,
            0.5,
            0.25,
            0.75,
            1.0 - f32::EPSILON,
            ONE_MINUS_EPSILON,
        ]),
        0.0f32..1.0,
    ]
}

fn u2() -> impl Strategy<Value = [f32; 2]> {
    [unit_f32(), unit_f32()]
}

/// Any `f32`, biased to the awkward ones.
fn wild() -> impl Strategy<Value = f32> {
    prop_oneof![
        prop::sample::select(vec![
            0.0f32,
            -0.0,
            f32::from_bits(1),
            1.0,
            -1.0,
            1e-30,
            1e19,
            1.8e19,
            2e19,
            1e38,
            -1e38,
            f32::MAX,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ]),
        -4.0f32..4.0,
        any::<f32>(),
    ]
}

fn wild3() -> impl Strategy<Value = [f32; 3]> {
    [wild(), wild(), wild()]
}

fn norm(w: [f32; 3]) -> f64 {
    w.iter().map(|&x| (x as f64).powi(2)).sum::<f64>().sqrt()
}

/// Distance between two fractions of a turn, the short way round.
fn turn_gap(a: f32, b: f32) -> f32 {
    let d = (a - b).abs();
    d.min(1.0 - d)
}

fn v(a: [f32; 3]) -> [f64; 3] {
    a.map(|x| x as f64)
}
fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn len(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// Solid angle of the rectangle `[x0, x1] x [y0, y1]` at depth `z > 0` seen from the
/// origin: `F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0)`, `F = atan(x y / (z r))`.
fn rect_solid_angle(x0: f64, x1: f64, y0: f64, y1: f64, z: f64) -> f64 {
    let f = |x: f64, y: f64| (x * y / (z * (x * x + y * y + z * z).sqrt())).atan();
    f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0)
}

/// A rectangle with a rotated orthonormal frame, log-uniform size and distance.
fn rect_geometry() -> impl Strategy<Value = ([f32; 3], [f32; 3], [f32; 3], [f32; 3])> {
    (
        [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0],
        0.0f64..std::f64::consts::TAU,
        [-12i32..12, -12i32..12],
        [-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0],
        -20i32..20,
    )
        .prop_map(|(axis, angle, [kx, ky], off, ks)| {
            // A frame from a rotation of the standard one about `axis` (Rodrigues).
            let l = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2])
                .sqrt()
                .max(1e-9);
            let k = axis.map(|a| a / l);
            let rot = |e: [f64; 3]| {
                let (s, c) = angle.sin_cos();
                let kxe = [
                    k[1] * e[2] - k[2] * e[1],
                    k[2] * e[0] - k[0] * e[2],
                    k[0] * e[1] - k[1] * e[0],
                ];
                let kd = k[0] * e[0] + k[1] * e[1] + k[2] * e[2];
                [0, 1, 2].map(|i| e[i] * c + kxe[i] * s + k[i] * kd * (1.0 - c))
            };
            let scale = 2f64.powi(ks);
            let (ex, ey) = (
                rot([2f64.powi(kx), 0.0, 0.0]),
                rot([0.0, 2f64.powi(ky), 0.0]),
            );
            let corner = off.map(|x| x * scale);
            let o = [0.0f32; 3];
            let f = |a: [f64; 3]| a.map(|x| (x * scale) as f32);
            (o, corner.map(|x| x as f32), f(ex), f(ey))
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn disk_sphere_triangle_gaussian_outputs_are_on_their_domains(u in u2()) {
        for (name, p, inv) in [
            (
                "polar",
                sample_uniform_disk_polar(u),
                invert_uniform_disk_polar as fn([f32; 2]) -> [f32; 2],
            ),
            (
                "concentric",
                sample_uniform_disk_concentric(u),
                invert_uniform_disk_concentric,
            ),
        ] {
            let r2 = (p[0] as f64).powi(2) + (p[1] as f64).powi(2);
            prop_assert!(
                p.iter().all(|x| x.is_finite()) && r2 <= 1.0 + 1e-6,
                "{name} {u:?} -> {p:?}"
            );
            let back = inv(p);
            prop_assert!(
                back.iter().all(|x| (0.0..=1.0 + 1e-6).contains(x)),
                "{name} {back:?}"
            );
            if name == "polar" {
                // r^2 = u1; the angle is undefined at the centre.
                prop_assert!((back[1] - u[1]).abs() < 2e-6, "{name} {u:?} -> {back:?}");
                if u[1] > 1e-6 {
                    prop_assert!(turn_gap(back[0], u[0]) < 2e-5, "{name} {u:?} -> {back:?}");
                }
            } else {
                prop_assert!(
                    (back[0] - u[0]).abs() < 2e-5 && (back[1] - u[1]).abs() < 2e-5,
                    "{name} {u:?} -> {back:?}"
                );
            }
        }
        for (name, w, z_min) in [
            ("sphere", sample_uniform_sphere(u), -1.0),
            ("hemisphere", sample_uniform_hemisphere(u), 0.0),
            ("cosine", sample_cosine_hemisphere(u), 0.0),
        ] {
            prop_assert!(w.iter().all(|x| x.is_finite()), "{name} {u:?} -> {w:?}");
            prop_assert!(
                (norm(w) - 1.0).abs() < 2e-6 && w[2] >= z_min,
                "{name} {u:?} -> {w:?}"
            );
        }
        let s = invert_uniform_sphere(sample_uniform_sphere(u));
        prop_assert!((s[0] - u[0]).abs() < 2e-6);
        let b = sample_uniform_triangle(u);
        prop_assert!(b.iter().all(|&x| (0.0..=1.0).contains(&x)));
        prop_assert!((b.iter().map(|&x| x as f64).sum::<f64>() - 1.0).abs() < 1e-6);
        let t = invert_uniform_triangle(b);
        prop_assert!(
            (t[0] - u[0]).abs() < 1e-6 && (t[1] - u[1]).abs() < 1e-6,
            "{u:?} -> {t:?}"
        );
        let z = sample_box_muller(u);
        // r = sqrt(-2 ln(1 - u0)) <= sqrt(2 * 24 ln 2) = 5.77 for u0 < 1 in f32.
        prop_assert!(z.iter().all(|x| x.is_finite()) && (z[0].hypot(z[1]) as f64) < 5.8);
        for x in u {
            let n = sample_normal(x);
            prop_assert!(n.is_finite() && n.abs() < 6.5, "normal {x} -> {n}");
            if (1e-6..=1.0 - 1e-6).contains(&x) {
                prop_assert!(
                    (normal_cdf(n) - x).abs() < 1e-6 * x.max(1e-6).max(1.0 - x) + 1e-7
                );
            }
        }
    }

    #[test]
    fn cones_take_any_parameter(u in u2(), c in prop_oneof![wild(), -1.0f32..1.0]) {
        let w = sample_uniform_cone(u, c);
        let cc = if c.is_nan() { 1.0 } else { c.clamp(-1.0, 1.0) };
        prop_assert!(w.iter().all(|x| x.is_finite()), "{c} {u:?} -> {w:?}");
        prop_assert!(
            (norm(w) - 1.0).abs() < 2e-6 && w[2] >= cc - 1e-6,
            "{c} {u:?} -> {w:?}"
        );
        match UniformCone::new(c) {
            Ok(cone) => {
                prop_assert!((-1.0..1.0).contains(&c));
                let pdf = cone.pdf() as f64;
                let exact = 1.0 / (2.0 * std::f64::consts::PI * (1.0 - c as f64));
                prop_assert!(
                    pdf.is_finite() && (pdf / exact - 1.0).abs() < 1e-5,
                    "{c}: {pdf} vs {exact}"
                );
                prop_assert_eq!(cone.sample(u), w);
                let back = cone.invert(w);
                // u0 is conditioned by 1 / (1 - c): f32 rounding of z over the span.
                let tol = 4e-7 / (1.0 - c).max(1e-7) + 1e-6;
                prop_assert!((back[0] - u[0]).abs() <= tol, "{c} {u:?} -> {back:?}");
            }
            Err(_) => prop_assert!(!(-1.0..1.0).contains(&c)),
        }
    }

    #[test]
    fn triangles_take_any_vertices(
        p in [[wild(), wild()], [wild(), wild()], [wild(), wild()]],
        u in u2(),
    ) {
        let area = 0.5
            * ((p[1][0] as f64 - p[0][0] as f64) * (p[2][1] as f64 - p[0][1] as f64)
                - (p[2][0] as f64 - p[0][0] as f64) * (p[1][1] as f64 - p[0][1] as f64))
                .abs();
        match Triangle::new(p) {
            Ok(t) => {
                prop_assert!(
                    p.iter()
                        .flatten()
                        .all(|x| x.is_finite() && x.abs() <= 1.9e19)
                );
                prop_assert!(
                    (t.pdf() as f64 * area - 1.0).abs() < 1e-5,
                    "{p:?}: {} vs 1/{area}",
                    t.pdf()
                );
                let (x, pdf) = t.sample(u);
                prop_assert_eq!(pdf, t.pdf());
                for k in 0..2 {
                    let lo = p.iter().map(|q| q[k]).fold(f32::INFINITY, f32::min);
                    let hi = p.iter().map(|q| q[k]).fold(f32::NEG_INFINITY, f32::max);
                    let slack = 1e-6 * (hi - lo).abs().max(lo.abs()).max(hi.abs());
                    prop_assert!(
                        x[k].is_finite() && x[k] >= lo - slack && x[k] <= hi + slack,
                        "{p:?} {u:?} -> {x:?}"
                    );
                }
            }
            Err(_) => prop_assert!(
                !p.iter()
                    .flatten()
                    .all(|x| x.is_finite() && x.abs() <= 1.8e19)
                    || area.is_nan()
                    || area <= 0.0
                    // The documented rule: twice the area below 2^-20 of the
                    // longest edge squared (with a margin for the area's rounding).
                    || area * 2.0
                        < 1.001 / 1_048_576.0
                            * [(0, 1), (0, 2), (1, 2)]
                                .iter()
                                .map(|&(i, j)| {
                                    (0..2)
                                        .map(|k| (p[j][k] as f64 - p[i][k] as f64).powi(2))
                                        .sum::<f64>()
                                })
                                .fold(0.0, f64::max)
                    || !((1.0 / area) as f32).is_finite(),
                "{p:?} refused, area {area}"
            ),
        }
    }

    #[test]
    fn rectangles_with_raw_parameters_are_refused_or_finite(
        g in [wild3(), wild3(), wild3(), wild3()],
        u in u2(),
    ) {
        if let Ok(r) = SphericalRectangle::new(g[0], g[1], g[2], g[3]) {
            let (p, pdf) = r.sample(u);
            prop_assert!(
                p.iter().all(|x| x.is_finite()) && pdf.is_finite() && pdf > 0.0,
                "{g:?} {u:?} -> {p:?} {pdf}"
            );
            prop_assert!(r.invert(p).iter().all(|x| (0.0..=1.0).contains(x)));
        }
        if let Ok(t) = SphericalTriangle::new([g[0], g[1], g[2]], g[3]) {
            let (w, pdf) = t.sample(u);
            prop_assert!(
                w.iter().all(|x| x.is_finite()) && pdf.is_finite() && pdf > 0.0,
                "{g:?} {u:?} -> {w:?} {pdf}"
            );
            prop_assert!((norm(w) - 1.0).abs() < 1e-6);
            prop_assert!(t.invert(w).iter().all(|x| (0.0..=1.0).contains(x)));
        }
    }

    #[test]
    fn rectangles_sample_on_the_plane_and_invert(
        (o, corner, ex, ey) in rect_geometry(),
        u in u2(),
    ) {
        let Ok(r) = SphericalRectangle::new(o, corner, ex, ey) else {
            return Ok(());
        };
        let (p, pdf) = r.sample(u);
        prop_assert!(p.iter().all(|x| x.is_finite()) && pdf.is_finite());
        for edge in [[1.0, 1.0], [0.0, 1.0], [1.0, 0.0]] {
            prop_assert!(r.sample(edge).0.iter().all(|x| x.is_finite()));
        }
        // On the plane and within the rectangle: p - corner = s ex + t ey + n h, h ~ 0.
        let (ex, ey, q) = (v(ex), v(ey), sub(v(p), v(corner)));
        let (lx, ly) = (len(ex), len(ey));
        let (s, t) = (dot(q, ex) / (lx * lx), dot(q, ey) / (ly * ly));
        let off = sub(q, [0, 1, 2].map(|i| s * ex[i] + t * ey[i]));
        let size = len(v(corner)).max(lx).max(ly);
        prop_assert!(
            len(off) <= 2e-7 * size,
            "off the plane by {} (size {size})",
            len(off)
        );
        // Within the edges, to the f32 rounding of p (relative to the rectangle's distance).
        let (ts, tt) = (4e-7 * size / lx, 4e-7 * size / ly);
        prop_assert!(
            (-ts..=1.0 + ts).contains(&s) && (-tt..=1.0 + tt).contains(&t),
            "s {s} t {t}"
        );
        // The solid angle against the corner formula in the rectangle's frame.
        let d = sub(v(corner), v(o));
        let n = [
            ex[1] * ey[2] - ex[2] * ey[1],
            ex[2] * ey[0] - ex[0] * ey[2],
            ex[0] * ey[1] - ex[1] * ey[0],
        ];
        let z = dot(d, n).abs() / len(n);
        let (x0, y0) = (dot(d, ex) / lx, dot(d, ey) / ly);
        let exact = rect_solid_angle(x0, x0 + lx, y0, y0 + ly, z);
        prop_assert!(
            (r.solid_angle() as f64 / exact - 1.0).abs() < 1e-5,
            "{} vs {exact}",
            r.solid_angle()
        );
        // The inverse reads u back from the f32 hit point, whose rounding (relative to the
        // rectangle's distance) is amplified by distance / edge: checked where that ratio
        // is at most 2^6.
        if lx.min(ly) >= size / 64.0 {
            let back = r.invert(p);
            prop_assert!(
                (back[0] - u[0]).abs() < 1e-4 && (back[1] - u[1]).abs() < 1e-4,
                "{u:?} -> {back:?}"
            );
        }
    }

    #[test]
    fn spherical_triangles_stay_inside_and_invert(
        (o, corner, ex, ey) in rect_geometry(),
        u in u2(),
    ) {
        let tri = [
            corner,
            [0, 1, 2].map(|i| corner[i] + ex[i]),
            [0, 1, 2].map(|i| corner[i] + ey[i]),
        ];
        let Ok(t) = SphericalTriangle::new(tri, o) else {
            return Ok(());
        };
        let (w, pdf) = t.sample(u);
        prop_assert!(w.iter().all(|x| x.is_finite()) && pdf.is_finite());
        prop_assert!((norm(w) - 1.0).abs() < 1e-6);
        for edge in [[1.0, 1.0], [0.0, 1.0], [1.0, 0.0]] {
            prop_assert!((norm(t.sample(edge).0) - 1.0).abs() < 1e-6);
        }
        // Inside the cone of the three vertex directions: same side of every edge plane.
        let dirs = tri.map(|p| sub(v(p), v(o)));
        let cross = |a: [f64; 3], b: [f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let orient = dot(dirs[0], cross(dirs[1], dirs[2])).signum();
        for k in 0..3 {
            let nk = cross(dirs[k], dirs[(k + 1) % 3]);
            prop_assert!(
                orient * dot(v(w), nk) / len(nk) >= -1e-6,
                "{w:?} outside edge {k}"
            );
        }
        // Van Oosterom & Strackee's solid angle, independently.
        let [a, b, c] = dirs.map(|d| d.map(|x| x / len(d)));
        let exact = 2.0
            * dot(a, cross(b, c))
                .abs()
                .atan2(1.0 + dot(a, b) + dot(b, c) + dot(c, a));
        prop_assert!(
            (pdf as f64 * exact - 1.0).abs() < 1e-5,
            "{pdf} vs 1/{exact}"
        );
        // The inverse from the f32 direction, where the triangle is not a sliver (edges
        // within 2^6 of its distance) and u0 is defined (u1 > 0: w is not the vertex B).
        let size = dirs.iter().map(|d| len(*d)).fold(0.0, f64::max);
        let short = len(v(ex)).min(len(v(ey)));
        if short >= size / 64.0 {
            // The f32 inverse loses bits in proportion to how far the triangle is
            // against its shortest edge (the arcs' condition number).
            let tol = (1e-4 * (size / short).max(1.0)) as f32;
            let back = t.invert(w);
            if u[1] > 1e-2 {
                prop_assert!((back[0] - u[0]).abs() < tol, "{u:?} -> {back:?}");
            }
            prop_assert!((back[1] - u[1]).abs() < tol, "{u:?} -> {back:?}");
        }
    }
}
