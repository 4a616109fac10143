//! Limited-memory BFGS (Nocedal, "Updating quasi-Newton matrices with limited storage",
//! Math. Comp. 35, 1980; Nocedal & Wright, "Numerical Optimization", algorithm 7.4) for the
//! descent of [`super::spectral`]: the last `m` moves `s_k` and gradient changes `y_k`
//! define an approximation `H` of the inverse Hessian, applied to a gradient by the
//! two-loop recursion in `O(m n)` operations (`n` coordinates), with `H_0 = (s . y) /
//! (y . y)` of the newest pair. A pair is kept only when its curvature `s . y` is positive,
//! which keeps `H` positive definite.

/// Limited-memory BFGS pairs kept (Nocedal, "Updating quasi-Newton matrices with limited
/// storage", Math. Comp. 35, 1980).
pub(crate) const MEMORY: usize = 8;
/// The root-mean-square move of a steepest-descent step, in mean spacings.
pub(crate) const FIRST_STEP: f64 = 0.05;
/// The longest move of any point in one step, in mean spacings.
pub(crate) const MAX_MOVE: f64 = 0.5;
/// The sufficient-decrease constant of the line search.
pub(crate) const ARMIJO: f64 = 1e-4;

pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The last pairs `(s_k, y_k)` of moves and gradient changes.
pub(crate) struct Memory {
    cap: usize,
    s: Vec<Vec<f64>>,
    y: Vec<Vec<f64>>,
    rho: Vec<f64>,
}

impl Memory {
    pub(crate) fn new(cap: usize) -> Self {
        Memory {
            cap,
            s: Vec::new(),
            y: Vec::new(),
            rho: Vec::new(),
        }
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.s.is_empty()
    }

    pub(crate) fn clear(&mut self) {
        self.s.clear();
        self.y.clear();
        self.rho.clear();
    }

    /// Keeps `s = alpha dir`, `y = g1 - g0` when the curvature `s . y` is positive.
    pub(crate) fn push(&mut self, alpha: f64, dir: &[f64], g1: &[f64], g0: &[f64]) {
        let (mut s, mut y) = if self.s.len() == self.cap {
            self.rho.remove(0);
            (self.s.remove(0), self.y.remove(0))
        } else {
            (vec![0.0; dir.len()], vec![0.0; dir.len()])
        };
        for (o, &v) in s.iter_mut().zip(dir) {
            *o = alpha * v;
        }
        for ((o, &a), &b) in y.iter_mut().zip(g1).zip(g0) {
            *o = a - b;
        }
        let sy = dot(&s, &y);
        if sy > 1e-10 * (dot(&y, &y) * dot(&s, &s)).sqrt() {
            self.s.push(s);
            self.y.push(y);
            self.rho.push(1.0 / sy);
        }
    }

    /// `dir = -H g` by the two-loop recursion, `H_0 = (s . y) / (y . y)` of the newest pair.
    pub(crate) fn direction(&self, g: &[f64], dir: &mut [f64]) {
        dir.copy_from_slice(g);
        let mut a = [0.0f64; MEMORY];
        for (((ai, s), y), &r) in a.iter_mut().zip(&self.s).zip(&self.y).zip(&self.rho).rev() {
            *ai = r * dot(s, dir);
            for (q, &yv) in dir.iter_mut().zip(y) {
                *q -= *ai * yv;
            }
        }
        if let (Some(s), Some(y)) = (self.s.last(), self.y.last()) {
            let gamma = dot(s, y) / dot(y, y);
            for q in dir.iter_mut() {
                *q *= gamma;
            }
        }
        for (((ai, s), y), &r) in a.iter().zip(&self.s).zip(&self.y).zip(&self.rho) {
            let b = r * dot(y, dir);
            for (q, &sv) in dir.iter_mut().zip(s) {
                *q += (ai - b) * sv;
            }
        }
        for q in dir.iter_mut() {
            *q = -*q;
        }
    }
}
