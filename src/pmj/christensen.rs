//! Best-candidate PMJ02 ("pmj02bn" as pmj-cpp and the paper name it): progressive
//! multi-jittered (0, 2)-sequences by Christensen, Kensler & Kilpatrick's 2018 construction
//! with Pharr's 2019 valid-strata search ("Efficient generation of points that satisfy
//! two-dimensional elementary intervals"), each point the best of `K` candidates.
//!
//! qmckit's PMJ02BN ([`super::bn`]) does not use this construction: best candidate buys
//! little spacing here (below), nested flips buy much more ([`super::spread`]). It is kept
//! as the reference construction, to compare against pmj-cpp and pbrt's tables.
//!
//! Why not the stochastic construction of the [parent module](super): there, the stratum
//! of width `2^-(L+1)` of point `2^L + i` is forced in both axes, so only the jitter inside a
//! `2^-(L+1) x 2^-(L+1)` square is free, a region `sqrt(2^(L+1))` times smaller than the
//! point spacing. Christensen's construction also leaves the choice of *which* valid x and
//! y strata the point takes.
//!
//! **What best candidate buys (measured, `tests/suite/pmj.rs`)**: little. The valid strata
//! of a point are the leaves of a descent in which each child cell is occupied about half
//! the time (half the cells of every elementary grid hold a point when a pass starts), a
//! critical branching process: mostly one valid stratum an axis, so the candidates differ
//! mostly in their jitter. Mean nearest-neighbour distance over the hexagonal spacing
//! `sqrt(2 / (sqrt(3) N))`, `N = 4096`, 4 seeds: stochastic PMJ02 0.603, this construction
//! with `K = 1` 0.612, `K = 10` 0.613, `K = 100` 0.604; pmj-cpp's own `pmj02` and
//! `pmj02bn` (an independent implementation, 4 sets each) 0.610 and 0.600. The minimum
//! distance gains more (0.057 stochastic, 0.082 to 0.100 with candidates). Choosing the
//! sub-quadrant per candidate instead of per pass raises the spacing at `3N/4` (0.65) but
//! breaks Christensen's balance: aligned blocks stop being nets, so it is not offered.
//!
//! The construction, with `n = 4^h` points placed:
//! * points `n + i` (`i < n`): in the `2^(h+1) x 2^(h+1)` grid, point `i` lies in one of the
//!   four sub-quadrants of its cell; point `n + i` goes to the diagonally opposite one;
//! * points `2n + i`: one global coin per pass chooses, for every `i`, the sub-quadrant next
//!   to point `i`'s in x (or, for every `i`, in y) (Christensen's balance: the sub-sequences
//!   between odd and even powers of two are (0, 2)-sequences too); points `3n + i` take the
//!   last sub-quadrant of the cell;
//! * inside its sub-quadrant a point takes an x stratum (width `1/N` for the `N = 2n` or
//!   `4n` points of the pass) and a y stratum such that no elementary interval of area `1/N`
//!   already holds a point: the valid x strata are the leaves of a descent from the
//!   sub-quadrant through the elementary grids `2^a x 2^(m-a)` toward `N x 1` that only
//!   enters empty cells (the y strata likewise toward `1 x N`); the two choices are
//!   independent (Pharr 2019). The point is uniform in the chosen strata.
//!
//! Best candidate: each point draws `K` candidates (random valid x and y strata, random
//! jitter) and keeps the one farthest, on the torus, from every point placed before it
//! (Mitchell 1991). The strata constraint is met by every candidate, so the (0, 2) property
//! does not depend on `K`; `K = 1` is plain PMJ02 by Christensen's construction.
//!
//! Storage is the caller's (`no_std`): the `N` points, and a workspace of
//! [`workspace_len`]`(N)` words: occupancy bits of the `log2 N + 1` elementary grids and a
//! nearest-neighbour grid of `2^floor(m/2)` cells a side holding at most `2^(m mod 2)`
//! points each (a (0, m, 2)-net puts exactly that many points in each such cell, so the
//! net structure itself bounds it; `m = log2` of the pass size).
//!
//! Cost: `O(N log N)` for the occupancy bits, plus `O(N K)` nearest-neighbour searches of
//! a few cells each (rings of cells, searched outward until no unscanned cell can be
//! nearer). Any length up to [`MAX_POINTS`]. Seeded and deterministic (every random choice
//! is [`crate::hash::uniform`] of the seed, the point index and a stream number).
//!
//! ```
//! use qmckit::pmj::christensen::{self, DEFAULT_CANDIDATES};
//! let mut pts = [[0u32; 2]; 64];
//! let mut work = [0u32; 256];
//! assert!(christensen::workspace_len(64)? <= work.len());
//! let unlimited = &qmckit::work::Budget::UNLIMITED;
//! christensen::fill(7, DEFAULT_CANDIDATES, &mut pts, &mut work, unlimited)?;
//! // One point in every cell of the 8 x 8 grid.
//! let mut seen = [false; 64];
//! for p in &pts { seen[((p[1] >> 29) * 8 + (p[0] >> 29)) as usize] = true; }
//! assert!(seen.iter().all(|&s| s));
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::{ceil_log2, check_len, top};
use crate::error::{Error, Result};
use crate::hash::uniform;
use crate::work::{Budget, Pacer};

/// The default number of best-candidate trials a point: 100, as pmj-cpp's
/// `kBestCandidateSamples` (UTK's `SamplerPMJ` uses 10; more candidates give slightly
/// larger spacing at proportional cost).
pub const DEFAULT_CANDIDATES: u32 = 100;

/// The most candidates a point [`fill`] accepts.
pub const MAX_CANDIDATES: u32 = 1 << 12;

/// The longest sequence [`fill`] generates, `2^30` points.
pub const MAX_POINTS: usize = 1 << 30;

/// An empty slot of the nearest-neighbour grid.
const EMPTY: u32 = u32::MAX;

/// The words of workspace [`fill`] needs for `n` points: with `R = 2^m` the smallest power
/// of two `>= n`, `R` grid slots, `(m + 1) R` occupancy bits and two strata lists of
/// `2^ceil(m/2)` entries.
///
/// # Errors
/// [`Error::TooManyPoints`] past [`MAX_POINTS`].
pub const fn workspace_len(n: usize) -> Result<usize> {
    if let Err(e) = check_len(n, MAX_POINTS) {
        return Err(e);
    }
    if n == 0 {
        return Ok(0);
    }
    let m = ceil_log2(n);
    let r = 1usize << m;
    let bits = (m as usize + 1) * r;
    Ok(r + bits.div_ceil(32) + 2 * (1usize << m.div_ceil(2)))
}

/// A point in stratum `s` of width `2^-m`, jittered by the top bits of `jitter`.
#[inline]
const fn compose(s: u32, m: u32, jitter: u32) -> u32 {
    if m == 0 {
        jitter
    } else {
        (s << (32 - m)) | (jitter >> m)
    }
}

/// A uniform integer in `[0, len)` from a 0.32 fraction (`len <= 2^32`).
#[inline]
const fn pick(r: u32, len: usize) -> usize {
    ((r as u64 * len as u64) >> 32) as usize
}

/// Squared toroidal distance of two points in 0.32 fixed point.
#[inline]
fn dist2(a: [u32; 2], b: [u32; 2]) -> u64 {
    let dx = (a[0].wrapping_sub(b[0]) as i32).unsigned_abs() as u64;
    let dy = (a[1].wrapping_sub(b[1]) as i32).unsigned_abs() as u64;
    dx * dx + dy * dy
}

/// The per-pass state: occupancy bits of the elementary grids of `2^m` cells, the
/// nearest-neighbour grid, the strata lists.
struct Pass<'w> {
    occ: &'w mut [u32],
    grid: &'w mut [u32],
    xs: &'w mut [u32],
    ys: &'w mut [u32],
    m: u32,
    /// `log2` of the nearest-neighbour grid's side.
    side: u32,
    /// Points a nearest-neighbour cell holds (1 or 2).
    slots: usize,
}

impl Pass<'_> {
    /// Bit index of cell `(xc, yc)` of the grid with `g` y bits and `m - g` x bits.
    #[inline]
    fn bit(&self, g: u32, xc: u32, yc: u32) -> usize {
        (g as usize) * (1usize << self.m) + (((yc as usize) << (self.m - g)) | xc as usize)
    }

    #[inline]
    fn occupied(&self, g: u32, xc: u32, yc: u32) -> bool {
        let b = self.bit(g, xc, yc);
        self.occ
            .get(b / 32)
            .is_some_and(|w| (w >> (b % 32)) & 1 == 1)
    }

    /// Starts a pass of `2^m` points with the `placed` points already there.
    fn begin(&mut self, m: u32, placed: &[[u32; 2]]) {
        self.m = m;
        self.side = m / 2;
        self.slots = 1 << (m - 2 * self.side);
        let r = 1usize << m;
        let words = ((m as usize + 1) * r).div_ceil(32);
        self.occ.iter_mut().take(words).for_each(|w| *w = 0);
        self.grid.iter_mut().take(r).for_each(|w| *w = EMPTY);
        for (k, &p) in placed.iter().enumerate() {
            self.mark(k as u32, p);
        }
    }

    /// Records point `k` at `p` in every elementary grid and the nearest-neighbour grid.
    fn mark(&mut self, k: u32, p: [u32; 2]) {
        for g in 0..=self.m {
            let b = self.bit(g, top(p[0], self.m - g), top(p[1], g));
            if let Some(w) = self.occ.get_mut(b / 32) {
                *w |= 1 << (b % 32);
            }
        }
        let cell = ((top(p[1], self.side) as usize) << self.side) | top(p[0], self.side) as usize;
        for s in 0..self.slots {
            if let Some(slot) = self.grid.get_mut(cell * self.slots + s)
                && *slot == EMPTY
            {
                *slot = k;
                break;
            }
        }
    }

    /// The valid x strata below cell `(xc, yc)` of grid `g`, into `xs` from `len`.
    fn collect_x(&mut self, g: u32, xc: u32, yc: u32, len: &mut usize) {
        if self.occupied(g, xc, yc) {
            return;
        }
        if g == 0 {
            if let Some(s) = self.xs.get_mut(*len) {
                *s = xc;
                *len += 1;
            }
            return;
        }
        self.collect_x(g - 1, 2 * xc, yc >> 1, len);
        self.collect_x(g - 1, 2 * xc + 1, yc >> 1, len);
    }

    /// The valid y strata below cell `(xc, yc)` of grid `g`, into `ys` from `len`.
    fn collect_y(&mut self, g: u32, xc: u32, yc: u32, len: &mut usize) {
        if self.occupied(g, xc, yc) {
            return;
        }
        if g == self.m {
            if let Some(s) = self.ys.get_mut(*len) {
                *s = yc;
                *len += 1;
            }
            return;
        }
        self.collect_y(g + 1, xc >> 1, 2 * yc, len);
        self.collect_y(g + 1, xc >> 1, 2 * yc + 1, len);
    }

    /// Squared toroidal distance from `c` to its nearest placed point, or any value at most
    /// `bound` once it is known to be at most `bound`.
    fn nearest(&self, pts: &[[u32; 2]], c: [u32; 2], bound: u64) -> u64 {
        let s = 1i64 << self.side;
        let w = 1u64 << (32 - self.side);
        let (cx, cy) = (top(c[0], self.side) as i64, top(c[1], self.side) as i64);
        let mut best = u64::MAX;
        let visit = |dx: i64, dy: i64, best: &mut u64| {
            let x = (cx + dx).rem_euclid(s) as usize;
            let y = (cy + dy).rem_euclid(s) as usize;
            let cell = (y << self.side) | x;
            for k in 0..self.slots {
                match self.grid.get(cell * self.slots + k) {
                    Some(&i) if i != EMPTY => {
                        if let Some(&p) = pts.get(i as usize) {
                            *best = (*best).min(dist2(p, c));
                        }
                    }
                    _ => break,
                }
            }
        };
        for ring in 0..=(s / 2) {
            if ring == 0 {
                visit(0, 0, &mut best);
            } else {
                for dx in -ring..=ring {
                    visit(dx, -ring, &mut best);
                    visit(dx, ring, &mut best);
                }
                for dy in (1 - ring)..ring {
                    visit(-ring, dy, &mut best);
                    visit(ring, dy, &mut best);
                }
            }
            // Every unscanned cell is `ring + 1` cells away on an axis: its points are at
            // least `ring` cell widths from `c`.
            let reach = ring as u64 * w;
            if best <= reach * reach || best <= bound {
                break;
            }
        }
        best
    }

    /// Places point `k` in sub-quadrant `(xp, yp)` of the `2^ceil(m/2)` grid, the best of
    /// `candidates` trials.
    fn place(
        &mut self,
        seed: u64,
        candidates: u32,
        pts: &mut [[u32; 2]],
        k: usize,
        (xp, yp): (u32, u32),
        pacer: &mut Pacer,
    ) -> Result<()> {
        pacer.tick_n(candidates)?;
        let m = self.m;
        let h = m.div_ceil(2);
        let (gx, gy) = (m - h, h);
        let (mut nx, mut ny) = (0, 0);
        self.collect_x(gx, xp, yp >> (h - gx), &mut nx);
        self.collect_y(gy, xp >> (h - (m - h)), yp, &mut ny);
        if nx == 0 || ny == 0 {
            return Err(Error::InvalidParameter {
                what: "PMJ02 best candidate found no valid stratum (a construction invariant failed)",
            });
        }
        let (placed, rest) = pts.split_at_mut(k);
        let mut best = [0u32; 2];
        let mut best_d = 0u64;
        for c in 0..candidates as u64 {
            let r = |j: u64| uniform(seed, k as u32, 2 + 4 * c + j);
            let sx = self.xs.get(pick(r(0), nx)).copied().unwrap_or(0);
            let sy = self.ys.get(pick(r(1), ny)).copied().unwrap_or(0);
            let cand = [compose(sx, m, r(2)), compose(sy, m, r(3))];
            if candidates == 1 {
                best = cand;
                break;
            }
            let d = self.nearest(placed, cand, best_d);
            if c == 0 || d > best_d {
                best = cand;
                best_d = d;
            }
        }
        if let Some(slot) = rest.first_mut() {
            *slot = best;
        }
        self.mark(k as u32, best);
        Ok(())
    }
}

/// The first `out.len()` points of the best-candidate PMJ02 sequence of `seed` with `candidates`
/// best-candidate trials a point (see the [module documentation](self)); `work` is scratch
/// of at least [`workspace_len`]`(out.len())` words. Every aligned block of `2^m` points is
/// a (0, m, 2)-net. Deterministic: the same arguments give the same points, and a shorter
/// `out` gets a prefix of a longer one's (the passes do not depend on the length).
///
/// # Errors
/// [`Error::TooManyPoints`] past [`MAX_POINTS`]; [`Error::InvalidParameter`] for
/// `candidates` outside `1..=`[`MAX_CANDIDATES`]; [`Error::BufferLength`] for a short `work`;
/// [`Error::OutOfTime`] past the deadline of `budget` (started on entry if it was not;
/// [`Budget::UNLIMITED`] has none), whose clock is read (with `std`) about once every
/// [`crate::work::PACER_INTERVAL`] candidates (`out` then holds only a prefix of the
/// sequence: discard it). Within the deadline the points are the same bit for bit whatever
/// the budget.
pub fn fill(
    seed: u64,
    candidates: u32,
    out: &mut [[u32; 2]],
    work: &mut [u32],
    budget: &Budget,
) -> Result<()> {
    let n = out.len();
    let need = workspace_len(n)?;
    if candidates == 0 || candidates > MAX_CANDIDATES {
        return Err(Error::InvalidParameter {
            what: "PMJ02 best-candidate counts must be 1..=4096",
        });
    }
    if work.len() < need {
        return Err(Error::BufferLength {
            expected: need,
            got: work.len(),
        });
    }
    if n == 0 {
        return Ok(());
    }
    let mm = ceil_log2(n);
    let r = 1usize << mm;
    let words = ((mm as usize + 1) * r).div_ceil(32);
    let (grid, rest) = work.split_at_mut(r);
    let (occ, rest) = rest.split_at_mut(words);
    let half = rest.len() / 2;
    let (xs, ys) = rest.split_at_mut(half);
    let mut pass = Pass {
        occ,
        grid,
        xs,
        ys,
        m: 0,
        side: 0,
        slots: 1,
    };
    let mut pacer = budget.started().pacer("PMJ02 best candidate");
    out[0] = [uniform(seed, 0, 0), uniform(seed, 0, 1)];
    let mut q = 1usize; // 4^h points placed at the start of a round
    let mut m = 0u32; // log2(q)
    while q < n {
        // Points q + i: the sub-quadrant diagonally opposite point i's.
        pass.begin(m + 1, &out[..q]);
        let h = (m + 2) / 2;
        for i in 0..q.min(n - q) {
            let p = out[i];
            let sub = (top(p[0], h) ^ 1, top(p[1], h) ^ 1);
            pass.place(seed, candidates, out, q + i, sub, &mut pacer)?;
        }
        if 2 * q >= n {
            break;
        }
        // Points 2q + i next to point i's sub-quadrant, all in x or all in y; 3q + i the
        // last sub-quadrant.
        pass.begin(m + 2, &out[..2 * q]);
        let swap_x = uniform(seed, m, u64::MAX) >> 31 == 1;
        for pass_no in 0..2usize {
            let start = (2 + pass_no) * q;
            for i in 0..q.min(n.saturating_sub(start)) {
                let p = out[i];
                let (mut xp, mut yp) = (top(p[0], h), top(p[1], h));
                if swap_x {
                    xp ^= 1;
                } else {
                    yp ^= 1;
                }
                if pass_no == 1 {
                    xp ^= 1;
                    yp ^= 1;
                }
                pass.place(seed, candidates, out, start + i, (xp, yp), &mut pacer)?;
            }
        }
        q *= 4;
        m += 2;
    }
    Ok(())
}
