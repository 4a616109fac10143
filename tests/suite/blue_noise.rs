//! The blue-noise point sets against their definitions: Poisson-disk separation (every
//! pair checked by brute force, toroidal or not), maximality on a probe grid, the
//! densities of the literature (Bridson k = 30 about N r^2 = 0.61 as SciPy's
//! `qmc.PoissonDisk` reaches; random sequential adsorption about 0.69), nearest-neighbour
//! statistics normalized by the hexagonal spacing (white noise: 0.4653), and low-frequency
//! power from the direct-sum periodogram (white noise: 1).
#![cfg(feature = "analysis")]

use qmckit::analysis::Points;
use qmckit::analysis::spectrum::spectrum_2d;
use qmckit::blue_noise::{BestCandidate, GaussianBlueNoise, PointSet, PoissonDisk};
use qmckit::work::Budget;
use qmckit::{Error, Independent, Sampler};

fn gap(a: f64, b: f64, torus: bool) -> f64 {
    let d = (a - b).abs();
    if torus { d.min(1.0 - d) } else { d }
}

fn dist2(a: &[f64], b: &[f64], torus: bool) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| gap(*x, *y, torus).powi(2))
        .sum()
}

/// The smallest pairwise distance, by brute force.
fn min_distance(x: &[f64], d: usize, torus: bool) -> f64 {
    let n = x.len() / d;
    let mut best = f64::INFINITY;
    for i in 0..n {
        for j in i + 1..n {
            best = best.min(dist2(&x[i * d..i * d + d], &x[j * d..j * d + d], torus));
        }
    }
    best.sqrt()
}

/// Min and mean nearest-neighbour distance (toroidal, 2D) over the hexagonal spacing.
fn nn_stats(x: &[f64]) -> (f64, f64) {
    let n = x.len() / 2;
    let mut nn = vec![f64::INFINITY; n];
    for i in 0..n {
        for j in 0..n {
            if i != j {
                nn[i] = nn[i].min(dist2(&x[2 * i..2 * i + 2], &x[2 * j..2 * j + 2], true));
            }
        }
    }
    let hex = (2.0 / (3f64.sqrt() * n as f64)).sqrt();
    let min = nn.iter().cloned().fold(f64::INFINITY, f64::min).sqrt();
    let mean = nn.iter().map(|v| v.sqrt()).sum::<f64>() / n as f64;
    (min / hex, mean / hex)
}

/// Mean periodogram over `0 < |k| < 0.5 sqrt(N)`.
fn low_power(x: &[f64]) -> f64 {
    let n = x.len() / 2;
    let kmax = (0.5 * (n as f64).sqrt()).ceil() as usize;
    let s = spectrum_2d(Points::new(x, 2).unwrap(), kmax, &Budget::DEFAULT).unwrap();
    let lim2 = 0.25 * n as f64;
    let (sum, count) = s
        .iter()
        .filter(|&(kx, ky, _)| {
            let k2 = (kx * kx + ky * ky) as f64;
            k2 > 0.0 && k2 < lim2
        })
        .fold((0.0, 0usize), |(s, c), (_, _, p)| (s + p, c + 1));
    sum / count as f64
}

fn coords(s: &PointSet) -> Vec<f64> {
    s.to_f64()
}

#[test]
fn poisson_disk_pairs_are_at_least_r_apart() {
    for (d, r, torus) in [
        (2, 0.02, false),
        (2, 0.02, true),
        (1, 0.001, true),
        (3, 0.08, false),
        (3, 0.08, true),
        (5, 0.35, true),
    ] {
        for seed in 0..3 {
            let s = PoissonDisk::new(d, r)
                .unwrap()
                .torus(torus)
                .seed(seed)
                .generate(&Budget::DEFAULT)
                .unwrap();
            let x = coords(&s);
            assert!(s.count() > 10, "{d} {r} {torus}: {}", s.count());
            let m = min_distance(&x, d, torus);
            assert!(
                m >= r,
                "d {d} r {r} torus {torus} seed {seed}: min distance {m}"
            );
            assert!(x.iter().all(|v| (0.0..1.0).contains(v)));
        }
    }
}

/// Nearest-neighbour distance of every point (brute force; not toroidal).
fn nn_distances(x: &[f64], d: usize) -> Vec<f64> {
    let n = x.len() / d;
    (0..n)
        .map(|i| {
            (0..n)
                .filter(|&j| j != i)
                .map(|j| dist2(&x[i * d..i * d + d], &x[j * d..j * d + d], false))
                .fold(f64::INFINITY, f64::min)
                .sqrt()
        })
        .collect()
}

/// Surface candidates (SciPy's `hypersphere="surface"`): every new point is placed at
/// `1.001 r` from the active point it grew from, so (Bridson's first point aside, and
/// each tile's first point in the tiled 2D loop) every point has a neighbour within
/// `1.001 r` (plus the 2^-32 rounding of the coordinates), and none closer than `r`. Shell
/// candidates (`r .. 2r`) leave most points without so close a neighbour. 1D, the tiled
/// 2D loop (r = 0.006: 236 cells a side, 2 x 2 tiles), the sequential 2D loop, 3D, 5D.
#[test]
fn poisson_disk_surface_points_touch_a_neighbour() {
    for (d, r) in [(1, 0.002), (2, 0.006), (2, 0.05), (3, 0.08), (5, 0.35)] {
        let set = |surface: bool| {
            let s = PoissonDisk::new(d, r)
                .unwrap()
                .surface(surface)
                .seed(3)
                .generate(&Budget::DEFAULT)
                .unwrap();
            coords(&s)
        };
        let (x, shell) = (set(true), set(false));
        let n = x.len() / d;
        let nn = nn_distances(&x, d);
        let min = nn.iter().cloned().fold(f64::INFINITY, f64::min);
        assert!(min >= r, "d {d} r {r}: min distance {min}");
        let touching = |nn: &[f64]| nn.iter().filter(|&&v| v <= 1.001 * r + 1e-9).count();
        let tiles = if d == 2 && r < 0.01 { 4 } else { 1 };
        assert!(
            touching(&nn) + tiles >= n,
            "d {d} r {r}: {} of {n} points touch",
            touching(&nn)
        );
        let shell_nn = nn_distances(&shell, d);
        assert!(
            2 * touching(&shell_nn) < shell_nn.len(),
            "d {d} r {r}: shell candidates touch too"
        );
        assert!(x.iter().all(|v| (0.0..1.0).contains(v)));
    }
}

/// The smallest pairwise distance in 2D by a sweep along x (toroidal or not): points
/// sorted by x, each compared with those less than `r` further on (and, on the torus,
/// with the first ones moved by +1).
fn min_distance_sweep(x: &[f64], r: f64, torus: bool) -> f64 {
    let mut p: Vec<[f64; 2]> = x.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
    p.sort_by(|a, b| a[0].total_cmp(&b[0]));
    if torus {
        let wrap: Vec<[f64; 2]> = p
            .iter()
            .take_while(|q| q[0] < r)
            .map(|q| [q[0] + 1.0, q[1]])
            .collect();
        p.extend(wrap);
    }
    let mut best = f64::INFINITY;
    for i in 0..p.len() {
        for j in i + 1..p.len() {
            if p[j][0] - p[i][0] >= r {
                break;
            }
            let dy = gap(p[i][1], p[j][1], torus);
            best = best.min(((p[j][0] - p[i][0]).powi(2) + dy * dy).sqrt());
        }
    }
    best
}

/// The tile borders of the 2D Poisson-disk construction at radius `r` (as documented in
/// `PoissonDisk`: cells of side `1/g`, `g = ceil(sqrt(2) / r)`, split into `n` tiles of at
/// most 128 cells, `n` even and at least 2 on the torus; tile `i` starts at cell
/// `floor(i g / n)`; colours by the parity of column and row, even first), as coordinates
/// in `[0, 1)`, each with whether the tile before it (lower coordinates) grows first.
fn tile_borders(r: f64, torus: bool) -> Vec<(f64, bool)> {
    let g = (2f64.sqrt() / r).ceil() as usize;
    let mut n = g.div_ceil(128);
    if torus {
        n = (n + n % 2).max(2);
    }
    let first = if torus { 0 } else { 1 };
    (first..n)
        .map(|i| ((i * g / n) as f64 / g as f64, i % 2 == 1))
        .collect()
}

#[test]
fn tiled_poisson_sets_are_r_separated_across_tiles() {
    // r = 0.003: 472 cells a side, 4 tiles; about 68 000 points a set.
    let r = 0.003;
    for torus in [false, true] {
        for seed in 0..2 {
            let s = PoissonDisk::new(2, r)
                .unwrap()
                .torus(torus)
                .seed(seed)
                .generate(&Budget::DEFAULT)
                .unwrap();
            assert!(s.count() > 60_000, "{}", s.count());
            let m = min_distance_sweep(&coords(&s), r, torus);
            assert!(m >= r, "torus {torus} seed {seed}: min distance {m} < {r}");
        }
    }
}

#[test]
fn tiled_poisson_sets_have_no_seams() {
    // The density profile across tile borders, in strips of width r/2 from 2r on the side
    // grown first to 2r on the side grown later (both axes, 16 seeds), against the same
    // strips around the tiles' middle lines (the control: the box's own edge effects are
    // in both): flat within 5%. A tile that filled up to its border before its neighbour
    // grew would pack points against the border (about +58% just before it, -55% just
    // after).
    let r = 0.004;
    let g = (2f64.sqrt() / r).ceil() as usize;
    for torus in [false, true] {
        let borders = tile_borders(r, torus);
        let n = if torus {
            borders.len()
        } else {
            borders.len() + 1
        };
        let middles: Vec<(f64, bool)> = (0..n)
            .map(|i| {
                (
                    ((i * g / n + (i + 1) * g / n) as f64 / 2.0) / g as f64,
                    true,
                )
            })
            .collect();
        assert!(borders.len() >= 2, "{borders:?}");
        let profile = |lines: &[(f64, bool)], x: &[f64], bins: &mut [usize; 8]| {
            for v in x {
                for &(b, before_first) in lines {
                    let mut d = v - b;
                    if d > 0.5 {
                        d -= 1.0;
                    } else if d < -0.5 {
                        d += 1.0;
                    }
                    if !before_first {
                        d = -d;
                    }
                    let bin = (d / (0.5 * r) + 4.0).floor();
                    if (0.0..8.0).contains(&bin) {
                        bins[bin as usize] += 1;
                    }
                }
            }
        };
        let (mut at_borders, mut at_middles) = ([0usize; 8], [0usize; 8]);
        for seed in 0..16 {
            let x = coords(
                &PoissonDisk::new(2, r)
                    .unwrap()
                    .torus(torus)
                    .seed(seed)
                    .generate(&Budget::DEFAULT)
                    .unwrap(),
            );
            profile(&borders, &x, &mut at_borders);
            profile(&middles, &x, &mut at_middles);
        }
        let control = at_middles.iter().sum::<usize>() as f64 / (8 * middles.len()) as f64;
        let ratio: Vec<f64> = at_borders
            .iter()
            .map(|&c| c as f64 / borders.len() as f64 / control)
            .collect();
        eprintln!("torus {torus}: density across tile borders / control {ratio:.3?}");
        for (i, v) in ratio.iter().enumerate() {
            assert!(
                (v - 1.0).abs() < 0.05,
                "torus {torus}: strip {i} density ratio {v} ({ratio:?})"
            );
        }
    }
}

/// The largest distance from a probe of a grid of spacing r/2 to its nearest sample
/// (buckets of side at least 2r; distances past 2r are reported as 2r).
fn largest_gap(x: &[f64], r: f64, torus: bool) -> f64 {
    let b = (1.0 / (2.0 * r)).floor() as usize;
    let mut buckets = vec![Vec::new(); b * b];
    let at = |v: f64| ((v * b as f64) as usize).min(b - 1);
    for p in x.chunks_exact(2) {
        buckets[at(p[1]) * b + at(p[0])].push([p[0], p[1]]);
    }
    let m = (2.0 / r) as usize;
    let mut worst = 0.0f64;
    for py in 0..m {
        for px in 0..m {
            let q = [(px as f64 + 0.5) / m as f64, (py as f64 + 0.5) / m as f64];
            let (cx, cy) = (at(q[0]) as i64, at(q[1]) as i64);
            let mut best = 4.0 * r * r;
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (bx, by) = (cx + dx, cy + dy);
                    let (bx, by) = if torus {
                        (bx.rem_euclid(b as i64), by.rem_euclid(b as i64))
                    } else if bx < 0 || by < 0 || bx >= b as i64 || by >= b as i64 {
                        continue;
                    } else {
                        (bx, by)
                    };
                    for p in &buckets[by as usize * b + bx as usize] {
                        best = best.min(dist2(&q, p, torus));
                    }
                }
            }
            worst = worst.max(best.sqrt());
        }
    }
    worst
}

#[test]
fn tiled_poisson_sets_leave_no_holes() {
    // Bridson's front reaches everywhere: no probe is 2r or farther from every sample (a
    // tile whose front was starved would leave a hole of many r).
    let r = 0.004;
    for torus in [false, true] {
        for seed in 0..8 {
            let s = PoissonDisk::new(2, r).unwrap().torus(torus).seed(seed);
            let worst = largest_gap(&coords(&s.generate(&Budget::DEFAULT).unwrap()), r, torus);
            assert!(worst < 2.0 * r, "torus {torus} seed {seed}: gap {worst}");
        }
    }
}

#[test]
#[ignore = "10^6 points: a long check"]
fn million_point_poisson_sets_leave_no_holes() {
    // The sets of the speed comparison (r = 0.00078, unit square, seeds 1 and 2).
    let r = 0.00078;
    for seed in 1..=2 {
        let s = PoissonDisk::new(2, r)
            .unwrap()
            .seed(seed)
            .generate(&Budget::DEFAULT)
            .unwrap();
        let nr2 = s.count() as f64 * r * r;
        assert!((0.61..0.62).contains(&nr2), "seed {seed}: N r^2 = {nr2}");
        let worst = largest_gap(&coords(&s), r, false);
        assert!(worst < 2.0 * r, "seed {seed}: gap {worst}");
    }
}

#[test]
fn poisson_sets_do_not_depend_on_the_thread_count() {
    let make = || {
        PoissonDisk::new(2, 0.003)
            .unwrap()
            .torus(true)
            .seed(11)
            .generate(&Budget::DEFAULT)
            .unwrap()
    };
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(make);
    let three = rayon::ThreadPoolBuilder::new()
        .num_threads(3)
        .build()
        .unwrap()
        .install(make);
    assert_eq!(one, three);
}

#[test]
fn bridson_density_matches_the_literature() {
    // N r^2 about 0.61 in 2D with k = 30 (SciPy's qmc.PoissonDisk: 0.608 to 0.625).
    let r = 0.01;
    let mut total = 0.0;
    for seed in 0..4 {
        let s = PoissonDisk::new(2, r)
            .unwrap()
            .torus(true)
            .seed(seed)
            .generate(&Budget::DEFAULT)
            .unwrap();
        total += s.count() as f64 * r * r / 4.0;
    }
    assert!((0.59..0.64).contains(&total), "N r^2 = {total}");
}

#[test]
fn maximal_sets_leave_no_room_for_another_disk() {
    for torus in [true, false] {
        let r = 0.04;
        let s = PoissonDisk::new(2, r)
            .unwrap()
            .torus(torus)
            .maximal(true)
            .seed(5)
            .generate(&Budget::DEFAULT)
            .unwrap();
        let x = coords(&s);
        assert!(min_distance(&x, 2, torus) >= r);
        // Random sequential adsorption jams at N r^2 ~ 0.69 (torus).
        let nr2 = s.count() as f64 * r * r;
        assert!((0.64..0.76).contains(&nr2), "torus {torus}: N r^2 = {nr2}");
        // Every point of a 500 x 500 probe grid lies within r of a sample.
        let m = 500;
        let tol = r * (1.0 + 1e-5);
        for py in 0..m {
            for px in 0..m {
                let p = [(px as f64 + 0.5) / m as f64, (py as f64 + 0.5) / m as f64];
                let near = x.chunks_exact(2).any(|q| dist2(&p, q, torus) <= tol * tol);
                assert!(
                    near,
                    "torus {torus}: probe {p:?} is farther than r from every sample"
                );
            }
        }
        // The plain Bridson set is not maximal: some probe is uncovered.
        let b = coords(
            &PoissonDisk::new(2, r)
                .unwrap()
                .torus(torus)
                .seed(5)
                .generate(&Budget::DEFAULT)
                .unwrap(),
        );
        let uncovered = (0..m * m).any(|i| {
            let p = [
                ((i % m) as f64 + 0.5) / m as f64,
                ((i / m) as f64 + 0.5) / m as f64,
            ];
            !b.chunks_exact(2).any(|q| dist2(&p, q, torus) <= r * r)
        });
        assert!(uncovered);
    }
}

#[test]
fn about_n_points_lands_near_n() {
    for (d, n, torus) in [
        (2, 2000u64, true),
        (2, 2000, false),
        (3, 1500, true),
        (1, 500, false),
    ] {
        let pd = PoissonDisk::with_points(d, n).unwrap().torus(torus).seed(3);
        let got = pd.generate(&Budget::DEFAULT).unwrap().count() as f64;
        assert!((got / n as f64 - 1.0).abs() < 0.03, "d {d} n {n}: {got}");
        let r = pd.radius(&Budget::DEFAULT).unwrap();
        let again = PoissonDisk::new(d, r)
            .unwrap()
            .torus(torus)
            .seed(3)
            .generate(&Budget::DEFAULT)
            .unwrap();
        assert_eq!(
            again.count() as f64,
            got,
            "the count mode is the radius mode at its radius"
        );
    }
}

#[test]
fn constructions_are_deterministic_per_seed() {
    let a = PoissonDisk::new(2, 0.03)
        .unwrap()
        .seed(9)
        .generate(&Budget::DEFAULT)
        .unwrap();
    let b = PoissonDisk::new(2, 0.03)
        .unwrap()
        .seed(9)
        .generate(&Budget::DEFAULT)
        .unwrap();
    let c = PoissonDisk::new(2, 0.03)
        .unwrap()
        .seed(10)
        .generate(&Budget::DEFAULT)
        .unwrap();
    assert_eq!(a, b);
    assert_ne!(a, c);
    let a = BestCandidate::new(300)
        .unwrap()
        .seed(1)
        .generate(&Budget::DEFAULT)
        .unwrap();
    assert_eq!(
        a,
        BestCandidate::new(300)
            .unwrap()
            .seed(1)
            .generate(&Budget::DEFAULT)
            .unwrap()
    );
    let a = GaussianBlueNoise::new(200)
        .unwrap()
        .iterations(20)
        .unwrap()
        .seed(1)
        .generate(&Budget::DEFAULT)
        .unwrap();
    assert_eq!(
        a,
        GaussianBlueNoise::new(200)
            .unwrap()
            .iterations(20)
            .unwrap()
            .seed(1)
            .generate(&Budget::DEFAULT)
            .unwrap()
    );
    // A point set is a sampler of its points.
    assert_eq!(a.len(), 200);
    assert_eq!(a.dims(), 2);
    assert_eq!(a.sample(199, 1).unwrap(), a.coords()[399]);
    assert!(a.sample(200, 0).is_err());
    assert!(a.sample(0, 2).is_err());
}

#[test]
fn bad_parameters_are_errors() {
    for r in [0.0, -0.1, f64::NAN, f64::INFINITY, 1.5] {
        assert!(
            matches!(PoissonDisk::new(2, r), Err(Error::InvalidParameter { .. })),
            "{r}"
        );
    }
    // 10^12 points: refused before anything is allocated.
    assert!(matches!(
        PoissonDisk::new(2, 1e-6),
        Err(Error::TooLarge { .. })
    ));
    assert!(matches!(
        PoissonDisk::new(0, 0.1),
        Err(Error::ZeroDimensions)
    ));
    assert!(matches!(
        PoissonDisk::new(9, 0.5),
        Err(Error::DimensionOutOfRange { .. })
    ));
    assert!(PoissonDisk::new(2, 0.1).unwrap().candidates(0).is_err());
    assert!(matches!(
        PoissonDisk::with_points(2, 0),
        Err(Error::ZeroPoints)
    ));
    assert!(PoissonDisk::with_points(2, 1 << 40).is_err());
    let tight = Budget::seconds(1e-6).unwrap();
    assert!(matches!(
        PoissonDisk::new(2, 0.001).unwrap().generate(&tight),
        Err(Error::OverBudget { .. })
    ));
    assert!(matches!(BestCandidate::new(0), Err(Error::ZeroPoints)));
    assert!(BestCandidate::new(10).unwrap().candidates(0).is_err());
    assert!(matches!(
        BestCandidate::new(100_000)
            .unwrap()
            .generate(&Budget::DEFAULT),
        Err(Error::OverBudget { .. })
    ));
    assert!(GaussianBlueNoise::new(1).is_err());
    assert!(GaussianBlueNoise::new(10).unwrap().sigma(f64::NAN).is_err());
    assert!(matches!(
        GaussianBlueNoise::new(1 << 20)
            .unwrap()
            .generate(&Budget::DEFAULT),
        Err(Error::OverBudget { .. })
    ));
}

/// White noise first: the checks below would not hold for it.
#[test]
fn white_noise_reference_statistics() {
    let s = Independent::new(2, 4).unwrap();
    let raw: Vec<u32> = (0..1024u32)
        .flat_map(|i| [s.sample(i, 0).unwrap(), s.sample(i, 1).unwrap()])
        .collect();
    let x = Points::from_u32(&raw);
    let (_, mean) = nn_stats(&x);
    assert!((mean - 0.4653).abs() < 0.05, "white mean NN {mean}");
    assert!((low_power(&x) - 1.0).abs() < 0.3);
}

#[test]
fn best_candidate_is_blue() {
    let mut power = 0.0;
    let sets = 4;
    for seed in 0..sets {
        let x = coords(
            &BestCandidate::new(1024)
                .unwrap()
                .seed(seed)
                .generate(&Budget::DEFAULT)
                .unwrap(),
        );
        let (min, mean) = nn_stats(&x);
        // Published (Schlömer et al. 2011): min 0.751, mean 0.839.
        assert!(
            min > 0.6 && (0.79..0.88).contains(&mean),
            "min {min} mean {mean}"
        );
        power += low_power(&x) / sets as f64;
    }
    assert!(power < 0.2, "best-candidate low-frequency power {power}");
}

#[test]
fn poisson_disk_low_frequency_plateau() {
    let mut power = 0.0;
    let sets = 4;
    for seed in 0..sets {
        let x = coords(
            &PoissonDisk::with_points(2, 1024)
                .unwrap()
                .torus(true)
                .seed(seed)
                .generate(&Budget::DEFAULT)
                .unwrap(),
        );
        let (min, mean) = nn_stats(&x);
        assert!(
            min > 0.7 && (0.76..0.84).contains(&mean),
            "min {min} mean {mean}"
        );
        power += low_power(&x) / sets as f64;
    }
    // A non-zero plateau about 0.07 (not the near-zero of optimized blue noise).
    assert!(
        (0.02..0.2).contains(&power),
        "Poisson-disk low-frequency power {power}"
    );
}

#[test]
fn gaussian_blue_noise_has_near_zero_low_frequency_power() {
    let mut power = 0.0;
    let sets = 3;
    for seed in 0..sets {
        let x = coords(
            &GaussianBlueNoise::new(1024)
                .unwrap()
                .seed(seed)
                .generate(&Budget::DEFAULT)
                .unwrap(),
        );
        let (min, mean) = nn_stats(&x);
        eprintln!("Gaussian blue noise, N = 1024, seed {seed}: NN min {min:.3} mean {mean:.3}");
        assert!(min > 0.3 && mean > 0.72, "min {min} mean {mean}");
        power += low_power(&x) / sets as f64;
    }
    // The target: below 0.01 of white noise for |k| < 0.5 sqrt(N).
    assert!(
        power < 0.01,
        "Gaussian blue noise low-frequency power {power}"
    );
}

pub(crate) mod budget;
