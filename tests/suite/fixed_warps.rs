//! Fixed-point warps against the f32 warps and against f64 trigonometry.
#![cfg(all(feature = "fixed", feature = "libm"))]

use fixed::types::{I2F30, U0F32};
use qmckit::Sobol;
use qmckit::bits::to_f32;
use qmckit::warp::fixed as fx;
use qmckit::warp::{disk, sphere, triangle};

fn grid() -> Vec<[u32; 2]> {
    let s = Sobol::new(2).unwrap();
    (0..1u32 << 14)
        .map(|i| [s.sample(i, 0).unwrap(), s.sample(i, 1).unwrap()])
        .chain([
            [0, 0],
            [u32::MAX, u32::MAX],
            [0, u32::MAX],
            [u32::MAX, 0],
            [1 << 31, 1 << 31],
        ])
        .collect()
}

fn f(x: I2F30) -> f64 {
    x.to_num::<f64>()
}

fn uq(u: [u32; 2]) -> [U0F32; 2] {
    u.map(U0F32::from_bits)
}

fn uf(u: [u32; 2]) -> [f32; 2] {
    u.map(to_f32)
}

#[test]
fn sin_cos_and_atan2_match_f64() {
    let (mut worst_sc, mut worst_at) = (0f64, 0f64);
    let mut t = 0x1234_5678u32;
    for k in 0..200_000u32 {
        t = t.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
        let t = if k < 8 { k << 29 } else { t };
        let (s, c) = fx::sin_cos_turns(t);
        let a = t as f64 / 4_294_967_296.0 * std::f64::consts::TAU;
        worst_sc = worst_sc.max((s as f64 / 2f64.powi(30) - a.sin()).abs());
        worst_sc = worst_sc.max((c as f64 / 2f64.powi(30) - a.cos()).abs());
        // atan2 of the point at that angle, radius 2^30.
        let back = fx::atan2_turns(s as i64, c as i64);
        let diff = (back.wrapping_sub(t) as i32) as f64 / 4_294_967_296.0;
        worst_at = worst_at.max(diff.abs());
    }
    println!("sin/cos max error {worst_sc:.2e}; atan2 round trip max error {worst_at:.2e} turns");
    assert!(worst_sc < 1e-7, "sin/cos {worst_sc}");
    assert!(worst_at < 2e-8, "atan2 {worst_at}");
    assert_eq!(fx::atan2_turns(0, 0), 0);
    // Small inputs are scaled up first: a half turn within a few units of 2^-32.
    assert!((fx::atan2_turns(0, -5) as i64 - (1i64 << 31)).abs() < 8);
    assert!((fx::atan2_turns(3, 0) as i64 - (1i64 << 30)).abs() < 8);
}

/// Oracles in f64 with the exact inputs `u = bits / 2^32` (std trigonometry).
fn oracle(k: usize, u: [u32; 2]) -> Vec<f64> {
    let (a, b) = (u[0] as f64 / 4_294_967_296.0, u[1] as f64 / 4_294_967_296.0);
    let tau = std::f64::consts::TAU;
    let concentric = || {
        let (x, y) = (2.0 * a - 1.0, 2.0 * b - 1.0);
        if x == 0.0 && y == 0.0 {
            return [0.0, 0.0];
        }
        let (r, t) = if x.abs() > y.abs() {
            (x, std::f64::consts::FRAC_PI_4 * (y / x))
        } else {
            (
                y,
                std::f64::consts::FRAC_PI_2 - std::f64::consts::FRAC_PI_4 * (x / y),
            )
        };
        [r * t.cos(), r * t.sin()]
    };
    match k {
        0 => vec![b.sqrt() * (tau * a).cos(), b.sqrt() * (tau * a).sin()],
        1 => concentric().to_vec(),
        2 => {
            let r = (1.0 - a * a).max(0.0).sqrt();
            vec![r * (tau * b).cos(), r * (tau * b).sin(), a]
        }
        3 => {
            let d = concentric();
            vec![
                d[0],
                d[1],
                (1.0 - d[0] * d[0] - d[1] * d[1]).max(0.0).sqrt(),
            ]
        }
        _ => {
            let (b0, b1) = if a < b {
                (a / 2.0, b - a / 2.0)
            } else {
                (a - b / 2.0, b / 2.0)
            };
            vec![b0, b1, 1.0 - b0 - b1]
        }
    }
}

fn fixed(k: usize, u: [u32; 2]) -> Vec<f64> {
    match k {
        0 => fx::sample_uniform_disk_polar(uq(u)).map(f).to_vec(),
        1 => fx::sample_uniform_disk_concentric(uq(u)).map(f).to_vec(),
        2 => fx::sample_uniform_hemisphere(uq(u)).map(f).to_vec(),
        3 => fx::sample_cosine_hemisphere(uq(u)).map(f).to_vec(),
        _ => fx::sample_uniform_triangle(uq(u)).map(f).to_vec(),
    }
}

fn float(k: usize, u: [u32; 2]) -> Vec<f64> {
    let v: Vec<f32> = match k {
        0 => disk::sample_uniform_disk_polar(uf(u)).to_vec(),
        1 => disk::sample_uniform_disk_concentric(uf(u)).to_vec(),
        2 => sphere::sample_uniform_hemisphere(uf(u)).to_vec(),
        3 => sphere::sample_cosine_hemisphere(uf(u)).to_vec(),
        _ => triangle::sample_uniform_triangle(uf(u)).to_vec(),
    };
    v.into_iter().map(f64::from).collect()
}

/// Every fixed-point warp is within 1e-7 of the exact map (f64 oracle) everywhere, and within
/// 1e-6 of the f32 warp where the f32 input is exact (the f32 warps' own rounding; the f32
/// path also rounds inputs to 24 significant bits, which near the hemisphere's pole moves
/// points by up to 3e-4, so those inputs are compared with the oracle only).
#[test]
fn fixed_warps_agree_with_exact_and_f32() {
    let names = ["polar", "concentric", "hemisphere", "cosine", "triangle"];
    for (k, name) in names.iter().enumerate() {
        let (mut vs_exact, mut vs_f32) = (0f64, 0f64);
        for u in grid() {
            let x = fixed(k, u);
            for (a, b) in x.iter().zip(oracle(k, u)) {
                vs_exact = vs_exact.max((a - b).abs());
            }
            if u.iter()
                .all(|&v| to_f32(v) as f64 * 4_294_967_296.0 == v as f64)
            {
                for (a, b) in x.iter().zip(float(k, u)) {
                    vs_f32 = vs_f32.max((a - b).abs());
                }
            }
        }
        println!(
            "fixed {name}: max |fixed - exact| {vs_exact:.1e}, max |fixed - f32| {vs_f32:.1e}"
        );
        assert!(vs_exact < 1e-7, "{name} vs exact: {vs_exact}");
        assert!(vs_f32 < 1e-6, "{name} vs f32: {vs_f32}");
    }
}

/// Fixed-point inverses return the input within 2^-20 (away from the polar map's centre).
#[test]
fn fixed_inverses_invert() {
    let close = |a: [U0F32; 2], b: [u32; 2], tol: f64| {
        for k in 0..2 {
            let d = (a[k].to_bits().wrapping_sub(b[k]) as i32) as f64 / 4_294_967_296.0;
            assert!(d.abs() < tol, "{a:?} vs {b:?}");
        }
    };
    for u in grid() {
        let interior = u.iter().all(|&x| x > 1 << 20 && x < u32::MAX - (1 << 20));
        if !interior {
            continue;
        }
        close(
            fx::invert_uniform_disk_polar(fx::sample_uniform_disk_polar(uq(u))),
            u,
            1e-6,
        );
        close(
            fx::invert_uniform_disk_concentric(fx::sample_uniform_disk_concentric(uq(u))),
            u,
            1e-6,
        );
        close(
            fx::invert_uniform_hemisphere(fx::sample_uniform_hemisphere(uq(u))),
            u,
            1e-6,
        );
        close(
            fx::invert_cosine_hemisphere(fx::sample_cosine_hemisphere(uq(u))),
            u,
            1e-6,
        );
        close(
            fx::invert_uniform_triangle(fx::sample_uniform_triangle(uq(u))),
            u,
            1e-8,
        );
    }
}

#[test]
fn fixed_densities() {
    let pi = std::f64::consts::PI;
    assert!((f(fx::UNIFORM_DISK_PDF) - 1.0 / pi).abs() < 2e-9);
    assert!((f(fx::UNIFORM_HEMISPHERE_PDF) - 0.5 / pi).abs() < 2e-9);
    let half = I2F30::from_num(0.5);
    assert!((f(fx::cosine_hemisphere_pdf(half)) - 0.5 / pi).abs() < 2e-9);
    assert_eq!(f(fx::cosine_hemisphere_pdf(I2F30::from_num(-0.5))), 0.0);
}

/// Property tests over the whole input types: samples at any `u` (0, 1, `2^32 - 1` and
/// random) against the f64 oracle; inverses at any `I2F30` (including `i32::MIN` and
/// `i32::MAX`, far off the domain), which must not overflow and must equal the f64 formula
/// saturated into `[0, 1)`; `atan2_turns` at any `i64` pair (including `i64::MIN`) against
/// `f64::atan2`. With overflow checks off (release) an overflow would show up as a wrapped,
/// far-off value.
mod properties {
    use super::*;
    use proptest::prelude::*;

    const TWO32: f64 = 4_294_967_296.0;

    fn u32s() -> impl Strategy<Value = u32> {
        prop_oneof![
            prop::sample::select(vec![
                0,
                1,
                2,
                (1 << 31) - 1,
                1 << 31,
                (1 << 31) + 1,
                u32::MAX - 1,
                u32::MAX
            ]),
            any::<u32>(),
        ]
    }

    fn q30s() -> impl Strategy<Value = i32> {
        prop_oneof![
            prop::sample::select(vec![
                i32::MIN,
                i32::MIN + 1,
                -(1 << 30) - 1,
                -(1 << 30),
                -1,
                0,
                1,
                1 << 30,
                (1 << 30) + 1,
                i32::MAX - 1,
                i32::MAX,
            ]),
            any::<i32>(),
            -(1i32 << 30)..=(1 << 30),
        ]
    }

    fn i64s() -> impl Strategy<Value = i64> {
        prop_oneof![
            prop::sample::select(vec![
                i64::MIN,
                i64::MIN + 1,
                -(1 << 62),
                -1,
                0,
                1,
                1 << 62,
                i64::MAX - 1,
                i64::MAX
            ]),
            any::<i64>(),
            -1000i64..1000,
        ]
    }

    /// `x` (a fraction) saturated into `[0, 1)` as 0.32 bits, as the inverses promise.
    fn saturate(x: f64) -> f64 {
        x.clamp(0.0, (TWO32 - 1.0) / TWO32)
    }

    fn frac(x: U0F32) -> f64 {
        x.to_bits() as f64 / TWO32
    }

    fn turn_gap(a: f64, b: f64) -> f64 {
        let d = (a - b).rem_euclid(1.0);
        d.min(1.0 - d)
    }

    fn turn(y: f64, x: f64) -> f64 {
        (y.atan2(x) / std::f64::consts::TAU).rem_euclid(1.0)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        #[test]
        fn samples_match_the_exact_maps_everywhere(u in [u32s(), u32s()]) {
            for k in 0..5 {
                let (got, want) = (fixed(k, u), oracle(k, u));
                for (g, w) in got.iter().zip(&want) {
                    prop_assert!((g - w).abs() < 1e-7, "warp {k} {u:?}: {got:?} vs {want:?}");
                }
            }
            let d = fx::sample_uniform_disk_concentric(uq(u)).map(f);
            prop_assert!(d[0].hypot(d[1]) <= 1.0 + 1e-7);
        }

        #[test]
        fn atan2_turns_takes_any_pair(y in i64s(), x in i64s()) {
            let t = fx::atan2_turns(y, x) as f64 / TWO32;
            if x == 0 && y == 0 {
                prop_assert_eq!(t, 0.0);
            } else {
                let want = turn(y as f64, x as f64);
                prop_assert!(
                    turn_gap(t, want) < 1e-8,
                    "atan2({y}, {x}) = {t} turns, want {want}"
                );
            }
        }

        #[test]
        fn inverses_take_any_q30(x in q30s(), y in q30s(), z in q30s()) {
            let (p, fz) = (
                [I2F30::from_bits(x), I2F30::from_bits(y)],
                I2F30::from_bits(z),
            );
            let (xf, yf, zf) = (f(p[0]), f(p[1]), f(fz));
            let r2 = xf * xf + yf * yf;
            // Polar: u = (angle turn, r^2).
            let polar = fx::invert_uniform_disk_polar(p);
            prop_assert!(
                (frac(polar[1]) - saturate(r2)).abs() <= 1.0 / TWO32 + 1e-12,
                "polar {p:?}: {polar:?}"
            );
            if r2 > 0.0 {
                prop_assert!(turn_gap(frac(polar[0]), turn(yf, xf)) < 1e-8);
            }
            // Concentric: the f32 warp's inverse formula in f64, then saturated.
            let r = r2.sqrt();
            let mut phi = yf.atan2(xf);
            let pi = std::f64::consts::PI;
            if phi < -pi / 4.0 {
                phi += 2.0 * pi;
            }
            let k = 4.0 / pi;
            let (a, b) = if phi < pi / 4.0 {
                (r, phi * k * r)
            } else if phi < 3.0 * pi / 4.0 {
                (-(phi - pi / 2.0) * k * r, r)
            } else if phi < 5.0 * pi / 4.0 {
                (-r, -(phi - pi) * k * r)
            } else {
                ((phi - 3.0 * pi / 2.0) * k * r, -r)
            };
            let c = fx::invert_uniform_disk_concentric(p);
            // Within 1e-7 except right at an octant's edge, where the angle's last bits pick
            // the branch (both branches give the same point of the square's boundary only on
            // the unit circle).
            let near_edge = (phi * 4.0 / pi - (phi * 4.0 / pi).round()).abs() < 1e-7;
            if !near_edge {
                for (g, w) in [frac(c[0]), frac(c[1])]
                    .iter()
                    .zip([saturate((a + 1.0) / 2.0), saturate((b + 1.0) / 2.0)])
                {
                    prop_assert!(
                        (g - w).abs() < 1e-7 * r.max(1.0),
                        "concentric {p:?}: {c:?} vs {a} {b}"
                    );
                }
            }
            // Hemispheres: u0 = z saturated, u1 the turn.
            let h = fx::invert_uniform_hemisphere([p[0], p[1], fz]);
            prop_assert!((frac(h[0]) - saturate(zf)).abs() <= 4.0 / TWO32);
            let cos = fx::invert_cosine_hemisphere([p[0], p[1], fz]);
            prop_assert_eq!(cos, c);
            // Triangle: u = (2 b0, b0 + b1) or (b0 + b1, 2 b1), saturated.
            let t = fx::invert_uniform_triangle([p[0], p[1], fz]);
            let (w0, w1) = if xf < yf {
                (2.0 * xf, xf + yf)
            } else {
                (xf + yf, 2.0 * yf)
            };
            prop_assert!(
                (frac(t[0]) - saturate(w0)).abs() <= 4.0 / TWO32,
                "triangle {p:?}: {t:?}"
            );
            prop_assert!(
                (frac(t[1]) - saturate(w1)).abs() <= 4.0 / TWO32,
                "triangle {p:?}: {t:?}"
            );
            // Density: cos / pi, 0 below the horizon.
            let pdf = f(fx::cosine_hemisphere_pdf(fz));
            prop_assert!((pdf - zf.max(0.0) / pi).abs() < 4e-9);
        }

        #[test]
        fn inverses_invert_the_samples(u in [u32s(), u32s()]) {
            let back = |v: [U0F32; 2]| [v[0].to_bits(), v[1].to_bits()];
            let gap = |a: u32, b: u32| (a.wrapping_sub(b) as i32).unsigned_abs() as f64 / TWO32;
            let tri = back(fx::invert_uniform_triangle(fx::sample_uniform_triangle(
                uq(u),
            )));
            prop_assert!(
                gap(tri[0], u[0]) < 1e-8 && gap(tri[1], u[1]) < 1e-8,
                "{u:?} -> {tri:?}"
            );
            let c = back(fx::invert_uniform_disk_concentric(
                fx::sample_uniform_disk_concentric(uq(u)),
            ));
            prop_assert!(
                (c[0] as f64 - u[0] as f64).abs() / TWO32 < 1e-6
                    && (c[1] as f64 - u[1] as f64).abs() / TWO32 < 1e-6,
                "{u:?} -> {c:?}"
            );
            let p = back(fx::invert_uniform_disk_polar(
                fx::sample_uniform_disk_polar(uq(u)),
            ));
            prop_assert!((p[1] as f64 - u[1] as f64).abs() / TWO32 < 1e-6);
            if u[1] as f64 / TWO32 > 1e-6 {
                prop_assert!(gap(p[0], u[0]) < 1e-6, "{u:?} -> {p:?}");
            }
        }
    }
}
