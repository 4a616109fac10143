//! Test integrands on `[0, 1]^d` with closed-form integrals: Genz's six families (Genz
//! 1984), Keister's (1996), and a European and a geometric-average Asian call under
//! Black–Scholes with the Brownian-bridge construction (Glasserman 2004, 3.1 and 3.2).

use core::f64::consts::PI;

/// Genz's families: `a` the difficulty, `u` the location parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GenzFamily {
    /// `cos(2 pi u_1 + sum a_k x_k)`; `I = Re(e^(2 pi i u_1) prod (e^(i a_k) - 1)/(i a_k))`.
    Oscillatory,
    /// `prod 1/(a_k^-2 + (x_k - u_k)^2)`; `I = prod a_k (atan(a_k (1 - u_k)) + atan(a_k u_k))`.
    ProductPeak,
    /// `(1 + sum a_k x_k)^-(d+1)`; `I = (1/(d! prod a_k)) sum_(v in {0,1}^d) (-1)^|v| / (1 + a.v)`.
    CornerPeak,
    /// `exp(-sum a_k^2 (x_k - u_k)^2)`; `I = prod sqrt(pi)/(2 a_k) (erf(a_k (1-u_k)) + erf(a_k u_k))`.
    Gaussian,
    /// `exp(-sum a_k |x_k - u_k|)`; `I = prod (2 - e^(-a_k u_k) - e^(-a_k (1-u_k))) / a_k`.
    Continuous,
    /// `exp(sum a_k x_k)` where `x_1 <= u_1` and `x_2 <= u_2`, else 0;
    /// `I = prod (e^(a_k c_k) - 1)/a_k`, `c_k = u_k` for `k <= 2`, else 1.
    Discontinuous,
}

/// What a [`Problem`] computes.
#[derive(Clone, Debug, PartialEq)]
pub enum ProblemKind {
    /// A Genz family with its parameters.
    Genz {
        /// The family.
        family: GenzFamily,
        /// Difficulty `a_k`.
        a: Vec<f64>,
        /// Location `u_k`.
        u: Vec<f64>,
    },
    /// Keister's `int_(R^d) cos(|x|) e^(-|x|^2) dx = pi^(d/2) E cos(|Z| / sqrt 2)`,
    /// `x = Phi^-1(u) / sqrt 2`.
    Keister,
    /// A European call `e^(-rT) max(S_T - K, 0)`, `S` geometric Brownian motion sampled at
    /// `d` dates by the Brownian bridge (the first coordinate sets `W_T`).
    European(Market),
    /// A geometric-average Asian call `e^(-rT) max(G - K, 0)`,
    /// `G = (prod_(j=1..d) S_(jT/d))^(1/d)`, by the Brownian bridge.
    AsianGeometric(Market),
}

/// Black–Scholes market and contract.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Market {
    /// Spot `S_0`.
    pub spot: f64,
    /// Strike `K`.
    pub strike: f64,
    /// Rate `r`.
    pub rate: f64,
    /// Volatility `sigma`.
    pub vol: f64,
    /// Maturity `T`.
    pub maturity: f64,
}

/// An integrand on `[0, 1]^dims` with its exact integral.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    /// A short name (`genz-oscillatory-d5`).
    pub name: String,
    /// Dimensions.
    pub dims: usize,
    /// The integrand.
    pub kind: ProblemKind,
}

/// `erf` through libm.
fn erf(x: f64) -> f64 {
    libm::erf(x)
}

/// `Phi(x)`.
fn normal_cdf(x: f64) -> f64 {
    0.5 * libm::erfc(-x / core::f64::consts::SQRT_2)
}

/// `Phi^-1(p)`, `0 < p < 1`: the `f32` quantile of [`crate::warp::gaussian`] refined by two
/// Halley steps in `f64` (full double precision).
pub fn normal_quantile(p: f64) -> f64 {
    if p > 0.5 {
        // Symmetry keeps the f32 start away from 1 (where it would round to 1.0).
        return -normal_quantile(1.0 - p);
    }
    let mut x = f64::from(crate::warp::gaussian::sample_normal(p as f32));
    for _ in 0..2 {
        let e = normal_cdf(x) - p;
        let u = e * (2.0 * PI).sqrt() * (x * x / 2.0).exp();
        x -= u / (1.0 + x * u / 2.0);
    }
    x
}

impl Problem {
    /// `f(x)`; `x` has `dims` coordinates in `(0, 1)`.
    pub fn eval(&self, x: &[f64]) -> f64 {
        match &self.kind {
            ProblemKind::Genz { family, a, u } => genz(*family, a, u, x),
            ProblemKind::Keister => {
                let r2: f64 = x
                    .iter()
                    .map(|&p| {
                        let z = normal_quantile(p);
                        z * z / 2.0
                    })
                    .sum();
                PI.powf(self.dims as f64 / 2.0) * r2.sqrt().cos()
            }
            ProblemKind::European(o) => {
                let w = bridge_end(x, o.maturity);
                let s = o.spot * ((o.rate - o.vol * o.vol / 2.0) * o.maturity + o.vol * w).exp();
                (-o.rate * o.maturity).exp() * (s - o.strike).max(0.0)
            }
            ProblemKind::AsianGeometric(o) => {
                let d = x.len();
                let mut w = vec![0f64; d];
                bridge(x, o.maturity, &mut w);
                let mean_w = w.iter().sum::<f64>() / d as f64;
                let mean_t = o.maturity * (d as f64 + 1.0) / (2.0 * d as f64);
                let g = o.spot * ((o.rate - o.vol * o.vol / 2.0) * mean_t + o.vol * mean_w).exp();
                (-o.rate * o.maturity).exp() * (g - o.strike).max(0.0)
            }
        }
    }

    /// The exact integral.
    pub fn exact(&self) -> f64 {
        match &self.kind {
            ProblemKind::Genz { family, a, u } => genz_exact(*family, a, u),
            ProblemKind::Keister => keister_exact(self.dims),
            ProblemKind::European(o) => {
                let v = o.vol * o.maturity.sqrt();
                let d1 =
                    ((o.spot / o.strike).ln() + (o.rate + o.vol * o.vol / 2.0) * o.maturity) / v;
                o.spot * normal_cdf(d1)
                    - o.strike * (-o.rate * o.maturity).exp() * normal_cdf(d1 - v)
            }
            ProblemKind::AsianGeometric(o) => {
                let d = self.dims as f64;
                let mean_t = o.maturity * (d + 1.0) / (2.0 * d);
                // Var(mean W) = (1/d^2) sum_(i,j) min(t_i, t_j) = T (d+1)(2d+1) / (6 d^2).
                let var = o.vol * o.vol * o.maturity * (d + 1.0) * (2.0 * d + 1.0) / (6.0 * d * d);
                let mu = o.spot.ln() + (o.rate - o.vol * o.vol / 2.0) * mean_t;
                let d2 = (mu - o.strike.ln()) / var.sqrt();
                (-o.rate * o.maturity).exp()
                    * ((mu + var / 2.0).exp() * normal_cdf(d2 + var.sqrt())
                        - o.strike * normal_cdf(d2))
            }
        }
    }
}

fn genz(family: GenzFamily, a: &[f64], u: &[f64], x: &[f64]) -> f64 {
    let terms = a.iter().zip(u).zip(x);
    match family {
        GenzFamily::Oscillatory => {
            let s: f64 = a.iter().zip(x).map(|(a, x)| a * x).sum();
            (2.0 * PI * u.first().copied().unwrap_or(0.0) + s).cos()
        }
        GenzFamily::ProductPeak => terms
            .map(|((a, u), x)| 1.0 / (1.0 / (a * a) + (x - u) * (x - u)))
            .product(),
        GenzFamily::CornerPeak => {
            let s: f64 = a.iter().zip(x).map(|(a, x)| a * x).sum();
            (1.0 + s).powi(-(a.len() as i32 + 1))
        }
        GenzFamily::Gaussian => terms
            .map(|((a, u), x)| -(a * a) * (x - u) * (x - u))
            .sum::<f64>()
            .exp(),
        GenzFamily::Continuous => terms
            .map(|((a, u), x)| -a * (x - u).abs())
            .sum::<f64>()
            .exp(),
        GenzFamily::Discontinuous => {
            let inside = x.iter().zip(u).take(2).all(|(x, u)| x <= u);
            if inside {
                a.iter().zip(x).map(|(a, x)| a * x).sum::<f64>().exp()
            } else {
                0.0
            }
        }
    }
}

fn genz_exact(family: GenzFamily, a: &[f64], u: &[f64]) -> f64 {
    let pairs = a.iter().zip(u);
    match family {
        GenzFamily::Oscillatory => {
            // prod (e^(i a) - 1)/(i a) = prod (sin a + i (1 - cos a)) / a, times e^(2 pi i u_1).
            let (mut re, mut im) = ((2.0 * PI * u.first().copied().unwrap_or(0.0)).cos(), 0.0);
            im += (2.0 * PI * u.first().copied().unwrap_or(0.0)).sin();
            for &ak in a {
                let (zr, zi) = (ak.sin() / ak, (1.0 - ak.cos()) / ak);
                (re, im) = (re * zr - im * zi, re * zi + im * zr);
            }
            re
        }
        GenzFamily::ProductPeak => pairs
            .map(|(a, u)| a * ((a * (1.0 - u)).atan() + (a * u).atan()))
            .product(),
        GenzFamily::CornerPeak => {
            let d = a.len();
            let mut sum = 0.0;
            for v in 0u64..1 << d {
                let dot: f64 = a
                    .iter()
                    .enumerate()
                    .filter(|(k, _)| v >> k & 1 == 1)
                    .map(|(_, a)| a)
                    .sum();
                let sign = if v.count_ones() % 2 == 0 { 1.0 } else { -1.0 };
                sum += sign / (1.0 + dot);
            }
            let fact: f64 = (1..=d).map(|k| k as f64).product();
            sum / (fact * a.iter().product::<f64>())
        }
        GenzFamily::Gaussian => pairs
            .map(|(a, u)| PI.sqrt() / (2.0 * a) * (erf(a * (1.0 - u)) + erf(a * u)))
            .product(),
        GenzFamily::Continuous => pairs
            .map(|(a, u)| (2.0 - (-a * u).exp() - (-a * (1.0 - u)).exp()) / a)
            .product(),
        GenzFamily::Discontinuous => pairs
            .enumerate()
            .map(|(k, (a, u))| {
                let c = if k < 2 { *u } else { 1.0 };
                ((a * c).exp() - 1.0) / a
            })
            .product(),
    }
}

/// `pi^(d/2) E cos(R / sqrt 2)`, `R` chi with `d` degrees of freedom: the radial integral
/// `int_0^inf cos(r / sqrt 2) r^(d-1) e^(-r^2/2) dr / (2^(d/2-1) Gamma(d/2))` by composite
/// Simpson on `[0, 40]` with 40000 intervals (error far below 1e-12 for `d <= 40`).
fn keister_exact(d: usize) -> f64 {
    let k = d as f64;
    let norm = 2f64.powf(k / 2.0 - 1.0) * libm::tgamma(k / 2.0);
    let steps = 40_000;
    let h = 40.0 / steps as f64;
    let g = |r: f64| {
        (r / core::f64::consts::SQRT_2).cos() * r.powi(d as i32 - 1) * (-r * r / 2.0).exp()
    };
    let mut s = g(0.0) + g(40.0);
    for i in 1..steps {
        s += g(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    PI.powf(k / 2.0) * s * h / 3.0 / norm
}

/// `W_T` of the Brownian bridge: `sqrt(T) Phi^-1(x_0)`.
fn bridge_end(x: &[f64], t: f64) -> f64 {
    t.sqrt() * normal_quantile(x.first().copied().unwrap_or(0.5))
}

/// The Brownian bridge: `w[j] = W((j+1) T / d)` from `x` (`d` coordinates in `(0, 1)`),
/// `W_T` from `x_0`, then midpoints by bisection of the index range, each from the next
/// coordinate: `W_m = ((t_r - t_m) W_l + (t_m - t_l) W_r) / (t_r - t_l) + sd Z`,
/// `sd^2 = (t_m - t_l)(t_r - t_m)/(t_r - t_l)`.
fn bridge(x: &[f64], t: f64, w: &mut [f64]) {
    let d = w.len();
    if d == 0 {
        return;
    }
    let dt = t / d as f64;
    if let Some(last) = w.last_mut() {
        *last = bridge_end(x, t);
    }
    // Intervals (l, r) of date indices 0..=d (date 0 at time 0, W = 0), breadth first.
    let mut queue = std::collections::VecDeque::from([(0usize, d)]);
    let mut next = 1;
    while let Some((l, r)) = queue.pop_front() {
        if r - l < 2 {
            continue;
        }
        let m = (l + r) / 2;
        let (tl, tm, tr) = (l as f64 * dt, m as f64 * dt, r as f64 * dt);
        let wl = if l == 0 {
            0.0
        } else {
            w.get(l - 1).copied().unwrap_or(0.0)
        };
        let wr = w.get(r - 1).copied().unwrap_or(0.0);
        let sd = ((tm - tl) * (tr - tm) / (tr - tl)).sqrt();
        let z = normal_quantile(x.get(next).copied().unwrap_or(0.5));
        next += 1;
        if let Some(slot) = w.get_mut(m - 1) {
            *slot = ((tr - tm) * wl + (tm - tl) * wr) / (tr - tl) + sd * z;
        }
        queue.push_back((l, m));
        queue.push_back((m, r));
    }
}

/// The 20 test problems: the six Genz families in 2 and 5 dimensions (12), Keister in 2, 3,
/// 5 and 8 dimensions (4), and the European and geometric Asian calls (`S_0 = K = 100`,
/// `r = 0.05`, `sigma = 0.2`, `T = 1`) with 4 and 16 dates (4).
pub fn test_suite() -> Vec<Problem> {
    use GenzFamily as G;
    let mut v = Vec::new();
    let genz = |family: G, d: usize, scale: f64| {
        let a: Vec<f64> = (0..d)
            .map(|k| scale * (1.0 + k as f64) / d as f64)
            .collect();
        let u: Vec<f64> = (0..d)
            .map(|k| 0.2 + 0.6 * ((k as f64 * 0.618).fract()))
            .collect();
        ProblemKind::Genz { family, a, u }
    };
    for (family, name, scale) in [
        (G::Oscillatory, "oscillatory", 2.0),
        (G::ProductPeak, "product-peak", 4.0),
        (G::CornerPeak, "corner-peak", 1.0),
        (G::Gaussian, "gaussian", 3.0),
        (G::Continuous, "continuous", 2.0),
        (G::Discontinuous, "discontinuous", 1.0),
    ] {
        for d in [2usize, 5] {
            v.push(Problem {
                name: format!("genz-{name}-d{d}"),
                dims: d,
                kind: genz(family, d, scale),
            });
        }
    }
    for d in [2usize, 3, 5, 8] {
        v.push(Problem {
            name: format!("keister-d{d}"),
            dims: d,
            kind: ProblemKind::Keister,
        });
    }
    let o = Market {
        spot: 100.0,
        strike: 100.0,
        rate: 0.05,
        vol: 0.2,
        maturity: 1.0,
    };
    for d in [4usize, 16] {
        v.push(Problem {
            name: format!("european-d{d}"),
            dims: d,
            kind: ProblemKind::European(o),
        });
        v.push(Problem {
            name: format!("asian-geometric-d{d}"),
            dims: d,
            kind: ProblemKind::AsianGeometric(o),
        });
    }
    v
}
