//! Semi-discrete optimal transport in 2D: the weights that give every Laguerre cell of
//! `N` sites the area `1/N`, in the unit square or on the unit torus.
//!
//! ## The problem
//!
//! Transporting the uniform measure of the domain `D` to the sites `p_1..p_N`, each of
//! mass `1/N`, at cost `|x - p|^2` is optimal along the Laguerre cells of some weights
//! (Aurenhammer, Hoffmann & Aronov 1998, "Minkowski-type theorems and least-squares
//! clustering", Algorithmica 20): those for which every cell has the capacity `1/N`. The
//! weights maximize the concave dual
//!
//! `Phi(w) = sum_i int_{L_i(w)} (|x - p_i|^2 - w_i) dx + (1/N) sum_i w_i`,
//!
//! whose gradient is `dPhi/dw_i = 1/N - A_i(w)` (the cell areas) and whose negated Hessian
//! is `H = dA/dw`, the cell-adjacency matrix of [`PowerDiagram::neighbours`]:
//! `H_ij = -l_ij / (2 |p_i - p_j|)`, `H_ii = -sum_(j != i) H_ij` (Mérigot 2011, "A multiscale
//! approach to optimal transport", Computer Graphics Forum 30(5)). At the maximum the
//! value is the squared Wasserstein distance, `W_2^2 = sum_i int_{L_i} |x - p_i|^2 dx`.
//!
//! ## The solve
//!
//! Damped Newton (Kitagawa, Mérigot & Thibert 2019, "Convergence of a Newton algorithm for
//! semi-discrete optimal transport", J. Eur. Math. Soc. 21(9)): from weights whose cells
//! all have positive area (the start, else zero weights: the Voronoi diagram), with
//! `eps = min(min_i A_i, 1/N) / 2`, solve `H d = 1/N - A(w)` (conjugate gradients with
//! the diagonal as preconditioner, to a relative residual of `1e-4`; `H` is singular
//! along constant vectors and the right side is orthogonal to them) and take
//! `w + 2^-k d` for the least `k` with every area at least `eps` and
//! `|A - 1/N| <= (1 - 2^-(k+1)) |A(w) - 1/N|` (Euclidean norms). Its authors prove global
//! convergence, locally quadratic (here with the inexact linear solve, a contraction of
//! about `1e-4` a step near the solution). It stops when `max_i |N A_i - 1| <= tolerance`
//! (default [`DEFAULT_TOLERANCE`], at least [`MIN_TOLERANCE`]), and fails with an error
//! after [`MAX_NEWTON_STEPS`] steps or when no step length of the `2^-40` tried is
//! accepted (rounding: a tolerance below what the areas can resolve).
//!
//! ## Range and cost
//!
//! 1 to [`super::power::POWER_MAX_SITES`] distinct sites in `[0, 1]^2`. A step costs one
//! diagram per step length tried (`O(N)`, see [`PowerDiagram`]) and the conjugate
//! gradients, `O(N^1.5)` (the iterations grow like `sqrt N` on a planar adjacency); from
//! zero weights about 6 to 10 steps, from the weights of nearby sites (a warm start, as in
//! BNOT's loop) 1 to 3. Estimated by [`cost`], stopped at the budget's deadline.
//!
//! ```
//! use qmckit::blue_noise::transport;
//! use qmckit::work::Budget;
//! let sites = [0.1, 0.1, 0.2, 0.15, 0.9, 0.8];
//! let t = transport::solve(&sites, false, transport::DEFAULT_TOLERANCE, &Budget::DEFAULT)?;
//! for &a in t.diagram().areas() {
//!     assert!((3.0 * a - 1.0).abs() <= 1e-9);
//! }
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::power::{self, PowerDiagram};
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The default stopping tolerance on `max_i |N A_i - 1|`.
pub const DEFAULT_TOLERANCE: f64 = 1e-9;

/// The smallest tolerance taken (the areas are sums of rounded products: about `1e-16`
/// relative to the domain, so `N 1e-16` relative to a cell).
pub const MIN_TOLERANCE: f64 = 1e-11;

/// The most Newton steps of a solve.
pub const MAX_NEWTON_STEPS: u32 = 100;

/// Halvings of the Newton step tried before the solve gives up.
const MAX_HALVINGS: u32 = 40;

/// The conjugate gradients' relative residual: an inexact Newton step (Dembo, Eisenstat
/// & Steihaug 1982) whose error contracts the misfit by about this factor on top of the
/// quadratic term, at a third of the iterations of a full solve.
const CG_RESIDUAL: f64 = 1e-4;

/// Diagram-equivalents of a cold solve: about 8 steps of one diagram each, with margin.
const COLD_DIAGRAMS: f64 = 12.0;

/// Conjugate-gradient entries (one product of a matrix entry) a second, release, assumed;
/// the whole estimate checked against cold solves of 1024, 4096 and 16384 points:
/// estimated 0.10, 0.64 and 4.3 s, measured 0.04 to 0.08, 0.5 to 0.86 and 4.1 to 5.8 s
/// (two cores shared with other work).
const CG_ENTRIES: Rate = Rate::per_second(2e8);

/// A solved transport: the weights, their diagram and how the solve went.
#[derive(Clone, Debug)]
pub struct Transport {
    weights: Vec<f64>,
    diagram: PowerDiagram,
    steps: u32,
    error: f64,
}

impl Transport {
    /// The weights `w`.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The power diagram of the weights: every cell of area `1/N` within the tolerance.
    pub fn diagram(&self) -> &PowerDiagram {
        &self.diagram
    }

    /// Newton steps taken.
    pub fn newton_steps(&self) -> u32 {
        self.steps
    }

    /// `max_i |N A_i - 1|` at the end.
    pub fn max_error(&self) -> f64 {
        self.error
    }

    /// The transport cost `sum_i int_{L_i} |x - p_i|^2 dx` (the squared distance `W_2^2`
    /// between the uniform measure and the sites at mass `1/N`, up to the tolerance).
    pub fn cost(&self) -> f64 {
        (0..self.diagram.len())
            .map(|i| self.diagram.moment(i))
            .sum()
    }

    /// The weights, given up.
    pub fn into_weights(self) -> Vec<f64> {
        self.weights
    }

    /// The weights and the diagram, given up.
    pub(crate) fn into_parts(self) -> (Vec<f64>, PowerDiagram) {
        (self.weights, self.diagram)
    }
}

/// The estimated running time of a solve from zero weights for `n` sites: about
/// 12 diagrams and as many conjugate-gradient solves of
/// `4 sqrt(n) + 20` iterations over `7 n` entries.
pub fn cost(n: usize) -> Cost {
    let diagrams = PowerDiagram::cost(n).seconds() * COLD_DIAGRAMS;
    let n = n as f64;
    let cg = Cost::steps(
        COLD_DIAGRAMS * (4.0 * n.sqrt() + 20.0) * 7.0 * n,
        CG_ENTRIES,
    );
    Cost::from_seconds(diagrams).plus(cg)
}

/// The weights that give every cell of `sites` (row-major `(x, y)` pairs in `[0, 1]^2`)
/// the area `1/N` within `tolerance` (`max_i |N A_i - 1|`), in the unit square or on the
/// torus, from zero weights.
///
/// # Errors
/// As [`PowerDiagram::new`]; [`Error::InvalidParameter`] for a tolerance below
/// [`MIN_TOLERANCE`] or not finite, or a solve that does not converge.
pub fn solve(sites: &[f64], torus: bool, tolerance: f64, budget: &Budget) -> Result<Transport> {
    let zero = crate::size::vec_zeroed::<f64>(sites.len() / 2)?;
    solve_from(sites, torus, &zero, tolerance, budget)
}

/// As [`solve`], from the weights `start` (one a site; zero weights are taken instead if
/// some cell of `start` is empty).
///
/// # Errors
/// As [`solve`].
pub fn solve_from(
    sites: &[f64],
    torus: bool,
    start: &[f64],
    tolerance: f64,
    budget: &Budget,
) -> Result<Transport> {
    let budget = budget.started();
    let pts = power::validate(sites, start, torus)?;
    budget.check("transport solve", cost(pts.len()))?;
    power::check_distinct(&pts)?;
    solve_points(&pts, torus, start.to_vec(), tolerance, None, &budget)
}

/// The solve for validated, distinct sites; `hint` is a diagram of nearby sites (the
/// previous iteration's in BNOT) whose neighbours are clipped first
/// ([`PowerDiagram::build_hinted`]; the diagrams are the same).
pub(crate) fn solve_points(
    pts: &[[f64; 2]],
    torus: bool,
    mut w: Vec<f64>,
    tolerance: f64,
    hint: Option<&PowerDiagram>,
    budget: &Budget,
) -> Result<Transport> {
    const WHAT: &str = "transport solve";
    if !(tolerance >= MIN_TOLERANCE && tolerance.is_finite()) {
        return Err(Error::InvalidParameter {
            what: "the transport tolerance must be finite and at least 1e-11",
        });
    }
    let n = pts.len();
    let nu = 1.0 / n as f64;
    let mut d = PowerDiagram::build_hinted(pts, &w, torus, hint, budget)?;
    if d.areas().iter().any(|&a| a <= 0.0) {
        w.iter_mut().for_each(|x| *x = 0.0);
        d = PowerDiagram::build(pts, &w, torus, budget)?;
    }
    let min_area = d.areas().iter().copied().fold(f64::INFINITY, f64::min);
    if min_area.is_nan() || min_area <= 0.0 {
        return Err(Error::InvalidParameter {
            what: "a Voronoi cell has no area: the sites are too close to be told apart",
        });
    }
    let eps = 0.5 * min_area.min(nu);
    let mut trial = crate::size::vec_zeroed::<f64>(n)?;
    for step in 0..=MAX_NEWTON_STEPS {
        let error = d
            .areas()
            .iter()
            .map(|a| (a * n as f64 - 1.0).abs())
            .fold(0.0, f64::max);
        if error <= tolerance {
            return Ok(Transport {
                weights: w,
                diagram: d,
                steps: step,
                error,
            });
        }
        if step == MAX_NEWTON_STEPS {
            break;
        }
        budget.check_deadline(WHAT)?;
        let mut b: Vec<f64> = d.areas().iter().map(|a| nu - a).collect();
        let mean = b.iter().sum::<f64>() / n as f64;
        b.iter_mut().for_each(|x| *x -= mean);
        let norm0 = misfit(&d, nu);
        let dir = conjugate_gradients(&d, &b, budget)?;
        let mut alpha = 1.0;
        let mut accepted = None;
        for _ in 0..=MAX_HALVINGS {
            for ((t, &x), &s) in trial.iter_mut().zip(&w).zip(&dir) {
                *t = x + alpha * s;
            }
            let next = PowerDiagram::build_hinted(pts, &trial, torus, Some(&d), budget)?;
            let min = next.areas().iter().copied().fold(f64::INFINITY, f64::min);
            if min >= eps && misfit(&next, nu) <= (1.0 - alpha / 2.0) * norm0 {
                accepted = Some(next);
                break;
            }
            alpha *= 0.5;
        }
        let Some(next) = accepted else {
            return Err(Error::InvalidParameter {
                what: "the transport solve stalled (no Newton step length improves the areas)",
            });
        };
        core::mem::swap(&mut w, &mut trial);
        d = next;
    }
    Err(Error::InvalidParameter {
        what: "the transport solve did not converge in 100 Newton steps",
    })
}

/// `|A - nu|`, Euclidean.
fn misfit(d: &PowerDiagram, nu: f64) -> f64 {
    d.areas()
        .iter()
        .map(|a| (a - nu) * (a - nu))
        .sum::<f64>()
        .sqrt()
}

/// `H x` for the adjacency matrix of `d`.
fn apply(d: &PowerDiagram, diag: &[f64], x: &[f64], out: &mut [f64]) {
    for (i, o) in out.iter_mut().enumerate() {
        let off: f64 = d
            .neighbours(i)
            .iter()
            .map(|&(j, c)| c * x.get(j as usize).copied().unwrap_or(0.0))
            .sum();
        *o = diag[i] * x[i] - off;
    }
}

/// Solves `H x = b` (`b` orthogonal to the constants) by conjugate gradients with the
/// diagonal as preconditioner, to a relative residual of [`CG_RESIDUAL`] or `4 N + 100`
/// iterations.
fn conjugate_gradients(d: &PowerDiagram, b: &[f64], budget: &Budget) -> Result<Vec<f64>> {
    let n = b.len();
    let mut diag = crate::size::vec_zeroed::<f64>(n)?;
    for (i, g) in diag.iter_mut().enumerate() {
        *g = d.neighbours(i).iter().map(|&(_, c)| c).sum();
    }
    let inv: Vec<f64> = diag
        .iter()
        .map(|&g| if g > 0.0 { 1.0 / g } else { 0.0 })
        .collect();
    let mut x = crate::size::vec_zeroed::<f64>(n)?;
    let mut r = b.to_vec();
    let mut z: Vec<f64> = r.iter().zip(&inv).map(|(r, m)| r * m).collect();
    let mut p = z.clone();
    let mut hp = crate::size::vec_zeroed::<f64>(n)?;
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let target = CG_RESIDUAL * dot(b, b).sqrt();
    let mut rz = dot(&r, &z);
    for it in 0..4 * n + 100 {
        if dot(&r, &r).sqrt() <= target {
            break;
        }
        if it % 32 == 0 {
            budget.check_deadline("transport solve")?;
        }
        apply(d, &diag, &p, &mut hp);
        let php = dot(&p, &hp);
        if php.is_nan() || php <= 0.0 {
            break;
        }
        let a = rz / php;
        for k in 0..n {
            x[k] += a * p[k];
            r[k] -= a * hp[k];
            z[k] = r[k] * inv[k];
        }
        let rz_next = dot(&r, &z);
        let beta = rz_next / rz;
        rz = rz_next;
        for k in 0..n {
            p[k] = z[k] + beta * p[k];
        }
    }
    Ok(x)
}
