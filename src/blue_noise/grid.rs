//! The background grid of the disk constructions: cells of side `1/g <= r/sqrt(d)` on the
//! unit cube (so a cell holds at most one point of an `r`-separated set, Bridson 2007), the
//! points in insertion order, and the cell offsets that can hold a point closer than `r`.
//!
//! Points are kept as 0.32 fixed-point coordinates (`u32`, the values written out), so the
//! separation holds for the written values and distances are exact integer differences:
//! squared distances are summed in `f64` in units of `2^-32` (the same bits as in unit
//! scale: the scale is a power of two). Distances are Euclidean in the box or toroidal
//! (nearest image: on the torus the wrapping `u32` difference read as `i32` is the
//! nearest-image difference). A point is *free* when every stored point is at least `r`
//! away. Which cells hold a point is a bit set (a few hundred KiB for a million points), so
//! the neighbour test reads a cell's point only when there is one.

use crate::size;
use crate::work::Budget;
use crate::{Error, Result};

/// `2^32`, the 0.32 fixed-point scale.
pub(crate) const SCALE: f64 = 4_294_967_296.0;

/// The coordinate `v` (in units of `2^-32`, any finite value) rounded down onto the grid:
/// `None` outside `[0, 2^32)` in the box, wrapped modulo `2^32` on the torus. No `floor`
/// call (a library call on baseline x86-64): truncation is the floor of a non-negative
/// value, and a torus coordinate within one period below 0 is first lifted by `2^32`.
#[inline]
pub(crate) fn quantize_units(v: f64, torus: bool) -> Option<u32> {
    if torus {
        let lifted = if v < 0.0 { v + SCALE } else { v };
        if (0.0..2.0 * SCALE).contains(&lifted) {
            // `as u32` of the truncated value wraps [2^32, 2^33) to [0, 2^32).
            return Some(lifted as u64 as u32);
        }
        let w = v - (v / SCALE).floor() * SCALE;
        return Some(if (0.0..SCALE).contains(&w) {
            w as u32
        } else {
            0
        });
    }
    (0.0..SCALE).contains(&v).then_some(v as u32)
}

/// The distance along one axis (toroidal: to the nearest image).
#[inline]
pub(crate) fn axis_gap(a: f64, b: f64, torus: bool) -> f64 {
    let d = (a - b).abs();
    if torus && d > 0.5 { 1.0 - d } else { d }
}

/// The squared distance between two grid points in units of `2^-64` (toroidal or not).
#[inline]
pub(crate) fn dist2_units<const D: usize>(a: &[u32; D], b: &[u32; D], torus: bool) -> f64 {
    let mut s = 0.0;
    for (&x, &y) in a.iter().zip(b) {
        let d = if torus {
            f64::from(x.wrapping_sub(y) as i32)
        } else {
            f64::from(x) - f64::from(y)
        };
        s += d * d;
    }
    s
}

/// A grid point in unit scale.
#[inline]
pub(crate) fn to_unit<const D: usize>(p: &[u32; D]) -> [f64; D] {
    p.map(|c| f64::from(c) / SCALE)
}

/// The grid and the points.
pub(crate) struct Grid<const D: usize> {
    /// Cells per axis.
    pub(crate) g: usize,
    /// The separation radius, and its square in units of `2^-64`.
    pub(crate) r: f64,
    r2: f64,
    pub(crate) torus: bool,
    /// The point of each cell (meaningful where `full` has the cell's bit).
    cells: Vec<[u32; D]>,
    /// One bit a cell: whether it holds a point.
    full: Vec<u64>,
    /// The points, in insertion order.
    pub(crate) pts: Vec<[u32; D]>,
    /// Cell offsets in `[-reach, reach]^D` that may hold a point closer than `r` to a
    /// point of the centre cell, nearest first, and their row-major index differences.
    offsets: Vec<[i64; D]>,
    deltas: Vec<isize>,
    /// Cells from the boundary within which an offset can leave the grid.
    reach: usize,
}

/// Cells per axis for radius `r` in `d` dimensions: `ceil(sqrt(d) / r)`, at least 1.
pub(crate) fn cells_per_axis(r: f64, d: usize) -> f64 {
    ((d as f64).sqrt() / r).ceil().max(1.0)
}

/// The offsets along one axis that can reach a neighbour cell: `-reach ..= reach`, cut to
/// the `g` cells there are. In the box an offset past `g - 1` leaves the grid; on the torus,
/// when `2 reach + 1 > g`, offsets that differ by `g` name the same cell, so one offset of
/// each residue is kept, the one of least magnitude (whose gap is the least, so the kept
/// set of cells is the same). Visiting each cell once changes no answer of the free test.
fn axis_offsets(reach: i64, g: i64, torus: bool) -> Vec<i64> {
    if torus && 2 * reach + 1 > g {
        (-((g - 1) / 2)..=g / 2).collect()
    } else {
        let m = if torus { reach } else { reach.min(g - 1) };
        (-m..=m).collect()
    }
}

/// A vector of `count` copies of `fill`, or [`Error::TooLarge`] past the allocation limit.
fn try_vec<T: Copy>(count: usize, fill: T) -> Result<Vec<T>> {
    let bytes = size::bytes(count, core::mem::size_of::<T>())?;
    let mut v = Vec::new();
    v.try_reserve_exact(count).map_err(|_| Error::TooLarge {
        what: "bytes",
        requested: bytes as u64,
        max: size::MAX_ALLOC_BYTES,
    })?;
    v.resize(count, fill);
    Ok(v)
}

impl<const D: usize> Grid<D> {
    /// An empty grid for radius `r`, with room reserved for `capacity` points; the
    /// enumeration of the neighbour offsets (up to `9^D` candidates) checks the deadline of
    /// the (started) `budget`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] when the cells or the points pass the allocation limit;
    /// [`Error::OutOfTime`] past the deadline.
    pub(crate) fn new(r: f64, torus: bool, capacity: usize, budget: &Budget) -> Result<Self> {
        let gf = cells_per_axis(r, D);
        let cells_f = gf.powi(D as i32);
        if cells_f > (size::MAX_ALLOC_BYTES / 4) as f64 {
            return Err(Error::TooLarge {
                what: "grid cells",
                requested: cells_f.min(u64::MAX as f64) as u64,
                max: size::MAX_ALLOC_BYTES / 4,
            });
        }
        let g = gf as usize;
        let count = g.pow(D as u32);
        let cells = try_vec(count, [0u32; D])?;
        let full = try_vec(count.div_ceil(64), 0u64)?;
        let mut pts = try_vec(capacity, [0u32; D])?;
        pts.clear();
        let reach = (r * gf).ceil() as i64;
        let side = 1.0 / gf;
        let axis = axis_offsets(reach, g as i64, torus);
        let span = axis.len();
        let total = span.pow(D as u32);
        let mut pacer = budget.pacer("Poisson-disk grid");
        let mut offsets = Vec::new();
        for code in 0..total {
            pacer.tick()?;
            let mut o = [0i64; D];
            let mut c = code;
            let mut gap2 = 0.0;
            for slot in o.iter_mut() {
                *slot = axis.get(c % span).copied().unwrap_or(0);
                c /= span;
                let gap = (slot.abs() - 1).max(0) as f64 * side;
                gap2 += gap * gap;
            }
            if gap2 < r * r {
                if offsets.len() == offsets.capacity() {
                    let more = offsets.len().max(64);
                    size::reserve(&mut offsets, more)?;
                }
                offsets.push(o);
            }
        }
        // Nearest cells first: a rejected candidate usually stops at the first few.
        offsets.sort_by_key(|o| o.iter().map(|&v| v * v).sum::<i64>());
        let gi = g as i64;
        let deltas = offsets
            .iter()
            .map(|o| o.iter().rev().fold(0i64, |acc, &v| acc * gi + v) as isize)
            .collect();
        let ru = r * SCALE;
        Ok(Grid {
            g,
            r,
            r2: ru * ru,
            torus,
            cells,
            full,
            pts,
            offsets,
            deltas,
            reach: reach as usize,
        })
    }

    /// The cell of a grid point: `floor(x g / 2^32)` per axis, exact.
    #[inline]
    pub(crate) fn cell_of(&self, p: &[u32; D]) -> [usize; D] {
        let g = self.g as u64;
        p.map(|x| ((u64::from(x) * g) >> 32) as usize)
    }

    /// The cell holding the unit-scale point `p` (clamped into the grid).
    pub(crate) fn cell_of_unit(&self, p: &[f64; D]) -> [usize; D] {
        p.map(|x| ((x * self.g as f64) as usize).min(self.g - 1))
    }

    #[inline]
    fn index(&self, c: &[usize; D]) -> usize {
        c.iter().rev().fold(0, |acc, &ci| acc * self.g + ci)
    }

    /// The point of cell `idx`, if it holds one.
    #[inline]
    fn at(&self, idx: usize) -> Option<&[u32; D]> {
        let word = self.full.get(idx / 64)?;
        if word >> (idx % 64) & 1 == 0 {
            return None;
        }
        self.cells.get(idx)
    }

    /// Calls `f` on every stored point in the cells near cell `c`, until `f` returns `true`;
    /// returns whether it did.
    #[inline]
    pub(crate) fn any_near(&self, c: &[usize; D], mut f: impl FnMut(&[u32; D]) -> bool) -> bool {
        let interior = c
            .iter()
            .all(|&ci| ci >= self.reach && ci + self.reach < self.g);
        if interior {
            // No offset leaves the grid: plain index differences.
            let base = self.index(c) as isize;
            for &d in &self.deltas {
                if let Some(p) = self.at((base + d) as usize)
                    && f(p)
                {
                    return true;
                }
            }
            return false;
        }
        let g = self.g as i64;
        'offsets: for o in &self.offsets {
            let mut idx = 0usize;
            for k in (0..D).rev() {
                let ck = c.get(k).copied().unwrap_or(0) as i64 + o.get(k).copied().unwrap_or(0);
                let ck = if self.torus {
                    ck.rem_euclid(g)
                } else if ck < 0 || ck >= g {
                    continue 'offsets;
                } else {
                    ck
                };
                idx = idx * self.g + ck as usize;
            }
            if let Some(p) = self.at(idx)
                && f(p)
            {
                return true;
            }
        }
        false
    }

    /// The neighbour-cell offsets (see [`Grid::new`]), nearest first.
    pub(crate) fn neighbour_offsets(&self) -> &[[i64; D]] {
        &self.offsets
    }

    /// The neighbour cells a free test may visit, in units of 64 (at least 1): the weight
    /// of one test for a [`crate::work::Pacer`], so that the clock is read about once every
    /// `2^18` cell visits however many cells a test reads.
    pub(crate) fn test_weight(&self) -> u32 {
        u32::try_from(self.offsets.len() / 64)
            .unwrap_or(u32::MAX)
            .max(1)
    }

    /// The largest offset along an axis.
    pub(crate) fn reach(&self) -> usize {
        self.reach
    }

    /// The point of the cell with (unwrapped) coordinates `c`: wrapped on the torus,
    /// `None` outside the box or when the cell is empty.
    pub(crate) fn point_at(&self, c: &[i64; D]) -> Option<[u32; D]> {
        let g = self.g as i64;
        let mut idx = 0usize;
        for &ck in c.iter().rev() {
            let ck = if self.torus {
                ck.rem_euclid(g)
            } else if (0..g).contains(&ck) {
                ck
            } else {
                return None;
            };
            idx = idx * self.g + ck as usize;
        }
        self.at(idx).copied()
    }

    /// Whether `p` is at least `r` from every stored point.
    #[inline]
    pub(crate) fn is_free(&self, p: &[u32; D]) -> bool {
        let c = self.cell_of(p);
        let (r2, torus) = (self.r2, self.torus);
        !self.any_near(&c, |q| dist2_units(p, q, torus) < r2)
    }

    /// Whether the cell `c` holds a point.
    pub(crate) fn occupied(&self, c: &[usize; D]) -> bool {
        self.at(self.index(c)).is_some()
    }

    /// Stores `p` (which must be free) and returns its index; `None` when the point limit
    /// (2^32 - 1) is reached.
    pub(crate) fn insert(&mut self, p: [u32; D]) -> Option<usize> {
        let idx = self.index(&self.cell_of(&p));
        let n = self.pts.len();
        if n >= u32::MAX as usize || self.at(idx).is_some() {
            return None;
        }
        *self.cells.get_mut(idx)? = p;
        *self.full.get_mut(idx / 64)? |= 1 << (idx % 64);
        self.pts.push(p);
        Some(n)
    }
}
