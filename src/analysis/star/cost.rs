//! The calibrated rates of the star-discrepancy family, shared by its modules (see
//! [`crate::analysis::budget`] for the mechanism).
//!
//! Each rate converts a counted number of inner-loop steps into seconds. They were measured
//! with the release build on two cores shared with other work, so they are conservative for
//! an idle machine.

use crate::analysis::budget::Rate;

/// Steps per second of the exact algorithms: `N^2` sweep steps in 2D, the units of
/// [`super::dem::work_estimate`] for `d >= 3`. 40000 3D Sobol' points (estimate `1e10`...)
/// and the other rows of [`super::dem`] fit `3e8` steps a second: the default budget of ten
/// seconds admits `3e9` steps (`N <= 54772` in 2D, where `2^14` points take about one
/// second).
pub const STAR_RATE: Rate = Rate::per_second(3e8);

/// Point-coordinate comparisons per second of Thiémard's cover ([`super::thiemard`]), with
/// their share of list filtering and region bookkeeping: `2e8`, two thirds of
/// [`STAR_RATE`] (measured on the rows of [`super::thiemard::bounds`]).
pub const THIEMARD_RATE: Rate = Rate::per_second(2e8);

/// Point-coordinate steps per second of threshold accepting
/// ([`super::star_lower_bound`]): one step is one coordinate of one point scored against one
/// box, `3e8` a second (20000 iterations on 1000 Sobol' points in 20D, `4e8` steps, took
/// 0.9 s; on 10000 points, `4e9` steps, 11 s).
pub const LOWER_BOUND_RATE: Rate = Rate::per_second(3e8);
