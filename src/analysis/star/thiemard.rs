//! Guaranteed bounds on the star discrepancy by Thiémard's δ-bracketing decomposition.
//!
//! E. Thiémard, "An algorithm to compute bounds for the star discrepancy", J. Complexity 17
//! (2001) 850–880, and "Computing bounds for the star discrepancy", Computing 65 (2000);
//! surveyed in Doerr, Gnewuch & Wahlström, "Calculation of discrepancy measures and
//! applications" (2014); the size of the cover is bounded explicitly in Gnewuch,
//! "Improved bounds for the bracketing number of orthants or revisiting an algorithm of
//! Thiémard" (2024, arXiv:2401.00801).
//!
//! # The bound
//!
//! A *bracket* is a pair of corners `α <= β` (componentwise) in `[0, 1]^d`. For every `y`
//! with `α <= y <= β`, `[0, α) ⊂ [0, y) ⊂ [0, β)`, so with `A(c) = #{i : x_i < c}` (all
//! coordinates strictly below) and `vol(c) = c_1 ⋯ c_d`,
//!
//! ```text
//! A(y)/N - vol(y) <= A(β)/N - vol(α)        vol(y) - A(y)/N <= vol(β) - A(α)/N.
//! ```
//!
//! If a family of brackets covers `[0, 1]^d`, the maximum of the right-hand sides over the
//! family is therefore **at least `D*_N`**; if moreover `vol(β) - vol(α) <= δ` for every
//! bracket (a δ-bracketing cover), it is **at most `D*_N + δ`**, because
//! `A(β)/N - vol(α) = (A(β)/N - vol(β)) + (vol(β) - vol(α))` and `[0, β)` is a test box.
//! The corners themselves are test boxes too, so `max |A(c)/N - vol(c)|` over all corners is
//! a lower bound, and at least `D*_N - δ` (a box `[0, y)` with `A(y)/N - vol(y) = D*_N`
//! lies in a bracket whose `β` has at least its points and at most `δ` more volume; for a
//! deficit, `α` has at most its points and at most `δ` less volume). It is sharpened at the
//! end by moving the best corner onto the critical grid (shrinking an overfull corner to the
//! largest coordinates of the points it holds, which keeps the count and lowers the volume;
//! growing an underfull one up to the next point coordinates or 1, which keeps the count
//! and raises the volume).
//!
//! # Thiémard's decomposition
//!
//! A *region* `R = [a, b]` has its first `m` coordinates *fixed* (`a_j <= y_j <= b_j`) and
//! the others *free* (`0 <= y_j <= b_j`, so `a_j = 0`). It is split into the bracket
//! `[γ, b]` with `γ_j = a_j` on the fixed coordinates and `γ_j = s b_j` on the `k = d - m`
//! free ones, the common factor `s = ((vol(b) - δ) / (vol_fixed(a) vol_free(b)))^(1/k)`
//! chosen so that `vol(γ) = vol(b) - δ`, and `k` child regions covering the rest: child `i`
//! (`m <= i < d`) takes coordinates `m..i` in `[γ_j, b_j]` (now fixed), coordinate `i` in
//! `[0, γ_i]` and leaves the later ones free. Every child has `vol(b') = s vol(b)`; a child
//! with `vol(b') <= δ` is itself a bracket `[a', b']` (`vol(a') = 0`), the others are split
//! again. Starting from `[0, 1]^d` with `m = 0` this is a δ-bracketing cover (the pieces of
//! a split cover the region for *any* `γ` with `0 <= γ <= b`, so rounding in `s` cannot
//! leave a gap). The child `i = m` has the same fixed coordinates as its parent, so the
//! recursion runs as a loop along it and nests at most `d` deep.
//!
//! # Counting
//!
//! Each region carries the list of points inside `[0, b)`. Then `A(b)` is the list length,
//! `A(γ)` one pass over it, and child `i` differs from its parent only in `b_i`, so its list
//! is the parent's filtered on the single coordinate `i` (a leaf child is only counted).
//! Deep regions have small `[0, b)` and see few points: for evenly spread points a region
//! costs about `N vol(b) (d + k)` comparisons, instead of `N d` per bracket when each
//! bracket is counted against all points. Once only the last coordinate is free (`k = 1`,
//! the most numerous regions: in 2D nearly all), the chain along it moves only `b_d` and
//! `γ_d`, so its counts come from two sorted arrays of `x_d` by binary search: one sort
//! per chain instead of one pass per bracket. A region whose list is empty is not split: every
//! bracket inside has `A = 0` and gives at most `vol(b)`, the value of the region's own
//! bracket (and `[0, b)` is an empty test box, so this is also a lower bound). Regions with
//! many points are processed in parallel (rayon).
//!
//! # Accuracy
//!
//! Counts are exact; `vol` is a product of at most `d` factors in `[0, 1]`, rounded with a
//! relative error below `1.01 (d - 1) 2^-53`; `A/N` and the difference add two more
//! roundings. The upper bound is returned plus `(d + 2) f64::EPSILON` and the lower bound
//! minus the same, so both are guaranteed in floating point.

use super::cost::THIEMARD_RATE;
use super::thiemard_cost::{
    chain_step_cost, estimate, region_cost, root_chain_lower_bound, split, vol,
};
use crate::analysis::Points;
use crate::work::Limits;
use crate::work::Stop;
use crate::{Error, Result};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Lower and upper bounds on the star discrepancy from [`bounds`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// A guaranteed lower bound: the best test box met during the decomposition.
    pub lower: f64,
    /// A guaranteed upper bound, at most `D*_N + δ` (plus a few ulps).
    pub upper: f64,
    /// Brackets evaluated (a region holding no point is evaluated as one bracket: every
    /// bracket inside it gives at most its volume).
    pub brackets: u64,
}

/// Regions holding at least this many points become separate rayon tasks.
const SPAWN_POINTS: usize = 2048;

/// Largest `N` the index lists can hold.
const MAX_POINTS: u64 = u32::MAX as u64;

/// Lower and upper bounds on `D*_N` by Thiémard's δ-bracketing cover (see the module
/// documentation for the construction and the guarantee).
///
/// `D*_N - δ <= lower <= D*_N <= upper <= D*_N + δ` (the outer two up to a few ulps). The
/// number of brackets grows like `δ^-d` times a factor exponential in `d` (see Gnewuch 2024
/// in the module documentation), so the reachable `δ` shrinks fast with `d`: about
/// `0.0002`–`0.0004` in 2D, `0.08`–`0.15` in 5D, `0.4`–`0.5` in 10D and `0.7` in 20D for
/// `N = 1000`–`10000` within the budget.
///
/// # Cost
/// For evenly spread points about `Σ_R (N vol(b_R) + 16)(d + k_R) + 2 d (k_R - 1)`
/// comparisons over the regions `R` of the decomposition with `k_R >= 2` free coordinates,
/// plus a sort of `N vol(b)` values per chain along the last coordinate and `16 + 3 d` per
/// bracket in it, at
/// [`THIEMARD_RATE`]. Before anything is allocated, the root chain alone gives a lower
/// bound in `O(1)` memory (about `2 d^2` per step: two points in 1000 dimensions, or one in
/// 20000, are refused in microseconds); then a pass over the regions without points
/// estimates the whole, in at most about a tenth of the budget's time. Measured with the
/// `time_thiemard` example (release build, two shared cores; random points from
/// [`crate::Independent`] with seed 1), the default budget of ten seconds accepting the
/// first five rows and refusing the last four:
///
/// | `d`, `N`, points | `δ` | time | lower | upper | exact |
/// |---|---|---|---|---|---|
/// | 2, 1000, Sobol' | 0.0002 | 2.7 s | 0.005717 | 0.005758 | 0.005717 |
/// | 5, 1000, random | 0.08 | 3.7 s | 0.0766 | 0.152 | |
/// | 5, 10000, Sobol' | 0.15 | 3.8 s | 0.0024 | 0.152 | |
/// | 10, 1000, random | 0.4 | 1.2 s | 0.0765 | 0.463 | |
/// | 20, 10000, random | 0.7 | 3.1 s | 0.0215 | 0.711 | |
/// | 2, 1000, Sobol' | 0.00012 | 11.1 s | 0.005717 | 0.005763 | 0.005717 |
/// | 5, 1000, random | 0.06 | 17.8 s | 0.0793 | 0.137 | |
/// | 10, 1000, random | 0.3 | 26.7 s | 0.0795 | 0.370 | |
/// | 20, 1000, random | 0.6 | 10.0 s | 0.0807 | 0.664 | |
///
/// So the upper bound is informative in 2D–3D; from about 5D on it is close to `δ` itself
/// for any reasonable `N`, and [`lower`](Bounds::lower) is the more useful number.
///
/// Both bounds lie in `[0, 1]`: `D*_N <= 1` always (a local discrepancy is a difference of
/// two numbers in `[0, 1]`), so an upper bound above 1 (the rounding margin on a bracket
/// worth 1) is lowered to 1, which stays a valid bound; and `lower <= upper`.
///
/// The limits: the time budget (`&Budget::DEFAULT`, ten seconds, for the usual requests),
/// checked against the estimated comparisons at [`THIEMARD_RATE`].
///
/// # Errors
/// [`Error::Unsupported`] for `δ` not in `(0, 1]`; [`Error::TooManyPoints`] when the
/// estimated time exceeds `budget`, or when the run exceeds four times it (points clustered
/// near the origin), or above `2^32 - 1` points; `max` is the largest `N` the estimate
/// allows for this `δ` and `d` (an upper limit of it when the estimating pass stopped
/// early; 0 when the regions alone are too many: take a larger `δ`). [`Error::TooLarge`]
/// when the estimating pass would need more than [`crate::size::MAX_ALLOC_BYTES`].
/// [`Error::OutOfTime`] past the deadline of `budget` (started here if it was not), read
/// every `2^16` comparisons of work.
///
/// ```
/// use qmckit::work::Budget;
/// use qmckit::analysis::{Points, star::thiemard::bounds};
/// // One point at the center of the square: D* = 1 - 1/4 = 3/4.
/// let b = bounds(Points::new(&[0.5, 0.5], 2)?, 0.01, &Budget::DEFAULT)?;
/// assert!(b.lower <= 0.75 && 0.75 <= b.upper && b.upper <= 0.76 + 1e-12);
/// let data = vec![0.5; 2 * 1000]; // two points in 1000 dimensions
/// let p = Points::new(&data, 1000)?;
/// assert!(bounds(p, 0.05, &Budget::DEFAULT).is_err()); // refused at once
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn bounds<'a>(points: Points<'_>, delta: f64, limits: impl Into<Limits<'a>>) -> Result<Bounds> {
    let limits = limits.into();
    let budget = limits.budget();
    if !(delta > 0.0 && delta <= 1.0) {
        return Err(Error::Unsupported {
            what: "Thiémard's bounds need 0 < delta <= 1",
        });
    }
    let n = points.len();
    let d = points.dims();
    if n as u64 > MAX_POINTS {
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max: MAX_POINTS,
        });
    }
    let limit = budget.steps(THIEMARD_RATE);
    let refuse = |max: f64| Error::TooManyPoints {
        requested: n as u64,
        max: if max.is_nan() { 0 } else { max.max(0.0) as u64 },
    };
    if root_chain_lower_bound(d, delta, n as f64, limit) > limit {
        return Err(refuse(0.0));
    }
    let (per_point, fixed, complete) = estimate(d, delta, n as f64, limit)?;
    if !complete || per_point * n as f64 + fixed > limit {
        return Err(refuse((limit - fixed) / per_point));
    }
    let x = points.as_slice();
    // Points with a coordinate 1 lie in no box [0, c), c <= 1.
    let list: Vec<u32> = (0..n as u32)
        .filter(|&i| points.point(i as usize).iter().all(|&c| c < 1.0))
        .collect();
    let run = Run {
        x,
        d,
        n: n as f64,
        delta,
        work: AtomicU64::new(0),
        cap: cap(4.0 * limit),
        aborted: AtomicBool::new(false),
        stop: Stop::new(budget, "Thiémard's bounds"),
        total: Mutex::new(Acc::new(d)),
    };
    rayon::scope(|s| {
        let mut acc = Acc::new(d);
        run.region(s, vec![0.0; d], vec![1.0; d], 0, list, &mut acc);
        run.merge(acc);
    });
    run.stop.result()?;
    if run.aborted.load(Ordering::Relaxed) {
        return Err(refuse(
            n as f64 * limit / run.work.load(Ordering::Relaxed) as f64,
        ));
    }
    let acc = run
        .total
        .into_inner()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    let margin = (d + 2) as f64 * f64::EPSILON;
    let lower = snap_over(points, &acc.over_corner, n as f64)
        .max(snap_under(points, &acc.under_corner, n as f64))
        .max(acc.over)
        .max(acc.under);
    // D* <= 1: the margin must not lift the bound past the largest possible value.
    let upper = (acc.upper + margin).min(1.0);
    Ok(Bounds {
        lower: (lower - margin).max(0.0).min(upper),
        upper,
        brackets: acc.brackets,
    })
}

/// A work cap in whole comparisons (saturated; an unlimited budget has none).
fn cap(steps: f64) -> u64 {
    if steps >= u64::MAX as f64 {
        u64::MAX
    } else {
        steps as u64
    }
}

/// The best values met so far in one task.
struct Acc {
    /// Max over brackets of `max(A(β)/N - vol(α), vol(β) - A(α)/N)`.
    upper: f64,
    /// Max over corners of `A(c)/N - vol(c)`, and the corner.
    over: f64,
    over_corner: Vec<f64>,
    /// Max over corners of `vol(c) - A(c)/N`, and the corner.
    under: f64,
    under_corner: Vec<f64>,
    brackets: u64,
}

impl Acc {
    fn new(d: usize) -> Self {
        Acc {
            upper: 0.0,
            over: 0.0,
            over_corner: vec![0.0; d],
            under: 0.0,
            under_corner: vec![0.0; d],
            brackets: 0,
        }
    }

    /// Records a corner `c` with count `count` and volume `v` as a test box.
    fn corner(&mut self, c: &[f64], count: f64, v: f64) {
        if count - v > self.over {
            self.over = count - v;
            self.over_corner.copy_from_slice(c);
        }
        if v - count > self.under {
            self.under = v - count;
            self.under_corner.copy_from_slice(c);
        }
    }

    /// Records the bracket `[α, β]` with `A(α)/N = qa`, `vol(α) = va` and the same for `β`.
    fn bracket(&mut self, qa: f64, va: f64, qb: f64, vb: f64) {
        self.upper = self.upper.max(qb - va).max(vb - qa);
        self.brackets += 1;
    }

    fn merge(&mut self, other: Acc) {
        self.upper = self.upper.max(other.upper);
        self.brackets += other.brackets;
        if other.over > self.over {
            self.over = other.over;
            self.over_corner = other.over_corner;
        }
        if other.under > self.under {
            self.under = other.under;
            self.under_corner = other.under_corner;
        }
    }
}

/// Shared state of one run of [`bounds`].
struct Run<'x> {
    x: &'x [f64],
    d: usize,
    n: f64,
    delta: f64,
    work: AtomicU64,
    cap: u64,
    aborted: AtomicBool,
    /// The deadline, read each time the work counter passes a multiple of
    /// [`WORK_PER_CHECK`].
    stop: Stop,
    total: Mutex<Acc>,
}

/// Comparisons between two readings of the clock (a few hundred microseconds).
const WORK_PER_CHECK: u64 = 1 << 16;

impl Run<'_> {
    fn merge(&self, acc: Acc) {
        match self.total.lock() {
            Ok(mut t) => t.merge(acc),
            Err(poisoned) => poisoned.into_inner().merge(acc),
        }
    }

    /// Coordinate `k` of point `i`.
    fn coord(&self, i: u32, k: usize) -> f64 {
        self.x.get(i as usize * self.d + k).copied().unwrap_or(1.0)
    }

    /// Whether point `i` lies in `[0, c)`.
    fn below(&self, i: u32, c: &[f64]) -> bool {
        let start = i as usize * self.d;
        match self.x.get(start..start + self.d) {
            Some(p) => p.iter().zip(c).all(|(&x, &y)| x < y),
            None => false,
        }
    }

    /// Adds `w` to the work counter; false once the run is over its cap or its deadline.
    fn charge(&self, w: u64) -> bool {
        let before = self.work.fetch_add(w, Ordering::Relaxed);
        let total = before.saturating_add(w);
        if total > self.cap
            || (before / WORK_PER_CHECK != total / WORK_PER_CHECK && self.stop.check())
        {
            self.aborted.store(true, Ordering::Relaxed);
        }
        !self.aborted.load(Ordering::Relaxed)
    }

    /// Decomposes the region `[a, b]` (first `m` coordinates fixed) whose points inside
    /// `[0, b)` are `list`; children with many points are spawned into `scope`.
    ///
    /// Depth first, in the order of the recursion "split, then each child `i = m + 1..d`
    /// in turn, then go on along child `m`", kept on an explicit stack of [`Region`]s (at
    /// most `d` deep) so that the call stack does not grow with `d`.
    fn region<'s>(
        &'s self,
        scope: &rayon::Scope<'s>,
        a: Vec<f64>,
        b: Vec<f64>,
        m: usize,
        list: Vec<u32>,
        acc: &mut Acc,
    ) {
        let d = self.d;
        let mut stack = vec![Region {
            a,
            b,
            m,
            list,
            g: Vec::new(),
            next: None,
        }];
        while let Some(r) = stack.last_mut() {
            if r.m + 1 == d {
                if let Some(r) = stack.pop() {
                    self.last_chain(&r.a, r.b, &r.list, acc);
                }
                continue;
            }
            let start = match r.next {
                Some(i) => i,
                None => {
                    if !self.step(r, acc) {
                        stack.pop();
                        continue;
                    }
                    r.m + 1
                }
            };
            match self.children(scope, r, start, acc) {
                Some(child) => stack.push(child),
                None => {
                    // Child m: same fixed coordinates, b_m lowered to γ_m.
                    let m = r.m;
                    let gm = r.g.get(m).copied().unwrap_or(0.0);
                    if let Some(c) = r.b.get_mut(m) {
                        *c = gm;
                    }
                    r.list.retain(|&p| self.coord(p, m) < gm);
                    r.next = None;
                }
            }
        }
    }

    /// The head of a step of the chain of `r`: records its corner and bracket, and splits
    /// it (`γ` in `r.g`) unless it is empty, a bracket itself, or the run is over its cap
    /// (then false: the chain ends).
    fn step(&self, r: &mut Region, acc: &mut Acc) -> bool {
        let (d, n, m) = (self.d, self.n, r.m);
        let vb = vol(&r.b);
        let qb = r.list.len() as f64 / n;
        acc.corner(&r.b, qb, vb);
        if r.list.is_empty() {
            // Every bracket inside has A = 0, so it gives vol(β) - 0 <= vol(b), attained
            // by the region's own bracket; the test box [0, b) is empty too.
            acc.bracket(0.0, 0.0, 0.0, vb);
            return false;
        }
        if vb <= self.delta {
            // The region is a bracket [a, b] itself; vol(a) = 0 and A(a) = 0.
            acc.bracket(0.0, 0.0, qb, vb);
            return false;
        }
        if !self.charge(region_cost(d, d - m, r.list.len() as f64) as u64) {
            return false;
        }
        r.g.clear();
        r.g.resize(d, 0.0);
        split(&r.a, &r.b, m, self.delta, &mut r.g);
        let vg = vol(&r.g);
        let qg = r.list.iter().filter(|&&i| self.below(i, &r.g)).count() as f64 / n;
        acc.corner(&r.g, qg, vg);
        acc.bracket(qg, vg, qb, vb);
        true
    }

    /// Children `start..d` of the split region `r`: leaves and empty children are recorded,
    /// children with many points spawned; the first other child is returned to be
    /// descended into (with `r.next` set past it), `None` once all are done.
    fn children<'s>(
        &'s self,
        scope: &rayon::Scope<'s>,
        r: &mut Region,
        start: usize,
        acc: &mut Acc,
    ) -> Option<Region> {
        let (d, n, m) = (self.d, self.n, r.m);
        for i in start..d {
            let gi = r.g.get(i).copied().unwrap_or(0.0);
            let mut cb = r.b.clone();
            if let Some(c) = cb.get_mut(i) {
                *c = gi;
            }
            let vcb = vol(&cb);
            if vcb <= self.delta {
                let count = r.list.iter().filter(|&&p| self.coord(p, i) < gi).count();
                let q = count as f64 / n;
                acc.corner(&cb, q, vcb);
                acc.bracket(0.0, 0.0, q, vcb);
                continue;
            }
            let sub: Vec<u32> = r
                .list
                .iter()
                .copied()
                .filter(|&p| self.coord(p, i) < gi)
                .collect();
            if sub.is_empty() {
                // As for an empty region: the child gives vol(b') and nothing else.
                acc.corner(&cb, 0.0, vcb);
                acc.bracket(0.0, 0.0, 0.0, vcb);
                continue;
            }
            let mut ca = r.a.clone();
            if let (Some(dst), Some(src)) = (ca.get_mut(m..i), r.g.get(m..i)) {
                dst.copy_from_slice(src);
            }
            if sub.len() >= SPAWN_POINTS {
                scope.spawn(move |s| {
                    let mut own = Acc::new(d);
                    self.region(s, ca, cb, i, sub, &mut own);
                    self.merge(own);
                });
            } else {
                r.next = Some(i + 1);
                return Some(Region {
                    a: ca,
                    b: cb,
                    m: i,
                    list: sub,
                    g: Vec::new(),
                    next: None,
                });
            }
        }
        None
    }
}

/// A region of [`Run::region`]'s walk: `[a, b]` with the first `m` coordinates fixed, the
/// points of `[0, b)`, the lower corner `γ` of its current bracket and the next child to
/// visit (`None` before the split of the current step of its chain).
struct Region {
    a: Vec<f64>,
    b: Vec<f64>,
    m: usize,
    list: Vec<u32>,
    g: Vec<f64>,
    next: Option<usize>,
}

impl Run<'_> {
    /// [`Run::region`] when only the last coordinate `m = d - 1` is free. Along the chain
    /// only `b_m` and `γ_m` change, both decreasing, and the other coordinates of `b` and
    /// `γ` stay fixed (`γ_j = a_j`), so `A(b)` is the number of points of `list` with
    /// `x_m < b_m` and `A(γ)` the number of those with `x_j < a_j` for `j < m` and
    /// `x_m < γ_m`: two sorted arrays of `x_m` and a binary search each per bracket, instead
    /// of a pass over the list.
    fn last_chain(&self, a: &[f64], mut b: Vec<f64>, list: &[u32], acc: &mut Acc) {
        let d = self.d;
        let m = d - 1;
        let n = self.n;
        let fixed = a.get(..m).unwrap_or(&[]);
        let mut all: Vec<f64> = list.iter().map(|&p| self.coord(p, m)).collect();
        let mut inner: Vec<f64> = list
            .iter()
            .filter(|&&p| {
                fixed
                    .iter()
                    .enumerate()
                    .all(|(j, &aj)| self.coord(p, j) < aj)
            })
            .map(|&p| self.coord(p, m))
            .collect();
        all.sort_unstable_by(f64::total_cmp);
        inner.sort_unstable_by(f64::total_cmp);
        let sort = |len: usize| len * (1 + (usize::BITS - len.leading_zeros()) as usize);
        if !self.charge((list.len() * d + sort(all.len()) + sort(inner.len())) as u64) {
            return;
        }
        let mut g = vec![0.0; d];
        let mut steps = 0u64;
        loop {
            let vb = vol(&b);
            let bm = b.get(m).copied().unwrap_or(0.0);
            let cb = all.partition_point(|&x| x < bm);
            let qb = cb as f64 / n;
            acc.corner(&b, qb, vb);
            if cb == 0 || vb <= self.delta {
                // Empty (every bracket inside gives at most vol(b)) or a bracket itself.
                acc.bracket(0.0, 0.0, qb, vb);
                break;
            }
            steps += 1;
            if steps.is_multiple_of(1024) && !self.charge((1024.0 * chain_step_cost(d)) as u64) {
                return;
            }
            split(a, &b, m, self.delta, &mut g);
            let gm = g.get(m).copied().unwrap_or(0.0);
            let vg = vol(&g);
            let qg = inner.partition_point(|&x| x < gm) as f64 / n;
            acc.corner(&g, qg, vg);
            acc.bracket(qg, vg, qb, vb);
            if let Some(c) = b.get_mut(m) {
                *c = gm;
            }
        }
    }
}

/// `A(c)/N - vol(c')` for the closed box `[0, c']`, `c'_j` the largest coordinate `j` of the
/// points in `[0, c)`: it holds the same points with less volume (a limit of test boxes).
fn snap_over(points: Points<'_>, c: &[f64], n: f64) -> f64 {
    let mut top = vec![0.0f64; c.len()];
    let mut count = 0usize;
    for p in points.iter() {
        if p.iter().zip(c).all(|(&x, &y)| x < y) {
            count += 1;
            for (t, &x) in top.iter_mut().zip(p) {
                *t = t.max(x);
            }
        }
    }
    if count == 0 {
        return 0.0;
    }
    count as f64 / n - vol(&top)
}

/// `vol(c'') - A(c)/N` for the open box `[0, c'')`, `c''_j` the smallest coordinate `j >= c_j`
/// over all points (or 1): it holds the same points as `[0, c)` with more volume.
fn snap_under(points: Points<'_>, c: &[f64], n: f64) -> f64 {
    let mut up: Vec<f64> = vec![1.0; c.len()];
    let mut count = 0usize;
    for p in points.iter() {
        if p.iter().zip(c).all(|(&x, &y)| x < y) {
            count += 1;
        }
        for ((u, &x), &y) in up.iter_mut().zip(p).zip(c) {
            if x >= y && x < *u {
                *u = x;
            }
        }
    }
    vol(&up) - count as f64 / n
}
