//! `discrepancy(sample, method, iterative, workers)`: SciPy's four L2 discrepancies
//! (`scipy.stats.qmc.discrepancy`) computed by qmckit's analysis (compensated sums,
//! parallel pair sums).
//!
//! `iterative=True` is SciPy's convention for starting `update_discrepancy`: the formulas
//! with `n + 1` in place of `n` (the sums still over the `n` given points). qmckit
//! computes `D = C - (a / n) S1 + S2 / n^2`; the single sum `S1` is recomputed here
//! (compensated), `S2 = n^2 (D - C + a S1 / n)` recovered, and the formula re-evaluated
//! with `n + 1`.

use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use qmckit::analysis::Points;
use qmckit::analysis::l2;

use crate::error::{to_py, value_error};

#[derive(Clone, Copy)]
enum Method {
    Centered,
    WrapAround,
    Mixture,
    L2Star,
}

impl Method {
    fn parse(s: &str) -> Option<Method> {
        match s {
            "CD" => Some(Method::Centered),
            "WD" => Some(Method::WrapAround),
            "MD" => Some(Method::Mixture),
            "L2-star" => Some(Method::L2Star),
            _ => None,
        }
    }

    /// qmckit's value (squared for CD, WD, MD; the root for L2-star, as SciPy).
    fn eval(self, p: Points<'_>) -> qmckit::Result<f64> {
        match self {
            Method::Centered => l2::centered(p),
            Method::WrapAround => l2::wrap_around(p),
            Method::Mixture => l2::mixture(p),
            Method::L2Star => l2::l2_star(p),
        }
    }

    /// `(C, a, g)`: `D^2 = C - (a / n) sum_i prod_k g(x_ik) + S2 / n^2`.
    fn terms(self, d: i32) -> (f64, f64, fn(f64) -> f64) {
        match self {
            Method::Centered => ((13.0f64 / 12.0).powi(d), 2.0, |x| {
                let a = (x - 0.5).abs();
                1.0 + 0.5 * a - 0.5 * a * a
            }),
            Method::WrapAround => (-(4.0f64 / 3.0).powi(d), 0.0, |_| 0.0),
            Method::Mixture => ((19.0f64 / 12.0).powi(d), 2.0, |x| {
                let a = (x - 0.5).abs();
                5.0 / 3.0 - 0.25 * a - 0.25 * a * a
            }),
            Method::L2Star => (3.0f64.powi(-d), 2.0f64.powi(1 - d), |x| 1.0 - x * x),
        }
    }
}

/// Neumaier-compensated sum of `prod_k g(x_ik)` over the points.
fn single_sum(p: Points<'_>, g: fn(f64) -> f64) -> f64 {
    let (mut s, mut c) = (0.0f64, 0.0f64);
    for row in p.iter() {
        let v: f64 = row.iter().map(|&x| g(x)).product();
        let t = s + v;
        c += if s.abs() >= v.abs() {
            (s - t) + v
        } else {
            (v - t) + s
        };
        s = t;
    }
    s + c
}

fn compute(method: Method, p: Points<'_>, iterative: bool) -> qmckit::Result<f64> {
    let value = method.eval(p)?;
    if !iterative {
        return Ok(value);
    }
    let n = p.len() as f64;
    let squared = match method {
        Method::L2Star => value * value,
        _ => value,
    };
    let (c, a, g) = method.terms(p.dims() as i32);
    let s1 = if a == 0.0 { 0.0 } else { single_sum(p, g) };
    let s2_over_n2 = squared - c + a * s1 / n;
    let m = n + 1.0;
    let it = c - a * s1 / m + s2_over_n2 * (n / m) * (n / m);
    Ok(match method {
        Method::L2Star => it.max(0.0).sqrt(),
        _ => it,
    })
}

/// SciPy's `discrepancy` on a C-contiguous `(n, d)` float64 array in `[0, 1]`.
#[pyfunction]
#[pyo3(signature = (sample, method = "CD", iterative = false, workers = 1))]
pub fn discrepancy(
    py: Python<'_>,
    sample: PyReadonlyArray2<'_, f64>,
    method: &str,
    iterative: bool,
    workers: usize,
) -> PyResult<f64> {
    let m = Method::parse(method).ok_or_else(|| {
        value_error(format!(
            "{method:?} is not a valid method. It must be one of {{'CD', 'WD', 'MD', 'L2-star'}}"
        ))
    })?;
    let d = sample.shape().get(1).copied().unwrap_or(0);
    let data = sample
        .as_slice()
        .map_err(|_| value_error("sample must be C-contiguous"))?;
    let p = Points::new(data, d).map_err(to_py)?;
    let workers = workers.max(1);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(workers)
        .build()
        .map_err(|e| value_error(format!("cannot start {workers} threads: {e}")))?;
    py.detach(|| pool.install(|| compute(m, p, iterative)))
        .map_err(to_py)
}
