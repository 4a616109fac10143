//! The exact extreme (unanchored) discrepancy in 2D.

use super::sweep::{counted, grid, rank};
use crate::analysis::Points;
use crate::work::Stop;
use crate::work::{Limits, Rate};
use crate::{Error, Result};
use rayon::prelude::*;

/// Sweep steps per second of [`extreme_2d`] (`N^3 / 2` steps for `N` points): 1000 points,
/// `5e8` steps, took 2.7 s on two shared cores.
pub const EXTREME_RATE: Rate = Rate::per_second(1.7e8);

/// Exact extreme (unanchored) discrepancy in 2D:
/// `D_N = sup over boxes [a, b) in [0,1]^2 of |A([a, b))/N - vol([a, b))|`.
///
/// As for [`super::star_2d`], the supremum is a maximum over one-sided limits on the critical grid
/// (`a_k` in `{0} ∪ {x_ik}`, `b_k` in `{x_ik} ∪ {1}`): `vol - #(a < x < b)/N` for the open
/// box (limit of `[a + ε, b)`) and `#(a <= x <= b)/N - vol` for the closed box (limit of
/// `[a, b + ε)`, possibly degenerate), points with a coordinate 1 never counted. Always
/// `D*_N <= D_N <= 2^d D*_N` (here `4 D*_N`), and `D_N >= 1/N` (a degenerate box on a
/// point).
///
/// For each pair of critical `x` bounds (an `x`-slab, `O(N^2)` of them) one pass over the
/// `y` ranks finds the best `y`-interval as a maximum-difference scan. Cost `O(N^3)` time
/// (about `N^3 / 2` steps), `O(N)` memory per thread; parallel over the lower `x` bound.
/// Measured: `N = 500` in 0.4 s, `N = 1000` in 2.7 s (shared 2-core machine).
///
/// The budget of `limits` bounds it: `N^3 / 2` steps at [`EXTREME_RATE`], checked first
/// ([`Budget::DEFAULT`](crate::work::Budget::DEFAULT), ten seconds, admits `N <= 1503`).
///
/// # Errors
/// [`Error::Unsupported`] unless `points.dims() == 2`; [`Error::TooManyPoints`] past the
/// budget, `max` the largest `N` within it; [`Error::OutOfTime`] past the deadline of the
/// budget (started here if it was not), read once per `O(N)` slab.
///
/// ```
/// use qmckit::analysis::{Points, star::extreme_2d};
/// use qmckit::work::Budget;
/// // One point: the degenerate closed box on it holds it with volume 0, so D = 1.
/// assert_eq!(extreme_2d(Points::new(&[0.5, 0.5], 2)?, &Budget::DEFAULT)?, 1.0);
/// // Four points at the centers of the 2x2 cells: the open slab (1/4, 3/4) x (0, 1) misses
/// // them all (vol 1/2), and the closed [1/4, 3/4] x [1/4, 3/4] holds all with vol 1/4:
/// // 1 - 1/4 = 3/4 is the maximum.
/// let c = [0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75];
/// assert_eq!(extreme_2d(Points::new(&c, 2)?, &Budget::DEFAULT)?, 0.75);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn extreme_2d<'a>(points: Points<'_>, limits: impl Into<Limits<'a>>) -> Result<f64> {
    let limits = limits.into();
    let budget = limits.budget();
    if points.dims() != 2 {
        return Err(Error::Unsupported {
            what: "extreme_2d of points that are not 2-dimensional",
        });
    }
    let n = points.len();
    let steps = |n: f64| n * n * n / 2.0;
    if steps(n as f64) > budget.steps(EXTREME_RATE) {
        let max = (2.0 * budget.steps(EXTREME_RATE)).cbrt().floor();
        let mut max = max as u64;
        while max > 0 && steps(max as f64) > budget.steps(EXTREME_RATE) {
            max -= 1;
        }
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max,
        });
    }
    let pts: Vec<(f64, f64)> = counted(points).map(|p| (p[0], p[1])).collect();
    let xs = grid(pts.iter().map(|p| p.0).chain([0.0]));
    let ys = grid(pts.iter().map(|p| p.1).chain([0.0]));
    // groups[i] = y-ranks of the points with x = xs[i].
    let mut groups: Vec<Vec<usize>> = vec![Vec::new(); xs.len()];
    for p in &pts {
        if let Some(g) = groups.get_mut(rank(&xs, p.0)) {
            g.push(rank(&ys, p.1));
        }
    }
    let nf = n as f64;
    let stop = Stop::new(budget, "the extreme discrepancy");
    let best = (0..xs.len())
        .into_par_iter()
        .map(|i| extreme_from(i, &xs, &ys, &groups, nf, &stop))
        .reduce(|| 0.0, f64::max);
    stop.finish(best / nf)
}

/// [`extreme_2d`] for the slabs with lower `x` bound `xs[i]`; scaled by `N`.
fn extreme_from(
    i: usize,
    xs: &[f64],
    ys: &[f64],
    groups: &[Vec<usize>],
    n: f64,
    stop: &Stop,
) -> f64 {
    let m = ys.len();
    // interior[r]: points with xs[i] < x < xs[j] at y-rank r; edge[r]: those with x = xs[i]
    // or x = xs[j] (the closed slab adds them).
    let mut interior = vec![0.0f64; m];
    let mut edge = vec![0.0f64; m];
    let add = |v: &mut [f64], g: Option<&Vec<usize>>, w: f64| {
        for &r in g.into_iter().flatten() {
            if let Some(c) = v.get_mut(r) {
                *c += w;
            }
        }
    };
    add(&mut edge, groups.get(i), 1.0);
    let lo = xs.get(i).copied().unwrap_or(0.0);
    let mut best = 0.0f64;
    for (j, &hi) in xs.iter().enumerate().skip(i) {
        if stop.check() {
            return best;
        }
        if j > i {
            add(&mut edge, groups.get(j), 1.0);
        }
        let wn = (hi - lo) * n;
        // Open: max over r' < r of (wn y_r - #(y < y_r)) - (wn y_r' - #(y <= y_r')).
        // Closed: max over r' <= r of (#(y <= y_r) - wn y_r) - (#(y < y_r') - wn y_r').
        let (mut so, mut sc) = (0.0f64, 0.0f64); // open / closed counts below the rank
        let (mut min_o, mut min_c) = (f64::INFINITY, f64::INFINITY);
        for ((&y, &ci), &ce) in ys.iter().zip(&interior).zip(&edge) {
            let v = wn * y;
            if j > i && v - so - min_o > best {
                best = v - so - min_o;
            }
            min_c = min_c.min(sc - v);
            so += ci;
            sc += ci + ce;
            min_o = min_o.min(v - so);
            if sc - v - min_c > best {
                best = sc - v - min_c;
            }
        }
        if j > i {
            // Group j moves from the edge to the interior of the next slabs.
            add(&mut edge, groups.get(j), -1.0);
            add(&mut interior, groups.get(j), 1.0);
        }
    }
    best
}
