//! Exact star discrepancy in `d` dimensions by the cell decomposition of Dobkin, Eppstein &
//! Mitchell (1996), "Computing the discrepancy with applications to supersampling patterns",
//! ACM Trans. Graphics 15(4), in the practical form described by Doerr, Gnewuch & Wahlström
//! (2014), "Calculation of discrepancy measures and applications", §3.2.
//!
//! # The problem on integer ranks
//!
//! Coordinate `k` of the points counted by some box (those with every coordinate below 1,
//! see [`super`]) takes `M_k - 1` distinct values `g_k[0] < ... < g_k[M_k - 2]`, and
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
//! bound of Dobkin, Eppstein & Mitchell (the constant grows with `d`).
//!
//! # Pruning and the measured cost
//!
//! A cell is evaluated only if it can beat the best value so far, checked twice, for the
//! open and the closed half separately: first by `N vol(hi) - R` and `R + slab - N vol(lo)`,
//! then by bounds from the cell's per-coordinate tables (`open_slack` and `closed_slack`
//! below: the product of the volume ratios is bounded by a linear function of them, so each
//! coordinate's trade of volume against counted points is bounded on its own). Only then
//! are the knapsacks brought up to date. On 6D Sobol' points (`N` = 450) the second check
//! leaves 92701 of 77.9 million cells; the knapsacks did 9.5e9 multiply-compares before it,
//! 2.5e6 with it. The cost left is the walk over the cells, which grows a little more than
//! `sqrt N` slower than `N^(1 + d/2)` on the sizes measured (see [`work_estimate`]).
//!
//! The per-coordinate tables and the knapsack prefixes are updated incrementally along the
//! last coordinate, and the sorted lists of a cut are merged from the previous sibling's,
//! not re-sorted. The slabs of the first cut run in parallel (rayon), and from `d = 4` on
//! those of the second cut too. Timed task by task on one thread (6D), the heaviest slab of
//! the first cut takes 14% of the time at `N` = 450 and 12% at 800, the heaviest task of
//! the second cut 1.7% and 1.1%: the first cut alone would cap the speed-up near 8 whatever
//! the number of cores.
//!
//! Measured with the `time_dem` example (first `N` Sobol' points, two threads, load about
//! 1.5). 6D: `N` = 500 in 8.4 s, 600 in 17 s, 800 in 43 s, 1000 in 86 s, 2000 in 17 minutes
//! (1026 s); without the table bounds the time grows like `N^4` (1000 points: 285 s).
//! Other dimensions: `d = 3`: 40000 in 5.3 s; `d = 4`: 6000
//! in 10.5 s; `d = 5`: 1300 in 9.0 s; `d = 7`: 260 in 10.9 s; `d = 8`: 150 in 8.5 s;
//! `d = 10`: 70 in 8.2 s. [`work_estimate`] is fitted to the CPU time of one thread
//! (`examples/time_costs.rs`, 3 to 24 dimensions; the table in `docs/budgets.md`), and the
//! estimate assumes two cores; [`star_dem`] takes the budget (ten seconds for
//! `&Budget::DEFAULT`).

use super::cells::{
    SortedPrefix, closed_slack, convolve_max, convolve_min, merge_sorted, open_slack,
};
use super::cost::within;
pub use super::cost::{max_points, work_estimate};
use crate::analysis::Points;
use crate::work::Stop;
use crate::work::{Limits, Progress};
use crate::{Error, Result};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// The most dimensions the decomposition runs in for two or more counted points: its walk
/// nests one level per coordinate and a slab point records its coordinate in a byte, so
/// both stay bounded: a set with two or more counted points in more dimensions is
/// [`Error::TooLarge`]. A set with at most one counted point has a closed form (see
/// [`star_dem`]) and no dimension limit.
pub const DEM_MAX_DIMS: usize = 255;

/// Exact star discrepancy `D*_N` of `points` (any `d >= 1`) by the Dobkin–Eppstein–Mitchell
/// decomposition (see the [module documentation](self)), including the open/closed
/// boundary cases of [`super`]: the maximum over the critical grid of
/// `max(vol - open/N, closed/N - vol)`, a point with a coordinate equal to 1 never counted.
///
/// Time `O(N^(1 + d/2))` (less with pruning), memory `O(N d)` per thread; measured times in
/// the [module documentation](self). Results are within a few ulps of the exact value
/// (volumes are products of grid coordinates in `f64`), exact for dyadic sets with few bits.
///
/// The limits: the time budget (`&Budget::DEFAULT`, ten seconds, for the usual requests;
/// [`work_estimate`] steps at [`STAR_RATE`](super::STAR_RATE) on two cores, checked in
/// `O(1)` before anything is allocated) and a progress report:
/// `progress(done, PROGRESS_STEPS)` is called, from any thread, each time one of the slabs
/// of the first cut is finished (and once at the end with `done = PROGRESS_STEPS`). A slab
/// counts as its estimated share of the work (those with more points take longer): `done`
/// is a rough fraction of the time, not a count.
///
/// In more than [`DEM_MAX_DIMS`] dimensions a set with at most one counted point (every
/// coordinate below 1) is evaluated by its closed form: with no counted point the empty
/// open box `[0, 1)^d` gives `D*_N = 1`; with one, `x`,
/// `N D*_N = max(N - 1, N max_k x_k, 1 - N prod_k x_k)` (the whole cube holds it; a box
/// missing it has volume at most `max_k x_k`; the smallest closed box holding it is
/// `[0, x]`), in `O(N d)`.
///
/// # Errors
/// [`Error::TooManyPoints`] when [`work_estimate`] exceeds the budget (`max`: the largest
/// `N` within it, [`max_points`]); [`Error::TooLarge`] for two or more counted points
/// in more than [`DEM_MAX_DIMS`] dimensions; [`Error::OutOfTime`] past the deadline of
/// the budget (started here if it was not), checked before every evaluated cell and every
/// 256 pruned ones.
///
/// ```
/// use qmckit::work::{Budget, Limits};
/// use qmckit::analysis::{Points, star::dem::star_dem};
/// use std::sync::atomic::{AtomicUsize, Ordering};
/// // One point at the center of the cube: the closed box [0, 1/2]^3 holds it,
/// // 1 - 1/8 = 7/8.
/// assert_eq!(star_dem(Points::new(&[0.5, 0.5, 0.5], 3)?, &Budget::DEFAULT)?, 0.875);
/// let calls = AtomicUsize::new(0);
/// let p = Points::new(&[0.5, 0.5, 0.5, 0.25, 0.75, 0.125], 3)?;
/// let report = |_, _| {
///     calls.fetch_add(1, Ordering::Relaxed);
/// };
/// let d = star_dem(p, Limits::DEFAULT.with_progress(&report))?;
/// assert!(d >= 0.75 && calls.load(Ordering::Relaxed) >= 1);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn star_dem<'a>(points: Points<'_>, limits: impl Into<Limits<'a>>) -> Result<f64> {
    let limits = limits.into();
    let (budget, progress) = (limits.budget(), limits.progress());
    let (n, d) = (points.len(), points.dims());
    if !within(work_estimate(n, d), budget) {
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max: max_points(d, budget),
        });
    }
    if d > DEM_MAX_DIMS {
        let mut counted = points.iter().filter(|p| p.iter().all(|&x| x < 1.0));
        let first = counted.next();
        if counted.next().is_some() {
            return Err(Error::TooLarge {
                what: "dimensions for the exact star discrepancy of two or more points",
                requested: d as u64,
                max: DEM_MAX_DIMS as u64,
            });
        }
        progress(PROGRESS_STEPS, PROGRESS_STEPS);
        return Ok(single_point(first, n as f64));
    }
    let stop = Stop::new(budget, "the exact star discrepancy");
    let v = dem_from(points, progress, &stop);
    stop.finish(v)
}

/// `D*_N` of a set whose only counted point is `x` (or none), `N = n`: see
/// [`star_dem`].
fn single_point(x: Option<&[f64]>, n: f64) -> f64 {
    let Some(x) = x else {
        return 1.0;
    };
    let largest = x.iter().copied().fold(0.0, f64::max);
    let vol: f64 = x.iter().product();
    (n - 1.0).max(n * largest).max(1.0 - n * vol) / n
}

/// The `total` of [`star_dem`]'s progress reports.
pub const PROGRESS_STEPS: usize = 1000;

/// [`star_dem`] without the work check; the walk stops early (with a meaningless
/// value) once `stop` says so.
fn dem_from(points: Points<'_>, progress: Progress<'_>, stop: &Stop) -> f64 {
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
        stop,
    };
    ctx.run(counted.len() as u32, progress);
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
    /// The deadline: checked before each evaluated cell and every [`CELLS_PER_CHECK`]
    /// pruned ones.
    stop: &'a Stop,
}

/// Pruned cells (a few partition points each) between two deadline checks.
const CELLS_PER_CHECK: u32 = 256;

/// Buffers of one cut level, reused across the nodes of a depth-first walk.
#[derive(Default)]
struct Level {
    /// Points below in every earlier coordinate, sorted by this coordinate's level.
    rem: SortedPrefix<u32>,
    /// Slab points (point, slab coordinate), sorted by this coordinate's level.
    forced: Vec<(u32, u8)>,
    /// Lower ends of the slabs of this coordinate.
    starts: Vec<u32>,
    /// The slab points handed to the current child.
    child: Vec<(u32, u8)>,
}

/// Per-walk state below the cut levels: the current cell bounds and the buffers of
/// [`Ctx::last`] and [`Ctx::cell`].
struct Tail {
    lo: Vec<u32>,
    hi: Vec<u32>,
    /// Sorted slab levels of the active slab points, per coordinate `0..L`.
    active: Vec<Vec<u32>>,
    /// Their tables (see [`Ctx::tables`]), kept up to date as points are activated.
    tab_big: Vec<Vec<f64>>,
    tab_small: Vec<Vec<f64>>,
    /// `pre_big[j]`: the knapsack of the tables of coordinates `0..j`; valid up to
    /// `clean_big` (likewise for `small`).
    pre_big: Vec<Vec<f64>>,
    pre_small: Vec<Vec<f64>>,
    clean_big: usize,
    clean_small: usize,
    /// Sorted last-coordinate levels of the points below in all other coordinates.
    rem: SortedPrefix<u32>,
    /// The slab points the current node keeps from earlier cuts, sorted by last level.
    kept: SortedPrefix<(u32, u8)>,
    /// The slab points of the node, sorted by last level.
    forced: Vec<(u32, u8)>,
    bj: Vec<f64>,
    sj: Vec<f64>,
    /// `1 / A_j(hi_j)` and `1 / B_j(lo_j)` of the node's coordinates `0..L` (the last and
    /// the first entries of their `big` and `small` tables).
    inv_top: Vec<f64>,
    inv_bottom: Vec<f64>,
}

impl Tail {
    fn new(d: usize) -> Self {
        Tail {
            lo: vec![0; d],
            hi: vec![0; d],
            active: vec![Vec::new(); d],
            tab_big: vec![Vec::new(); d],
            tab_small: vec![Vec::new(); d],
            pre_big: vec![vec![1.0]; d + 1],
            pre_small: vec![vec![1.0]; d + 1],
            clean_big: 0,
            clean_small: 0,
            rem: SortedPrefix::default(),
            kept: SortedPrefix::default(),
            forced: Vec::new(),
            bj: Vec::new(),
            sj: Vec::new(),
            inv_top: Vec::new(),
            inv_bottom: Vec::new(),
        }
    }
}

/// One slab `[lo, hi]` of a cut: `below` points of `rem` are below it, `rem[below..inside]`
/// stab it, `forced[..kept]` stay.
struct Slab {
    lo: u32,
    hi: u32,
    below: usize,
    inside: usize,
    kept: usize,
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

    /// The whole walk over `counted` points; the slabs of the first cut run in parallel,
    /// and `progress(done, PROGRESS_STEPS)` follows them, each slab weighted by its
    /// estimated share of the work.
    fn run(&self, counted: u32, progress: Progress<'_>) {
        let d = self.d;
        let all: Vec<u32> = (0..counted).collect();
        if d == 1 {
            let mut tail = Tail::new(d);
            self.sorted_for_last(&all, &[], std::iter::empty(), &mut tail);
            self.last(&mut tail);
            progress(PROGRESS_STEPS, PROGRESS_STEPS);
            return;
        }
        let mut first = Level::default();
        self.cut(0, &all, &[], &mut first);
        let first = &first;
        // A slab leaves a problem on the points it does not exclude in d - 1 coordinates:
        // weight m^(1 + (d - 1) / 2), as a share of the whole in millionths.
        let weights: Vec<f64> = (0..first.starts.len())
            .map(|idx| (self.slab(0, idx, first).inside as f64).powf(0.5 * (d + 1) as f64))
            .collect();
        let sum: f64 = weights.iter().sum();
        let shares: Vec<u64> = weights.iter().map(|w| (1e6 * w / sum) as u64).collect();
        let done = AtomicU64::new(0);
        (0..shares.len()).into_par_iter().for_each(|idx| {
            let mut levels: Vec<Level> = (1..d).map(|_| Level::default()).collect();
            let mut tail = Tail::new(d);
            self.child(0, idx, first, 1.0, &mut levels, &mut tail);
            let millionths = done.fetch_add(shares[idx], Ordering::Relaxed) + shares[idx];
            let steps = (millionths as usize * PROGRESS_STEPS / 1_000_000).min(PROGRESS_STEPS);
            progress(steps, PROGRESS_STEPS);
        });
        progress(PROGRESS_STEPS, PROGRESS_STEPS);
    }

    /// Sorts `rem` and `forced` by coordinate `k` into `me` and places the cuts.
    ///
    /// Between two cuts of the parent, the cuts of `me` take growing prefixes `rem` of the
    /// parent's list (its slabs in order): only the points new to it are sorted and merged
    /// into `me.rem` (a [`SortedPrefix`], reset by the parent).
    fn cut(&self, k: usize, rem: &[u32], forced: &[(u32, u8)], me: &mut Level) {
        me.rem.extend(rem, |&i| i, |&i| self.level(i, k));
        me.forced.clear();
        me.forced.extend_from_slice(forced);
        me.forced.sort_unstable_by_key(|&(i, _)| self.level(i, k));
        me.starts.clear();
        me.starts.push(0);
        me.starts
            .extend(me.forced.iter().map(|&(i, _)| self.level(i, k)));
        me.starts.extend(
            me.rem
                .iter()
                .skip(self.step)
                .step_by(self.step)
                .map(|&i| self.level(i, k)),
        );
        me.starts.sort_unstable();
        me.starts.dedup();
    }

    /// Slab `idx` of the cut of coordinate `k` in `me`.
    fn slab(&self, k: usize, idx: usize, me: &Level) -> Slab {
        let lo = me.starts[idx];
        let hi = me
            .starts
            .get(idx + 1)
            .map_or(self.grids[k].len() as u32, |&s| s - 1);
        Slab {
            lo,
            hi,
            below: me.rem.partition_point(|&i| self.level(i, k) <= lo),
            inside: me.rem.partition_point(|&i| self.level(i, k) <= hi),
            kept: me.forced.partition_point(|&(i, _)| self.level(i, k) <= lo),
        }
    }

    /// Recurses into slab `idx` of the cut `me` of coordinate `k` (`vol_hi` is
    /// `prod A_j(hi_j)` over coordinates `0..k`), unless it cannot beat the best so far.
    fn child(
        &self,
        k: usize,
        idx: usize,
        me: &Level,
        vol_hi: f64,
        levels: &mut [Level],
        tail: &mut Tail,
    ) {
        if self.stop.stopped() {
            return;
        }
        let s = self.slab(k, idx, me);
        let vh = vol_hi * self.a(k, s.hi);
        let best = self.best();
        // Inside: volume at most vh, count at most the points not yet excluded.
        if self.n * vh <= best && (s.inside + s.kept) as f64 <= best {
            return;
        }
        tail.lo[k] = s.lo;
        tail.hi[k] = s.hi;
        let rem = &me.rem[..s.below];
        let new_forced = me.rem[s.below..s.inside].iter().map(|&i| (i, k as u8));
        if k + 2 >= self.d {
            // The last coordinate comes next.
            self.sorted_for_last(rem, &me.forced[..s.kept], new_forced, tail);
            self.last(tail);
            return;
        }
        let Some((next, rest)) = levels.split_first_mut() else {
            return;
        };
        let mut forced = std::mem::take(&mut next.child);
        forced.clear();
        forced.extend_from_slice(&me.forced[..s.kept]);
        forced.extend(new_forced);
        self.cut(k + 1, rem, &forced, next);
        if let Some(below) = rest.first_mut() {
            // The next level's cuts take prefixes of this new cut's points.
            below.rem.reset();
        }
        // The last coordinate's calls below take prefixes of the new cut's points.
        tail.rem.reset();
        tail.kept.reset();
        next.child = forced;
        if k == 0 && k + 3 < self.d {
            // The slabs of the second cut run in parallel too (the first cut's slabs alone,
            // 17 to 45 of them, the heaviest 12-14% of the work at 6D, would not keep many
            // cores busy); each task has its own buffers, with this node's bounds. (For
            // d = 3 the second cut is the last coordinate's: only the first cut's slabs run
            // in parallel, and they are many, one per sqrt N points.)
            let next = &*next;
            let (lo, hi) = (tail.lo[0], tail.hi[0]);
            let fresh = || {
                let mut t = Tail::new(self.d);
                (t.lo[0], t.hi[0]) = (lo, hi);
                let levels: Vec<Level> = rest.iter().map(|_| Level::default()).collect();
                (levels, t)
            };
            (0..next.starts.len())
                .into_par_iter()
                .for_each_init(fresh, |(levels, t), j| {
                    self.child(k + 1, j, next, vh, levels, t);
                });
            return;
        }
        for j in 0..next.starts.len() {
            self.child(k + 1, j, next, vh, rest, tail);
        }
    }

    /// Fills `tail.rem` with the sorted last-coordinate levels of `rem` (the points below
    /// in all other coordinates) and `tail.forced` with the slab points `kept` and `new`,
    /// sorted by their last-coordinate level, for [`last`](Self::last).
    ///
    /// Between two cuts, the calls take growing prefixes `rem` and `kept` of the cut's
    /// lists (its slabs in order), so only the points new to them are sorted and then merged
    /// into the lists kept from the previous call (two [`SortedPrefix`]es).
    fn sorted_for_last(
        &self,
        rem: &[u32],
        kept: &[(u32, u8)],
        new: impl Iterator<Item = (u32, u8)>,
        tail: &mut Tail,
    ) {
        let l = self.d - 1;
        tail.rem.extend(rem, |&i| self.level(i, l), |&x| x);
        let key = |&(i, _): &(u32, u8)| self.level(i, l);
        tail.kept.extend(kept, |&p| p, key);
        tail.forced.clear();
        tail.forced.extend(new);
        tail.forced.sort_unstable_by_key(key);
        merge_sorted(&mut tail.forced, &tail.kept.list, key);
    }

    /// The last coordinate `L = d - 1` of the node with bounds `tail.lo`, `tail.hi` on
    /// coordinates `0..L`, the points below in all of them (`tail.rem`, their sorted levels)
    /// and slab points `tail.forced` (sorted by level), from
    /// [`sorted_for_last`](Self::sorted_for_last): cut only at the slab points' levels, then
    /// evaluate every cell exactly.
    fn last(&self, tail: &mut Tail) {
        let l = self.d - 1;
        let top = self.grids[l].len() as u32;
        let forced = std::mem::take(&mut tail.forced);
        for j in 0..l {
            tail.active[j].clear();
            tail.tab_big[j].clear();
            tail.tab_big[j].push(self.a(j, tail.hi[j]));
            tail.tab_small[j].clear();
            tail.tab_small[j].push(self.b(j, tail.lo[j]));
        }
        tail.clean_big = 0;
        tail.clean_small = 0;
        tail.inv_top.clear();
        tail.inv_top
            .extend((0..l).map(|j| 1.0 / self.a(j, tail.hi[j])));
        tail.inv_bottom.clear();
        tail.inv_bottom
            .extend((0..l).map(|j| 1.0 / self.b(j, tail.lo[j])));
        let vol_hi: f64 = (0..l).map(|j| self.a(j, tail.hi[j])).product();
        let vol_lo: f64 = (0..l).map(|j| self.b(j, tail.lo[j])).product();
        let mut n_active = 0usize;
        let mut fi = 0usize;
        let mut lo_l = 0u32;
        let mut pruned = 0u32;
        loop {
            // Activate the slab points whose last level is lo_l (the cuts are at them).
            while let Some(&(i, j)) = forced.get(fi) {
                if self.level(i, l) > lo_l {
                    break;
                }
                let (j, v) = (j as usize, self.level(i, j as usize));
                let list = &mut tail.active[j];
                let at = list.partition_point(|&x| x <= v);
                list.insert(at, v);
                // See `tables`: A(v - 1) enters big at `at`, B(v) enters small after it.
                tail.tab_big[j].insert(at, self.a(j, v - 1));
                tail.tab_small[j].insert(at + 1, self.b(j, v));
                tail.clean_big = tail.clean_big.min(j);
                tail.clean_small = tail.clean_small.min(j);
                n_active += 1;
                fi += 1;
            }
            let hi_l = forced.get(fi).map_or(top, |&(i, _)| self.level(i, l) - 1);
            let below = tail.rem.partition_point(|&x| x <= lo_l);
            let inside = tail.rem.partition_point(|&x| x <= hi_l);
            let rr = below as f64;
            let best = self.best();
            // The cell's largest and smallest volumes (times N), at its upper and lower corners.
            let (a_hi, b_lo) = (self.a(l, hi_l), self.b(l, lo_l));
            let (v, w) = (self.n * vol_hi * a_hi, self.n * vol_lo * b_lo);
            let open_bound = v - rr;
            let closed_bound = (inside + n_active) as f64 - w;
            let (mut open, mut closed) = (open_bound > best, closed_bound > best);
            if open || closed {
                let slab = &tail.rem[below..inside];
                self.tables(l, lo_l, hi_l, slab, &mut tail.bj, &mut tail.sj);
                // Tighter bounds from the tables (see `open_slack`, `closed_slack`), before
                // the knapsacks are brought up to date. The tables of coordinates 0..L keep
                // their last (open) and first (closed) entries over the node: their
                // reciprocals are `inv_top`, `inv_bottom`.
                let margin = 1e-12 * (self.n + open_bound.abs() + closed_bound.abs());
                if open {
                    let tables = tail.tab_big[..l].iter().map(Vec::as_slice);
                    let tables = tables.zip(tail.inv_top.iter().copied());
                    let tables = tables.chain([(&tail.bj[..], 1.0 / a_hi)]);
                    // Pruned once the slack reaches `open_bound - best + margin`.
                    let slack = open_slack(v, open_bound - best + margin, tables);
                    open = open_bound - slack + margin > best;
                }
                if closed && w > 0.0 {
                    let tables = tail.tab_small[..l].iter().map(Vec::as_slice);
                    let tables = tables.zip(tail.inv_bottom.iter().copied());
                    let tables = tables.chain([(&tail.sj[..], 1.0 / b_lo)]);
                    let most = closed_slack(w, tables);
                    closed = rr - w + most + margin > best;
                }
            }
            if open || closed {
                if self.stop.check() {
                    break;
                }
                let v = self.cell(tail, below, inside, (open, closed));
                self.offer(v);
            } else {
                pruned += 1;
                if pruned.is_multiple_of(CELLS_PER_CHECK) && self.stop.check() {
                    break;
                }
            }
            if hi_l >= top {
                break;
            }
            lo_l = hi_l + 1;
        }
        tail.forced = forced;
    }

    /// Exact value (scaled by `N`) of the cell with bounds `tail.lo`, `tail.hi` on
    /// coordinates `0..L` and `last` on coordinate `L`, slab levels `tail.active[j]` of
    /// coordinate `j < L` and `tail.rem[below..inside]` of coordinate `L`, `below` points
    /// below everywhere.
    fn cell(
        &self,
        tail: &mut Tail,
        below: usize,
        inside: usize,
        (open, closed): (bool, bool),
    ) -> f64 {
        let l = self.d - 1;
        let t = tail;
        // Knapsack over coordinates 0..L: big[c] (small[c]) = largest (smallest) product of
        // A (B) factors with total slab count c, from the prefixes still valid. Only the
        // halves that can beat the best so far (`open`, `closed`) are brought up to date.
        if open {
            for j in t.clean_big..l {
                let (done, todo) = t.pre_big.split_at_mut(j + 1);
                convolve_max(&done[j], &t.tab_big[j], &mut todo[0]);
            }
            t.clean_big = l;
        }
        if closed {
            for j in t.clean_small..l {
                let (done, todo) = t.pre_small.split_at_mut(j + 1);
                convolve_min(&done[j], &t.tab_small[j], &mut todo[0]);
            }
            t.clean_small = l;
        }
        let slab = &t.rem[below..inside];
        let (na, nb) = (self.n, self.n);
        let base = below as f64;
        let m = slab.len() as f64;
        let mut best = self.best();
        if open {
            let top = t.bj.last().copied().unwrap_or(0.0);
            for (a, &bg) in t.pre_big[l].iter().enumerate() {
                let x = na * bg;
                let mut count = base + a as f64;
                if x * top - count <= best {
                    continue;
                }
                for &bl in &t.bj {
                    let v = x * bl - count;
                    best = if v > best { v } else { best };
                    count += 1.0;
                }
            }
        }
        if closed {
            let bottom = t.sj.first().copied().unwrap_or(0.0);
            for (a, &sm) in t.pre_small[l].iter().enumerate() {
                let y = nb * sm;
                let mut count = base + a as f64;
                if count + m - y * bottom <= best {
                    continue;
                }
                for &sl in &t.sj {
                    let v = count - y * sl;
                    best = if v > best { v } else { best };
                    count += 1.0;
                }
            }
        }
        best
    }

    /// Per-coordinate tables of a cell: for `c = 0..=m` slab points counted (`list`: their
    /// sorted levels in `(lo, hi]`), `big[c] = A_k(t)` at the largest `t` in `[lo, hi]`
    /// counting at most `c` of them and `small[c] = B_k(t)` at the smallest `t` counting at
    /// least `c`.
    fn tables(
        &self,
        k: usize,
        lo: u32,
        hi: u32,
        list: &[u32],
        big: &mut Vec<f64>,
        small: &mut Vec<f64>,
    ) {
        big.clear();
        small.clear();
        small.push(self.b(k, lo));
        for &v in list {
            big.push(self.a(k, v - 1));
            small.push(self.b(k, v));
        }
        big.push(self.a(k, hi));
    }
}
