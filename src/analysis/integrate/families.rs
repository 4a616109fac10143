//! Random integrand families with exact integrals over `[0, 1]^d`, for comparing samplers
//! on thousands of integrands at once (the integration benchmark of graphics papers: random
//! Gaussians, Heavisides and Blinn–Phong lobes; [`benchmark`](super::benchmark) runs them).
//!
//! | family | `f(x)` | exact integral | dimensions |
//! |---|---|---|---|
//! | [`Family::Gaussian`] | `exp(-sum_k (x_k - c_k)^2 / (2 s_k^2))`, `c_k ~ U(0, 1)`, `s_k ~ U(0.05, 0.5)` (an anisotropic Gaussian, axis-aligned, clipped to the cube) | `prod_k s_k sqrt(pi / 2) (erf((1 - c_k) / (s_k sqrt 2)) + erf(c_k / (s_k sqrt 2)))` | any |
//! | [`Family::RotatedGaussian`] | `exp(-(1/2) (x - c)^T P (x - c))`, `P = R_theta diag(1/s_1^2, 1/s_2^2) R_theta^T`: the same centres and widths, the axes rotated by `theta ~ U(0, pi)` (a full covariance) | no closed form: the inner integral in closed form (`erf`), the outer by adaptive Gauss–Legendre to `1e-13` absolute ([`super::rotated`]) | 2 |
//! | [`Family::GaussianMixture`] | `sum_(j<4) w_j g_j(x)`, four such Gaussians with weights `w_j ~ U(0, 1)` normalized to sum 1 | the weighted sum of the four | any |
//! | [`Family::BlinnPhong`] | `prod_j max(0, w(x_(2j), x_(2j+1)) . h_j)^(n_j)`: Blinn–Phong lobes on the sphere, `w(u, v) = (sqrt(1 - z^2) cos 2 pi v, sqrt(1 - z^2) sin 2 pi v, z)` with `z = 1 - 2u` (Archimedes' area-preserving map), lobe axes `h_j` uniform on the sphere, exponents `n_j` in `1..=32`; an odd last coordinate is a lobe on the circle, `max(0, cos(2 pi x - t))^n` | `prod_j 1 / (2 (n_j + 1))` (the map keeps area, and `int_(S^2) max(0, w . h)^n dw = 2 pi / (n + 1)` for every axis `h`); the circle's factor `W_n / (2 pi)`, Wallis' `W_n = int_(-pi/2)^(pi/2) cos^n t dt` | any |
//! | [`Family::Heaviside`] | `1` where `w . x >= w . p`, else `0`: a random hyperplane through a random point `p` (`w_k = +-k_k / 64`, `k_k` in `13..=64`, random signs; `p_k = j_k / 16`, `j_k` in `1..=15`) | the cube's volume on that side, exactly: after reflecting the coordinates with `w_k < 0`, `vol{a . y <= t} = (1 / (d! prod a_k)) sum_(v in {0,1}^d) (-1)^|v| (t - a . v)_+^d` (the inclusion-exclusion formula for a simplex cut by the cube; Barrow & Smith 1979), summed in `i128` integers and divided once | 1 to 8 |
//!
//! The Heaviside's normal and point sit on grids so that its integral is an exact rational
//! (`i128` holds every term up to `d = 8`); its orientations stay away from the axes
//! (`|w_k| >= 13/64`), so no edge is aligned with a sampler's strata. The Gaussian's
//! integral is exact up to `libm`'s `erf` (a few ulps). Each integrand is drawn from a
//! seed by a counter-based hash ([`crate::hash::hash3`]): `draw(family, d, seed)` is the same
//! integrand everywhere.
//!
//! Cost: drawing O(d) (Heaviside: O(2^d d) for its integral); evaluating O(d) (mixture:
//! 4 d; lobes: a `pow` and three trigonometric functions a pair).

use std::vec::Vec;

use crate::error::{Error, Result};
use crate::hash::hash3;

use super::rotated::RotatedGaussian;

/// The largest dimension of [`Family::Heaviside`] (exact in `i128`).
pub const HEAVISIDE_MAX_DIMS: usize = 8;

/// The largest dimension of the Gaussian families (a point of the benchmark is held in
/// memory; the product of `d` factors stays representable far beyond this).
pub const GAUSSIAN_MAX_DIMS: usize = 1 << 16;

/// The dimension of [`Family::RotatedGaussian`] (its reference integral is a 1D
/// quadrature of a closed-form inner integral).
pub const ROTATED_DIMS: usize = 2;

/// A random integrand family (see the module's table).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// Anisotropic axis-aligned Gaussians with random centres and widths.
    Gaussian,
    /// Mixtures of four such Gaussians.
    GaussianMixture,
    /// Anisotropic Gaussians with rotated axes (a full covariance), 2D.
    RotatedGaussian,
    /// Indicators of half-spaces cut by random hyperplanes.
    Heaviside,
    /// Products of Blinn–Phong lobes on the sphere (coordinate pairs mapped to directions).
    BlinnPhong,
}

impl Family {
    /// Every family, in the order of the module's table.
    pub const ALL: [Family; 5] = [
        Family::Gaussian,
        Family::GaussianMixture,
        Family::RotatedGaussian,
        Family::Heaviside,
        Family::BlinnPhong,
    ];

    /// The family's name: `gaussian`, `gaussian-mixture`, `rotated-gaussian`, `heaviside`,
    /// `blinn-phong`.
    pub const fn name(self) -> &'static str {
        match self {
            Family::Gaussian => "gaussian",
            Family::GaussianMixture => "gaussian-mixture",
            Family::RotatedGaussian => "rotated-gaussian",
            Family::Heaviside => "heaviside",
            Family::BlinnPhong => "blinn-phong",
        }
    }

    /// The family named `name` (its [`name`](Self::name)).
    pub fn from_name(name: &str) -> Option<Family> {
        Family::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The largest dimension it takes.
    pub const fn max_dims(self) -> usize {
        match self {
            Family::Heaviside => HEAVISIDE_MAX_DIMS,
            Family::RotatedGaussian => ROTATED_DIMS,
            _ => GAUSSIAN_MAX_DIMS,
        }
    }
}

/// One axis-aligned Gaussian: centre, `1 / (2 s^2)` per axis, its integral.
#[derive(Clone, Debug, PartialEq)]
struct Gaussian {
    centre: Vec<f64>,
    scale: Vec<f64>,
    integral: f64,
}

impl Gaussian {
    /// Draws the Gaussian of `seed` (stream `j`) in `d` dimensions.
    fn draw(d: usize, seed: u64, j: u64) -> Gaussian {
        let mut centre = Vec::with_capacity(d);
        let mut scale = Vec::with_capacity(d);
        let mut integral = 1.0;
        for k in 0..d as u64 {
            let c = unit(hash3(seed, 2 * (j * GAUSSIAN_MAX_DIMS as u64 + k), 1));
            let s = 0.05 + 0.45 * unit(hash3(seed, 2 * (j * GAUSSIAN_MAX_DIMS as u64 + k) + 1, 1));
            let r = 1.0 / (s * core::f64::consts::SQRT_2);
            integral *= s
                * (core::f64::consts::PI / 2.0).sqrt()
                * (libm::erf((1.0 - c) * r) + libm::erf(c * r));
            centre.push(c);
            scale.push(r * r);
        }
        Gaussian {
            centre,
            scale,
            integral,
        }
    }

    fn eval(&self, x: &[f64]) -> f64 {
        let e: f64 = x
            .iter()
            .zip(&self.centre)
            .zip(&self.scale)
            .map(|((x, c), s)| (x - c) * (x - c) * s)
            .sum();
        (-e).exp()
    }
}

/// A uniform double in `[0, 1)` from the top 53 bits of a hash.
pub(super) fn unit(h: u64) -> f64 {
    (h >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// A drawn integrand of a [`Family`]: `f` and its exact integral.
#[derive(Clone, Debug, PartialEq)]
pub struct RandomIntegrand {
    kind: Kind,
    dims: usize,
    integral: f64,
}

#[derive(Clone, Debug, PartialEq)]
enum Kind {
    Mixture(Vec<(f64, Gaussian)>),
    Rotated(RotatedGaussian),
    /// `sum_k w_k x_k >= b`, `w_k = m_k / 64`, `b` as a float (the test) and the exact
    /// integral computed from the integers.
    Heaviside {
        w: Vec<f64>,
        b: f64,
    },
    /// Lobes on the sphere (axis, exponent), then at most one on the circle (angle,
    /// exponent).
    Lobes {
        sphere: Vec<([f64; 3], i32)>,
        circle: Option<(f64, i32)>,
    },
}

impl RandomIntegrand {
    /// The integrand of `family` in `d` dimensions drawn from `seed`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for `d = 0` or `d` past the family's
    /// [`max_dims`](Family::max_dims); for the rotated Gaussians `d` other than 2, or a
    /// reference quadrature that misses its tolerance.
    ///
    /// ```
    /// use qmckit::analysis::integrate::{Family, RandomIntegrand};
    /// let f = RandomIntegrand::draw(Family::Heaviside, 2, 7)?;
    /// assert!(f.exact() > 0.0 && f.exact() < 1.0);
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn draw(family: Family, d: usize, seed: u64) -> Result<RandomIntegrand> {
        if d == 0 || d > family.max_dims() {
            return Err(Error::InvalidParameter {
                what: "random integrand: dimensions out of the family's range (1..=8 for \
                       heaviside, 1..=65536 for the Gaussians)",
            });
        }
        if family == Family::RotatedGaussian && d != ROTATED_DIMS {
            return Err(Error::InvalidParameter {
                what: "random integrand: the rotated Gaussians are 2D",
            });
        }
        let (kind, integral) = match family {
            Family::Gaussian => {
                let g = Gaussian::draw(d, seed, 0);
                let i = g.integral;
                (Kind::Mixture(vec![(1.0, g)]), i)
            }
            Family::GaussianMixture => {
                let w: Vec<f64> = (0..4).map(|j| 0.05 + unit(hash3(seed, j, 2))).collect();
                let total: f64 = w.iter().sum();
                let parts: Vec<(f64, Gaussian)> = w
                    .iter()
                    .enumerate()
                    .map(|(j, &wj)| (wj / total, Gaussian::draw(d, seed, j as u64 + 1)))
                    .collect();
                let i = parts.iter().map(|(w, g)| w * g.integral).sum();
                (Kind::Mixture(parts), i)
            }
            Family::RotatedGaussian => {
                let g = RotatedGaussian::draw(seed)?;
                let i = g.integral();
                (Kind::Rotated(g), i)
            }
            Family::Heaviside => heaviside(d, seed),
            Family::BlinnPhong => lobes(d, seed),
        };
        Ok(RandomIntegrand {
            kind,
            dims: d,
            integral,
        })
    }

    /// Its dimensions.
    pub fn dims(&self) -> usize {
        self.dims
    }

    /// `f(x)` for `x` of [`dims`](Self::dims) coordinates in `[0, 1]`.
    pub fn eval(&self, x: &[f64]) -> f64 {
        match &self.kind {
            Kind::Mixture(parts) => parts.iter().map(|(w, g)| w * g.eval(x)).sum(),
            Kind::Rotated(g) => g.eval(x),
            Kind::Heaviside { w, b } => {
                let s: f64 = w.iter().zip(x).map(|(w, x)| w * x).sum();
                if s >= *b { 1.0 } else { 0.0 }
            }
            Kind::Lobes { sphere, circle } => {
                let mut f = 1.0;
                for (pair, (h, n)) in x.chunks_exact(2).zip(sphere) {
                    let w = sphere_direction(pair[0], pair[1]);
                    let c = w[0] * h[0] + w[1] * h[1] + w[2] * h[2];
                    f *= libm::pow(c.max(0.0), f64::from(*n));
                }
                if let (Some((t, n)), Some(&u)) = (circle, x.get(2 * sphere.len())) {
                    let c = libm::cos(core::f64::consts::TAU * u - t);
                    f *= libm::pow(c.max(0.0), f64::from(*n));
                }
                f
            }
        }
    }

    /// The exact integral over `[0, 1]^d` (the rotated Gaussians: the reference
    /// quadrature's, within [`error_bound`](Self::error_bound)).
    pub fn exact(&self) -> f64 {
        self.integral
    }

    /// A bound on the error of [`exact`](Self::exact): 0 for the closed forms (up to
    /// rounding), the quadrature's estimate (at most `1e-13`) for the rotated Gaussians.
    pub fn error_bound(&self) -> f64 {
        match &self.kind {
            Kind::Rotated(g) => g.error_bound(),
            _ => 0.0,
        }
    }
}

/// The direction of `(u, v)` under Archimedes' map: `z = 1 - 2u`, azimuth `2 pi v`.
fn sphere_direction(u: f64, v: f64) -> [f64; 3] {
    let z = 1.0 - 2.0 * u;
    let r = libm::sqrt((1.0 - z * z).max(0.0));
    let phi = core::f64::consts::TAU * v;
    [r * libm::cos(phi), r * libm::sin(phi), z]
}

/// `int_(-pi/2)^(pi/2) cos^n t dt` (Wallis): `pi (n-1)!! / n!!` for even `n`,
/// `2 (n-1)!! / n!!` for odd `n`.
fn wallis(n: i32) -> f64 {
    let mut w = if n % 2 == 0 {
        core::f64::consts::PI
    } else {
        2.0
    };
    let mut k = n;
    while k >= 2 {
        w *= f64::from(k - 1) / f64::from(k);
        k -= 2;
    }
    w
}

/// The Blinn–Phong lobes of `seed` in `d` dimensions and their exact integral (see the
/// module's table).
fn lobes(d: usize, seed: u64) -> (Kind, f64) {
    let mut sphere = Vec::with_capacity(d / 2);
    let mut integral = 1.0;
    for j in 0..(d / 2) as u64 {
        // An axis uniform on the sphere (the same area-preserving map) and an exponent.
        let h = sphere_direction(unit(hash3(seed, j, 4)), unit(hash3(seed, j, 5)));
        let n = 1 + (hash3(seed, j, 6) % 32) as i32;
        integral *= 1.0 / (2.0 * f64::from(n + 1));
        sphere.push((h, n));
    }
    let circle = (d % 2 == 1).then(|| {
        let j = (d / 2) as u64;
        let t = core::f64::consts::TAU * unit(hash3(seed, j, 4));
        let n = 1 + (hash3(seed, j, 6) % 32) as i32;
        integral *= wallis(n) / core::f64::consts::TAU;
        (t, n)
    });
    (Kind::Lobes { sphere, circle }, integral)
}

/// The Heaviside of `seed`: its test and its exact integral (see the module's table).
fn heaviside(d: usize, seed: u64) -> (Kind, f64) {
    let mut m = Vec::with_capacity(d); // w_k = m_k / 64
    let mut j = Vec::with_capacity(d); // p_k = j_k / 16
    for k in 0..d as u64 {
        let h = hash3(seed, k, 3);
        let mag = 13 + (h % 52) as i128; // 13..=64
        let sign = if (h >> 32) & 1 == 1 { -1 } else { 1 };
        m.push(sign * mag);
        j.push(1 + ((h >> 40) % 15) as i128); // 1..=15
    }
    // In units of 1/1024 (= 1/64 * 1/16): b = sum m_k j_k.
    let b: i128 = m.iter().zip(&j).map(|(m, j)| m * j).sum();
    let below = volume_below(&m, b);
    let w: Vec<f64> = m.iter().map(|&m| m as f64 / 64.0).collect();
    let bf = b as f64 / 1024.0; // exact: integers below 2^53 over a power of two
    (Kind::Heaviside { w, b: bf }, 1.0 - below)
}

/// The volume of `{x in [0, 1]^d : sum_k m_k x_k / 64 < b / 1024}` for nonzero `m_k` (at
/// most 64 in magnitude, `d <= 8`): exact integers, one rounding per operand of the last
/// division.
fn volume_below(m: &[i128], b: i128) -> f64 {
    let d = m.len();
    // Reflect y_k = 1 - x_k where m_k < 0: sum m_k x_k = sum |m_k| y_k - sum_(m_k<0) |m_k|,
    // so the side is {a . y < t}, in units of 1/1024: a_k = 16 |m_k|, t = b + 16 neg.
    let neg: i128 = m.iter().filter(|&&m| m < 0).map(|m| -m).sum();
    let t = b + 16 * neg;
    let a: Vec<i128> = m.iter().map(|m| 16 * m.abs()).collect();
    // vol{a . y <= t} = sum_v (-1)^|v| (t - a.v)_+^d / (d! prod a_k).
    let mut sum: i128 = 0;
    for v in 0u32..(1 << d) {
        let av: i128 = (0..d).filter(|&k| v >> k & 1 == 1).map(|k| a[k]).sum();
        let r = t - av;
        if r > 0 {
            let term = r.pow(d as u32);
            sum += if v.count_ones() % 2 == 0 { term } else { -term };
        }
    }
    let den: i128 = (1..=d as i128).product::<i128>() * a.iter().product::<i128>();
    sum as f64 / den as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A midpoint rule on a fine grid agrees with the exact integrals in 1D and 2D (a
    /// Heaviside's midpoint error is the boundary's length times the cell, 1/4096 here).
    #[test]
    fn exact_integrals_match_a_fine_midpoint_rule() {
        for family in Family::ALL {
            for seed in 0..20 {
                for d in [1usize, 2] {
                    if family == Family::RotatedGaussian && d != 2 {
                        continue;
                    }
                    let f = RandomIntegrand::draw(family, d, seed).unwrap();
                    let k = if d == 1 { 1 << 16 } else { 1 << 11 };
                    let mut sum = 0.0;
                    let cells = (k as u64).pow(d as u32);
                    for c in 0..cells {
                        let x: Vec<f64> = (0..d)
                            .map(|a| ((c / (k as u64).pow(a as u32)) % k as u64) as f64 + 0.5)
                            .map(|i| i / k as f64)
                            .collect();
                        sum += f.eval(&x);
                    }
                    let mid = sum / cells as f64;
                    let tol = match family {
                        Family::Heaviside => 4.0 / k as f64,
                        // Exponents to 32: a narrow peak and a kink at the terminator.
                        Family::BlinnPhong => 2e-6,
                        _ => 1e-6,
                    };
                    assert!(
                        (mid - f.exact()).abs() < tol,
                        "{family:?} d={d} seed={seed}: {mid} vs {}",
                        f.exact()
                    );
                }
            }
        }
    }

    /// Every plane through the centre halves the cube (the map x -> 1 - x swaps its
    /// sides), whatever its normal; and `x_1 + ... + x_d < 1` is the simplex, `1/d!`.
    #[test]
    fn known_volumes() {
        for seed in 0..200u64 {
            for d in 1..=HEAVISIDE_MAX_DIMS {
                let m: Vec<i128> = (0..d as u64)
                    .map(|k| {
                        let h = hash3(seed, k, 3);
                        let sign = if (h >> 32) & 1 == 1 { -1 } else { 1 };
                        sign * (13 + (h % 52) as i128)
                    })
                    .collect();
                let b: i128 = m.iter().map(|m| m * 8).sum(); // p = (1/2, ..., 1/2)
                let v = volume_below(&m, b);
                assert!((v - 0.5).abs() < 1e-15, "d={d} seed={seed}: {v}");
            }
        }
        for d in 1..=HEAVISIDE_MAX_DIMS {
            let v = volume_below(&vec![64; d], 1024);
            let simplex = 1.0 / (1..=d).product::<usize>() as f64;
            assert!(
                (v - simplex).abs() < 1e-15 * simplex.max(1e-3),
                "d={d}: {v}"
            );
        }
    }

    /// A Monte Carlo check in 5 to 8 dimensions, where a grid is too coarse: 2^20 Sobol'
    /// points agree with the exact volume within 5e-3 (the Heaviside's QMC error at this N
    /// is far smaller).
    #[test]
    fn heaviside_volumes_agree_with_many_points_in_high_dimensions() {
        use crate::Sobol;
        for d in 5..=HEAVISIDE_MAX_DIMS {
            let s = Sobol::new(d).unwrap();
            let mut buf = vec![0f64; d];
            for seed in 0..4 {
                let f = RandomIntegrand::draw(Family::Heaviside, d, seed).unwrap();
                let n = 1u32 << 18;
                let mut sum = 0.0;
                for i in 0..n {
                    for (k, x) in buf.iter_mut().enumerate() {
                        *x = crate::bits::to_f64(s.sample(i, k).unwrap());
                    }
                    sum += f.eval(&buf);
                }
                let est = sum / n as f64;
                assert!(
                    (est - f.exact()).abs() < 5e-3,
                    "d={d}: {est} vs {}",
                    f.exact()
                );
            }
        }
    }

    /// Wallis' integrals against their textbook values, and a lobe pointing at the pole
    /// against `int_0^1 t^n dt / 2` computed in closed form.
    #[test]
    fn wallis_and_the_polar_lobe() {
        use core::f64::consts::PI;
        for (n, w) in [
            (0, PI),
            (1, 2.0),
            (2, PI / 2.0),
            (3, 4.0 / 3.0),
            (4, 3.0 * PI / 8.0),
        ] {
            assert!((wallis(n) - w).abs() < 1e-15, "n={n}");
        }
        // With h = (0, 0, 1), f(u, v) = max(0, 1 - 2u)^n: int_0^(1/2) (1 - 2u)^n du.
        for n in [1, 5, 32] {
            let k = 1 << 16;
            let mid: f64 = (0..k)
                .map(|i| (i as f64 + 0.5) / k as f64)
                .map(|u| {
                    let w = sphere_direction(u, 0.3);
                    libm::pow(w[2].max(0.0), f64::from(n))
                })
                .sum::<f64>()
                / k as f64;
            assert!(
                (mid - 1.0 / (2.0 * f64::from(n + 1))).abs() < 1e-8,
                "n={n}: {mid}"
            );
        }
    }

    #[test]
    fn bad_dimensions_are_refused() {
        assert!(RandomIntegrand::draw(Family::Heaviside, 9, 0).is_err());
        assert!(RandomIntegrand::draw(Family::Gaussian, 0, 0).is_err());
        assert!(RandomIntegrand::draw(Family::BlinnPhong, 0, 0).is_err());
        assert!(RandomIntegrand::draw(Family::RotatedGaussian, 1, 0).is_err());
        assert!(RandomIntegrand::draw(Family::RotatedGaussian, 3, 0).is_err());
    }
}
