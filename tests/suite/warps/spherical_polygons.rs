//! Spherical triangle and rectangle warps: areas, densities, inverses.

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
