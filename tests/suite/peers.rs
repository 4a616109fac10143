//! Agreement with the peer crates we did not write: `sobol_burley`, `sobol`, `sobol-qmc` and
//! `openqmc-rs` (dev-dependencies). Each compares qmckit's bits with a peer's where both
//! implement the same definition (Joe & Kuo's direction numbers, Gray order, Vegdahl's
//! Owen hash), so a wrong table entry, order or hash constant fails here.

use qmckit::Sampler;
use qmckit::bits::gray;
use qmckit::digital::sobol::{Order, Sobol, SobolDimension};
use qmckit::hash::vegdahl;

/// Points compared in Gray order.
const N: usize = 4096;
/// Dimensions compared.
const D: usize = 32;

fn dimensions(d: usize) -> Vec<SobolDimension> {
    (0..d)
        .map(|k| SobolDimension::new(k).expect("dimension in table"))
        .collect()
}

/// qmckit's first `N` points of `D` dimensions in Gray order (SciPy's and the peers' order).
fn gray_points() -> Vec<u32> {
    let mut q = vec![0u32; N * D];
    Sobol::with_order(D, Order::Gray)
        .unwrap()
        .fill(0, &mut q)
        .unwrap();
    q
}

#[test]
fn sobol_qmc_gives_the_same_gray_points() {
    let q = gray_points();
    let mut g = sobol_qmc::Sobol::<u32>::new(D, &sobol_qmc::params::JoeKuoD6::STANDARD).unwrap();
    for (k, row) in q.chunks_exact(D).enumerate() {
        g.update();
        let p: Vec<u32> = g.render_next().collect();
        assert_eq!(p, row, "sobol-qmc point {k}");
    }
}

#[test]
fn the_sobol_crate_gives_the_same_points_in_u32_and_f64() {
    let q = gray_points();
    let params = sobol::params::JoeKuoD6::standard();
    for (k, (row, p)) in q
        .chunks_exact(D)
        .zip(sobol::Sobol::<u32>::new(D, &params))
        .enumerate()
    {
        assert_eq!(p, row, "sobol point {k}");
    }
    // Its f64 output (53-bit resolution) is the same fractions.
    for (row, p) in q
        .chunks_exact(D)
        .zip(sobol::Sobol::<f64>::new(D, &params))
        .take(256)
    {
        for (&x, &y) in row.iter().zip(&p) {
            assert_eq!(qmckit::bits::to_f64(x), y);
        }
    }
    // Natural order is the Gray order permuted point by point through gray(i).
    let s = Sobol::new(D).unwrap();
    for (k, row) in q.chunks_exact(D).enumerate() {
        for (dim, &x) in row.iter().enumerate() {
            assert_eq!(s.sample(gray(k as u32), dim).unwrap(), x);
        }
    }
}

#[test]
fn sobol_burley_has_the_same_directions_and_owen_hash() {
    // Its unscrambled core: the same Joe-Kuo numbers, for indices below 2^16.
    let dims = dimensions(D);
    for i in 0..1u32 << 16 {
        for (dim, dd) in dims.iter().enumerate() {
            let burley =
                sobol_burley::parts::sobol_rev(i.reverse_bits(), dim as u32).reverse_bits();
            assert_eq!(burley, dd.sample(i), "index {i}, dimension {dim}");
        }
    }
    // Its Owen hash is qmckit's `vegdahl`, bit for bit (constants and rounds).
    for x in (0..1u32 << 16).map(|k| k.wrapping_mul(0x9E37_79B9)) {
        for key in [0u32, 1, 0x89AB_CDEF, 0xDEAD_BEEF] {
            assert_eq!(
                sobol_burley::parts::owen_scramble_rev(x, key),
                vegdahl(x, key),
                "x {x:#x}, key {key:#x}"
            );
        }
    }
}

#[test]
fn openqmc_has_the_same_first_four_dimensions() {
    // Its Sobol' core holds 16-bit direction numbers: Joe-Kuo's for dimensions 0..4, so its
    // values are the top 16 bits of qmckit's for every index below 2^16.
    let dims = dimensions(4);
    for i in 0..=u16::MAX {
        for (dim, dd) in dims.iter().enumerate() {
            let r = openqmc::owen::sobol_reversed_index(i.reverse_bits(), dim);
            assert_eq!(u32::from(r.reverse_bits()) << 16, dd.sample(u32::from(i)));
        }
    }
}
