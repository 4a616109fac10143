//! The projection terms of projective Lloyd relaxation ([`super::Lloyd::projective`]), in
//! the spirit of Reinert, Ritschel, Seidel & Georgiev (projective blue noise): besides the
//! full-space quantization energy, every axis projection of the sites is pulled towards
//! the 1D optimum, the midpoints `m_r = (r + 1/2) / N` of `N` equal intervals.
//!
//! ## The energy and the step
//!
//! With the sites `x_i`, their sample cells `V_i` (weight `w_i = |V_i| / M`, centroid
//! `c_i`) and, on every axis `k`, the rank `r_k(i)` of `x_ik` among the sites,
//!
//! ```text
//! E = (1/M) sum_j |y_j - x_owner(j)|^2 + mu sum_k (1/N) sum_i (x_ik - m_(r_k(i)))^2
//! ```
//!
//! (the second sum is, up to a constant, the squared 1D transport distance of each
//! projection to the uniform measure: the sorted assignment of sites to the intervals is
//! optimal). For fixed cells and ranks `E` is a sum of one quadratic a coordinate, least at
//!
//! `x_ik = (w_i c_ik + (mu / N) m_(r_k(i))) / (w_i + mu / N)`,
//!
//! and for fixed sites the nearest-site cells and the sorted ranks are optimal: the step
//! (ranks from the sites, then cells, then this move) never increases `E` (tested). `mu = 0`
//! is Lloyd. Cube only (on the torus the ranks have no origin). Cost: a sort of `N` a
//! dimension an iteration, `O(d N log N)`.

use std::vec::Vec;

/// `r_k(i)` for every site and axis: `ranks[k * n + i]`.
pub(super) fn ranks(sites: &[f64], n: usize, d: usize) -> Vec<u32> {
    let mut ranks = vec![0u32; n * d];
    let mut order: Vec<u32> = (0..n as u32).collect();
    for k in 0..d {
        let key = |i: &u32| sites.get(*i as usize * d + k).copied().unwrap_or(0.0);
        order.sort_by(|a, b| key(a).total_cmp(&key(b)));
        for (r, &i) in order.iter().enumerate() {
            if let Some(slot) = ranks.get_mut(k * n + i as usize) {
                *slot = r as u32;
            }
        }
    }
    ranks
}

/// `(1/N) sum_k sum_i (x_ik - m_(r_k(i)))^2` with the sorted ranks of `sites`.
pub(super) fn projection_energy(sites: &[f64], n: usize, d: usize) -> f64 {
    let r = ranks(sites, n, d);
    let mut e = 0.0;
    for (i, x) in sites.chunks_exact(d).enumerate() {
        for (k, &v) in x.iter().enumerate() {
            let m = (f64::from(r[k * n + i]) + 0.5) / n as f64;
            e += (v - m) * (v - m);
        }
    }
    e / n as f64
}

/// The step's move: `sites` hold the centroids `c_i` (a site without samples its old
/// position), `weights` the `w_i`, `ranks` those of the sites before the move.
pub(super) fn blend(sites: &mut [f64], weights: &[f64], ranks: &[u32], mu: f64, d: usize) {
    let n = weights.len();
    let a = mu / n as f64;
    for (i, (x, &w)) in sites.chunks_exact_mut(d).zip(weights).enumerate() {
        for (k, v) in x.iter_mut().enumerate() {
            let m = (f64::from(ranks.get(k * n + i).copied().unwrap_or(0)) + 0.5) / n as f64;
            *v = (w * *v + a * m) / (w + a);
        }
    }
}
