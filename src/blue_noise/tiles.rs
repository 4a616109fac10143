//! Bridson's algorithm in 2D over tiles of the background grid, run in parallel.
//!
//! The grid's cells are split into `n x n` tiles of at most [`TILE`] cells a side (`n`
//! even on the torus, so that the colouring wraps). A tile's colour is the parity of its
//! column and row, four colours in all, and the tiles are grown colour by colour, the
//! tiles of one colour in parallel (rayon), each with its own seeded generator: the set
//! depends on the seed only, not on the number of threads.
//!
//! A tile grows by Bridson's loop (random active point, `k` shell candidates, retire after
//! `k` failures) on a private copy of its cells and a halo around them, so every neighbour
//! lookup stays inside one small array (a 128-cell tile and its halo are about 300 KiB, in
//! L2) and needs no boundary test. The loop's centres are the tile's active points. Their
//! candidates are tested wherever they fall within the *margin* (`ceil(2 r g)` cells, the
//! reach of a shell) around the tile, so the growth front crosses tile borders as in the
//! sequential loop: a border is not a wall (a tile that could not place points beyond
//! its border would pack points against it, a layered seam of +58% and -55% density in the
//! strips of width `r/2` on either side, which the tests look for). A point placed in a
//! tile of a later colour becomes an active point of that tile, and the step's centre goes
//! with it (while the tile keeps more than [`HAND_OVER_MIN`] active points, so a young
//! front is not starved): kept, such centres would pack the strip beyond the border on
//! their own (+6.5% at `r` to `1.5 r`). A point placed in a tile of an earlier colour
//! (finished) is a centre of this tile's loop. A candidate beyond the
//! margin (from such a centre) in a tile of a later colour is kept with its step, and
//! tested when that tile grows. A tile with no active points starts from one uniform point.
//!
//! Tiles of one colour are at least [`MIN_WIDTH`] cells apart, more than two margins plus
//! `r`: what one tile writes (its cells and margin) is farther than `r` from what another
//! of the same colour writes or reads, so they cannot constrain each other.
//!
//! Empty cells of the private copy hold *sentinels*, far from every point, so the free
//! test reads every neighbour cell without asking whether it holds a point (a third of the
//! cells do: such a branch mispredicts often) and stops early only between three groups of
//! cells: the own cell and its edge neighbours, the diagonal ones, the rest. Coordinates
//! are `f64`, unwrapped into the tile's frame (a torus cell across the wrap holds its point
//! moved by the period), so plain differences are the nearest-image differences, exact.

use rayon::prelude::*;

use super::grid::{Grid, SCALE, quantize_units};
use super::rng::Rng;
use super::shell::Shell;
use crate::Result;
use crate::work::Budget;

/// Cells a tile side (at most).
pub(crate) const TILE: usize = 128;

/// The narrowest tile, in cells: more than two margins (3 cells each) plus the free
/// test's reach (2 cells), and the private copy of a tile never wraps onto itself.
const MIN_WIDTH: usize = 16;

/// A centre is handed to a later tile only while this tile keeps more active points than
/// this: a young front (a tile seeded near a border) is not starved.
const HAND_OVER_MIN: usize = 16;

/// The random stream of the tiles (distinct from the sequential loop's).
const STREAM: u64 = 0x5449_4C45_4432_0001;

/// The coordinate an empty cell of a private copy holds: farther than `r` from everything
/// (its squared differences stay finite).
const SENTINEL: f64 = 1e18;

/// The split of `g` cells into `n` tiles along each axis: tile `i` holds the cells
/// `start(i) .. start(i + 1)`, `start(i) = floor(i g / n)`.
#[derive(Clone, Copy, Debug)]
struct Layout {
    g: usize,
    n: usize,
}

impl Layout {
    /// The layout for `g` cells a side, or `None` when the grid is too small for tiles.
    fn new(g: usize, torus: bool) -> Option<Self> {
        let mut n = g.div_ceil(TILE).max(1);
        if torus {
            n = (n + n % 2).max(2);
        }
        (g / n >= MIN_WIDTH).then_some(Layout { g, n })
    }

    fn start(&self, i: usize) -> usize {
        i * self.g / self.n
    }

    /// The tile holding cell `c`: the largest `i` with `start(i) <= c`.
    fn tile_of(&self, c: usize) -> usize {
        ((c + 1) * self.n - 1) / self.g
    }

    /// The cell of the coordinate `x`.
    fn cell(&self, x: u32) -> usize {
        ((u64::from(x) * self.g as u64) >> 32) as usize
    }

    /// The tile `(tx, ty)` holding the point `p`.
    fn tile_of_point(&self, p: &[u32; 2]) -> (usize, usize) {
        (self.tile_of(self.cell(p[0])), self.tile_of(self.cell(p[1])))
    }

    /// The colour (growth phase) of tile `(tx, ty)`.
    fn colour(tx: usize, ty: usize) -> usize {
        tx % 2 + 2 * (ty % 2)
    }

    /// The colour of the tile holding `p`.
    fn colour_of(&self, p: &[u32; 2]) -> usize {
        let (tx, ty) = self.tile_of_point(p);
        Self::colour(tx, ty)
    }
}

/// A failed step whose candidates in tiles of later colours are not yet tested: the
/// step's centre and those candidates, in the order they were drawn.
struct Deferred {
    centre: [u32; 2],
    pending: Vec<[u32; 2]>,
}

/// One tile's work: its position, its active points, and the deferred steps with
/// candidates in it.
struct Job {
    tx: usize,
    ty: usize,
    active: Vec<[u32; 2]>,
    incoming: Vec<Deferred>,
}

/// What a tile grew: its new points (in its cells and margin), the new points that are
/// active points of tiles of later colours, and the steps it defers to them.
struct Grown {
    new: Vec<[u32; 2]>,
    spilled: Vec<[u32; 2]>,
    deferred: Vec<Deferred>,
}

/// The fixed inputs of every tile of one construction.
struct Context<'a> {
    grid: &'a Grid<2>,
    layout: Layout,
    k: u32,
    seed: u64,
    shell: Shell<2>,
    /// The margin around a tile where its loop places points, in cells.
    margin: usize,
    phase: usize,
    /// The (started) budget whose deadline every tile checks.
    budget: Budget,
}

/// Grows a Bridson set with `k` candidates (on the sphere when `surface`, as
/// [`super::bridson::bridson`]) into the empty 2D `grid` by tiles; `false`
/// (and nothing done) when the grid is too small or the radius too large for tiles.
/// Every tile checks the deadline of the (started) `budget` as it grows.
///
/// # Errors
/// [`crate::Error::OutOfTime`] past the deadline (from the first tile that sees it).
pub(crate) fn bridson_tiled(
    grid: &mut Grid<2>,
    k: u32,
    surface: bool,
    seed: u64,
    budget: &Budget,
) -> Result<bool> {
    if grid.r >= 1.0 / 6.0 {
        return Ok(false);
    }
    let Some(layout) = Layout::new(grid.g, grid.torus) else {
        return Ok(false);
    };
    let n = layout.n;
    let margin = (2.0 * grid.r * grid.g as f64).ceil() as usize;
    let mut deferred: Vec<Deferred> = Vec::new();
    let mut spilled: Vec<[u32; 2]> = Vec::new();
    for phase in 0..4 {
        let mut slot = vec![usize::MAX; n * n];
        let mut jobs = Vec::new();
        for ty in 0..n {
            for tx in 0..n {
                if Layout::colour(tx, ty) == phase {
                    if let Some(s) = slot.get_mut(ty * n + tx) {
                        *s = jobs.len();
                    }
                    jobs.push(Job {
                        tx,
                        ty,
                        active: Vec::new(),
                        incoming: Vec::new(),
                    });
                }
            }
        }
        let mut job_of = |p: &[u32; 2]| {
            let (tx, ty) = layout.tile_of_point(p);
            if Layout::colour(tx, ty) != phase {
                return None;
            }
            slot.get(ty * n + tx).copied()
        };
        // Spilled points join the tile that holds them; a deferred step the tile of this
        // colour that holds one of its pending candidates (at most one does).
        let mut later_spills = Vec::new();
        let mut to_jobs = Vec::new();
        for p in spilled {
            match job_of(&p) {
                Some(j) => to_jobs.push((j, p)),
                None => later_spills.push(p),
            }
        }
        let mut later_steps = Vec::new();
        let mut steps_to_jobs = Vec::new();
        for d in deferred {
            match d.pending.iter().find_map(&mut job_of) {
                Some(j) => steps_to_jobs.push((j, d)),
                None => later_steps.push(d),
            }
        }
        for (j, p) in to_jobs {
            if let Some(job) = jobs.get_mut(j) {
                job.active.push(p);
            }
        }
        for (j, d) in steps_to_jobs {
            if let Some(job) = jobs.get_mut(j) {
                job.incoming.push(d);
            }
        }
        let grown: Vec<Grown> = {
            let ctx = Context {
                grid,
                layout,
                k,
                seed,
                shell: Shell::<2>::with_surface(grid.r * SCALE, surface),
                margin,
                phase,
                budget: *budget,
            };
            jobs.par_iter()
                .map(|job| grow(&ctx, job))
                .collect::<Result<Vec<_>>>()?
        };
        spilled = later_spills;
        deferred = later_steps;
        for out in grown {
            for p in out.new {
                if grid.insert(p).is_none() {
                    return Ok(true); // the point limit: stop with what we have
                }
            }
            spilled.extend(out.spilled);
            deferred.extend(out.deferred);
        }
    }
    Ok(true)
}

/// The private copy of a tile's cells (with halo) and its free test.
struct TileCopy {
    /// The cells in `f64`, unwrapped into the tile's frame; empty cells hold [`SENTINEL`].
    cells: Vec<[f64; 2]>,
    /// Index differences of the neighbour cells, nearest first, and the ends of the
    /// three groups tested between early exits.
    deltas: Vec<isize>,
    ends: Vec<usize>,
    /// `r^2` in units of `2^-64`.
    r2: f64,
}

impl TileCopy {
    /// Stores the free point `p` (unwrapped) in cell `at`.
    fn place(&mut self, at: usize, p: [f64; 2]) {
        if let Some(c) = self.cells.get_mut(at) {
            *c = p;
        }
    }

    /// Whether `p` (unwrapped), in cell `at` of the copy, is at least `r` from every point.
    #[inline(never)]
    fn is_free(&self, at: usize, p: [f64; 2]) -> bool {
        let base = at as isize;
        let ([px, py], r2) = (p, self.r2);
        let mut from = 0;
        for &to in &self.ends {
            let group = self.deltas.get(from..to).unwrap_or(&[]);
            from = to;
            let near = group.iter().fold(false, |near, &d| {
                let q = self
                    .cells
                    .get((base + d) as usize)
                    .unwrap_or(&[SENTINEL, SENTINEL]);
                let (dx, dy) = (px - q[0], py - q[1]);
                near | (dx * dx + dy * dy < r2)
            });
            if near {
                return false;
            }
        }
        true
    }
}

/// Where a candidate falls, seen from the tile being grown.
enum Spot {
    /// In the tile or its margin: the cell of the copy, the unwrapped coordinates, and
    /// the colour of the tile holding it.
    Near {
        at: usize,
        unwrapped: [f64; 2],
        colour: usize,
    },
    /// Beyond the margin, in a tile of a later colour.
    Later,
    /// Beyond the margin, in a finished tile (or outside the box).
    Done,
}

/// The tile being grown: its frame and its private copy.
struct Frame {
    /// Global cell of the copy's first cell (unwrapped), per axis.
    origin: [i64; 2],
    /// Cells of the copy per axis.
    size: [usize; 2],
    /// The halo: cells of the copy before the tile's first cell.
    halo: usize,
    /// The tile's first cell and its cells, per axis.
    first: [usize; 2],
    tile: [usize; 2],
}

impl Frame {
    /// Where `p` falls: the common case (inside the tile) inline, the rest out of line.
    #[inline(always)]
    fn spot(&self, ctx: &Context, p: &[u32; 2]) -> Spot {
        let (cx, cy) = (ctx.layout.cell(p[0]), ctx.layout.cell(p[1]));
        let (lx, ly) = (
            cx.wrapping_sub(self.first[0]),
            cy.wrapping_sub(self.first[1]),
        );
        if lx < self.tile[0] && ly < self.tile[1] {
            return Spot::Near {
                at: (ly + self.halo) * self.size[0] + lx + self.halo,
                unwrapped: [f64::from(p[0]), f64::from(p[1])],
                colour: ctx.phase,
            };
        }
        self.spot_outside(ctx, p)
    }

    /// [`spot`](Self::spot) for a point outside the tile.
    #[inline(never)]
    fn spot_outside(&self, ctx: &Context, p: &[u32; 2]) -> Spot {
        let g = ctx.layout.g as i64;
        let mut local = [0usize; 2];
        let mut unwrapped = [0.0; 2];
        let (mut near, mut inside) = (true, true);
        for k in 0..2 {
            let c = ctx.layout.cell(p[k]) as i64;
            let origin = self.origin[k];
            let mut l = c - origin;
            if ctx.grid.torus {
                if l < 0 {
                    l += g;
                } else if l >= g {
                    l -= g;
                }
            }
            let (lo, hi) = (self.halo as i64, (self.halo + self.tile[k]) as i64);
            let m = ctx.margin as i64;
            if l < lo - m || l >= hi + m {
                near = false;
                break;
            }
            inside &= (lo..hi).contains(&l);
            local[k] = l as usize;
            let cell = origin + l;
            let period = if cell < 0 {
                -1.0
            } else if cell >= g {
                1.0
            } else {
                0.0
            };
            unwrapped[k] = f64::from(p[k]) + period * SCALE;
        }
        if near {
            let colour = if inside {
                ctx.phase
            } else {
                ctx.layout.colour_of(p)
            };
            return Spot::Near {
                at: local[1] * self.size[0] + local[0],
                unwrapped,
                colour,
            };
        }
        if ctx.layout.colour_of(p) > ctx.phase {
            Spot::Later
        } else {
            Spot::Done
        }
    }
}

/// Grows one tile (see the module text).
///
/// # Errors
/// [`crate::Error::OutOfTime`] past the deadline of `ctx.budget`.
fn grow(ctx: &Context, job: &Job) -> Result<Grown> {
    let mut pacer = ctx.budget.pacer("Poisson-disk sampling");
    let layout = ctx.layout;
    let g = layout.g;
    let halo = ctx.margin + ctx.grid.reach() + 1;
    let (x_lo, x_hi) = (layout.start(job.tx), layout.start(job.tx + 1));
    let (y_lo, y_hi) = (layout.start(job.ty), layout.start(job.ty + 1));
    let frame = Frame {
        origin: [x_lo as i64 - halo as i64, y_lo as i64 - halo as i64],
        size: [x_hi - x_lo + 2 * halo, y_hi - y_lo + 2 * halo],
        halo,
        first: [x_lo, y_lo],
        tile: [x_hi - x_lo, y_hi - y_lo],
    };
    let [width, height] = frame.size;
    let mut cells: Vec<[f64; 2]> = Vec::with_capacity(width * height);
    for ly in 0..height as i64 {
        for lx in 0..width as i64 {
            let (gx, gy) = (frame.origin[0] + lx, frame.origin[1] + ly);
            let p = match ctx.grid.point_at(&[gx, gy]) {
                Some(q) => [unwrap(q[0], gx, g), unwrap(q[1], gy, g)],
                None => [SENTINEL, SENTINEL],
            };
            cells.push(p);
        }
    }
    let offsets = ctx.grid.neighbour_offsets();
    let deltas = offsets
        .iter()
        .map(|o| (o[0] + o[1] * width as i64) as isize)
        .collect();
    // Groups by distance: the own cell and the 4 edge neighbours (in a test set they
    // reject 88% of the rejected candidates), the 4 diagonal ones (11%), the rest.
    let norm2 = |o: &[i64; 2]| o[0] * o[0] + o[1] * o[1];
    let ends = [1, 2, i64::MAX]
        .iter()
        .map(|&m| offsets.iter().filter(|o| norm2(o) <= m).count())
        .collect();
    let ru = ctx.grid.r * SCALE;
    let mut copy = TileCopy {
        cells,
        deltas,
        ends,
        r2: ru * ru,
    };
    let torus = ctx.grid.torus;
    let tile = job.ty * layout.n + job.tx;
    let mut rng = Rng::new(
        ctx.seed,
        STREAM ^ (tile as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15),
    );
    let mut out = Grown {
        new: Vec::new(),
        spilled: Vec::new(),
        deferred: Vec::new(),
    };
    let mut active: Vec<[u32; 2]> = job.active.clone();
    // Places `p` if free: a centre of this loop (in this tile or a finished one) or an
    // active point of a later tile.
    let try_place = |copy: &mut TileCopy, out: &mut Grown, active: &mut Vec<[u32; 2]>, p| {
        let Spot::Near {
            at,
            unwrapped,
            colour,
        } = frame.spot(ctx, &p)
        else {
            return None;
        };
        if !copy.is_free(at, unwrapped) {
            return None;
        }
        copy.place(at, unwrapped);
        out.new.push(p);
        let later = colour > ctx.phase;
        if later {
            out.spilled.push(p);
        } else {
            active.push(p);
        }
        Some(later)
    };
    // Deferred steps first: their pending candidates here are tested in the order drawn;
    // the first free one is placed and the step's centre becomes active again, as in the
    // sequential loop, where that candidate would have ended the step.
    for d in &job.incoming {
        let mut later = Vec::new();
        let mut placed = false;
        for &p in &d.pending {
            match frame.spot(ctx, &p) {
                Spot::Near { .. } if !placed => {
                    if let Some(later) = try_place(&mut copy, &mut out, &mut active, p) {
                        placed = true;
                        if later {
                            out.spilled.push(d.centre);
                        } else {
                            active.push(d.centre);
                        }
                    }
                }
                Spot::Later => later.push(p),
                _ => {}
            }
        }
        if !placed && !later.is_empty() {
            out.deferred.push(Deferred {
                centre: d.centre,
                pending: later,
            });
        }
    }
    if active.is_empty() && out.new.is_empty() {
        let lo = |s: usize| ((s as u64) << 32).div_ceil(g as u64);
        let mut span = |a: usize, b: usize| {
            let (l, u) = (lo(a), lo(b));
            (l + (((rng.next_u64() >> 32) * (u - l)) >> 32)) as u32
        };
        let p = [span(x_lo, x_hi), span(y_lo, y_hi)];
        let _ = try_place(&mut copy, &mut out, &mut active, p);
    }
    let mut pending = Vec::new();
    while !active.is_empty() {
        pacer.tick_n(ctx.k)?;
        let slot = rng.below(active.len());
        let Some(&centre) = active.get(slot) else {
            break;
        };
        let (mut placed, mut handed) = (false, false);
        pending.clear();
        'tries: for _ in 0..ctx.k {
            let off = ctx.shell.draw(&mut rng);
            let mut p = [0u32; 2];
            for ((pk, &c), o) in p.iter_mut().zip(&centre).zip(&off) {
                match quantize_units(f64::from(c) + o, torus) {
                    Some(x) => *pk = x,
                    None => continue 'tries,
                }
            }
            match frame.spot(ctx, &p) {
                Spot::Near { .. } => {
                    if let Some(later) = try_place(&mut copy, &mut out, &mut active, p) {
                        placed = true;
                        handed = later;
                        break;
                    }
                }
                Spot::Later => pending.push(p),
                Spot::Done => {}
            }
        }
        if handed && active.len() > HAND_OVER_MIN {
            // The step placed a point in a later tile: the centre goes there too.
            out.spilled.push(centre);
            active.swap_remove(slot);
        } else if !placed {
            if !pending.is_empty() {
                out.deferred.push(Deferred {
                    centre,
                    pending: pending.clone(),
                });
            }
            active.swap_remove(slot);
        }
    }
    Ok(out)
}

/// The coordinate `x` of a point in the (unwrapped) cell `c` of a `g`-cell axis, in the
/// frame where cell `c` covers `[c, c + 1) 2^32 / g`: shifted by a period when `c` is
/// outside `0..g` (a torus cell across the wrap).
fn unwrap(x: u32, c: i64, g: usize) -> f64 {
    let period = c.div_euclid(g as i64);
    f64::from(x) + period as f64 * SCALE
}

#[cfg(test)]
mod tests {
    use super::Layout;

    #[test]
    fn tile_of_inverts_start() {
        for g in [8usize, 9, 17, 130, 1814] {
            for torus in [false, true] {
                let Some(l) = Layout::new(g, torus) else {
                    continue;
                };
                for i in 0..l.n {
                    for c in l.start(i)..l.start(i + 1) {
                        assert_eq!(l.tile_of(c), i, "g {g} n {} c {c}", l.n);
                    }
                }
                if torus {
                    assert_eq!(l.n % 2, 0);
                }
            }
        }
    }
}
