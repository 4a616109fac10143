//! Cell lists on the unit torus `[0, 1)^d` for the pair sums of the spectral and the
//! kernel-density samplers: the points bucketed into `g^d` cubic cells of side `1/g >= cut`,
//! so that every pair closer than `cut` (in the nearest-image metric) lies in one of the
//! `3^d` cells around a point's own. When fewer than three cells fit along an axis, or
//! `3^d` would exceed the number of points, every pair is visited instead.
//!
//! Cost: building is `O(N d + g^d)` (a counting sort of the points by cell); a neighbour
//! query visits `3^d` cells and the points in them, about `3^d N / g^d` points.

use crate::Result;

/// `x` wrapped to the nearest image, `[-1/2, 1/2)` for `x` in `(-1, 1)`.
#[inline]
pub(crate) fn wrap(x: f64) -> f64 {
    if x >= 0.5 {
        x - 1.0
    } else if x < -0.5 {
        x + 1.0
    } else {
        x
    }
}

/// The cells of a point set of `d` coordinates (row-major `f64` in `[0, 1)`).
pub(crate) struct Cells {
    d: usize,
    /// Cells along an axis; 0 when every pair is visited.
    g: usize,
    /// `start[c]..start[c + 1]` indexes `order` for cell `c`.
    start: Vec<u32>,
    /// The point indices sorted by cell.
    order: Vec<u32>,
}

impl Cells {
    /// The cells side at least `cut` for `pts` (`n = pts.len() / d` points, `n < 2^32`).
    ///
    /// # Errors
    /// [`crate::Error::TooLarge`] when the tables do not fit.
    pub(crate) fn new(pts: &[f64], d: usize, cut: f64) -> Result<Self> {
        let n = pts.len() / d.max(1);
        let mut g = if cut > 0.0 { (1.0 / cut).floor() } else { 0.0 };
        // At most about 2n cells: more would be mostly empty.
        let cap = (2.0 * n as f64).powf(1.0 / d as f64).floor();
        g = g.min(cap).min(1024.0);
        let three = 3f64.powi(d as i32);
        let g = if g >= 3.0 && three < n as f64 {
            g as usize
        } else {
            0
        };
        let mut cells = Cells {
            d,
            g,
            start: Vec::new(),
            order: Vec::new(),
        };
        if g == 0 {
            return Ok(cells);
        }
        let total = g.pow(d as u32);
        let mut start = crate::size::vec_zeroed::<u32>(total + 1)?;
        let mut which = crate::size::vec_zeroed::<u32>(n)?;
        for (i, p) in pts.chunks_exact(d).enumerate() {
            let c = cells.cell_of(p);
            if let (Some(w), Some(s)) = (which.get_mut(i), start.get_mut(c + 1)) {
                *w = c as u32;
                *s += 1;
            }
        }
        for c in 0..total {
            let prev = start.get(c).copied().unwrap_or(0);
            if let Some(s) = start.get_mut(c + 1) {
                *s += prev;
            }
        }
        let mut fill = start.clone();
        let mut order = crate::size::vec_zeroed::<u32>(n)?;
        for (i, &c) in which.iter().enumerate() {
            if let Some(f) = fill.get_mut(c as usize) {
                if let Some(o) = order.get_mut(*f as usize) {
                    *o = i as u32;
                }
                *f += 1;
            }
        }
        cells.start = start;
        cells.order = order;
        Ok(cells)
    }

    fn cell_of(&self, p: &[f64]) -> usize {
        let gf = self.g as f64;
        p.iter().rev().fold(0usize, |acc, &x| {
            acc * self.g + ((x * gf) as usize).min(self.g - 1)
        })
    }

    /// Calls `f(j)` for every point `j` (the point itself among them) that may lie within
    /// `cut` of `p`: those of the `3^d` cells around `p`'s, or all `n` points.
    pub(crate) fn near(&self, p: &[f64], n: usize, mut f: impl FnMut(usize)) {
        if self.g == 0 {
            (0..n).for_each(f);
            return;
        }
        let g = self.g;
        let gf = g as f64;
        let mut home = [0usize; 16];
        for (h, &x) in home.iter_mut().zip(p) {
            *h = ((x * gf) as usize).min(g - 1);
        }
        let d = self.d;
        let mut off = [0usize; 16]; // each 0, 1, 2 meaning -1, 0, +1
        loop {
            let mut c = 0usize;
            for k in (0..d).rev() {
                let h = home.get(k).copied().unwrap_or(0);
                let o = off.get(k).copied().unwrap_or(1);
                c = c * g + (h + g + o - 1) % g;
            }
            let (a, b) = (
                self.start.get(c).copied().unwrap_or(0) as usize,
                self.start.get(c + 1).copied().unwrap_or(0) as usize,
            );
            for &j in self.order.get(a..b).unwrap_or(&[]) {
                f(j as usize);
            }
            // Next offset (odometer).
            let mut k = 0;
            loop {
                if k == d {
                    return;
                }
                if let Some(o) = off.get_mut(k) {
                    *o += 1;
                    if *o < 3 {
                        break;
                    }
                    *o = 0;
                }
                k += 1;
            }
        }
    }
}
