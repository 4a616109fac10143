//! Warps: densities match the maps (Jacobians), integrate to 1, inverses invert, outputs stay
//! in their domains with no NaN at the boundary inputs, and warped QMC still beats warped
//! random on a light-transport integral.
#![cfg(feature = "libm")]

use qmckit::bits::to_f32;
use qmckit::randomize::{FastOwen, Scrambled};
use qmckit::warp::ONE_MINUS_EPSILON;
use qmckit::warp::disk::*;
use qmckit::warp::gaussian::*;
use qmckit::warp::sphere::*;
use qmckit::warp::triangle::*;
use qmckit::{Independent, Jitter, Sampler, Sobol, Stratified};

/// 4096 Sobol' points in (0.01, 0.99)^2 (away from the seams and degenerate edges).
fn grid() -> Vec<[f32; 2]> {
    let s = Sobol::new(2).unwrap();
    (0..4096)
        .map(|i| {
            let u = [
                to_f32(s.sample(i, 0).unwrap()),
                to_f32(s.sample(i, 1).unwrap()),
            ];
            [0.01 + 0.98 * u[0], 0.01 + 0.98 * u[1]]
        })
        .collect()
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The area (or solid-angle) element of `f` at `u` by central differences, in 3D.
fn jacobian<const N: usize>(f: &dyn Fn([f32; 2]) -> [f32; N], u: [f32; 2]) -> f64 {
    let h = 1e-3f32;
    let d = |k: usize| {
        let (mut a, mut b) = (u, u);
        a[k] += h;
        b[k] -= h;
        let (fa, fb) = (f(a), f(b));
        let mut v = [0f64; 3];
        for j in 0..N {
            v[j] = (fa[j] as f64 - fb[j] as f64) / (2.0 * h as f64);
        }
        v
    };
    let c = cross(d(0), d(1));
    (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt()
}

/// Near the concentric map's seams (the square's diagonals), where it is continuous but not
/// differentiable, so central differences straddle two pieces.
fn near_diagonal(u: [f32; 2]) -> bool {
    let (a, b) = ((2.0 * u[0] - 1.0).abs(), (2.0 * u[1] - 1.0).abs());
    (a - b).abs() < 1e-2
}

/// |J| * pdf = 1 on the grid (away from `skip`, the map's seams): the stated density is the
/// map's density.
fn assert_density<const N: usize>(
    name: &str,
    f: &dyn Fn([f32; 2]) -> [f32; N],
    pdf: &dyn Fn([f32; N]) -> f32,
    skip: &dyn Fn([f32; 2]) -> bool,
) {
    let mut worst = 0f64;
    for u in grid().into_iter().filter(|&u| !skip(u)) {
        let j = jacobian(f, u);
        let err = (j * pdf(f(u)) as f64 - 1.0).abs();
        worst = worst.max(err);
        assert!(
            err < 1e-2,
            "{name}: |J| pdf = {} at {u:?}",
            j * pdf(f(u)) as f64
        );
    }
    println!("{name}: max | |J| pdf - 1 | = {worst:.2e}");
}

#[test]
fn densities_match_the_maps() {
    let none = |_: [f32; 2]| false;
    assert_density(
        "disk polar",
        &sample_uniform_disk_polar,
        &|_| UNIFORM_DISK_PDF,
        &none,
    );
    assert_density(
        "disk concentric",
        &sample_uniform_disk_concentric,
        &|_| UNIFORM_DISK_PDF,
        &near_diagonal,
    );
    assert_density(
        "sphere",
        &sample_uniform_sphere,
        &|_| UNIFORM_SPHERE_PDF,
        &none,
    );
    assert_density(
        "hemisphere",
        &sample_uniform_hemisphere,
        &|_| UNIFORM_HEMISPHERE_PDF,
        &none,
    );
    assert_density(
        "cosine hemisphere",
        &sample_cosine_hemisphere,
        &|w| cosine_hemisphere_pdf(w[2]),
        &near_diagonal,
    );
    for c in [-0.5f32, 0.0, 0.5, 0.9] {
        assert_density(
            "cone",
            &|u| sample_uniform_cone(u, c),
            &|_| uniform_cone_pdf(c),
            &none,
        );
    }
    // Triangle: barycentrics (b0, b1) over the reference triangle (area 1/2), density 2;
    // the map's seam is the square's diagonal u0 = u1.
    assert_density(
        "triangle",
        &|u| {
            let b = sample_uniform_triangle(u);
            [b[0], b[1]]
        },
        &|_| 2.0,
        &|u| (u[0] - u[1]).abs() < 1e-2,
    );
    assert_density("box-muller", &sample_box_muller, &box_muller_pdf, &none);
}

/// Each density integrates to 1 over its domain (independent midpoint quadrature).
#[test]
fn densities_integrate_to_one() {
    let n = 2000;
    let (mut cos_h, mut bm, mut normal) = (0f64, 0f64, 0f64);
    for i in 0..n {
        let theta = (i as f64 + 0.5) / n as f64 * std::f64::consts::FRAC_PI_2;
        // Cosine hemisphere: the integrand has no phi dependence: 2 pi * int pdf sin dtheta.
        let dtheta = std::f64::consts::FRAC_PI_2 / n as f64;
        cos_h += 2.0
            * std::f64::consts::PI
            * cosine_hemisphere_pdf(theta.cos() as f32) as f64
            * theta.sin()
            * dtheta;
        // Box-Muller pair: radial, r in [0, 12].
        let r = (i as f64 + 0.5) / n as f64 * 12.0;
        bm += 2.0
            * std::f64::consts::PI
            * box_muller_pdf([r as f32, 0.0]) as f64
            * r
            * (12.0 / n as f64);
        let x = -10.0 + (i as f64 + 0.5) / n as f64 * 20.0;
        normal += normal_pdf(x as f32) as f64 * (20.0 / n as f64);
    }
    for (name, v) in [
        ("cosine hemisphere", cos_h),
        ("box-muller", bm),
        ("normal", normal),
    ] {
        assert!((v - 1.0).abs() < 1e-4, "{name}: {v}");
    }
    let pi = std::f64::consts::PI;
    assert!((UNIFORM_DISK_PDF as f64 * pi - 1.0).abs() < 1e-6);
    assert!((UNIFORM_SPHERE_PDF as f64 * 4.0 * pi - 1.0).abs() < 1e-6);
    assert!((UNIFORM_HEMISPHERE_PDF as f64 * 2.0 * pi - 1.0).abs() < 1e-6);
    for c in [-1.0f32, 0.0, 0.7] {
        assert!((uniform_cone_pdf(c) as f64 * 2.0 * pi * (1.0 - c as f64) - 1.0).abs() < 1e-5);
    }
    let (_, pdf) = point_in_triangle([[0.0, 0.0], [4.0, 0.0], [0.0, 2.0]], [0.2, 0.3, 0.5]);
    assert_eq!(pdf, 0.25);
}

fn assert_inverse<const N: usize>(
    name: &str,
    f: &dyn Fn([f32; 2]) -> [f32; N],
    inv: &dyn Fn([f32; N]) -> [f32; 2],
    tol: f32,
) {
    let mut worst = 0f32;
    for u in grid() {
        let v = inv(f(u));
        let err = (v[0] - u[0]).abs().max((v[1] - u[1]).abs());
        worst = worst.max(err);
        assert!(err <= tol, "{name}: {u:?} -> {v:?}");
    }
    println!("{name}: max |invert(sample(u)) - u| = {worst:.2e} (bound {tol:.0e})");
}

/// `invert(sample(u)) = u` within 2e-5 (f32 arithmetic through sin/cos/atan2) on the grid.
#[test]
fn inverses_invert() {
    let tol = 2e-5;
    assert_inverse(
        "disk polar",
        &sample_uniform_disk_polar,
        &invert_uniform_disk_polar,
        tol,
    );
    assert_inverse(
        "disk concentric",
        &sample_uniform_disk_concentric,
        &invert_uniform_disk_concentric,
        tol,
    );
    assert_inverse(
        "sphere",
        &sample_uniform_sphere,
        &invert_uniform_sphere,
        tol,
    );
    assert_inverse(
        "hemisphere",
        &sample_uniform_hemisphere,
        &invert_uniform_hemisphere,
        tol,
    );
    assert_inverse(
        "cosine hemisphere",
        &sample_cosine_hemisphere,
        &invert_cosine_hemisphere,
        tol,
    );
    assert_inverse(
        "cone",
        &|u| sample_uniform_cone(u, 0.3),
        &|w| invert_uniform_cone(w, 0.3),
        tol,
    );
    assert_inverse(
        "triangle",
        &sample_uniform_triangle,
        &invert_uniform_triangle,
        1e-6,
    );
    assert_inverse("box-muller", &sample_box_muller, &invert_box_muller, tol);
    for u in grid() {
        assert!(
            (normal_cdf(sample_normal(u[0])) - u[0]).abs() < 1e-6,
            "normal at {}",
            u[0]
        );
    }
}

/// Outputs lie in their domains; the boundary inputs give finite values.
#[test]
fn outputs_stay_in_their_domains() {
    let edges = [0.0f32, to_f32(1), 0.5, ONE_MINUS_EPSILON, to_f32(u32::MAX)];
    let mut us: Vec<[f32; 2]> = grid();
    for &a in &edges {
        for &b in &edges {
            us.push([a, b]);
        }
    }
    let unit = |w: [f32; 3]| ((w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) - 1.0).abs() < 1e-5;
    for u in us {
        for p in [
            sample_uniform_disk_polar(u),
            sample_uniform_disk_concentric(u),
        ] {
            assert!(p.iter().all(|x| x.is_finite()) && p[0] * p[0] + p[1] * p[1] <= 1.0 + 1e-6);
        }
        let s = sample_uniform_sphere(u);
        assert!(unit(s), "sphere {u:?} -> {s:?}");
        for w in [sample_uniform_hemisphere(u), sample_cosine_hemisphere(u)] {
            assert!(unit(w) && w[2] >= 0.0, "hemisphere {u:?} -> {w:?}");
        }
        let c = sample_uniform_cone(u, 0.8);
        assert!(unit(c) && c[2] >= 0.8 - 1e-6, "cone {u:?} -> {c:?}");
        let b = sample_uniform_triangle(u);
        assert!(b.iter().all(|&x| x >= 0.0) && (b.iter().sum::<f32>() - 1.0).abs() < 1e-6);
        let z = sample_box_muller(u);
        assert!(z.iter().all(|x| x.is_finite()), "box-muller {u:?}");
        assert!(sample_normal(u[0]).is_finite() && sample_normal(u[1]).is_finite());
        // Inverses map back into [0, 1].
        for v in [
            invert_uniform_disk_polar(sample_uniform_disk_polar(u)),
            invert_uniform_disk_concentric(sample_uniform_disk_concentric(u)),
            invert_uniform_sphere(s),
            invert_cosine_hemisphere(sample_cosine_hemisphere(u)),
        ] {
            assert!(
                v.iter().all(|&x| (0.0..=1.0 + 1e-6).contains(&x)),
                "inverse {u:?} -> {v:?}"
            );
        }
    }
    assert!(sample_normal(0.0) > -7.0 && sample_normal(ONE_MINUS_EPSILON) < 6.0);
}

/// Irradiance at the origin from a disk light of radius R at height h, parallel to the
/// surface (radiance 1): E = pi R^2 / (R^2 + h^2). Estimated by sampling the light's area
/// through the concentric map, n = 16, over many seeds.
#[test]
fn warped_qmc_beats_warped_random_on_a_disk_light() {
    let (radius, h) = (1.0f64, 1.0f64);
    let exact = std::f64::consts::PI * radius * radius / (radius * radius + h * h);
    let area = std::f64::consts::PI * radius * radius;
    let estimate = |s: &dyn Sampler| {
        let mut sum = 0.0;
        for i in 0..16 {
            let u = [
                to_f32(s.sample(i, 0).unwrap()),
                to_f32(s.sample(i, 1).unwrap()),
            ];
            let p = sample_uniform_disk_concentric(u);
            let (x, y) = (p[0] as f64 * radius, p[1] as f64 * radius);
            let d2 = x * x + y * y + h * h;
            sum += h * h / (d2 * d2) * area; // cos * cos / d^2 / pdf
        }
        sum / 16.0
    };
    let seeds = 4000;
    let mse = |make: &dyn Fn(u64) -> Box<dyn Sampler>| {
        (0..seeds)
            .map(|s| (estimate(&*make(s)) - exact).powi(2))
            .sum::<f64>()
            / seeds as f64
    };
    let independent = mse(&|s| Box::new(Independent::new(2, s).unwrap()));
    let jittered = mse(&|s| Box::new(Stratified::uniform(4, 2, Jitter::Random(s)).unwrap()));
    let sobol = mse(&|s| Box::new(Scrambled::new(Sobol::new(2).unwrap(), FastOwen::new(s))));
    println!(
        "disk light, n = 16: MSE independent {independent:.3e}, jittered 1/{:.1}, Owen-Sobol' 1/{:.1}",
        independent / jittered,
        independent / sobol
    );
    assert!(
        jittered * 2.0 < independent,
        "jittered {jittered} vs {independent}"
    );
    assert!(
        sobol * 2.0 < independent && sobol < jittered,
        "sobol {sobol} vs {jittered}"
    );
}

mod spherical_polygons {
    use super::*;
    use qmckit::warp::spherical::*;

    const O: [f32; 3] = [0.1, -0.2, 0.0];
    const CORNER: [f32; 3] = [-0.5, -0.5, 1.0];
    const EX: [f32; 3] = [1.0, 0.0, 0.0];
    const EY: [f32; 3] = [0.0, 1.5, 0.0];

    fn dir(p: [f32; 3], o: [f32; 3]) -> [f32; 3] {
        let d = [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        [d[0] / l, d[1] / l, d[2] / l]
    }

    #[test]
    fn rectangle_density_inverse_and_solid_angle() {
        let f = |u: [f32; 2]| {
            dir(
                sample_spherical_rectangle(O, CORNER, EX, EY, u).unwrap().0,
                O,
            )
        };
        let pdf = sample_spherical_rectangle(O, CORNER, EX, EY, [0.5, 0.5])
            .unwrap()
            .1;
        assert_density("spherical rectangle", &f, &|_| pdf, &|_| false);
        // Solid angle: the two triangles of the rectangle, by Van Oosterom & Strackee.
        let (c, x, y) = (CORNER, EX, EY);
        let p = |s: f32, t: f32| {
            [
                c[0] + s * x[0] + t * y[0],
                c[1] + s * x[1] + t * y[1],
                c[2] + s * x[2] + t * y[2],
            ]
        };
        let tris = spherical_triangle_solid_angle([p(0., 0.), p(1., 0.), p(1., 1.)], O)
            + spherical_triangle_solid_angle([p(0., 0.), p(1., 1.), p(0., 1.)], O);
        let omega = spherical_rectangle_solid_angle(O, CORNER, EX, EY).unwrap();
        assert!((omega - tris).abs() < 1e-5, "{omega} vs {tris}");
        assert!((pdf * omega - 1.0).abs() < 1e-5);
        let mut worst = 0f32;
        for u in grid() {
            let (hit, _) = sample_spherical_rectangle(O, CORNER, EX, EY, u).unwrap();
            assert!((hit[2] - 1.0).abs() < 1e-5, "off the light plane: {hit:?}");
            let v = invert_spherical_rectangle(O, CORNER, EX, EY, hit).unwrap();
            worst = worst.max((v[0] - u[0]).abs().max((v[1] - u[1]).abs()));
        }
        assert!(worst < 1e-4, "rectangle inverse error {worst}");
        println!("spherical rectangle: max |invert(sample(u)) - u| = {worst:.2e} (bound 1e-4)");
        // Degenerate inputs are refused, not NaN.
        assert!(sample_spherical_rectangle(O, [0.0, 0.0, 0.0], EX, EY, [0.5, 0.5]).is_err());
        assert!(sample_spherical_rectangle(O, CORNER, [0.0; 3], EY, [0.5, 0.5]).is_err());
        for u in [
            [0.0, 0.0],
            [ONE_MINUS_EPSILON, ONE_MINUS_EPSILON],
            [0.0, ONE_MINUS_EPSILON],
        ] {
            let (hit, _) = sample_spherical_rectangle(O, CORNER, EX, EY, u).unwrap();
            assert!(hit.iter().all(|x| x.is_finite()), "{u:?}");
        }
    }

    #[test]
    fn triangle_density_inverse_and_domain() {
        let tri = [[0.0, 0.0, 1.0], [1.0, 0.2, 0.8], [-0.3, 1.0, 1.2]];
        let o = [0.05, 0.05, 0.0];
        let f = |u: [f32; 2]| sample_spherical_triangle(tri, o, u).unwrap().0;
        let pdf = sample_spherical_triangle(tri, o, [0.5, 0.5]).unwrap().1;
        assert!((pdf * spherical_triangle_solid_angle(tri, o) - 1.0).abs() < 1e-5);
        assert_density("spherical triangle", &f, &|_| pdf, &|_| false);
        let mut worst = 0f32;
        for u in grid() {
            let w = f(u);
            let v = invert_spherical_triangle(tri, o, w).unwrap();
            worst = worst.max((v[0] - u[0]).abs().max((v[1] - u[1]).abs()));
        }
        assert!(worst < 1e-4, "triangle inverse error {worst}");
        println!("spherical triangle: max |invert(sample(u)) - u| = {worst:.2e} (bound 1e-4)");
        assert!(sample_spherical_triangle([[0.0, 0.0, 1.0]; 3], o, [0.5, 0.5]).is_err());
    }

    /// Each validation rule, at and just past its limit: `InvalidParameter` past it, a
    /// finite sample on the domain before it.
    #[test]
    fn geometry_rules_refuse_exactly_past_their_limits() {
        use qmckit::Error;
        use qmckit::warp::MAX_COORDINATE;
        let invalid =
            |r: Result<SphericalRectangle, Error>| matches!(r, Err(Error::InvalidParameter { .. }));
        let (c, ex, ey) = ([-0.5f32, -0.5, 1.0], [1.0f32, 0.0, 0.0], [0.0f32, 1.0, 0.0]);
        assert!(SphericalRectangle::new([0.0; 3], c, ex, ey).is_ok());
        // Coordinates: 2^64 is accepted, the next f32 up is not; NaN and inf never.
        let big = MAX_COORDINATE;
        assert!(
            SphericalRectangle::new(
                [0.0, 0.0, -big],
                [-big, -big, 0.0],
                [big, 0.0, 0.0],
                [0.0, big, 0.0]
            )
            .is_ok()
        );
        let past = f32::from_bits(big.to_bits() + 1);
        assert!(invalid(SphericalRectangle::new(
            [0.0; 3],
            [-0.5, -0.5, past],
            ex,
            ey
        )));
        for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            assert!(invalid(SphericalRectangle::new([0.0, 0.0, bad], c, ex, ey)));
            assert!(invalid(SphericalRectangle::new(
                [0.0; 3],
                c,
                [bad, 0.0, 0.0],
                ey
            )));
        }
        // Perpendicular within 2^-16: cos = 2^-17 accepted, 2^-15 refused.
        let tilt = |cos: f32| [cos, (1.0 - cos * cos).sqrt(), 0.0];
        assert!(SphericalRectangle::new([0.0; 3], c, ex, tilt(1.0 / 131_072.0)).is_ok());
        assert!(invalid(SphericalRectangle::new(
            [0.0; 3],
            c,
            ex,
            tilt(1.0 / 32_768.0)
        )));
        // The viewpoint's height over the plane: 2^-19 of the distance accepted, 2^-21 not.
        let r = SphericalRectangle::new([0.0, 0.0, 1.0 - 1.0 / 524_288.0], [0.0, 0.0, 1.0], ex, ey)
            .unwrap();
        let (p, pdf) = r.sample([0.3, 0.7]);
        assert!(p[2] == 1.0 && pdf.is_finite());
        assert!(invalid(SphericalRectangle::new(
            [0.0, 0.0, 1.0 - 1.0 / 2_097_152.0],
            [0.0, 0.0, 1.0],
            ex,
            ey
        )));
        // Solid angle 2^-24 sr: a unit square at distance d subtends about 1 / d^2.
        assert!(SphericalRectangle::new([0.0, 0.0, -2000.0], c, ex, ey).is_ok());
        assert!(invalid(SphericalRectangle::new(
            [0.0, 0.0, -8000.0],
            c,
            ex,
            ey
        )));
        // Triangles: a vertex at the viewpoint, collinear vertices, a viewpoint in the plane.
        let tri = [[0.0f32, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];
        assert!(SphericalTriangle::new(tri, [0.0; 3]).is_ok());
        for (v, o) in [
            (tri, [0.0, 0.0, 1.0]),
            (
                [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [3.0, 0.0, 1.0]],
                [0.0; 3],
            ),
            (tri, [0.3, 0.3, 1.0]),
            (tri, [0.0, 0.0, -1e5]),
            ([[f32::NAN, 0.0, 1.0], tri[1], tri[2]], [0.0; 3]),
        ] {
            assert!(
                matches!(
                    SphericalTriangle::new(v, o),
                    Err(Error::InvalidParameter { .. })
                ),
                "{v:?} {o:?}"
            );
        }
    }

    /// Irradiance at the origin (normal +z) from a unit-radiance square light of side 1 at
    /// height 1, by solid-angle sampling of the spherical rectangle, n = 16. Exact value by
    /// Lambert's polygon formula: E = 1/2 sum_i angle(v_i, v_i+1) (n . unit(v_i x v_i+1)).
    #[test]
    fn warped_qmc_beats_warped_random_on_a_quad_light() {
        let (o, c, ex, ey) = (
            [0.0f32; 3],
            [-0.5f32, -0.5, 1.0],
            [1.0f32, 0.0, 0.0],
            [0.0f32, 1.0, 0.0],
        );
        let verts: [[f64; 3]; 4] = [
            [-0.5, -0.5, 1.0],
            [0.5, -0.5, 1.0],
            [0.5, 0.5, 1.0],
            [-0.5, 0.5, 1.0],
        ];
        let mut exact = 0.0;
        for i in 0..4 {
            let (a, b) = (verts[i], verts[(i + 1) % 4]);
            let (la, lb) = (
                (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt(),
                (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]).sqrt(),
            );
            let cosang = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
            let cr = [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ];
            let lc = (cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]).sqrt();
            exact += 0.5 * cosang.acos() * cr[2] / lc;
        }
        let exact = exact.abs();
        let estimate = |s: &dyn Sampler| {
            let mut sum = 0.0;
            for i in 0..16 {
                let u = [
                    to_f32(s.sample(i, 0).unwrap()),
                    to_f32(s.sample(i, 1).unwrap()),
                ];
                let (p, pdf) = sample_spherical_rectangle(o, c, ex, ey, u).unwrap();
                sum += dir(p, o)[2] as f64 / pdf as f64; // L cos(theta) / pdf
            }
            sum / 16.0
        };
        let seeds = 4000;
        let mse = |make: &dyn Fn(u64) -> Box<dyn Sampler>| {
            (0..seeds)
                .map(|s| (estimate(&*make(s)) - exact).powi(2))
                .sum::<f64>()
                / seeds as f64
        };
        let independent = mse(&|s| Box::new(Independent::new(2, s).unwrap()));
        let jittered = mse(&|s| Box::new(Stratified::uniform(4, 2, Jitter::Random(s)).unwrap()));
        let sobol = mse(&|s| Box::new(Scrambled::new(Sobol::new(2).unwrap(), FastOwen::new(s))));
        println!(
            "quad light (E = {exact:.6}), n = 16: MSE independent {independent:.3e}, jittered 1/{:.1}, Owen-Sobol' 1/{:.1}",
            independent / jittered,
            independent / sobol
        );
        assert!(
            jittered * 2.0 < independent,
            "jittered {jittered} vs {independent}"
        );
        assert!(
            sobol * 2.0 < independent && sobol < jittered,
            "sobol {sobol} vs {jittered}"
        );
    }
}

/// Property tests at the edges: inputs 0, the smallest subnormal and normal, 1/2, the largest
/// `f32` below 1 (and random ones); parameters at and past their limits (NaN, infinities,
/// huge and tiny magnitudes). Every output must be finite and on its domain, and inverses
/// must return the input where the map is invertible. Reference values are closed forms in
/// `f64` (disk radius, unit norm, plane equation, solid angle of a rectangle by the corner
/// formula `sum +- atan(x y / (z r))`), never the library's own output.
mod properties {
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
}
