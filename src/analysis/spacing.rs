//! The normalized minimum distance of a point set: its smallest pairwise distance over
//! the largest any `N` points can have, on the torus or in the cube, found through a
//! uniform grid.
//!
//! ## The normalization
//!
//! `N` points at mutual distance at least `r` are centres of disjoint balls of radius
//! `r / 2`; on the unit torus their density `N V_d (r/2)^d` is at most the packing density
//! `Delta_d` of `R^d`, so
//!
//! ```text
//! d_max(N, d) = 2 (Delta_d / (N V_d))^(1/d),      V_d = pi^(d/2) / Gamma(d/2 + 1)
//! ```
//!
//! (Lagae & Dutré 2008, "A comparison of methods for generating Poisson disk
//! distributions", whose relative radius is this ratio). `Delta_d` is the densest lattice
//! packing: `1`, `pi / sqrt(12)` (hexagonal, Thue; Fejes Tóth), `pi / sqrt(18)` (FCC, Hales
//! 2005), then `D_4`, `D_5`, `E_6`, `E_7`, `E_8`: `pi^2/16`, `pi^2/(15 sqrt 2)`,
//! `pi^3/(48 sqrt 3)`, `pi^3/105`, `pi^4/384` (Conway & Sloane, "Sphere Packings, Lattices
//! and Groups", table 1.2; optimal among all packings for `d <= 3` and `d = 8`). In 2D,
//! `d_max = sqrt(2 / (sqrt(3) N))`, reached by the hexagonal grid when it tiles the torus.
//! The same `d_max` normalizes the cube's distance (a set in the cube is a set on the
//! torus whose distances can only shrink, so the cube's ratio is also at most about 1).
//! Dimensions 1 to 8.
//!
//! ## The search
//!
//! A grid of `g^d` cells, `g = floor(N^(1/d))`: every pair in neighbouring cells (the
//! `3^d` around each point, wrapped on the torus) is compared. If the closest pair found
//! is within the cell width `1/g`, it is the closest pair (two points that close lie in
//! neighbouring cells); otherwise the true minimum exceeds `1/g` and the grid is coarsened
//! (`g` halved) and searched again; below `g = 3` every pair is compared. For spread sets
//! (about one point a cell) the cost is `O(N 3^d)` per grid, `O(N log N)` overall with the
//! counting sort; clustered sets (many points a cell) approach `O(N^2)`. Estimated before
//! and paced against a [`Budget`].

use super::Points;
use crate::work::{Budget, Cost, Limits, Rate};
use crate::{Error, Result};

/// Pair comparisons a second in `d <= 3`, one core, release (about 1e8 measured; lower
/// for loaded machines).
const PAIRS: Rate = Rate::per_second(3e7);

/// Pairs between two readings of the clock.
const PACE: u64 = 1 << 16;

/// The densest lattice packing densities `Delta_d`, `d = 1..=8`.
fn packing_density(d: usize) -> Option<f64> {
    use core::f64::consts::PI;
    Some(match d {
        1 => 1.0,
        2 => PI / 12f64.sqrt(),
        3 => PI / 18f64.sqrt(),
        4 => PI * PI / 16.0,
        5 => PI * PI / (15.0 * 2f64.sqrt()),
        6 => PI.powi(3) / (48.0 * 3f64.sqrt()),
        7 => PI.powi(3) / 105.0,
        8 => PI.powi(4) / 384.0,
        _ => return None,
    })
}

/// The volume of the unit ball of `R^d`, by `V_d = V_(d-2) 2 pi / d`.
fn ball_volume(d: usize) -> f64 {
    let mut v = if d.is_multiple_of(2) { 1.0 } else { 2.0 };
    let mut k = if d.is_multiple_of(2) { 2 } else { 3 };
    while k <= d {
        v *= 2.0 * core::f64::consts::PI / k as f64;
        k += 2;
    }
    v
}

/// `d_max(N, d)`, the largest minimum distance of `n` points of the `d`-torus allowed by
/// the packing bound (module documentation).
///
/// ```
/// use qmckit::analysis::spacing::packing_distance;
/// let d = packing_distance(100, 2)?;
/// assert!((d - (2.0 / (3f64.sqrt() * 100.0)).sqrt()).abs() < 1e-15);
/// assert_eq!(packing_distance(10, 1)?, 0.1);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::ZeroPoints`]; [`Error::Unsupported`] past 8 dimensions (or 0).
pub fn packing_distance(n: usize, d: usize) -> Result<f64> {
    if n == 0 {
        return Err(Error::ZeroPoints);
    }
    let delta = packing_density(d).ok_or(Error::Unsupported {
        what: "the normalized minimum distance is defined for 1 to 8 dimensions",
    })?;
    Ok(2.0 * (delta / (n as f64 * ball_volume(d))).powf(1.0 / d as f64))
}

/// The smallest distance between two of the points (cube or torus), by the grid search
/// of the module documentation; `f64::INFINITY` for one point.
///
/// ```
/// use qmckit::{analysis::{Points, spacing::min_distance}, work::Budget};
/// let p = [0.1, 0.1, 0.9, 0.9, 0.5, 0.45];
/// let b = Budget::DEFAULT;
/// assert!((min_distance(Points::new(&p, 2)?, true, &b)? - 0.2 * 2f64.sqrt()).abs() < 1e-15);
/// assert!((min_distance(Points::new(&p, 2)?, false, &b)? - 0.4f64.hypot(0.35)).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::OverBudget`] when even the first grid's estimate exceeds the budget,
/// [`Error::OutOfTime`], [`Error::TooLarge`].
pub fn min_distance<'a>(
    points: Points,
    toroidal: bool,
    limits: impl Into<Limits<'a>>,
) -> Result<f64> {
    let budget = limits.into().budget().started();
    let (n, d) = (points.len(), points.dims());
    if n < 2 {
        return Ok(f64::INFINITY);
    }
    let neighbours = 3f64.powi(d.min(64) as i32).min(n as f64);
    budget.check(
        "minimum distance",
        Cost::steps(n as f64 * neighbours, PAIRS),
    )?;
    let mut g = ((n as f64).powf(1.0 / d as f64).floor() as usize).max(1);
    // At most 2^20 cells.
    while (g as f64).powi(d.min(64) as i32) > (1u64 << 20) as f64 {
        g /= 2;
    }
    let mut pairs = 0u64;
    loop {
        if g < 3 {
            return brute(points, toroidal, &budget, &mut pairs);
        }
        let best = grid_pass(points, toroidal, g, &budget, &mut pairs)?;
        if best <= 1.0 / g as f64 {
            return Ok(best);
        }
        g /= 2;
    }
}

/// The minimum distance over [`packing_distance`]: 1 for a hexagonal grid tiling the
/// torus in 2D, near 0 for clustered points (about `0.1`-`0.3` for uniform random ones at
/// a few hundred points, as the minimum of `N^2/2` distances).
///
/// ```
/// use qmckit::{analysis::{Points, spacing::normalized_min_distance}, work::Budget};
/// // Two points at (1/4, 1/4) and (3/4, 3/4): 1/sqrt(2) apart on the torus, and
/// // d_max(2, 2) = sqrt(1 / sqrt(3)).
/// let p = [0.25, 0.25, 0.75, 0.75];
/// let r = normalized_min_distance(Points::new(&p, 2)?, true, &Budget::DEFAULT)?;
/// assert!((r - 0.5f64.sqrt() / (1.0 / 3f64.sqrt()).sqrt()).abs() < 1e-12);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// As [`min_distance`] and [`packing_distance`].
pub fn normalized_min_distance<'a>(
    points: Points,
    toroidal: bool,
    limits: impl Into<Limits<'a>>,
) -> Result<f64> {
    let dmax = packing_distance(points.len(), points.dims())?;
    Ok(min_distance(points, toroidal, limits)? / dmax)
}

fn dist2(a: &[f64], b: &[f64], toroidal: bool) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| {
            let t = (x - y).abs();
            let t = if toroidal { t.min(1.0 - t) } else { t };
            t * t
        })
        .sum()
}

fn pace(pairs: &mut u64, add: u64, budget: &Budget) -> Result<()> {
    let before = *pairs / PACE;
    *pairs += add;
    if *pairs / PACE != before {
        budget.check_deadline("minimum distance")?;
    }
    Ok(())
}

fn brute(points: Points, toroidal: bool, budget: &Budget, pairs: &mut u64) -> Result<f64> {
    let n = points.len();
    let mut best = f64::INFINITY;
    for i in 0..n {
        pace(pairs, (n - i) as u64, budget)?;
        let a = points.point(i);
        for k in i + 1..n {
            best = best.min(dist2(a, points.point(k), toroidal));
        }
    }
    Ok(best.sqrt())
}

/// The closest pair among neighbouring cells of the `g^d` grid (`g >= 3`).
fn grid_pass(
    points: Points,
    toroidal: bool,
    g: usize,
    budget: &Budget,
    pairs: &mut u64,
) -> Result<f64> {
    let (n, d) = (points.len(), points.dims());
    let cells = g.pow(d as u32);
    let cell_of = |p: &[f64]| -> usize {
        p.iter().rev().fold(0usize, |acc, &x| {
            acc * g + ((x * g as f64) as usize).min(g - 1)
        })
    };
    let mut start = crate::size::vec_zeroed::<usize>(cells + 1)?;
    let mut home = crate::size::vec_zeroed::<usize>(n)?;
    for (i, h) in home.iter_mut().enumerate() {
        *h = cell_of(points.point(i));
        if let Some(s) = start.get_mut(*h + 1) {
            *s += 1;
        }
    }
    for c in 0..cells {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut sorted = crate::size::vec_zeroed::<usize>(n)?;
    for (i, &h) in home.iter().enumerate() {
        if let Some(f) = fill.get_mut(h) {
            if let Some(s) = sorted.get_mut(*f) {
                *s = i;
            }
            *f += 1;
        }
    }
    let mut coord = vec![0usize; d];
    let mut best = f64::INFINITY;
    let offsets = 3usize.pow(d as u32);
    for (i, &h) in home.iter().enumerate() {
        let a = points.point(i);
        let mut c = h;
        for k in coord.iter_mut() {
            *k = c % g;
            c /= g;
        }
        'offset: for o in 0..offsets {
            let (mut cell, mut scale, mut rest) = (0usize, 1usize, o);
            for &k in coord.iter() {
                let step = rest % 3; // 0, 1, 2 for -1, 0, +1
                rest /= 3;
                let j = k + step;
                let j = if j == 0 {
                    if !toroidal {
                        continue 'offset;
                    }
                    g - 1
                } else if j > g {
                    if !toroidal {
                        continue 'offset;
                    }
                    0
                } else {
                    j - 1
                };
                cell += j * scale;
                scale *= g;
            }
            let members = sorted.get(start[cell]..start[cell + 1]).unwrap_or(&[]);
            pace(pairs, members.len() as u64, budget)?;
            for &k in members {
                if k > i {
                    best = best.min(dist2(a, points.point(k), toroidal));
                }
            }
        }
    }
    Ok(best.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ball_volumes() {
        let pi = core::f64::consts::PI;
        for (d, v) in [(1, 2.0), (2, pi), (3, 4.0 * pi / 3.0), (4, pi * pi / 2.0)] {
            assert!((ball_volume(d) - v).abs() < 1e-14, "{d}");
        }
    }
}
