//! Hierarchical sampling on a Penrose tiling, after Ostromoukhov, Donohue & Jodoin 2004
//! ("Fast Hierarchical Importance Sampling with Blue Noise Properties", ACM TOG 23(3),
//! SIGGRAPH): one sample a tile of a recursively subdivided Penrose tiling, the tiles
//! ranked through the subdivision so that thresholding the ranks against a density gives
//! that density, at any level of the hierarchy.
//!
//! ## The tiling
//!
//! The rhombus tiling (P3) cut into Robinson triangles: a *thin* half (the golden triangle,
//! angles 36°, 72°, 72°, legs `l`, base `l / phi`) and a *thick* half (the golden gnomon,
//! 108°, 36°, 36°, legs `l`, base `phi l`), `phi = (1 + sqrt 5) / 2`. A triangle
//! `(a, b, c)` with its apex `a` subdivides into triangles of legs `l / phi`:
//!
//! * thin: `p = a + (b - a) / phi`; children thin `(c, p, b)` and thick `(p, c, a)`;
//! * thick: `q = b + (a - b) / phi`, `r = b + (c - b) / phi`; children thick `(r, c, a)`,
//!   thick `(q, r, b)` and thin `(r, q, a)`.
//!
//! Areas shrink by `phi^2` a level, and a thin (thick) triangle has `F(2h + 1)`
//! (`F(2h + 2)`) descendants `h` levels down, `F` the Fibonacci numbers (`F(1) = F(2) = 1`):
//! the counts obey `thin(h) = thin(h-1) + thick(h-1)`, `thick(h) = thin(h-1) + 2 thick(h-1)`.
//! The start is the "sun", ten thin triangles of legs 1 around the origin (a decagon of
//! area `5 sin 36°`), subdivided `L` levels; the unit square sits inside it, rotated by a
//! random angle and moved by a random offset of at most 0.1 from the centre (the seed).
//! Each leaf triangle carries one sample, at its centroid moved by a correction vector
//! (below).
//!
//! ## The ranks
//!
//! A tile `T` of height `h` with children `C_1 .. C_k` (their leaf counts `m_j`, `n = sum
//! m_j`) orders its leaves by interleaving its children's orders: slot `s = 0 .. n-1` of
//! `T` goes to the child with the largest deficit `(s + 1) m_j - t_j n` (`t_j` the slots it
//! has, ties to the first child), and that child's next leaf takes it. So among the first
//! `s` leaves of `T`, child `j` holds `s m_j / n` within one, at every level at once: the
//! first `t n` leaves of the whole tiling hold about `t` of the leaves of every tile (to
//! within one leaf a level). The leaves' global ranks are the paper's thresholds; where
//! the paper numbers the tiles in the Fibonacci number system, the ranks here follow the
//! same Fibonacci counts through this interleaving (our construction).
//!
//! * [`Penrose::generate`]: `N` points, the first `N` leaves of the square in rank order
//!   (the depth `L` the least with at least `N` leaves in the square). The set is
//!   progressive: every prefix of it is a uniform set of that many points.
//! * [`importance`]: density `rho` (points per unit area): the leaf at `x` of global rank
//!   `i` is kept when `(i + 1/2) / n_leaves < rho(x) / D`, `D = n_leaves / area` the leaf
//!   density (at least the density's maximum). The expected count in a region is the
//!   integral of `rho` over it, to the rank stratification's error.
//!
//! ## Correction vectors
//!
//! As in the paper, samples move by vectors learned offline by relaxation: the sample of a
//! leaf `(a, b, c)` is `centroid + alpha (b - a) + beta (c - a)`, `(alpha, beta)` from a
//! [`Table`] indexed by the leaf's class (its index among the 89 or 144 leaves of its
//! ancestor five levels up) and the band of the threshold fraction `t` (four bands of
//! `(phi^-2, 1]`, equal in `log t`); a move that would leave the square is not made. The
//! table, `tables/penrose_corrections.rs`, is made by our optimizer
//! ([`crate::blue_noise::penrose_train`]). [`Penrose::corrected`]`(false)` keeps the
//! centroids (the tiling's rings of centroids around its vertices, a minimum distance of
//! about 0.57 of the hexagonal spacing).
//!
//! ## Deviation from the paper
//!
//! The thresholds are the interleaved ranks above, not the paper's F-codes; the table's
//! indexing and values are ours; [`importance`] leaves its samples at the centroids (its
//! threshold varies beyond the trained bands); the depth is uniform (the paper refines
//! only where the density asks). Some rings of ten samples around tiling vertices survive
//! the correction (a class does not see beyond its ancestor).
//!
//! ## Cost
//!
//! `O(M L)` for the `M` leaves in and around the square (`M` at most `phi^2 N` plus the
//! border) and `L = O(log N)` levels, plus sorting `M` ranks; memory about `M + 0.42 n`
//! words for `n` leaves of the whole sun (the rank tables). Estimated ([`Penrose::cost`])
//! against a [`Budget`] and stopped at its deadline.
//!
//! ```
//! use qmckit::blue_noise::Penrose;
//! use qmckit::work::Budget;
//! let set = Penrose::new(500)?.seed(1).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 500);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::lloyd::to_fraction;
use super::rng::Rng;
use crate::work::{Budget, Cost, Pacer, Rate};
use crate::{Error, Result};

/// The most points [`Penrose`] and [`importance`] give: 2^20.
pub const PENROSE_MAX_POINTS: u64 = 1 << 20;

/// The golden ratio.
const PHI: f64 = 1.618_033_988_749_895;

/// The deepest subdivision (the sun then has `10 F(2 L + 1)` leaves, 2.9e8 at 20).
const MAX_LEVELS: usize = 20;

/// Leaf steps a second, one core, release (a leaf's rank walk over its levels counted as
/// one step a level; 10^6 points, written by the command, took 6.6 s on a loaded machine
/// against 2.5 s estimated at 5e7, so taken at 2e7).
const STEPS: Rate = Rate::per_second(2e7);

/// The two Robinson triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
enum Kind {
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
fn sun_area() -> f64 {
    5.0 * (core::f64::consts::PI / 5.0).sin()
}

/// Leaves `h` levels below a thin and a thick triangle: `(F(2h + 1), F(2h + 2))`.
fn leaves(h: usize) -> (u64, u64) {
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
struct Tables {
    thin: Vec<Vec<u32>>,
    thick: Vec<Vec<u32>>,
    sun: Vec<u32>,
    /// `leaves(h)` for `h = 0 ..= levels`.
    counts: Vec<(u64, u64)>,
    levels: usize,
}

impl Tables {
    fn new(levels: usize, pacer: &mut Pacer) -> Result<Self> {
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
    fn total(&self) -> u64 {
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
    fn new(seed: u64) -> Self {
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

fn inside(u: [f64; 2]) -> bool {
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

/// The class of a leaf with fewer than [`CLASS_DEPTH`] levels above it.
pub(crate) const NO_CLASS: u8 = u8::MAX;

/// Levels between a leaf and the ancestor that defines its class.
pub(crate) const CLASS_DEPTH: usize = 5;

/// Classes of leaves: 89 below a thin ancestor five levels up (`F(11)`), 144 below a
/// thick one (`F(12)`).
pub(crate) const CLASSES: usize = 233;

/// Bands of the threshold fraction `t` in `(phi^-2, 1]`, equal in `log t`.
pub(crate) const BANDS: usize = 4;

/// A correction table: for each band and class, the offset `(alpha, beta)` of the sample
/// from the leaf's centroid in the leaf's frame, `alpha (b - a) + beta (c - a)`.
pub type Table = [[[f64; 2]; CLASSES]; BANDS];

/// The correction table made by [`crate::blue_noise::penrose_train`] (see
/// `examples/gen_penrose_table.rs`).
static CORRECTIONS: Table = include!("../../tables/penrose_corrections.rs");

/// The band of a threshold fraction `t` (`(phi^-2, 1]` maps onto `0 .. BANDS`, outside
/// clamped to the ends).
pub(crate) fn band(t: f64) -> usize {
    let u = (1.0 / t).ln() / (PHI * PHI).ln();
    ((u * BANDS as f64).floor().max(0.0) as usize).min(BANDS - 1)
}

/// The class of the leaf at the end of `path` (module doc of [`Leaf::class`]).
fn class(path: &[(Kind, u8)]) -> u8 {
    let Some(tail) = path
        .len()
        .checked_sub(CLASS_DEPTH)
        .and_then(|s| path.get(s..))
    else {
        return NO_CLASS;
    };
    let mut local = 0u64;
    for (i, &(kind, child)) in tail.iter().enumerate() {
        let (tn, tk) = leaves(CLASS_DEPTH - 1 - i);
        local += match kind {
            Kind::Thin => u64::from(child) * tn,
            Kind::Thick => u64::from(child) * tk,
        };
    }
    let base = if tail[0].0 == Kind::Thick {
        leaves(CLASS_DEPTH).0
    } else {
        0
    };
    (local + base) as u8
}

/// The direction of `v` in steps of 18° (`0 .. 20`).
fn direction(v: [f64; 2]) -> u8 {
    let k = (v[1].atan2(v[0]) / (core::f64::consts::PI / 10.0)).round() as i64;
    k.rem_euclid(20) as u8
}

/// The sample of `leaf`: its centroid moved by `table[band][class]` in its frame (legs of
/// length `leg`), or the centroid when it has no class or the move would leave the square.
pub(crate) fn place(leaf: &Leaf, frame: &Frame, leg: f64, band: usize, table: &Table) -> [f64; 2] {
    let Some(&[alpha, beta]) = table
        .get(band)
        .and_then(|row| row.get(usize::from(leaf.class)))
    else {
        return leaf.p;
    };
    let [e1, e2] = leaf.dirs.map(|k| {
        let t = f64::from(k) * core::f64::consts::PI / 10.0;
        frame.rotate([leg * t.cos(), leg * t.sin()])
    });
    let moved = [
        leaf.p[0] + alpha * e1[0] + beta * e2[0],
        leaf.p[1] + alpha * e1[1] + beta * e2[1],
    ];
    if inside(moved) { moved } else { leaf.p }
}

/// Every leaf of the sun subdivided `tables.levels` times whose centroid lies in the
/// square, with its global rank, unordered.
fn square_leaves(tables: &Tables, frame: &Frame, pacer: &mut Pacer) -> Result<Vec<Leaf>> {
    // The leaves of the square: its area over a leaf's mean area, with a margin.
    let expect = tables.total() as f64 / sun_area();
    let mut out = crate::size::vec_with_capacity::<Leaf>((expect * 1.1) as usize + 64)?;
    let mut path = Vec::with_capacity(tables.levels);
    for (i, t) in sun().iter().enumerate() {
        walk(t, i, tables, frame, &mut path, &mut out, pacer)?;
    }
    Ok(out)
}

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

/// The least depth whose leaves in the square number at least `density` a unit area (on
/// average), or an error past [`MAX_LEVELS`].
pub(crate) fn depth_for(density: f64) -> Result<usize> {
    (1..=MAX_LEVELS)
        .find(|&l| 10.0 * leaves(l).0 as f64 / sun_area() >= density)
        .ok_or(Error::InvalidParameter {
            what: "penrose sampling takes at most 2^20 points a unit area",
        })
}

/// The estimated cost of a subdivision giving about `density` leaves a unit area: the
/// square's leaves (at most `phi^2` times the density), their rank walks of `L` levels,
/// the pruned border and the rank tables.
fn cost_for(density: f64) -> Cost {
    let levels = depth_for(density).unwrap_or(MAX_LEVELS) as f64;
    let leaves = density * PHI * PHI * 1.3;
    Cost::steps(leaves * (levels + 2.0 + leaves.log2().max(1.0)), STEPS)
}

/// The leaves of the square at `levels` for `seed`, sorted by rank, the frame, and the
/// number of leaves of the sun.
pub(crate) fn ranked(levels: usize, seed: u64, budget: &Budget) -> Result<(Vec<Leaf>, Frame, u64)> {
    const WHAT: &str = "penrose sampling";
    let mut pacer = budget.pacer(WHAT);
    let tables = Tables::new(levels, &mut pacer)?;
    let frame = Frame::new(seed);
    let mut leaves = square_leaves(&tables, &frame, &mut pacer)?;
    leaves.sort_unstable_by_key(|l| l.rank);
    Ok((leaves, frame, tables.total()))
}

/// The legs of the leaves of a sun of legs 1 subdivided `levels` times.
pub(crate) fn leg(levels: usize) -> f64 {
    PHI.powi(-(levels as i32))
}

fn to_set(points: impl ExactSizeIterator<Item = [f64; 2]>) -> Result<PointSet> {
    let mut coords =
        crate::size::vec_with_capacity(crate::size::coordinates(points.len() as u64, 2)?)?;
    coords.extend(points.flat_map(|p| p.map(to_fraction)));
    PointSet::new(coords, 2)
}

/// Penrose-tiling sampling of the unit square (builder): `N` points in rank order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Penrose {
    n: u64,
    seed: u64,
    corrected: bool,
}

impl Penrose {
    /// `n` points (1 to [`PENROSE_MAX_POINTS`]), seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`].
    pub fn new(n: u64) -> Result<Self> {
        if n == 0 {
            return Err(Error::ZeroPoints);
        }
        if n > PENROSE_MAX_POINTS {
            return Err(Error::TooManyPoints {
                requested: n,
                max: PENROSE_MAX_POINTS,
            });
        }
        Ok(Penrose {
            n,
            seed: 0,
            corrected: true,
        })
    }

    /// Whether the samples move by the correction table (default `true`; `false`: the
    /// leaves' centroids).
    pub fn corrected(mut self, corrected: bool) -> Self {
        self.corrected = corrected;
        self
    }

    /// The seed: the rotation and offset of the square in the tiling.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The estimated running time (module doc, "Cost").
    pub fn cost(&self) -> Cost {
        cost_for(self.n as f64)
    }

    /// The `N` points of lowest rank among the leaves in the square: every prefix of the
    /// set is a uniform set. Refused before it starts when [`cost`](Self::cost) exceeds
    /// `budget`, stopped at its deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let budget = budget.started();
        budget.check("penrose sampling", self.cost())?;
        let mut levels = depth_for(self.n as f64)?;
        loop {
            let (leaves, frame, _) = ranked(levels, self.seed, &budget)?;
            if leaves.len() as u64 >= self.n {
                let b = band(self.n as f64 / leaves.len() as f64);
                let (leg, n) = (leg(levels), self.n as usize);
                return to_set(leaves.iter().take(n).map(|l| {
                    if self.corrected {
                        place(l, &frame, leg, b, &CORRECTIONS)
                    } else {
                        l.p
                    }
                }));
            }
            // The square holds fewer leaves than the mean says (its border): one more level.
            levels += 1;
            if levels > MAX_LEVELS {
                return Err(Error::InvalidParameter {
                    what: "penrose sampling: too many points for the deepest subdivision",
                });
            }
        }
    }
}

/// Importance sampling of the unit square by thresholding Penrose ranks: about
/// `integral of density` points, `density(x, y)` points a unit area, at most
/// `max_density` (1 to [`PENROSE_MAX_POINTS`]), in rank order (the set of a smaller
/// multiple of the density is a prefix-closed subset).
///
/// ```
/// use qmckit::blue_noise::penrose;
/// use qmckit::work::Budget;
/// // 2000 x on the square: about 1000 points, more to the right.
/// let set = penrose::importance(|x, _| 2000.0 * x, 2000.0, 0, &Budget::DEFAULT)?;
/// assert!((set.count() as f64 - 1000.0).abs() < 50.0);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for a `max_density` outside that range or a density value
/// that is not finite or outside `[0, max_density]`; as [`Penrose::generate`].
pub fn importance<F: Fn(f64, f64) -> f64>(
    density: F,
    max_density: f64,
    seed: u64,
    budget: &Budget,
) -> Result<PointSet> {
    if !(1.0..=PENROSE_MAX_POINTS as f64).contains(&max_density) {
        return Err(Error::InvalidParameter {
            what: "penrose importance sampling takes a maximum density from 1 to 2^20",
        });
    }
    let budget = budget.started();
    budget.check("penrose sampling", cost_for(max_density))?;
    let levels = depth_for(max_density)?;
    let (leaves, _, total) = ranked(levels, seed, &budget)?;
    let total = total as f64;
    let leaf_density = total / sun_area();
    let mut kept = crate::size::vec_with_capacity::<[f64; 2]>(0)?;
    for leaf in leaves {
        let rho = density(leaf.p[0], leaf.p[1]);
        if !(0.0..=max_density).contains(&rho) {
            return Err(Error::InvalidParameter {
                what: "penrose importance sampling: a density value not in [0, max_density]",
            });
        }
        if (f64::from(leaf.rank) + 0.5) / total < rho / leaf_density {
            crate::size::reserve(&mut kept, 1)?;
            kept.push(leaf.p);
        }
    }
    to_set(kept.into_iter())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The classes count the leaves of a thin and a thick triangle `CLASS_DEPTH` levels
    /// down: consecutive Fibonacci numbers (thin `F(2h+1)`, thick `F(2h+2)`).
    #[test]
    fn classes_are_the_leaves_below_the_ancestor() {
        let (thin, thick) = leaves(CLASS_DEPTH);
        assert_eq!((thin, thick), (89, 144));
        assert_eq!((thin + thick) as usize, CLASSES);
        assert!(CLASSES < usize::from(NO_CLASS));
    }

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
