//! The neighbour grids of projective blue noise: one uniform toroidal grid for the full
//! space and one for every tested projection (each axis; each pair of axes), so that a
//! candidate is tested only against the points that can conflict with it.
//!
//! A grid over `m` axes has `g^m` cells of side `1/g >= r`, `r` the largest radius its
//! test will use (the radii only shrink): every point closer than `r` on those axes
//! (toroidal) lies in one of the `3^m` cells around the candidate's. The points a test
//! can reject a candidate for are therefore all visited, and the candidate is rejected
//! exactly when the all-pairs scan would reject it. `g` is at most `(4 N)^(1/m)`; when
//! fewer than 3 cells fit along an axis the grid is not used and its test falls back to
//! all points. Cost: a query visits `3^m` cells (about `3^m 4^-1` points each at the
//! finest), an insertion is `O(m)`.

use std::vec::Vec;

const NONE: u32 = u32::MAX;

/// A grid over some axes with per-cell linked lists of point indices.
pub(super) struct AxisGrid {
    axes: Vec<usize>,
    g: usize,
    head: Vec<u32>,
}

impl AxisGrid {
    /// The grid over `axes` for radii up to `r` and up to `n` points; `None` when fewer
    /// than three cells fit along an axis.
    pub(super) fn new(axes: Vec<usize>, r: f64, n: usize) -> crate::Result<Option<Self>> {
        let m = axes.len() as i32;
        let cap = (4.0 * n as f64).powf(1.0 / f64::from(m)).floor();
        let g = if r > 0.0 { (1.0 / r).floor() } else { cap };
        let g = g.min(cap);
        if g < 3.0 {
            return Ok(None);
        }
        let g = g as usize;
        // g^m <= 4 n by the cap.
        let cells = g.pow(m as u32);
        let mut head = crate::size::vec_zeroed::<u32>(cells)?;
        head.fill(NONE);
        Ok(Some(AxisGrid { axes, g, head }))
    }

    fn coord(&self, x: f64) -> usize {
        ((x * self.g as f64) as usize).min(self.g - 1)
    }

    /// Files point `i` at `x` (all `d` coordinates) in this grid, whose list links are
    /// `next`.
    pub(super) fn insert(&mut self, x: &[f64], i: usize, next: &mut Vec<u32>) {
        let mut c = 0usize;
        for &a in self.axes.iter().rev() {
            c = c * self.g + self.coord(x.get(a).copied().unwrap_or(0.0));
        }
        if next.len() <= i {
            next.resize(i + 1, NONE);
        }
        if let (Some(h), Some(nx)) = (self.head.get_mut(c), next.get_mut(i)) {
            *nx = *h;
            *h = i as u32;
        }
    }

    /// Whether `test(j)` holds for some point `j` in the `3^m` cells around `x`.
    pub(super) fn any(&self, x: &[f64], next: &[u32], mut test: impl FnMut(usize) -> bool) -> bool {
        let m = self.axes.len();
        let g = self.g;
        let mut home = [0usize; 8];
        for (h, &a) in home.iter_mut().zip(&self.axes) {
            *h = self.coord(x.get(a).copied().unwrap_or(0.0));
        }
        let mut off = [0usize; 8]; // 0, 1, 2 for -1, 0, +1
        loop {
            let mut c = 0usize;
            for k in (0..m).rev() {
                let h = home.get(k).copied().unwrap_or(0);
                let o = off.get(k).copied().unwrap_or(1);
                // (h + o - 1) mod g, with h + o + g - 1 in [g - 1, 2 g].
                let v = h + o + g - 1;
                c = c * g
                    + if v >= 2 * g {
                        v - 2 * g
                    } else if v >= g {
                        v - g
                    } else {
                        v
                    };
            }
            let mut j = self.head.get(c).copied().unwrap_or(NONE);
            while j != NONE {
                if test(j as usize) {
                    return true;
                }
                j = next.get(j as usize).copied().unwrap_or(NONE);
            }
            let mut k = 0;
            loop {
                if k == m {
                    return false;
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
