//! The standard normal distribution: Box–Muller pairs and the inverse CDF, for users outside
//! graphics (option pricing, Brownian paths, Gaussian-process sampling).

use super::{PI, turn_fraction};

/// Smallest probability used by the maps: `u = 0` stands for the middle of the first 0.32
/// cell, `2^-33`, so that no output is infinite.
const P_MIN: f64 = 1.0 / 8_589_934_592.0;

/// A pair of independent standard normals from `u` (Box & Muller 1958):
/// `r = sqrt(-2 ln(1 - u0))`, `theta = 2 pi u1`, `(r cos theta, r sin theta)`. Finite for every
/// `u` in `[0, 1)`: `u0 = 0` gives `r = 0`, and the largest `u0` below 1 gives `r = 5.8`.
///
/// ```
/// use qmckit::warp::gaussian::{invert_box_muller, sample_box_muller};
/// let z = sample_box_muller([0.5, 0.125]);
/// let u = invert_box_muller(z);
/// assert!((u[0] - 0.5).abs() < 1e-6 && (u[1] - 0.125).abs() < 1e-6);
/// ```
#[inline]
pub fn sample_box_muller(u: [f32; 2]) -> [f32; 2] {
    let r = libm::sqrtf(-2.0 * libm::log1pf(-u[0]));
    let (s, c) = libm::sincosf(2.0 * PI * u[1]);
    [r * c, r * s]
}

/// Inverse of [`sample_box_muller`]: `u0 = 1 - exp(-r^2 / 2)`, `u1` the angle's turn.
#[inline]
pub fn invert_box_muller(z: [f32; 2]) -> [f32; 2] {
    let r2 = z[0] * z[0] + z[1] * z[1];
    [-libm::expm1f(-r2 / 2.0), turn_fraction(z[1], z[0])]
}

/// Density of a pair of independent standard normals: `exp(-(x^2 + y^2) / 2) / 2 pi`.
#[inline]
pub fn box_muller_pdf(z: [f32; 2]) -> f32 {
    libm::expf(-(z[0] * z[0] + z[1] * z[1]) / 2.0) / (2.0 * PI)
}

/// The standard normal quantile `Phi^-1(u)`, monotone in `u`, so it keeps 1D stratification.
/// Acklam's rational approximation refined by one Halley step on `erfc` (both in `f64`),
/// then rounded to `f32`: accurate to the `f32` rounding. `u = 0` is read as `2^-33`
/// (`Phi^-1 = -6.3`), so every output is finite.
///
/// ```
/// use qmckit::warp::gaussian::{normal_cdf, sample_normal};
/// assert_eq!(sample_normal(0.5), 0.0);
/// assert!((sample_normal(0.975) - 1.959964).abs() < 1e-5);
/// assert!((normal_cdf(sample_normal(0.1)) - 0.1).abs() < 1e-6);
/// ```
pub fn sample_normal(u: f32) -> f32 {
    normal_quantile((u as f64).max(P_MIN)) as f32
}

/// The standard normal CDF `Phi(x) = erfc(-x / sqrt 2) / 2`: the inverse of
/// [`sample_normal`].
#[inline]
pub fn normal_cdf(x: f32) -> f32 {
    (0.5 * libm::erfc(-(x as f64) / core::f64::consts::SQRT_2)) as f32
}

/// The standard normal density `exp(-x^2 / 2) / sqrt(2 pi)`.
#[inline]
pub fn normal_pdf(x: f32) -> f32 {
    libm::expf(-x * x / 2.0) / libm::sqrtf(2.0 * PI)
}

/// `Phi^-1(p)` for `p` in `(0, 1)` in `f64`.
fn normal_quantile(p: f64) -> f64 {
    // Acklam's coefficients (rational approximations, relative error < 1.15e-9).
    const A: [f64; 6] = [
        -3.969_683_028_665_376e1,
        2.209_460_984_245_205e2,
        -2.759_285_104_469_687e2,
        1.383_577_518_672_69e2,
        -3.066_479_806_614_716e1,
        2.506_628_277_459_239,
    ];
    const B: [f64; 5] = [
        -5.447_609_879_822_406e1,
        1.615_858_368_580_409e2,
        -1.556_989_798_598_866e2,
        6.680_131_188_771_972e1,
        -1.328_068_155_288_572e1,
    ];
    const C: [f64; 6] = [
        -7.784_894_002_430_293e-3,
        -3.223_964_580_411_365e-1,
        -2.400_758_277_161_838,
        -2.549_732_539_343_734,
        4.374_664_141_464_968,
        2.938_163_982_698_783,
    ];
    const D: [f64; 4] = [
        7.784_695_709_041_462e-3,
        3.224_671_290_700_398e-1,
        2.445_134_137_142_996,
        3.754_408_661_907_416,
    ];
    const P_LOW: f64 = 0.024_25;
    if p == 0.5 {
        return 0.0;
    }
    let tail = |q: f64| {
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    };
    let x = if p < P_LOW {
        tail(libm::sqrt(-2.0 * libm::log(p)))
    } else if p <= 1.0 - P_LOW {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    } else {
        -tail(libm::sqrt(-2.0 * libm::log1p(-p)))
    };
    // One Halley step on e = Phi(x) - p.
    let e = 0.5 * libm::erfc(-x / core::f64::consts::SQRT_2) - p;
    let u = e * libm::sqrt(2.0 * core::f64::consts::PI) * libm::exp(x * x / 2.0);
    x - u / (1.0 + x * u / 2.0)
}
