//! The pair-correlation mismatch of a 2D point set against a target (step blue noise,
//! Heck, Schlömer & Deussen 2013) and its gradient, pairs found through a grid of cells; on
//! the torus or in the plane. Shared by the table optimizers (`aa_optimize`,
//! `art_optimize`).

/// `J_1(x)` by its power series (`x <= 12` here: the terms stay below `10^3`).
fn bessel_j1(x: f64) -> f64 {
    let (mut term, mut sum) = (x / 2.0, x / 2.0);
    for k in 1..40 {
        term *= -(x * x / 4.0) / (k as f64 * (k as f64 + 1.0));
        sum += term;
    }
    sum
}

/// The pair correlation of step blue noise with cutoff `u0` (unit density, 2D; Heck,
/// Schlömer & Deussen 2013): `G_0(rho) = 1 - (u0 / rho) J_1(2 pi u0 rho)`.
pub fn step_pcf(rho: f64, u0: f64) -> f64 {
    if rho < 1e-9 {
        1.0 - std::f64::consts::PI * u0 * u0
    } else {
        1.0 - u0 / rho * bessel_j1(2.0 * std::f64::consts::PI * u0 * rho)
    }
}

/// The pair-correlation mismatch `E = sum_b (G_b - G_0(rho_b))^2` of points of unit
/// density, `G_b` estimated with a Gaussian kernel (width `H`) at `rho_b = (b + 1/2) D` up
/// to `RHO_MAX`, around the points marked in `centres` (on the torus of side `period`, or
/// in the plane), and its gradient (added to `grad`).
pub fn pcf_mismatch(
    p: &[[f64; 2]],
    centres: &[bool],
    period: Option<f64>,
    target: &dyn Fn(f64) -> f64,
    grad: &mut [[f64; 2]],
) -> f64 {
    const D: f64 = 0.04;
    const H: f64 = 0.04;
    const RHO_MAX: f64 = 2.5;
    let bins = (RHO_MAX / D) as usize;
    let reach = RHO_MAX + 4.0 * H;
    let pairs = near_pairs(p, reach, period);
    let nc = centres.iter().filter(|&&c| c).count().max(1) as f64;
    let norm = 1.0 / (H * (2.0 * std::f64::consts::PI).sqrt());
    let c: Vec<f64> = (0..bins)
        .map(|b| 1.0 / (nc * 2.0 * std::f64::consts::PI * (b as f64 + 0.5) * D))
        .collect();
    let kernel = |x: f64| norm * (-x * x / (2.0 * H * H)).exp();
    let mut g = vec![0.0; bins];
    for &(i, j, r, _) in &pairs {
        let w = f64::from(u8::from(centres[i])) + f64::from(u8::from(centres[j]));
        if w == 0.0 {
            continue;
        }
        let b0 = ((r - 4.0 * H) / D).floor().max(0.0) as usize;
        let b1 = (((r + 4.0 * H) / D).ceil() as usize).min(bins);
        for b in b0..b1 {
            g[b] += w * c[b] * kernel((b as f64 + 0.5) * D - r);
        }
    }
    let diff: Vec<f64> = (0..bins)
        .map(|b| g[b] - target((b as f64 + 0.5) * D))
        .collect();
    let e = diff.iter().map(|d| d * d).sum();
    for &(i, j, r, d) in &pairs {
        let w = f64::from(u8::from(centres[i])) + f64::from(u8::from(centres[j]));
        if w == 0.0 || r < 1e-12 {
            continue;
        }
        let b0 = ((r - 4.0 * H) / D).floor().max(0.0) as usize;
        let b1 = (((r + 4.0 * H) / D).ceil() as usize).min(bins);
        let mut de_dr = 0.0;
        for b in b0..b1 {
            let x = (b as f64 + 0.5) * D - r;
            // d kernel(x)/dr = kernel(x) x / H^2.
            de_dr += 2.0 * diff[b] * w * c[b] * kernel(x) * x / (H * H);
        }
        for k in 0..2 {
            grad[i][k] += de_dr * d[k] / r;
            grad[j][k] -= de_dr * d[k] / r;
        }
    }
    e
}

/// The hard-core penalty `E = sum (r0 - |p_i - p_j|)^2` over the pairs closer than `r0`
/// with at least one point marked in `centres` (a point process with a hard core `r0`
/// has `E = 0`; Poisson-disk and maximal-minimum-distance sets are its targets), and its
/// gradient (added to `grad`).
#[allow(dead_code)]
pub fn hard_core(
    p: &[[f64; 2]],
    centres: &[bool],
    period: Option<f64>,
    r0: f64,
    grad: &mut [[f64; 2]],
) -> f64 {
    let mut e = 0.0;
    for (i, j, r, d) in near_pairs(p, r0, period) {
        if !(centres[i] || centres[j]) || r < 1e-12 {
            continue;
        }
        e += (r0 - r) * (r0 - r);
        // dE/dp_i = -2 (r0 - r) (p_i - p_j) / r.
        let f = -2.0 * (r0 - r) / r;
        for k in 0..2 {
            grad[i][k] += f * d[k];
            grad[j][k] -= f * d[k];
        }
    }
    e
}

/// The pairs `(i, j, |p_i - p_j|, p_i - p_j)`, `i < j`, closer than `reach`.
fn near_pairs(
    p: &[[f64; 2]],
    reach: f64,
    period: Option<f64>,
) -> Vec<(usize, usize, f64, [f64; 2])> {
    let (lo, span) = match period {
        Some(t) => (0.0, t),
        None => {
            let lo = p.iter().flatten().fold(f64::INFINITY, |a, &b| a.min(b));
            let hi = p.iter().flatten().fold(f64::NEG_INFINITY, |a, &b| a.max(b));
            (lo, hi - lo + 1e-9)
        }
    };
    let m = ((span / reach).floor() as usize).max(1);
    let periodic = period.is_some();
    let all = periodic && m < 3;
    let cell = |v: f64| (((v - lo) / span * m as f64).floor() as isize).clamp(0, m as isize - 1);
    let mut heads = vec![usize::MAX; m * m];
    let mut next = vec![usize::MAX; p.len()];
    for (i, q) in p.iter().enumerate() {
        let c = (cell(q[0]) + m as isize * cell(q[1])) as usize;
        next[i] = heads[c];
        heads[c] = i;
    }
    let wrap = |d: f64| match period {
        Some(t) => d - t * (d / t).round(),
        None => d,
    };
    let mut out = Vec::new();
    for (i, q) in p.iter().enumerate() {
        let (cx, cy) = (cell(q[0]), cell(q[1]));
        let mut cells = Vec::with_capacity(9);
        if all {
            cells.extend(0..m * m);
        } else {
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (mut x, mut y) = (cx + dx, cy + dy);
                    if periodic {
                        x = x.rem_euclid(m as isize);
                        y = y.rem_euclid(m as isize);
                    } else if x < 0 || y < 0 || x >= m as isize || y >= m as isize {
                        continue;
                    }
                    cells.push((x + m as isize * y) as usize);
                }
            }
            cells.sort_unstable();
            cells.dedup();
        }
        for c in cells {
            let mut j = heads[c];
            while j != usize::MAX {
                if j > i {
                    let d = [wrap(q[0] - p[j][0]), wrap(q[1] - p[j][1])];
                    let r = d[0].hypot(d[1]);
                    if r < reach {
                        out.push((i, j, r, d));
                    }
                }
                j = next[j];
            }
        }
    }
    out
}
