//! Bessel functions of the first kind of integer and half-integer order, `J_{m/2}(x)` for
//! `x >= 0`, for the `d`-dimensional Fourier–Bessel (Hankel) transforms of the spectral
//! sampler (orders `d/2 - 1` and `d/2`).
//!
//! Integer orders come from `libm::jn`. Half-integer orders are spherical Bessel functions:
//! `J_{n+1/2}(x) = sqrt(2x/pi) j_n(x)` (Abramowitz & Stegun 10.1.1), with
//! `j_{-1}(x) = cos(x)/x`, `j_0(x) = sin(x)/x`, `j_1(x) = sin(x)/x^2 - cos(x)/x` and the
//! recurrence `j_{n+1} = (2n+1)/x j_n - j_{n-1}` (A&S 10.1.19), stable upwards for
//! `x > n`; below, the power series `j_n(x) = x^n/(2n+1)!! sum_k (-x^2/2)^k /
//! (k! (2n+3)(2n+5)...(2n+2k+1))` (A&S 10.1.2). Cost: `O(n)` a value.

/// `J_{m/2}(x)` for `x >= 0`, `m >= -1`.
pub(crate) fn bessel_j_half(m: i32, x: f64) -> f64 {
    if m % 2 == 0 {
        return libm::jn(m / 2, x);
    }
    let n = (m - 1) / 2; // order n + 1/2
    if x == 0.0 {
        return 0.0; // m = -1 is not evaluated at 0 (the caller takes the limit)
    }
    (2.0 * x / core::f64::consts::PI).sqrt() * spherical_j(n, x)
}

/// The spherical Bessel function `j_n(x)`, `n >= -1`, `x > 0`.
fn spherical_j(n: i32, x: f64) -> f64 {
    if n == -1 {
        return x.cos() / x;
    }
    if x > f64::from(n) + 0.5 {
        let (s, c) = (x.sin(), x.cos());
        let (mut a, mut b) = (s / x, s / (x * x) - c / x);
        if n == 0 {
            return a;
        }
        for k in 1..n {
            let next = f64::from(2 * k + 1) / x * b - a;
            a = b;
            b = next;
        }
        return b;
    }
    // Series: x <= n + 1/2 <= 4.5 for the orders used, 40 terms are ample.
    let mut lead = 1.0;
    for k in 1..=n {
        lead *= x / f64::from(2 * k + 1);
    }
    let (mut term, mut sum) = (1.0f64, 1.0f64);
    let q = -x * x / 2.0;
    for k in 1..40 {
        term *= q / (f64::from(k) * f64::from(2 * n + 2 * k + 1));
        sum += term;
        if term.abs() < 1e-17 * sum.abs() {
            break;
        }
    }
    lead * sum
}
