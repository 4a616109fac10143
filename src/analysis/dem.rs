//! Exact star discrepancy in `d` dimensions by the cell decomposition of Dobkin, Eppstein &
//! Mitchell (1996), "Computing the discrepancy with applications to supersampling patterns",
//! ACM Trans. Graphics 15(4), in the practical form described by Doerr, Gnewuch & Wahlström
//! (2014), "Calculation of discrepancy measures and applications", §3.2.
//!
//! # The problem on integer ranks
//!
//! Coordinate `k` of the points counted by some box (those with every coordinate below 1,
//! see [`super::star`]) takes `M_k - 1` distinct values `g_k[0] < ... < g_k[M_k - 2]`, and
//! `g_k[M_k - 1] = 1`. A point has *level* `p_k = rank(x_k) + 1` in `1 ..= M_k - 1`, and for a
//! lattice vector `t` (`0 <= t_k <= M_k`)
//!
//! ```text
//! F(t) = #{ i : p_ik <= t_k for every k }.
//! ```
//!
//! The half-open box at the grid corner `y_k = g_k[j_k]` holds `F(j)` points and the closed
//! one `F(j + 1)`, so
//!
//! ```text
//! N D*_N = max over t of max( N prod_k A_k(t_k) - F(t),  F(t) - N prod_k B_k(t_k) ),
//! A_k(t) = g_k[min(t, M_k - 1)],   B_k(t) = g_k[t - 1] (B_k(0) = 0).
//! ```
//!
//! (`t_k = M_k` repeats `t_k = M_k - 1` in the first term, since no level is `M_k`; `t_k = 0`
//! gives the value 0 in the second.)
//!
//! # Cells
//!
//! A *cell* is a box `[lo_k, hi_k]` of lattice vectors. A point is *below* it in coordinate
//! `k` when `p_k <= lo_k`, *stabs* it when `lo_k < p_k <= hi_k`, and misses every box of the
//! cell when `p_k > hi_k` somewhere. The lattice is cut coordinate by coordinate so that in
//! every final cell each point is below in all coordinates (counted everywhere: `R` points),
//! misses the cell, or stabs it in **exactly one** coordinate (a *slab* point). Then
//! `F(t) = R + sum_k c_k(t_k)`, where `c_k` counts the slab points of coordinate `k` up to
//! `t_k`: the coordinates separate. For each count `c` of coordinate `k` the largest `t_k`
//! with `c_k(t_k) <= c` and the smallest with `c_k(t_k) >= c` are read off the sorted slab
//! levels, and a knapsack over the coordinates gives the largest and the smallest volume
//! for each total count (Wahlström's formulation); the maximum over counts is the cell's
//! value, exact.
//!
//! The cuts: in coordinate `k < d - 1` every level `p_k` of a point that already stabs in an
//! earlier coordinate is a cut (so it cannot stab twice), and the points still below in all
//! earlier coordinates get a cut every `s = ceil(sqrt(N))` of them (they become the new slab
//! points of coordinate `k`). The last coordinate is cut only at the levels of earlier slab
//! points: the points below in all other coordinates then stab it in one long slab, which
//! costs only linear time in the final combination (the "one-dimensional" last step). With
//! `O(sqrt N)` slab points per coordinate and cell, this gives `O(N^((d-1)/2))` nodes over
//! the first `d - 1` coordinates, each costing `O(N^(3/2))`: `O(N^(1 + d/2))` in all, the
//! bound of Dobkin, Eppstein & Mitchell, with constants growing like `d!`. Cells whose
//! value cannot beat the best so far (bounded by `N vol(hi) - R` and `R + slab - N vol(lo)`)
//! are skipped; the top-level slabs run in parallel.

use super::Points;
use crate::{Error, Result};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// Exact star discrepancy `D*_N` of `points` (any `d >= 1`) by the Dobkin–Eppstein–Mitchell
/// decomposition (see the [module documentation](self)), including the open/closed
/// boundary cases of [`super::star`]: the maximum over the critical grid of
/// `max(vol - open/N, closed/N - vol)`, a point with a coordinate equal to 1 never counted.
///
/// Time `O(N^(1 + d/2))` (constants growing like `d!`, less with pruning), memory `O(N d)`
/// per thread. Measured on a shared 2-core machine: see [`super::star`]'s cost table.
///
/// # Errors
/// [`Error::TooManyPoints`] when [`work_estimate`] exceeds
/// [`super::star::STAR_WORK_BUDGET`]; `max` is the largest `N` within budget for this `d`.
///
/// ```
/// use qmckit::analysis::{Points, dem::star_dem};
/// // One point at the center of the cube: the closed box [0, 1/2]^3 holds it,
/// // 1 - 1/8 = 7/8.
/// assert_eq!(star_dem(Points::new(&[0.5, 0.5, 0.5], 3)?)?, 0.875);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn star_dem(points: Points<'_>) -> Result<f64> {
    let (n, d) = (points.len(), points.dims());
    if work_estimate(n, d) > super::star::STAR_WORK_BUDGET {
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max: max_points(d),
        });
    }
    Ok(dem_unchecked(points))
}

/// Estimated inner-loop steps of [`star_dem`] for `n` points in `d` dimensions, fitted to
/// measured run times on random and Sobol' points (the worse of the two):
/// `c_d N^(1 + d/2)`.
pub fn work_estimate(n: usize, d: usize) -> f64 {
    let c = match d {
        0..=2 => 1.0,
        3 => 1e-6,
        4 => 1e-6,
        5 => 1e-6,
        6 => 1e-6,
        _ => (1..d).map(|k| k as f64).product::<f64>() / 20.0,
    };
    c * (n as f64).powf(1.0 + d as f64 / 2.0)
}

/// Largest `N` whose [`work_estimate`] is within [`super::star::STAR_WORK_BUDGET`].
pub fn max_points(d: usize) -> u64 {
    let (mut lo, mut hi) = (1u64, 1u64 << 40);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if work_estimate(mid as usize, d) <= super::star::STAR_WORK_BUDGET {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    lo
}

/// [`star_dem`] without the work check.
pub(crate) fn dem_unchecked(points: Points<'_>) -> f64 {
    let d = points.dims();
    let n = points.len() as f64;
    let counted: Vec<&[f64]> = points
        .iter()
        .filter(|p| p.iter().all(|&x| x < 1.0))
        .collect();
    // Grids: sorted distinct counted coordinates, then 1.
    let grids: Vec<Vec<f64>> = (0..d)
        .map(|k| {
            let mut g: Vec<f64> = counted.iter().map(|p| p[k]).collect();
            g.push(1.0);
            g.sort_unstable_by(f64::total_cmp);
            g.dedup();
            g
        })
        .collect();
    let mut levels = Vec::with_capacity(counted.len() * d);
    for p in &counted {
        for (k, &x) in p.iter().enumerate() {
            levels.push(grids[k].partition_point(|&g| g < x) as u32 + 1);
        }
    }
    let best = AtomicU64::new(0);
    let ctx = Ctx {
        d,
        n,
        levels: &levels,
        grids: &grids,
        step: (n.sqrt().ceil() as usize).max(1),
        best: &best,
    };
    let rem: Vec<u32> = (0..counted.len() as u32).collect();
    if d == 1 {
        ctx.last(&[], &[], &rem, &[]);
    } else {
        ctx.split(0, &[], &[], 1.0, &rem, &[]);
    }
    f64::from_bits(best.load(Ordering::Relaxed)) / n
}

/// Shared state of one run.
struct Ctx<'a> {
    d: usize,
    /// `N`, all points.
    n: f64,
    /// Levels `p_ik`, row-major over the counted points.
    levels: &'a [u32],
    grids: &'a [Vec<f64>],
    /// Points below in all earlier coordinates per slab of a cut.
    step: usize,
    /// Best value so far, scaled by `N`, as `f64` bits (non-negative, so ordered as `u64`).
    best: &'a AtomicU64,
}

impl Ctx<'_> {
    fn level(&self, i: u32, k: usize) -> u32 {
        self.levels[i as usize * self.d + k]
    }

    /// `A_k(t)`: the upper corner of the half-open box.
    fn a(&self, k: usize, t: u32) -> f64 {
        let g = &self.grids[k];
        g[(t as usize).min(g.len() - 1)]
    }

    /// `B_k(t)`: the upper corner of the closed box (0 for `t = 0`).
    fn b(&self, k: usize, t: u32) -> f64 {
        if t == 0 {
            0.0
        } else {
            self.grids[k][t as usize - 1]
        }
    }

    fn best(&self) -> f64 {
        f64::from_bits(self.best.load(Ordering::Relaxed))
    }

    fn offer(&self, v: f64) {
        if v > 0.0 {
            self.best.fetch_max(v.to_bits(), Ordering::Relaxed);
        }
    }

    /// Cuts coordinate `k < d - 1`. `lo`, `hi` bound coordinates `0..k`; `vol_hi` is
    /// `prod A_j(hi_j)` over them; `rem` are the points below in all of them, `forced` the
    /// slab points with their slab coordinate.
    fn split(
        &self,
        k: usize,
        lo: &[u32],
        hi: &[u32],
        vol_hi: f64,
        rem: &[u32],
        forced: &[(u32, u8)],
    ) {
        if k + 1 >= self.d {
            self.last(lo, hi, rem, forced);
            return;
        }
        let mut r = rem.to_vec();
        r.sort_unstable_by_key(|&i| self.level(i, k));
        let mut f = forced.to_vec();
        f.sort_unstable_by_key(|&(i, _)| self.level(i, k));
        let mut starts: Vec<u32> = Vec::with_capacity(f.len() + r.len() / self.step + 1);
        starts.push(0);
        starts.extend(f.iter().map(|&(i, _)| self.level(i, k)));
        starts.extend(r.iter().skip(self.step).step_by(self.step).map(|&i| self.level(i, k)));
        starts.sort_unstable();
        starts.dedup();
        let top = self.grids[k].len() as u32;
        let child = |idx: usize| {
            let lo_k = starts[idx];
            let hi_k = starts.get(idx + 1).map_or(top, |&s| s - 1);
            let below = r.partition_point(|&i| self.level(i, k) <= lo_k);
            let inside = r.partition_point(|&i| self.level(i, k) <= hi_k);
            let kept = f.partition_point(|&(i, _)| self.level(i, k) <= lo_k);
            let vh = vol_hi * self.a(k, hi_k);
            let best = self.best();
            if self.n * vh <= best && (inside + kept) as f64 <= best {
                return;
            }
            let mut nf = Vec::with_capacity(kept + inside - below);
            nf.extend_from_slice(&f[..kept]);
            nf.extend(r[below..inside].iter().map(|&i| (i, k as u8)));
            let mut lo2 = lo.to_vec();
            lo2.push(lo_k);
            let mut hi2 = hi.to_vec();
            hi2.push(hi_k);
            self.split(k + 1, &lo2, &hi2, vh, &r[..below], &nf);
        };
        if k == 0 {
            (0..starts.len()).into_par_iter().for_each(child);
        } else {
            (0..starts.len()).for_each(child);
        }
    }

    /// The last coordinate `L = d - 1`: cut only at the slab points' levels, then evaluate
    /// every cell exactly.
    fn last(&self, lo: &[u32], hi: &[u32], rem: &[u32], forced: &[(u32, u8)]) {
        let l = self.d - 1;
        let mut r: Vec<u32> = rem.iter().map(|&i| self.level(i, l)).collect();
        r.sort_unstable();
        let mut f = forced.to_vec();
        f.sort_unstable_by_key(|&(i, _)| self.level(i, l));
        let top = self.grids[l].len() as u32;
        // Constant factors of the coordinates without slab points are folded in as they go.
        let vol_hi: f64 = (0..l).map(|j| self.a(j, hi[j])).product();
        let vol_lo: f64 = (0..l).map(|j| self.b(j, lo[j])).product();
        let mut active: Vec<Vec<u32>> = vec![Vec::new(); l];
        let mut n_active = 0usize;
        let mut fi = 0usize;
        let mut scratch = Scratch::default();
        let mut lo_l = 0u32;
        loop {
            // Activate the slab points whose last level is at most lo_l (= lo_l exactly).
            while let Some(&(i, j)) = f.get(fi) {
                if self.level(i, l) > lo_l {
                    break;
                }
                let v = self.level(i, j as usize);
                let list = &mut active[j as usize];
                let at = list.partition_point(|&x| x <= v);
                list.insert(at, v);
                n_active += 1;
                fi += 1;
            }
            let hi_l = f.get(fi).map_or(top, |&(i, _)| self.level(i, l) - 1);
            let below = r.partition_point(|&x| x <= lo_l);
            let inside = r.partition_point(|&x| x <= hi_l);
            let rr = below as f64;
            let best = self.best();
            let open_bound = self.n * vol_hi * self.a(l, hi_l) - rr;
            let closed_bound = (inside + n_active) as f64 - self.n * vol_lo * self.b(l, lo_l);
            if open_bound > best || closed_bound > best {
                let v = self.cell(
                    lo,
                    hi,
                    &active,
                    (lo_l, hi_l),
                    &r[below..inside],
                    rr,
                    &mut scratch,
                );
                self.offer(v);
            }
            if hi_l >= top {
                break;
            }
            lo_l = hi_l + 1;
        }
    }

    /// Exact value (scaled by `N`) of the cell with bounds `lo`, `hi` (coordinates `0..L`)
    /// and `last` (coordinate `L`), slab levels `active[j]` (sorted) of coordinate `j < L`,
    /// `slab` (sorted) of coordinate `L`, and `rr` points below everywhere.
    #[allow(clippy::too_many_arguments)]
    fn cell(
        &self,
        lo: &[u32],
        hi: &[u32],
        active: &[Vec<u32>],
        last: (u32, u32),
        slab: &[u32],
        rr: f64,
        s: &mut Scratch,
    ) -> f64 {
        let l = self.d - 1;
        // Knapsack over coordinates 0..L: big[c] (small[c]) = largest (smallest) product of
        // A (B) factors with total slab count c.
        s.big.clear();
        s.big.push(1.0);
        s.small.clear();
        s.small.push(1.0);
        let (mut fa, mut fb) = (1.0f64, 1.0f64);
        for j in 0..l {
            let list = &active[j];
            if list.is_empty() {
                fa *= self.a(j, hi[j]);
                fb *= self.b(j, lo[j]);
                continue;
            }
            fill_coordinate(self, j, lo[j], hi[j], list, &mut s.bj, &mut s.sj);
            convolve(&s.big, &s.bj, &mut s.tmp, f64::max, 0.0);
            std::mem::swap(&mut s.big, &mut s.tmp);
            convolve(&s.small, &s.sj, &mut s.tmp, f64::min, f64::INFINITY);
            std::mem::swap(&mut s.small, &mut s.tmp);
        }
        fill_coordinate(self, l, last.0, last.1, slab, &mut s.bj, &mut s.sj);
        let (na, nb) = (self.n * fa, self.n * fb);
        let mut best = 0.0f64;
        for (a, (&bg, &sm)) in s.big.iter().zip(&s.small).enumerate() {
            let (x, y) = (na * bg, nb * sm);
            let mut count = rr + a as f64;
            for (&bl, &sl) in s.bj.iter().zip(&s.sj) {
                let open = x * bl - count;
                let closed = count - y * sl;
                best = best.max(open).max(closed);
                count += 1.0;
            }
        }
        best
    }
}

/// Per-coordinate tables of a cell: for `c = 0..=m` slab points counted, `big[c] = A(t)` at
/// the largest `t` in `[lo, hi]` counting at most `c` of them and `small[c] = B(t)` at the
/// smallest `t` counting at least `c`.
fn fill_coordinate(
    ctx: &Ctx<'_>,
    k: usize,
    lo: u32,
    hi: u32,
    list: &[u32],
    big: &mut Vec<f64>,
    small: &mut Vec<f64>,
) {
    big.clear();
    small.clear();
    small.push(ctx.b(k, lo));
    for &v in list {
        big.push(ctx.a(k, v - 1));
        small.push(ctx.b(k, v));
    }
    big.push(ctx.a(k, hi));
}

/// `out[a + b] = op over a, b of x[a] * y[b]`, starting from `init`.
fn convolve(x: &[f64], y: &[f64], out: &mut Vec<f64>, op: fn(f64, f64) -> f64, init: f64) {
    out.clear();
    out.resize(x.len() + y.len() - 1, init);
    for (a, &xa) in x.iter().enumerate() {
        for (o, &yb) in out[a..].iter_mut().zip(y) {
            *o = op(*o, xa * yb);
        }
    }
}

/// Reused buffers of [`Ctx::cell`].
#[derive(Default)]
struct Scratch {
    big: Vec<f64>,
    small: Vec<f64>,
    tmp: Vec<f64>,
    bj: Vec<f64>,
    sj: Vec<f64>,
}
