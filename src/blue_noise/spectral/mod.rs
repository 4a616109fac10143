//! Spectrum-controlled blue noise (Heck, Schlömer & Deussen, "Blue Noise Sampling with
//! Controlled Aliasing", ACM TOG 32(3), 2013): `N` points on the unit torus `[0, 1)^d`
//! whose radial power spectrum follows a chosen profile — the **step** (zero below a cutoff,
//! white above) or the **single peak** (zero below, one smoothed peak at the cutoff, white
//! above) — built by gradient descent on the mismatch between their pair correlation
//! function and the one the profile implies.
//!
//! ## From the spectrum to the pair correlation
//!
//! Lengths are in units of the mean spacing `s = N^(-1/d)` and frequencies in units of
//! `1/s = N^(1/d)` (in 2D: `|k| / sqrt(N)`, the abscissa of the radial spectrum). For a
//! stationary isotropic point process of unit density the power spectrum and the pair
//! correlation function `G` are related by the `d`-dimensional Fourier transform of radial
//! functions (the Hankel transform, a Fourier–Bessel integral):
//!
//! ```text
//! P(u) - 1 = 2 pi u^(1-d/2) int_0^inf rho^(d/2) (G(rho) - 1) J_{d/2-1}(2 pi u rho) d rho
//! G(rho) - 1 = 2 pi rho^(1-d/2) int_0^inf u^(d/2) (P(u) - 1) J_{d/2-1}(2 pi u rho) d u
//! ```
//!
//! (the delta at `u = 0` left out; in 2D `J_0`, the relation of the paper). The second line
//! turns the profile into the target `G_0`, by Simpson's rule over the finite range where
//! `P != 1`. For the step `P(u) = 0` for `u < u_0`, 1 above, in closed form
//! `G_0(rho) = 1 - (u_0/rho)^(d/2) J_{d/2}(2 pi u_0 rho)`, whose value at 0 is
//! `1 - V_d u_0^d` (`V_d` the unit ball's volume): realizable only for
//! `u_0 <= V_d^(-1/d)`, `1/sqrt(pi) = 0.564` in 2D (the paper's bound). The single peak is
//! the paper's `P(u) = G_sigma * (p_0 delta(u - u_0) + H(u - u_0))`: a Dirac peak of energy
//! `p_0` at the cutoff and the step, both smoothed by a Gaussian of standard deviation
//! `sigma`. A profile whose `G_0` dips below 0 is not realizable and is refused.
//!
//! Defaults: the step at `u_0 = 0.9995 V_d^(-1/d)`, just inside the bound (0.5639 in 2D,
//! `G_0(0) = 0.001`: the paper's critical frequency, 0.606 in units of the hexagonal
//! lattice's `sqrt(sqrt(3) N / 2)`, also the default of Heck et al.'s code); the single
//! peak at `u_0 = 1.33 V_d^(-1/d)` (0.75 in 2D, where a step alone is not realizable),
//! `p_0 = 0.3`, `sigma = 0.08` (the peak reaches `p_0 / (sigma sqrt(2 pi)) + 1/2 = 2.0`;
//! `G_0 >= 0.16` in 1 to 6 dimensions). The paper fixes the shape of the family and
//! studies which `(u_0, p_0, sigma)` are realizable; these values are ours, chosen within
//! its realizable range (a narrower peak, `sigma = 0.05`, rings further than the
//! correlation window and left more low-frequency power: 0.08 to 0.12 against 0.05 to
//! 0.09 at 512 points).
//!
//! ## The descent
//!
//! The pair correlation is estimated on `B` bins `rho_b = (b + 1/2) Delta` up to
//! `rho_max = 6` (`Delta = 0.04`) with a Gaussian kernel `k_h` (`h = 0.04`):
//! `G_b = c_b sum_{i != j} k_h(rho_b - rho_ij)`, `c_b = 1 / ((N - 1) S_{d-1} rho_b^(d-1))`
//! (`S_{d-1}` the unit sphere's area; toroidal nearest-image distances). The target is the
//! estimator's expectation, `G_0` smoothed the same way. The energy
//! `E = sum_b (G_b - Gbar_b)^2` has the gradient
//! `dE/dx_i = sum_j psi(rho_ij) (x_i - x_j)/|x_i - x_j|`,
//! `psi(rho) = -4 sum_b (G_b - Gbar_b) c_b k_h'(rho_b - rho)` (tabulated each iteration).
//! The points move together by limited-memory BFGS (Nocedal 1980; 8 pairs of moves and
//! gradient changes, the first step steepest descent with a root-mean-square move of
//! `0.05 s`), no point more than `0.5 s` a step, with a backtracking line search to
//! Armijo's sufficient decrease (`E` never increases). At 1024 points in 2D this gives in 200
//! energy evaluations bluer sets than 1000 steps of a gradient descent with a
//! growing and halving step (at a step cutoff of 0.5, 4 sets: mean power over
//! `1 <= |k| <= sqrt(N)/2` 0.030 against 0.053).
//!
//! The mismatch is nearly flat along long-wavelength displacements (a denser and a sparser
//! region change `G` in opposite directions), so the lowest frequencies are decided by the
//! start: the points start from the Owen-scrambled Sobol' points ([`crate::Sobol`] with
//! [`crate::randomize::FastOwen`] from the seed), whose low-frequency power is already near
//! zero; the descent shapes the rest of the spectrum. (From uniform random points the
//! power at `|k| <= 3` stays near white noise.)
//!
//! ## Range and cost
//!
//! Dimensions 1 to 6, 2 to 2^22 points. The correlation window `rho_cut = rho_max + 4h =
//! 6.16` mean spacings must fit in half the torus, which takes `(2 rho_cut)^d` points (152
//! in 2D, 1870 in 3D, 3.5 million in 6D); smaller sets use a shorter range
//! `rho_max = 0.5 N^(1/d) - 4h` (so they control the pair correlation, and the spectrum,
//! less finely). The Hankel relation holds in every dimension; past 6 even 2^22 points
//! leave less than the full window. Each iteration (an energy evaluation, and for an
//! accepted step a gradient) visits the pairs within `rho_cut s`: `O(N V_d (rho_cut +
//! 0.6)^d)` pair terms of about ten kernel values by the Verlet lists below, in parallel (rayon, in chunks of fixed size so the
//! result does not depend on the thread count). Estimated against a [`Budget`]
//! ([`SpectralBlueNoise::cost`]) and stopped at its deadline (read once an iteration and
//! every 1024 points). The pairs come from Verlet lists (all neighbours within
//! `rho_cut + 0.6` spacings, rebuilt from the cell lists once a point has moved 0.3 spacings
//! since the build; exact: no pair within `rho_cut` is missed) when they hold at most
//! 2^26 entries, from the cell lists of every step otherwise.
//!
//! ```
//! use qmckit::blue_noise::{SpectralBlueNoise, spectral::Profile};
//! use qmckit::work::Budget;
//! let set = SpectralBlueNoise::new(256, 2, Profile::step(2)?)?
//!     .iterations(20)?
//!     .seed(1)
//!     .generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 256);
//! assert!(Profile::Step { cutoff: 0.6 }.target_pcf(2, 0.1).is_err()); // past 1/sqrt(pi)
//! # Ok::<(), qmckit::Error>(())
//! ```

use rayon::prelude::*;

use super::PointSet;
use super::lbfgs::{ARMIJO, FIRST_STEP, MAX_MOVE, MEMORY, Memory, dot};
use super::lloyd::unit_point_set;
use super::torus_cells::wrap;
use super::verlet::{Near, SKIN};
use crate::randomize::{FastOwen, Scrambled};
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result, Sampler, Sobol};

mod profile;
use profile::check_dims;
pub use profile::{Profile, ball_volume};

/// The most points [`SpectralBlueNoise`] takes: 2^22.
pub const SPECTRAL_MAX_POINTS: u64 = 1 << 22;

/// The most dimensions [`SpectralBlueNoise`] takes.
pub const SPECTRAL_MAX_DIMS: usize = 6;

/// Bin width and kernel width of the pair correlation estimate, in mean spacings.
const DELTA: f64 = 0.04;
const H: f64 = 0.04;
/// The estimate's range, in mean spacings (the pair cut-off adds the kernel's support,
/// `4h`).
const RHO_MAX: f64 = 6.0;

/// The estimate's range for `n` points in `d` dimensions: [`RHO_MAX`], or less for small
/// sets, so that the pair cut-off `range + 4h` stays within half the torus
/// (`0.5 N^(1/d)` mean spacings).
fn range(n: u64, d: usize) -> f64 {
    RHO_MAX.min(0.5 * (n as f64).powf(1.0 / d as f64) - 4.0 * H)
}
/// Points a chunk of the parallel loops (fixed: the sums do not depend on the threads).
const CHUNK: usize = 1024;

/// Pair visits a second, one core (a distance, and for the pairs within the cut-off about
/// ten kernel values or one table look-up; measured 5.8e7 for 1024 points in 2D).
const PAIRS: Rate = Rate::per_second(5e7);

/// Spectrum-controlled blue noise (builder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpectralBlueNoise {
    n: u64,
    dims: usize,
    profile: Profile,
    iterations: u32,
    seed: u64,
}

impl SpectralBlueNoise {
    /// `n` points in `dims` dimensions following `profile`; 200 iterations, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::ZeroDimensions`],
    /// [`Error::DimensionOutOfRange`]; [`Error::InvalidParameter`] for one point, a bad or
    /// an unrealizable profile.
    pub fn new(n: u64, dims: usize, profile: Profile) -> Result<Self> {
        crate::size::points(n, SPECTRAL_MAX_POINTS)?;
        check_dims(dims)?;
        if n < 2 || range(n, dims) < 4.0 * DELTA {
            return Err(Error::InvalidParameter {
                what: "spectral blue noise needs at least two points",
            });
        }
        profile.validate()?;
        profile.realizable(dims)?;
        Ok(SpectralBlueNoise {
            n,
            dims,
            profile,
            iterations: 200,
            seed: 0,
        })
    }

    /// The iteration count: the energy evaluations of the descent, each one pass over the
    /// pairs (an accepted step also one gradient pass); 0 to 10^5, 0 returns the start.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] past 10^5.
    pub fn iterations(mut self, iterations: u32) -> Result<Self> {
        if iterations > 100_000 {
            return Err(Error::InvalidParameter {
                what: "spectral blue noise takes at most 10^5 iterations",
            });
        }
        self.iterations = iterations;
        Ok(self)
    }

    /// The seed (the start's scramble).
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The pairs visited a point: those of its Verlet list (`V_d (rho_cut + skin)^d`) when
    /// the lists fit, else `3^d` cells of side `rho_cut s` around it, or all points.
    fn visits(&self) -> f64 {
        let n = self.n as f64;
        let d = self.dims as i32;
        let rho_cut = range(self.n, self.dims) + 4.0 * H;
        let listed = ball_volume(self.dims) * (rho_cut + SKIN).powi(d);
        if Near::listed(self.n as usize, self.dims, rho_cut) {
            return listed.min(n);
        }
        let cut = rho_cut * n.powf(-1.0 / self.dims as f64);
        let g = (1.0 / cut)
            .floor()
            .min((2.0 * n).powf(1.0 / self.dims as f64).floor());
        if g >= 3.0 && 3f64.powi(d) < n {
            3f64.powi(d) * n / g.powi(d)
        } else {
            n
        }
    }

    /// The estimated running time: iterations times `N` times the pairs visited a point,
    /// twice (the estimate and the gradient), at a rate per core on two cores.
    pub fn cost(&self) -> Cost {
        // Per iteration: the pairs, twice, and the force table (about 2e4 kernel values).
        let work =
            f64::from(self.iterations) * (self.n as f64 * (self.visits() * 2.0 + 50.0) + 2e4);
        Cost::parallel(work, PAIRS)
    }

    /// The set, refused before it starts when [`cost`](Self::cost) exceeds `budget`,
    /// stopped at the budget's deadline.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let pts = self.run(budget)?;
        unit_point_set(&pts, self.dims)
    }

    /// The points as `f64` in `[0, 1)`, row-major.
    ///
    /// # Errors
    /// As [`SpectralBlueNoise::generate`].
    pub fn run(&self, budget: &Budget) -> Result<Vec<f64>> {
        const WHAT: &str = "spectral blue noise";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let (n, d) = (self.n as usize, self.dims);
        let len = crate::size::coordinates(self.n, d)?;
        let mut raw = crate::size::vec_zeroed::<u32>(len)?;
        Scrambled::new(Sobol::new(d)?, FastOwen::new(self.seed)).fill(0, &mut raw)?;
        let mut pts = crate::size::vec_zeroed::<f64>(len)?;
        for (p, &u) in pts.iter_mut().zip(&raw) {
            *p = crate::bits::to_f64(u);
        }
        drop(raw);
        if self.iterations == 0 {
            return Ok(pts);
        }
        let est = Estimator::new(n, d, &self.profile);
        let mut near = Near::new(&pts, d, est.cut, est.s, n)?;
        let mut evals = 1u32;
        let g = est.histogram(&pts, &near, &budget)?;
        let mut e = est.energy(&g);
        let mut grad = crate::size::vec_zeroed::<f64>(len)?;
        est.gradient_all(&pts, &near, &g, &mut grad, &budget)?;
        let mut memory = Memory::new(MEMORY);
        let mut dir = crate::size::vec_zeroed::<f64>(len)?;
        let mut trial = crate::size::vec_zeroed::<f64>(len)?;
        let mut grad_new = crate::size::vec_zeroed::<f64>(len)?;
        'descent: while evals < self.iterations {
            budget.check_deadline(WHAT)?;
            memory.direction(&grad, &mut dir);
            let mut slope = dot(&grad, &dir);
            if slope.is_nan() || slope >= 0.0 || memory.is_empty() {
                // Steepest descent, the root-mean-square move FIRST_STEP spacings.
                let rms = (dot(&grad, &grad) / n as f64).sqrt();
                if rms.is_nan() || rms <= 0.0 {
                    break;
                }
                let k = FIRST_STEP * est.s / rms;
                for (o, &x) in dir.iter_mut().zip(&grad) {
                    *o = -k * x;
                }
                memory.clear();
                slope = dot(&grad, &dir);
            }
            // At most MAX_MOVE spacings for any point.
            let longest = dir
                .chunks_exact(d)
                .map(|v| v.iter().map(|x| x * x).sum::<f64>())
                .fold(0.0f64, f64::max)
                .sqrt();
            let mut alpha = if longest > MAX_MOVE * est.s {
                MAX_MOVE * est.s / longest
            } else {
                1.0
            };
            // Backtracking to the sufficient decrease (Armijo) condition.
            let e_new = loop {
                budget.check_deadline(WHAT)?;
                for ((t, &x), &v) in trial.iter_mut().zip(&pts).zip(&dir) {
                    let y = x + alpha * v;
                    let y = y - y.floor();
                    *t = if y >= 1.0 { 0.0 } else { y };
                }
                if near.stale(&trial) {
                    near = Near::new(&trial, d, est.cut, est.s, n)?;
                }
                let g = est.histogram(&trial, &near, &budget)?;
                let e_new = est.energy(&g);
                evals += 1;
                if e_new <= e + ARMIJO * alpha * slope {
                    est.gradient_all(&trial, &near, &g, &mut grad_new, &budget)?;
                    break e_new;
                }
                alpha *= 0.5;
                if alpha < 1e-8 || evals >= self.iterations {
                    break 'descent;
                }
            };
            // s = alpha dir, y = grad_new - grad.
            memory.push(alpha, &dir, &grad_new, &grad);
            core::mem::swap(&mut pts, &mut trial);
            core::mem::swap(&mut grad, &mut grad_new);
            e = e_new;
        }
        Ok(pts)
    }
}

/// The pair correlation estimate, its target and its gradient.
struct Estimator {
    n: usize,
    d: usize,
    /// The mean spacing `N^(-1/d)`.
    s: f64,
    /// The pair cut-off in unit lengths.
    cut: f64,
    /// The pair cut-off in mean spacings.
    rho_cut: f64,
    /// Bins of the estimate.
    bins: usize,
    /// `c_b` of each bin.
    scale: Vec<f64>,
    /// The smoothed target `Gbar_b`.
    target: Vec<f64>,
}

/// Table spacing of `psi`.
const TABLE_STEP: f64 = DELTA / 8.0;

/// `exp(-DELTA^2 / H^2)`: the factor between successive ratios of the kernel's values at
/// the bin centres.
const KERNEL_RATIO_STEP: f64 = 0.367_879_441_171_442_33; // e^-1, DELTA = H
const _: () = assert!(DELTA == H);

/// The weight of bin `b`, `rho_b^(d-1)`: with it `E` is the squared `L^2(R^d)` distance
/// of `G` to the target, which by Parseval's identity for the Hankel transform equals the
/// squared `L^2` distance of the spectra (over the estimate's range).
fn weight(b: usize, d: usize) -> f64 {
    ((b as f64 + 0.5) * DELTA).powi(d as i32 - 1)
}

fn kernel(x: f64) -> f64 {
    (-0.5 * x * x / (H * H)).exp() / (H * (2.0 * core::f64::consts::PI).sqrt())
}

impl Estimator {
    fn new(n: usize, d: usize, profile: &Profile) -> Self {
        let s = (n as f64).powf(-1.0 / d as f64);
        let sphere = d as f64 * ball_volume(d);
        let rho = |b: usize| (b as f64 + 0.5) * DELTA;
        let range = range(n as u64, d);
        let bins = ((range / DELTA) as usize).max(1);
        let rho_cut = range + 4.0 * H;
        let scale = (0..bins)
            .map(|b| 1.0 / ((n as f64 - 1.0) * sphere * rho(b).powi(d as i32 - 1)))
            .collect();
        // Gbar_b = int k_h(rho_b - t) (t / rho_b)^(d-1) G_0(t) dt, midpoint rule on t > 0.
        let dt = H / 8.0;
        let ts: Vec<(f64, f64)> = (0..((rho_cut + 4.0 * H) / dt) as usize)
            .map(|i| {
                let t = (i as f64 + 0.5) * dt;
                (t, profile.pcf_unchecked(d, t))
            })
            .collect();
        let target = (0..bins)
            .map(|b| {
                let r = rho(b);
                ts.iter()
                    .map(|&(t, g)| kernel(r - t) * (t / r).powi(d as i32 - 1) * g * dt)
                    .sum()
            })
            .collect();
        Estimator {
            n,
            d,
            s,
            cut: rho_cut * s,
            rho_cut,
            bins,
            scale,
            target,
        }
    }

    /// Calls `f(j, diff, rho)` for every `j != i` within the cut-off (`diff = x_i - x_j`
    /// wrapped, `rho` in mean spacings).
    fn pairs(
        &self,
        pts: &[f64],
        near: &Near,
        i: usize,
        above: bool,
        mut f: impl FnMut(usize, &[f64], f64),
    ) {
        let d = self.d;
        let Some(p) = pts.get(i * d..i * d + d) else {
            return;
        };
        let mut diff = [0.0f64; SPECTRAL_MAX_DIMS];
        let cut2 = self.cut * self.cut;
        let mut visit = |j: usize| {
            if j == i {
                return;
            }
            let Some(q) = pts.get(j * d..j * d + d) else {
                return;
            };
            let mut r2 = 0.0;
            for ((o, a), b) in diff.iter_mut().zip(p).zip(q) {
                *o = wrap(a - b);
                r2 += *o * *o;
            }
            if r2 < cut2 && r2 > 0.0 {
                f(j, diff.get(..d).unwrap_or(&[]), r2.sqrt() / self.s);
            }
        };
        match near {
            Near::Lists(l) => {
                let row = l.of(i);
                // The rows are sorted: the pairs counted once start past `i`.
                let from = if above {
                    row.partition_point(|&j| (j as usize) < i)
                } else {
                    0
                };
                row.get(from..)
                    .unwrap_or(&[])
                    .iter()
                    .for_each(|&j| visit(j as usize));
            }
            Near::Cells(c) => c.near(p, self.n, visit),
        }
    }

    /// The estimate `G_b`.
    fn histogram(&self, pts: &[f64], near: &Near, budget: &Budget) -> Result<Vec<f64>> {
        let chunks = self.n.div_ceil(CHUNK);
        let parts = (0..chunks)
            .into_par_iter()
            .map(|c| -> Result<Vec<f64>> {
                budget.check_deadline("spectral blue noise")?;
                let mut h = vec![0.0f64; self.bins];
                for i in c * CHUNK..((c + 1) * CHUNK).min(self.n) {
                    // Each pair once (j > i), counted twice.
                    self.pairs(pts, near, i, true, |j, _, rho| {
                        if j < i {
                            return;
                        }
                        let lo = ((rho - 4.0 * H) / DELTA - 0.5).ceil().max(0.0) as usize;
                        let hi = (((rho + 4.0 * H) / DELTA - 0.5).floor().max(0.0) as usize)
                            .min(self.bins - 1);
                        // k(x + DELTA) = k(x) q(x), q(x) = exp(-(2 x DELTA + DELTA^2) / (2 H^2)),
                        // q(x + DELTA) = q(x) exp(-DELTA^2 / H^2): two exponentials a pair
                        // instead of one a bin.
                        let x = (lo as f64 + 0.5) * DELTA - rho;
                        let mut k = 2.0 * kernel(x);
                        let mut q = (-(2.0 * x * DELTA + DELTA * DELTA) / (2.0 * H * H)).exp();
                        for v in h.get_mut(lo..=hi).unwrap_or(&mut []) {
                            *v += k;
                            k *= q;
                            q *= KERNEL_RATIO_STEP;
                        }
                    });
                }
                Ok(h)
            })
            .collect::<Result<Vec<_>>>()?;
        let mut g = vec![0.0f64; self.bins];
        for part in &parts {
            for (a, b) in g.iter_mut().zip(part) {
                *a += b;
            }
        }
        for (a, c) in g.iter_mut().zip(&self.scale) {
            *a *= c;
        }
        Ok(g)
    }

    /// `E = sum_b w_b (G_b - Gbar_b)^2`, `w_b = rho_b^(d-1)`.
    fn energy(&self, g: &[f64]) -> f64 {
        g.iter()
            .zip(&self.target)
            .enumerate()
            .map(|(b, (a, t))| weight(b, self.d) * (a - t) * (a - t))
            .sum()
    }

    /// `psi` on `[0, rho_cut]` at spacing [`TABLE_STEP`].
    fn force_table(&self, g: &[f64]) -> Vec<f64> {
        let len = (self.rho_cut / TABLE_STEP) as usize + 2;
        (0..len)
            .map(|t| {
                let rho = t as f64 * TABLE_STEP;
                // The bins within the kernel's support, 5h.
                let lo = ((rho - 5.0 * H) / DELTA - 0.5).ceil().max(0.0) as usize;
                let hi =
                    (((rho + 5.0 * H) / DELTA - 0.5).floor().max(0.0) as usize).min(self.bins - 1);
                (lo..=hi)
                    .map(|b| {
                        let x = (b as f64 + 0.5) * DELTA - rho;
                        let (gb, tb, cb) = (
                            g.get(b).copied().unwrap_or(0.0),
                            self.target.get(b).copied().unwrap_or(0.0),
                            self.scale.get(b).copied().unwrap_or(0.0),
                        );
                        if x.abs() > 5.0 * H {
                            return 0.0;
                        }
                        let dk = -x / (H * H) * kernel(x);
                        -4.0 * weight(b, self.d) * (gb - tb) * cb * dk
                    })
                    .sum()
            })
            .collect()
    }

    /// `dE/dx_i` into `out` (`d` values).
    fn gradient_all(
        &self,
        pts: &[f64],
        near: &Near,
        g: &[f64],
        out: &mut [f64],
        budget: &Budget,
    ) -> Result<()> {
        let psi = self.force_table(g);
        let d = self.d;
        out.par_chunks_mut(CHUNK * d)
            .enumerate()
            .try_for_each(|(c, out)| -> Result<()> {
                budget.check_deadline("spectral blue noise")?;
                for (k, gi) in out.chunks_exact_mut(d).enumerate() {
                    self.gradient(pts, near, c * CHUNK + k, &psi, gi);
                }
                Ok(())
            })
    }

    fn gradient(&self, pts: &[f64], near: &Near, i: usize, psi: &[f64], out: &mut [f64]) {
        out.fill(0.0);
        self.pairs(pts, near, i, false, |_, diff, rho| {
            let t = rho / TABLE_STEP;
            let k = t as usize;
            let f = t - k as f64;
            let a = psi.get(k).copied().unwrap_or(0.0);
            let b = psi.get(k + 1).copied().unwrap_or(0.0);
            let w = (a + f * (b - a)) / (rho * self.s);
            for (o, x) in out.iter_mut().zip(diff) {
                *o += w * x;
            }
        });
    }
}
