//! Star discrepancy `D*_N`: exact in 1D (closed form), 2D (`O(N^2)` sweep) and d dimensions
//! (Dobkin–Eppstein–Mitchell, in [`dem`]), the extreme (unanchored) discrepancy in 2D, and
//! bounds for sets too large to compute exactly.
//!
//! # Definition and the open/closed subtlety
//!
//! For `N` points `x_i` in `[0, 1]^d`,
//!
//! ```text
//! D*_N = sup_{y in [0,1]^d} | A([0, y)) / N - vol([0, y)) |,   A = number of points inside.
//! ```
//!
//! The supremum is attained, as a limit, on the *critical grid*: every coordinate `y_k` taken
//! from `{x_ik} ∪ {1}`. At a grid point the two one-sided limits are
//!
//! * `vol(y) - open(y) / N`, with `open(y) = #{i : x_i < y}` (the box `[0, y)` itself), and
//! * `closed(y) / N - vol(y)`, with `closed(y) = #{i : x_i <= y}` (the limit of `[0, y + ε)`),
//!
//! and `D*_N` is the maximum of both over the grid (Niederreiter 1992, §2.1; Gnewuch,
//! Wahlström & Winzen 2012, §1). Checking only half-open boxes underestimates: for the
//! 64-point Larcher–Pillichshammer net it gives 0.0242 instead of the exact 21/512.
//!
//! One more boundary case: a coordinate equal to 1 is never inside any `[0, y)` with
//! `y <= 1`, and the limit `[0, y + ε)` does not exist past 1. So a point with a coordinate
//! equal to 1 is never counted (it still counts in `N`); at `y_k = 1` the closed limit is
//! `x_k < 1`. (Counting it would overestimate: three points `(1, 0), (1, 0), (0, 0)` have
//! `D* = 2/3`, not 1.)
//!
//! # Accuracy
//!
//! Everything is evaluated in `f64` at grid points: counts are exact, `vol(y)` is a product of
//! coordinates rounded once per factor, so results are within a few ulps of the exact value
//! (exact for dyadic sets with `N` a power of two and few bits, e.g. the nets of
//! [`crate::LarcherPillichshammer`]).
//!
//! # Cost
//!
//! | function | cost | limit |
//! |---|---|---|
//! | [`star_1d`] | `O(N log N)` | none |
//! | [`star_2d`] | `O(N^2)` time, `O(N)` memory, parallel over columns | `(N + 1)^2` cells at [`SWEEP_RATE`] on two cores ([`star_cost`]) within the budget: `N <= 114_016` in ten seconds |
//! | [`star_exact`] | `O(N^2)` in 2D; `O(N^(1 + d/2))` for `d >= 3` (Dobkin–Eppstein–Mitchell, [`dem`]), pruned: measured about `N^((d + 1)/2 - 0.15)` | [`star_cost`] within ten seconds: `N <= 64517, 6391, 1483, 557` for `d = 3, 4, 5, 6`; its second argument is the budget |
//! | [`extreme_2d`] | `O(N^3)` | `N^3 / 2` steps at [`EXTREME_RATE`] within the budget: `N <= 1503` in ten seconds; its second argument is the budget |
//! | [`star_lower_bound`] | `O(iterations · (N + 32) d)` ([`lower_bound_steps`]) | [`lower_bound_steps`] at [`LOWER_BOUND_RATE`] within the budget, its last argument ([`Budget::UNLIMITED`](crate::work::Budget::UNLIMITED): none) |
//! | [`star_upper_bound`] | Thiémard's cover ([`thiemard`]): about `Σ_R (N vol(b_R) + 16)(d + k_R) + 2 d (k_R - 1)` over its regions, parallel | ten seconds at [`THIEMARD_RATE`], estimated first; [`thiemard::bounds`] takes a budget |
//!
//! Every budgeted function estimates its cost before it allocates anything that grows with
//! the input, and none recurses deeper than a constant: the searches keep their state on the
//! heap.

mod cells;
pub mod cost;
pub mod dem;
mod extreme;
mod lower_bound;
mod sweep;
pub mod thiemard;
mod thiemard_cost;

pub use cost::{LOWER_BOUND_RATE, SORT_RATE, STAR_RATE, SWEEP_RATE, THIEMARD_RATE, star_cost};
pub use extreme::{EXTREME_RATE, extreme_2d};
pub use lower_bound::{lower_bound_steps, star_lower_bound};

use super::Points;
use crate::work::Stop;
use crate::work::{Budget, Limits};
use crate::{Error, Result};

/// Largest `N` [`star_2d`] (and [`star`], [`star_exact`] in 2D) accepts within
/// [`Budget::DEFAULT`]: the largest `N` whose `(N + 1)^2` cells at [`SWEEP_RATE`] on
/// [`CORES`](crate::work::CORES) cores take at most ten seconds ([`star_cost`]).
pub const STAR_2D_MAX_POINTS: u64 = 114_016;

// The 2D limit is the default budget's: one rule for every exact entry point.
const _: () = {
    let cells = SWEEP_RATE.steps_per_second() * crate::work::CORES * crate::work::DEFAULT_SECONDS;
    let (n, next) = (
        (STAR_2D_MAX_POINTS + 1) as f64,
        (STAR_2D_MAX_POINTS + 2) as f64,
    );
    assert!(n * n <= cells && next * next > cells);
};

/// Star discrepancy of `points`, exact: [`star_1d`] in 1D, [`star_2d`] in 2D,
/// Dobkin–Eppstein–Mitchell for `d >= 3`; the same as [`star_exact`] (one time budget,
/// [`Budget::DEFAULT`], in every dimension).
///
/// # Errors
/// [`Error::TooManyPoints`] when the estimated work exceeds the budget.
///
/// ```
/// use qmckit::analysis::{Points, star::star};
/// // One point at the center of the square. The closed box [0, 1/2]^2 holds it:
/// // 1 - 1/4 = 3/4; a box missing it has volume at most 1/2 (e.g. [0, 1) x [0, 1/2)).
/// let p = Points::new(&[0.5, 0.5], 2)?;
/// assert_eq!(star(p)?, 0.75);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn star(points: Points<'_>) -> Result<f64> {
    star_exact(points, &Budget::DEFAULT)
}

/// Exact 1D star discrepancy by the closed form (Niederreiter 1992, Thm. 2.6):
/// `D*_N = 1/(2N) + max_i |x_(i) - (2i - 1)/(2N)|` over the sorted `x_(1) <= ... <= x_(N)`.
///
/// Ties and points at 0 or 1 need no special care. Range `[1/(2N), 1]`; the minimum
/// `1/(2N)` is attained by the centered grid `(2i - 1)/(2N)`. Cost `O(N log N)`.
///
/// # Errors
/// [`Error::Unsupported`] unless `points.dims() == 1`.
///
/// ```
/// use qmckit::analysis::{Points, star::star_1d};
/// // A single point at 1/2: [0, 1/2) is empty (1/2 - 0) and [0, 1/2] holds it (1 - 1/2).
/// assert_eq!(star_1d(Points::new(&[0.5], 1)?)?, 0.5);
/// // The centered grid 1/8, 3/8, 5/8, 7/8 has the least possible D* = 1/(2N).
/// assert_eq!(star_1d(Points::new(&[0.125, 0.375, 0.625, 0.875], 1)?)?, 0.125);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn star_1d(points: Points<'_>) -> Result<f64> {
    if points.dims() != 1 {
        return Err(Error::Unsupported {
            what: "star_1d of points with more than one coordinate",
        });
    }
    let mut xs = points.as_slice().to_vec();
    xs.sort_unstable_by(f64::total_cmp);
    let two_n = 2.0 * xs.len() as f64;
    let worst = xs
        .iter()
        .enumerate()
        .map(|(i, &x)| (x - (2 * i + 1) as f64 / two_n).abs())
        .fold(0.0, f64::max);
    Ok(1.0 / two_n + worst)
}

/// Exact 2D star discrepancy over the critical grid, open and closed boxes.
///
/// Sweep: points sorted by `x`; for each critical `x = a` (in `{x_i} ∪ {1}`) a count array
/// over the ranks of the distinct `y`s holds the points left of `a`, and one pass over it
/// evaluates `a b - open/N` and `closed/N - a b` at every critical `b`. Cost
/// `O(N · M)` with `M <= N + 1` distinct `y`s, so `O(N^2)` time and `O(N)` memory; the
/// columns are split over rayon's threads. Estimated `(N + 1)^2` cells at [`SWEEP_RATE`]
/// (6.5e8 a second and core) on two cores ([`star_cost`]): 20000 Sobol' points, 0.31 s.
///
/// # Errors
/// [`Error::Unsupported`] unless `points.dims() == 2`; [`Error::TooManyPoints`] above
/// [`STAR_2D_MAX_POINTS`].
///
/// ```
/// use qmckit::analysis::{Points, star::star_2d};
/// // The 4-point Larcher–Pillichshammer net (i/4, y_i), y = 0, 1/2, 3/4, 1/4. The closed
/// // box [0, 3/4]^2 holds all four points: 1 - 9/16 = 7/16, the maximum (the same box
/// // taken half-open, [0, 3/4)^2, holds two: 9/16 - 1/2 = 1/16 only).
/// let p = Points::new(&[0.0, 0.0, 0.25, 0.5, 0.5, 0.75, 0.75, 0.25], 2)?;
/// assert_eq!(star_2d(p)?, 7.0 / 16.0);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn star_2d(points: Points<'_>) -> Result<f64> {
    if points.dims() != 2 {
        return Err(Error::Unsupported {
            what: "star_2d of points that are not 2-dimensional",
        });
    }
    star_exact(points, &Budget::DEFAULT)
}

/// Exact star discrepancy in any dimension: [`star_1d`] in 1D, the `O(N^2)` sweep of
/// [`star_2d`] in 2D, and for `d >= 3` the cell decomposition of Dobkin, Eppstein & Mitchell
/// (1996), "Computing the discrepancy with applications to supersampling patterns", ACM TOG
/// 15(4), in [`dem::star_dem`]: `O(N^(1 + d/2))` time instead of the `O(N^d)` of
/// enumerating the critical grid.
///
/// The value is `max over the critical grid of max(vol - open/N, closed/N - vol)`, points
/// with a coordinate equal to 1 never counted (see the module documentation). Measured on
/// one thread (CPU time, Sobol' points; `docs/budgets.md`): `d = 3`: 40000 points in 8.4 s;
/// `d = 4`: 8000 in 33 s; `d = 5`: 2000 in 45 s; `d = 6`: 600 in 25 s, two threads taking
/// about half (details in [`dem`]); enumerating the critical grid takes ten seconds at
/// about 1900, 365, 140 and 70 points.
/// Beyond that use [`star_lower_bound`] / [`star_upper_bound`].
///
/// The limits: the time budget (`&Budget::DEFAULT`, ten seconds, for the usual
/// requests), checked against the estimate [`star_cost`] (the 2D sweep's cells at
/// [`SWEEP_RATE`], [`dem::work_estimate`] for `d >= 3` at [`STAR_RATE`], both on two cores)
/// in `O(1)` before anything is allocated, and a progress report for `d >= 3` (see
/// [`dem::star_dem`]). With a budget of ten minutes `d = 6` takes up to 1893 points
/// (estimated 71 s for 1000 Sobol' points, which took 86 s on two cores at a load of 1.5).
///
/// # Errors
/// [`Error::TooManyPoints`] when the estimated time exceeds the budget (`max`: the largest
/// `N` within it, [`max_points`]); [`Error::TooLarge`] for two or more counted points
/// in more than [`dem::DEM_MAX_DIMS`] dimensions; [`Error::OutOfTime`] when the run passes
/// the deadline of the budget (started here if the caller did not: `1.25 x` its seconds),
/// checked once per column of the 2D sweep and every few cells of the decomposition.
///
/// ```
/// use qmckit::work::Budget;
/// use qmckit::analysis::{Points, star::star_exact};
/// // One point at the center of the cube: the closed box [0, 1/2]^3 holds it,
/// // 1 - 1/8 = 7/8; every box missing it has volume at most 1/2.
/// let p = Points::new(&[0.5, 0.5, 0.5], 3)?;
/// assert_eq!(star_exact(p, &Budget::DEFAULT)?, 0.875);
/// let tiny = Budget::seconds(1e-12)?;
/// assert!(star_exact(p, &tiny).is_err()); // past the budget
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn star_exact<'a>(points: Points<'_>, limits: impl Into<Limits<'a>>) -> Result<f64> {
    let limits = limits.into();
    let budget = limits.budget();
    let n = points.len();
    match points.dims() {
        1 => star_1d(points),
        2 => {
            if budget
                .check("the exact star discrepancy", star_cost(n, 2))
                .is_err()
            {
                return Err(Error::TooManyPoints {
                    requested: n as u64,
                    max: max_points(2, budget),
                });
            }
            sweep::sweep_2d(points, &Stop::new(budget, "the exact star discrepancy"))
        }
        _ => dem::star_dem(points, limits),
    }
}

/// The largest `N` whose exact star discrepancy in `d` dimensions is estimated
/// ([`star_cost`]) within `budget`: unlimited (`u64::MAX`) for `d <= 1`, the largest `N`
/// with `(N + 1)^2 <= cells` in 2D (`cells` the budget's cells at [`SWEEP_RATE`] on two
/// cores), [`dem::max_points`] for `d >= 3`. `O(1)` for `d <= 2`, a binary search of
/// 40 estimates otherwise.
///
/// ```
/// use qmckit::{work::Budget, analysis::star::max_points};
/// assert_eq!(max_points(2, &Budget::DEFAULT), 114_016);
/// assert_eq!(max_points(6, &Budget::DEFAULT), 557);
/// ```
pub fn max_points(d: usize, budget: &Budget) -> u64 {
    match d {
        0 | 1 => u64::MAX,
        2 => cost::max_points_2d(budget),
        _ => dem::max_points(d, budget),
    }
}

/// A guaranteed upper bound on `D*_N`, at most `D*_N + δ`: the upper end of
/// [`thiemard::bounds`], Thiémard's δ-bracketing cover (E.
/// Thiémard 2001, "An algorithm to compute bounds for the star discrepancy", J. Complexity
/// 17(4)).
///
/// The cube is covered by brackets `[α, β]` with `vol([0,β)) - vol([0,α)) <= δ`; for every
/// `y` in a bracket `|A(y)/N - vol(y)| <= max(A(β)/N - vol(α), vol(β) - A(α)/N)` with
/// `A(c)` the points in `[0, c)`, and the maximum over the brackets is the bound (rounding of
/// the volumes accounted for, so it is `>= D*_N` in floating point too). The brackets are
/// generated recursively and each level of the recursion only sees the points still
/// inside its region; see [`thiemard`] for the construction, the cost and the
/// matching lower bound. Use it for sets too large for [`star_exact`]; within the budget
/// `δ` reaches about `0.0002` in 2D, `0.08` in 5D, `0.4` in 10D and `0.7` in 20D for
/// `N = 1000` (so from 5D on the bound is little more than `δ`).
///
/// # Errors
/// Those of [`thiemard::bounds`]: [`Error::Unsupported`] for `δ`
/// not in `(0, 1]`; [`Error::TooManyPoints`] when the estimated time exceeds
/// [`Budget::DEFAULT`] (take a larger `δ`; [`thiemard::bounds`] takes a budget).
///
/// ```
/// use qmckit::analysis::{Points, star::star_upper_bound};
/// // One point at 1/2 in 1D has D* = 1/2; the bound is within delta of it.
/// let u = star_upper_bound(Points::new(&[0.5], 1)?, 0.01)?;
/// assert!(0.5 <= u && u <= 0.51 + 1e-12);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn star_upper_bound(points: Points<'_>, delta: f64) -> Result<f64> {
    thiemard::bounds(points, delta, &Budget::DEFAULT).map(|b| b.upper)
}
