//! The multi-scale sampler of the uniform kernel-density model (Fattal 2011):
//! coarse-to-fine levels of stochastic (Langevin) relaxation.
//!
//! ## The levels
//!
//! Level `l = L - 1, ..., 0` has `n_l` points, `n_0 = N`, `n_{l+1} = ceil(n_l / 2^d)`: a
//! point of level `l` stands for `2^(d l)` points of the set, and its kernel (the model's
//! `sigma` in that level's mean spacings `s_l = n_l^(-1/d)`) is `2^l` times wider. The
//! coarsest level starts uniform at random and is relaxed; each point then splits into the
//! `2^d` corners of a cube of side `s_l / 2` (one finer spacing) around it, turned by a
//! random angle in 2D, the surplus `2^d n_{l+1} - n_l` children are removed at random, and
//! the finer level is relaxed from there. The long wavelengths are thus arranged while they
//! are short ones of a coarse level, where a sweep moves a point a whole fine spacing: the
//! point of the scheme, which avoids the single-scale sampler's critical slowing down.
//!
//! ## A relaxation step
//!
//! The overdamped Langevin step of the Gibbs distribution `p ∝ exp(-E / T)`, one point at a
//! time in order (with the others' newest positions):
//!
//! ```text
//! x_i <- x_i - h s_l^2 grad_i E + sqrt(2 h T) s_l xi,   xi ~ N(0, I_d)
//! ```
//!
//! `E` the pair sum of the parent module in the level's spacings, `h = 0.2` (a step well
//! below the inverse of the energy's curvature at a point for the kernel widths of the
//! defaults; chosen by measurement, 1.0 gave the same statistics at `sigma = 0.71`). The temperature
//! falls geometrically within each level from `4 T` to `T` over its first half and stays
//! at `T` after; the last sweep of the finest level takes no noise (the gradient step
//! alone, which removes the last sweep's jitter). A sweep costs one kernel term and its
//! gradient for each of the `m` neighbours within the cut-off (about `pi 18` in 2D):
//! `N m` terms, against the heat-bath's `16 N m`.

use std::vec::Vec;

use super::super::rng::Rng;
use super::super::torus_cells::{Cells, wrap};
use super::{CUT_SIGMAS, DEADLINE_POINTS, KDE_MAX_DIMS};
use crate::Result;
use crate::work::Budget;

/// The Langevin step `h` in squared mean spacings.
const STEP: f64 = 0.2;

/// The temperature at a level's start, in multiples of the target's.
const START_HEAT: f64 = 4.0;

/// The schedule of one run.
pub(super) struct Schedule {
    pub(super) dims: usize,
    pub(super) sigma: f64,
    pub(super) temperature: f64,
    /// Sweeps at each coarse level.
    pub(super) coarse_sweeps: u32,
    /// Sweeps at the finest level.
    pub(super) fine_sweeps: u32,
    /// Levels `L` (1: single scale).
    pub(super) levels: u32,
}

/// The counts `n_0 = n, n_{l+1} = ceil(n_l / 2^d)` of `levels` levels, finest first.
pub(super) fn counts(n: usize, d: usize, levels: u32) -> Vec<usize> {
    let mut c = Vec::new();
    let mut m = n;
    for _ in 0..levels {
        c.push(m);
        m = m.div_ceil(1 << d);
    }
    c
}

impl Schedule {
    /// The points of `n` (at least 2) after the run, `f64` in `[0, 1)`, row-major.
    pub(super) fn run(
        &self,
        n: usize,
        rng: &mut Rng,
        budget: &Budget,
        what: &'static str,
    ) -> Result<Vec<f64>> {
        let d = self.dims;
        let counts = counts(n, d, self.levels.max(1));
        let coarsest = counts.last().copied().unwrap_or(n);
        let mut pts =
            crate::size::vec_zeroed::<f64>(crate::size::coordinates(coarsest as u64, d)?)?;
        pts.iter_mut().for_each(|x| *x = rng.unit());
        for (l, &m) in counts.iter().enumerate().rev() {
            if pts.len() != m * d {
                pts = split(&pts, d, m, rng)?;
            }
            let sweeps = if l == 0 {
                self.fine_sweeps
            } else {
                self.coarse_sweeps
            };
            self.relax(&mut pts, sweeps, l == 0, rng, budget, what)?;
        }
        Ok(pts)
    }

    /// `sweeps` Langevin sweeps of the level whose points are `pts`.
    fn relax(
        &self,
        pts: &mut [f64],
        sweeps: u32,
        finest: bool,
        rng: &mut Rng,
        budget: &Budget,
        what: &'static str,
    ) -> Result<()> {
        let d = self.dims;
        let n = pts.len() / d;
        if n < 2 {
            return Ok(());
        }
        let s = (n as f64).powf(-1.0 / d as f64);
        let inv = 1.0 / (4.0 * self.sigma * self.sigma * s * s);
        let cut = CUT_SIGMAS * self.sigma * s;
        let cut2 = cut * cut;
        let step = STEP * s * s;
        // Rebuilt each sweep: a point moves well under a spacing a sweep, the cells are a
        // spacing wider than the cut-off.
        let reach = cut + s;
        let warm = (sweeps / 2).max(1);
        for sweep in 0..sweeps {
            budget.check_deadline(what)?;
            let heat = if sweep < warm {
                START_HEAT.powf(1.0 - f64::from(sweep) / f64::from(warm))
            } else {
                1.0
            };
            let t = self.temperature * heat;
            let noise = if finest && sweep + 1 == sweeps {
                0.0
            } else {
                (2.0 * STEP * t).sqrt() * s
            };
            let cells = Cells::new(pts, d, reach)?;
            for i in 0..n {
                if i % DEADLINE_POINTS == DEADLINE_POINTS - 1 {
                    budget.check_deadline(what)?;
                }
                let mut grad = [0.0f64; KDE_MAX_DIMS];
                {
                    let Some(p) = pts.get(i * d..i * d + d) else {
                        continue;
                    };
                    let all: &[f64] = pts;
                    cells.near(p, n, |j| {
                        if j == i {
                            return;
                        }
                        if let Some(q) = all.get(j * d..j * d + d) {
                            let mut diff = [0.0f64; KDE_MAX_DIMS];
                            let mut r2 = 0.0;
                            for ((o, a), b) in diff.iter_mut().zip(p).zip(q) {
                                *o = wrap(a - b);
                                r2 += *o * *o;
                            }
                            if r2 < cut2 {
                                // grad_i exp(-inv r^2) = -2 inv (x_i - x_j) exp(-inv r^2)
                                let w = -2.0 * inv * (-inv * r2).exp();
                                for (g, o) in grad.iter_mut().zip(&diff) {
                                    *g += w * o;
                                }
                            }
                        }
                    });
                }
                if let Some(p) = pts.get_mut(i * d..i * d + d) {
                    for (x, g) in p.iter_mut().zip(&grad) {
                        let mut y = *x - step * g;
                        if noise > 0.0 {
                            y += noise * rng.normal();
                        }
                        let y = y - y.floor();
                        *x = if y >= 1.0 { 0.0 } else { y };
                    }
                }
            }
        }
        Ok(())
    }
}

/// The `m` points of the next finer level: each of `pts`'s points split into the `2^d`
/// corners of a cube of side one finer spacing (turned by a random angle in 2D), the
/// surplus removed at random.
fn split(pts: &[f64], d: usize, m: usize, rng: &mut Rng) -> Result<Vec<f64>> {
    let parents = pts.len() / d;
    let kids = parents << d;
    let s = (m as f64).powf(-1.0 / d as f64);
    let half = 0.5 * s;
    let mut out = crate::size::vec_zeroed::<f64>(crate::size::coordinates(kids as u64, d)?)?;
    for (p, chunk) in pts.chunks_exact(d).zip(out.chunks_exact_mut(d << d)) {
        let (c, sn) = if d == 2 {
            let a = core::f64::consts::TAU * rng.unit();
            (a.cos(), a.sin())
        } else {
            (1.0, 0.0)
        };
        for (k, kid) in chunk.chunks_exact_mut(d).enumerate() {
            let mut off = [0.0f64; KDE_MAX_DIMS];
            for (b, o) in off.iter_mut().enumerate().take(d) {
                *o = if (k >> b) & 1 == 1 { half } else { -half };
            }
            if let [u, v, ..] = &mut off
                && d == 2
            {
                let (a, b) = (*u, *v);
                *u = c * a - sn * b;
                *v = sn * a + c * b;
            }
            for ((y, x), o) in kid.iter_mut().zip(p).zip(&off) {
                let z = x + o;
                let z = z - z.floor();
                *y = if z >= 1.0 { 0.0 } else { z };
            }
        }
    }
    // Remove `kids - m` children at random: a partial Fisher-Yates moving the kept ones
    // to the front.
    let mut keep: Vec<usize> = (0..kids).collect();
    for i in 0..m.min(kids) {
        let j = i + rng.below(kids - i);
        keep.swap(i, j);
    }
    keep.truncate(m);
    keep.sort_unstable();
    let mut res = crate::size::vec_zeroed::<f64>(crate::size::coordinates(m as u64, d)?)?;
    for (dst, &k) in res.chunks_exact_mut(d).zip(&keep) {
        if let Some(src) = out.get(k * d..k * d + d) {
            dst.copy_from_slice(src);
        }
    }
    Ok(res)
}
