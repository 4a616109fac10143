//! Lloyd relaxation (Lloyd 1982, "Least squares quantization in PCM") and
//! capacity-constrained Voronoi tessellations (Balzer, Schlömer & Deussen 2009,
//! "Capacity-constrained point distributions: a variant of Lloyd's method", SIGGRAPH), in
//! any dimension, in the unit cube or on the unit torus.
//!
//! ## Lloyd
//!
//! Lloyd's algorithm decreases the quantization energy of the sites `s_1..s_N`,
//! `E = integral min_i |x - s_i|^2 dx`, by alternating the assignment of the domain to the
//! nearest site (the Voronoi cells `V_i`) and moving every site to its cell's centroid.
//!
//! In 2D and 3D the cells are exact: convex polygons ([`super::power`], the power diagram
//! with zero weights) and polyhedra ([`super::voronoi3`]) cut from the square or cube (on
//! the torus, from the periodic cell around the site) by the bisectors of the nearby
//! sites, with exact centroids, and `E` is the sum of their exact second moments, so it
//! never increases (tested); the cells are computed in parallel (rayon). Only plain
//! Lloyd: CCVT and projective Lloyd, and every dimension other than 2 and 3 (where exact
//! cells in general `d` are not implemented), take the sampled cells below.
//!
//! Otherwise the integral is a Monte Carlo estimate over one dense sample `y_1..y_M`,
//! `M = k N` uniform points drawn once from the seed (`k` = samples a site, default 64):
//! `E = (1/M) sum_j min_i |y_j - s_i|^2`. With the sample fixed, both steps minimize `E`
//! over their variable, so `E` never increases (tested). The nearest site is found with a
//! k-d tree. On the torus distances are periodic (per axis `min(|d|, 1 - |d|)`) and the
//! centroid is `s_i + mean(wrap(y_j - s_i))` modulo 1 (wrapped differences in
//! `[-1/2, 1/2)`); a site with no sample point stays. Sites start uniform at random.
//!
//! ## CCVT
//!
//! The capacity-constrained variant gives every site exactly `k` of the `M` sample points
//! (equal capacities, so equal-area cells as `k` grows), starting from a random equal
//! split. A pass looks at pairs of sites `(i, j)` where a point of `i` is nearer to `j`
//! than to `i` (its nearest site is `j`); with `h_i(y) = |y - s_i|^2 - |y - s_j|^2` for
//! points of `i` and `h_j(y) = |y - s_j|^2 - |y - s_i|^2` for points of `j`, both sorted
//! in decreasing order, it swaps the leading pairs while `h_i + h_j > 0` (each swap lowers
//! the energy and keeps the capacities: the paper's site-swap step). After a pass the sites
//! move to the centroids of their points. An iteration is one pass and one move; the
//! construction stops after the iterations asked for or when a pass swaps nothing.
//! Unlike the paper, only the pairs (owner, nearest site) of the points are visited (all
//! pairs would cost `O(N^2)`), so a converged result is stable under those swaps.
//!
//! ## Cost
//!
//! Exact cells (plain Lloyd in 2D and 3D): `O(N)` an iteration for evenly spread sites
//! (each cell meets a bounded number of nearby sites through a uniform grid; about 12
//! half-space cuts a cell in 3D), `O(N log N)` for the duplicate check; memory `O(N)`.
//! Sampled cells: each iteration assigns `M` points by the tree: `O(M log N)` in low dimension (the tree
//! degrades towards `O(M N)` as `d` grows past about 10); CCVT adds the sorts of the
//! visited pairs, `O(M log k)`. Estimated before it runs ([`Lloyd::cost`]) against a
//! [`Budget`], stopped at its deadline between and within iterations. Memory
//! `(N + M) (d + 1)` words.
//!
//! ```
//! use qmckit::blue_noise::Lloyd;
//! use qmckit::work::Budget;
//! let set = Lloyd::new(64, 2)?.iterations(10)?.seed(1).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 64);
//! let cc = Lloyd::new(32, 3)?.capacity_constrained(true).torus(true).iterations(5)?.generate(&Budget::DEFAULT)?;
//! assert_eq!(cc.count(), 32);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::kdtree::KdTree;
use super::lloyd_projective::{blend, projection_energy, ranks};
use super::power::PowerDiagram;
use super::rng::Rng;
use super::voronoi3::Voronoi3;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The most sites [`Lloyd`] takes: 2^20.
pub const LLOYD_MAX_POINTS: u64 = 1 << 20;

/// The most dimensions [`Lloyd`] takes.
pub const LLOYD_MAX_DIMS: usize = 64;

/// Steps of [`Lloyd::cost`] a second, one core, release (measured about 1.3e7 for Lloyd
/// and 1e7 for CCVT at 2D, 1024 sites, 64 points a site; taken lower for loaded machines).
const ASSIGNMENTS: Rate = Rate::per_second(3e6);

/// The largest `f64` below 1.
const BELOW_ONE: f64 = 1.0 - f64::EPSILON / 2.0;

/// Sample points between two readings of the clock.
const DEADLINE_POINTS: usize = 1 << 14;

/// Lloyd relaxation or CCVT (builder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lloyd {
    n: u64,
    dims: usize,
    iterations: u32,
    per_site: u32,
    torus: bool,
    ccvt: bool,
    seed: u64,
    projective: f64,
}

/// What [`Lloyd::run`] reports besides the set.
#[derive(Clone, Debug, PartialEq)]
pub struct LloydTrace {
    /// The energy `E` before each iteration and after the last: exact for Lloyd in 2D and
    /// 3D, over the dense sample otherwise (for CCVT, of the capacity-constrained
    /// assignment).
    pub energy: Vec<f64>,
    /// Sample points per site after the last assignment (Voronoi counts for Lloyd on the
    /// dense sample; all `k` for CCVT); empty for Lloyd on exact cells (2D and 3D).
    pub counts: Vec<u32>,
    /// The exact cell volumes (areas in 2D) of the last sites, for Lloyd on exact cells
    /// (2D and 3D; they sum to 1); empty on the dense sample.
    pub volumes: Vec<f64>,
    /// The sites, row-major, as `f64` in `[0, 1)`.
    pub sites: Vec<f64>,
    /// With [`Lloyd::projective`] weight `mu > 0`: the projective energy `E` (the sample
    /// energy plus `mu` times the projections' term, [`super::lloyd_projective`]) with
    /// the ranks and cells of the sites before each iteration and after the last; empty
    /// otherwise.
    pub projective_energy: Vec<f64>,
}

impl Lloyd {
    /// `n` sites (1 to [`LLOYD_MAX_POINTS`]) in `dims` (1 to [`LLOYD_MAX_DIMS`]), Lloyd in
    /// the cube, 30 iterations, 64 samples a site, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::ZeroDimensions`],
    /// [`Error::DimensionOutOfRange`].
    pub fn new(n: u64, dims: usize) -> Result<Self> {
        crate::size::points(n, LLOYD_MAX_POINTS)?;
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if dims > LLOYD_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: dims,
                dims: LLOYD_MAX_DIMS,
            });
        }
        Ok(Lloyd {
            n,
            dims,
            iterations: 30,
            per_site: 64,
            torus: false,
            ccvt: false,
            seed: 0,
            projective: 0.0,
        })
    }

    /// Projective Lloyd: every axis projection pulled towards the midpoints of `N` equal
    /// intervals with weight `mu` (0 to 100; 0 is Lloyd), the energy and step of
    /// [`super::lloyd_projective`]. Plain Lloyd only, in the cube: [`Lloyd::run`] refuses
    /// it with CCVT or on the torus.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for `mu` out of range or not finite.
    ///
    /// ```
    /// use qmckit::blue_noise::Lloyd;
    /// use qmckit::work::Budget;
    /// let t = Lloyd::new(64, 2)?.projective(2.0)?.iterations(10)?.run(&Budget::DEFAULT)?;
    /// assert!(t.projective_energy.last() < t.projective_energy.first());
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn projective(mut self, mu: f64) -> Result<Self> {
        if !(mu.is_finite() && (0.0..=100.0).contains(&mu)) {
            return Err(Error::InvalidParameter {
                what: "the projective Lloyd weight must be 0 to 100",
            });
        }
        self.projective = mu;
        Ok(self)
    }

    /// Iterations (0 to 10^5; 0 returns the random start).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] past 10^5.
    pub fn iterations(mut self, iterations: u32) -> Result<Self> {
        if iterations > 100_000 {
            return Err(Error::InvalidParameter {
                what: "Lloyd relaxation takes at most 10^5 iterations",
            });
        }
        self.iterations = iterations;
        Ok(self)
    }

    /// Dense-sample points a site, `k` (1 to 2^16; the CCVT capacity). Unused by Lloyd on
    /// exact cells (2D and 3D).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn samples_per_site(mut self, k: u32) -> Result<Self> {
        if k == 0 || k > 1 << 16 {
            return Err(Error::InvalidParameter {
                what: "samples a site must be 1 to 65536",
            });
        }
        self.per_site = k;
        Ok(self)
    }

    /// On the unit torus (periodic distances) instead of the cube.
    pub fn torus(mut self, torus: bool) -> Self {
        self.torus = torus;
        self
    }

    /// Capacity-constrained (CCVT) instead of plain Lloyd.
    pub fn capacity_constrained(mut self, ccvt: bool) -> Self {
        self.ccvt = ccvt;
        self
    }

    /// The seed (start and dense sample).
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    fn samples(&self) -> u64 {
        self.n * u64::from(self.per_site)
    }

    /// The estimated running time: `iterations + 1` diagrams of `N` cells on exact cells
    /// ([`PowerDiagram::cost`], [`Voronoi3::cost`]); otherwise `(iterations + 1) M (1 +
    /// d/4) log2(N + 1)` tree steps (CCVT twice that, for the swaps).
    pub fn cost(&self) -> Cost {
        let steps = f64::from(self.iterations) + 1.0;
        if self.exact() {
            let one = if self.dims == 2 {
                PowerDiagram::cost(self.n as usize)
            } else {
                Voronoi3::cost(self.n as usize)
            };
            return Cost::from_seconds(steps * one.seconds());
        }
        let m = self.samples() as f64;
        let depth = ((self.n + 1) as f64).log2().max(1.0) / 10.0 + 1.0;
        let dims = 1.0 + self.dims as f64 / 4.0;
        let per = if self.ccvt { 2.0 } else { 1.0 };
        Cost::steps(
            (f64::from(self.iterations) + 1.0) * m * dims * depth * per,
            ASSIGNMENTS,
        )
    }

    /// The set, refused before it starts when [`cost`](Self::cost) exceeds `budget`,
    /// stopped at the budget's deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let trace = self.run(budget)?;
        let mut coords = crate::size::vec_with_capacity(trace.sites.len())?;
        coords.extend(trace.sites.iter().map(|&x| to_fraction(x)));
        PointSet::new(coords, self.dims)
    }

    /// The construction with its energies and final counts ([`LloydTrace`]).
    ///
    /// # Errors
    /// As [`Lloyd::generate`].
    pub fn run(&self, budget: &Budget) -> Result<LloydTrace> {
        let what = if self.ccvt {
            "CCVT"
        } else {
            "Lloyd relaxation"
        };
        let budget = budget.started();
        let mu = self.projective;
        if mu > 0.0 && (self.ccvt || self.torus) {
            return Err(Error::InvalidParameter {
                what: "projective Lloyd: plain Lloyd in the cube only (not CCVT, not the torus)",
            });
        }
        budget.check(what, self.cost())?;
        let (n, d) = (self.n as usize, self.dims);
        let m = self.samples() as usize;
        let mut rng = Rng::new(self.seed, 0x4C4C_4F59_4443_4356); // "LLOYDCCV"
        let mut sites = crate::size::vec_zeroed::<f64>(crate::size::coordinates(n as u64, d)?)?;
        sites.iter_mut().for_each(|x| *x = rng.unit());
        if self.exact() {
            return self.run_exact(sites, &budget);
        }
        let mut dense = crate::size::vec_zeroed::<f64>(crate::size::coordinates(m as u64, d)?)?;
        dense.iter_mut().for_each(|x| *x = rng.unit());
        let mut owner = crate::size::vec_zeroed::<u32>(m)?;
        if self.ccvt {
            // A random equal split: sample j goes to site perm(j) mod n.
            for (j, o) in owner.iter_mut().enumerate() {
                *o = (j % n) as u32;
            }
            for j in (1..m).rev() {
                owner.swap(j, rng.below(j + 1));
            }
        }
        let mut energy = Vec::new();
        let mut projective_energy = Vec::new();
        let mut nearest = crate::size::vec_zeroed::<u32>(m)?;
        for it in 0..=self.iterations {
            budget.check_deadline(what)?;
            let e = self.assign(&sites, &dense, &mut nearest, &budget, what)?;
            if !self.ccvt {
                owner.copy_from_slice(&nearest);
                energy.push(e);
                if mu > 0.0 {
                    projective_energy.push(e + mu * projection_energy(&sites, n, d));
                }
            } else {
                energy.push(self.energy(&sites, &dense, &owner));
            }
            if it == self.iterations {
                break;
            }
            if self.ccvt {
                let swapped = self.swap_pass(&sites, &dense, &mut owner, &nearest, &budget)?;
                if swapped == 0 {
                    break;
                }
            }
            if mu > 0.0 {
                let r = ranks(&sites, n, d);
                self.centroids(&mut sites, &dense, &owner)?;
                let mut w = crate::size::vec_zeroed::<f64>(n)?;
                for &o in &owner {
                    if let Some(w) = w.get_mut(o as usize) {
                        *w += 1.0 / m as f64;
                    }
                }
                blend(&mut sites, &w, &r, mu, d);
            } else {
                self.centroids(&mut sites, &dense, &owner)?;
            }
        }
        let mut counts = crate::size::vec_zeroed::<u32>(n)?;
        for &o in &owner {
            if let Some(c) = counts.get_mut(o as usize) {
                *c += 1;
            }
        }
        Ok(LloydTrace {
            energy,
            counts,
            volumes: Vec::new(),
            sites,
            projective_energy,
        })
    }

    /// `true` when the cells are exact: plain Lloyd (not CCVT, not projective) in 2D or 3D.
    fn exact(&self) -> bool {
        !self.ccvt && self.projective == 0.0 && (self.dims == 2 || self.dims == 3)
    }

    /// Lloyd on exact Voronoi cells from the start `sites`.
    fn run_exact(&self, mut sites: Vec<f64>, budget: &Budget) -> Result<LloydTrace> {
        let (d, torus) = (self.dims, self.torus);
        let mut energy = Vec::new();
        let mut volumes = Vec::new();
        let mut hints = None;
        for it in 0..=self.iterations {
            budget.check_deadline("Lloyd relaxation")?;
            let (e, vol, centroid): (f64, Vec<f64>, Vec<f64>) = if d == 2 {
                let v = PowerDiagram::voronoi(&sites, torus, budget)?;
                let e = (0..v.len()).map(|i| v.moment(i)).sum();
                let c = (0..v.len()).flat_map(|i| v.centroid(i)).collect();
                (e, v.areas().to_vec(), c)
            } else {
                // The previous cells' neighbours as the first cuts (the sites moved little).
                let (v, nb) = Voronoi3::hinted(&sites, torus, hints.as_ref(), budget)?;
                hints = Some(nb);
                let e = (0..v.len()).map(|i| v.moment(i)).sum();
                let c = (0..v.len()).flat_map(|i| v.centroid(i)).collect();
                (e, v.volumes().to_vec(), c)
            };
            energy.push(e);
            volumes = vol;
            if it == self.iterations {
                break;
            }
            for (s, c) in sites.iter_mut().zip(centroid) {
                // The centroid lies in the cell, so in the domain up to rounding.
                *s = if torus { c - c.floor() } else { c };
                *s = s.clamp(0.0, BELOW_ONE);
            }
        }
        Ok(LloydTrace {
            energy,
            counts: Vec::new(),
            volumes,
            sites,
            projective_energy: Vec::new(),
        })
    }

    /// Nearest site of every sample point; returns the Voronoi energy.
    fn assign(
        &self,
        sites: &[f64],
        dense: &[f64],
        nearest: &mut [u32],
        budget: &Budget,
        what: &'static str,
    ) -> Result<f64> {
        let d = self.dims;
        let tree = KdTree::new(sites, d, self.torus)?;
        let (mut lo, mut hi) = (vec![0.0; d], vec![0.0; d]);
        let mut sum = 0.0;
        for (j, (y, o)) in dense.chunks_exact(d).zip(nearest.iter_mut()).enumerate() {
            if j % DEADLINE_POINTS == 0 {
                budget.check_deadline(what)?;
            }
            let (s, e) = tree.nearest(y, &mut lo, &mut hi);
            *o = s;
            sum += e;
        }
        Ok(sum / (dense.len() / d).max(1) as f64)
    }

    /// Squared distance between a sample point and a site.
    fn dist2(&self, y: &[f64], s: &[f64]) -> f64 {
        y.iter()
            .zip(s)
            .map(|(a, b)| {
                let t = (a - b).abs();
                let t = if self.torus { t.min(1.0 - t) } else { t };
                t * t
            })
            .sum()
    }

    fn site<'s>(&self, sites: &'s [f64], i: u32) -> &'s [f64] {
        let b = i as usize * self.dims;
        sites.get(b..b + self.dims).unwrap_or(&[])
    }

    /// The energy of an assignment.
    fn energy(&self, sites: &[f64], dense: &[f64], owner: &[u32]) -> f64 {
        let d = self.dims;
        let sum: f64 = dense
            .chunks_exact(d)
            .zip(owner)
            .map(|(y, &o)| self.dist2(y, self.site(sites, o)))
            .sum();
        sum / owner.len().max(1) as f64
    }

    /// One CCVT pass over the pairs (owner, nearest site); the number of swaps.
    fn swap_pass(
        &self,
        sites: &[f64],
        dense: &[f64],
        owner: &mut [u32],
        nearest: &[u32],
        budget: &Budget,
    ) -> Result<u64> {
        let n = self.n as usize;
        let d = self.dims;
        // Members of each site (counting sort by owner).
        let mut start = crate::size::vec_zeroed::<usize>(n + 1)?;
        for &o in owner.iter() {
            if let Some(s) = start.get_mut(o as usize + 1) {
                *s += 1;
            }
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        let mut members = crate::size::vec_zeroed::<u32>(owner.len())?;
        let mut fill = start.clone();
        for (j, &o) in owner.iter().enumerate() {
            if let Some(f) = fill.get_mut(o as usize) {
                if let Some(slot) = members.get_mut(*f) {
                    *slot = j as u32;
                }
                *f += 1;
            }
        }
        let mut pairs: Vec<(u32, u32)> = owner
            .iter()
            .zip(nearest)
            .filter(|(o, s)| o != s)
            .map(|(&o, &s)| (o.min(s), o.max(s)))
            .collect();
        pairs.sort_unstable();
        pairs.dedup();
        let mut swaps = 0u64;
        let (mut hi_, mut hj_) = (Vec::new(), Vec::new());
        for (k, &(i, j)) in pairs.iter().enumerate() {
            if k % 256 == 0 {
                budget.check_deadline("CCVT")?;
            }
            let (si, sj) = (self.site(sites, i), self.site(sites, j));
            let gain = |list: &mut Vec<(f64, u32)>, site: u32, a: &[f64], b: &[f64]| {
                list.clear();
                let (s0, s1) = (start[site as usize], start[site as usize + 1]);
                for &p in members.get(s0..s1).unwrap_or(&[]) {
                    // Members may have moved to the other site in this pass.
                    if owner.get(p as usize) != Some(&site) {
                        continue;
                    }
                    let y = dense
                        .get(p as usize * d..(p as usize + 1) * d)
                        .unwrap_or(&[]);
                    list.push((self.dist2(y, a) - self.dist2(y, b), p));
                }
                list.sort_unstable_by(|x, y| y.0.total_cmp(&x.0));
            };
            gain(&mut hi_, i, si, sj);
            gain(&mut hj_, j, sj, si);
            for (&(a, p), &(b, q)) in hi_.iter().zip(&hj_) {
                if a + b <= 0.0 {
                    break;
                }
                if let Some(o) = owner.get_mut(p as usize) {
                    *o = j;
                }
                if let Some(o) = owner.get_mut(q as usize) {
                    *o = i;
                }
                swaps += 1;
            }
        }
        Ok(swaps)
    }

    /// Every site to the centroid of its points (periodic mean on the torus); a site
    /// without points stays.
    fn centroids(&self, sites: &mut [f64], dense: &[f64], owner: &[u32]) -> Result<()> {
        let d = self.dims;
        let mut sum = crate::size::vec_zeroed::<f64>(sites.len())?;
        let mut count = crate::size::vec_zeroed::<u32>(self.n as usize)?;
        for (y, &o) in dense.chunks_exact(d).zip(owner) {
            let b = o as usize * d;
            let (Some(acc), Some(s)) = (sum.get_mut(b..b + d), sites.get(b..b + d)) else {
                continue;
            };
            for ((a, &x), &c) in acc.iter_mut().zip(y).zip(s) {
                *a += if self.torus { wrap(x - c) } else { x };
            }
            if let Some(c) = count.get_mut(o as usize) {
                *c += 1;
            }
        }
        for ((s, acc), &c) in sites
            .chunks_exact_mut(d)
            .zip(sum.chunks_exact(d))
            .zip(&count)
        {
            if c == 0 {
                continue;
            }
            let inv = 1.0 / f64::from(c);
            for (x, &a) in s.iter_mut().zip(acc) {
                *x = if self.torus {
                    let v = *x + a * inv;
                    v - v.floor()
                } else {
                    a * inv
                };
            }
        }
        Ok(())
    }
}

/// `d` wrapped to `[-1/2, 1/2)`.
fn wrap(d: f64) -> f64 {
    d - (d + 0.5).floor()
}

/// Row-major coordinates in `[0, 1]` (`dims` a point) as a [`PointSet`] of 0.32 fractions
/// ([`to_fraction`] each), its storage through the checked allocation.
pub(crate) fn unit_point_set(pts: &[f64], dims: usize) -> Result<PointSet> {
    let mut coords = crate::size::vec_with_capacity(pts.len())?;
    coords.extend(pts.iter().map(|&x| to_fraction(x)));
    PointSet::new(coords, dims)
}

/// `x` in `[0, 1]` to a 0.32 fraction (1.0, from rounding, to the largest below 1).
pub(crate) fn to_fraction(x: f64) -> u32 {
    let v = x * 4_294_967_296.0;
    if v >= 4_294_967_295.0 {
        u32::MAX
    } else if v > 0.0 {
        v as u32
    } else {
        0
    }
}
