//! qmckit against oracles it did not write: SciPy's Halton and exact rational radical
//! inverses from Python's `fractions` (files made by tests/golden/gen.py).

use qmckit::{Halton, RadicalInverse, Sampler, bits::to_f64};

const TWO_32: f64 = 4_294_967_296.0;

fn golden(name: &str) -> String {
    let path = format!("{}/tests/golden/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn data_lines(text: &str) -> impl Iterator<Item = &str> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
}

fn check_halton(file: &str, d: usize, n: u32) {
    let text = golden(file);
    let rows: Vec<Vec<f64>> = data_lines(&text)
        .map(|l| l.split(' ').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), n as usize);
    let h = Halton::new(d).unwrap();
    // Random access and the sequential fill both match SciPy within 2^-32.
    let mut filled = vec![0u32; n as usize * d];
    h.fill(0, &mut filled).unwrap();
    let mut worst = 0f64;
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(row.len(), d);
        for (dim, &want) in row.iter().enumerate() {
            let got = h.sample(i as u32, dim).unwrap();
            assert_eq!(got, filled[i * d + dim], "fill differs at {i},{dim}");
            let err = (to_f64(got) - want).abs();
            worst = worst.max(err);
            assert!(
                err <= 1.0 / TWO_32,
                "{file}: point {i} dim {dim}: {got} vs {want}"
            );
        }
    }
    // A test that can fail: a one-index shift would be far off.
    assert!(worst < 1.0 / TWO_32);
    let shifted = to_f64(h.sample(1, d - 1).unwrap()) - rows[0][d - 1];
    assert!(shifted.abs() > 1e-3);
}

#[test]
fn halton_matches_scipy_d64() {
    check_halton("scipy_halton_d64_n64.txt", 64, 64);
}

#[test]
fn halton_matches_scipy_d8() {
    check_halton("scipy_halton_d8_n512.txt", 8, 512);
}

#[test]
fn halton_matches_scipy_d2() {
    check_halton("scipy_halton_d2_n2048.txt", 2, 2048);
}

#[test]
fn radical_inverse_is_the_exact_rational_rounded_down() {
    let text = golden("exact_radical_inverse.txt");
    let mut checked = 0;
    for line in data_lines(&text) {
        let f: Vec<u128> = line.split(' ').map(|x| x.parse().unwrap()).collect();
        let (base, index, num, den) = (f[0] as u32, f[1] as u32, f[2], f[3]);
        let want = ((num << 32) / den) as u32;
        let ri = RadicalInverse::new(base).unwrap();
        assert_eq!(ri.sample(index), want, "phi_{base}({index}) = {num}/{den}");
        // The sequential path agrees.
        assert_eq!(ri.iter_from(index).next(), Some(want));
        checked += 1;
    }
    assert!(checked >= 7 * 76);
}

#[test]
fn textbook_examples() {
    let phi = |b, i| RadicalInverse::new(b).unwrap().sample(i);
    assert_eq!(phi(3, 1000) as u64, (760u64 << 32) / 2187);
    assert_eq!(phi(7, 10) as u64, (22u64 << 32) / 49);
    assert_eq!(to_f64(phi(2, 6)), 0.375);
    // The textbook base-3 table: 0, 1/3, 2/3, 1/9, 4/9, 7/9, 2/9, 5/9, 8/9.
    let ninths = [0, 3, 6, 1, 4, 7, 2, 5, 8];
    for (i, k) in ninths.iter().enumerate() {
        assert_eq!(phi(3, i as u32) as u64, ((*k as u64) << 32) / 9);
    }
}
