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
//! The polyhedron is kept as vertices and faces (vertex index cycles, counter-clockwise
//! seen from outside). A cut keeps the vertices on the inner side (`x . q <= |q|^2 / 2`),
//! puts one new vertex on every edge that crosses the plane (the same one for both faces
//! of the edge) and closes the hole by a new face: in every cut face the new edge runs
//! from the vertex where the face leaves the half-space to the one where it re-enters,
//! and the new face traverses those edges backwards, chained into cycles.
//!
//! ## The integrals
//!
//! Fanning every face from its first vertex into triangles `(a, b, c)` (relative to the
//! site) gives tetrahedra `(0, a, b, c)` of signed volume `det(a, b, c) / 6`: the volume
//! is their sum, the first moment `sum det(a, b, c) (a + b + c) / 24` and the second
//! moment `int |x - p_i|^2 = sum det(a, b, c) (|a|^2 + |b|^2 + |c|^2 + |a + b + c|^2) /
//! 120` (the simplex moment `int x x^T = V/20 (sum v v^T + (sum v)(sum v)^T)` with one
//! vertex at the origin). Exact for any closed, consistently oriented surface, so the
//! volumes sum to the domain's volume 1 up to rounding (tested to `1e-12`).
//!
//! ## Range and cost
//!
//! 1 to [`VORONOI3_MAX_SITES`] distinct sites in `[0, 1]^3` (on the torus taken modulo
//! 1). For evenly spread sites a cell meets a bounded number of candidates (about 45
//! gathered and 12 cuts a cell at 1024 Lloyd-relaxed sites), so the diagram costs `O(N)`
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

/// One cell's integrals relative to its site.
#[derive(Clone, Copy, Default)]
struct Integrals {
    volume: f64,
    first: [f64; 3],
    moment: f64,
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
        let budget = budget.started();
        let pts = sites::validate::<3>(sites, torus, VORONOI3_MAX_SITES)?;
        budget.check("3D Voronoi cells", Self::cost(pts.len()))?;
        sites::check_distinct(
            &pts,
            "two sites coincide: Voronoi cells need distinct sites",
        )?;
        let n = pts.len();
        let buckets = Buckets::new(&pts)?;
        let parts: Vec<Vec<Integrals>> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| {
                budget.check_deadline("3D Voronoi cells")?;
                let mut s = Scratch::default();
                Ok((c * CHUNK..((c + 1) * CHUNK).min(n))
                    .map(|i| cell(i, &pts, torus, &buckets, &mut s))
                    .collect())
            })
            .collect::<Result<Vec<_>>>()?;
        let mut v = Voronoi3 {
            torus,
            volume: crate::size::vec_with_capacity(n)?,
            centroid: crate::size::vec_with_capacity(n)?,
            moment: crate::size::vec_with_capacity(n)?,
        };
        for (c, p) in parts.into_iter().flatten().zip(&pts) {
            v.volume.push(c.volume);
            v.centroid.push(if c.volume > 0.0 {
                [0, 1, 2].map(|k| p[k] + c.first[k] / c.volume)
            } else {
                *p
            });
            v.moment.push(c.moment);
        }
        Ok(v)
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
    cand: Vec<(f64, [f64; 3])>,
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

/// The cell of site `i`.
fn cell(
    i: usize,
    pts: &[[f64; 3]],
    torus: bool,
    buckets: &Buckets<3>,
    s: &mut Scratch,
) -> Integrals {
    let p = pts[i];
    if torus {
        s.reset([-0.5; 3], [0.5; 3]);
    } else {
        s.reset(p.map(|x| -x), p.map(|x| 1.0 - x));
    }
    let g = buckets.g as i64;
    let h = 1.0 / g as f64;
    let home = p.map(|x| bucket_of(x, buckets.g) as i64);
    let mut r = 0i64;
    loop {
        // The sites of the ring of buckets at Chebyshev distance r, nearest first.
        s.cand.clear();
        let limit = 4.0 * s.r2;
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
                            s.cand.push((d2, q));
                        }
                    }
                }
            }
        }
        s.cand.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let cand = core::mem::take(&mut s.cand);
        for &(d2, q) in &cand {
            // A bisector at distance |q| / 2 cuts only when some vertex is farther.
            if d2 >= 4.0 * s.r2 {
                break;
            }
            s.clip(q, 0.5 * d2);
        }
        s.cand = cand;
        if s.start.len() < 2 {
            return Integrals::default();
        }
        // Sites of ring r + 1 are at least r h away.
        let reach = 2.0 * s.r2.sqrt();
        if r as f64 * h >= reach || (!torus && r >= g) {
            break;
        }
        r += 1;
    }
    s.integrate()
}
