//! Spreading a (0, 2)-sequence apart by nested flips: the blue-noise step of PMJ02BN.
//!
//! A nested flip of depth `d` in x, at column `q` (the points whose top `d` bits of x are
//! `q`), complements bit `d + 1` of their x: the two halves of the column swap places. Any
//! set of such flips, in either axis, is a nested (Owen) scramble, a bijection that maps
//! every elementary interval onto an elementary interval of the same shape (Owen 1995). So
//! every aligned block of `2^m` points that was a (0, m, 2)-net stays one, whatever flips
//! are chosen: the flips are free parameters, and [`spread`] chooses them to push
//! neighbours apart, as Ahmed & Wonka 2021 ("Optimizing dyadic nets") do for a single net,
//! here for every power-of-two prefix of a sequence at once.
//!
//! **The energy.** For the prefix of `P = 2^k` points, `E_k = sum over pairs of
//! (1 - r^2 / R_k^2)^2` for `r < R_k = P^(-1/2)` (toroidal distance `r`; a compactly
//! supported repulsion of one point spacing), and the total is `sum_k E_k / P`, so every
//! prefix weighs the same per point. The partial last block of a length that is not a power
//! of two counts as the prefix of the next power.
//!
//! **The greedy sweep.** Depths `d = 1 ..= K - 1` (`K = ceil(log2 n)`), coarse to fine; at
//! each depth the x columns, then the y rows, one at a time: flip, and keep the flip only
//! if the total energy went down. Depth 0 is a translation by 1/2 on the torus and changes
//! nothing. One sweep: a second changes the spacing by less than 1%.
//!
//! **What it buys (measured, `tests/suite/pmj.rs`).** The mean nearest-neighbour distance
//! over the hexagonal spacing, at every power-of-two prefix from 2^6 to 2^12, rises from
//! 0.60-0.62 (PMJ02, with or without best candidate) to 0.66-0.71.
//!
//! **Neighbours without a search.** A (0, k, 2)-net has exactly one point in every cell of
//! every elementary grid, and a flip only permutes a grid's columns (or rows) or moves
//! points inside their cells. So each prefix keeps three grids that a flip updates by
//! swapping half-columns: the `2^floor(k/2) x 2^ceil(k/2)` grid of the points'
//! coordinates, where the neighbours of a point are the points of the `3 x 3` cells around
//! it (`3 x 5` for odd `k`, whose cells are shorter than `R_k`), and the `2^k` strata of x
//! and of y (point indices), where a flipped column's points are one run. A column wider than a cell swaps its halves
//! rigidly, so only its points within `R_k` of the halves' edges are visited; a flip that
//! keeps every point in its cell is scored before and after in one pass, without applying
//! it.
//!
//! Cost: `O(K n)` kernel evaluations for `n` points, `K = ceil(log2 n)`, integer
//! arithmetic only (timings in docs/pixel-samplers.md). Storage: the caller's
//! [`workspace_len`]`(n)` words (`8n` to `16n`), no allocation.
//!
//! ```
//! use qmckit::pmj::{fill, spread};
//! let mut pts = [[0u32; 2]; 256];
//! fill(3, &mut pts)?;
//! let mut work = [0u32; 2048];
//! assert!(spread::workspace_len(256)? <= work.len());
//! spread::spread(&mut pts, &mut work, &qmckit::work::Budget::UNLIMITED)?;
//! // Still one point in every cell of the 16 x 16 grid (and of every elementary grid).
//! let mut seen = [false; 256];
//! for p in &pts { seen[((p[1] >> 28) * 16 + (p[0] >> 28)) as usize] = true; }
//! assert!(seen.iter().all(|&s| s));
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::{ceil_log2, check_len, top};
use crate::error::{Error, Result};
use crate::work::Budget;

/// The longest sequence [`spread`] accepts, `2^30` points.
pub const MAX_POINTS: usize = 1 << 30;

/// An empty cell of a prefix table (only the last, partial, prefix has them).
const EMPTY: u32 = u32::MAX;

/// The words of workspace [`spread`] needs for `n` points: for each prefix
/// `k = 1 ..= K = ceil(log2 n)`, two strata grids of `2^k` indices and a grid of `2^k`
/// coordinate pairs, `4 (2^(K+1) - 2)` words in all (`8n` for a power of two).
///
/// # Errors
/// [`Error::TooManyPoints`] past [`MAX_POINTS`].
pub const fn workspace_len(n: usize) -> Result<usize> {
    if let Err(e) = check_len(n, MAX_POINTS) {
        return Err(e);
    }
    Ok(4 * table_offset(ceil_log2(n) + 1))
}

/// `sum_{j < k} 2^j` over `j >= 1`: where the grids of prefix `k >= 1` start, in units of
/// one grid a prefix.
const fn table_offset(k: u32) -> usize {
    (1usize << k) - 2
}

/// Toroidal distance of two 0.32 coordinates, in units of `2^-32`.
#[inline]
fn wrap(a: u32, b: u32) -> u64 {
    let d = a.wrapping_sub(b);
    d.min(d.wrapping_neg()) as u64
}

/// One flip: `axis` (0 = x, 1 = y), `depth` `d` (bit `d + 1` of the coordinate) and the
/// column (or row) `q`, the top `d` bits.
#[derive(Clone, Copy)]
struct Flip {
    axis: usize,
    depth: u32,
    q: u32,
}

impl Flip {
    /// Whether a point lies in the flipped column.
    #[inline]
    fn holds(self, p: &[u32; 2]) -> bool {
        top(p[self.axis], self.depth) == self.q
    }
}

/// An elementary grid of `2^bits[0] x 2^bits[1]` cells, cell `(cx, cy)` at
/// `cy 2^bits[0] + cx`, each holding the point in it (its index or its coordinates).
#[derive(Clone, Copy)]
struct Grid {
    bits: [u32; 2],
}

impl Grid {
    #[inline]
    const fn cell(&self, c: [u32; 2]) -> usize {
        ((c[1] as usize) << self.bits[0]) | c[0] as usize
    }

    #[inline]
    const fn cell_of(&self, p: &[u32; 2]) -> usize {
        self.cell([top(p[0], self.bits[0]), top(p[1], self.bits[1])])
    }

    /// Swaps the half-columns `flip` exchanges, if the flip moves points between cells.
    fn apply<T>(&self, cells: &mut [T], flip: Flip) {
        let ab = self.bits[flip.axis];
        if flip.depth >= ab {
            return;
        }
        let ob = self.bits[1 - flip.axis];
        let half = 1u32 << (ab - flip.depth - 1);
        let first = flip.q << (ab - flip.depth);
        for col in first..first + half {
            for other in 0..1u32 << ob {
                let (mut c, mut e) = ([0u32; 2], [0u32; 2]);
                c[flip.axis] = col;
                e[flip.axis] = col + half;
                c[1 - flip.axis] = other;
                e[1 - flip.axis] = other;
                cells.swap(self.cell(c), self.cell(e));
            }
        }
    }
}

/// The grids kept for the prefix of `2^k` points, each with exactly one point a cell (the
/// prefix is a (0, k, 2)-net; the partial last prefix leaves some empty): the `2^k` strata
/// of x and of y (point indices), where the points of a flipped column are one run of
/// cells and a flip swaps its two halves, and the near-square `2^floor(k/2) x
/// 2^ceil(k/2)` grid the neighbours are found in, holding the points' coordinates (so a
/// neighbour search reads neighbouring memory). An empty cell holds `[EMPTY, EMPTY]` (a point
/// exactly there, probability `2^-64` for uniform jitter, would be taken for an empty
/// cell: it is left out of the energy, which only weakens the spacing, never the nets).
struct Prefix {
    k: u32,
}

impl Prefix {
    /// The strata grid of `axis`.
    const fn strata_grid(&self, axis: usize) -> Grid {
        let mut bits = [0; 2];
        bits[axis] = self.k;
        Grid { bits }
    }

    const fn square(&self) -> Grid {
        Grid {
            bits: [self.k / 2, self.k - self.k / 2],
        }
    }

    /// Where the grids of this prefix start in the workspace (four words a cell for each
    /// `2^j` cells, `j` in `1..k`): the x strata, the y strata, then the square grid.
    const fn offset(&self) -> usize {
        4 * table_offset(self.k)
    }

    /// The strata of `axis` of this prefix.
    fn strata<'w>(&self, work: &'w [u32], axis: usize) -> &'w [u32] {
        let start = self.offset() + (axis << self.k);
        &work[start..start + (1 << self.k)]
    }

    /// This prefix's three grids, mutable: the strata of x and of y, the square grid.
    fn grids_mut<'w>(
        &self,
        work: &'w mut [u32],
    ) -> (&'w mut [u32], &'w mut [u32], &'w mut [[u32; 2]]) {
        let n = 1usize << self.k;
        let all = &mut work[self.offset()..self.offset() + 4 * n];
        let (x, rest) = all.split_at_mut(n);
        let (y, sq) = rest.split_at_mut(n);
        (x, y, sq.as_chunks_mut::<2>().0)
    }

    /// The square grid's cells.
    fn coords<'w>(&self, work: &'w [u32]) -> &'w [[u32; 2]] {
        let n = 1usize << self.k;
        let start = self.offset() + 2 * n;
        work[start..start + 2 * n].as_chunks::<2>().0
    }

    /// Cells of the square grid searched around a point's, in x and in y: the kernel's
    /// reach `R_k` is at most one cell wide and, for odd `k`, up to two cells tall.
    const fn reach(&self) -> [u32; 2] {
        [1, 1 + (self.k & 1)]
    }

    /// The strata of the flip's axis that hold this prefix's points in `flip`'s column: a
    /// run of `2^(k-d)`, or the one stratum that contains a column narrower than a stratum
    /// (its point may lie outside the column: see [`Flip::holds`]).
    const fn run(&self, flip: Flip) -> core::ops::Range<usize> {
        if flip.depth < self.k {
            let first = (flip.q as usize) << (self.k - flip.depth);
            first..first + (1 << (self.k - flip.depth))
        } else {
            let s = (flip.q >> (flip.depth - self.k)) as usize;
            s..s + 1
        }
    }

    /// The points of this prefix in `flip`'s column whose energy the flip can change. When
    /// the column is wider than a cell of the square grid, its two halves swap rigidly, so
    /// only pairs with a point within the kernel's reach of a half's edges change: only
    /// the square grid's columns at those edges are visited.
    fn for_each_in<F: FnMut(u32)>(&self, work: &[u32], flip: Flip, mut f: F) {
        let strata = self.strata(work, flip.axis);
        let run = self.run(flip);
        let (first, half) = (run.start, run.len() / 2);
        let w = (self.reach()[flip.axis] as usize) << (self.k - self.square().bits[flip.axis]);
        let mut visit = |r: core::ops::Range<usize>| {
            for &i in &strata[r] {
                if i != EMPTY {
                    f(i);
                }
            }
        };
        for h0 in [first, first + half] {
            if 2 * w >= half {
                visit(h0..h0 + half);
            } else {
                visit(h0..h0 + w);
                visit(h0 + half - w..h0 + half);
            }
        }
    }

    /// Calls `f` with every point of this prefix in the square-grid cells around `p`'s
    /// (within the kernel's reach), other than `p`.
    #[inline]
    fn for_each_neighbour<F: FnMut(&[u32; 2])>(&self, work: &[u32], p: [u32; 2], mut f: F) {
        let sq = self.square();
        let cells = self.coords(work);
        let reach = self.reach();
        let mut lo = [0u32; 2];
        let mut span = [0u32; 2];
        for ax in 0..2 {
            let side = 1u32 << sq.bits[ax];
            let full = 2 * reach[ax] + 1;
            if full >= side {
                span[ax] = side;
            } else {
                span[ax] = full;
                lo[ax] = top(p[ax], sq.bits[ax]).wrapping_sub(reach[ax]) & (side - 1);
            }
        }
        for oy in 0..span[1] {
            let cy = (lo[1] + oy) & ((1u32 << sq.bits[1]) - 1);
            for ox in 0..span[0] {
                let cx = (lo[0] + ox) & ((1u32 << sq.bits[0]) - 1);
                let q = &cells[sq.cell([cx, cy])];
                if *q != p && *q != [EMPTY; 2] {
                    f(q);
                }
            }
        }
    }

    /// The kernel `(1 - r^2 / R_k^2)^2` of two points, in 0.24 fixed point (0 past `R_k`).
    #[inline]
    fn kernel(&self, p: &[u32; 2], q: &[u32; 2]) -> u64 {
        let r2 = 1u64 << (64 - self.k);
        let (dx, dy) = (wrap(p[0], q[0]), wrap(p[1], q[1]));
        let d2 = dx * dx + dy * dy;
        if d2 < r2 {
            // The fraction keeps 16 bits: (R^2 - r^2) / R^2 in 0.16.
            let u = (r2 - d2) >> (48 - self.k);
            (u * u) >> 8
        } else {
            0
        }
    }

    /// Twice the energy between `p` and its neighbours in this prefix, counting the pairs
    /// inside `flip`'s column once and the others twice (so that summing over the column's
    /// points counts every pair the flip can change exactly twice).
    fn energy(&self, work: &[u32], p: [u32; 2], flip: Flip) -> u64 {
        let mut sum = 0u64;
        self.for_each_neighbour(work, p, |q| {
            let w = self.kernel(&p, q);
            sum += if flip.holds(q) { w } else { 2 * w };
        });
        sum
    }

    /// [`Self::energy`] of `p` before and after `flip`, in one pass, for a flip that moves
    /// no point out of its cell of the square grid: after it, `p` and its neighbours in the
    /// column have the flipped bit complemented, the others are where they were.
    fn energy_pair(&self, work: &[u32], p: [u32; 2], flip: Flip) -> (u64, u64) {
        let bit = 1u32 << (31 - flip.depth);
        let mut moved = p;
        moved[flip.axis] ^= bit;
        let (mut before, mut after) = (0u64, 0u64);
        self.for_each_neighbour(work, p, |q| {
            if flip.holds(q) {
                let mut q2 = *q;
                q2[flip.axis] ^= bit;
                before += self.kernel(&p, q);
                after += self.kernel(&moved, &q2);
            } else {
                before += 2 * self.kernel(&p, q);
                after += 2 * self.kernel(&moved, q);
            }
        });
        (before, after)
    }

    /// Whether `flip` moves points between cells of this prefix's square grid.
    const fn moves_cells(&self, flip: Flip) -> bool {
        flip.depth < self.square().bits[flip.axis]
    }

    /// Fills this prefix's grids from the first `2^k` points.
    fn build(&self, work: &mut [u32], pts: &[[u32; 2]]) -> Result<()> {
        let (x, y, sq) = self.grids_mut(work);
        x.fill(EMPTY);
        y.fill(EMPTY);
        sq.fill([EMPTY; 2]);
        let taken = Error::InvalidParameter {
            what: "points to spread must be a (0, 2)-sequence: two share a stratum",
        };
        for (i, p) in pts.iter().enumerate().take(1 << self.k) {
            for (axis, cells) in [&mut *x, &mut *y].into_iter().enumerate() {
                let c = self.strata_grid(axis).cell_of(p);
                if cells[c] != EMPTY {
                    return Err(taken);
                }
                cells[c] = i as u32;
            }
            let c = self.square().cell_of(p);
            if sq[c] != [EMPTY; 2] {
                return Err(taken);
            }
            sq[c] = *p;
        }
        Ok(())
    }

    /// Applies `flip` to this prefix's grids, the points having been flipped already.
    fn apply(&self, work: &mut [u32], pts: &[[u32; 2]], flip: Flip) {
        let (x, y, sq) = self.grids_mut(work);
        let strata = if flip.axis == 0 { x } else { y };
        self.strata_grid(flip.axis).apply(strata, flip);
        let square = self.square();
        square.apply(sq, flip);
        for &i in &strata[self.run(flip)] {
            if let Some(p) = pts.get(i as usize)
                && flip.holds(p)
            {
                sq[square.cell_of(p)] = *p;
            }
        }
    }
}

/// The weighted energy every prefix's points in `flip`'s column have, over the prefixes
/// whose square grid the flip rearranges: `sum_k 2^(K-k)` times each prefix's (each prefix
/// weighs the same per point).
fn column_energy(work: &[u32], pts: &[[u32; 2]], top_k: u32, flip: Flip) -> u64 {
    let mut total = 0u64;
    for k in flip.depth + 1..=top_k {
        let pre = Prefix { k };
        if pre.moves_cells(flip) {
            let mut e = 0u64;
            pre.for_each_in(work, flip, |i| e += pre.energy(work, pts[i as usize], flip));
            total += e << (top_k - k);
        }
    }
    total
}

/// The weighted energies, before and after `flip`, over the other prefixes (those whose
/// points the flip moves inside their cells), without applying it.
fn column_energy_pair(work: &[u32], pts: &[[u32; 2]], top_k: u32, flip: Flip) -> (u64, u64) {
    let (mut before, mut after) = (0u64, 0u64);
    for k in flip.depth + 1..=top_k {
        let pre = Prefix { k };
        if !pre.moves_cells(flip) {
            let (mut b, mut a) = (0u64, 0u64);
            pre.for_each_in(work, flip, |i| {
                let (eb, ea) = pre.energy_pair(work, pts[i as usize], flip);
                b += eb;
                a += ea;
            });
            before += b << (top_k - k);
            after += a << (top_k - k);
        }
    }
    (before, after)
}

/// Applies `flip` to the points and to every prefix's grids.
fn apply(work: &mut [u32], pts: &mut [[u32; 2]], top_k: u32, flip: Flip) {
    let bit = 1u32 << (31 - flip.depth);
    // The last prefix holds every point; its strata list the column's as one run.
    let last = Prefix { k: top_k };
    for &i in &last.strata(work, flip.axis)[last.run(flip)] {
        if let Some(p) = pts.get_mut(i as usize) {
            p[flip.axis] ^= bit;
        }
    }
    for k in 1..=top_k {
        Prefix { k }.apply(work, pts, flip);
    }
}

/// Whether `work` words suffice for [`spread`] over `n` points.
///
/// # Errors
/// [`Error::TooManyPoints`] past [`MAX_POINTS`]; [`Error::BufferLength`] for a short `work`.
pub const fn check_work(n: usize, work: usize) -> Result<()> {
    match workspace_len(n) {
        Ok(need) if work < need => Err(Error::BufferLength {
            expected: need,
            got: work,
        }),
        Ok(_) => Ok(()),
        Err(e) => Err(e),
    }
}

/// Chooses nested flips of `pts` (see the [module documentation](self)) that lower the
/// energy of every power-of-two prefix, in place. `pts` should be a (0, 2)-sequence (every
/// aligned block of `2^m` points a (0, m, 2)-net, as [`super::fill`] and
/// [`super::bn::fill`] give); the result is a nested scramble of it, so it is one too.
/// `work` is scratch of at least [`workspace_len`]`(pts.len())` words. Deterministic.
///
/// # Errors
/// [`Error::TooManyPoints`] past [`MAX_POINTS`]; [`Error::BufferLength`] for a short
/// `work`; [`Error::InvalidParameter`] if two of the first `2^k` points share a stratum of
/// width `2^-k` or a cell of the `2^floor(k/2) x 2^ceil(k/2)` grid (then `pts` is not a
/// (0, 2)-sequence), with `pts` unchanged; [`Error::OutOfTime`] past the deadline of
/// `budget`, with `pts` a nested scramble of the input (still a (0, 2)-sequence, every net
/// intact) whose flips are only partly chosen: not the result, to be discarded.
///
/// The deadline of `budget` (started on entry if it was not; [`Budget::UNLIMITED`] has
/// none) bounds the sweep: it reads the clock (with `std`) about once every
/// [`crate::work::PACER_INTERVAL`] points its flips visit, so it stops within a few
/// milliseconds of the deadline. No estimate is checked here: the caller estimates
/// (`O(n log n)`, see the module text).
pub fn spread(pts: &mut [[u32; 2]], work: &mut [u32], budget: &Budget) -> Result<()> {
    let n = pts.len();
    check_work(n, work.len())?;
    let mut pacer = budget.started().pacer("PMJ02BN spread");
    let top_k = ceil_log2(n);
    if top_k < 2 {
        return Ok(());
    }
    for k in 1..=top_k {
        Prefix { k }.build(work, pts)?;
    }
    let deepest = top_k - 1;
    for depth in 1..=deepest {
        for axis in 0..2 {
            // A flip visits the points of its column in every prefix: about `n 2^-depth`.
            let weight = u32::try_from((n >> depth).max(1)).unwrap_or(u32::MAX);
            for q in 0..1u32 << depth {
                pacer.tick_n(weight)?;
                let flip = Flip { axis, depth, q };
                // Prefixes whose cells the flip keeps: both energies in one pass. The
                // others (the flip swaps their half-columns): before, apply, after.
                let (mut before, mut after) = column_energy_pair(work, pts, top_k, flip);
                if (Prefix { k: top_k }).moves_cells(flip) {
                    before += column_energy(work, pts, top_k, flip);
                    apply(work, pts, top_k, flip);
                    after += column_energy(work, pts, top_k, flip);
                    if after >= before {
                        apply(work, pts, top_k, flip);
                    }
                } else if after < before {
                    apply(work, pts, top_k, flip);
                }
            }
        }
    }
    Ok(())
}
