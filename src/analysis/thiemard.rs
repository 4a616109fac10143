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

use super::Points;
use super::star::STAR_WORK_BUDGET;
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

/// Cost units of a region besides its points: volumes, γ and the child corners.
const REGION_OVERHEAD: f64 = 16.0;

/// Steps of [`STAR_WORK_BUDGET`] per comparison counted here: the budget (about ten
/// seconds) is calibrated on the exact algorithms; a comparison of [`bounds`], with its
/// share of list filtering and region bookkeeping, takes about 1.5 times as long.
const STEP_WEIGHT: f64 = 1.5;

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
/// For evenly spread points about `Σ_R (N vol(b_R) + 16)(d + k_R)` comparisons over the
/// regions `R` of the decomposition with `k_R >= 2` free coordinates, plus a sort of
/// `N vol(b)` values per chain along the last coordinate and a binary search per bracket
/// in it; estimated before running by a
/// pass over the regions without points, which takes up to about a second before a
/// refusal when the regions alone exceed the budget. Measured on a shared 2-core machine:
///
/// | `d`, `N`, points | `δ` | time | lower | upper | exact |
/// |---|---|---|---|---|---|
/// | 2, 1000, Sobol' | 0.0002 | 9.9 s | 0.005717 | 0.005758 | 0.005717 |
/// | 2, 10000, random | 0.0004 | 9.2 s | 0.01247 | 0.01282 | 0.01257 |
/// | 5, 1000, random | 0.08 | 12.7 s | 0.055 | 0.132 | |
/// | 5, 10000, Sobol' | 0.15 | 9.9 s | 0.0024 | 0.152 | |
/// | 10, 1000, random | 0.4 | 2.8 s | 0.060 | 0.450 | |
/// | 20, 10000, random | 0.7 | 7.5 s | 0.023 | 0.714 | |
///
/// So the upper bound is informative in 2D–3D; from about 5D on it is close to `δ` itself
/// for any reasonable `N`, and [`lower`](Bounds::lower) is the more useful number.
///
/// # Errors
/// [`Error::Unsupported`] for `δ` not in `(0, 1]`; [`Error::TooManyPoints`] when the
/// estimated work exceeds [`STAR_WORK_BUDGET`], or when the run exceeds four times the budget
/// (points clustered near the origin), or above `2^32 - 1` points; `max` is the largest `N`
/// the estimate allows for this `δ` and `d` (an upper limit of it when the estimating pass
/// stopped early; 0 when the regions alone are too many: take a larger `δ`).
///
/// ```
/// use qmckit::analysis::{Points, thiemard::bounds};
/// // One point at the center of the square: D* = 1 - 1/4 = 3/4.
/// let b = bounds(Points::new(&[0.5, 0.5], 2)?, 0.01)?;
/// assert!(b.lower <= 0.75 && 0.75 <= b.upper && b.upper <= 0.76 + 1e-12);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn bounds(points: Points<'_>, delta: f64) -> Result<Bounds> {
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
    // The budget counts steps of the exact algorithms' inner loops; a comparison here
    // costs about STEP_WEIGHT of them (measured, 2 cores).
    let limit = STAR_WORK_BUDGET / STEP_WEIGHT;
    let (per_point, fixed, complete) = estimate(d, delta, n as f64, limit);
    if !complete || per_point * n as f64 + fixed > limit {
        let max = ((limit - fixed) / per_point).max(0.0);
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max: max as u64,
        });
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
        cap: (4.0 * limit) as u64,
        aborted: AtomicBool::new(false),
        total: Mutex::new(Acc::new(d)),
    };
    rayon::scope(|s| {
        let mut acc = Acc::new(d);
        run.region(s, vec![0.0; d], vec![1.0; d], 0, list, &mut acc);
        run.merge(acc);
    });
    if run.aborted.load(Ordering::Relaxed) {
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max: (n as f64 * limit / run.work.load(Ordering::Relaxed) as f64) as u64,
        });
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
    Ok(Bounds {
        lower: (lower - margin).max(0.0),
        upper: acc.upper + margin,
        brackets: acc.brackets,
    })
}

/// Product of the coordinates.
fn vol(c: &[f64]) -> f64 {
    c.iter().product()
}

/// Thiémard's split of the region `[a, b]` with the first `m` coordinates fixed: writes the
/// lower corner `γ` of its bracket into `g`. Requires `vol(b) > delta`. The free part of `γ`
/// always moves below `b` in coordinate `m`, so the loop along child `m` ends.
fn split(a: &[f64], b: &[f64], m: usize, delta: f64, g: &mut [f64]) {
    let k = (b.len() - m) as f64;
    let fixed = vol(a.get(..m).unwrap_or(&[]));
    let free = vol(b.get(m..).unwrap_or(&[]));
    let ratio = (vol(b) - delta) / (fixed * free);
    let s = if !ratio.is_finite() {
        1.0
    } else if k == 1.0 {
        ratio.clamp(0.0, 1.0)
    } else if k == 2.0 {
        ratio.max(0.0).sqrt().min(1.0)
    } else {
        ratio.max(0.0).powf(1.0 / k).min(1.0)
    };
    for (j, gj) in g.iter_mut().enumerate() {
        *gj = if j < m {
            a.get(j).copied().unwrap_or(0.0)
        } else {
            s * b.get(j).copied().unwrap_or(0.0)
        };
    }
    // In exact arithmetic s < 1 (vol(b) - vol_fixed(a) vol_free(b) < delta holds for every
    // region of the decomposition); after rounding, force progress.
    if let (Some(gm), Some(&bm)) = (g.get_mut(m), b.get(m))
        && *gm >= bm
    {
        *gm = bm.next_down().max(0.0);
    }
}

/// Work estimate of [`bounds`] for evenly spread points: `(per_point, fixed, complete)`
/// with the work `per_point · N + fixed`, from a pass over the regions without points. It
/// assumes every region holds points ([`Run::region`] ends early at empty regions, so sets
/// with few points run faster than estimated). The pass stops (`complete = false`, partial
/// sums) once the work for `n` points exceeds `limit`.
fn estimate(d: usize, delta: f64, n: f64, limit: f64) -> (f64, f64, bool) {
    // Level L of the recursion (at most d deep) keeps a, b and γ at buf[3dL..3d(L+1)].
    let mut buf = vec![0.0; 3 * d * (d + 1)];
    if let Some(b) = buf.get_mut(d..2 * d) {
        b.fill(1.0);
    }
    let mut e = Estimate {
        d,
        delta,
        n,
        limit,
        buf,
        per_point: 0.0,
        fixed: 0.0,
        complete: true,
    };
    e.walk(0, 0);
    (e.per_point, e.fixed, e.complete)
}

/// State of [`estimate`].
struct Estimate {
    d: usize,
    delta: f64,
    n: f64,
    limit: f64,
    buf: Vec<f64>,
    per_point: f64,
    fixed: f64,
    complete: bool,
}

impl Estimate {
    /// The chain of regions starting at the one stored at `level` (first `m` coordinates
    /// fixed), as in [`Run::region`]; volumes are updated by ratios, close enough for an
    /// estimate. No allocation: the children go to `level + 1`.
    fn walk(&mut self, level: usize, m: usize) {
        let d = self.d;
        let k = (d - m) as f64;
        let base = 3 * d * level;
        let (ia, ib, ig) = (base, base + d, base + 2 * d);
        let mut vb = self.buf.get(ib..ig).map_or(0.0, vol);
        if m + 1 == d && vb > self.delta {
            // Run::last_chain: one pass and two sorts, then a few steps per bracket.
            let len = (vb * self.n).max(1.0);
            self.per_point += vb * (d as f64 + 2.0 * (1.0 + len.log2()));
        }
        while vb > self.delta && self.complete {
            if m + 1 == d {
                self.fixed += 2.0 * REGION_OVERHEAD;
            } else {
                self.fixed += REGION_OVERHEAD * (d as f64 + k);
                self.per_point += vb * (d as f64 + k);
            }
            if self.per_point * self.n + self.fixed > self.limit {
                self.complete = false;
                return;
            }
            if let Some(chunk) = self.buf.get_mut(ia..ig + d) {
                let (ab, g) = chunk.split_at_mut(2 * d);
                let (a, b) = ab.split_at(d);
                split(a, b, m, self.delta, g);
            }
            for i in m + 1..d {
                let gi = self.buf.get(ig + i).copied().unwrap_or(0.0);
                let bi = self.buf.get(ib + i).copied().unwrap_or(1.0);
                if vb * gi / bi > self.delta {
                    // Child i: a with a[m..i] = γ[m..i], b with b[i] = γ_i.
                    let next = base + 3 * d;
                    self.buf.copy_within(ia..ig, next);
                    self.buf.copy_within(ig + m..ig + i, next + m);
                    if let Some(c) = self.buf.get_mut(next + d + i) {
                        *c = gi;
                    }
                    self.walk(level + 1, i);
                } else {
                    self.fixed += REGION_OVERHEAD;
                }
            }
            let gm = self.buf.get(ig + m).copied().unwrap_or(0.0);
            if let Some(c) = self.buf.get_mut(ib + m) {
                vb = vb * gm / *c;
                *c = gm;
            }
        }
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
    total: Mutex<Acc>,
}

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

    /// Adds `w` to the work counter; false once the run is over its cap.
    fn charge(&self, w: u64) -> bool {
        let total = self.work.fetch_add(w, Ordering::Relaxed) + w;
        if total > self.cap {
            self.aborted.store(true, Ordering::Relaxed);
        }
        !self.aborted.load(Ordering::Relaxed)
    }

    /// Decomposes the region `[a, b]` (first `m` coordinates fixed) whose points inside
    /// `[0, b)` are `list`; children with many points are spawned into `scope`.
    fn region<'s>(
        &'s self,
        scope: &rayon::Scope<'s>,
        a: Vec<f64>,
        mut b: Vec<f64>,
        m: usize,
        mut list: Vec<u32>,
        acc: &mut Acc,
    ) {
        let d = self.d;
        let n = self.n;
        if m + 1 == d {
            self.last_chain(&a, b, &list, acc);
            return;
        }
        let mut g = vec![0.0; d];
        loop {
            let vb = vol(&b);
            let qb = list.len() as f64 / n;
            acc.corner(&b, qb, vb);
            if list.is_empty() {
                // Every bracket inside has A = 0, so it gives vol(β) - 0 <= vol(b), attained
                // by the region's own bracket; the test box [0, b) is empty too.
                acc.bracket(0.0, 0.0, 0.0, vb);
                return;
            }
            if vb <= self.delta {
                // The region is a bracket [a, b] itself; vol(a) = 0 and A(a) = 0.
                acc.bracket(0.0, 0.0, qb, vb);
                return;
            }
            let k = d - m;
            if !self.charge((list.len() * (d + k) + REGION_OVERHEAD as usize * (d + k)) as u64) {
                return;
            }
            split(&a, &b, m, self.delta, &mut g);
            let vg = vol(&g);
            let qg = list.iter().filter(|&&i| self.below(i, &g)).count() as f64 / n;
            acc.corner(&g, qg, vg);
            acc.bracket(qg, vg, qb, vb);
            for i in m + 1..d {
                let gi = g.get(i).copied().unwrap_or(0.0);
                let mut cb = b.clone();
                if let Some(c) = cb.get_mut(i) {
                    *c = gi;
                }
                let vcb = vol(&cb);
                if vcb <= self.delta {
                    let count = list.iter().filter(|&&p| self.coord(p, i) < gi).count();
                    let q = count as f64 / n;
                    acc.corner(&cb, q, vcb);
                    acc.bracket(0.0, 0.0, q, vcb);
                    continue;
                }
                let sub: Vec<u32> = list
                    .iter()
                    .copied()
                    .filter(|&p| self.coord(p, i) < gi)
                    .collect();
                if sub.is_empty() {
                    // As at the top of the loop: the child gives vol(b') and nothing else.
                    acc.corner(&cb, 0.0, vcb);
                    acc.bracket(0.0, 0.0, 0.0, vcb);
                    continue;
                }
                let mut ca = a.clone();
                if let (Some(dst), Some(src)) = (ca.get_mut(m..i), g.get(m..i)) {
                    dst.copy_from_slice(src);
                }
                if sub.len() >= SPAWN_POINTS {
                    scope.spawn(move |s| {
                        let mut own = Acc::new(d);
                        self.region(s, ca, cb, i, sub, &mut own);
                        self.merge(own);
                    });
                } else {
                    self.region(scope, ca, cb, i, sub, acc);
                }
            }
            // Child m: same fixed coordinates, b_m lowered to γ_m.
            let gm = g.get(m).copied().unwrap_or(0.0);
            if let Some(c) = b.get_mut(m) {
                *c = gm;
            }
            list.retain(|&p| self.coord(p, m) < gm);
        }
    }
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
            if steps.is_multiple_of(1024) && !self.charge(1024 * REGION_OVERHEAD as u64 * 2) {
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
