//! Fuzzes the library's constructors with arbitrary parameters: the pixel samplers
//! (`qmckit::pixel`), the PMJ sequences (`qmckit::pmj`) and the blue-noise sets
//! (`qmckit::blue_noise`). Every call must return a value or an error, never panic, and
//! every value must be in range: floats in [0, 1), the first 2^m PMJ points stratified in
//! each axis, a blue-noise set of `count * dims` coordinates, a void-and-cluster mask a
//! permutation of its ranks. Work is kept small (short sequences, a time budget of a few
//! milliseconds for the blue-noise sets) so that a run reaches many parameters.
#![no_main]

use libfuzzer_sys::arbitrary::{Result, Unstructured};
use libfuzzer_sys::fuzz_target;
use qmckit::Sampler;
use qmckit::blue_noise::{BestCandidate, GaussianBlueNoise, PoissonDisk, VoidAndCluster};
use qmckit::pixel::{
    ImageSobol, IndependentPixels, PaddedSobol, PixelSampler, Pmj02BnTables, Pmj02Pixels,
    Randomization, ZSobol,
};
use qmckit::pmj;
use qmckit::work::Budget;

/// The budget of one blue-noise generation: a few milliseconds.
fn budget() -> Budget {
    Budget::seconds(0.005).unwrap().started()
}

/// A u32 that is often small, sometimes at the edges.
fn size(u: &mut Unstructured) -> Result<u32> {
    Ok(match u.int_in_range(0u8..=3)? {
        0 => u.int_in_range(0..=17)?,
        1 => u.int_in_range(0..=70_000)?,
        2 => u32::MAX - u.int_in_range(0..=2)?,
        _ => u.arbitrary()?,
    })
}

/// An f64 that is often ordinary, sometimes hostile (0, subnormal, huge, NaN, inf).
fn real(u: &mut Unstructured) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=3)? {
        0 => f64::from(u.int_in_range(0u32..=1000)?) / 1000.0,
        1 => *u.choose(&[
            0.0,
            -0.0,
            5e-324,
            1e-300,
            1e300,
            f64::NAN,
            f64::INFINITY,
            -1.0,
        ])?,
        _ => u.arbitrary()?,
    })
}

fn randomization(u: &mut Unstructured) -> Result<Randomization> {
    Ok(*u.choose(&[
        Randomization::None,
        Randomization::PermuteDigits,
        Randomization::FastOwen,
        Randomization::Owen,
    ])?)
}

fn check_unit(v: f32, what: &str) {
    assert!((0.0..1.0).contains(&v), "{what}: {v}");
}

/// A few requests to a pixel sampler at arbitrary pixels, indices and dimensions.
fn probe<S: PixelSampler>(s: &S, u: &mut Unstructured) -> Result<()> {
    let grid = s.grid();
    assert!(grid.width >= 1 && grid.height >= 1 && grid.spp >= 1);
    for _ in 0..4 {
        let x = if u.arbitrary()? {
            u.arbitrary()?
        } else {
            u.int_in_range(0..=grid.width - 1)?
        };
        let y = if u.arbitrary()? {
            u.arbitrary()?
        } else {
            u.int_in_range(0..=grid.height - 1)?
        };
        let i = if u.arbitrary()? {
            u.arbitrary()?
        } else {
            u.int_in_range(0..=grid.spp - 1)?
        };
        let dim: usize = u.arbitrary()?;
        let inside = x < grid.width && y < grid.height && i < grid.spp;
        let Ok(h) = s.start_pixel_sample(x, y, i) else {
            assert!(!inside, "({x}, {y}) #{i} inside but refused");
            continue;
        };
        assert!(inside, "({x}, {y}) #{i} outside but started");
        let mut h = h.with_dimension(dim);
        let _ = h.sample_index();
        check_unit(h.get_1d_f32(), "get_1d");
        for v in h.get_2d_f32().into_iter().chain(h.get_pixel_2d_f32()) {
            check_unit(v, "get_2d");
        }
    }
    Ok(())
}

fn pixel(u: &mut Unstructured) -> Result<()> {
    let (w, h, spp) = (size(u)?, size(u)?, size(u)?);
    let seed: u64 = u.arbitrary()?;
    let r = randomization(u)?;
    match u.int_in_range(0u8..=5)? {
        0 => {
            if let Ok(s) = ZSobol::new(w, h, spp, r, seed) {
                probe(&s, u)?;
            }
        }
        1 => {
            if let Ok(s) = ImageSobol::new(w, h, spp, r, seed) {
                probe(&s, u)?;
            }
        }
        2 => {
            if let Ok(s) = PaddedSobol::new(w, h, spp, r, seed) {
                probe(&s, u)?;
            }
        }
        3 => {
            if let Ok(s) = Pmj02Pixels::new(w, h, spp, seed) {
                probe(&s, u)?;
            }
        }
        4 => {
            if let Ok(s) = IndependentPixels::new(w, h, spp, u.arbitrary()?) {
                probe(&s, u)?;
            }
        }
        _ => {
            // The 65,536-point table is built once (its cost is a PMJ02BN generation).
            static TABLES: std::sync::OnceLock<Pmj02BnTables> = std::sync::OnceLock::new();
            let tables = TABLES.get_or_init(|| Pmj02BnTables::new(16, 7).unwrap());
            if let Ok(s) = tables.sampler(w, h, seed) {
                probe(&s, u)?;
            }
        }
    }
    Ok(())
}

/// The first 2^m points of a (0, 2)-sequence: one in each of the 2^m strata of each axis.
fn stratified(pts: &[[u32; 2]], what: &str) {
    let m = pts.len().ilog2();
    let n = 1usize << m;
    for axis in 0..2 {
        let mut seen = vec![false; n];
        for p in &pts[..n] {
            let cell = if m == 0 {
                0
            } else {
                (p[axis] >> (32 - m)) as usize
            };
            assert!(
                !seen[cell],
                "{what}: two of the first {n} points in stratum {cell} of axis {axis}"
            );
            seen[cell] = true;
        }
    }
}

fn pmj_sequences(u: &mut Unstructured) -> Result<()> {
    let n = u.int_in_range(0usize..=300)?;
    let seed: u64 = u.arbitrary()?;
    let mut pts = vec![[0u32; 2]; n];
    match u.int_in_range(0u8..=3)? {
        0 => {
            if pmj::fill(seed, &mut pts).is_ok() && n > 0 {
                stratified(&pts, "pmj02");
            }
        }
        1 => {
            let work_len = pmj::bn::workspace_len(n).unwrap_or(0);
            let short = u.int_in_range(0..=work_len.min(4))?;
            let mut work = vec![0u32; work_len - short];
            let r = pmj::bn::fill(seed, &mut pts, &mut work, &Budget::UNLIMITED);
            assert!(
                short == 0 || n < 2 || r.is_err() || work_len == 0,
                "short workspace accepted"
            );
            if r.is_ok() && n > 0 {
                stratified(&pts, "pmj02bn");
            }
        }
        2 => {
            let candidates = size(u)?;
            let work_len = pmj::christensen::workspace_len(n).unwrap_or(0);
            let mut work = vec![0u32; work_len];
            let r =
                pmj::christensen::fill(seed, candidates, &mut pts, &mut work, &Budget::UNLIMITED);
            if candidates == 0 || candidates > pmj::christensen::MAX_CANDIDATES {
                assert!(r.is_err() || n == 0, "{candidates} candidates accepted");
            }
            if r.is_ok() && n > 0 {
                stratified(&pts, "pmj02 best candidate");
            }
        }
        _ => {
            // Arbitrary points: spread keeps a (0, 2)-sequence one, and refuses others.
            for p in &mut pts {
                *p = [u.arbitrary()?, u.arbitrary()?];
            }
            let before = pts.clone();
            let mut work = vec![0u32; pmj::spread::workspace_len(n).unwrap_or(0)];
            if pmj::spread::spread(&mut pts, &mut work, &Budget::UNLIMITED).is_err() {
                assert_eq!(pts, before, "spread changed the points it refused");
            }
        }
    }
    Ok(())
}

fn blue_noise(u: &mut Unstructured) -> Result<()> {
    let seed: u64 = u.arbitrary()?;
    let set = match u.int_in_range(0u8..=4)? {
        0 => {
            let dims = u.int_in_range(0usize..=10)?;
            let p = if u.arbitrary()? {
                PoissonDisk::new(dims, real(u)?)
            } else {
                PoissonDisk::with_points(dims, u64::from(size(u)?))
            };
            let Ok(p) = p else { return Ok(()) };
            let Ok(p) = p
                .torus(u.arbitrary()?)
                .maximal(u.arbitrary()?)
                .seed(seed)
                .candidates(size(u)?)
            else {
                return Ok(());
            };
            let _ = p.cost();
            p.generate(&budget())
        }
        1 => {
            let Ok(b) = BestCandidate::new(u64::from(size(u)?)) else {
                return Ok(());
            };
            let Ok(b) = b.candidates(size(u)?) else {
                return Ok(());
            };
            let _ = b.cost();
            b.seed(seed).generate(&budget())
        }
        2 => {
            let Ok(g) = GaussianBlueNoise::new(u64::from(size(u)?)) else {
                return Ok(());
            };
            let Ok(g) = g.iterations(size(u)?) else {
                return Ok(());
            };
            let Ok(g) = g.sigma(real(u)?) else {
                return Ok(());
            };
            let _ = g.cost();
            g.seed(seed).generate(&budget())
        }
        _ => {
            let (w, h) = (size(u)? as usize, size(u)? as usize);
            let Ok(v) = VoidAndCluster::new(w, h) else {
                return Ok(());
            };
            let Ok(v) = v.seed(seed).sigma(real(u)?) else {
                return Ok(());
            };
            let _ = v.cost();
            if let Ok(mask) = v.generate(&budget()) {
                let n = mask.width() * mask.height();
                assert_eq!(mask.ranks().len(), n);
                let mut seen = vec![false; n];
                for &r in mask.ranks() {
                    assert!((r as usize) < n && !seen[r as usize], "rank {r} of {n}");
                    seen[r as usize] = true;
                }
                let ones = u.int_in_range(0..=n)?;
                assert_eq!(mask.threshold(ones).iter().filter(|&&b| b).count(), ones);
            }
            return Ok(());
        }
    };
    if let Ok(set) = set {
        assert_eq!(
            set.coords().len(),
            set.count() * set.dims(),
            "coordinates of a set"
        );
        assert!(set.to_f64().iter().all(|x| (0.0..1.0).contains(x)));
    }
    Ok(())
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let _ = match u.int_in_range(0u8..=2) {
        Ok(0) => pixel(&mut u),
        Ok(1) => pmj_sequences(&mut u),
        Ok(_) => blue_noise(&mut u),
        Err(_) => Ok(()),
    };
});
