//! A convex polyhedron in 3D kept as its triangulated dual, cut by half-spaces in place:
//! the fast path of the exact Voronoi cells of [`super::voronoi3`].
//!
//! ## The representation
//!
//! The polyhedron is `{x : x . q_a <= c_a for every plane a}` (coordinates relative to
//! its site, which lies inside: every `c_a >= 0`). Every vertex is where three planes
//! meet and is stored as the triangle `(a, b, c)` of their indices, ordered
//! counter-clockwise seen from outside, with its coordinates; the triangles form the
//! dual mesh, a closed triangulated sphere whose directed edges `a -> b` each belong to
//! one triangle, found through a table indexed by the pair. This is the cell
//! representation of Ray, Sokolov, Lefebvre & Lévy (2018, "Meshless Voronoi on the GPU",
//! ACM TOG 37(6)).
//!
//! ## A cut
//!
//! Cutting by `x . q <= c` removes the triangles whose vertex lies strictly outside
//! (`x . q > c`). The directed edges `a -> b` of removed triangles whose twin `b -> a`
//! belongs to a kept triangle form the hole's boundary; each gets the new triangle
//! `(a, b, p)` (`p` the new plane) whose vertex lies on the polyhedron's edge along the
//! line of planes `a` and `b`, interpolated between the removed vertex and the kept one
//! (the same point the face-list clipping computes). In exact arithmetic the boundary is
//! one cycle visiting every plane at most once (a convex face meets a half-space in one
//! piece); a cut whose boundary is not (rounding, in a near-degenerate configuration) is
//! refused and leaves the polyhedron unchanged, and the caller computes that cell
//! another way. A cut costs the side test of every vertex and work proportional to the
//! removed and created vertices, with no rebuild.
//!
//! ## The integrals
//!
//! Every edge of the polyhedron joins the vertices of two triangles sharing a directed
//! pair: for the triangle `t` with `a -> b` and the twin `t'` with `b -> a`, the edge from
//! `v_t` to `v_t'` runs counter-clockwise (seen from outside) around face `b`. Fanning each
//! face from `m_b`, the foot of the site's perpendicular on plane `b`
//! (`m_b = c_b q_b / |q_b|^2`), gives the tetrahedra `(0, m_b, v_t, v_t')` of signed volume
//! `det(m_b, v_t, v_t') / 6`, one for each directed pair of each triangle; the volume,
//! first moment `sum det (m + v + w) / 24` and second moment
//! `sum det (|m|^2 + |v|^2 + |w|^2 + |m + v + w|^2) / 120` follow as for any fan of a
//! closed, consistently oriented surface (exact up to rounding; `m_b` may lie outside its
//! face, the signs then cancel).

use super::voronoi3::Integrals;

/// No triangle.
const NONE: u32 = u32::MAX;

/// The planes a fresh table holds before it grows (doubling).
const START_PLANES: usize = 64;

/// The polyhedron and its reused buffers.
#[derive(Default)]
pub(super) struct DualCell {
    /// Plane normals and offsets (`x . q <= c`) and the feet `c q / |q|^2`.
    q: Vec<[f64; 3]>,
    c: Vec<f64>,
    foot: Vec<[f64; 3]>,
    /// The site each plane comes from ([`NONE`] for the box).
    tag: Vec<u32>,
    /// The triangles' planes (counter-clockwise from outside) and vertices; a free slot
    /// holds the origin (never outside a plane, as `c >= 0`) and is listed in `free`.
    tri: Vec<[u32; 3]>,
    x: Vec<f64>,
    y: Vec<f64>,
    z: Vec<f64>,
    alive: Vec<bool>,
    free: Vec<u32>,
    live: usize,
    /// `edge[a * cap + b]`: the triangle holding the directed pair `a -> b`.
    edge: Vec<u32>,
    cap: usize,
    /// The largest squared vertex distance from the site.
    r2: f64,
    side: Vec<f64>,
    out: Vec<u32>,
    mark: Vec<u32>,
    stamp: u32,
    /// The hole's boundary: `(a, b, new vertex)`.
    bound: Vec<(u32, u32, [f64; 3])>,
    /// Per plane: the successor on the boundary and the stamp it was set under.
    succ: Vec<(u32, u32)>,
}

impl DualCell {
    /// The box `[lo, hi]` (relative to the site; `lo <= 0 <= hi`).
    pub(super) fn reset(&mut self, lo: [f64; 3], hi: [f64; 3]) {
        self.q.clear();
        self.c.clear();
        self.foot.clear();
        self.tag.clear();
        for k in 0..3 {
            let mut e = [0.0; 3];
            e[k] = -1.0;
            self.push_plane(e, -lo[k], NONE);
            e[k] = 1.0;
            self.push_plane(e, hi[k], NONE);
        }
        if self.cap < START_PLANES {
            self.cap = START_PLANES;
            self.edge = vec![NONE; START_PLANES * START_PLANES];
        }
        self.tri.clear();
        self.x.clear();
        self.y.clear();
        self.z.clear();
        self.alive.clear();
        self.free.clear();
        self.mark.clear();
        for k in 0..8u32 {
            let (i, j, l) = (k & 1, (k >> 1) & 1, (k >> 2) & 1);
            // Planes 2 d (low) and 2 d + 1 (high); det(q_a, q_b, q_c) is the product of
            // the three signs, positive when counter-clockwise.
            let t = if (i + j + l) % 2 == 1 {
                [i, 2 + j, 4 + l]
            } else {
                [i, 4 + l, 2 + j]
            };
            let pick = |d: usize, b: u32| if b == 0 { lo[d] } else { hi[d] };
            self.add(t, [pick(0, i), pick(1, j), pick(2, l)]);
        }
        self.live = 8;
        self.update_radius();
    }

    fn push_plane(&mut self, q: [f64; 3], c: f64, tag: u32) {
        self.tag.push(tag);
        let n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
        let f = c / n2;
        self.q.push(q);
        self.c.push(c);
        self.foot.push([q[0] * f, q[1] * f, q[2] * f]);
    }

    /// A triangle in a free slot (or a new one), entered in the edge table.
    fn add(&mut self, t: [u32; 3], v: [f64; 3]) {
        let slot = match self.free.pop() {
            Some(s) => s as usize,
            None => {
                self.tri.push(t);
                self.x.push(0.0);
                self.y.push(0.0);
                self.z.push(0.0);
                self.alive.push(false);
                self.mark.push(0);
                self.tri.len() - 1
            }
        };
        self.tri[slot] = t;
        (self.x[slot], self.y[slot], self.z[slot]) = (v[0], v[1], v[2]);
        self.alive[slot] = true;
        let cap = self.cap;
        for k in 0..3 {
            self.edge[t[k] as usize * cap + t[(k + 1) % 3] as usize] = slot as u32;
        }
    }

    fn update_radius(&mut self) {
        let mut r2 = 0.0f64;
        for ((x, y), z) in self.x.iter().zip(&self.y).zip(&self.z) {
            r2 = r2.max(x * x + y * y + z * z);
        }
        self.r2 = r2;
    }

    /// The largest squared distance of a vertex from the site.
    pub(super) fn r2(&self) -> f64 {
        self.r2
    }

    /// `true` once a cut removed every vertex.
    pub(super) fn is_empty(&self) -> bool {
        self.live == 0
    }

    /// Cuts by `x . q <= c` (`c > 0`), the plane of site `tag`. `false` when the cut was
    /// refused (a hole boundary that is not one simple cycle; the polyhedron is
    /// unchanged), `true` otherwise.
    pub(super) fn cut(&mut self, q: [f64; 3], c: f64, tag: u32) -> bool {
        let m = self.tri.len();
        self.side.clear();
        self.out.clear();
        let mut any = false;
        for ((x, y), z) in self.x.iter().zip(&self.y).zip(&self.z) {
            let s = x * q[0] + y * q[1] + z * q[2] - c;
            any |= s > 0.0;
            self.side.push(s);
        }
        if !any {
            return true;
        }
        for (k, &s) in self.side.iter().enumerate() {
            if s > 0.0 {
                self.out.push(k as u32);
            }
        }
        if self.out.is_empty() {
            return true;
        }
        if self.out.len() == self.live {
            self.live = 0;
            return true;
        }
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.mark.iter_mut().for_each(|s| *s = 0);
            self.succ.iter_mut().for_each(|s| s.1 = 0);
            self.stamp = 1;
        }
        let stamp = self.stamp;
        for &t in &self.out {
            self.mark[t as usize] = stamp;
        }
        let cap = self.cap;
        self.bound.clear();
        for &t in &self.out {
            let t = t as usize;
            let tri = self.tri[t];
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                let Some(&u) = self.edge.get(b as usize * cap + a as usize) else {
                    return false;
                };
                let u = u as usize;
                if u >= m || !self.alive[u] {
                    return false;
                }
                if self.mark[u] == stamp {
                    continue;
                }
                let (si, so) = (self.side[u], self.side[t]);
                let f = si / (si - so);
                let v = [
                    self.x[u] + f * (self.x[t] - self.x[u]),
                    self.y[u] + f * (self.y[t] - self.y[u]),
                    self.z[u] + f * (self.z[t] - self.z[u]),
                ];
                self.bound.push((a, b, v));
            }
        }
        // One simple cycle: every plane leaves at most once, and the walk from the first
        // edge returns after visiting them all.
        if self.succ.len() < self.q.len() {
            self.succ.resize(self.q.len(), (NONE, 0));
        }
        for &(a, b, _) in &self.bound {
            let s = &mut self.succ[a as usize];
            if s.1 == stamp {
                return false;
            }
            *s = (b, stamp);
        }
        let Some(&(first, _, _)) = self.bound.first() else {
            return false;
        };
        let (mut walk, mut steps) = (first, 0);
        loop {
            let (b, s) = self.succ[walk as usize];
            if s != stamp || steps == self.bound.len() {
                return false;
            }
            (walk, steps) = (b, steps + 1);
            if walk == first {
                break;
            }
        }
        if steps != self.bound.len() {
            return false;
        }
        // Commit: the new plane, the removed triangles freed, the new ones added.
        let p = self.q.len();
        if p >= self.cap {
            self.grow();
        }
        self.push_plane(q, c, tag);
        for k in 0..self.out.len() {
            let t = self.out[k] as usize;
            self.alive[t] = false;
            (self.x[t], self.y[t], self.z[t]) = (0.0, 0.0, 0.0);
            self.free.push(t as u32);
        }
        self.live -= self.out.len();
        let bound = core::mem::take(&mut self.bound);
        for &(a, b, v) in &bound {
            self.add([a, b, p as u32], v);
        }
        self.live += bound.len();
        self.bound = bound;
        self.update_radius();
        true
    }

    /// Appends the sites of the faces (each once; not the box's) to `out`.
    pub(super) fn faces(&mut self, out: &mut Vec<u32>) {
        if self.live == 0 {
            return;
        }
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.mark.iter_mut().for_each(|s| *s = 0);
            self.succ.iter_mut().for_each(|s| s.1 = 0);
            self.stamp = 1;
        }
        if self.succ.len() < self.q.len() {
            self.succ.resize(self.q.len(), (NONE, 0));
        }
        for (t, tri) in self.tri.iter().enumerate() {
            if !self.alive[t] {
                continue;
            }
            for &a in tri {
                let a = a as usize;
                if self.succ[a].1 != self.stamp {
                    self.succ[a].1 = self.stamp;
                    if self.tag[a] != NONE {
                        out.push(self.tag[a]);
                    }
                }
            }
        }
    }

    /// Doubles the plane capacity of the edge table.
    fn grow(&mut self) {
        self.cap *= 2;
        let cap = self.cap;
        self.edge = vec![NONE; cap * cap];
        for (t, tri) in self.tri.iter().enumerate() {
            if self.alive[t] {
                for k in 0..3 {
                    self.edge[tri[k] as usize * cap + tri[(k + 1) % 3] as usize] = t as u32;
                }
            }
        }
    }

    /// The volume, first and second moments (relative to the site); `None` should the
    /// dual mesh not be closed (never after accepted cuts).
    pub(super) fn integrate(&self) -> Option<Integrals> {
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let mut r = Integrals::default();
        if self.live == 0 {
            return Some(r);
        }
        let cap = self.cap;
        for (t, tri) in self.tri.iter().enumerate() {
            if !self.alive[t] {
                continue;
            }
            let v = [self.x[t], self.y[t], self.z[t]];
            for k in 0..3 {
                let (a, b) = (tri[k] as usize, tri[(k + 1) % 3] as usize);
                let u = self
                    .edge
                    .get(b * cap + a)
                    .map_or(usize::MAX, |&u| u as usize);
                let (Some(&x), Some(&y), Some(&z)) = (self.x.get(u), self.y.get(u), self.z.get(u))
                else {
                    return None;
                };
                let w = [x, y, z];
                let m = self.foot[b];
                let det = m[0] * (v[1] * w[2] - v[2] * w[1]) - m[1] * (v[0] * w[2] - v[2] * w[0])
                    + m[2] * (v[0] * w[1] - v[1] * w[0]);
                let sum = [m[0] + v[0] + w[0], m[1] + v[1] + w[1], m[2] + v[2] + w[2]];
                r.volume += det;
                for (f, &x) in r.first.iter_mut().zip(&sum) {
                    *f += det * x;
                }
                r.moment += det * (dot(m, m) + dot(v, v) + dot(w, w) + dot(sum, sum));
            }
        }
        r.volume /= 6.0;
        r.first = r.first.map(|x| x / 24.0);
        r.moment /= 120.0;
        Some(r)
    }
}
