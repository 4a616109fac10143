//! The catalog's builders against values we did not write: SciPy's Sobol' and Halton,
//! exact rational radical inverses, QMCPy's lattices and Faure, pbrt-v4's pixel samplers,
//! SciPy's discrepancies and the test problems' exact integrals.

use super::{data_lines, fill, golden, named};
use qmckit::Sampler;
use qmckit::bits::to_f64;
use qmckit::catalog::{self, INTEGRANDS, Params};
use qmckit::digital::sobol::Order;
use qmckit::pixel::PixelSampler;

/// FNV-1a 64 over the little-endian bytes of the values (as tests/golden/gen.py does).
fn fnv1a64(values: impl IntoIterator<Item = u32>) -> u64 {
    let mut h = 0xCBF2_9CE4_8422_2325u64;
    for v in values {
        for byte in v.to_le_bytes() {
            h = (h ^ byte as u64).wrapping_mul(0x0100_0000_01B3);
        }
    }
    h
}

#[test]
fn sobol_gray_is_scipy() {
    let p = Params {
        order: Order::Gray,
        ..Params::dims(64)
    };
    let s = named("Sobol", "None", &p);
    let n = 1usize << 16;
    let pts = fill(&*s, n);
    let (mut digests, mut points) = (0, 0);
    for line in data_lines(&golden("scipy_sobol_d64_n65536.txt")) {
        let f: Vec<&str> = line.split_whitespace().collect();
        match f[0] {
            "digest" => {
                let dim: usize = f[1].parse().unwrap();
                let want = u64::from_str_radix(f[2], 16).unwrap();
                assert_eq!(fnv1a64(pts.iter().skip(dim).step_by(64).copied()), want);
                digests += 1;
            }
            "point" => {
                let i: usize = f[1].parse().unwrap();
                for (dim, v) in f[2..].iter().enumerate() {
                    assert_eq!(pts[i * 64 + dim], v.parse::<u32>().unwrap(), "{i},{dim}");
                }
                points += 1;
            }
            other => panic!("unknown line {other}"),
        }
    }
    assert_eq!((digests, points), (64, 64));
}

#[test]
fn halton_is_scipy_within_one_ulp() {
    for (file, d, n) in [
        ("scipy_halton_d8_n512.txt", 8usize, 512usize),
        ("scipy_halton_d64_n64.txt", 64, 64),
    ] {
        let s = named("halton", "none", &Params::dims(d));
        let pts = fill(&*s, n);
        let rows: Vec<Vec<f64>> = data_lines(&golden(file))
            .map(|l| l.split(' ').map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), n);
        for (i, row) in rows.iter().enumerate() {
            for (k, &want) in row.iter().enumerate() {
                let err = (to_f64(pts[i * d + k]) - want).abs();
                assert!(err <= 1.0 / 4_294_967_296.0, "{file}: {i},{k}");
            }
        }
    }
}

#[test]
fn vdc_is_the_exact_radical_inverse_in_every_base() {
    let mut checked = 0;
    for line in data_lines(&golden("exact_radical_inverse.txt")) {
        let f: Vec<u128> = line.split(' ').map(|x| x.parse().unwrap()).collect();
        let (base, index, num, den) = (f[0] as u32, f[1] as u32, f[2], f[3]);
        let p = Params {
            base: Some(base),
            ..Params::default()
        };
        let s = named("van-der-corput", "none", &p);
        assert_eq!(s.sample(index, 0).unwrap(), ((num << 32) / den) as u32);
        checked += 1;
    }
    assert!(checked >= 7 * 76);
}

fn integer_rows(name: &str) -> Vec<Vec<u64>> {
    data_lines(&golden(name))
        .map(|l| l.split_whitespace().map(|t| t.parse().unwrap()).collect())
        .collect()
}

fn as_rows(v: &[u32], d: usize) -> Vec<Vec<u64>> {
    v.chunks(d)
        .map(|r| r.iter().map(|&x| x as u64).collect())
        .collect()
}

#[test]
fn lattices_are_qmcpy() {
    let ext = named("lattice", "none", &Params::dims(8));
    assert_eq!(
        as_rows(&fill(&*ext, 1024), 8),
        integer_rows("qmcpy_lattice_natural_d8_n1024.txt")
    );
    let lin = named("rank-1-lattice", "none", &Params::dims(8).with_points(256));
    assert_eq!(
        as_rows(&fill(&*lin, 256), 8),
        integer_rows("qmcpy_lattice_linear_d8_n256.txt")
    );
}

#[test]
fn faure_is_qmcpy() {
    for (file, d, n) in [
        ("qmcpy_faure_d3_n243.txt", 3usize, 243usize),
        ("qmcpy_faure_d5_n625.txt", 5, 625),
    ] {
        let s = named("faure", "none", &Params::dims(d));
        let pts = fill(&*s, n);
        for (i, l) in data_lines(&golden(file)).enumerate() {
            for (k, t) in l.split_whitespace().enumerate() {
                let want: f64 = t.parse().unwrap();
                let err = (to_f64(pts[i * d + k]) - want).abs();
                assert!(err <= 1.0 / 4_294_967_296.0 + 1e-12, "{file}: {i},{k}");
            }
        }
    }
}

#[test]
fn pixel_samplers_are_pbrt() {
    let mut checked = 0;
    for line in data_lines(&golden("pbrt_samplers.txt")) {
        let f: Vec<&str> = line.split_whitespace().collect();
        let n = |k: usize| f[k].parse::<u32>().unwrap();
        let params = catalog::PixelParams {
            width: n(1),
            height: n(2),
            spp: n(3),
            seed: n(4) as u64,
        };
        // The file's names ("padded", "sobol", "fastowen") are catalog aliases.
        let entry = catalog::pixel_sampler(f[0]).unwrap();
        let r = catalog::randomizer(f[5]).unwrap();
        let s = catalog::build_pixel(entry, Some(r), &params).unwrap();
        let (px, py, i, dim) = (n(6), n(7), n(8), n(9) as usize);
        let want: Vec<u32> = f[11..14]
            .iter()
            .map(|s| u32::from_str_radix(s, 16).unwrap())
            .collect();
        let start = || s.start_pixel_sample(px, py, i).unwrap().with_dimension(dim);
        let [a, b] = start().get_2d();
        assert_eq!([start().get_1d(), a, b], want[..], "{line}");
        checked += 1;
    }
    assert!(checked >= 300, "{checked}");
}

/// The seed reaches the randomizers as the library's own helpers and studies map it.
#[test]
fn seeds_map_as_the_library_helpers() {
    let p = Params::dims(3).with_seed(9);
    let fast = fill(&*named("sobol", "fast-owen", &p), 100);
    let want = qmckit::collect::sobol_scrambled(100, 3, 9).unwrap();
    assert_eq!(fast.iter().map(|&x| to_f64(x)).collect::<Vec<_>>(), want);
    let owen_sobol = qmckit::OwenSobol::new(3, 9).unwrap();
    assert_eq!(fast, fill(&owen_sobol, 100));
    let perm = fill(&*named("halton", "perm", &p), 100);
    let want = qmckit::collect::halton_scrambled(100, 3, 9).unwrap();
    assert_eq!(perm.iter().map(|&x| to_f64(x)).collect::<Vec<_>>(), want);
    // The samplers of `qmckit variance` and of the scene studies, as catalog entries (the
    // studies' Owen-Sobol' is fast-owen above; variance's owen-sobol is owen here).
    use qmckit::randomize::{DigitalShift, ExactOwen, Scrambled};
    use qmckit::{Independent, Jitter, Sobol, Stratified};
    let jittered = Stratified::uniform(8, 2, Jitter::Random(9)).unwrap();
    let p2 = Params::dims(2).with_seed(9);
    let catalog = named("jittered", "none", &p2.clone().with_points(64));
    assert_eq!(fill(&*catalog, 64), fill(&jittered, 64));
    let strata = Stratified::new(&[4, 2], Jitter::Random(9)).unwrap();
    let catalog = Params {
        strata: Some(vec![4, 2]),
        ..Params::default().with_seed(9)
    };
    assert_eq!(
        fill(&*named("stratified", "none", &catalog), 8),
        fill(&strata, 8)
    );
    let owen = Scrambled::new(Sobol::new(2).unwrap(), ExactOwen::new(9));
    assert_eq!(fill(&*named("sobol", "owen", &p2), 64), fill(&owen, 64));
    let xor = Scrambled::new(Sobol::new(3).unwrap(), DigitalShift::new(9));
    assert_eq!(fill(&*named("sobol", "xor", &p), 64), fill(&xor, 64));
    let white = Independent::new(3, 9).unwrap();
    assert_eq!(
        fill(&*named("independent", "none", &p), 64),
        fill(&white, 64)
    );
}

#[cfg(feature = "analysis")]
#[test]
fn measures_are_scipy() {
    use qmckit::analysis::Points;
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if !name.starts_with("scipy_discrepancy_") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let mut lines = data_lines(&text);
        let mut field = || {
            lines
                .next()
                .unwrap()
                .split_once(' ')
                .unwrap()
                .1
                .parse::<usize>()
        };
        let (_n, d) = (field().unwrap(), field().unwrap());
        let mut values = Vec::new();
        let mut points = Vec::new();
        let mut in_points = false;
        for l in data_lines(&text).skip(2) {
            if l == "points" {
                in_points = true;
            } else if in_points {
                points.extend(l.split(' ').map(|x| x.parse::<f64>().unwrap()));
            } else {
                let f: Vec<&str> = l.split(' ').collect();
                values.push((f[0].to_owned(), f[2].parse::<f64>().unwrap()));
            }
        }
        let p = Points::new(&points, d).unwrap();
        for (method, reference) in values {
            // SciPy's method names ("L2-star", "CD", "WD", "MD") resolve in the catalog.
            let m = catalog::measure(&method).unwrap();
            let got = m.scalar(p, &qmckit::work::Budget::DEFAULT).unwrap();
            let rel = if got == reference {
                0.0
            } else {
                ((got - reference) / reference).abs()
            };
            assert!(rel <= 1e-12, "{name} {method}: {got:e} vs {reference:e}");
            checked += 1;
        }
    }
    assert!(checked >= 32, "{checked}");
}

#[cfg(feature = "analysis")]
#[test]
fn integrands_are_the_test_suite_and_its_exact_values() {
    use catalog::{IntegrandParams, TestIntegrand};
    let want: Vec<(String, f64)> = data_lines(&golden("integrate_exact.txt"))
        .map(|l| {
            let (n, v) = l.split_once(' ').unwrap();
            (n.to_owned(), v.parse().unwrap())
        })
        .collect();
    let suite = qmckit::analysis::integrate::test_suite();
    assert_eq!(suite.len(), want.len());
    for (problem, (name, value)) in suite.iter().zip(&want) {
        let (family, d) = name.rsplit_once("-d").unwrap();
        let p = IntegrandParams {
            dims: Some(d.parse().unwrap()),
            ..Default::default()
        };
        let f = catalog::build_integrand(catalog::integrand(family).unwrap(), &p).unwrap();
        assert_eq!(f, TestIntegrand::Problem(problem.clone()), "{name}");
        let got = f.exact();
        assert!(
            (got - value).abs() <= 1e-10 * value.abs().max(1.0),
            "{name}"
        );
    }
    // The convergence and variance integrands are the library's, by their old names.
    let p = IntegrandParams::default();
    for (name, f) in [("gaussian", "gaussian"), ("heaviside", "heaviside")] {
        let built = catalog::build_integrand(catalog::integrand(name).unwrap(), &p).unwrap();
        let lib = qmckit::analysis::integrate::Integrand::ALL
            .into_iter()
            .find(|i| i.name() == f)
            .unwrap();
        assert_eq!(built, TestIntegrand::Cube { f: lib, dims: 2 });
    }
    let disk = catalog::build_integrand(catalog::integrand("disk").unwrap(), &p).unwrap();
    assert_eq!(disk.exact(), core::f64::consts::PI * 0.0625);
    // Every entry builds with its defaults and evaluates inside its domain.
    for e in INTEGRANDS {
        let f = catalog::build_integrand(e, &p).unwrap();
        let x = vec![0.3; f.dims()];
        assert!(
            f.eval(&x).is_finite() && f.exact().is_finite(),
            "{}",
            e.name
        );
    }
    let bad = IntegrandParams {
        dims: Some(25),
        ..Default::default()
    };
    assert!(
        catalog::build_integrand(catalog::integrand("genz-corner-peak").unwrap(), &bad).is_err()
    );
    let bad = IntegrandParams {
        radius: Some(0.7),
        ..Default::default()
    };
    assert!(catalog::build_integrand(catalog::integrand("torus-disk").unwrap(), &bad).is_err());
    assert!(catalog::build_integrand(catalog::integrand("ball").unwrap(), &bad).is_err());
}
