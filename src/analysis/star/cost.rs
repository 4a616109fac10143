//! The calibrated rates of the star-discrepancy family, shared by its modules (see
//! [`crate::work`] for the mechanism).
//!
//! Each rate converts a counted number of inner-loop steps into seconds. They were measured
//! with the release build on two cores shared with other work (load average about 1.5), so
//! they are conservative for an idle machine; a busier machine runs proportionally slower
//! (the 6D row of [`super::dem`], 500 Sobol' points, took 20.5 s instead of 8.4 s at a load
//! average of 7).

use crate::work::{Budget, Cost, Rate};

/// Steps per second of the exact algorithms: `N^2` sweep steps in 2D, the units of
/// [`work_estimate`] for `d >= 3`, fitted to the measured rows of [`super::dem`] (e.g. 500
/// 6D Sobol' points, `1.25 * 500^3.5 = 3.5e9` steps, in 8.4 s): the default budget of ten
/// seconds admits `3e9` steps (`N <= 54772` in 2D, where `2^14` points take about one
/// second).
pub const STAR_RATE: Rate = Rate::per_second(3e8);

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

/// Estimated work of [`super::dem::star_dem`] for `n` points in `d` dimensions, in steps of
/// [`STAR_RATE`] (`3e8` a second: the default budget of ten seconds admits `3e9`):
///
/// * `d <= 2`: `N^(1 + d/2)`;
/// * `3 <= d <= 7`: `1.25 N^((d + 1)/2)`. The cell bounds of the last coordinate (module
///   documentation) remove about a factor `sqrt N` from Dobkin, Eppstein & Mitchell's
///   `N^(1 + d/2)` on these sizes: doubling `N` multiplied the time by `2^1.7` at `d = 3`,
///   `2^2.1`, `2^2.6`, `2^3.2` (`N` = 600 to 1000) and `2^3.7` at `d = 7`;
/// * `d >= 8`: `0.005 N^((d + 3)/2)`: here the bounds gain less, `d = 8` grew like `N^5.4`
///   from 150 to 190 points.
///
/// Fitted to Sobol' points (slower than random ones) with the `time_dem` example, two
/// threads, load about 1.5. The budget then admits `N` up to 48989, 5650, 1338, 478, 221,
/// 138 for `d` = 3..8; measured nearby: 40000 3D points in 5.3 s, 6000 4D in 10.5 s, 1300
/// 5D in 9.0 s, 500 6D in 8.4 s, 260 7D in 10.9 s, 150 8D in 8.5 s (estimated 15.5; 190
/// 8D: 30 s against 57). It is conservative for high `d` (70 10D points: 8.2 s against 16
/// estimated; 40 12D: 3.1 s against 17) and for large sets at `d <= 7` (1000 6D points:
/// 86 s against 132). A loaded machine runs slower. Ties make a set faster than
/// estimated.
pub fn work_estimate(n: usize, d: usize) -> f64 {
    let n = n as f64;
    match d {
        0..=2 => n.powf(1.0 + d as f64 / 2.0),
        3..=7 => 1.25 * n.powf((d + 1) as f64 / 2.0),
        _ => 0.005 * n.powf((d + 3) as f64 / 2.0),
    }
}

/// Largest `N` whose [`work_estimate`] is within [`Budget::DEFAULT`].
pub fn max_points(d: usize) -> u64 {
    max_points_within(d, &Budget::DEFAULT)
}

/// Largest `N` (at least 1, at most `2^40`) whose [`work_estimate`] is within `budget`, by
/// a binary search of 40 estimates.
pub fn max_points_within(d: usize, budget: &Budget) -> u64 {
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
        .check("the exact star discrepancy", Cost::steps(steps, STAR_RATE))
        .is_ok()
}
