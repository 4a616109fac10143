//! The statistics of `scripts/utk_compare.sh` for a 2D set in the unit square, as
//! `cli/examples/set_stats.rs` measures them: the exact star discrepancy, the mean
//! nearest-neighbour distance times
//! `sqrt(N)` (in the square, not the torus) and the mean radial power of the periodogram
//! over `1 <= |k| <= sqrt(N)/2`. Shared by the table optimizers to report the tables
//! they write.

use qmckit::analysis::{
    Points,
    distance::mean_min_distance,
    spectrum::{DEFAULT_TOLERANCE, Method, periodogram_2d},
    star::star_exact,
};
use qmckit::work::Budget;

/// `(mean NN distance x sqrt(N), low-band mean radial power, band sqrt(N)/2 to sqrt(N))`
/// of the points `xy` (interleaved `x, y` in `[0, 1)`).
pub fn nn_low_mid(xy: &[f64]) -> (f64, f64, f64) {
    let p = Points::new(xy, 2).expect("2D points");
    let n = p.len() as f64;
    let root = n.sqrt();
    let nn = mean_min_distance(p, false) * root;
    let s = periodogram_2d(
        p,
        root.ceil() as usize,
        Method::Auto,
        DEFAULT_TOLERANCE,
        &Budget::DEFAULT,
    )
    .expect("periodogram");
    let radial = s.radial();
    let band = |lo: f64, hi: f64| {
        let v: Vec<f64> = radial
            .iter()
            .filter(|b| (b.radius as f64) > lo && (b.radius as f64) <= hi)
            .map(|b| b.mean)
            .collect();
        v.iter().sum::<f64>() / v.len().max(1) as f64
    };
    (nn, band(0.5, root / 2.0), band(root / 2.0, root))
}

/// The mean exact star discrepancy `D*` of `sets` (interleaved `x, y` in `[0, 1)`).
pub fn mean_star(sets: &[Vec<f64>]) -> f64 {
    let total: f64 = sets
        .iter()
        .map(|s| {
            let p = Points::new(s, 2).expect("2D points");
            star_exact(p, &Budget::DEFAULT).expect("star discrepancy")
        })
        .sum();
    total / sets.len().max(1) as f64
}

/// The means of [`nn_low_mid`] over `sets`.
pub fn mean_nn_low_mid(sets: &[Vec<f64>]) -> (f64, f64, f64) {
    let mut m = (0.0, 0.0, 0.0);
    for s in sets {
        let (a, b, c) = nn_low_mid(s);
        m = (m.0 + a, m.1 + b, m.2 + c);
    }
    let k = sets.len().max(1) as f64;
    (m.0 / k, m.1 / k, m.2 / k)
}
