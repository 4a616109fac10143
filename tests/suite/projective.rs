//! Projective blue noise (Reinert et al. 2016) and projective sliced optimal transport
//! (Paulin et al. 2020) against their stated properties: the radii each set states hold
//! for every pair (brute force, full space and every 1D and 2D axis projection); the
//! periodograms of the 1D and 2D projections have mean low-frequency power well below
//! that of independent uniform points of the same size (white noise, expected level 1);
//! plain dart throwing in the full space, the contrast, leaves its 1D projections white;
//! projective SOT lowers the sliced Wasserstein distance of the projections below plain
//! SOT's at equal iterations, and it falls with the iterations.

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::blue_noise::{ProjectiveBlueNoise, Sot};
use qmckit::work::Budget;

use crate::common::independent_set as uniform;

/// Coordinates `axes` of every point of `pts` (`d` a point), as a 2D set (a 1D projection
/// is put on the line `y = 0`, where `P(k, 0)` is its 1D periodogram).
fn project(pts: &[f64], d: usize, axes: &[usize]) -> Vec<f64> {
    pts.chunks(d)
        .flat_map(|p| [p[axes[0]], axes.get(1).map_or(0.0, |&b| p[b])])
        .collect()
}

/// Mean periodogram value of the projection on `axes` over the low frequencies: `1 <= k
/// <= kmax` on the axis for a 1D projection, `1 <= |k| <= kmax` for a 2D one.
fn low_power(pts: &[f64], d: usize, axes: &[usize], kmax: usize) -> f64 {
    let proj = project(pts, d, axes);
    let s = spectrum_2d(Points::new(&proj, 2).unwrap(), kmax, &Budget::DEFAULT).unwrap();
    let (mut sum, mut count) = (0.0, 0usize);
    for (kx, ky, p) in s.iter() {
        let r2 = (kx * kx + ky * ky) as usize;
        let inside = if axes.len() == 1 {
            ky == 0 && kx >= 1
        } else {
            r2 >= 1 && r2 <= kmax * kmax
        };
        if inside {
            sum += p;
            count += 1;
        }
    }
    sum / count as f64
}

/// The mean low-frequency power of every 1D projection and of every 2D projection,
/// averaged over the sets: 1D up to `k = N / 8`, 2D up to `|k| = sqrt(N) / 2` (the
/// peaks of a spacing `1/N` on the line and of the hexagonal spacing in the plane lie
/// near `N` and `1.07 sqrt(N)`).
fn projection_power(sets: &[Vec<f64>], n: usize, d: usize) -> (f64, f64) {
    let (k1, k2) = (n / 8, ((n as f64).sqrt() / 2.0) as usize);
    let (mut one, mut two, mut c1, mut c2) = (0.0, 0.0, 0, 0);
    for pts in sets {
        for a in 0..d {
            one += low_power(pts, d, &[a], k1);
            c1 += 1;
            for b in a + 1..d {
                two += low_power(pts, d, &[a, b], k2);
                c2 += 1;
            }
        }
    }
    (one / c1 as f64, two / c2 as f64)
}

/// The smallest toroidal distance over pairs in the full space, along one axis, and in a
/// pair of axes.
fn min_distances(pts: &[f64], d: usize) -> (f64, f64, f64) {
    let wrap = |a: f64, b: f64| {
        let t = (a - b).abs();
        t.min(1.0 - t)
    };
    let (mut full, mut one, mut two) = (f64::INFINITY, f64::INFINITY, f64::INFINITY);
    let rows: Vec<&[f64]> = pts.chunks(d).collect();
    for (i, x) in rows.iter().enumerate() {
        for y in &rows[i + 1..] {
            let t: Vec<f64> = x.iter().zip(y.iter()).map(|(&a, &b)| wrap(a, b)).collect();
            full = full.min(t.iter().map(|v| v * v).sum::<f64>().sqrt());
            for a in 0..d {
                one = one.min(t[a]);
                for b in a + 1..d {
                    two = two.min((t[a] * t[a] + t[b] * t[b]).sqrt());
                }
            }
        }
    }
    (full, one, two)
}

#[test]
#[ignore = "measurement: cargo test --release --all-features --test suite projective::measure -- --ignored --nocapture"]
fn measure() {
    for &(n, d) in &[(1024u64, 2usize), (1024, 3), (1024, 4), (4096, 2)] {
        for proj in [0u8, 2] {
            for trials in [200u32, 1000, 5000] {
                let b = ProjectiveBlueNoise::new(n, d)
                    .unwrap()
                    .projections(proj)
                    .unwrap()
                    .schedule(0.9, 0.99, trials)
                    .unwrap();
                let t = std::time::Instant::now();
                let p = b.run(&Budget::seconds(600.0).unwrap()).unwrap();
                let secs = t.elapsed().as_secs_f64();
                let pts = p.points.to_f64();
                // In 2D the "2D" column is the full space's low-frequency power.
                let (one, mut two) = projection_power(std::slice::from_ref(&pts), n as usize, d);
                if d == 2 {
                    two = low_power(&pts, 2, &[0, 1], ((n as f64).sqrt() / 2.0) as usize);
                }
                println!(
                    "n {n} d {d} proj {proj} T {trials}: rho {:.3} candidates/N {:.1} time {secs:.3}s est {:.3}s  low power 1D {one:.3} 2D {two:.3}",
                    p.relative_radius,
                    p.candidates as f64 / n as f64,
                    b.cost().seconds()
                );
            }
        }
    }
}

/// The squared Wasserstein distance between the 1D projection on axis `a` and the
/// uniform measure of `[0, 1]`, exact: the sorted `k`-th value is coupled with the
/// quantile block `[(k - 1)/N, k/N]`, `W_2^2 = sum_k int_block (x_(k) - u)^2 du`.
fn w2_axis(pts: &[f64], d: usize, a: usize) -> f64 {
    let mut x: Vec<f64> = pts.chunks(d).map(|p| p[a]).collect();
    x.sort_by(f64::total_cmp);
    let n = x.len() as f64;
    x.iter()
        .enumerate()
        .map(|(k, &v)| {
            let (lo, hi) = (k as f64 / n, (k + 1) as f64 / n);
            ((v - lo).powi(3) - (v - hi).powi(3)) / 3.0
        })
        .sum()
}

/// The squared sliced Wasserstein distance between the 2D projection on axes `(a, b)` and
/// the uniform square: `dirs` directions evenly spread over the half circle (offset by a
/// fixed irrational angle), the square represented by the `m^2 = 64 N` centres of an
/// `m x m` grid (`N` a power of 4), each point coupled with its block of 64 sorted
/// projected centres.
fn sw2_plane(pts: &[f64], d: usize, a: usize, b: usize, dirs: usize) -> f64 {
    let n = pts.len() / d;
    let c = 64;
    let m = ((n * c) as f64).sqrt() as usize;
    assert_eq!(m * m, n * c, "N must be a power of 4");
    let reference: Vec<f64> = (0..m * m)
        .flat_map(|i| {
            [
                ((i % m) as f64 + 0.5) / m as f64,
                ((i / m) as f64 + 0.5) / m as f64,
            ]
        })
        .collect();
    let mut total = 0.0;
    for j in 0..dirs {
        let angle =
            std::f64::consts::PI * (j as f64 + 0.5 * std::f64::consts::SQRT_2) / dirs as f64;
        let (s, co) = angle.sin_cos();
        let mut p: Vec<f64> = pts.chunks(d).map(|x| co * x[a] + s * x[b]).collect();
        let mut r: Vec<f64> = reference.chunks(2).map(|y| co * y[0] + s * y[1]).collect();
        p.sort_by(f64::total_cmp);
        r.sort_by(f64::total_cmp);
        for (i, x) in p.iter().enumerate() {
            total += r[i * c..(i + 1) * c]
                .iter()
                .map(|y| (x - y).powi(2))
                .sum::<f64>()
                / (c * n) as f64;
        }
    }
    total / dirs as f64
}

/// Mean `W_2^2` of the 1D projections and mean sliced `W_2^2` of the 2D projections.
fn projection_w2(pts: &[f64], d: usize) -> (f64, f64) {
    let one = (0..d).map(|a| w2_axis(pts, d, a)).sum::<f64>() / d as f64;
    let (mut two, mut c) = (0.0, 0);
    for a in 0..d {
        for b in a + 1..d {
            two += sw2_plane(pts, d, a, b, 64);
            c += 1;
        }
    }
    (one, two / c as f64)
}

fn sot(n: u64, d: usize, iterations: u32, projective: bool, seed: u64) -> Vec<f64> {
    Sot::new(n, d)
        .unwrap()
        .seed(seed)
        .iterations(iterations)
        .unwrap()
        .projective(projective)
        .generate(&Budget::DEFAULT)
        .unwrap()
        .to_f64()
}

#[test]
#[ignore = "measurement"]
fn measure_sot() {
    for (n, d) in [(256u64, 2usize), (256, 3), (256, 4)] {
        for it in [0u32, 10, 50, 200] {
            for proj in [false, true] {
                let p = sot(n, d, it, proj, 3);
                let (one, two) = projection_w2(&p, d);
                println!("n {n} d {d} it {it} proj {proj}: 1D {one:.3e} 2D {two:.3e}");
            }
        }
    }
}

#[test]
fn projective_blue_noise_keeps_its_radii() {
    // The largest spacings, written from the packings (not from the crate): the line
    // 1/N, the hexagonal lattice sqrt(2 / (sqrt(3) N)), FCC (sqrt(2) / N)^(1/3).
    let spacing = |n: f64, m: usize| match m {
        1 => 1.0 / n,
        2 => (2.0 / (3f64.sqrt() * n)).sqrt(),
        _ => (2f64.sqrt() / n).cbrt(),
    };
    for (n, d) in [(300u64, 2usize), (300, 3), (150, 3)] {
        for proj in [0u8, 1, 2] {
            let p = ProjectiveBlueNoise::new(n, d)
                .unwrap()
                .projections(proj)
                .unwrap()
                .seed(n + u64::from(proj))
                .run(&Budget::DEFAULT)
                .unwrap();
            let pts = p.points.to_f64();
            assert_eq!(pts.len(), n as usize * d);
            let rho = p.relative_radius;
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b;
            assert!(close(p.radius, rho * spacing(n as f64, d)), "{p:?}");
            assert_eq!(p.radius_1d.is_some(), proj >= 1);
            assert_eq!(p.radius_2d.is_some(), proj >= 2 && d > 2);
            let (full, one, two) = min_distances(&pts, d);
            let tol = 1.0 - 1e-12;
            assert!(
                full >= tol * p.radius,
                "n {n} d {d} proj {proj}: {full} < {}",
                p.radius
            );
            if let Some(r1) = p.radius_1d {
                assert!(close(r1, rho * spacing(n as f64, 1)));
                assert!(one >= tol * r1, "n {n} d {d} proj {proj}: 1D {one} < {r1}");
            }
            if let Some(r2) = p.radius_2d {
                assert!(close(r2, rho * spacing(n as f64, 2)));
                assert!(two >= tol * r2, "n {n} d {d} proj {proj}: 2D {two} < {r2}");
            }
            // The schedule stops where dart throwing saturates, not near zero: the stated
            // minimum distance is a fair share of the packing spacing.
            let floor = if proj == 0 { 0.55 } else { 0.3 };
            assert!(rho > floor, "n {n} d {d} proj {proj}: rho {rho}");
        }
    }
}

#[test]
fn projective_blue_noise_projections_are_blue() {
    let n = 512usize;
    for d in [2usize, 3] {
        let sets = |proj: Option<u8>| -> Vec<Vec<f64>> {
            (0..4u64)
                .map(|seed| match proj {
                    None => uniform(n, d, 100 + seed),
                    Some(k) => ProjectiveBlueNoise::new(n as u64, d)
                        .unwrap()
                        .projections(k)
                        .unwrap()
                        .seed(seed)
                        .generate(&Budget::DEFAULT)
                        .unwrap()
                        .to_f64(),
                })
                .collect()
        };
        let white = projection_power(&sets(None), n, d);
        let full_only = projection_power(&sets(Some(0)), n, d);
        let projective = projection_power(&sets(Some(2)), n, d);
        // Independent points: every periodogram value has mean 1 (the mean over
        // 4 d (N/8) exponential values is within a few per cent of it).
        assert!((0.85..1.15).contains(&white.0), "white 1D {white:?}");
        // Dart throwing in the full space alone leaves the 1D projections white.
        assert!(
            full_only.0 > 0.75 * white.0,
            "full-space only {full_only:?}"
        );
        // Projective: the 1D projections far below white noise; the 2D ones (d = 3;
        // in 2D the plane is the full space) well below.
        assert!(
            projective.0 < 0.35 * white.0,
            "d {d}: 1D {projective:?} vs {white:?}"
        );
        if d > 2 {
            assert!((0.8..1.2).contains(&white.1), "white 2D {white:?}");
            assert!(full_only.1 > 0.7 * white.1, "full-space only {full_only:?}");
            assert!(
                projective.1 < 0.6 * white.1,
                "d {d}: 2D {projective:?} vs {white:?}"
            );
        }
    }
}

#[test]
fn projective_blue_noise_refuses_bad_input() {
    assert!(ProjectiveBlueNoise::new(0, 2).is_err());
    assert!(ProjectiveBlueNoise::new(10, 1).is_err());
    assert!(ProjectiveBlueNoise::new(10, 9).is_err());
    assert!(ProjectiveBlueNoise::new((1 << 16) + 1, 2).is_err());
    let p = ProjectiveBlueNoise::new(10, 2).unwrap();
    assert!(p.projections(3).is_err());
    assert!(p.schedule(f64::NAN, 0.99, 10).is_err());
    assert!(p.schedule(0.9, 1.0, 10).is_err());
    assert!(p.schedule(0.9, 0.99, 0).is_err());
    assert!(p.weight(0.0).is_err());
    assert!(p.weight(1.5).is_err());
    let tight = Budget::seconds(1e-6).unwrap();
    assert!(matches!(
        ProjectiveBlueNoise::new(1 << 16, 4)
            .unwrap()
            .generate(&tight),
        Err(qmckit::Error::OverBudget { .. })
    ));
}

#[test]
fn projective_sot_spreads_the_projections() {
    for d in [3usize, 4] {
        let n = 256;
        let plain = projection_w2(&sot(n, d, 200, false, 3), d);
        let at: Vec<(f64, f64)> = [0, 10, 200]
            .iter()
            .map(|&it| projection_w2(&sot(n, d, it, true, 3), d))
            .collect();
        for w in at.windows(2) {
            assert!(w[1].0 < w[0].0 && w[1].1 < w[0].1, "d {d}: {at:?}");
        }
        let last = at[2];
        assert!(
            last.0 < 0.3 * plain.0,
            "d {d}: 1D {last:?} vs plain {plain:?}"
        );
        assert!(
            last.1 < 0.8 * plain.1,
            "d {d}: 2D {last:?} vs plain {plain:?}"
        );
    }
    // In 1D there is no subspace: the option changes nothing.
    assert_eq!(sot(64, 1, 20, true, 1), sot(64, 1, 20, false, 1));
}
