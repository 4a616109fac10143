//! Sliced optimal transport sampling (Paulin, Bonneel, Coeurjolly, Iehl, Webanck,
//! Desbrun & Ostromoukhov 2020, "Sliced Optimal Transport Sampling", ACM TOG 39(4)):
//! `N` points of `[0, 1)^d` moved towards the uniform measure of the cube by stochastic
//! descent on the sliced Wasserstein distance.
//!
//! ## The iteration
//!
//! The sliced Wasserstein distance between the points' measure `mu = (1/N) sum delta_x_i`
//! and the uniform measure `nu` of the cube is
//! `SW_2^2(mu, nu) = E_theta W_2^2(P_theta mu, P_theta nu)`, `theta` uniform on the sphere,
//! `P_theta` the projection `x -> <theta, x>`. In 1D optimal transport is sorting: if
//! `<theta, x_sigma(1)> <= ... <= <theta, x_sigma(N)>`, the `k`-th point is sent to the
//! `k`-th of `N` equal-mass quantile blocks of `P_theta nu`, and its barycentric target is
//! that block's mean `t_k`. An iteration draws a batch of `L` directions (default 16,
//! Gaussian vectors normalized) and moves every point by the average over the batch of its
//! 1D displacements, `x_i <- x_i + (1/L) sum_theta (t_rank(i) - <theta, x_i>) theta`.
//!
//! ## The target
//!
//! `P_theta nu` is the law of `sum_k theta_k U_k` (a convolution of uniforms, an
//! Irwin–Hall-like spline). When `theta` has at most two non-zero components (every
//! direction in 1D and 2D, the axis and plane directions of the projective variant) the
//! target of the `k`-th of `N` sorted points is the exact quantile
//! `t_k = F^-1((k + 1/2) / N)` of that law: with `a <= b` the two absolute components and
//! `o` the sum of the negative ones, `<theta, U> - o = a U + b V` has the trapezoidal
//! density of height `1/b` on `[a, b]` and linear ramps on `[0, a]` and `[b, a + b]`, so
//!
//! ```text
//! F^-1(p) - o = sqrt(2 a b p)                 for p <= a / (2 b),
//!               b p + a / 2                   for a / (2 b) < p <= 1 - a / (2 b),
//!               a + b - sqrt(2 a b (1 - p))   above
//! ```
//!
//! ([`square_quantile`]; `a = 0` is the uniform law on `[0, b]`). For other directions
//! (`d > 2`) the law is represented, as in the paper's implementation, by a large
//! projected sample of the cube: `M = c N` points (`c` = samples a point, default 16) of
//! the Owen-scrambled Sobol' sequence ([`crate::Sobol`] with
//! [`crate::randomize::FastOwen`] from the seed), fixed for the run. Projected and sorted,
//! its `k`-th block of `c` consecutive values has mean `t_k` (the exact 1D transport plan
//! between the `N` points and the `M`-point sample). In 1D and 2D no sample is built and
//! `c` changes nothing.
//!
//! ## The projective variant
//!
//! With [`Sot::projective`] (the paper's projective sampling) every other direction of a
//! batch is drawn not in the full space but in one axis-aligned subspace: the 1D
//! subspaces (the axes, `theta = e_k`) and, for `d > 2`, the 2D ones (a uniform direction
//! of the plane of axes `k < l`), taken in turn through the run. The projection of the
//! uniform cube on such a `theta` is still `P_theta nu`, so the same target sample serves;
//! the step then also lowers the sliced Wasserstein distance of the 1D and 2D projections
//! of the set to the uniform measure of their square (tested against plain SOT at equal
//! iterations). In 1D there are no subspaces and the option changes nothing.
//!
//! Points start uniform at random and are clamped to `[0, 1)` only when written as 0.32
//! fractions (a step rarely leaves the cube: the targets lie inside). Only the cube (no
//! torus). Dimensions 1 to 64.
//!
//! ## Cost
//!
//! `iterations L N d` per run in 1D and 2D for points spread over the cube: a
//! direction projects the points, ranks them by a bucket sort of 32-bit fixed-point
//! keys of the projections (`O(N)` when they are spread, `O(N log N)` at worst; ties
//! closer than `2^-32` of the projections' range keep index order) and evaluates `N`
//! closed-form quantiles; for `d > 2` each sampled direction adds `M d + M log M`. The
//! directions of an iteration are drawn in order and transported in parallel (rayon),
//! their displacements summed in direction order, so the set does not depend on the
//! thread count. Estimated ([`Sot::cost`]) against a [`Budget`] and stopped at its
//! deadline (checked once a group of directions). Memory `N d` values plus `5 N` (and
//! `M` for `d > 2`) a thread, `(N + M) d` for `d > 2`.
//!
//! ```
//! use qmckit::blue_noise::Sot;
//! use qmckit::work::Budget;
//! let set = Sot::new(64, 2)?.iterations(20)?.seed(3).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 64);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::keysort::{KeySort, key_scale, key32};
use super::lloyd::to_fraction;
use super::rng::Rng;
use crate::randomize::{FastOwen, Scrambled};
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result, Sampler, Sobol};
use rayon::prelude::*;

/// The most points [`Sot`] takes: 2^20.
pub const SOT_MAX_POINTS: u64 = 1 << 20;

/// The most dimensions [`Sot`] takes.
pub const SOT_MAX_DIMS: usize = 64;

/// Projected-and-sorted values a second, one core, release (a projection, a comparison
/// sort's share; about 6e8 measured for 10^3 points in 2D, taken lower).
const VALUES: Rate = Rate::per_second(2e8);

/// Sliced optimal transport sampling (builder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sot {
    n: u64,
    dims: usize,
    iterations: u32,
    batch: u32,
    per_point: u32,
    seed: u64,
    projective: bool,
}

impl Sot {
    /// `n` points (1 to [`SOT_MAX_POINTS`]) in `dims` (1 to [`SOT_MAX_DIMS`]), 100
    /// iterations of 16 directions, 16 target samples a point, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::ZeroDimensions`],
    /// [`Error::DimensionOutOfRange`].
    pub fn new(n: u64, dims: usize) -> Result<Self> {
        crate::size::points(n, SOT_MAX_POINTS)?;
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if dims > SOT_MAX_DIMS.min(crate::SOBOL_MAX_DIMS) {
            return Err(Error::DimensionOutOfRange {
                dim: dims,
                dims: SOT_MAX_DIMS.min(crate::SOBOL_MAX_DIMS),
            });
        }
        Ok(Sot {
            n,
            dims,
            iterations: 100,
            batch: 16,
            per_point: 16,
            seed: 0,
            projective: false,
        })
    }

    /// Iterations (0 to 10^5; 0 returns the random start).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] past 10^5.
    pub fn iterations(mut self, iterations: u32) -> Result<Self> {
        if iterations > 100_000 {
            return Err(Error::InvalidParameter {
                what: "sliced optimal transport takes at most 10^5 iterations",
            });
        }
        self.iterations = iterations;
        Ok(self)
    }

    /// Directions an iteration, `L` (1 to 4096).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn batch(mut self, directions: u32) -> Result<Self> {
        if directions == 0 || directions > 4096 {
            return Err(Error::InvalidParameter {
                what: "sliced optimal transport takes 1 to 4096 directions an iteration",
            });
        }
        self.batch = directions;
        Ok(self)
    }

    /// Target samples a point, `c` (1 to 1024); used only for `d > 2`, where directions
    /// with more than two non-zero components take the sampled target.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn samples_per_point(mut self, c: u32) -> Result<Self> {
        if c == 0 || c > 1024 {
            return Err(Error::InvalidParameter {
                what: "sliced optimal transport takes 1 to 1024 target samples a point",
            });
        }
        self.per_point = c;
        Ok(self)
    }

    /// Projective sampling: every other direction drawn in an axis-aligned 1D or 2D
    /// subspace (see the module text). Default off.
    pub fn projective(mut self, on: bool) -> Self {
        self.projective = on;
        self
    }

    /// The seed (start, directions, target scramble).
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The estimated running time: `iterations L (N + M) (d + log2 M)` values, `M = 0`
    /// in 1D and 2D (closed-form targets).
    pub fn cost(&self) -> Cost {
        let n = self.n as f64;
        let m = if self.dims > 2 {
            n * f64::from(self.per_point)
        } else {
            0.0
        };
        let work = (n + m) * (self.dims as f64 + (n + m).log2().max(1.0));
        Cost::steps(
            f64::from(self.iterations) * f64::from(self.batch) * work,
            VALUES,
        )
    }

    /// The set, refused before it starts when [`cost`](Self::cost) exceeds `budget`,
    /// stopped at the budget's deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let pts = self.run(budget)?;
        let mut coords = crate::size::vec_with_capacity(pts.len())?;
        coords.extend(pts.iter().map(|&x| to_fraction(x.clamp(0.0, 1.0))));
        PointSet::new(coords, self.dims)
    }

    /// The points as `f64`, row-major (not clamped).
    ///
    /// # Errors
    /// As [`Sot::generate`].
    pub fn run(&self, budget: &Budget) -> Result<Vec<f64>> {
        const WHAT: &str = "sliced optimal transport";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let (n, d) = (self.n as usize, self.dims);
        let c = self.per_point as usize;
        let mut rng = Rng::new(self.seed, 0x534F_5453_414D_504C); // "SOTSAMPL"
        let mut pts = crate::size::vec_zeroed::<f64>(crate::size::coordinates(n as u64, d)?)?;
        pts.iter_mut().for_each(|x| *x = rng.unit());
        // The sampled target, for directions with more than two non-zero components
        // (d > 2 only): M Owen-scrambled Sobol' points (M <= 2^30 by the limits above).
        let m = if d > 2 { n * c } else { 0 };
        let target: Vec<f64> = if m > 0 {
            let sobol = Scrambled::new(Sobol::new(d)?, FastOwen::new(self.seed));
            let mut raw = crate::size::vec_zeroed::<u32>(crate::size::coordinates(m as u64, d)?)?;
            sobol.fill(0, &mut raw)?;
            raw.iter().map(|&u| crate::bits::to_f64(u)).collect()
        } else {
            Vec::new()
        };
        // Directions are drawn in order, then processed in groups of `G` in parallel, each
        // giving every point's 1D displacement; the displacements are summed in direction
        // order, so the result does not depend on `G` or the thread count.
        let batch = self.batch as usize;
        let g = rayon::current_num_threads().clamp(1, batch);
        let mut thetas = crate::size::vec_zeroed::<f64>(batch * d)?;
        let mut scratch = crate::size::vec_with_capacity::<Scratch>(g)?;
        for _ in 0..g {
            scratch.push(Scratch::new(n, m)?);
        }
        let mut deltas = crate::size::vec_zeroed::<f64>(crate::size::coordinates(n as u64, g)?)?;
        let mut step = crate::size::vec_zeroed::<f64>(pts.len())?;
        let inv_batch = 1.0 / f64::from(self.batch);
        let subspaces = if self.projective {
            Subspaces::new(d)
        } else {
            Subspaces::none()
        };
        let mut turn = 0usize;
        for _ in 0..self.iterations {
            step.fill(0.0);
            for (j, theta) in thetas.chunks_exact_mut(d).enumerate() {
                if j % 2 == 1 && subspaces.count() > 0 {
                    subspaces.direction(turn, &mut rng, theta);
                    turn = (turn + 1) % subspaces.count();
                } else {
                    direction(&mut rng, theta);
                }
            }
            for group in thetas.chunks(g * d) {
                budget.check_deadline(WHAT)?;
                let pts = &pts;
                let target = &target;
                deltas
                    .par_chunks_mut(n)
                    .zip(scratch.par_iter_mut())
                    .zip(group.par_chunks(d))
                    .for_each(|((delta, s), theta)| {
                        s.transport(pts, d, theta, target, c, delta);
                    });
                for (delta, theta) in deltas.chunks_exact(n).zip(group.chunks_exact(d)) {
                    for (s, &t) in step.chunks_exact_mut(d).zip(delta) {
                        for (s, &th) in s.iter_mut().zip(theta) {
                            *s += t * th;
                        }
                    }
                }
            }
            for (x, s) in pts.iter_mut().zip(&step) {
                *x += s * inv_batch;
            }
        }
        Ok(pts)
    }
}

/// The buffers of one direction's transport.
struct Scratch {
    values: Vec<f64>,
    keys: Vec<u64>,
    sorter: KeySort,
    exact: Vec<f64>,
    tproj: Vec<f64>,
}

impl Scratch {
    fn new(n: usize, m: usize) -> Result<Self> {
        Ok(Scratch {
            values: crate::size::vec_zeroed(n)?,
            keys: crate::size::vec_zeroed(n)?,
            sorter: KeySort::new(n)?,
            exact: crate::size::vec_zeroed(n)?,
            tproj: crate::size::vec_zeroed(m)?,
        })
    }

    /// The 1D optimal transport of the projections `<theta, x_i>` to their targets: the
    /// displacement `t_rank(i) - <theta, x_i>` of every point into `delta`. The points are
    /// ranked by a bucket sort ([`KeySort`]) of 32-bit fixed-point keys of their
    /// projections in `[min, max]`, ties (projections within `2^-32` of the range) in
    /// index order.
    fn transport(
        &mut self,
        pts: &[f64],
        d: usize,
        theta: &[f64],
        target: &[f64],
        c: usize,
        delta: &mut [f64],
    ) {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for (v, x) in self.values.iter_mut().zip(pts.chunks_exact(d)) {
            *v = dot(x, theta);
            // Not `f64::min`: no NaN to handle (finite points and directions).
            lo = if *v < lo { *v } else { lo };
            hi = if *v > hi { *v } else { hi };
        }
        let scale = key_scale(lo, hi);
        for (k, (key, &v)) in self.keys.iter_mut().zip(&self.values).enumerate() {
            *key = (key32(v, lo, scale) << 32) | k as u64;
        }
        if !exact_targets(theta, &mut self.exact) {
            for (t, y) in self.tproj.iter_mut().zip(target.chunks_exact(d)) {
                *t = dot(y, theta);
            }
            self.tproj.sort_unstable_by(f64::total_cmp);
            for (e, block) in self.exact.iter_mut().zip(self.tproj.chunks_exact(c)) {
                *e = block.iter().sum::<f64>() / c as f64;
            }
        }
        self.sorter.sort(&mut self.keys);
        for (&key, &t) in self.keys.iter().zip(&self.exact) {
            let i = (key & 0xFFFF_FFFF) as usize;
            if let (Some(out), Some(&v)) = (delta.get_mut(i), self.values.get(i)) {
                *out = t - v;
            }
        }
    }
}

/// `F^-1(p)` of `<theta, U>`, `U` uniform in the unit square, `0 < p < 1` (the trapezoid
/// quantile of the module text; exact up to the rounding of a square root). Cost O(1).
///
/// # Errors
/// [`Error::InvalidParameter`] for `p` outside `(0, 1)`, a non-finite `theta` or `theta = 0`.
///
/// ```
/// use qmckit::blue_noise::sot::square_quantile;
/// // x + y has the triangular law on [0, 2]: F(1/2) = 1/8.
/// assert!((square_quantile([1.0, 1.0], 0.125)? - 0.5).abs() < 1e-15);
/// // x - y on [-1, 1]: the median is 0.
/// assert!(square_quantile([1.0, -1.0], 0.5)?.abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn square_quantile(theta: [f64; 2], p: f64) -> Result<f64> {
    let valid = p > 0.0 && p < 1.0 && theta.iter().all(|t| t.is_finite());
    if !valid || theta == [0.0; 2] {
        return Err(Error::InvalidParameter {
            what: "the projected square's quantile needs 0 < p < 1 and a finite non-zero theta",
        });
    }
    let offset = theta[0].min(0.0) + theta[1].min(0.0);
    let (a, b) = (theta[0].abs(), theta[1].abs());
    Ok(offset + trapezoid_quantile(a.min(b), a.max(b), p))
}

/// `F^-1(p)` of `a U + b V` for `0 <= a <= b`, `b > 0` (see the module text).
fn trapezoid_quantile(a: f64, b: f64, p: f64) -> f64 {
    let tail = a / (2.0 * b);
    if p <= tail {
        (2.0 * a * b * p).sqrt()
    } else if p <= 1.0 - tail {
        b * p + 0.5 * a
    } else {
        a + b - (2.0 * a * b * (1.0 - p)).sqrt()
    }
}

/// The exact targets `F^-1((k + 1/2) / N)`, `k < N = out.len()`, of the projection of the
/// uniform cube on `theta` when `theta` has at most two non-zero components (then `true`);
/// `false` (and `out` untouched) otherwise or for `theta = 0`.
fn exact_targets(theta: &[f64], out: &mut [f64]) -> bool {
    let (mut w, mut count, mut offset) = ([0.0f64; 2], 0usize, 0.0f64);
    for &t in theta.iter().filter(|&&t| t != 0.0) {
        match w.get_mut(count) {
            Some(slot) => *slot = t.abs(),
            None => return false,
        }
        count += 1;
        offset += t.min(0.0);
    }
    let (a, b) = (w[0].min(w[1]), w[0].max(w[1]));
    if b <= 0.0 {
        return false;
    }
    // `trapezoid_quantile` of `p_k = (k + 1/2) / N` split into its three pieces (`p_k`
    // increases with `k`), so that the long middle piece runs without a branch.
    let len = out.len();
    let n = len as f64;
    let p = |k: usize| (k as f64 + 0.5) / n;
    let tail = a / (2.0 * b);
    let mut first = 0;
    while first < len && p(first) <= tail {
        out[first] = offset + (2.0 * a * b * p(first)).sqrt();
        first += 1;
    }
    let mut end = len;
    while end > first && p(end - 1) > 1.0 - tail {
        out[end - 1] = offset + (a + b - (2.0 * a * b * (1.0 - p(end - 1))).sqrt());
        end -= 1;
    }
    for (k, t) in out.iter_mut().enumerate().take(end).skip(first) {
        *t = offset + (b * p(k) + 0.5 * a);
    }
    true
}

/// The axis-aligned subspaces of projective SOT: the `d` axes, then (for `d > 2`) the
/// `d (d - 1) / 2` planes of axis pairs in lexicographic order.
struct Subspaces {
    dims: usize,
    planes: usize,
}

impl Subspaces {
    fn new(dims: usize) -> Self {
        let planes = if dims > 2 { dims * (dims - 1) / 2 } else { 0 };
        Subspaces {
            dims: if dims > 1 { dims } else { 0 },
            planes,
        }
    }

    fn none() -> Self {
        Subspaces { dims: 0, planes: 0 }
    }

    fn count(&self) -> usize {
        self.dims + self.planes
    }

    /// A direction in subspace `turn`: the axis `e_turn`, or a uniform unit vector of the
    /// plane of the `(turn - d)`-th pair of axes (angle uniform in `[0, 2 pi)`).
    fn direction(&self, turn: usize, rng: &mut Rng, theta: &mut [f64]) {
        theta.fill(0.0);
        if turn < self.dims {
            if let Some(t) = theta.get_mut(turn) {
                *t = 1.0;
            }
            return;
        }
        let (mut rest, mut k) = (turn - self.dims, 0);
        while k + 1 < self.dims && rest >= self.dims - 1 - k {
            rest -= self.dims - 1 - k;
            k += 1;
        }
        let l = k + 1 + rest;
        let angle = core::f64::consts::TAU * rng.unit();
        if let Some(t) = theta.get_mut(k) {
            *t = angle.cos();
        }
        if let Some(t) = theta.get_mut(l) {
            *t = angle.sin();
        }
    }
}

/// A uniform direction on the sphere: a normalized Gaussian vector (redrawn in the
/// vanishing case, at most 64 times; then the first axis).
fn direction(rng: &mut Rng, theta: &mut [f64]) {
    for _ in 0..64 {
        theta.iter_mut().for_each(|t| *t = rng.normal());
        let norm = dot(theta, theta).sqrt();
        if norm > 1e-12 {
            theta.iter_mut().for_each(|t| *t /= norm);
            return;
        }
    }
    theta
        .iter_mut()
        .enumerate()
        .for_each(|(k, t)| *t = if k == 0 { 1.0 } else { 0.0 });
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
