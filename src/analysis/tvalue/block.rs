//! The t-value of a block of a base-`b` digital sequence, by counting points in elementary
//! intervals with the exact coordinates.

use crate::analysis::Points;
use crate::analysis::tvalue::{t_value_cost, t_value_points};
use crate::digital::DigitalNetB;
use crate::error::{Error, Result};
use crate::work::Budget;

/// The t-value in base `b` of points `start .. start + b^m` of `net`: the smallest `t`
/// such that every elementary interval of volume `b^(t-m)` holds `b^t` of them.
///
/// Only `floor(x b^m)` decides which interval of volume `>= b^-m` holds a point, and it is
/// taken from the exact coordinate [`DigitalNetB::value`] (`v / b^K`), so the count is
/// exact although the 0.32 samples round (`1/3` would fall below its interval). Cost:
/// [`t_value_cost`] (the levels of the binary
/// search, each about `C(rho + s - 1, s - 1) b^m (s + 1)` steps), checked against `budget`
/// before any work.
///
/// ```
/// use qmckit::work::Budget;
/// use qmckit::analysis::tvalue::t_value_block;
/// use qmckit::digital::DigitalNetB;
/// let f = DigitalNetB::faure(5, 4)?;
/// assert_eq!(t_value_block(&f, 0, 3, &Budget::DEFAULT)?, 0); // a (0, 3, 4)-net in base 5
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::MTooLarge`] when `b^m` points do not fit from `start` or `b^m > 2^53`;
/// [`Error::OverBudget`]; errors of the counting.
pub fn t_value_block<M: AsRef<[u16]>>(
    net: &DigitalNetB<M>,
    start: u32,
    m: u32,
    budget: &Budget,
) -> Result<u32> {
    use crate::Sampler;
    let b = net.base() as u64;
    let too_large = Error::MTooLarge { m, max: 32 };
    let n = b.checked_pow(m).ok_or(too_large)?;
    if n > 1 << 53 || start as u64 + n > net.len() {
        return Err(too_large);
    }
    let s = net.dims();
    budget.check(
        "counting points in elementary intervals",
        t_value_cost(n, s, m, net.base(), None),
    )?;
    let (k, _) = crate::digital::output_digits(net.base())?;
    let drop = b.pow((k as u32).saturating_sub(m));
    let cells = n as f64;
    let mut x = crate::size::vec_zeroed(crate::size::coordinates(n, s)?)?;
    for (i, row) in x.chunks_exact_mut(s).enumerate() {
        for (dim, slot) in row.iter_mut().enumerate() {
            // The centre of the point's cell of side b^-m: same intervals, exact in f64.
            let cell = net.value(start + i as u32, dim)? / drop;
            *slot = (cell as f64 + 0.5) / cells;
        }
    }
    t_value_points(Points::new(&x, s)?, net.base(), m, budget)
}
