//! The exact 2D sweep of [`super::star_2d`]: the critical grid column by column.

use crate::Result;
use crate::analysis::Points;
use crate::work::Stop;
use rayon::prelude::*;

/// The 2D sweep of [`super::star_2d`] without the size check; every column checks `stop`
/// (one clock reading per `O(N)` column).
///
/// # Errors
/// [`crate::Error::OutOfTime`] once `stop`'s deadline passes.
pub(super) fn sweep_2d(points: Points<'_>, stop: &Stop) -> Result<f64> {
    let pts: Vec<(f64, f64)> = counted(points).map(|p| (p[0], p[1])).collect();
    let n = points.len() as f64;
    let v = kernel_2d(&pts, &pts, 1.0, n, stop) / n;
    stop.finish(v)
}

/// Points counted by some anchored box: those with every coordinate below 1.
pub(super) fn counted<'a>(points: Points<'a>) -> impl Iterator<Item = &'a [f64]> + 'a {
    points.iter().filter(|p| p.iter().all(|&x| x < 1.0))
}

/// Sorted distinct values of `values` followed by 1 (if not already last).
pub(super) fn grid(values: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut g: Vec<f64> = values.collect();
    g.push(1.0);
    g.sort_unstable_by(f64::total_cmp);
    g.dedup();
    g
}

/// Index of `v` in the sorted, deduplicated `grid` (`v` must be in it).
pub(super) fn rank(grid: &[f64], v: f64) -> usize {
    grid.partition_point(|&g| g < v)
}

/// The 2D sweep behind [`super::star_2d`] and [`super::star_exact`]: the maximum over the critical grid
/// `(a, b)` of `c a b N - open(a, b)` and `closed(a, b) - c a b N`, where `open` counts the
/// points of `open_pts` with `x < a, y < b` and `closed` those of `closed_pts` with
/// `x <= a, y <= b`. `open_pts` must be a subset of `closed_pts`, all coordinates below 1.
/// Returns the value scaled by `N` (`n`); 0 at least (the empty box).
fn kernel_2d(
    open_pts: &[(f64, f64)],
    closed_pts: &[(f64, f64)],
    c: f64,
    n: f64,
    stop: &Stop,
) -> f64 {
    let xs = grid(closed_pts.iter().map(|p| p.0));
    let ys = grid(closed_pts.iter().map(|p| p.1));
    // (x, y-rank), sorted by x.
    let ranked = |pts: &[(f64, f64)]| {
        let mut v: Vec<(f64, usize)> = pts.iter().map(|p| (p.0, rank(&ys, p.1))).collect();
        v.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        v
    };
    let open = ranked(open_pts);
    let closed = ranked(closed_pts);
    let columns = xs.len();
    let work = columns * ys.len();
    let chunks = if work > 1 << 22 {
        (rayon::current_num_threads() * 4).min(columns)
    } else {
        1
    };
    let per = columns.div_ceil(chunks);
    (0..chunks)
        .into_par_iter()
        .map(|k| {
            let cols = xs.get(k * per..((k + 1) * per).min(columns)).unwrap_or(&[]);
            sweep_columns(cols, &ys, &open, &closed, c * n, stop)
        })
        .reduce(|| 0.0, f64::max)
}

/// Sweeps the critical columns `cols` (ascending) of [`kernel_2d`]; `cn = c N`.
fn sweep_columns(
    cols: &[f64],
    ys: &[f64],
    open: &[(f64, usize)],
    closed: &[(f64, usize)],
    cn: f64,
    stop: &Stop,
) -> f64 {
    let Some(&first) = cols.first() else {
        return 0.0;
    };
    // counts[r] = [open points with x < a, closed points with x <= a] at y-rank r.
    let mut counts = vec![[0.0f64; 2]; ys.len()];
    let mut io = open.partition_point(|p| p.0 < first);
    let mut ic = closed.partition_point(|p| p.0 < first);
    for p in open.get(..io).unwrap_or(&[]) {
        if let Some(c) = counts.get_mut(p.1) {
            c[0] += 1.0;
        }
    }
    for p in closed.get(..ic).unwrap_or(&[]) {
        if let Some(c) = counts.get_mut(p.1) {
            c[1] += 1.0;
        }
    }
    let mut best = 0.0f64;
    for &a in cols {
        if stop.check() {
            return best;
        }
        // Open points strictly left of a are already in; add closed points with x == a.
        while let Some(p) = open.get(io).filter(|p| p.0 < a) {
            if let Some(c) = counts.get_mut(p.1) {
                c[0] += 1.0;
            }
            io += 1;
        }
        while let Some(p) = closed.get(ic).filter(|p| p.0 <= a) {
            if let Some(c) = counts.get_mut(p.1) {
                c[1] += 1.0;
            }
            ic += 1;
        }
        let can = cn * a;
        let (mut run_o, mut run_c) = (0.0f64, 0.0f64);
        let (mut best_o, mut best_c) = (0.0f64, 0.0f64);
        for (&b, cnt) in ys.iter().zip(&counts) {
            let v = can * b;
            let o = v - run_o;
            if o > best_o {
                best_o = o;
            }
            run_o += cnt[0];
            run_c += cnt[1];
            let cl = run_c - v;
            if cl > best_c {
                best_c = cl;
            }
        }
        best = best.max(best_o).max(best_c);
    }
    best
}
