//! The cost models and calibrated rates of the star-discrepancy family, shared by its modules
//! (see [`crate::work`] for the mechanism).
//!
//! Each model follows the algorithm that runs: the 2D sweep visits every cell of the
//! critical grid ([`SWEEP_RATE`]); the decomposition of [`super::dem`] is timed per dimension
//! ([`work_estimate`], at [`STAR_RATE`]). Both are split over rayon's threads, so their
//! estimates are [`Cost::parallel`]: the per-core rates on [`CORES`] cores. The rates were
//! measured as CPU time of one thread (`examples/time_costs.rs`, the least of repeated runs
//! on Sobol' points; the table is in `docs/budgets.md`).

use crate::work::{Budget, CORES, Cost, Rate};

/// Cells of the critical grid per second and core of the 2D sweep ([`super::star_2d`]): one
/// cell is one column `a` and one row `b`, two multiply-compares and two additions. Measured
/// 6.5e8 (20000 and 8000 Sobol' points, 0.61 s and 0.098 s of CPU on one thread); the
/// estimate of `N` points is `(N + 1)^2` cells ([`star_cost`]).
pub const SWEEP_RATE: Rate = Rate::per_second(6.5e8);

/// Sort steps per second of the 1D closed form ([`super::star_1d`]), `N log2 N` steps on one
/// core: `4e8` (`10^6` points sorted in 0.047 s of CPU).
pub const SORT_RATE: Rate = Rate::per_second(4e8);

/// The units of [`work_estimate`] per second and core: the decomposition's model is written
/// in nanoseconds of one core, so this is `1e9`.
pub const STAR_RATE: Rate = Rate::per_second(1e9);

/// Point-coordinate comparisons per second of Thiémard's cover ([`super::thiemard`]), with
/// their share of list filtering and region bookkeeping, in the units of the cost model of
/// [`super::thiemard::bounds`]: `2e8`. With it the default budget accepts sets measured at
/// 1.2 to 3.8 s and refuses sets measured at 10 to 27 s (the table there): the estimate
/// assumes evenly spread points and errs on the long side.
pub const THIEMARD_RATE: Rate = Rate::per_second(2e8);

/// Point-coordinate steps per second of threshold accepting
/// ([`super::star_lower_bound`]): one step is one coordinate of one point scored against one
/// box, `3e8` a second (20000 iterations on 1000 Sobol' points in 20D, `4e8` steps, took
/// 0.9 s; on 10000 points, `4e9` steps, 11 s).
pub const LOWER_BOUND_RATE: Rate = Rate::per_second(3e8);

/// `(c_d, e_d)` of [`work_estimate`] for `d = 3..=8`: nanoseconds of one core, and the
/// exponent `(d + 1) / 2 - 0.15`, fitted to the CPU time of the first `N` Sobol' points on
/// one thread (the least of repeated runs), `N` from about 0.2 s to 60 s of it: `d = 3`:
/// 6000 to 80000 points, 4: 1500 to 8000, 5: 500 to 2000, 6: 200 to 800, 7: 100 to 300,
/// 8: 60 to 150. Every measured time is within 0.90 to 1.15 times the fit.
const DEM_FIT: [(f64, f64); 6] = [
    (25.3, 1.85),
    (22.8, 2.35),
    (18.3, 2.85),
    (12.6, 3.35),
    (8.6, 3.85),
    (4.54, 4.35),
];

/// The dimension up to which [`work_estimate`] follows measured times (beyond, it is
/// extrapolated).
pub const DEM_MEASURED_DIMS: usize = 24;

/// Estimated work of [`super::dem::star_dem`] for `n` points in `d` dimensions, in
/// nanoseconds of one core ([`STAR_RATE`] is `1e9` of them a second), `c_d N^(e_d)`:
///
/// * `3 <= d <= 8`: `e_d = (d + 1) / 2 - 0.15` and `c_d` (25.3, 22.8, 18.3, 12.6, 8.6 and
///   4.54) fitted per dimension. Dobkin, Eppstein & Mitchell's bound is `N^(1 + d/2)`; the
///   cell bounds of the last coordinate and the pruning (module documentation of
///   [`super::dem`]) take a little more than `sqrt N` off it on the sizes a budget admits;
/// * `9 <= d <= 24`: `e_d = 1 + d/2` and
///   `log10 c_d = -1.07 - 0.401 (d - 10) - 0.0106 (d - 10)^2`, fitted to 9, 10, 11, 12, 14,
///   16 and 24 dimensions (20 to 80 points). Here the time grows irregularly with `N`
///   (between 40 and 55 points in 11D like `N^4.9`, between 36 and 44 in 14D like
///   `N^12`): measured times are within 0.6 to 1.4 times the fit;
/// * `d > 24`: the value of 24 dimensions times `d / 24`, not measured beyond a few sets (25
///   points in 50D took 0.33 s, estimated 5 s; 14 points in 100D 0.03 s, estimated 0.002
///   s): the deadline bounds what this misjudges;
/// * `d <= 2`: `N^(1 + d/2)` (the decomposition in one and two dimensions, which
///   [`super::star_exact`] does not use).
///
/// `O(1)`; the value grows with `n` for every `d`.
pub fn work_estimate(n: usize, d: usize) -> f64 {
    let n = n as f64;
    let high = |d: usize| {
        let x = d as f64 - 10.0;
        let log_c = -1.07 - 0.401 * x - 0.0106 * x * x;
        10f64.powf(log_c) * n.powf(1.0 + d as f64 / 2.0)
    };
    match d {
        0..=2 => n.powf(1.0 + d as f64 / 2.0),
        3..=8 => {
            let (c, e) = DEM_FIT[d - 3];
            c * n.powf(e)
        }
        9..=DEM_MEASURED_DIMS => high(d),
        _ => high(DEM_MEASURED_DIMS) * d as f64 / DEM_MEASURED_DIMS as f64,
    }
}

/// The estimated time of the exact star discrepancy ([`super::star_exact`]) of `n` points in
/// `d` dimensions: a sort in 1D (`N log2 N` steps at [`SORT_RATE`], one core), the
/// `(N + 1)^2` cells of the critical grid at [`SWEEP_RATE`] in 2D and [`work_estimate`] at
/// [`STAR_RATE`] from 3D on, both on [`CORES`] cores. `O(1)`.
///
/// ```
/// use qmckit::analysis::star::star_cost;
/// // 20000 2D points: 4e8 cells at 6.5e8 a second on each of two cores.
/// assert!((star_cost(20_000, 2).seconds() - 0.308).abs() < 0.001);
/// ```
pub fn star_cost(n: usize, d: usize) -> Cost {
    let nf = n as f64;
    match d {
        0 | 1 => Cost::steps(nf * (nf + 1.0).log2(), SORT_RATE),
        2 => Cost::parallel((nf + 1.0) * (nf + 1.0), SWEEP_RATE),
        _ => Cost::parallel(work_estimate(n, d), STAR_RATE),
    }
}

/// Largest `N` (at least 1, at most `2^40`) whose decomposition ([`work_estimate`] at
/// [`STAR_RATE`] on [`CORES`] cores) is within `budget`, by a binary search of 40
/// estimates.
pub fn max_points(d: usize, budget: &Budget) -> u64 {
    let (mut lo, mut hi) = (1u64, 1u64 << 40);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if within(work_estimate(mid as usize, d), budget) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    lo
}

/// Whether `steps` of [`work_estimate`] fit in `budget`.
pub(super) fn within(steps: f64, budget: &Budget) -> bool {
    budget
        .check(
            "the exact star discrepancy",
            Cost::parallel(steps, STAR_RATE),
        )
        .is_ok()
}

/// The largest `N` whose 2D sweep, `(N + 1)^2` cells at [`SWEEP_RATE`] on [`CORES`] cores,
/// fits in `budget` (`u64::MAX` for a budget too large to matter). `O(1)`.
pub(super) fn max_points_2d(budget: &Budget) -> u64 {
    let cells = budget.steps(SWEEP_RATE) * CORES;
    if cells >= (u64::MAX as f64) * (u64::MAX as f64) {
        return u64::MAX;
    }
    let mut r = cells.sqrt().floor() as u64;
    // Correct the rounding of the square root: the largest r with r^2 <= cells.
    while r > 0 && (r as f64) * (r as f64) > cells {
        r -= 1;
    }
    while ((r + 1) as f64) * ((r + 1) as f64) <= cells {
        r += 1;
    }
    r.saturating_sub(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Seconds of one core by the model.
    fn per_core(n: usize, d: usize) -> f64 {
        star_cost(n, d).seconds() * CORES
    }

    /// The model against the least CPU time of one thread on the first `N` Sobol' points
    /// (`examples/time_costs.rs` and `RAYON_NUM_THREADS=1 qmckit discrepancy --metric
    /// star`, on a machine loaded by other work): within the factors the documentation of
    /// [`work_estimate`] states.
    #[test]
    fn the_model_follows_the_measured_times() {
        // (d, N, seconds of one core).
        let measured: [(usize, usize, f64); 38] = [
            (2, 8000, 0.0977),
            (2, 20000, 0.613),
            (3, 6000, 0.25),
            (3, 20000, 2.22),
            (3, 80000, 30.41),
            (4, 1500, 0.69),
            (4, 4000, 6.62),
            (4, 8000, 32.6),
            (5, 500, 1.0),
            (5, 1100, 8.37),
            (5, 2000, 44.84),
            (6, 200, 0.74),
            (6, 400, 6.44),
            (6, 800, 64.39),
            (7, 100, 0.45),
            (7, 200, 5.86),
            (7, 300, 28.11),
            (8, 60, 0.26),
            (8, 90, 1.49),
            (8, 150, 11.95),
            (9, 40, 0.14),
            (9, 80, 4.25),
            (10, 30, 0.07),
            (10, 60, 3.57),
            (11, 30, 0.153),
            (11, 40, 1.248),
            (11, 55, 6.035),
            (12, 25, 0.0906),
            (12, 35, 0.734),
            (12, 45, 6.169),
            (14, 20, 0.0468),
            (14, 28, 0.555),
            (14, 36, 2.677),
            (14, 44, 30.25),
            (16, 20, 0.0617),
            (16, 30, 2.351),
            (16, 40, 48.32),
            (24, 28, 11.37),
        ];
        for (d, n, seconds) in measured {
            let ratio = seconds / per_core(n, d);
            let (lo, hi) = if d <= 8 { (0.85, 1.2) } else { (0.55, 1.8) };
            assert!((lo..hi).contains(&ratio), "d {d} N {n}: {ratio}");
        }
    }

    #[test]
    fn the_largest_admitted_set_is_the_estimate_s() {
        for seconds in [0.01, 1.0, 10.0, 600.0] {
            let budget = Budget::seconds(seconds).unwrap();
            for d in 2..=30 {
                let max = super::super::max_points(d, &budget) as usize;
                assert!(star_cost(max, d).seconds() <= seconds || max <= 1, "d {d}");
                assert!(star_cost(max + 1, d).seconds() > seconds, "d {d}");
            }
        }
        // The estimate grows with the points in every dimension.
        for d in 1..=60 {
            let mut last = 0.0;
            for n in (1..2000).step_by(37) {
                let s = star_cost(n, d).seconds();
                assert!(s >= last, "d {d} n {n}");
                last = s;
            }
        }
    }
}
