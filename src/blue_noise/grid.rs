//! The background grid of the disk constructions: cells of side `1/g <= r/sqrt(d)` on the
//! unit cube (so a cell holds at most one point of an `r`-separated set, Bridson 2007), the
//! points in insertion order, and the cell offsets that can hold a point closer than `r`.
//!
//! Distances are Euclidean in the box or toroidal (nearest image, per axis
//! `min(|a - b|, 1 - |a - b|)`). A point is *free* when every stored point is at least `r`
//! away. Points are kept on the 2^-32 grid, so they convert to 0.32 fractions exactly and
//! the separation holds for the written values.

use crate::size;
use crate::{Error, Result};

/// `2^32`, the 0.32 fixed-point scale.
pub(crate) const SCALE: f64 = 4_294_967_296.0;

/// `x` rounded down onto the 2^-32 grid; `None` outside `[0, 1)` (box) — on the torus `x`
/// is first wrapped into `[0, 1)`.
#[inline]
pub(crate) fn quantize(x: f64, torus: bool) -> Option<f64> {
    let x = if torus { x - x.floor() } else { x };
    if !(0.0..1.0).contains(&x) {
        return None;
    }
    let q = (x * SCALE).floor();
    if q >= SCALE {
        return if torus { Some(0.0) } else { None };
    }
    Some(q / SCALE)
}

/// The distance along one axis (toroidal: to the nearest image).
#[inline]
pub(crate) fn axis_gap(a: f64, b: f64, torus: bool) -> f64 {
    let d = (a - b).abs();
    if torus && d > 0.5 { 1.0 - d } else { d }
}

/// Squared distance between two points (toroidal or not).
#[inline]
pub(crate) fn dist2<const D: usize>(a: &[f64; D], b: &[f64; D], torus: bool) -> f64 {
    let mut s = 0.0;
    for (x, y) in a.iter().zip(b) {
        let d = axis_gap(*x, *y, torus);
        s += d * d;
    }
    s
}

/// Whether a cell holds a point.
#[inline]
fn filled<const D: usize>(p: &[f64; D]) -> bool {
    p.first().is_some_and(|x| !x.is_nan())
}

/// The grid and the points.
pub(crate) struct Grid<const D: usize> {
    /// Cells per axis.
    pub(crate) g: usize,
    /// The separation radius and its square.
    pub(crate) r: f64,
    r2: f64,
    pub(crate) torus: bool,
    /// The point of each cell (first coordinate NaN when empty): the neighbour test reads
    /// only this array, so it touches a few cache lines a query.
    cells: Vec<[f64; D]>,
    /// The points, in insertion order.
    pub(crate) pts: Vec<[f64; D]>,
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

impl<const D: usize> Grid<D> {
    /// An empty grid for radius `r`, with room reserved for `capacity` points.
    ///
    /// # Errors
    /// [`Error::TooLarge`] when the cells or the points pass the allocation limit.
    pub(crate) fn new(r: f64, torus: bool, capacity: usize) -> Result<Self> {
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
        size::bytes(count, core::mem::size_of::<[f64; D]>())?;
        let mut cells = Vec::new();
        cells
            .try_reserve_exact(count)
            .map_err(|_| Error::TooLarge {
                what: "bytes",
                requested: (count * core::mem::size_of::<[f64; D]>()) as u64,
                max: size::MAX_ALLOC_BYTES,
            })?;
        cells.resize(count, [f64::NAN; D]);
        size::bytes(capacity, core::mem::size_of::<[f64; D]>())?;
        let mut pts = Vec::new();
        pts.try_reserve_exact(capacity)
            .map_err(|_| Error::TooLarge {
                what: "bytes",
                requested: (capacity * core::mem::size_of::<[f64; D]>()) as u64,
                max: size::MAX_ALLOC_BYTES,
            })?;
        let reach = (r * gf).ceil() as i64;
        let side = 1.0 / gf;
        let mut offsets = Vec::new();
        let span = 2 * reach + 1;
        let total = span.pow(D as u32);
        for code in 0..total {
            let mut o = [0i64; D];
            let mut c = code;
            let mut gap2 = 0.0;
            for slot in o.iter_mut() {
                *slot = c % span - reach;
                c /= span;
                let gap = (slot.abs() - 1).max(0) as f64 * side;
                gap2 += gap * gap;
            }
            if gap2 < r * r {
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
        Ok(Grid {
            g,
            r,
            r2: r * r,
            torus,
            cells,
            pts,
            offsets,
            deltas,
            reach: reach as usize,
        })
    }

    /// The cell of a point of `[0, 1)^D`.
    #[inline]
    pub(crate) fn cell_of(&self, p: &[f64; D]) -> [usize; D] {
        let mut c = [0usize; D];
        for (ci, x) in c.iter_mut().zip(p) {
            *ci = ((x * self.g as f64) as usize).min(self.g - 1);
        }
        c
    }

    #[inline]
    fn index(&self, c: &[usize; D]) -> usize {
        c.iter().rev().fold(0, |acc, &ci| acc * self.g + ci)
    }

    /// Calls `f` on every stored point in the cells near cell `c`, until `f` returns `true`;
    /// returns whether it did.
    #[inline]
    pub(crate) fn any_near(&self, c: &[usize; D], mut f: impl FnMut(&[f64; D]) -> bool) -> bool {
        let interior = c
            .iter()
            .all(|&ci| ci >= self.reach && ci + self.reach < self.g);
        if interior {
            // No offset leaves the grid: plain index differences.
            let base = self.index(c) as isize;
            for &d in &self.deltas {
                if let Some(p) = self.cells.get((base + d) as usize)
                    && filled(p)
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
            if let Some(p) = self.cells.get(idx)
                && filled(p)
                && f(p)
            {
                return true;
            }
        }
        false
    }

    /// Whether `p` is at least `r` from every stored point.
    #[inline]
    pub(crate) fn is_free(&self, p: &[f64; D]) -> bool {
        let c = self.cell_of(p);
        let (r2, torus) = (self.r2, self.torus);
        !self.any_near(&c, |q| dist2(p, q, torus) < r2)
    }

    /// Whether the cell `c` holds a point.
    pub(crate) fn occupied(&self, c: &[usize; D]) -> bool {
        self.cells.get(self.index(c)).is_some_and(filled)
    }

    /// Stores `p` (which must be free) and returns its index; `None` when the point limit
    /// (2^32 - 1) is reached.
    pub(crate) fn insert(&mut self, p: [f64; D]) -> Option<usize> {
        let idx = self.index(&self.cell_of(&p));
        let n = self.pts.len();
        if n >= u32::MAX as usize {
            return None;
        }
        let slot = self.cells.get_mut(idx)?;
        if filled(slot) {
            return None;
        }
        *slot = p;
        self.pts.push(p);
        Some(n)
    }
}
