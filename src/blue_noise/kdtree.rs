//! A k-d tree over sites in `[0, 1)^d` for nearest-site queries in the unit cube or on
//! the unit torus (Bentley 1975; Friedman, Bentley & Finkel 1977): median splits cycling
//! through the axes (the median is the node's pivot, the halves below and above it its
//! children), leaves of at most [`LEAF`] sites, a query prunes a subtree whose box
//! is no nearer than the best site so far (the box distance taken per axis on the circle
//! for the torus). Build `O(n log n)`, a query `O(log n)` expected for uniform sites in
//! low dimension (approaching `O(n)` as `d` grows), memory `n` indices.

use crate::Result;

/// Sites a leaf holds.
const LEAF: usize = 8;

/// The tree: a permutation of the site indices, recursively split at medians.
pub(crate) struct KdTree<'a> {
    sites: &'a [f64],
    dims: usize,
    order: Vec<u32>,
    torus: bool,
}

impl<'a> KdTree<'a> {
    /// The tree of `sites` (row-major, `dims` a site, at least one site).
    ///
    /// # Errors
    /// [`crate::Error::TooLarge`] when the index array does not fit.
    pub(crate) fn new(sites: &'a [f64], dims: usize, torus: bool) -> Result<Self> {
        let n = sites.len() / dims.max(1);
        let mut order = crate::size::vec_with_capacity(n)?;
        order.extend(0..n as u32);
        let mut t = KdTree {
            sites,
            dims,
            order,
            torus,
        };
        let mut order = core::mem::take(&mut t.order);
        t.split(&mut order, 0);
        t.order = order;
        Ok(t)
    }

    fn coord(&self, site: u32, axis: usize) -> f64 {
        self.sites
            .get(site as usize * self.dims + axis)
            .copied()
            .unwrap_or(0.0)
    }

    fn split(&self, part: &mut [u32], depth: usize) {
        if part.len() <= LEAF {
            return;
        }
        let axis = depth % self.dims;
        let mid = part.len() / 2;
        part.select_nth_unstable_by(mid, |&a, &b| {
            self.coord(a, axis).total_cmp(&self.coord(b, axis))
        });
        // The median stays at `mid` (the node's pivot); the halves split on.
        let (lo, hi) = part.split_at_mut(mid);
        self.split(lo, depth + 1);
        if let Some(hi) = hi.get_mut(1..) {
            self.split(hi, depth + 1);
        }
    }

    /// Squared distance of `a - b` along one axis (wrapped on the torus).
    fn axis_d(&self, d: f64) -> f64 {
        let d = d.abs();
        let d = if self.torus { d.min(1.0 - d) } else { d };
        d * d
    }

    /// Squared distance from `q` to site `s`.
    pub(crate) fn dist2(&self, q: &[f64], s: u32) -> f64 {
        let base = s as usize * self.dims;
        let row = self.sites.get(base..base + self.dims).unwrap_or(&[]);
        q.iter().zip(row).map(|(a, b)| self.axis_d(a - b)).sum()
    }

    /// Squared distance from coordinate `x` to the interval `[lo, hi]` of one axis.
    fn interval_d(&self, x: f64, lo: f64, hi: f64) -> f64 {
        if x >= lo && x <= hi {
            0.0
        } else {
            self.axis_d(x - lo).min(self.axis_d(x - hi))
        }
    }

    /// The site nearest to `q` (ties to the first found) and its squared distance.
    /// `lo`, `hi` are scratch of `dims` values.
    pub(crate) fn nearest(&self, q: &[f64], lo: &mut [f64], hi: &mut [f64]) -> (u32, f64) {
        lo.fill(0.0);
        hi.fill(1.0);
        let mut best = (0u32, f64::INFINITY);
        self.search(&self.order, 0, q, lo, hi, 0.0, &mut best);
        best
    }

    #[allow(clippy::too_many_arguments)]
    fn search(
        &self,
        part: &[u32],
        depth: usize,
        q: &[f64],
        lo: &mut [f64],
        hi: &mut [f64],
        box_d: f64,
        best: &mut (u32, f64),
    ) {
        if box_d >= best.1 {
            return;
        }
        if part.len() <= LEAF {
            for &s in part {
                let d = self.dist2(q, s);
                if d < best.1 {
                    *best = (s, d);
                }
            }
            return;
        }
        let axis = depth % self.dims;
        let mid = part.len() / 2;
        let (left, rest) = part.split_at(mid);
        let Some((&pivot, right)) = rest.split_first() else {
            return;
        };
        let split = self.coord(pivot, axis);
        let d = self.dist2(q, pivot);
        if d < best.1 {
            *best = (pivot, d);
        }
        let x = q.get(axis).copied().unwrap_or(0.0);
        let (l0, h0) = (
            lo.get(axis).copied().unwrap_or(0.0),
            hi.get(axis).copied().unwrap_or(1.0),
        );
        let whole = self.interval_d(x, l0, h0);
        // Children's boxes on this axis: [l0, split] and [split, h0].
        let dl = box_d - whole + self.interval_d(x, l0, split);
        let dr = box_d - whole + self.interval_d(x, split, h0);
        let mut visit = |first: bool, this: &Self, lo: &mut [f64], hi: &mut [f64], d: f64| {
            if first {
                if let Some(h) = hi.get_mut(axis) {
                    *h = split;
                }
                this.search(left, depth + 1, q, lo, hi, d, best);
                if let Some(h) = hi.get_mut(axis) {
                    *h = h0;
                }
            } else {
                if let Some(l) = lo.get_mut(axis) {
                    *l = split;
                }
                this.search(right, depth + 1, q, lo, hi, d, best);
                if let Some(l) = lo.get_mut(axis) {
                    *l = l0;
                }
            }
        };
        if dl <= dr {
            visit(true, self, lo, hi, dl);
            visit(false, self, lo, hi, dr);
        } else {
            visit(false, self, lo, hi, dr);
            visit(true, self, lo, hi, dl);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_agrees_with_brute_force() {
        let mut rng = super::super::rng::Rng::new(3, 1);
        for dims in [1usize, 2, 3, 5] {
            for torus in [false, true] {
                let n = 157;
                let sites: Vec<f64> = (0..n * dims).map(|_| rng.unit()).collect();
                let t = KdTree::new(&sites, dims, torus).unwrap();
                let (mut lo, mut hi) = (vec![0.0; dims], vec![0.0; dims]);
                for _ in 0..300 {
                    let q: Vec<f64> = (0..dims).map(|_| rng.unit()).collect();
                    let (_, d) = t.nearest(&q, &mut lo, &mut hi);
                    let brute = (0..n as u32)
                        .map(|s| t.dist2(&q, s))
                        .fold(f64::INFINITY, f64::min);
                    assert_eq!(d, brute, "dims {dims} torus {torus}");
                }
            }
        }
    }
}
