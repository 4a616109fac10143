//! `qmckit::catalog`: (a) every sampler entry with every randomizer that applies to it
//! through the `Sampler` contract, and the refusals (here); (b) the builder against golden
//! values we did not write (SciPy, QMCPy, pbrt, exact rationals: `golden`) and against the
//! command line (`cli`); (c) every name and alias (`names`).

use qmckit::bits::{to_f32, to_f64};
use qmckit::catalog::{
    self, CatalogError, Family, Params, RANDOMIZERS, RandomizerEntry, SAMPLERS, SamplerEntry,
};
use qmckit::digital::sobol::Order;
use qmckit::{Sampler, sampler::fill_as_by_chunks};

fn golden(name: &str) -> String {
    let path = format!("{}/tests/golden/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn data_lines(text: &str) -> impl Iterator<Item = &str> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
}

/// The parameter sets every sampler is walked with: the catalog's examples.
fn cases() -> Vec<(&'static str, Params)> {
    catalog::examples()
        .into_iter()
        .map(|(e, p)| (e.name, p))
        .collect()
}

/// The sampler's points `0..n` by `fill`, after checking that every other path gives the
/// same bits: `sample`, `point`, `fill` from offsets and in pieces, `fill_as` to `f64` and
/// `f32` (as `Box<dyn Sampler>` and through the `dyn` helper), `collect::points`; and that
/// bad calls are errors.
// The box itself: `fill_as` is for sized samplers, and the builder's box is one.
#[allow(clippy::borrowed_box)]
fn contract(label: &str, s: &Box<dyn Sampler>) -> Vec<u32> {
    let (d, len) = (s.dims(), s.len());
    assert!(d >= 1 && len >= 1, "{label}");
    // Past CONVERT_CHUNK (1024) values, so the conversions run in several chunks.
    let n = len.min((1024 / d + 7) as u64) as usize;
    let mut filled = vec![0u32; n * d];
    s.fill(0, &mut filled).unwrap();
    let mut row = vec![0u32; d];
    for i in 0..n {
        s.point(i as u32, &mut row).unwrap();
        assert_eq!(row, filled[i * d..(i + 1) * d], "{label}: point {i}");
        for k in 0..d {
            assert_eq!(
                s.sample(i as u32, k).unwrap(),
                filled[i * d + k],
                "{label}: {i},{k}"
            );
        }
    }
    // From an offset, and in pieces of 7 points.
    let start = n / 3;
    let mut tail = vec![0u32; (n - start) * d];
    s.fill(start as u32, &mut tail).unwrap();
    assert_eq!(tail, filled[start * d..], "{label}: fill from {start}");
    let mut pieces = vec![0u32; n * d];
    for (c, chunk) in pieces.chunks_mut(7 * d).enumerate() {
        s.fill((c * 7) as u32, chunk).unwrap();
    }
    assert_eq!(pieces, filled, "{label}: fill in pieces");
    // Conversions: the same values as converting the u32s, in [0, 1).
    let mut f = vec![0f64; n * d];
    s.fill_as(0, &mut f).unwrap();
    let mut g = vec![0f32; n * d];
    s.fill_as(0, &mut g).unwrap();
    let mut h = vec![0f64; n * d];
    fill_as_by_chunks(&**s, 0, &mut h).unwrap();
    let collected: Vec<f64> = qmckit::collect::points(s, n as u64).unwrap();
    for (k, &u) in filled.iter().enumerate() {
        assert_eq!(f[k], to_f64(u), "{label}: f64 {k}");
        assert_eq!(g[k], to_f32(u), "{label}: f32 {k}");
        assert_eq!(h[k], f[k], "{label}: dyn f64 {k}");
        assert_eq!(collected[k], f[k], "{label}: collect {k}");
        assert!(
            (0.0..1.0).contains(&f[k]) && (0.0..1.0).contains(&g[k]),
            "{label}"
        );
    }
    // The last point, and the refusals.
    let last = (len - 1) as u32;
    let mut one = vec![0u32; d];
    s.fill(last, &mut one).unwrap();
    assert_eq!(one[d - 1], s.sample(last, d - 1).unwrap(), "{label}: last");
    assert!(s.fill(last, &mut vec![0u32; 2 * d]).is_err(), "{label}");
    if len < 1 << 32 {
        assert!(
            s.sample(len as u32, 0).is_err(),
            "{label}: index past the set"
        );
    }
    assert!(s.sample(0, d).is_err(), "{label}: dimension past the point");
    assert!(s.point(0, &mut vec![0u32; d + 1]).is_err(), "{label}");
    if d > 1 {
        assert!(s.fill(0, &mut vec![0u32; d + 1]).is_err(), "{label}");
    }
    filled
}

fn build(
    s: &SamplerEntry,
    r: &RandomizerEntry,
    p: &Params,
) -> Result<Box<dyn Sampler>, CatalogError> {
    catalog::build(s, r, p)
}

#[test]
fn every_sampler_and_randomizer_keeps_the_contract() {
    let cases = cases();
    for entry in SAMPLERS {
        let walked = cases.iter().any(|(name, _)| *name == entry.name);
        let whole = entry.kind.family(None) == Family::BlueNoise
            || entry.kind == catalog::SamplerKind::Pmj02bn;
        assert!(
            walked || (whole && !cfg!(feature = "analysis")),
            "{} is not walked",
            entry.name
        );
    }
    let mut combinations = 0;
    for (name, params) in &cases {
        let s = catalog::sampler(name).unwrap();
        for r in RANDOMIZERS {
            let label = format!("{name} {:?} + {}", params.base, r.name);
            let applies = catalog::applies(r, s, params.base).is_ok();
            let p = params.clone().with_seed(12345);
            let built = build(s, r, &p);
            if !applies {
                let e = built.err().unwrap_or_else(|| panic!("{label}: built"));
                assert!(
                    matches!(e, CatalogError::NotApplicable { .. }),
                    "{label}: {e}"
                );
                let text = e.to_string();
                assert!(
                    text.starts_with(&format!("{} applies to ", r.name)),
                    "{text}"
                );
                assert!(text.contains(&format!("not {name}")), "{text}");
                continue;
            }
            let built = built.unwrap_or_else(|e| panic!("{label}: {e}"));
            let bits = contract(&label, &built);
            // Determinism: built again, the same bits.
            let again = contract(&label, &build(s, r, &p).unwrap());
            assert_eq!(bits, again, "{label}: built twice");
            // Another seed: other bits exactly when something is random.
            let other = contract(&label, &build(s, r, &p.clone().with_seed(54321)).unwrap());
            let random = (s.kind.is_random() && !p.centered) || r.kind.is_seeded();
            if random {
                assert_ne!(bits, other, "{label}: the seed changes nothing");
            } else {
                assert_eq!(bits, other, "{label}: deterministic but seed-dependent");
            }
            combinations += 1;
        }
    }
    assert!(combinations >= 60, "{combinations}");
}

/// Bad parameters are errors with a message, never a panic.
#[test]
fn bad_parameters_are_errors() {
    let none = catalog::randomizer("none").unwrap();
    let dims = |d| Params::dims(d);
    let mut cases: Vec<(&str, &str, Params, &str)> = vec![
        (
            "lp",
            "none",
            Params::default().with_points(48),
            "power of two",
        ),
        ("lp", "none", Params::default(), "points"),
        ("lp", "none", dims(3).with_points(64), "two-dimensional"),
        ("vdc", "none", dims(2), "one-dimensional"),
        (
            "vdc",
            "none",
            Params {
                base: Some(1),
                ..Params::default()
            },
            "base",
        ),
        (
            "faure",
            "none",
            Params {
                base: Some(4),
                ..dims(3)
            },
            "prime",
        ),
        (
            "faure",
            "none",
            Params {
                base: Some(2),
                ..dims(3)
            },
            "prime of at least dims",
        ),
        ("faure", "none", dims(1 << 20), "base"),
        ("halton", "none", dims(2000), "dimension"),
        ("sobol", "none", dims(1_000_000), "dimension"),
        (
            "sobol",
            "none",
            Params::dims(3).with_points(8),
            "points does not apply",
        ),
        (
            "sobol",
            "none",
            Params {
                base: Some(3),
                ..dims(2)
            },
            "base does not apply",
        ),
        (
            "halton",
            "none",
            Params {
                strata: Some(vec![2, 2]),
                ..dims(2)
            },
            "strata",
        ),
        (
            "halton",
            "none",
            Params {
                order: Order::Gray,
                ..dims(2)
            },
            "order",
        ),
        ("stratified", "none", dims(2).with_points(50), "k^d"),
        ("stratified", "none", dims(2), "points"),
        (
            "stratified",
            "none",
            Params {
                strata: Some(vec![4, 4]),
                ..dims(3)
            },
            "strata",
        ),
        (
            "stratified",
            "none",
            Params {
                strata: Some(vec![4, 0]),
                ..Params::default()
            },
            "strata",
        ),
        (
            "stratified",
            "none",
            Params {
                strata: Some(vec![4, 4]),
                ..Params::default().with_points(15)
            },
            "cells",
        ),
        ("latin", "none", dims(2).with_points(0), "at least 1"),
        (
            "hammersley",
            "none",
            dims(2).with_points(1 << 33),
            "allowed",
        ),
        (
            "lattice",
            "none",
            Params {
                korobov: Some(3),
                ..dims(2)
            },
            "needs points",
        ),
        ("lattice", "none", dims(10_000), "9125"),
        (
            "kronecker",
            "none",
            Params {
                korobov: Some(3),
                ..dims(2)
            },
            "korobov",
        ),
        ("pmj02", "none", dims(3), "two-dimensional"),
        ("cmj", "none", dims(2), "points"),
        ("cmj", "none", dims(2).with_points(0), "at least 1"),
        ("hex", "none", Params::default().with_points(15), "even"),
        ("hex", "none", dims(3).with_points(16), "two-dimensional"),
        ("hex", "none", Params::default(), "points"),
        ("independent", "none", dims(0), "at least 1"),
        ("independent", "none", dims((1 << 27) + 1), "too large"),
        ("independent", "none", dims(usize::MAX), "too large"),
        ("sobol", "lms", dims(0), "at least 1"),
    ];
    if cfg!(feature = "analysis") {
        let blue = |b: catalog::BlueNoiseOptions| Params {
            blue_noise: b,
            ..Params::default().with_points(10)
        };
        cases.extend([
            ("pmj02bn", "none", Params::default(), "points"),
            ("pmj02bn", "none", Params::default().with_points(0), ""),
            (
                "pmj02bn",
                "none",
                Params {
                    budget: qmckit::work::Budget::seconds(1e-6).unwrap(),
                    ..Params::default().with_points(1 << 30)
                },
                "",
            ),
            ("poisson", "none", Params::default(), "radius"),
            (
                "poisson",
                "none",
                blue(catalog::BlueNoiseOptions {
                    radius: Some(0.1),
                    ..Default::default()
                }),
                "not both",
            ),
            (
                "best-candidate",
                "none",
                blue(catalog::BlueNoiseOptions {
                    radius: Some(0.1),
                    ..Default::default()
                }),
                "radius does not apply",
            ),
            (
                "poisson",
                "none",
                blue(catalog::BlueNoiseOptions {
                    iterations: Some(3),
                    ..Default::default()
                }),
                "iterations",
            ),
            (
                "gaussian-blue-noise",
                "none",
                dims(3).with_points(10),
                "two-dimensional",
            ),
            ("best-candidate", "none", Params::default(), "points"),
            ("lloyd", "none", Params::default(), "points"),
            ("lloyd", "none", dims(65).with_points(10), "dimension"),
            (
                "sot",
                "none",
                blue(catalog::BlueNoiseOptions {
                    torus: true,
                    ..Default::default()
                }),
                "torus does not apply",
            ),
            (
                "ccvt",
                "none",
                Params {
                    budget: qmckit::work::Budget::seconds(1e-6).unwrap(),
                    ..Params::default().with_points(1 << 20)
                },
                "budget",
            ),
        ]);
    }
    for (name, r, p, needle) in cases {
        let s = catalog::sampler(name).unwrap();
        let r = if r == "none" {
            none
        } else {
            catalog::randomizer(r).unwrap()
        };
        let e = build(s, r, &p)
            .err()
            .unwrap_or_else(|| panic!("{name} {p:?}: built"));
        let text = e.to_string();
        assert!(
            !text.is_empty() && text.contains(needle),
            "{name}: {text:?} lacks {needle:?}"
        );
    }
}

fn named(sampler: &str, randomizer: &str, p: &Params) -> Box<dyn Sampler> {
    catalog::build_named(sampler, randomizer, p).unwrap()
}

fn fill(s: &dyn Sampler, n: usize) -> Vec<u32> {
    let mut v = vec![0u32; n * s.dims()];
    s.fill(0, &mut v).unwrap();
    v
}

mod golden;
mod names;

/// A generating vector read from text: its modulus chooses the order, as in the command.
#[test]
fn generating_vectors_choose_their_rule() {
    use catalog::GeneratingVector;
    use qmckit::lattice::Rank1Lattice;
    let vector = |text: &str, d: usize, points: Option<u64>| Params {
        vector: Some(GeneratingVector::parse(text, d).unwrap()),
        points,
        ..Params::dims(d)
    };
    let ldd = "# lattice\n3 # dims\n16 # n\n1\n5\n7\n";
    let ext = named("lattice", "none", &vector(ldd, 3, None));
    let want = Rank1Lattice::extensible(vec![1u32, 5, 7], 4).unwrap();
    assert_eq!(ext.len(), 16);
    assert_eq!(fill(&*ext, 16), fill(&want, 16));
    let odd = "# lattice\n2\n13\n1\n5\n";
    let lin = named("lattice", "shift", &vector(odd, 2, None));
    assert_eq!(lin.len(), 13);
    // Kuo's two columns name no modulus: the size must be given.
    let kuo = "1 1\n2 5\n3 7\n";
    assert!(catalog::build_named("lattice", "none", &vector(kuo, 2, None)).is_err());
    let lin = named("lattice", "none", &vector(kuo, 2, Some(13)));
    let want = Rank1Lattice::linear(vec![1u32, 5], 13).unwrap();
    assert_eq!(fill(&*lin, 13), fill(&want, 13));
    // Fewer components than dimensions, and a vector beside a Korobov parameter.
    assert!(GeneratingVector::parse(kuo, 4).is_err());
    let both = Params {
        korobov: Some(3),
        ..vector(kuo, 2, Some(13))
    };
    assert!(catalog::build_named("lattice", "none", &both).is_err());
}
