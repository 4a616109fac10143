//! Properties of every sampler: stratification, fill == sample, errors instead of panics.

use crate::common;

use common::{points_2d, star_discrepancy_2d_exact};
use qmckit::{
    Error, Halton, Hammersley, Independent, Jitter, LarcherPillichshammer, LatinHypercube, Sampler,
    Stratified, VanDerCorput,
};

fn all_samplers() -> Vec<(&'static str, Box<dyn Sampler>)> {
    vec![
        ("independent", Box::new(Independent::new(3, 9).unwrap())),
        (
            "stratified",
            Box::new(Stratified::new(&[5, 3, 2], Jitter::Random(4)).unwrap()),
        ),
        ("latin", Box::new(LatinHypercube::new(30, 3, 1).unwrap())),
        ("vdc3", Box::new(VanDerCorput::new(3).unwrap())),
        ("halton", Box::new(Halton::new(7).unwrap())),
        ("hammersley", Box::new(Hammersley::new(30, 4).unwrap())),
        ("lp", Box::new(LarcherPillichshammer::new(5).unwrap())),
    ]
}

#[test]
fn fill_equals_random_access_for_every_sampler() {
    for (name, s) in all_samplers() {
        let d = s.dims();
        for start in [0u32, 3] {
            let rows = (s.len().min(1000) - start as u64) as usize;
            let mut buf = vec![0u32; rows * d];
            s.fill(start, &mut buf).unwrap();
            for (k, row) in buf.chunks(d).enumerate() {
                for (dim, &x) in row.iter().enumerate() {
                    assert_eq!(
                        x,
                        s.sample(start + k as u32, dim).unwrap(),
                        "{name} {k} {dim}"
                    );
                }
            }
        }
    }
}

/// The typed fill (`fill_as`, here the trait's default through `Box<dyn Sampler>`:
/// `u32`s a chunk, converted) equals converting random access: `f64` and `f32`, whole
/// chunks and a partial last one, and one sampler wider than a chunk (1100 dimensions,
/// point by point).
#[test]
fn typed_fill_equals_converted_random_access() {
    use qmckit::bits::{to_f32, to_f64};
    let mut samplers = all_samplers();
    samplers.push((
        "independent 1100",
        Box::new(Independent::new(1100, 5).unwrap()),
    ));
    for (name, s) in samplers {
        let d = s.dims();
        let rows = s.len().min(700) as usize - 3;
        let mut x = vec![0f64; rows * d];
        let mut y = vec![0f32; rows * d];
        s.fill_as(3, &mut x).unwrap();
        s.fill_as(3, &mut y).unwrap();
        for (k, (px, py)) in x.chunks(d).zip(y.chunks(d)).enumerate() {
            for dim in 0..d {
                let u = s.sample(3 + k as u32, dim).unwrap();
                assert_eq!(px[dim].to_bits(), to_f64(u).to_bits(), "{name} {k} {dim}");
                assert_eq!(py[dim].to_bits(), to_f32(u).to_bits(), "{name} {k} {dim}");
            }
        }
        let mut odd = vec![0f64; d + 1];
        if d > 1 {
            assert!(
                matches!(s.fill_as(0, &mut odd), Err(Error::BufferLength { .. })),
                "{name}"
            );
        }
    }
}

#[test]
fn requests_past_the_end_are_errors_not_panics() {
    for (name, s) in all_samplers() {
        let d = s.dims();
        assert!(
            matches!(s.sample(0, d), Err(Error::DimensionOutOfRange { .. })),
            "{name}"
        );
        let mut odd = vec![0u32; d + 1];
        if d > 1 {
            assert!(
                matches!(s.fill(0, &mut odd), Err(Error::BufferLength { .. })),
                "{name}"
            );
        }
        assert!(s.point(0, &mut odd).is_err(), "{name}");
        if s.len() < 1 << 32 {
            let last = s.len() as u32;
            assert!(
                matches!(s.sample(last, 0), Err(Error::IndexOutOfRange { .. })),
                "{name}"
            );
            let mut two = vec![0u32; 2 * d];
            assert!(s.fill(last - 1, &mut two).is_err(), "{name}");
        } else {
            let mut two = vec![0u32; 2 * d];
            assert!(s.fill(u32::MAX, &mut two).is_err(), "{name}");
            let mut one = vec![0u32; d];
            s.fill(u32::MAX, &mut one).unwrap();
        }
        // Empty buffers are fine.
        s.fill(0, &mut []).unwrap();
    }
}

#[test]
fn invalid_parameters_are_reported() {
    assert_eq!(Halton::new(0), Err(Error::ZeroDimensions));
    assert!(matches!(
        Halton::new(1025),
        Err(Error::DimensionOutOfRange { .. })
    ));
    assert_eq!(Hammersley::new(0, 2), Err(Error::ZeroPoints));
    assert!(matches!(
        Hammersley::new((1 << 32) + 1, 2),
        Err(Error::TooManyPoints { .. })
    ));
    assert!(matches!(
        Hammersley::with_m(33, 2),
        Err(Error::MTooLarge { m: 33, max: 32 })
    ));
    assert!(matches!(
        LarcherPillichshammer::new(33),
        Err(Error::MTooLarge { .. })
    ));
    assert_eq!(
        LarcherPillichshammer::with_points(48),
        Err(Error::NotPowerOfTwo { n: 48 })
    );
    assert_eq!(VanDerCorput::new(1), Err(Error::BaseTooSmall { base: 1 }));
    assert_eq!(
        Stratified::new(&[4, 0], Jitter::Center),
        Err(Error::ZeroStrata { dim: 1 })
    );
    assert!(matches!(
        Stratified::new(&[1 << 16, 1 << 16, 2], Jitter::Center),
        Err(Error::TooManyPoints { .. })
    ));
    assert_eq!(
        Stratified::new(&[], Jitter::Center),
        Err(Error::ZeroDimensions)
    );
    assert_eq!(LatinHypercube::new(0, 2, 0), Err(Error::ZeroPoints));
    assert_eq!(Independent::new(0, 0), Err(Error::ZeroDimensions));
    // Every error explains itself in one line.
    let msg = Error::IndexOutOfRange { index: 9, len: 8 }.to_string();
    assert!(msg.contains('9') && msg.contains('8') && !msg.contains('\n'));
}

#[test]
fn largest_sets_and_indices_work() {
    let h = Hammersley::new(1 << 32, 2).unwrap();
    assert_eq!(h.sample(u32::MAX, 0).unwrap(), u32::MAX);
    let lp = LarcherPillichshammer::new(32).unwrap();
    assert_eq!(lp.sample(u32::MAX, 0).unwrap(), u32::MAX);
    let lhs = LatinHypercube::new(1 << 32, 1, 5).unwrap();
    lhs.sample(u32::MAX, 0).unwrap();
    let single = Hammersley::new(1, 3).unwrap();
    assert_eq!(single.sample(0, 0).unwrap(), 0);
    let one = Stratified::new(&[1], Jitter::Center).unwrap();
    assert_eq!(one.sample(0, 0).unwrap(), 1 << 31);
}

#[test]
fn stratified_puts_one_point_in_every_cell() {
    for seed in 0..50 {
        let s = Stratified::new(&[7, 3, 4], Jitter::Random(seed)).unwrap();
        let mut seen = [false; 84];
        for i in 0..84u32 {
            let cell: Vec<u64> = [7u64, 3, 4]
                .iter()
                .enumerate()
                .map(|(k, &sk)| (s.sample(i, k).unwrap() as u64 * sk) >> 32)
                .collect();
            let id = (cell[0] + 7 * (cell[1] + 3 * cell[2])) as usize;
            assert!(!seen[id], "seed {seed}: cell {cell:?} twice");
            seen[id] = true;
        }
    }
    // Centered: exact cell midpoints.
    let c = Stratified::uniform(4, 2, Jitter::Center).unwrap();
    assert_eq!(c.sample(6, 0).unwrap(), 0xA000_0000); // cell 2 of 4 -> 5/8
    assert_eq!(c.sample(6, 1).unwrap(), 0x6000_0000); // cell 1 of 4 -> 3/8
}

#[test]
fn latin_hypercube_hits_every_slab_once() {
    for (n, seed) in [(1u64, 0u64), (2, 1), (17, 2), (64, 3), (1000, 4), (4097, 5)] {
        let lhs = LatinHypercube::new(n, 4, seed).unwrap();
        for dim in 0..4 {
            let mut seen = vec![false; n as usize];
            for i in 0..n as u32 {
                let slab = ((lhs.sample(i, dim).unwrap() as u64 * n) >> 32) as usize;
                assert!(!seen[slab], "n {n} dim {dim}");
                seen[slab] = true;
            }
        }
        if n >= 64 {
            // Dimensions use different permutations.
            let a: Vec<u32> = (0..16).map(|i| lhs.sample(i, 0).unwrap() >> 24).collect();
            let b: Vec<u32> = (0..16).map(|i| lhs.sample(i, 1).unwrap() >> 24).collect();
            assert_ne!(a, b);
        }
    }
}

#[test]
fn independent_points_are_uniform() {
    // Chi-square over 64 bins of 64k values per dimension: 63 degrees of freedom, the 0.9999
    // quantile is about 110.
    let s = Independent::new(3, 2024).unwrap();
    for dim in 0..3 {
        let mut bins = [0f64; 64];
        let n = 1 << 16;
        for i in 0..n {
            bins[(s.sample(i, dim).unwrap() >> 26) as usize] += 1.0;
        }
        let e = n as f64 / 64.0;
        let chi2: f64 = bins.iter().map(|c| (c - e) * (c - e) / e).sum();
        assert!(chi2 < 110.0, "dim {dim}: chi2 {chi2}");
    }
}

/// The textbook table of D* for 64 points: independent about 0.148, 8x8 stratified about
/// 0.081, Larcher–Pillichshammer 0.041 (exactly 21/512). Means over 200 random sets.
#[test]
fn textbook_discrepancy_table() {
    let dstar = |pts: &[[u32; 2]]| {
        let (d, s) = star_discrepancy_2d_exact(pts);
        d as f64 / s as f64
    };
    let sets = 200;
    let mean = |f: &dyn Fn(u64) -> Box<dyn Sampler>| {
        (0..sets)
            .map(|seed| dstar(&points_2d(&*f(seed), 64, (0, 1))))
            .sum::<f64>()
            / sets as f64
    };
    let independent = mean(&|seed| Box::new(Independent::new(2, seed).unwrap()));
    let jittered = mean(&|seed| Box::new(Stratified::uniform(8, 2, Jitter::Random(seed)).unwrap()));
    let lp = dstar(&points_2d(
        &LarcherPillichshammer::new(6).unwrap(),
        64,
        (0, 1),
    ));
    println!("D*: independent {independent:.4}, jittered {jittered:.4}, LP {lp}");
    assert!(
        (0.12..0.18).contains(&independent),
        "independent {independent}"
    );
    assert!((0.06..0.10).contains(&jittered), "jittered {jittered}");
    assert_eq!(lp, 21.0 / 512.0);
}

#[test]
fn halton_point_iterator_matches_random_access() {
    let h = Halton::new(4).unwrap();
    for (k, p) in h.points::<4>(1000).unwrap().take(500).enumerate() {
        for (dim, &x) in p.iter().enumerate() {
            assert_eq!(x, h.sample(1000 + k as u32, dim).unwrap());
        }
    }
    assert!(h.points::<3>(0).is_err());
    assert_eq!(h.points::<4>(u32::MAX - 1).unwrap().count(), 2);
}

#[cfg(feature = "rand_core")]
#[test]
fn independent_from_any_rng() {
    use rand_pcg::Pcg32;
    let mut a = Pcg32::new(7, 11);
    let mut b = Pcg32::new(7, 11);
    let s1 = Independent::from_rng(2, &mut a).unwrap();
    let s2 = Independent::from_rng(2, &mut b).unwrap();
    assert_eq!(s1, s2);
    let s3 = Independent::from_rng(2, &mut a).unwrap();
    assert_ne!(s1.sample(0, 0), s3.sample(0, 0));
    let mut buf = [0u32; 1000];
    qmckit::random::independent::fill_from_rng(&mut b, &mut buf);
    let mean = buf.iter().map(|&x| x as f64).sum::<f64>() / 1000.0 / 4_294_967_296.0;
    assert!((0.45..0.55).contains(&mean), "{mean}");
}

#[test]
fn halton_point_matches_per_coordinate_access() {
    use qmckit::randomize::digits::DigitScramble;
    let scrambles = [
        DigitScramble::None,
        DigitScramble::Faure,
        DigitScramble::Permutations(3),
        DigitScramble::Owen(5),
    ];
    for scramble in scrambles {
        for d in [1, 2, 32, 1024] {
            let h = Halton::with_scramble(d, scramble).unwrap();
            let mut row = vec![0u32; d];
            for i in [0u32, 1, 130, 17_161, 4_000_000, u32::MAX] {
                Sampler::point(&h, i, &mut row).unwrap();
                for (dim, &x) in row.iter().enumerate() {
                    assert_eq!(x, h.sample(i, dim).unwrap(), "{scramble:?} d {d} i {i}");
                }
            }
            let mut short = vec![0u32; d - 1];
            assert!(Sampler::point(&h, 0, &mut short).is_err());
        }
    }
}
