//! Density adaptation of kernel-density blue noise (Fattal 2011, section 4): points whose
//! local density follows a target density `D` on the torus, each point's kernel width
//! scaled by the local spacing.
//!
//! ## The model
//!
//! `D` is normalized to mean 1 over the torus (its mean estimated on `2^14` uniform
//! points). Point `i` carries a Gaussian kernel of mass `1/N` and standard deviation
//! `sigma_i = sigma s D(x_i)^(-1/d)` (`s = N^(-1/d)`: the kernel follows the local mean
//! spacing `(N D)^(-1/d)`). The energy is `int (f - D)^2` for the estimate
//! `f = sum_i k_i`: two Gaussians overlap in a Gaussian of variance `sigma_i^2 + sigma_j^2`,
//! and for kernels narrow against the variation of `D`, `int k_i D ≈ D(x_i) / N`. In units
//! of the largest overlap of two kernels at the uniform density, `(4 pi sigma^2 s^2)^(-d/2)
//! / N^2`, the energy is, up to a constant,
//!
//! ```text
//! E = sum_{i<j} (2 sigma^2 s^2 / (sigma_i^2 + sigma_j^2))^(d/2) exp(-|x_i - x_j|^2 / (2 (sigma_i^2 + sigma_j^2)))
//!     + sum_i D(x_i) (1/2 - (4 pi sigma^2)^(d/2))
//! ```
//!
//! (the second line: each kernel's overlap with itself, `D(x_i)` in these units, and twice
//! its overlap with the target). With `D = 1` it is the uniform model's pair sum plus a
//! constant. Minimizing `int (f - D)^2` makes the points' local density `N D`; the
//! sampler is single-scale local heat-bath updates among 16 candidates, the current position
//! and 15 uniform in a window half a *local* spacing wide (a Gibbs step on a random
//! discretization of each point's conditional), defaults `T = 0.01`, `sigma = 1/sqrt(2)`,
//! 200 sweeps (the uniform model's multi-scale scheme is not implemented for varying
//! kernel widths).
//!
//! ## The start and the range
//!
//! The local updates move mass slowly over long distances, so the points start from `D`
//! itself: `8 N` uniform candidates resampled to `N` with probabilities proportional to
//! `D` (systematic resampling). `D` must be finite and positive, with the largest over the
//! smallest of its values on the estimation points at most [`KDE_MAX_DENSITY_RATIO`]; a
//! candidate position where `D` is below half that smallest value is not taken (its
//! kernel would reach past the neighbour search). The pair sum is cut at 6 widths of the
//! pair, `|x_i - x_j|^2 < 18 (sigma_i^2 + sigma_j^2)`, as the uniform model's.
//!
//! ## Cost
//!
//! The uniform model's ([`KdeBlueNoise::cost`]) times the ratio of the mean to the
//! smallest density (the neighbour cells are sized for the widest kernel), plus one
//! evaluation of `D` a candidate (`16 N` a sweep) and `2^14 + 8 N` for the start.

use std::vec::Vec;

use super::super::PointSet;
use super::super::lloyd::unit_point_set;
use super::super::rng::Rng;
use super::super::torus_cells::{Cells, wrap};
use super::{CANDIDATES, CUT_SIGMAS, DEADLINE_POINTS, KDE_MAX_DIMS, KdeBlueNoise, WINDOW, choose};
use crate::work::{Budget, Cost};
use crate::{Error, Result};

/// The largest ratio of the largest to the smallest density value the adaptation takes.
pub const KDE_MAX_DENSITY_RATIO: f64 = 1000.0;

/// Uniform points on which the density's mean and range are estimated.
const ESTIMATION_POINTS: usize = 1 << 14;

/// Start candidates a point.
const START_CANDIDATES: usize = 8;

fn bad_density() -> Error {
    Error::InvalidParameter {
        what: "a kernel-density target density must be finite and positive, its largest value \
               at most 1000 times its smallest",
    }
}

impl KdeBlueNoise {
    /// `N` points following `density` on the torus `[0, 1)^d` (see the module's
    /// documentation), refused before they start when the estimated cost exceeds `budget`,
    /// stopped at its deadline. `density` takes a point of `d` coordinates in `[0, 1)` and
    /// need not be normalized.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a density value not finite or not positive, or a
    /// range past [`KDE_MAX_DENSITY_RATIO`]; [`Error::OverBudget`], [`Error::TooLarge`],
    /// [`Error::OutOfTime`].
    ///
    /// ```
    /// use qmckit::blue_noise::KdeBlueNoise;
    /// use qmckit::work::Budget;
    /// // The density is 1 at x = 0 and 3 at x = 1/2.
    /// let d = |x: &[f64]| 2.0 - (std::f64::consts::TAU * x[0]).cos();
    /// let set = KdeBlueNoise::new(256, 2)?.sweeps(20)?.seed(1).sample(&d, &Budget::DEFAULT)?;
    /// assert_eq!(set.count(), 256);
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn sample(&self, density: &dyn Fn(&[f64]) -> f64, budget: &Budget) -> Result<PointSet> {
        let pts = self.run_density(density, budget)?;
        unit_point_set(&pts, self.dims)
    }

    /// [`sample`](Self::sample)'s points as `f64` in `[0, 1)`, row-major.
    ///
    /// # Errors
    /// As [`KdeBlueNoise::sample`].
    pub fn run_density(
        &self,
        density: &dyn Fn(&[f64]) -> f64,
        budget: &Budget,
    ) -> Result<Vec<f64>> {
        const WHAT: &str = "kernel-density blue noise with a density";
        let budget = budget.started();
        let (n, d) = (self.n as usize, self.dims);
        let eval = |x: &[f64]| -> Result<f64> {
            let v = density(x);
            if v.is_finite() && v > 0.0 {
                Ok(v)
            } else {
                Err(bad_density())
            }
        };
        // The mean and the range on uniform points.
        let mut rng = Rng::new(self.seed, 0x4B44_4544_454E_5331); // "KDEDENS1"
        let mut x = [0.0f64; KDE_MAX_DIMS];
        let (mut sum, mut lo, mut hi) = (0.0, f64::INFINITY, 0.0f64);
        for _ in 0..ESTIMATION_POINTS {
            x.iter_mut().take(d).for_each(|c| *c = rng.unit());
            let v = eval(&x[..d])?;
            sum += v;
            lo = lo.min(v);
            hi = hi.max(v);
        }
        let mean = sum / ESTIMATION_POINTS as f64;
        if hi > KDE_MAX_DENSITY_RATIO * lo {
            return Err(bad_density());
        }
        let floor = 0.5 * lo / mean;
        let base = self.heat_bath_cost().seconds() * (1.0 / floor).max(1.0);
        budget.check(WHAT, Cost::from_seconds(base))?;
        let norm = |x: &[f64]| -> Result<f64> { Ok(eval(x)? / mean) };

        // The start: systematic resampling of 8 N uniform candidates by D.
        let m = START_CANDIDATES * n;
        let mut cands = crate::size::vec_zeroed::<f64>(crate::size::coordinates(m as u64, d)?)?;
        cands.iter_mut().for_each(|c| *c = rng.unit());
        let mut cum = crate::size::vec_zeroed::<f64>(m)?;
        let mut total = 0.0;
        for (c, row) in cum.iter_mut().zip(cands.chunks_exact(d)) {
            total += norm(row)?;
            *c = total;
        }
        let mut pts = crate::size::vec_zeroed::<f64>(crate::size::coordinates(self.n, d)?)?;
        let u0 = rng.unit();
        let mut k = 0usize;
        for (i, p) in pts.chunks_exact_mut(d).enumerate() {
            let t = (i as f64 + u0) / n as f64 * total;
            while k + 1 < m && cum.get(k).is_some_and(|&c| c <= t) {
                k += 1;
            }
            if let Some(row) = cands.get(k * d..k * d + d) {
                p.copy_from_slice(row);
            }
        }
        drop(cands);
        drop(cum);

        let s = (n as f64).powf(-1.0 / d as f64);
        let sigma = self.density_sigma();
        let s2 = sigma * sigma * s * s; // sigma^2 s^2
        let width2 = |dens: f64| s2 * dens.powf(-2.0 / d as f64);
        let unary = 0.5 - (4.0 * core::f64::consts::PI * sigma * sigma).powf(d as f64 / 2.0);
        let half_d = d as f64 / 2.0;
        // The widest kernel (density at the floor) sets the neighbour reach.
        let stretch = floor.powf(-1.0 / d as f64);
        let cut_max = CUT_SIGMAS * sigma * s * stretch;
        let reach = cut_max + 2.0 * WINDOW * s * stretch * (d as f64).sqrt();
        let mut dens = crate::size::vec_zeroed::<f64>(n)?;
        for (v, p) in dens.iter_mut().zip(pts.chunks_exact(d)) {
            *v = norm(p)?;
        }
        // Neighbours: (difference x_j - x_i, width^2 of j).
        let mut near: Vec<f64> = Vec::new();
        let mut cand = [[0.0f64; KDE_MAX_DIMS]; CANDIDATES];
        let mut energy = [0.0f64; CANDIDATES];
        let mut cand_dens = [0.0f64; CANDIDATES];
        for _ in 0..self.sweeps.unwrap_or(super::DENSITY_SWEEPS) {
            budget.check_deadline(WHAT)?;
            let cells = Cells::new(&pts, d, reach)?;
            for i in 0..n {
                if i % DEADLINE_POINTS == 0 {
                    budget.check_deadline(WHAT)?;
                }
                near.clear();
                let Some(p) = pts.get(i * d..i * d + d) else {
                    continue;
                };
                let di = dens.get(i).copied().unwrap_or(1.0);
                let half = WINDOW * s * di.powf(-1.0 / d as f64);
                cells.near(p, n, |j| {
                    if j == i {
                        return;
                    }
                    if let (Some(q), Some(&dj)) = (pts.get(j * d..j * d + d), dens.get(j)) {
                        let r2: f64 = q.iter().zip(p).map(|(b, a)| wrap(b - a).powi(2)).sum();
                        if r2 < reach * reach {
                            near.extend(q.iter().zip(p).map(|(b, a)| wrap(b - a)));
                            near.push(width2(dj));
                        }
                    }
                });
                for (c, off) in cand.iter_mut().enumerate() {
                    for o in off.iter_mut().take(d) {
                        *o = if c == 0 {
                            0.0
                        } else {
                            (2.0 * rng.unit() - 1.0) * half
                        };
                    }
                }
                for c in 0..CANDIDATES {
                    let (Some(off), Some(e), Some(cd)) =
                        (cand.get(c), energy.get_mut(c), cand_dens.get_mut(c))
                    else {
                        continue;
                    };
                    if c == 0 {
                        *cd = di;
                    } else {
                        let mut y = [0.0f64; KDE_MAX_DIMS];
                        for ((y, x), o) in y.iter_mut().zip(p).zip(off) {
                            let v = x + o;
                            let v = v - v.floor();
                            *y = if v >= 1.0 { 0.0 } else { v };
                        }
                        *cd = norm(&y[..d])?;
                    }
                    // The current position is always a candidate (finite energy).
                    if c != 0 && *cd < floor {
                        *e = f64::INFINITY;
                        continue;
                    }
                    let wy = width2(*cd);
                    let pair: f64 = near
                        .chunks_exact(d + 1)
                        .map(|q| {
                            let w = wy + q[d];
                            let r2: f64 =
                                q[..d].iter().zip(off).map(|(a, b)| (a - b) * (a - b)).sum();
                            if r2 < 0.5 * CUT_SIGMAS * CUT_SIGMAS * w {
                                (2.0 * s2 / w).powf(half_d) * (-r2 / (2.0 * w)).exp()
                            } else {
                                0.0
                            }
                        })
                        .sum();
                    *e = pair + unary * *cd;
                }
                let pick = choose(
                    &energy,
                    self.temperature.unwrap_or(super::DENSITY_TEMPERATURE),
                    &mut rng,
                );
                if pick != 0
                    && let (Some(p), Some(off), Some(&cd)) = (
                        pts.get_mut(i * d..i * d + d),
                        cand.get(pick),
                        cand_dens.get(pick),
                    )
                {
                    for (x, o) in p.iter_mut().zip(off) {
                        let y = *x + o;
                        let y = y - y.floor();
                        *x = if y >= 1.0 { 0.0 } else { y };
                    }
                    if let Some(v) = dens.get_mut(i) {
                        *v = cd;
                    }
                }
            }
        }
        Ok(pts)
    }
}
