//! Minimum (Euclidean) distance between points, in the unit cube or on the torus.
//!
//! For points `x_1 .. x_N` in `[0, 1]^d`,
//!
//! ```text
//! min_distance = min_{i != k} ( sum_j delta(x_ij, x_kj)^2 )^(1/2)
//! delta(a, b) = |a - b|                     (in the cube)
//! delta(a, b) = min(|a - b|, 1 - |a - b|)   (on the torus [0, 1)^d, toroidal)
//! ```
//!
//! The larger the minimum distance, the better spread (the "Poisson-disk" quality of a
//! sample pattern); for `N` points it is at most of order `N^(-1/d)`.
//!
//! Both measures sort the points by their first coordinate and sweep: a pair is only
//! compared when its first coordinates differ (cyclically, on the torus) by less than the
//! current best distance. For well-spread sets (nets, jittered, Poisson-disk) about
//! `N^(1 - 1/d)` neighbours fall in that slab, so the cost is `O(N log N + N^(2 - 1/d) d)`
//! (in 2D, `N^1.5`: a fraction of a second for a million points); the worst case (all points
//! in a thin slab) is the brute force `O(N^2 d)`.

use super::Points;

/// `delta^2` summed over the coordinates, in the cube or on the torus.
#[inline]
fn dist2(a: &[f64], b: &[f64], toroidal: bool) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| {
            let mut d = (x - y).abs();
            if toroidal {
                d = d.min(1.0 - d);
            }
            d * d
        })
        .sum()
}

/// The points' indices sorted by first coordinate.
fn order(points: Points) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..points.len()).collect();
    idx.sort_by(|&a, &b| points.point(a)[0].total_cmp(&points.point(b)[0]));
    idx
}

/// The smallest Euclidean distance between two of the points (the formula in the
/// [module docs](self)); with `toroidal`, each coordinate difference wraps around
/// (`min(|a - b|, 1 - |a - b|)`), so 0.05 and 0.95 are 0.1 apart. `f64::INFINITY` for a
/// single point; 0 for repeated points.
///
/// Cost: a sort and a sweep in first-coordinate order (on the torus, cyclically forward,
/// which finds every pair closer than the current best from one of its ends): about
/// `O(N log N + N^(2 - 1/d) d)` for spread-out sets, `O(N^2 d)` at worst. Memory `8 N`
/// bytes.
///
/// ```
/// use qmckit::analysis::{Points, distance::min_distance};
/// // The 4 x 4 grid of cell centres: 1/4 apart, in the cube and on the torus.
/// let grid: Vec<f64> = (0..16).flat_map(|i| [(i % 4) as f64 / 4.0 + 0.125,
///                                            (i / 4) as f64 / 4.0 + 0.125]).collect();
/// assert_eq!(min_distance(Points::new(&grid, 2)?, false), 0.25);
/// assert_eq!(min_distance(Points::new(&grid, 2)?, true), 0.25);
/// let line = [0.05, 0.95];
/// assert!((min_distance(Points::new(&line, 1)?, true) - 0.1).abs() < 1e-15);
/// assert!((min_distance(Points::new(&line, 1)?, false) - 0.9).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn min_distance(points: Points, toroidal: bool) -> f64 {
    let n = points.len();
    let idx = order(points);
    let mut best2 = f64::INFINITY;
    for (pos, &i) in idx.iter().enumerate() {
        let a = points.point(i);
        let a0 = a[0];
        for step in 1..n {
            let k = idx[(pos + step) % n];
            if !toroidal && pos + step >= n {
                break;
            }
            let b = points.point(k);
            let mut gap = b[0] - a0;
            if gap < 0.0 {
                gap += 1.0; // wrapped past 1 (toroidal only)
            }
            if gap * gap >= best2 {
                break;
            }
            best2 = best2.min(dist2(a, b, toroidal));
        }
    }
    best2.sqrt()
}

/// Each point's distance to its nearest other point (cube or torus, as in
/// [`min_distance`]); `f64::INFINITY` for a single point. Parallel over the points (rayon).
///
/// Cost: in 2D, a uniform grid of about `N` cells searched ring by ring around each point,
/// `O(N)` for spread-out sets. Otherwise, for each point, a sweep both ways in
/// first-coordinate order until the first coordinate alone is farther than its nearest
/// neighbour so far: about `O(N log N + N^(2 - 1/d) d)` for spread-out sets. `O(N^2 d)` at
/// worst (clustered points).
///
/// ```
/// use qmckit::analysis::{Points, distance::nearest_neighbor_distances};
/// let p = [0.1, 0.2, 0.6];
/// let d = nearest_neighbor_distances(Points::new(&p, 1)?, false);
/// assert!((d[0] - 0.1).abs() < 1e-15 && (d[1] - 0.1).abs() < 1e-15);
/// assert!((d[2] - 0.4).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn nearest_neighbor_distances(points: Points, toroidal: bool) -> Vec<f64> {
    use rayon::prelude::*;
    if points.dims() == 2 {
        return nearest_neighbor_grid_2d(points, toroidal);
    }
    let n = points.len();
    let idx = order(points);
    let mut out = vec![f64::INFINITY; n];
    let found: Vec<(usize, f64)> = (0..n)
        .into_par_iter()
        .map(|pos| {
            let i = idx[pos];
            let a = points.point(i);
            let mut best2 = f64::INFINITY;
            // Forward, then backward; on the torus each direction wraps, and together they
            // visit every other point at most twice.
            for forward in [true, false] {
                for step in 1..n {
                    let (q, wrapped) = if forward {
                        (pos + step, pos + step >= n)
                    } else {
                        (pos + n - step, step > pos)
                    };
                    if wrapped && !toroidal {
                        break;
                    }
                    let b = points.point(idx[q % n]);
                    let mut gap = (b[0] - a[0]).abs();
                    if wrapped {
                        gap = 1.0 - gap;
                    }
                    if gap * gap >= best2 {
                        break;
                    }
                    best2 = best2.min(dist2(a, b, toroidal));
                }
            }
            (i, best2.sqrt())
        })
        .collect();
    for (i, d) in found {
        out[i] = d;
    }
    out
}

/// [`nearest_neighbor_distances`] in 2D: a uniform grid of `g x g` cells, `g = ceil(sqrt N)`
/// (about one point a cell), and for each point a search by square rings of cells around
/// its own, stopping after ring `r` once `r / g` (a lower bound on the distance to any point
/// in ring `r + 1`) reaches the nearest distance found; on the torus the rings wrap. `O(N)`
/// for spread-out sets; memory `8 (N + g^2)` bytes.
fn nearest_neighbor_grid_2d(points: Points, toroidal: bool) -> Vec<f64> {
    use rayon::prelude::*;
    let n = points.len();
    let g = ((n as f64).sqrt().ceil() as usize).max(1);
    let h = 1.0 / g as f64;
    let cell = |x: f64| ((x * g as f64) as usize).min(g - 1);
    let cell_of = |i: usize| {
        let p = points.point(i);
        (cell(p[0]), cell(p[1]))
    };
    // Counting sort of the points by cell (row-major in (cx, cy)).
    let mut start = vec![0usize; g * g + 1];
    for i in 0..n {
        let (cx, cy) = cell_of(i);
        start[cx * g + cy + 1] += 1;
    }
    for c in 0..g * g {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut sorted = vec![0usize; n];
    for i in 0..n {
        let (cx, cy) = cell_of(i);
        let slot = &mut fill[cx * g + cy];
        sorted[*slot] = i;
        *slot += 1;
    }
    let g_i = g as isize;
    (0..n)
        .into_par_iter()
        .map(|i| {
            let a = points.point(i);
            let (cx, cy) = cell_of(i);
            let mut best2 = f64::INFINITY;
            let mut r = 0isize;
            loop {
                for dx in -r..=r {
                    for dy in -r..=r {
                        if dx.abs().max(dy.abs()) != r {
                            continue;
                        }
                        let (mut x, mut y) = (cx as isize + dx, cy as isize + dy);
                        if toroidal {
                            x = x.rem_euclid(g_i);
                            y = y.rem_euclid(g_i);
                        } else if x < 0 || y < 0 || x >= g_i || y >= g_i {
                            continue;
                        }
                        let c = x as usize * g + y as usize;
                        for &k in &sorted[start[c]..start[c + 1]] {
                            if k != i {
                                best2 = best2.min(dist2(a, points.point(k), toroidal));
                            }
                        }
                    }
                }
                let bound = r as f64 * h;
                let covered = if toroidal { 2 * r + 1 >= g_i } else { r >= g_i };
                if covered || bound * bound >= best2 {
                    break;
                }
                r += 1;
            }
            best2.sqrt()
        })
        .collect()
}

/// The mean over the points of the distance to the nearest other point (see
/// [`nearest_neighbor_distances`]); `f64::INFINITY` for a single point.
///
/// ```
/// use qmckit::analysis::{Points, distance::mean_min_distance};
/// let p = [0.1, 0.2, 0.6];
/// assert!((mean_min_distance(Points::new(&p, 1)?, false) - 0.2).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn mean_min_distance(points: Points, toroidal: bool) -> f64 {
    let d = nearest_neighbor_distances(points, toroidal);
    d.iter().sum::<f64>() / d.len() as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute(points: Points, toroidal: bool) -> (f64, Vec<f64>) {
        let n = points.len();
        let mut nn = vec![f64::INFINITY; n];
        for (i, slot) in nn.iter_mut().enumerate() {
            for k in 0..n {
                if i != k {
                    let d = dist2(points.point(i), points.point(k), toroidal).sqrt();
                    *slot = slot.min(d);
                }
            }
        }
        (nn.iter().copied().fold(f64::INFINITY, f64::min), nn)
    }

    /// `n` seeded independent coordinates in [0, 1) (the crate's hash-based sampler).
    fn uniform(n: usize, seed: u64) -> Vec<f64> {
        let ind = crate::Independent::new(1, seed).expect("one dimension");
        let mut raw = vec![0u32; n];
        crate::Sampler::fill(&ind, 0, &mut raw).expect("in range");
        Points::from_u32(&raw)
    }

    #[test]
    fn matches_brute_force() {
        for dims in 1..=4 {
            for (n, seed) in [(2, 1), (3, 2), (50, 3), (300, 4), (1500, 5)] {
                let data = uniform(n * dims, seed * 10 + dims as u64);
                let p = Points::new(&data, dims).unwrap();
                for toroidal in [false, true] {
                    let (want, nn) = brute(p, toroidal);
                    assert_eq!(min_distance(p, toroidal), want, "d {dims} n {n} {toroidal}");
                    assert_eq!(nearest_neighbor_distances(p, toroidal), nn);
                }
            }
        }
    }

    #[test]
    fn lattice_on_cell_boundaries_and_the_closed_edge() {
        // 33 x 33 points j / 32 (including 1.0): every nearest neighbour is 1/32 away in the
        // cube; on the torus 1.0 and 0.0 coincide.
        let data: Vec<f64> = (0..33 * 33)
            .flat_map(|i| [(i % 33) as f64 / 32.0, (i / 33) as f64 / 32.0])
            .collect();
        let p = Points::new(&data, 2).unwrap();
        let nn = nearest_neighbor_distances(p, false);
        assert!(nn.iter().all(|&d| d == 1.0 / 32.0));
        assert_eq!(min_distance(p, false), 1.0 / 32.0);
        let (want, nn_t) = brute(p, true);
        assert_eq!(want, 0.0);
        assert_eq!(nearest_neighbor_distances(p, true), nn_t);
        assert_eq!(min_distance(p, true), 0.0);
    }

    #[test]
    fn single_point_and_duplicates() {
        let one = [0.3, 0.3];
        let p = Points::new(&one, 2).unwrap();
        assert_eq!(min_distance(p, true), f64::INFINITY);
        assert_eq!(nearest_neighbor_distances(p, false), vec![f64::INFINITY]);
        let dup = [0.3, 0.7, 0.3, 0.7, 0.9, 0.1];
        assert_eq!(min_distance(Points::new(&dup, 2).unwrap(), false), 0.0);
    }

    #[test]
    fn torus_wraps_every_coordinate() {
        // (0.02, 0.5) and (0.98, 0.52): 0.04 and 0.02 apart on the torus.
        let p = [0.02, 0.5, 0.98, 0.52, 0.5, 0.0];
        let d = min_distance(Points::new(&p, 2).unwrap(), true);
        assert!((d - (0.04f64.powi(2) + 0.02f64.powi(2)).sqrt()).abs() < 1e-12);
        // (0.5, 0.0) and (0.5, 1.0): the same point on the torus.
        let q = [0.5, 0.0, 0.5, 1.0, 0.1, 0.5];
        assert_eq!(min_distance(Points::new(&q, 2).unwrap(), true), 0.0);
        // In the cube: (0.5, 0) to (0.1, 0.5) is sqrt(0.16 + 0.25).
        assert_eq!(
            min_distance(Points::new(&q, 2).unwrap(), false),
            0.41f64.sqrt()
        );
    }
}
