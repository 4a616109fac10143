//! Voronoi cells in 3D, in the unit cube or on the unit torus, with exact volumes,
//! centroids and second moments.
//!
//! ## The cells
//!
//! The Voronoi cell of site `p_i` among `p_1..p_N` is
//! `V_i = {x in D : |x - p_i| <= |x - p_j| for all j}`. Each condition is a half-space:
//! with `q = p_j - p_i` and `x` relative to `p_i`, `x . q <= |q|^2 / 2` (the bisector
//! plane). So a cell is a convex polyhedron, computed as in Rycroft's voro++ (2009,
//! "VORO++: A three-dimensional Voronoi cell library in C++", Chaos 19, 041111): start
//! from the domain (the unit cube around the site; on the torus, whose sites repeat with
//! period 1, the cube `p_i + [-1/2, 1/2]^3`) and cut it by the bisector half-spaces of the
//! other sites (and, on the torus, their periodic copies), nearest first, found through a
//! uniform grid of buckets, ring of buckets by ring. Every vertex of the cell is within
//! `R` of the site; a site at distance `d >= 2R` has its bisector beyond every vertex and
//! cannot cut, so the search stops once the next ring of buckets is `2R` away (and, in the
//! cube, when the rings cover the grid). Every returned cell is the exact Voronoi cell up
//! to rounding.
//!
//! The polyhedron is kept as its triangulated dual (`src/blue_noise/cell3.rs`: a vertex
//! is the triangle of the three planes meeting there; a cut removes the triangles outside and
//! fans the hole's boundary around the new plane, in place). Should a cut meet a
//! boundary that is not one simple cycle (rounding, near a degenerate configuration),
//! the cell is computed again by the face-list polyhedron below, which rebuilds the
//! polyhedron at every cut and accepts any configuration. It is kept as vertices and
//! faces (vertex index cycles, counter-clockwise seen from outside). A cut keeps the
//! vertices on the inner side (`x . q <= |q|^2 / 2`), puts one new vertex on every edge that crosses the plane (the same one for both faces
//! of the edge) and closes the hole by a new face: in every cut face the new edge runs
//! from the vertex where the face leaves the half-space to the one where it re-enters,
//! and the new face traverses those edges backwards, chained into cycles.
//!
//! Lloyd's steps ([`super::lloyd`]) pass each cell's neighbours of the previous step
//! as hints: those bisectors are cut first, nearest first, leaving a cell close to the
//! final one, and then every other site within twice its radius `R` is tried, through the
//! buckets meeting the cube of half-side `2 R` around the site. Any site's bisector
//! bounds the cell and a farther site cannot cut, so the hinted cells are the same exact
//! cells, without the search ring by ring and its sorts.
//!
//! ## The integrals
//!
//! The dual cell fans each face from the foot of the site's perpendicular on its plane
//! (`src/blue_noise/cell3.rs`); the face-list polyhedron fans every face from its first
//! vertex. Either way, triangles `(a, b, c)` (relative to the site) give tetrahedra
//! `(0, a, b, c)` of signed volume `det(a, b, c) / 6`: the volume is their sum, the first moment `sum det(a, b, c) (a + b + c) / 24` and the second
//! moment `int |x - p_i|^2 = sum det(a, b, c) (|a|^2 + |b|^2 + |c|^2 + |a + b + c|^2) /
//! 120` (the simplex moment `int x x^T = V/20 (sum v v^T + (sum v)(sum v)^T)` with one
//! vertex at the origin). Exact for any closed, consistently oriented surface, so the
//! volumes sum to the domain's volume 1 up to rounding (tested to `1e-12`).
//!
//! ## Range and cost
//!
//! 1 to [`VORONOI3_MAX_SITES`] distinct sites in `[0, 1]^3` (on the torus taken modulo
//! 1). For evenly spread sites a cell meets a bounded number of candidates (about 45
//! gathered and 12 cuts a cell at 1024 Lloyd-relaxed sites without hints), so the diagram costs `O(N)`
//! after an `O(N log N)` duplicate check; clustered sites widen the search (bounded by
//! the domain). Estimated by
//! [`Voronoi3::cost`], stopped at the budget's deadline, parallel over the cells
//! (rayon). Memory about `8 N` words besides a few hundred words a thread.
//!
//! ```
//! use qmckit::blue_noise::voronoi3::Voronoi3;
//! use qmckit::work::Budget;
//! // Two sites on the line y = z = 1/2: the bisector x = 1/2 halves the cube.
//! let v = Voronoi3::new(&[0.25, 0.5, 0.5, 0.75, 0.5, 0.5], false, &Budget::DEFAULT)?;
//! assert!((v.volume(0) - 0.5).abs() < 1e-15);
//! let c = v.centroid(1);
//! assert!((c[0] - 0.75).abs() < 1e-15 && (c[1] - 0.5).abs() < 1e-15);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::cell3::DualCell;
use super::sites::{self, Buckets, bucket_of};
use crate::Result;
use crate::work::{Budget, Cost, Rate};
use rayon::prelude::*;

/// The most sites a [`Voronoi3`] takes: 2^20.
pub const VORONOI3_MAX_SITES: usize = 1 << 20;

/// Cells a second, release, for evenly spread sites (measured 1.5e5 on one core for
/// 1024 Lloyd-relaxed sites on a loaded machine; taken lower).
const CELLS: Rate = Rate::per_second(5e4);

/// Cells between two readings of the clock.
const CHUNK: usize = 256;

/// No index.
const NONE: u32 = u32::MAX;

/// The Voronoi cells of a 3D point set: volumes, centroids and second moments.
#[derive(Clone, Debug)]
pub struct Voronoi3 {
    torus: bool,
    volume: Vec<f64>,
    centroid: Vec<[f64; 3]>,
    moment: Vec<f64>,
}

/// The neighbours of every cell (the sites of its faces; none listed for a cell the
/// face-list polyhedron computed).
#[derive(Clone, Debug, Default)]
pub(crate) struct Neighbours {
    start: Vec<usize>,
    list: Vec<u32>,
}

impl Neighbours {
    /// The neighbours of cell `i`.
    fn of(&self, i: usize) -> &[u32] {
        match (self.start.get(i), self.start.get(i + 1)) {
            (Some(&a), Some(&b)) => self.list.get(a..b).unwrap_or(&[]),
            _ => &[],
        }
    }
}

/// One cell's integrals relative to its site.
#[derive(Clone, Copy, Default)]
pub(super) struct Integrals {
    pub(super) volume: f64,
    pub(super) first: [f64; 3],
    pub(super) moment: f64,
}

impl Voronoi3 {
    /// The estimated running time for `n` evenly spread sites.
    pub fn cost(n: usize) -> Cost {
        Cost::steps(n as f64, CELLS)
    }

    /// The Voronoi cells of `sites` (row-major `(x, y, z)` triples in `[0, 1]^3`), in the
    /// unit cube or (`torus`) on the unit torus.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`](crate::Error::ZeroPoints), [`Error::RaggedPoints`](crate::Error::RaggedPoints) for a coordinate count not a
    /// multiple of 3, [`Error::TooManyPoints`](crate::Error::TooManyPoints) past [`VORONOI3_MAX_SITES`],
    /// [`Error::CoordinateOutOfRange`](crate::Error::CoordinateOutOfRange) for a coordinate outside `[0, 1]` or NaN,
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) for two equal sites, [`Error::OverBudget`](crate::Error::OverBudget),
    /// [`Error::OutOfTime`](crate::Error::OutOfTime), [`Error::TooLarge`](crate::Error::TooLarge).
    pub fn new(sites: &[f64], torus: bool, budget: &Budget) -> Result<Self> {
        Ok(Self::hinted(sites, torus, None, budget)?.0)
    }

    /// As [`Voronoi3::new`], first cutting every cell by the bisectors of the sites that
    /// `hints` lists for it (the neighbours of the previous cells of moved sites, as in
    /// Lloyd's steps), and also returning each cell's neighbours (the sites of its faces).
    /// Every cell is still exact: any site's bisector bounds the cell, and once the
    /// hinted cuts are made, every site within twice the cell's radius is tried.
    pub(crate) fn hinted(
        sites: &[f64],
        torus: bool,
        hints: Option<&Neighbours>,
        budget: &Budget,
    ) -> Result<(Self, Neighbours)> {
        let budget = budget.started();
        let pts = sites::validate::<3>(sites, torus, VORONOI3_MAX_SITES)?;
        budget.check("3D Voronoi cells", Self::cost(pts.len()))?;
        sites::check_distinct(
            &pts,
            "two sites coincide: Voronoi cells need distinct sites",
        )?;
        let n = pts.len();
        let hints = hints.filter(|h| h.start.len() == n + 1);
        let buckets = Buckets::new(&pts)?;
        type Part = (Vec<Integrals>, Vec<u32>, Vec<u32>);
        let parts: Vec<Part> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| {
                budget.check_deadline("3D Voronoi cells")?;
                let (mut dual, mut s) = (DualCell::default(), Scratch::default());
                let mut cand = Vec::new();
                let (mut cells, mut list, mut count) = (Vec::new(), Vec::new(), Vec::new());
                for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                    let hint = hints.map_or(&[][..], |h| h.of(i));
                    let before = list.len();
                    let got = cell(i, &pts, torus, &buckets, hint, &mut dual, &mut cand)
                        .inspect(|_| dual.faces(&mut list));
                    cells.push(got.unwrap_or_else(|| {
                        cell(i, &pts, torus, &buckets, &[], &mut s, &mut cand).unwrap_or_default()
                    }));
                    count.push((list.len() - before) as u32);
                }
                Ok((cells, list, count))
            })
            .collect::<Result<Vec<_>>>()?;
        let mut v = Voronoi3 {
            torus,
            volume: crate::size::vec_with_capacity(n)?,
            centroid: crate::size::vec_with_capacity(n)?,
            moment: crate::size::vec_with_capacity(n)?,
        };
        let mut nb = Neighbours {
            start: crate::size::vec_with_capacity(n + 1)?,
            list: Vec::new(),
        };
        nb.start.push(0);
        let mut p = pts.iter();
        for (cells, list, count) in parts {
            crate::size::reserve(&mut nb.list, list.len())?;
            nb.list.extend_from_slice(&list);
            for (c, k) in cells.into_iter().zip(count) {
                let Some(p) = p.next() else { break };
                v.volume.push(c.volume);
                v.centroid.push(if c.volume > 0.0 {
                    [0, 1, 2].map(|k| p[k] + c.first[k] / c.volume)
                } else {
                    *p
                });
                v.moment.push(c.moment);
                nb.start.push(nb.start[nb.start.len() - 1] + k as usize);
            }
        }
        Ok((v, nb))
    }

    /// The number of sites.
    pub fn len(&self) -> usize {
        self.volume.len()
    }

    /// `true` for no sites (never: the cells have at least one).
    pub fn is_empty(&self) -> bool {
        self.volume.is_empty()
    }

    /// `true` on the torus.
    pub fn torus(&self) -> bool {
        self.torus
    }

    /// The volume of every cell (they sum to 1 up to rounding).
    pub fn volumes(&self) -> &[f64] {
        &self.volume
    }

    /// The volume of cell `i` (0 past the end).
    pub fn volume(&self, i: usize) -> f64 {
        self.volume.get(i).copied().unwrap_or(0.0)
    }

    /// The centroid of cell `i` (on the torus in the unrolled coordinates around the
    /// site, not reduced modulo 1).
    pub fn centroid(&self, i: usize) -> [f64; 3] {
        self.centroid.get(i).copied().unwrap_or([0.0; 3])
    }

    /// `int_{V_i} |x - p_i|^2 dx`, the quantization energy of cell `i`.
    pub fn moment(&self, i: usize) -> f64 {
        self.moment.get(i).copied().unwrap_or(0.0)
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// A convex polyhedron around a site, cut by half-spaces.
trait Polyhedron {
    /// The box `[lo, hi]` (relative to the site).
    fn reset(&mut self, lo: [f64; 3], hi: [f64; 3]);
    /// Cuts by `x . q <= c`; `false` when the cut was refused (the cell is then computed
    /// by the face-list polyhedron).
    fn cut(&mut self, q: [f64; 3], c: f64, tag: u32) -> bool;
    /// The largest squared vertex distance from the site.
    fn r2(&self) -> f64;
    /// `true` when nothing is left.
    fn is_empty(&self) -> bool;
    /// The integrals relative to the site (`None` when they cannot be formed).
    fn integrals(&self) -> Option<Integrals>;
}

impl Polyhedron for DualCell {
    fn reset(&mut self, lo: [f64; 3], hi: [f64; 3]) {
        DualCell::reset(self, lo, hi);
    }
    fn cut(&mut self, q: [f64; 3], c: f64, tag: u32) -> bool {
        DualCell::cut(self, q, c, tag)
    }
    fn r2(&self) -> f64 {
        DualCell::r2(self)
    }
    fn is_empty(&self) -> bool {
        DualCell::is_empty(self)
    }
    fn integrals(&self) -> Option<Integrals> {
        self.integrate()
    }
}

impl Polyhedron for Scratch {
    fn reset(&mut self, lo: [f64; 3], hi: [f64; 3]) {
        Scratch::reset(self, lo, hi);
    }
    fn cut(&mut self, q: [f64; 3], c: f64, _tag: u32) -> bool {
        self.clip(q, c);
        true
    }
    fn r2(&self) -> f64 {
        self.r2
    }
    fn is_empty(&self) -> bool {
        self.start.len() < 2
    }
    fn integrals(&self) -> Option<Integrals> {
        Some(self.integrate())
    }
}

/// The polyhedron and reused buffers of one thread.
#[derive(Default)]
struct Scratch {
    /// Vertices relative to the site.
    verts: Vec<[f64; 3]>,
    /// Faces: `faces[start[f]..start[f + 1]]` index `verts`, counter-clockwise from outside.
    faces: Vec<u32>,
    start: Vec<usize>,
    /// The largest squared vertex distance from the site.
    r2: f64,
    side: Vec<f64>,
    map: Vec<u32>,
    next_verts: Vec<[f64; 3]>,
    next_faces: Vec<u32>,
    next_start: Vec<usize>,
    /// Crossing edges `(inner vertex, new vertex, next edge of the same outer vertex)`.
    edges: Vec<(u32, u32, u32)>,
    /// The new face's edges: `(from, to)`.
    links: Vec<(u32, u32)>,
    next_link: Vec<u32>,
}

impl Scratch {
    /// The box `[lo, hi]` (relative to the site).
    fn reset(&mut self, lo: [f64; 3], hi: [f64; 3]) {
        self.verts.clear();
        for k in 0..8 {
            self.verts.push([
                if k & 1 == 0 { lo[0] } else { hi[0] },
                if k & 2 == 0 { lo[1] } else { hi[1] },
                if k & 4 == 0 { lo[2] } else { hi[2] },
            ]);
        }
        // Corner (i, j, k) is i + 2 j + 4 k; each face counter-clockwise from outside.
        self.faces.clear();
        self.faces.extend_from_slice(&[
            0, 4, 6, 2, // x = lo
            1, 3, 7, 5, // x = hi
            0, 1, 5, 4, // y = lo
            2, 6, 7, 3, // y = hi
            0, 2, 3, 1, // z = lo
            4, 5, 7, 6, // z = hi
        ]);
        self.start.clear();
        self.start.extend((0..=6).map(|f| 4 * f));
        self.r2 = self.verts.iter().map(|&v| dot(v, v)).fold(0.0, f64::max);
    }

    /// The new vertex on the edge from inner vertex `i` to outer vertex `o`, shared by
    /// both its faces: the edges found so far are listed by their outer vertex (`map[o]`
    /// heads the list, unused for outer vertices otherwise).
    fn edge_vertex(&mut self, i: u32, o: u32) -> u32 {
        let mut e = self.map[o as usize];
        while e != NONE {
            let (inner, x, next) = self.edges[e as usize];
            if inner == i {
                return x;
            }
            e = next;
        }
        let (si, so) = (self.side[i as usize], self.side[o as usize]);
        let t = si / (si - so);
        let (vi, vo) = (self.verts[i as usize], self.verts[o as usize]);
        let x = self.next_verts.len() as u32;
        self.next_verts
            .push([0, 1, 2].map(|k| vi[k] + t * (vo[k] - vi[k])));
        self.edges.push((i, x, self.map[o as usize]));
        self.map[o as usize] = self.edges.len() as u32 - 1;
        x
    }

    /// Cuts the polyhedron by `x . q <= c`; `true` when it cut.
    fn clip(&mut self, q: [f64; 3], c: f64) -> bool {
        self.side.clear();
        let mut out = false;
        for &v in &self.verts {
            let s = dot(v, q) - c;
            out |= s > 0.0;
            self.side.push(s);
        }
        if !out {
            return false;
        }
        self.map.clear();
        self.next_verts.clear();
        for (k, &s) in self.side.iter().enumerate() {
            if s <= 0.0 {
                self.map.push(self.next_verts.len() as u32);
                self.next_verts.push(self.verts[k]);
            } else {
                self.map.push(NONE);
            }
        }
        let kept = self.next_verts.len();
        self.edges.clear();
        self.links.clear();
        self.next_faces.clear();
        self.next_start.clear();
        self.next_start.push(0);
        let faces = core::mem::take(&mut self.faces);
        for f in 0..self.start.len() - 1 {
            let face = &faces[self.start[f]..self.start[f + 1]];
            let begin = self.next_faces.len();
            let Some(&last) = face.last() else { continue };
            let (mut leave, mut first_entry) = (NONE, NONE);
            // The edges (a, b), starting with the closing one.
            let (mut a, mut a_in) = (last, self.side[last as usize] <= 0.0);
            for &b in face {
                let b_in = self.side[b as usize] <= 0.0;
                let (this, this_in) = (a, a_in);
                (a, a_in) = (b, b_in);
                let a = this;
                if this_in {
                    self.next_faces.push(self.map[a as usize]);
                    if !b_in {
                        leave = self.edge_vertex(a, b);
                        self.next_faces.push(leave);
                    }
                } else if b_in {
                    let entry = self.edge_vertex(b, a);
                    self.next_faces.push(entry);
                    if leave == NONE {
                        first_entry = entry;
                    } else {
                        // The face's new edge runs leave -> entry; the new face's backwards.
                        self.links.push((entry, leave));
                        leave = NONE;
                    }
                }
            }
            if leave != NONE && first_entry != NONE {
                self.links.push((first_entry, leave));
            }
            if self.next_faces.len() - begin >= 3 {
                self.next_start.push(self.next_faces.len());
            } else {
                self.next_faces.truncate(begin);
            }
        }
        self.faces = faces;
        // The new face(s): follow the links from every new vertex not yet used.
        let total = self.next_verts.len();
        self.next_link.clear();
        self.next_link.resize(total, NONE);
        for &(from, to) in &self.links {
            self.next_link[from as usize] = to;
        }
        for s in kept..total {
            if self.next_link[s] == NONE {
                continue;
            }
            let begin = self.next_faces.len();
            let mut v = s as u32;
            for _ in 0..total {
                let w = self.next_link[v as usize];
                if w == NONE {
                    break;
                }
                self.next_faces.push(v);
                self.next_link[v as usize] = NONE;
                v = w;
            }
            if self.next_faces.len() - begin >= 3 {
                self.next_start.push(self.next_faces.len());
            } else {
                self.next_faces.truncate(begin);
            }
        }
        core::mem::swap(&mut self.verts, &mut self.next_verts);
        core::mem::swap(&mut self.faces, &mut self.next_faces);
        core::mem::swap(&mut self.start, &mut self.next_start);
        self.r2 = self.verts.iter().map(|&v| dot(v, v)).fold(0.0, f64::max);
        true
    }

    /// The integrals of the polyhedron (relative to its site).
    fn integrate(&self) -> Integrals {
        let mut r = Integrals::default();
        for f in 0..self.start.len().saturating_sub(1) {
            let face = &self.faces[self.start[f]..self.start[f + 1]];
            let Some(&a) = face.first() else { continue };
            let a = self.verts[a as usize];
            for w in face[1..].windows(2) {
                let (b, c) = (self.verts[w[0] as usize], self.verts[w[1] as usize]);
                let det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0]);
                let sum = [a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]];
                r.volume += det;
                for (f, &x) in r.first.iter_mut().zip(&sum) {
                    *f += det * x;
                }
                r.moment += det * (dot(a, a) + dot(b, b) + dot(c, c) + dot(sum, sum));
            }
        }
        r.volume /= 6.0;
        r.first = r.first.map(|x| x / 24.0);
        r.moment /= 120.0;
        r
    }
}

/// The cell of site `i`, cut from `poly` (first by the bisectors of the sites of `hint`);
/// `None` when a cut was refused.
fn cell<P: Polyhedron>(
    i: usize,
    pts: &[[f64; 3]],
    torus: bool,
    buckets: &Buckets<3>,
    hint: &[u32],
    poly: &mut P,
    cand: &mut Vec<(f64, [f64; 3], u32)>,
) -> Option<Integrals> {
    let p = pts[i];
    if torus {
        poly.reset([-0.5; 3], [0.5; 3]);
    } else {
        poly.reset(p.map(|x| -x), p.map(|x| 1.0 - x));
    }
    if !hint.is_empty() {
        return hinted_cell(i, pts, torus, buckets, hint, poly, cand);
    }
    let g = buckets.g as i64;
    let h = 1.0 / g as f64;
    let home = p.map(|x| bucket_of(x, buckets.g) as i64);
    let mut r = 0i64;
    loop {
        // The sites of the ring of buckets at Chebyshev distance r, nearest first.
        cand.clear();
        let limit = 4.0 * poly.r2();
        for dz in -r..=r {
            for dy in -r..=r {
                let inner = dz.abs() < r && dy.abs() < r;
                let step = if inner { (2 * r).max(1) } else { 1 };
                let mut dx = -r;
                while dx <= r {
                    let b = [home[0] + dx, home[1] + dy, home[2] + dz];
                    dx += step;
                    let (shift, u) = if torus {
                        (
                            b.map(|x| x.div_euclid(g) as f64),
                            b.map(|x| x.rem_euclid(g) as usize),
                        )
                    } else if b.iter().any(|&x| x < 0 || x >= g) {
                        continue;
                    } else {
                        ([0.0; 3], b.map(|x| x as usize))
                    };
                    for &j in buckets.get(u) {
                        if j as usize == i {
                            // Its own copies' bisectors are the faces of the torus box.
                            continue;
                        }
                        let pj = pts[j as usize];
                        let q = [0, 1, 2].map(|k| pj[k] + shift[k] - p[k]);
                        let d2 = dot(q, q);
                        // Beyond twice the current radius: cannot cut, now or later.
                        if d2 < limit {
                            cand.push((d2, q, j));
                        }
                    }
                }
            }
        }
        cand.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        for &(d2, q, j) in cand.iter() {
            // A bisector at distance |q| / 2 cuts only when some vertex is farther.
            if d2 >= 4.0 * poly.r2() {
                break;
            }
            if !poly.cut(q, 0.5 * d2, j) {
                return None;
            }
        }
        if poly.is_empty() {
            return Some(Integrals::default());
        }
        // Sites of ring r + 1 are at least r h away.
        let reach = 2.0 * poly.r2().sqrt();
        if r as f64 * h >= reach || (!torus && r >= g) {
            break;
        }
        r += 1;
    }
    poly.integrals()
}

/// The cell of site `i` from the box `poly`, first cut by the bisectors of the sites of
/// `hint` (each at its nearest copy on the torus), then by every other site within twice
/// the cell's radius `R` (the buckets meeting the cube of half-side `2 R` around the site;
/// a farther site cannot cut, and `R` only shrinks); `None` when a cut was refused.
fn hinted_cell<P: Polyhedron>(
    i: usize,
    pts: &[[f64; 3]],
    torus: bool,
    buckets: &Buckets<3>,
    hint: &[u32],
    poly: &mut P,
    used: &mut Vec<(f64, [f64; 3], u32)>,
) -> Option<Integrals> {
    let p = pts[i];
    used.clear();
    for &j in hint {
        let Some(&pj) = pts.get(j as usize) else {
            continue;
        };
        if j as usize == i {
            continue;
        }
        let shift = [0, 1, 2].map(|k| if torus { -(pj[k] - p[k]).round() } else { 0.0 });
        let q = [0, 1, 2].map(|k| pj[k] + shift[k] - p[k]);
        used.push((dot(q, q), shift, j));
    }
    // Nearest first: the near bisectors shrink the cell fastest.
    used.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    for &(d2, shift, j) in used.iter() {
        if d2 >= 4.0 * poly.r2() {
            break;
        }
        let pj = pts[j as usize];
        let q = [0, 1, 2].map(|k| pj[k] + shift[k] - p[k]);
        if !poly.cut(q, 0.5 * d2, j) {
            return None;
        }
    }
    if poly.is_empty() {
        return Some(Integrals::default());
    }
    let reach = 2.0 * poly.r2().sqrt();
    let range = |x: f64| buckets.span(x, reach, torus);
    let (rx, ry, rz) = (range(p[0]), range(p[1]), range(p[2]));
    let wrap = |b: i64| buckets.unroll(b);
    for bz in rz.0..=rz.1 {
        let (uz, sz) = wrap(bz);
        for by in ry.0..=ry.1 {
            let (uy, sy) = wrap(by);
            for bx in rx.0..=rx.1 {
                let (ux, sx) = if torus { wrap(bx) } else { (bx as usize, 0.0) };
                let shift = [sx, sy, sz];
                for &j in buckets.get([ux, uy, uz]) {
                    if j as usize == i && shift == [0.0; 3] {
                        continue;
                    }
                    let pj = pts[j as usize];
                    let q = [0, 1, 2].map(|k| pj[k] + shift[k] - p[k]);
                    let d2 = dot(q, q);
                    if d2 >= 4.0 * poly.r2() || used.iter().any(|u| u.2 == j && u.1 == shift) {
                        continue;
                    }
                    if j as usize == i {
                        // Its own copies' bisectors are the faces of the torus box.
                        continue;
                    }
                    if !poly.cut(q, 0.5 * d2, j) {
                        return None;
                    }
                }
            }
        }
    }
    if poly.is_empty() {
        return Some(Integrals::default());
    }
    poly.integrals()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Uniform sites in the cube from a small linear congruential generator.
    fn sites(n: usize, seed: u64) -> Vec<[f64; 3]> {
        let mut x = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let mut unit = move || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..n).map(|_| [unit(), unit(), unit()]).collect()
    }

    fn close(a: Integrals, b: Integrals) -> bool {
        let near = |x: f64, y: f64| (x - y).abs() <= 1e-14;
        near(a.volume, b.volume)
            && near(a.moment, b.moment)
            && (0..3).all(|k| near(a.first[k], b.first[k]))
    }

    /// The dual cells against the independent face-list polyhedron, cell by cell, with
    /// and without hints (the true neighbours, other sites' neighbours, and none).
    #[test]
    fn dual_and_hinted_cells_match_the_face_list_cells() {
        for torus in [false, true] {
            let pts = sites(300, 5 + torus as u64);
            let flat: Vec<f64> = pts.iter().flatten().copied().collect();
            let b = Buckets::new(&pts).unwrap();
            let (mut dual, mut faces, mut cand) =
                (DualCell::default(), Scratch::default(), Vec::new());
            let (_, nb) = Voronoi3::hinted(&flat, torus, None, &Budget::DEFAULT).unwrap();
            for i in 0..pts.len() {
                let want = cell(i, &pts, torus, &b, &[], &mut faces, &mut cand).unwrap();
                assert!(want.volume > 0.0);
                let wrong: Vec<u32> = nb.of((i + 7) % pts.len()).to_vec();
                for hint in [&[][..], nb.of(i), &wrong] {
                    let got = cell(i, &pts, torus, &b, hint, &mut dual, &mut cand).unwrap();
                    assert!(close(got, want), "{torus} {i}");
                }
            }
        }
    }
}
