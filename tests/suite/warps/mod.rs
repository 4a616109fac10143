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

/// Spherical triangles and rectangles (Arvo 1995; Ureña et al. 2013).
mod spherical_polygons;

/// Property tests at the edges: every output finite and on its domain.
mod properties;
