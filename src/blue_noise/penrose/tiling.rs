//! The tiling of [`super`]: Robinson triangles and their subdivision, the sun, the
//! interleaved rank tables, the frame of the unit square in the sun, and the walk that
//! collects the leaves of the square with their ranks and classes.

use super::corrections::{class, direction};
use crate::Result;
use crate::blue_noise::rng::Rng;
use crate::work::Pacer;

/// The golden ratio.
pub(super) const PHI: f64 = 1.618_033_988_749_895;

/// The two Robinson triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub(super) enum Kind {
    /// Half a thin rhombus: the golden triangle, apex 36°.
    Thin = 0,
    /// Half a thick rhombus: the golden gnomon, apex 108°.
    Thick = 1,
}

/// A triangle of the tiling, its apex first.
#[derive(Clone, Copy, Debug)]
struct Tri {
    kind: Kind,
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
}

fn lerp(p: [f64; 2], q: [f64; 2], t: f64) -> [f64; 2] {
    [p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t]
}

impl Tri {
    /// The children, in the order of the module doc; the count is 2 (thin) or 3 (thick).
    fn children(&self) -> ([Tri; 3], usize) {
        let (a, b, c) = (self.a, self.b, self.c);
        let t = |kind, a, b, c| Tri { kind, a, b, c };
        match self.kind {
            Kind::Thin => {
                let p = lerp(a, b, 1.0 / PHI);
                let x = t(Kind::Thin, c, p, b);
                ([x, t(Kind::Thick, p, c, a), x], 2)
            }
            Kind::Thick => {
                let q = lerp(b, a, 1.0 / PHI);
                let r = lerp(b, c, 1.0 / PHI);
                (
                    [
                        t(Kind::Thick, r, c, a),
                        t(Kind::Thick, q, r, b),
                        t(Kind::Thin, r, q, a),
                    ],
                    3,
                )
            }
        }
    }

    fn centroid(&self) -> [f64; 2] {
        [
            (self.a[0] + self.b[0] + self.c[0]) / 3.0,
            (self.a[1] + self.b[1] + self.c[1]) / 3.0,
        ]
    }
}

/// The ten thin triangles of the sun, legs 1, apex at the origin (mirrored alternately so
/// that the rhombus halves match).
fn sun() -> [Tri; 10] {
    core::array::from_fn(|i| {
        let angle = |k: f64| {
            let t = k * core::f64::consts::PI / 10.0;
            [t.cos(), t.sin()]
        };
        let (mut b, mut c) = (angle(2.0 * i as f64 - 1.0), angle(2.0 * i as f64 + 1.0));
        if i % 2 == 0 {
            core::mem::swap(&mut b, &mut c);
        }
        Tri {
            kind: Kind::Thin,
            a: [0.0, 0.0],
            b,
            c,
        }
    })
}

/// The area of the sun: ten golden triangles of legs 1.
pub(super) fn sun_area() -> f64 {
    5.0 * (core::f64::consts::PI / 5.0).sin()
}

/// Leaves `h` levels below a thin and a thick triangle: `(F(2h + 1), F(2h + 2))`.
pub(super) fn leaves(h: usize) -> (u64, u64) {
    (0..h).fold((1, 1), |(thin, thick), _| (thin + thick, thin + 2 * thick))
}

/// The interleaving of children of leaf counts `m` (module doc): `slots[off_j + r]` is the
/// parent's slot of child `j`'s `r`-th leaf, `off_j` the sum of the counts before `j`.
fn interleave(m: &[u64], pacer: &mut Pacer) -> Result<Vec<u32>> {
    let n: u64 = m.iter().sum();
    let len = crate::size::product("penrose rank table", n, 1)?;
    let mut slots = crate::size::vec_zeroed::<u32>(len)?;
    let mut offset = [0u64; 10];
    let mut taken = [0u64; 10];
    for j in 1..m.len() {
        offset[j] = offset[j - 1] + m[j - 1];
    }
    let n = n as i64;
    for s in 0..n {
        pacer.tick()?;
        let mut best = 0;
        let mut best_deficit = i64::MIN;
        for (j, &mj) in m.iter().enumerate() {
            let deficit = (s + 1) * mj as i64 - taken[j] as i64 * n;
            if deficit > best_deficit {
                best = j;
                best_deficit = deficit;
            }
        }
        // The deficits sum to n > 0, so the best child has a leaf left.
        slots[(offset[best] + taken[best]) as usize] = s as u32;
        taken[best] += 1;
    }
    Ok(slots)
}

/// The rank tables of a sun subdivided `levels` times: `thin[h]`, `thick[h]` for heights
/// `1 ..= levels`, and the sun's own.
pub(super) struct Tables {
    thin: Vec<Vec<u32>>,
    thick: Vec<Vec<u32>>,
    sun: Vec<u32>,
    /// `leaves(h)` for `h = 0 ..= levels`.
    counts: Vec<(u64, u64)>,
    levels: usize,
}

impl Tables {
    pub(super) fn new(levels: usize, pacer: &mut Pacer) -> Result<Self> {
        let (mut thin, mut thick) = (vec![Vec::new()], vec![Vec::new()]);
        for h in 1..=levels {
            let (tn, tk) = leaves(h - 1);
            thin.push(interleave(&[tn, tk], pacer)?);
            thick.push(interleave(&[tk, tk, tn], pacer)?);
        }
        let sun = interleave(&[leaves(levels).0; 10], pacer)?;
        Ok(Tables {
            thin,
            thick,
            sun,
            counts: (0..=levels).map(leaves).collect(),
            levels,
        })
    }

    /// The number of leaves of the sun.
    pub(super) fn total(&self) -> u64 {
        10 * leaves(self.levels).0
    }

    /// The global rank of the leaf reached by `path`: `(kind, child)` of every level from
    /// the sun's triangle (`path[0]`, its child the sun index) down to the leaf's parent.
    fn rank(&self, sun_index: usize, path: &[(Kind, u8)]) -> u32 {
        let mut r = 0usize;
        for (depth, &(kind, child)) in path.iter().enumerate().rev() {
            let h = self.levels - depth;
            let (tn, tk) = self.counts[h - 1];
            let (table, off) = match kind {
                Kind::Thin => (&self.thin[h], if child == 0 { 0 } else { tn }),
                Kind::Thick => (&self.thick[h], u64::from(child) * tk),
            };
            r = table[off as usize + r] as usize;
        }
        let per = self.counts[self.levels].0 as usize;
        self.sun[sun_index * per + r]
    }
}

/// Where the unit square sits in the sun: `u = R(-theta) (p - centre) + 1/2`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    cos: f64,
    sin: f64,
    centre: [f64; 2],
}

impl Frame {
    pub(super) fn new(seed: u64) -> Self {
        let mut rng = Rng::new(seed, 0x5045_4E52_4F53_4531); // "PENROSE1"
        let theta = rng.unit() * core::f64::consts::TAU;
        let (rho, phi) = (0.1 * rng.unit().sqrt(), rng.unit() * core::f64::consts::TAU);
        Frame {
            cos: theta.cos(),
            sin: theta.sin(),
            centre: [rho * phi.cos(), rho * phi.sin()],
        }
    }

    fn square_point(&self, p: [f64; 2]) -> [f64; 2] {
        let v = self.rotate([p[0] - self.centre[0], p[1] - self.centre[1]]);
        [v[0] + 0.5, v[1] + 0.5]
    }

    /// A vector of the tiling in the square's axes.
    pub(crate) fn rotate(&self, v: [f64; 2]) -> [f64; 2] {
        [
            self.cos * v[0] + self.sin * v[1],
            -self.sin * v[0] + self.cos * v[1],
        ]
    }

    /// Whether triangle `t` may hold a point of the square (its box meets it).
    fn meets(&self, t: &Tri) -> bool {
        let [p, q, r] = [t.a, t.b, t.c].map(|v| self.square_point(v));
        let lo = |k: usize| p[k].min(q[k]).min(r[k]);
        let hi = |k: usize| p[k].max(q[k]).max(r[k]);
        lo(0) < 1.0 && hi(0) >= 0.0 && lo(1) < 1.0 && hi(1) >= 0.0
    }
}

/// Whether `u` lies in the unit square `[0, 1)^2`.
pub(super) fn inside(u: [f64; 2]) -> bool {
    (0.0..1.0).contains(&u[0]) && (0.0..1.0).contains(&u[1])
}

/// A leaf in the square: its global rank, its structural class, the directions of its
/// legs and its centroid.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Leaf {
    /// The global rank.
    pub(crate) rank: u32,
    /// [`NO_CLASS`] or the class: the leaf's index among the leaves of its ancestor
    /// [`CLASS_DEPTH`] levels up, plus 89 when that ancestor is thick.
    pub(crate) class: u8,
    /// The directions of `b - a` and `c - a` in the tiling, in steps of 18°.
    pub(crate) dirs: [u8; 2],
    /// The centroid, in the square.
    pub(crate) p: [f64; 2],
}

/// Every leaf of the sun subdivided `tables.levels` times whose centroid lies in the
/// square, with its global rank, unordered.
pub(super) fn square_leaves(
    tables: &Tables,
    frame: &Frame,
    pacer: &mut Pacer,
) -> Result<Vec<Leaf>> {
    // The leaves of the square: its area over a leaf's mean area, with a margin.
    let expect = tables.total() as f64 / sun_area();
    let mut out = crate::size::vec_with_capacity::<Leaf>((expect * 1.1) as usize + 64)?;
    let mut path = Vec::with_capacity(tables.levels);
    for (i, t) in sun().iter().enumerate() {
        walk(t, i, tables, frame, &mut path, &mut out, pacer)?;
    }
    Ok(out)
}

/// Collects the leaves below `t` (its path from the sun in `path`) whose centroids lie in
/// the square.
fn walk(
    t: &Tri,
    sun_index: usize,
    tables: &Tables,
    frame: &Frame,
    path: &mut Vec<(Kind, u8)>,
    out: &mut Vec<Leaf>,
    pacer: &mut Pacer,
) -> Result<()> {
    if !frame.meets(t) {
        return Ok(());
    }
    if path.len() == tables.levels {
        pacer.tick_n(tables.levels as u32 + 1)?;
        let u = frame.square_point(t.centroid());
        if inside(u) {
            crate::size::reserve(out, 1)?;
            out.push(Leaf {
                rank: tables.rank(sun_index, path),
                class: class(path),
                dirs: [
                    direction([t.b[0] - t.a[0], t.b[1] - t.a[1]]),
                    direction([t.c[0] - t.a[0], t.c[1] - t.a[1]]),
                ],
                p: u,
            });
        }
        return Ok(());
    }
    let (children, k) = t.children();
    for (j, child) in children.iter().take(k).enumerate() {
        path.push((t.kind, j as u8));
        walk(child, sun_index, tables, frame, path, out, pacer)?;
        path.pop();
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::work::Budget;

    fn area(t: &Tri) -> f64 {
        let (u, v) = (
            [t.b[0] - t.a[0], t.b[1] - t.a[1]],
            [t.c[0] - t.a[0], t.c[1] - t.a[1]],
        );
        0.5 * (u[0] * v[1] - u[1] * v[0]).abs()
    }

    fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
        (p[0] - q[0]).hypot(p[1] - q[1])
    }

    /// Every triangle of a few levels is the golden triangle or gnomon its kind says (legs
    /// from the apex equal, base phi or 1/phi times a leg), its children cover its area,
    /// and legs shrink by phi a level.
    #[test]
    fn subdivision_keeps_the_robinson_triangles() {
        let mut level: Vec<Tri> = sun().to_vec();
        let mut leg = 1.0;
        for _ in 0..6 {
            for t in &level {
                let (ab, ac, bc) = (dist(t.a, t.b), dist(t.a, t.c), dist(t.b, t.c));
                assert!((ab - leg).abs() < 1e-9 && (ac - leg).abs() < 1e-9);
                let base = match t.kind {
                    Kind::Thin => leg / PHI,
                    Kind::Thick => leg * PHI,
                };
                assert!((bc - base).abs() < 1e-9, "{t:?}");
                let (ch, k) = t.children();
                let sum: f64 = ch.iter().take(k).map(area).sum();
                assert!((sum - area(t)).abs() < 1e-12);
            }
            level = level
                .iter()
                .flat_map(|t| {
                    let (ch, k) = t.children();
                    ch.into_iter().take(k)
                })
                .collect();
            leg /= PHI;
        }
        let total: f64 = level.iter().map(area).sum();
        assert!((total - sun_area()).abs() < 1e-9);
    }

    #[test]
    fn interleaving_keeps_every_prefix_proportional() {
        let mut pacer = Budget::DEFAULT.started().pacer("test");
        let m = [13u64, 13, 8];
        let slots = interleave(&m, &mut pacer).unwrap();
        let mut sorted = slots.clone();
        sorted.sort_unstable();
        assert!(sorted.iter().enumerate().all(|(i, &s)| s as usize == i));
        let n = 34.0;
        for s in 0..34u32 {
            let mut off = 0;
            for &mj in &m {
                let held = slots[off..off + mj as usize]
                    .iter()
                    .filter(|&&x| x < s)
                    .count() as f64;
                assert!((held - s as f64 * mj as f64 / n).abs() <= 1.0);
                off += mj as usize;
            }
        }
    }
}
