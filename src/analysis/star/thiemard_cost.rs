//! The cost model of [`super::thiemard::bounds`]: the work of a region, a lower bound from
//! the first chain alone (`O(1)` memory), and the estimate from a pass over the regions.
//! The split of a region ([`split`]) lives here, as the estimate walks the same regions as
//! the cover: the cover imports it from this module, never the other way round.
//!
//! Units are point-coordinate comparisons at [`super::cost::THIEMARD_RATE`]. A region
//! `[a, b]` with `k = d - m >= 2` free coordinates and `L` points in `[0, b)` costs
//! [`region_cost`]`(d, k, L) = (L + 16)(d + k) + 2 d (k - 1)`: a pass over its list for
//! `A(γ)` and the filtering for its children (`L (d + k)`), the volumes, `γ` and the child
//! corners (`16 (d + k)`), and a copy and a volume of `d` coordinates for each of its
//! `k - 1` children with new fixed coordinates (`2 d (k - 1)`). A step of a chain along the
//! last coordinate costs [`CHAIN_STEP`]` + 3 d` (two volumes and `γ`), and its chain one
//! pass and two sorts of its list once.

use crate::size;
use crate::{Error, Result};

/// Cost units of a region besides its points and children: volumes, `γ`, corners.
pub(super) const REGION_OVERHEAD: f64 = 16.0;

/// Cost units of one step of a chain along the last coordinate besides its `3 d`.
pub(super) const CHAIN_STEP: f64 = 2.0 * REGION_OVERHEAD;

/// Cost of a region with `k >= 2` free coordinates (of `d`) holding `points` points.
pub(super) fn region_cost(d: usize, k: usize, points: f64) -> f64 {
    (points + REGION_OVERHEAD) * (d + k) as f64 + 2.0 * (d * (k - 1)) as f64
}

/// Cost of one step of a chain along the last coordinate, in `d` dimensions.
pub(super) fn chain_step_cost(d: usize) -> f64 {
    CHAIN_STEP + 3.0 * d as f64
}

/// `s` of Thiémard's split (see [`super::thiemard`]) from `ratio` for `k` free coordinates.
pub(super) fn split_factor(ratio: f64, k: usize) -> f64 {
    if !ratio.is_finite() {
        1.0
    } else if k == 1 {
        ratio.clamp(0.0, 1.0)
    } else if k == 2 {
        ratio.max(0.0).sqrt().min(1.0)
    } else {
        ratio.max(0.0).powf(1.0 / k as f64).min(1.0)
    }
}

/// Product of the coordinates.
pub(super) fn vol(c: &[f64]) -> f64 {
    c.iter().product()
}

/// Thiémard's split (see [`super::thiemard`]) of the region `[a, b]` with the first `m`
/// coordinates fixed: writes the lower corner `γ` of its bracket into `g`. Requires
/// `vol(b) > delta`. The free part of `γ` always moves below `b` in coordinate `m`, so the
/// loop along child `m` ends. Shared by the cover and its estimate.
pub(super) fn split(a: &[f64], b: &[f64], m: usize, delta: f64, g: &mut [f64]) {
    let fixed = vol(a.get(..m).unwrap_or(&[]));
    let free = vol(b.get(m..).unwrap_or(&[]));
    let ratio = (vol(b) - delta) / (fixed * free);
    let s = split_factor(ratio, b.len() - m);
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

/// A lower bound on [`estimate`]'s work for `n` points in `d >= 2` dimensions, from the
/// chain of the root region alone, in `O(1)` memory; it stops as soon as it exceeds `limit`
/// (then returns a value above `limit`).
///
/// Along the root chain only `b_0` moves: `b = (b_0, 1, .., 1)`, `vol(b) = b_0`, and the
/// split factor is `s = (1 - δ / b_0)^(1/d)`. Each step is a region with `k = d` free
/// coordinates and its `d - 1` children `i >= 1` have volume `s b_0`: leaves (cost
/// `REGION_OVERHEAD`) when that is at most `δ`, otherwise regions with `d - i` free
/// coordinates (the last one a chain of at least one step), each at least
/// [`region_cost`] with no points. The sum over the children is in closed form.
pub(super) fn root_chain_lower_bound(d: usize, delta: f64, n: f64, limit: f64) -> f64 {
    if d < 2 {
        return 0.0;
    }
    let df = d as f64;
    // Σ_{i=1}^{d-2} region_cost(d, d - i, 0) = Σ_{k=2}^{d-1} (16 (d + k) + 2 d (k - 1)).
    let ks = df - 2.0; // number of k values
    let sum_k = (df - 1.0) * df / 2.0 - 1.0; // Σ_{k=2}^{d-1} k
    let inner = REGION_OVERHEAD * (df * ks + sum_k) + 2.0 * df * (sum_k - ks);
    let inner_children = inner + chain_step_cost(d);
    let leaf_children = REGION_OVERHEAD * (df - 1.0);
    let mut b0: f64 = 1.0;
    let mut total = 0.0;
    while b0 > delta {
        total += region_cost(d, d, n * b0);
        let s = split_factor((b0 - delta) / b0, d);
        total += if s * b0 > delta {
            inner_children
        } else {
            leaf_children
        };
        if total > limit {
            return total;
        }
        let next = s * b0;
        if next >= b0 {
            // Rounding: the run forces progress the same way.
            b0 = b0.next_down();
        } else {
            b0 = next;
        }
    }
    total
}

/// Work estimate of [`super::thiemard::bounds`] for evenly spread points: `(per_point,
/// fixed, complete)` with the work `per_point · N + fixed`, from a pass over the regions
/// without points. It assumes every region holds points (the run ends early at empty
/// regions, so sets with few points run faster than estimated). The pass stops
/// (`complete = false`, partial sums) once the work for `n` points exceeds `limit`.
///
/// The pass is a loop over an explicit stack (no recursion): level `L` of the decomposition
/// (at most `d` deep) keeps `a`, `b` and `γ` in `3 d` values, allocated when the walk first
/// gets there.
///
/// # Errors
/// [`Error::TooLarge`] when those values would pass [`size::MAX_ALLOC_BYTES`] (the walk is
/// then far beyond any budget: `L` levels cost at least `16 L d`).
pub(super) fn estimate(d: usize, delta: f64, n: f64, limit: f64) -> Result<(f64, f64, bool)> {
    let mut e = Estimate {
        d,
        delta,
        n,
        limit,
        buf: Vec::new(),
        per_point: 0.0,
        fixed: 0.0,
        complete: true,
    };
    e.ensure_level(0)?;
    if let Some(b) = e.buf.get_mut(d..2 * d) {
        b.fill(1.0);
    }
    e.walk()?;
    Ok((e.per_point, e.fixed, e.complete))
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

/// A region of the walk: its level in the buffer, its fixed coordinates `m`, its volume
/// `vol(b)` and the next child to visit (`None` before the split of the current step).
struct Frame {
    level: usize,
    m: usize,
    vb: f64,
    next: Option<usize>,
}

impl Estimate {
    /// Makes room for level `level` of the buffer.
    fn ensure_level(&mut self, level: usize) -> Result<()> {
        let want = (level + 1)
            .checked_mul(3)
            .and_then(|x| x.checked_mul(self.d))
            .ok_or(Error::TooLarge {
                what: "bytes",
                requested: u64::MAX,
                max: size::MAX_ALLOC_BYTES,
            })?;
        if want > self.buf.len() {
            size::bytes(want, core::mem::size_of::<f64>())?;
            let more = want - self.buf.len();
            self.buf.try_reserve(more).map_err(|_| Error::TooLarge {
                what: "bytes",
                requested: (want * 8) as u64,
                max: size::MAX_ALLOC_BYTES,
            })?;
            self.buf.resize(want, 0.0);
        }
        Ok(())
    }

    /// Starts the region stored at `level` (first `m` coordinates fixed): its volume, and
    /// the one-off cost of a chain along the last coordinate.
    fn enter(&mut self, level: usize, m: usize) -> Frame {
        let d = self.d;
        let ib = 3 * d * level + d;
        let vb: f64 = self.buf.get(ib..ib + d).map_or(0.0, |b| b.iter().product());
        if m + 1 == d && vb > self.delta {
            // The chain along the last coordinate: one pass and two sorts, then a few steps
            // per bracket.
            let len = (vb * self.n).max(1.0);
            self.per_point += vb * (d as f64 + 2.0 * (1.0 + len.log2()));
        }
        Frame {
            level,
            m,
            vb,
            next: None,
        }
    }

    /// The walk over the regions, depth first, as the run visits them; volumes are updated
    /// by ratios, close enough for an estimate.
    fn walk(&mut self) -> Result<()> {
        let d = self.d;
        let first = self.enter(0, 0);
        let mut stack = vec![first];
        while let Some(f) = stack.last_mut() {
            let (level, m, vb) = (f.level, f.m, f.vb);
            let base = 3 * d * level;
            let (ia, ib, ig) = (base, base + d, base + 2 * d);
            let start = match f.next {
                Some(i) => i,
                None => {
                    if vb <= self.delta || !self.complete {
                        stack.pop();
                        continue;
                    }
                    if m + 1 == d {
                        self.fixed += chain_step_cost(d);
                    } else {
                        self.fixed += region_cost(d, d - m, 0.0);
                        self.per_point += vb * (d + d - m) as f64;
                    }
                    if self.per_point * self.n + self.fixed > self.limit {
                        self.complete = false;
                        return Ok(());
                    }
                    if let Some(chunk) = self.buf.get_mut(ia..ig + d) {
                        let (ab, g) = chunk.split_at_mut(2 * d);
                        let (a, b) = ab.split_at(d);
                        split(a, b, m, self.delta, g);
                    }
                    m + 1
                }
            };
            let mut child = None;
            for i in start..d {
                let gi = self.buf.get(ig + i).copied().unwrap_or(0.0);
                let bi = self.buf.get(ib + i).copied().unwrap_or(1.0);
                if vb * gi / bi > self.delta {
                    child = Some(i);
                    break;
                }
                self.fixed += REGION_OVERHEAD;
            }
            if let Some(i) = child {
                if let Some(f) = stack.last_mut() {
                    f.next = Some(i + 1);
                }
                // Child i: a with a[m..i] = γ[m..i], b with b[i] = γ_i.
                self.ensure_level(level + 1)?;
                let next = base + 3 * d;
                let gi = self.buf.get(ig + i).copied().unwrap_or(0.0);
                self.buf.copy_within(ia..ig, next);
                self.buf.copy_within(ig + m..ig + i, next + m);
                if let Some(c) = self.buf.get_mut(next + d + i) {
                    *c = gi;
                }
                let frame = self.enter(level + 1, i);
                stack.push(frame);
                continue;
            }
            // Child m: the same fixed coordinates, b_m lowered to γ_m; the chain goes on.
            let gm = self.buf.get(ig + m).copied().unwrap_or(0.0);
            if let Some(f) = stack.last_mut() {
                if let Some(c) = self.buf.get_mut(ib + m) {
                    f.vb = f.vb * gm / *c;
                    *c = gm;
                }
                f.next = None;
            }
        }
        Ok(())
    }
}
