//! The periodogram by a type-1 non-uniform FFT (NUFFT) in 2D: spread the points onto a
//! fine periodic grid with a compact kernel, FFT the grid, keep the central `(2K + 1)^2`
//! modes and divide by the kernel's Fourier transform (Dutt & Rokhlin 1993; the
//! "exponential of semicircle" kernel and its parameters of Barnett, Magland & af Klinteberg,
//! "A parallel non-uniform fast Fourier transform library based on an 'exponential of
//! semicircle' kernel", SIAM J. Sci. Comput. 2019).
//!
//! With `n` grid nodes per axis, each point `u` sits at `t = n u`, and adds
//! `phi((l - t) / (w/2))` to the `w` nodes `l` nearest it along each axis, where
//!
//! ```text
//! phi(z) = exp(beta (sqrt(1 - z^2) - 1))   for |z| <= 1, else 0.
//! ```
//!
//! The grid is the power of two just below `2 (2K + 1)` when the upsampling
//! `sigma = n / (2K + 1)` is still at least 1.9, with `w = ceil(ln(1/eps) / (pi
//! sqrt(1 - 1/sigma))) + 1` and `beta = 0.97 pi w (1 - 1/(2 sigma))`; otherwise `sigma = 2`
//! exactly (the smallest even `2^a 3^b 5^c` at least `2 (2K + 1)` and `2w`) with
//! `w = ceil(log10(10 / eps))`, `beta = 2.30 w` (2.20, 2.26, 2.38 for `w = 2, 3, 4`).
//!
//! By Poisson summation the FFT of the grid at `|k| <= K` is
//! `S(k) phihat(kx) phihat(ky)` up to the aliased images, which this kernel keeps below
//! about `eps` relative to `sum_j 1 = N`, with
//! `phihat(k) = (w/2) int_{-1}^{1} phi(z) cos(pi k w z / n) dz` (Gauss–Legendre
//! quadrature). The grid is real, so its rows are transformed two at a time as the real and
//! imaginary parts of one complex FFT, and only the `K + 1` columns `kx >= 0` are transformed
//! along `y` (`S(-k)` is the conjugate of `S(k)`).
//!
//! Accuracy: `|P - P_exact| <= tolerance * N` (`N = P(0)`, the largest value) with
//! `eps = tolerance / 4`, since `|dP| <= (2 |S| |dS| + |dS|^2) / N` and `|S| <= N`.
//! Cost: `N w^2` spreading multiply-adds and `(n/2 + K + 1)` FFTs of length `n`
//! (`O(n^2 log n)`); memory `8 n^2 + 16 n (K + 1)` bytes.

use rayon::prelude::*;
use rustfft::FftPlanner;
use rustfft::num_complex::Complex;

use super::Spectrum;
use crate::Result;
use crate::analysis::Points;
use crate::size::vec_zeroed;
use crate::work::Stop;

/// The smallest tolerance the NUFFT path accepts: below it double rounding (about `1e-16 N`
/// per sum, growing with `log n`) is the larger error.
pub const NUFFT_MIN_TOLERANCE: f64 = 1e-14;

/// The largest kernel width (`eps = 1e-15`).
const MAX_WIDTH: usize = 16;

/// Kernel width, shape parameter and grid size of one transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Plan {
    /// Kernel width `w` in grid nodes.
    pub width: usize,
    /// `beta`.
    pub beta: f64,
    /// Fine grid nodes per axis, `n`.
    pub grid: usize,
}

impl Plan {
    /// The plan for frequencies `[-K, K]` and a tolerance relative to `P(0)` (already
    /// checked to lie in `[NUFFT_MIN_TOLERANCE, 1)`). Precondition: `k_max <=`
    /// [`super::SPECTRUM_MAX_K`] (the grid search is then a few hundred steps; callers
    /// check it, and [`super::estimated_cost`] does not build a plan beyond it).
    pub fn new(k_max: usize, tolerance: f64) -> Self {
        let eps = tolerance / 4.0;
        let modes = 2 * k_max + 1;
        // sigma = 2: the legacy width and shape.
        let width = ((10.0 / eps).log10().ceil() as usize).clamp(2, MAX_WIDTH);
        let beta = match width {
            2 => 2.20,
            3 => 2.26,
            4 => 2.38,
            _ => 2.30,
        } * width as f64;
        let grid = next_smooth((2 * modes).max(2 * width));
        let classic = Plan { width, beta, grid };
        // A power of two just below 2 (2K + 1) (sigma >= 1.9) transforms faster; its width
        // and shape from the general-sigma formulas.
        let pow2 = (2 * modes).next_power_of_two() / 2;
        let sigma = pow2 as f64 / modes as f64;
        if sigma < 1.9 || pow2 < 2 * MAX_WIDTH {
            return classic;
        }
        let root = (1.0 - 1.0 / sigma).sqrt();
        let w = ((1.0 / eps).ln() / (core::f64::consts::PI * root)).ceil() as usize + 1;
        if w > MAX_WIDTH {
            return classic;
        }
        Plan {
            width: w.max(2),
            beta: 0.97 * core::f64::consts::PI * w as f64 * (1.0 - 0.5 / sigma),
            grid: pow2,
        }
    }
}

/// The smallest even `2^a 3^b 5^c` at least `at_least`.
fn next_smooth(at_least: usize) -> usize {
    let mut n = at_least.max(2);
    n += n % 2;
    loop {
        let mut m = n;
        for p in [2, 3, 5] {
            while m.is_multiple_of(p) {
                m /= p;
            }
        }
        if m == 1 {
            return n;
        }
        n += 2;
    }
}

/// The kernel `phi(z)`.
fn kernel(beta: f64, z: f64) -> f64 {
    let s = 1.0 - z * z;
    if s < 0.0 {
        0.0
    } else {
        (beta * (s.sqrt() - 1.0)).exp()
    }
}

/// Nodes and weights of `q`-point Gauss–Legendre quadrature on `[-1, 1]` (Newton's method
/// on the Legendre polynomial from Chebyshev guesses; 1e-15 accurate).
fn gauss_legendre(q: usize) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(q);
    for i in 0..q {
        let mut x = (core::f64::consts::PI * (i as f64 + 0.75) / (q as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            // P_q(x) and P_q'(x) by the three-term recurrence.
            let (mut p0, mut p1) = (1.0, x);
            for j in 2..=q {
                let j = j as f64;
                (p0, p1) = (p1, ((2.0 * j - 1.0) * x * p1 - (j - 1.0) * p0) / j);
            }
            dp = q as f64 * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        out.push((x, 2.0 / ((1.0 - x * x) * dp * dp)));
    }
    out
}

/// `1 / phihat(k)` for `k = -K ..= K`.
fn deconvolution(plan: &Plan, k_max: usize) -> Vec<f64> {
    let half = plan.width as f64 / 2.0;
    let nodes = gauss_legendre(2 * plan.width + 40);
    let values: Vec<(f64, f64)> = nodes
        .iter()
        .map(|&(z, wt)| (z, wt * kernel(plan.beta, z)))
        .collect();
    let k = k_max as i64;
    (-k..=k)
        .map(|kk| {
            let a = core::f64::consts::TAU * kk as f64 * half / plan.grid as f64;
            let s: f64 = values.iter().map(|&(z, v)| v * (a * z).cos()).sum();
            1.0 / (half * s)
        })
        .collect()
}

/// The kernel values of one coordinate: the first node `l0` (not yet reduced mod `n`) and
/// `phi((l0 + a - t) / (w/2))` for `a < w`.
fn weights(plan: &Plan, u: f64, out: &mut [f64; MAX_WIDTH]) -> i64 {
    let half = plan.width as f64 / 2.0;
    let t = u * plan.grid as f64;
    let l0 = (t - half).ceil();
    for (a, o) in out.iter_mut().take(plan.width).enumerate() {
        *o = kernel(plan.beta, (l0 + a as f64 - t) / half);
    }
    l0 as i64
}

/// Adds every point's kernel to the real `n x n` grid (row `y`, column `x`).
fn spread(points: Points<'_>, plan: &Plan, grid: &mut [f64], stop: &Stop) {
    let (n, w) = (plan.grid, plan.width);
    let (mut wx, mut wy) = ([0.0; MAX_WIDTH], [0.0; MAX_WIDTH]);
    for (i, p) in points.iter().enumerate() {
        // One clock reading per 4096 points (w^2 multiply-adds each).
        if i % 4096 == 4095 && stop.check() {
            return;
        }
        let (x, y) = match *p {
            [x, y] => (x, y),
            _ => continue,
        };
        let x0 = weights(plan, x, &mut wx);
        let y0 = weights(plan, y, &mut wy);
        let wx = wx.get(..w).unwrap_or(&[]);
        let contiguous = x0 >= 0 && (x0 as usize) + w <= n;
        for (a, &vy) in wy.iter().take(w).enumerate() {
            let row = (y0 + a as i64).rem_euclid(n as i64) as usize;
            let Some(row) = grid.get_mut(row * n..(row + 1) * n) else {
                continue;
            };
            if contiguous {
                let at = x0 as usize;
                if let Some(cells) = row.get_mut(at..at + w) {
                    for (c, &vx) in cells.iter_mut().zip(wx) {
                        *c += vy * vx;
                    }
                }
            } else {
                for (b, &vx) in wx.iter().enumerate() {
                    let col = (x0 + b as i64).rem_euclid(n as i64) as usize;
                    if let Some(c) = row.get_mut(col) {
                        *c += vy * vx;
                    }
                }
            }
        }
    }
}

/// The periodogram on `[-K, K]^2` by the NUFFT; the caller has checked the dimension, `K`,
/// the tolerance and the budget.
///
/// # Errors
/// [`crate::Error::TooLarge`] when the grid does not fit in memory;
/// [`crate::Error::OutOfTime`] past the deadline of `stop` (read every 4096 points of the
/// spreading and before every FFT).
pub(super) fn nufft(
    points: Points<'_>,
    k_max: usize,
    tolerance: f64,
    stop: &Stop,
) -> Result<Spectrum> {
    let plan = Plan::new(k_max, tolerance);
    let (n, side) = (plan.grid, 2 * k_max + 1);
    let count = points.len();
    let mut grid: Vec<f64> = vec_zeroed(n * n)?;
    spread(points, &plan, &mut grid, stop);
    stop.result()?;

    let fft = FftPlanner::<f64>::new().plan_fft_forward(n);
    let scratch_len = fft.get_inplace_scratch_len();
    // Frequency kx = -K ..= K sits at FFT index kx mod n.
    let index = |kk: usize| (kk + n - k_max) % n;
    // The grid is real, so S(-k) = conj S(k): the columns kx = 0 ..= K suffice.
    let half = k_max + 1;
    // Row stage: rows 2r, 2r + 1 as one complex FFT; the wanted columns of both rows.
    let mut rows: Vec<Complex<f64>> = vec_zeroed(n * half)?;
    rows.par_chunks_mut(2 * half)
        .zip(grid.par_chunks(2 * n))
        .for_each_init(
            || {
                (
                    vec![Complex::new(0.0, 0.0); n],
                    vec![Complex::new(0.0, 0.0); scratch_len],
                )
            },
            |(buf, scratch), (out, pair)| {
                if stop.check() {
                    return;
                }
                let (a, b) = pair.split_at(n);
                for ((z, &re), &im) in buf.iter_mut().zip(a).zip(b) {
                    *z = Complex::new(re, im);
                }
                fft.process_with_scratch(buf, scratch);
                let (oa, ob) = out.split_at_mut(half);
                for (m, (ra, rb)) in oa.iter_mut().zip(ob.iter_mut()).enumerate() {
                    let z = buf.get(m).copied().unwrap_or_default();
                    let zc = buf.get((n - m) % n).copied().unwrap_or_default().conj();
                    // A(m) = (Z(m) + conj Z(-m)) / 2, B(m) = (Z(m) - conj Z(-m)) / 2i.
                    *ra = (z + zc) * 0.5;
                    *rb = (z - zc) * Complex::new(0.0, -0.5);
                }
            },
        );
    drop(grid);
    stop.result()?;

    // Column stage: for each wanted kx, the FFT along y of its column.
    let inverse = deconvolution(&plan, k_max);
    let inv_n = 1.0 / count as f64;
    let columns: Vec<Vec<f64>> = (0..half)
        .into_par_iter()
        .map_init(
            || {
                (
                    vec![Complex::new(0.0, 0.0); n],
                    vec![Complex::new(0.0, 0.0); scratch_len],
                )
            },
            |(buf, scratch), kx| {
                if stop.check() {
                    return Vec::new();
                }
                for (row, z) in buf.iter_mut().enumerate() {
                    *z = rows.get(row * half + kx).copied().unwrap_or_default();
                }
                fft.process_with_scratch(buf, scratch);
                let dx = inverse.get(k_max + kx).copied().unwrap_or(0.0);
                (0..side)
                    .map(|ky| {
                        let dy = inverse.get(ky).copied().unwrap_or(0.0);
                        let s = buf.get(index(ky)).copied().unwrap_or_default() * (dx * dy);
                        s.norm_sqr() * inv_n
                    })
                    .collect()
            },
        )
        .collect();
    stop.result()?;
    let mut power: Vec<f64> = vec_zeroed(side * side)?;
    for (kx, column) in columns.iter().enumerate() {
        for (ky, &p) in column.iter().enumerate() {
            // (kx, ky - K) and its mirror (-kx, K - ky).
            if let Some(slot) = power.get_mut(ky * side + k_max + kx) {
                *slot = p;
            }
            if let Some(slot) = power.get_mut((side - 1 - ky) * side + k_max - kx) {
                *slot = p;
            }
        }
    }
    if let Some(origin) = power.get_mut(k_max * side + k_max) {
        *origin = count as f64; // exact: every phase is 1
    }
    Ok(Spectrum {
        k_max,
        points: count,
        power,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smooth_sizes_and_quadrature() {
        assert_eq!(next_smooth(1026), 1080);
        assert_eq!(next_smooth(7), 8);
        assert_eq!(next_smooth(2050), 2160);
        // Gauss–Legendre integrates x^4 exactly: 2/5.
        let s: f64 = gauss_legendre(5).iter().map(|&(x, w)| w * x.powi(4)).sum();
        assert!((s - 0.4).abs() < 1e-14);
    }
}
