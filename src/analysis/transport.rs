//! The semi-discrete optimal-transport distance between a 2D point set and the uniform
//! measure of the unit square.
//!
//! ## The measure
//!
//! For points `p_1..p_N` of `[0, 1]^2`, each of mass `1/N`, and the uniform measure `mu`
//! of the square,
//!
//! `W_2(mu, (1/N) sum_i delta_p_i)^2 = min sum_i int_{C_i} |x - p_i|^2 dx`
//!
//! over partitions of the square into cells `C_i` of area `1/N`; the optimal cells are
//! the Laguerre cells of the weights that solve the semi-discrete transport problem
//! (Aurenhammer, Hoffmann & Aronov 1998; Mérigot 2011), found by damped Newton
//! (Kitagawa, Mérigot & Thibert 2019) in [`crate::blue_noise::transport`], and the
//! integrals are exact for polygons ([`crate::blue_noise::power`]). [`ot_distance`]
//! returns `W_2`, the square root; [`ot_cost`] the square. The capacities are met to
//! `max_i |N A_i - 1| <= 1e-9`, which moves the cost by at most about `1e-9` times the
//! squared cell diameter a point.
//!
//! Closed forms that check it (tested): one point `p` gives
//! `int |x - p|^2 = 2/3 - (p_x + p_y) + p_x^2 + p_y^2`; the `k x k` grid of cell centres
//! gives `N` squares of side `1/k`, `W_2^2 = 1/(6 N)`. Uniform random points give about
//! `c / N` with a logarithmic factor (Ajtai, Komlós & Tusnády 1984), jittered grids
//! less, BNOT's points (which minimize it) least.
//!
//! ## Range and cost
//!
//! 2D only, 1 to 2^20 distinct points (equal points have no transport plan of this kind:
//! an error). The cost of one cold transport solve ([`crate::blue_noise::transport::cost`]),
//! estimated and stopped at the budget's deadline: 0.5 to 0.9 s for 4096 points
//! (measured on two cores shared with other work).
//!
//! ```
//! use qmckit::analysis::{Points, transport::ot_distance};
//! use qmckit::work::Budget;
//! // The 2 x 2 grid of cell centres: W_2 = sqrt(1 / 24).
//! let p = Points::new(&[0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75], 2)?;
//! let w = ot_distance(p, &Budget::DEFAULT)?;
//! assert!((w - (1.0f64 / 24.0).sqrt()).abs() < 1e-12);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::Points;
use crate::blue_noise::transport::{self, DEFAULT_TOLERANCE};
use crate::work::Budget;
use crate::{Error, Result};

/// `W_2^2` between `points` (2D, mass `1/N` each) and the uniform measure of the unit
/// square.
///
/// # Errors
/// [`Error::DimensionOutOfRange`] for points that are not 2D; [`Error::InvalidParameter`]
/// for equal points; the solve's [`Error::OverBudget`], [`Error::OutOfTime`],
/// [`Error::TooManyPoints`].
pub fn ot_cost(points: Points<'_>, budget: &Budget) -> Result<f64> {
    if points.dims() != 2 {
        return Err(Error::DimensionOutOfRange {
            dim: points.dims(),
            dims: 2,
        });
    }
    let t = transport::solve(points.as_slice(), false, DEFAULT_TOLERANCE, budget)?;
    Ok(t.cost())
}

/// `W_2` between `points` and the uniform measure of the unit square: the square root of
/// [`ot_cost`].
///
/// # Errors
/// As [`ot_cost`].
pub fn ot_distance(points: Points<'_>, budget: &Budget) -> Result<f64> {
    Ok(ot_cost(points, budget)?.sqrt())
}
