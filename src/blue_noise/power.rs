//! Power diagrams (Laguerre cells) of weighted sites in the unit square or on the unit
//! torus, in 2D, with exact cell areas, centroids and second moments.
//!
//! ## The cells
//!
//! Sites `p_1..p_N` with weights `w_1..w_N` have the power distance
//! `pow_i(x) = |x - p_i|^2 - w_i`; the Laguerre cell of `p_i` is
//! `L_i = {x in D : pow_i(x) <= pow_j(x) for all j}` (Aurenhammer 1987, "Power diagrams:
//! properties, algorithms and applications", SIAM J. Comput. 16(1)). With all weights
//! equal it is the Voronoi cell. Each condition is a half-plane: with `q = p_j - p_i`,
//! `(x - p_i) . q <= (|q|^2 + w_i - w_j) / 2`, so a cell is a convex polygon (possibly
//! empty, and not necessarily containing its site). On the torus `D` is the unit square
//! with opposite sides identified: the sites are repeated with period 1 and the cell of
//! `p_i` is computed in the plane around `p_i`, inside the square `p_i + [-1/2, 1/2]^2`
//! (the bisectors with its own copies); its vertices are given in those unrolled
//! coordinates (they may leave `[0, 1)`).
//!
//! Each cell starts as its domain (the unit square, or the square around the site) and is
//! clipped by the half-planes of the candidate sites, taken ring by ring from a uniform
//! grid of buckets around the site. The search stops once no farther site can cut: a
//! site at distance `d` from `p_i` cannot reach a point of the cell (all within `R` of
//! `p_i`) when `d >= R + sqrt(max(0, R^2 - w_i + w_max))`, and never needs to go past
//! `R + sqrt(2)/2` on the torus (every point has a copy of every site that near).
//!
//! ## The integrals
//!
//! Fanning the polygon from the site (`a`, `b` consecutive vertices relative to `p_i`,
//! `c = a x b`): area `sum c/2`, first moment `sum c (a + b)/6`, second moment
//! `int |x - p_i|^2 = sum c (|a|^2 + a.b + |b|^2)/12`, exact up to rounding. The edge
//! shared with the cell of `p_j` (length `l_ij`) gives the derivative of the areas with
//! respect to the weights, `dA_i/dw_j = -l_ij / (2 |p_i - p_j|)` for `j != i` and
//! `dA_i/dw_i = sum_j l_ij / (2 |p_i - p_j|)` (Aurenhammer, Hoffmann & Aronov 1998,
//! "Minkowski-type theorems and least-squares clustering", Algorithmica 20), which the
//! transport solve ([`super::transport`]) uses as its Hessian.
//!
//! ## Range and cost
//!
//! 1 to [`POWER_MAX_SITES`] distinct sites in `[0, 1]^2` (on the torus taken modulo 1),
//! finite weights. For weights of a spread below the squared spacing (Voronoi diagrams,
//! the transport weights of evenly spread sites) a cell meets a bounded number of
//! candidates and the diagram costs `O(N)` after an `O(N log N)` duplicate check; larger
//! spreads widen the search (bounded by the domain). Estimated by [`PowerDiagram::cost`],
//! stopped at the budget's deadline, parallel over the cells (rayon). Memory about
//! `20 N` words.
//!
//! ```
//! use qmckit::blue_noise::power::PowerDiagram;
//! use qmckit::work::Budget;
//! // Two sites on the midline: the bisector x = 1/2 splits the square in halves; a weight
//! // of 0.1 on the first moves it to x = 1/2 + 0.1 / (2 * 0.5) = 0.6.
//! let sites = [0.25, 0.5, 0.75, 0.5];
//! let d = PowerDiagram::new(&sites, &[0.1, 0.0], false, &Budget::DEFAULT)?;
//! assert!((d.area(0) - 0.6).abs() < 1e-15);
//! assert!((d.areas().iter().sum::<f64>() - 1.0).abs() < 1e-15);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::sites::{self, Buckets, bucket_of};
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};
use rayon::prelude::*;

/// The most sites a [`PowerDiagram`] takes: 2^20.
pub const POWER_MAX_SITES: usize = 1 << 20;

/// Cells a second, release, for evenly spread sites (measured 1.7e5 to 7.7e5 for Voronoi
/// diagrams of 1024 to 16384 BNOT-like sites, on two cores shared with other work).
const CELLS: Rate = Rate::per_second(3e5);

/// Cells between two readings of the clock.
const CHUNK: usize = 512;

/// An edge on the domain's boundary (not shared with another cell).
const BOUNDARY: u32 = u32::MAX;

/// The power diagram: every cell's polygon, area, centroid, second moment and the
/// area derivatives along its shared edges.
#[derive(Clone, Debug)]
pub struct PowerDiagram {
    torus: bool,
    area: Vec<f64>,
    centroid: Vec<[f64; 2]>,
    moment: Vec<f64>,
    poly_start: Vec<usize>,
    vertices: Vec<[f64; 2]>,
    adj_start: Vec<usize>,
    adj: Vec<(u32, f64)>,
}

/// One computed cell, relative to its site: its integrals and how many vertices and
/// shared edges it appended to its chunk's lists.
struct Cell {
    area: f64,
    first: [f64; 2],
    moment: f64,
    vertices: usize,
    adj: usize,
}

impl PowerDiagram {
    /// The estimated running time for `n` evenly spread sites.
    pub fn cost(n: usize) -> Cost {
        Cost::steps(n as f64, CELLS)
    }

    /// The Voronoi diagram (all weights zero) of `sites`, row-major `(x, y)` pairs.
    ///
    /// # Errors
    /// As [`PowerDiagram::new`].
    pub fn voronoi(sites: &[f64], torus: bool, budget: &Budget) -> Result<Self> {
        let zero = crate::size::vec_zeroed::<f64>(sites.len() / 2)?;
        Self::new(sites, &zero, torus, budget)
    }

    /// The power diagram of `sites` (row-major `(x, y)` pairs in `[0, 1]^2`) with
    /// `weights` (one a site), in the unit square or (`torus`) on the unit torus.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::RaggedPoints`] for an odd coordinate count,
    /// [`Error::TooManyPoints`] past [`POWER_MAX_SITES`], [`Error::CoordinateOutOfRange`]
    /// for a coordinate outside `[0, 1]` or NaN, [`Error::InvalidParameter`] for a weight
    /// count other than one a site, a weight that is not finite or two equal sites,
    /// [`Error::OverBudget`], [`Error::OutOfTime`], [`Error::TooLarge`].
    pub fn new(sites: &[f64], weights: &[f64], torus: bool, budget: &Budget) -> Result<Self> {
        let budget = budget.started();
        let pts = validate(sites, weights, torus)?;
        budget.check("power diagram", Self::cost(pts.len()))?;
        check_distinct(&pts)?;
        Self::build(&pts, weights, torus, &budget)
    }

    /// The diagram of validated, distinct sites.
    pub(crate) fn build(
        pts: &[[f64; 2]],
        weights: &[f64],
        torus: bool,
        budget: &Budget,
    ) -> Result<Self> {
        Self::build_hinted(pts, weights, torus, None, budget)
    }

    /// As [`PowerDiagram::build`], first clipping every cell by the half-planes of its
    /// neighbours in `hint` (a diagram of the same number of sites: the previous step's,
    /// as in the transport's Newton steps and BNOT's iterations), nearest first, then by
    /// every other site within the reach of the clipped cell (the buckets meeting the
    /// square of half-side `R + sqrt(max(0, R^2 - w_i + w_max))` around the site; a farther
    /// site cannot cut and the reach only shrinks). Any site's half-plane bounds the cell,
    /// so the cells are the same exact cells, without the search ring by ring.
    pub(crate) fn build_hinted(
        pts: &[[f64; 2]],
        weights: &[f64],
        torus: bool,
        hint: Option<&PowerDiagram>,
        budget: &Budget,
    ) -> Result<Self> {
        let n = pts.len();
        let hint = hint.filter(|h| h.len() == n);
        let buckets = Buckets::new(pts)?;
        let w_max = weights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let chunks = n.div_ceil(CHUNK);
        // Each chunk's cells, their vertices (relative to the sites) and adjacencies.
        type Part = (Vec<Cell>, Vec<[f64; 2]>, Vec<(u32, f64)>);
        let parts: Vec<Part> = (0..chunks)
            .into_par_iter()
            .map(|c| {
                budget.check_deadline("power diagram")?;
                let mut scratch = Scratch::default();
                let (mut cells, mut verts, mut adj) = (Vec::new(), Vec::new(), Vec::new());
                for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                    match hint {
                        Some(h) if !h.neighbours(i).is_empty() => hinted_cell(
                            i,
                            pts,
                            weights,
                            w_max,
                            torus,
                            &buckets,
                            h.neighbours(i),
                            &mut scratch,
                        ),
                        _ => cell(i, pts, weights, w_max, torus, &buckets, &mut scratch)?,
                    }
                    cells.push(integrate(&scratch, &mut verts, &mut adj));
                }
                Ok((cells, verts, adj))
            })
            .collect::<Result<Vec<_>>>()?;
        let mut d = PowerDiagram {
            torus,
            area: crate::size::vec_with_capacity(n)?,
            centroid: crate::size::vec_with_capacity(n)?,
            moment: crate::size::vec_with_capacity(n)?,
            poly_start: crate::size::vec_with_capacity(n + 1)?,
            vertices: Vec::new(),
            adj_start: crate::size::vec_with_capacity(n + 1)?,
            adj: Vec::new(),
        };
        d.poly_start.push(0);
        d.adj_start.push(0);
        let mut p = pts.iter();
        for (cells, verts, adj) in parts {
            crate::size::reserve(&mut d.vertices, verts.len())?;
            crate::size::reserve(&mut d.adj, adj.len())?;
            let (mut v, mut a) = (0, 0);
            for c in cells {
                let Some(p) = p.next() else { break };
                d.area.push(c.area);
                let centroid = if c.area > 0.0 {
                    [p[0] + c.first[0] / c.area, p[1] + c.first[1] / c.area]
                } else {
                    *p
                };
                d.centroid.push(centroid);
                d.moment.push(c.moment);
                let (v1, a1) = (v + c.vertices, a + c.adj);
                d.vertices.extend(
                    verts
                        .get(v..v1)
                        .unwrap_or(&[])
                        .iter()
                        .map(|u| [u[0] + p[0], u[1] + p[1]]),
                );
                d.poly_start.push(d.vertices.len());
                d.adj.extend_from_slice(adj.get(a..a1).unwrap_or(&[]));
                d.adj_start.push(d.adj.len());
                (v, a) = (v1, a1);
            }
        }
        Ok(d)
    }

    /// The number of sites.
    pub fn len(&self) -> usize {
        self.area.len()
    }

    /// `true` for no sites (never: a diagram has at least one).
    pub fn is_empty(&self) -> bool {
        self.area.is_empty()
    }

    /// `true` on the torus.
    pub fn torus(&self) -> bool {
        self.torus
    }

    /// The area of every cell (they sum to 1 up to rounding).
    pub fn areas(&self) -> &[f64] {
        &self.area
    }

    /// The area of cell `i` (0 past the end).
    pub fn area(&self, i: usize) -> f64 {
        self.area.get(i).copied().unwrap_or(0.0)
    }

    /// The centroid of cell `i` (its site for an empty cell; on the torus in the
    /// unrolled coordinates around the site, not reduced modulo 1).
    pub fn centroid(&self, i: usize) -> [f64; 2] {
        self.centroid.get(i).copied().unwrap_or([0.0; 2])
    }

    /// `int_{L_i} |x - p_i|^2 dx`, the transport cost of cell `i` to its site.
    pub fn moment(&self, i: usize) -> f64 {
        self.moment.get(i).copied().unwrap_or(0.0)
    }

    /// The vertices of cell `i`, counter-clockwise (empty for an empty cell; on the torus
    /// in the unrolled coordinates around the site).
    pub fn cell(&self, i: usize) -> &[[f64; 2]] {
        match (self.poly_start.get(i), self.poly_start.get(i + 1)) {
            (Some(&a), Some(&b)) => self.vertices.get(a..b).unwrap_or(&[]),
            _ => &[],
        }
    }

    /// The neighbours `j` of cell `i` with `l_ij / (2 |p_i - p_j|)` (`-dA_i/dw_j`), one
    /// entry a shared edge (on the torus a site may meet two copies of another).
    pub fn neighbours(&self, i: usize) -> &[(u32, f64)] {
        match (self.adj_start.get(i), self.adj_start.get(i + 1)) {
            (Some(&a), Some(&b)) => self.adj.get(a..b).unwrap_or(&[]),
            _ => &[],
        }
    }
}

/// The sites as pairs, checked (reduced modulo 1 on the torus).
pub(crate) fn validate(sites: &[f64], weights: &[f64], torus: bool) -> Result<Vec<[f64; 2]>> {
    let pts = sites::validate::<2>(sites, torus, POWER_MAX_SITES)?;
    if weights.len() != pts.len() {
        return Err(Error::InvalidParameter {
            what: "a power diagram takes one weight a site",
        });
    }
    if weights.iter().any(|w| !w.is_finite()) {
        return Err(Error::InvalidParameter {
            what: "power diagram weights must be finite",
        });
    }
    Ok(pts)
}

/// [`Error::InvalidParameter`] when two sites coincide (their cells would be equal).
pub(crate) fn check_distinct(pts: &[[f64; 2]]) -> Result<()> {
    sites::check_distinct(
        pts,
        "two sites coincide: a power diagram needs distinct sites",
    )
}

/// Reused buffers of one thread.
#[derive(Default)]
struct Scratch {
    poly: Vec<[f64; 2]>,
    label: Vec<u32>,
    next: Vec<[f64; 2]>,
    next_label: Vec<u32>,
    cand: Vec<(u32, [f64; 2])>,
    used: Vec<(f64, [f64; 2], u32)>,
}

/// The cell of site `i`, left in `s`.
fn cell(
    i: usize,
    pts: &[[f64; 2]],
    weights: &[f64],
    w_max: f64,
    torus: bool,
    buckets: &Buckets<2>,
    s: &mut Scratch,
) -> Result<()> {
    let p = pts[i];
    let w_i = weights[i];
    start(s, p, torus);
    let g = buckets.g as i64;
    let h = 1.0 / g as f64;
    let (cx, cy) = (
        bucket_of(p[0], buckets.g) as i64,
        bucket_of(p[1], buckets.g) as i64,
    );
    let far = if torus { 0.5f64.sqrt() } else { 2f64.sqrt() };
    let mut r = 0i64;
    loop {
        for dy in -r..=r {
            let step = if dy.abs() == r { 1 } else { (2 * r).max(1) };
            let mut dx = -r;
            while dx <= r {
                let (bx, by) = (cx + dx, cy + dy);
                dx += step;
                let (shift, ux, uy) = if torus {
                    (
                        [bx.div_euclid(g) as f64, by.div_euclid(g) as f64],
                        bx.rem_euclid(g),
                        by.rem_euclid(g),
                    )
                } else if bx < 0 || by < 0 || bx >= g || by >= g {
                    continue;
                } else {
                    ([0.0, 0.0], bx, by)
                };
                for &j in buckets.get([ux as usize, uy as usize]) {
                    let pj = pts[j as usize];
                    let q = [pj[0] + shift[0] - p[0], pj[1] + shift[1] - p[1]];
                    if j as usize == i && shift == [0.0, 0.0] {
                        continue;
                    }
                    let c = 0.5 * (q[0] * q[0] + q[1] * q[1] + w_i - weights[j as usize]);
                    let label = if j as usize == i {
                        BOUNDARY
                    } else {
                        s.cand.len() as u32
                    };
                    if clip(s, q, c, label) && label != BOUNDARY {
                        s.cand.push((j, q));
                    }
                }
            }
        }
        if s.poly.len() < 3 {
            s.poly.clear();
            break;
        }
        let r2 = s
            .poly
            .iter()
            .map(|v| v[0] * v[0] + v[1] * v[1])
            .fold(0.0, f64::max);
        let rad = r2.sqrt();
        let reach = rad + (r2 - w_i + w_max).max(0.0).sqrt().min(far);
        // Sites of ring r + 1 are at least r h away.
        if r as f64 * h >= reach || (!torus && r >= g) {
            break;
        }
        r += 1;
    }
    Ok(())
}

/// The starting polygon of site `p`: the unit square, or on the torus the square of side
/// 1 around the site (relative to the site).
fn start(s: &mut Scratch, p: [f64; 2], torus: bool) {
    s.poly.clear();
    s.label.clear();
    s.cand.clear();
    let (lo, hi) = if torus {
        ([-0.5, -0.5], [0.5, 0.5])
    } else {
        ([-p[0], -p[1]], [1.0 - p[0], 1.0 - p[1]])
    };
    s.poly.extend([
        [lo[0], lo[1]],
        [hi[0], lo[1]],
        [hi[0], hi[1]],
        [lo[0], hi[1]],
    ]);
    s.label.extend([BOUNDARY; 4]);
}

/// The reach of the polygon of `s`: no site farther than it from the site can cut.
fn reach(s: &Scratch, w_i: f64, w_max: f64, torus: bool) -> f64 {
    let far = if torus { 0.5f64.sqrt() } else { 2f64.sqrt() };
    let r2 = s
        .poly
        .iter()
        .map(|v| v[0] * v[0] + v[1] * v[1])
        .fold(0.0, f64::max);
    r2.sqrt() + (r2 - w_i + w_max).max(0.0).sqrt().min(far)
}

/// The cell of site `i`, first clipped by the sites of `hint` (each at its nearest copy
/// on the torus; repeats skipped), nearest first, then by every other site of the
/// buckets within the clipped cell's reach.
#[allow(clippy::too_many_arguments)]
fn hinted_cell(
    i: usize,
    pts: &[[f64; 2]],
    weights: &[f64],
    w_max: f64,
    torus: bool,
    buckets: &Buckets<2>,
    hint: &[(u32, f64)],
    s: &mut Scratch,
) {
    let p = pts[i];
    let w_i = weights[i];
    start(s, p, torus);
    s.used.clear();
    for &(j, _) in hint {
        let Some(&pj) = pts.get(j as usize) else {
            continue;
        };
        if j as usize == i {
            continue;
        }
        let shift = [0, 1].map(|k| if torus { -(pj[k] - p[k]).round() } else { 0.0 });
        if s.used.iter().any(|u| u.2 == j && u.1 == shift) {
            continue;
        }
        let q = [pj[0] + shift[0] - p[0], pj[1] + shift[1] - p[1]];
        s.used.push((q[0] * q[0] + q[1] * q[1], shift, j));
    }
    s.used.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let used = core::mem::take(&mut s.used);
    let try_site = |s: &mut Scratch, j: u32, shift: [f64; 2]| {
        let pj = pts[j as usize];
        let q = [pj[0] + shift[0] - p[0], pj[1] + shift[1] - p[1]];
        let c = 0.5 * (q[0] * q[0] + q[1] * q[1] + w_i - weights[j as usize]);
        let label = s.cand.len() as u32;
        if clip(s, q, c, label) {
            s.cand.push((j, q));
        }
    };
    for &(_, shift, j) in &used {
        try_site(s, j, shift);
    }
    if s.poly.len() >= 3 {
        let reach = reach(s, w_i, w_max, torus);
        let range = |x: f64| buckets.span(x, reach, torus);
        let wrap = |b: i64| buckets.unroll(b);
        let (rx, ry) = (range(p[0]), range(p[1]));
        for by in ry.0..=ry.1 {
            let (uy, sy) = wrap(by);
            for bx in rx.0..=rx.1 {
                let (ux, sx) = if torus { wrap(bx) } else { (bx as usize, 0.0) };
                let shift = [sx, sy];
                for &j in buckets.get([ux, uy]) {
                    // Its own copies' bisectors are the faces of the torus square.
                    if j as usize == i || used.iter().any(|u| u.2 == j && u.1 == shift) {
                        continue;
                    }
                    try_site(s, j, shift);
                }
            }
        }
    }
    s.used = used;
    if s.poly.len() < 3 {
        s.poly.clear();
    }
}

/// Clips the polygon of `s` by `x . q <= c`; `true` when it cut (the new edge labelled
/// `label`).
fn clip(s: &mut Scratch, q: [f64; 2], c: f64, label: u32) -> bool {
    let side = |v: &[f64; 2]| v[0] * q[0] + v[1] * q[1] - c;
    if s.poly.iter().all(|v| side(v) <= 0.0) {
        return false;
    }
    s.next.clear();
    s.next_label.clear();
    let m = s.poly.len();
    for k in 0..m {
        let (a, b) = (s.poly[k], s.poly[(k + 1) % m]);
        let (sa, sb) = (side(&a), side(&b));
        let l = s.label[k];
        if sa <= 0.0 {
            s.next.push(a);
            s.next_label.push(l);
            if sb > 0.0 {
                let t = sa / (sa - sb);
                s.next
                    .push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
                s.next_label.push(label);
            }
        } else if sb <= 0.0 {
            let t = sa / (sa - sb);
            s.next
                .push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
            s.next_label.push(l);
        }
    }
    core::mem::swap(&mut s.poly, &mut s.next);
    core::mem::swap(&mut s.label, &mut s.next_label);
    true
}

/// The integrals of the finished polygon (relative to its site); its vertices and shared
/// edges are appended to `verts` and `adj`.
fn integrate(s: &Scratch, verts: &mut Vec<[f64; 2]>, adj: &mut Vec<(u32, f64)>) -> Cell {
    let m = s.poly.len();
    let (mut area, mut first, mut moment) = (0.0, [0.0, 0.0], 0.0);
    let before = adj.len();
    for k in 0..m {
        let (a, b) = (s.poly[k], s.poly[(k + 1) % m]);
        let c = a[0] * b[1] - a[1] * b[0];
        area += c;
        first[0] += c * (a[0] + b[0]);
        first[1] += c * (a[1] + b[1]);
        moment +=
            c * (a[0] * a[0] + a[1] * a[1] + a[0] * b[0] + a[1] * b[1] + b[0] * b[0] + b[1] * b[1]);
        let l = s.label[k];
        if let Some(&(j, q)) = s.cand.get(l as usize) {
            // Lengths below 2 (in the unit square or around a site on the torus): no
            // overflow to guard against.
            let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
            let len = (ex * ex + ey * ey).sqrt();
            let dist = (q[0] * q[0] + q[1] * q[1]).sqrt();
            if len > 0.0 {
                adj.push((j, len / (2.0 * dist)));
            }
        }
    }
    verts.extend_from_slice(&s.poly);
    Cell {
        area: area / 2.0,
        first: [first[0] / 6.0, first[1] / 6.0],
        moment: moment / 12.0,
        vertices: m,
        adj: adj.len() - before,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Uniform values in `[0, 1)` from a small linear congruential generator.
    fn uniform(n: usize, seed: u64) -> Vec<f64> {
        let mut x = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (0..n)
            .map(|_| {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (x >> 11) as f64 / (1u64 << 53) as f64
            })
            .collect()
    }

    /// Hinted diagrams (by the diagram of other sites and other weights) against the
    /// diagram searched ring by ring: the same cells and shared edges.
    #[test]
    fn hinted_cells_are_the_searched_cells() {
        let b = Budget::DEFAULT;
        for torus in [false, true] {
            let n = 400;
            let pts: Vec<[f64; 2]> = uniform(2 * n, 3).chunks(2).map(|c| [c[0], c[1]]).collect();
            let moved: Vec<[f64; 2]> = uniform(2 * n, 4)
                .chunks(2)
                .zip(&pts)
                .map(|(c, p)| [0, 1].map(|k| (p[k] + 0.02 * (c[k] - 0.5)).clamp(0.0, 0.999)))
                .collect();
            // Weights up to a fifth of the squared spacing.
            let w: Vec<f64> = uniform(n, 5).iter().map(|x| 0.2 * x / n as f64).collect();
            let zero = vec![0.0; n];
            let want = PowerDiagram::build(&pts, &w, torus, &b).unwrap();
            for (hint_pts, hint_w) in [(&pts, &zero), (&moved, &w), (&moved, &zero)] {
                let hint = PowerDiagram::build(hint_pts, hint_w, torus, &b).unwrap();
                let got = PowerDiagram::build_hinted(&pts, &w, torus, Some(&hint), &b).unwrap();
                for i in 0..n {
                    assert!((got.area(i) - want.area(i)).abs() < 1e-15, "{torus} {i}");
                    assert!((got.moment(i) - want.moment(i)).abs() < 1e-15);
                    let (c, d) = (got.centroid(i), want.centroid(i));
                    assert!((c[0] - d[0]).abs() < 1e-13 && (c[1] - d[1]).abs() < 1e-13);
                    let sorted = |d: &PowerDiagram| {
                        let mut v: Vec<u32> = d.neighbours(i).iter().map(|e| e.0).collect();
                        v.sort_unstable();
                        v
                    };
                    assert_eq!(sorted(&got), sorted(&want), "{torus} {i}");
                }
            }
        }
    }
}
