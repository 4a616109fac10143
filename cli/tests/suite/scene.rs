//! The analytic render scenes (`qmckit_cli::scene`): exact intersections, Lambert's
//! polygon irradiance against a closed form, the area and cosine estimators' means, and the
//! studies' qualitative claims (the lecture's MSE ordering, blue-noise AO error).

use qmckit::bits::to_f64;
use qmckit::{Independent, OwenSobol};
use qmckit_cli::scene::geometry::{Plane, Ray, Scene, Sphere, V3};
use qmckit_cli::scene::integrands::{
    ao_sample, lambert_irradiance, light_irradiance, light_sample, standard_camera, standard_scene,
};
use qmckit_cli::scene::{
    Study, StudyOptions, ambient_occlusion_study, check, motion_defocus_study, pixel_area_study,
    pixel_light_study, quad_light_points, quad_light_uv, reference_image, soft_shadow_study,
};
use std::f64::consts::PI;

fn small() -> StudyOptions {
    StudyOptions {
        width: 32,
        height: 32,
        spp: 16,
        seeds: 6,
        reference_spp: 1024,
    }
}

#[test]
fn ray_through_sphere_center_hits_at_distance_minus_radius() {
    for (c, r) in [
        (V3::new(1.0, 2.0, -3.0), 0.7),
        (V3::new(-10.0, 0.5, 4.0), 2.5),
        (V3::new(0.0, 0.0, -1e3), 1.0),
    ] {
        let s = Sphere::new(c, r, 0.5);
        let ray = Ray::new(V3::default(), c);
        let t = s.intersect(&ray, 0.0, 0.0, f64::INFINITY).unwrap();
        assert!(
            (t - (c.length() - r)).abs() <= 1e-12 * c.length(),
            "{t} vs {}",
            c.length() - r
        );
        // From the center, the far root: the radius.
        let inside = Ray::new(c, V3::new(0.3, -0.4, 0.5));
        let t = s.intersect(&inside, 0.0, 0.0, f64::INFINITY).unwrap();
        assert!((t - r).abs() < 1e-12 * r.max(1.0));
        // A ray passing at distance 1.01 r misses: closest approach |c| sin(angle).
        let side = (c.cross(V3::new(0.0, 1.0, 0.0))).normalize() * (1.01 * r);
        let miss = Ray::new(V3::default(), c + side);
        let d = (c + side).normalize();
        let closest = (c - d * c.dot(d)).length();
        assert_eq!(
            s.intersect(&miss, 0.0, 0.0, f64::INFINITY).is_some(),
            closest < r
        );
        // t_max before the sphere: no hit.
        assert_eq!(s.intersect(&ray, 0.0, 0.0, c.length() - r - 1e-6), None);
    }
    // A moving sphere: at time 1 it has moved out of the ray.
    let mut m = Sphere::new(V3::new(0.0, 0.0, -5.0), 1.0, 0.5);
    m.velocity = V3::new(3.0, 0.0, 0.0);
    let ray = Ray::new(V3::default(), V3::new(0.0, 0.0, -1.0));
    assert_eq!(m.intersect(&ray, 0.0, 0.0, f64::INFINITY), Some(4.0));
    assert_eq!(m.intersect(&ray, 1.0, 0.0, f64::INFINITY), None);
}

#[test]
fn plane_and_quad_hits_are_exact() {
    let p = Plane {
        height: 0.5,
        check: 1.0,
        albedo: (0.2, 0.8),
    };
    // From (0, 2.5, 0) along (3, -4, 0)/5: y drops by 0.8 a unit, 2 / 0.8 = 2.5.
    let r = Ray::new(V3::new(0.0, 2.5, 0.0), V3::new(3.0, -4.0, 0.0));
    assert_eq!(p.intersect(&r, 0.0, f64::INFINITY), Some(2.5));
    assert_eq!(p.intersect(&r, 0.0, 2.0), None);
    let up = Ray::new(V3::new(0.0, 2.5, 0.0), V3::new(0.0, 1.0, 0.0));
    assert_eq!(p.intersect(&up, 0.0, f64::INFINITY), None);
    assert_eq!(p.albedo_at(V3::new(0.5, 0.5, 0.5)), 0.2);
    assert_eq!(p.albedo_at(V3::new(1.5, 0.5, 0.5)), 0.8);
    assert_eq!(p.albedo_at(V3::new(-0.5, 0.5, 0.5)), 0.8);
    let q = standard_scene().light;
    assert_eq!(q.area(), 1.5);
    assert_eq!(q.normal(), V3::new(0.0, -1.0, 0.0));
    let r = Ray::new(V3::new(0.25, 0.0, 0.0), V3::new(0.0, 1.0, 0.0));
    let (t, u, v) = q.intersect(&r, 0.0, f64::INFINITY).unwrap();
    assert!((t - 2.6).abs() < 1e-15 && (u - 0.5).abs() < 1e-15 && (v - 0.5).abs() < 1e-15);
}

/// The irradiance at a point below a corner of an `a x b` rectangle parallel to it at
/// height `h` (the classic differential-area-to-parallel-rectangle form factor, times pi L):
/// `F = 1/(2 pi) [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2) atan(A/sqrt(1+B^2))]`.
fn corner_irradiance(a: f64, b: f64, h: f64, radiance: f64) -> f64 {
    let (x, y) = (a / h, b / h);
    let (sx, sy) = ((1.0 + x * x).sqrt(), (1.0 + y * y).sqrt());
    let f = (x / sx * (y / sx).atan() + y / sy * (x / sy).atan()) / (2.0 * PI);
    PI * radiance * f
}

#[test]
fn lambert_polygon_irradiance_matches_the_rectangle_form_factor() {
    for (a, b, h) in [
        (1.0, 1.0, 1.0),
        (1.5, 0.5, 2.0),
        (3.0, 0.2, 0.7),
        (0.1, 0.1, 10.0),
    ] {
        let quad = [
            V3::new(0.0, h, 0.0),
            V3::new(a, h, 0.0),
            V3::new(a, h, b),
            V3::new(0.0, h, b),
        ];
        let e = lambert_irradiance(V3::default(), V3::new(0.0, 1.0, 0.0), &quad, 2.0);
        let want = corner_irradiance(a, b, h, 2.0);
        assert!(
            (e - want).abs() < 1e-12 * want,
            "{a} {b} {h}: {e} vs {want}"
        );
    }
    // Four corner rectangles add up to the centered one (superposition).
    let q = |x0: f64, x1: f64, z0: f64, z1: f64| {
        [
            V3::new(x0, 1.0, z0),
            V3::new(x1, 1.0, z0),
            V3::new(x1, 1.0, z1),
            V3::new(x0, 1.0, z1),
        ]
    };
    let n = V3::new(0.0, 1.0, 0.0);
    let whole = lambert_irradiance(V3::default(), n, &q(-1.0, 2.0, -0.5, 1.5), 1.0);
    let parts = corner_irradiance(1.0, 0.5, 1.0, 1.0)
        + corner_irradiance(2.0, 0.5, 1.0, 1.0)
        + corner_irradiance(1.0, 1.5, 1.0, 1.0)
        + corner_irradiance(2.0, 1.5, 1.0, 1.0);
    assert!((whole - parts).abs() < 1e-12);
}

/// The area estimator with `shadows = false` averages to Lambert's irradiance, also for
/// tilted normals that see only part of the light (the clipped polygon).
#[test]
fn area_sampled_quad_light_irradiance_matches_lambert() {
    let scene = standard_scene();
    let s = OwenSobol::new(2, 9).unwrap();
    let n = 1u32 << 16;
    for (x, normal) in [
        (V3::new(0.2, 0.0, 1.5), V3::new(0.0, 1.0, 0.0)),
        (V3::new(-1.0, 0.3, 0.4), V3::new(0.6, 0.8, 0.0)),
        (V3::new(0.3, 1.2, 0.0), V3::new(1.0, 0.1, 0.2).normalize()), // light partly behind
        (V3::new(2.0, 0.5, -1.0), V3::new(-0.3, 0.2, 0.9).normalize()),
    ] {
        let want = light_irradiance(&scene, x, normal);
        let mut sum = 0.0;
        for i in 0..n {
            let u = [
                to_f64(s.sample(i, 0).unwrap()),
                to_f64(s.sample(i, 1).unwrap()),
            ];
            sum += light_sample(&scene, x, normal, u, 0.0, false);
        }
        let got = sum / n as f64;
        assert!(want > 0.0);
        assert!((got - want).abs() < 2e-3 * want, "{x:?}: {got} vs {want}");
    }
    // Above the light (behind its emitting side): nothing.
    assert_eq!(
        light_irradiance(&scene, V3::new(0.0, 3.0, 0.0), V3::new(0.0, 1.0, 0.0)),
        0.0
    );
}

#[test]
fn ambient_occlusion_of_an_unoccluded_plane_is_exactly_one() {
    let scene = Scene {
        spheres: vec![],
        ground: Some(Plane {
            height: 0.0,
            check: 0.0,
            albedo: (0.5, 0.5),
        }),
        light: standard_scene().light,
        radiance: 1.0,
        sky: 0.0,
    };
    let s = Independent::new(2, 3).unwrap();
    for i in 0..20_000u32 {
        let u = [
            to_f64(s.sample(i, 0).unwrap()),
            to_f64(s.sample(i, 1).unwrap()),
        ];
        let x = V3::new(i as f64 * 0.01 - 100.0, 0.0, 3.0);
        assert_eq!(ao_sample(&scene, x, V3::new(0.0, 1.0, 0.0), u, 0.0), 1.0);
    }
}

/// A point on the plane below a sphere of angular radius `alpha` centered on its normal:
/// the cosine-weighted occluded fraction is `sin^2 alpha`, so AO = `cos^2 alpha`. The mean
/// over many independent seeds lies within 4 standard errors of it.
#[test]
fn cosine_hemisphere_ao_estimator_is_unbiased() {
    let (d, r) = (2.0, 1.2);
    let scene = Scene {
        spheres: vec![Sphere::new(V3::new(0.0, d, 0.0), r, 0.5)],
        ground: Some(Plane {
            height: 0.0,
            check: 0.0,
            albedo: (0.5, 0.5),
        }),
        light: standard_scene().light,
        radiance: 1.0,
        sky: 0.0,
    };
    let truth = 1.0 - (r / d) * (r / d);
    let (seeds, per) = (400u64, 256u32);
    let mut sum = 0.0;
    for seed in 0..seeds {
        let s = Independent::new(2, seed).unwrap();
        for i in 0..per {
            let u = [
                to_f64(s.sample(i, 0).unwrap()),
                to_f64(s.sample(i, 1).unwrap()),
            ];
            sum += ao_sample(&scene, V3::default(), V3::new(0.0, 1.0, 0.0), u, 0.0);
        }
    }
    let n = (seeds * per as u64) as f64;
    let mean = sum / n;
    let sigma = (truth * (1.0 - truth) / n).sqrt();
    assert!(
        (mean - truth).abs() < 4.0 * sigma,
        "{mean} vs {truth} (sigma {sigma})"
    );
}

#[test]
fn camera_projection_inverts_the_pinhole_ray_and_the_lens_focuses() {
    let cam = standard_camera(64, 48, false).unwrap();
    for (px, py) in [(0.5, 0.5), (31.2, 20.7), (63.9, 47.1)] {
        let ray = cam.ray(px, py, [0.5, 0.5]);
        let p = cam.project(ray.at(3.7)).unwrap();
        assert!((p[0] - px).abs() < 1e-9 && (p[1] - py).abs() < 1e-9);
    }
    // Every lens sample of a film point passes through the same point at the focus depth.
    let lens = standard_camera(64, 48, true).unwrap();
    let target = V3::new(0.0, 0.5, 0.0);
    let c = lens.project(target).unwrap();
    let mut hits = Vec::new();
    for lu in [[0.1, 0.2], [0.9, 0.5], [0.4, 0.95]] {
        let ray = lens.ray(c[0], c[1], lu);
        // Closest approach to the target.
        let t = (target - ray.origin).dot(ray.dir);
        hits.push((ray.at(t) - target).length());
    }
    assert!(hits.iter().all(|&h| h < 1e-6), "{hits:?}");
}

#[test]
fn quad_light_patterns_are_stratified_and_nets() {
    let (st, so) = quad_light_uv(16, 5).unwrap();
    for pts in [&st, &so] {
        let mut cells = [0u32; 16];
        for p in pts.iter() {
            cells[(p[0] * 4.0) as usize * 4 + (p[1] * 4.0) as usize] += 1;
        }
        assert!(cells.iter().all(|&c| c == 1), "{cells:?}");
    }
    // Sobol': a (0, 4, 2)-net, one point in every 1/16 x 1 and 1 x 1/16 strip too.
    for k in 0..2 {
        let mut strips = [0u32; 16];
        for p in &so {
            strips[(p[k] * 16.0) as usize] += 1;
        }
        assert!(strips.iter().all(|&c| c == 1));
    }
    let (wst, wso) = quad_light_points(16, 5).unwrap();
    for (uv, w) in st.iter().zip(&wst).chain(so.iter().zip(&wso)) {
        assert!((w[0] - (-0.5 + 1.5 * uv[0])).abs() < 1e-15);
        assert!((w[1] - (-0.5 + uv[1])).abs() < 1e-15);
    }
    assert!(quad_light_points(12, 0).is_err());
    assert!(quad_light_points(0, 0).is_err());
    assert!(quad_light_points(1 << 20, 0).is_err());
}

#[test]
fn invalid_study_options_are_errors() {
    let o = small();
    assert!(check(&o).is_ok());
    for bad in [
        StudyOptions { width: 0, ..o },
        StudyOptions { height: 4, ..o },
        StudyOptions { spp: 0, ..o },
        StudyOptions { spp: 12, ..o },
        StudyOptions { seeds: 0, ..o },
        StudyOptions {
            reference_spp: 8,
            ..o
        },
        StudyOptions {
            reference_spp: 1000,
            ..o
        },
        StudyOptions {
            width: 1 << 20,
            height: 1 << 20,
            ..o
        },
    ] {
        assert!(check(&bad).is_err(), "{bad:?}");
        assert!(pixel_area_study(&bad).is_err());
    }
    // Past the sample budget: refused at once.
    let huge = StudyOptions {
        width: 1024,
        height: 1024,
        spp: 1024,
        seeds: 64,
        reference_spp: 1 << 16,
    };
    assert!(check(&huge).is_ok());
    let t = std::time::Instant::now();
    assert!(soft_shadow_study(&huge).is_err());
    assert!(t.elapsed().as_secs_f64() < 1.0);
}

/// The lecture's tables at n = 16: independent > stratified > Sobol' in MSE, for the
/// pixel-area and the quad-light integrands.
#[test]
fn n16_studies_order_independent_stratified_sobol() {
    for study in [
        pixel_area_study(&small()).unwrap(),
        soft_shadow_study(&small()).unwrap(),
    ] {
        let m: Vec<f64> = study.mse.iter().map(|e| e.mse).collect();
        assert_eq!(study.mse[0].sampler, "independent");
        assert!(m[0] > m[1] && m[1] > m[2], "{}: {m:?}", study.name);
        assert_eq!(study.renders.len(), 3);
        assert_eq!(study.errors.len(), 3);
        assert_eq!(study.mse[0].relative, 1.0);
        // The error image is render - reference.
        let (r, e) = (&study.renders[1].1, &study.errors[1].1);
        assert!((r.pixels[100] - study.reference.pixels[100] - e.pixels[100]).abs() < 1e-15);
    }
}

#[test]
fn motion_defocus_and_pixel_light_qmc_beats_independent() {
    let md = motion_defocus_study(&small()).unwrap();
    assert_eq!(md.mse[1].sampler, "halton + perm");
    assert!(md.mse[2].mse < md.mse[0].mse, "{:?}", md.mse);
    let pl = pixel_light_study(&small()).unwrap();
    assert_eq!(pl.mse.len(), 6);
    assert!(
        pl.mse[1..].iter().all(|e| e.mse < pl.mse[0].mse),
        "{:?}",
        pl.mse
    );
}

/// ZSobol's ambient-occlusion error is blue: less low-frequency power than white noise
/// (independent points, and Sobol' fast-owen with a seed per pixel).
#[test]
fn zsobol_ao_error_has_less_low_frequency_power() {
    let o = StudyOptions {
        width: 64,
        height: 64,
        spp: 4,
        seeds: 4,
        reference_spp: 1024,
    };
    let ao = ambient_occlusion_study(&o).unwrap();
    let names: Vec<&str> = ao.mse.iter().map(|e| e.sampler.as_str()).collect();
    assert_eq!(
        names,
        [
            "independent",
            "sobol + fast-owen",
            "zsobol + fast-owen",
            "bn-sobol",
            "bn-lattice"
        ]
    );
    let (ind, owen, z) = (&ao.mse[0], &ao.mse[1], &ao.mse[2]);
    // The table-driven blue-noise samplers too.
    for bn in &ao.mse[3..] {
        assert!(
            bn.low_band < 0.75 * ind.low_band.min(owen.low_band),
            "{:?}",
            ao.mse
        );
    }
    // Silhouettes and the sky's zero-error rows dilute the effect: about 0.6 against 1.1.
    assert!(
        z.low_band < 0.75 * ind.low_band.min(owen.low_band),
        "{:?}",
        ao.mse
    );
    assert!(z.low_band_absolute < owen.low_band_absolute);
    // White noise: normalized low-band power near 1.
    assert!((0.5..1.5).contains(&ind.low_band), "{}", ind.low_band);
}

/// The reference's own error is far below the measured MSEs: doubling its sample count
/// (and changing its scramble) moves it by much less than the best n = 16 MSE.
#[test]
fn reference_error_is_far_below_the_measured_mse() {
    let o = small();
    for (study, best) in [
        (Study::SoftShadow, soft_shadow_study(&o).unwrap()),
        (Study::PixelArea, pixel_area_study(&o).unwrap()),
    ] {
        let r2 = reference_image(study, &o, 2 * o.reference_spp, 77).unwrap();
        let drift = best.reference.mse(&r2).unwrap();
        let min = best.mse.iter().map(|e| e.mse).fold(f64::INFINITY, f64::min);
        assert!(drift < 0.01 * min, "{}: {drift} vs {min}", best.name);
    }
}

#[test]
fn studies_are_deterministic() {
    let o = StudyOptions {
        width: 8,
        height: 8,
        spp: 4,
        seeds: 2,
        reference_spp: 16,
    };
    assert_eq!(
        pixel_light_study(&o).unwrap(),
        pixel_light_study(&o).unwrap()
    );
}

/// `StudyOptions::quick()`: all five studies in under 30 s (release, loaded machine).
/// `cargo test --release --all-features scene_quick_timing -- --ignored`
#[test]
#[ignore]
fn scene_quick_timing() {
    let t = std::time::Instant::now();
    for s in Study::ALL {
        s.run(&StudyOptions::quick(), &qmckit::work::Budget::UNLIMITED)
            .unwrap();
    }
    let secs = t.elapsed().as_secs_f64();
    println!("quick studies: {secs:.2} s");
    assert!(secs < 30.0);
}
