//! Counting points in elementary intervals: the t-value of any point set, and the intervals
//! that break a given `t`.

#[cfg(doc)]
use super::cost::{COUNT_RATE, count_steps};
use super::cost::{failures_cost, t_value_cost};
use crate::analysis::Points;
use crate::work::{Limits, Stop};
use crate::{Error, Result};
use core::fmt;
use rayon::prelude::*;

/// An elementary interval that a point set fails to balance: the box
/// `prod_j [cell_j b^-shape_j, (cell_j + 1) b^-shape_j)` holds `count` points where the
/// (t, m, s)-net property asks for `expected`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IntervalFailure {
    /// The base `b`.
    pub base: u32,
    /// `(d_1, .., d_s)`: the box has side `b^-d_j` in dimension `j`.
    pub shape: Vec<u32>,
    /// `(a_1, .., a_s)`, `a_j < b^d_j`: the box's position.
    pub cell: Vec<u64>,
    /// Points found in the box.
    pub count: u64,
    /// Points a net would put there, `b^(m - sum d_j)`.
    pub expected: u64,
}

impl fmt::Display for IntervalFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "shape {:?}: ", self.shape)?;
        for (j, (d, a)) in self.shape.iter().zip(&self.cell).enumerate() {
            if j > 0 {
                write!(f, " x ")?;
            }
            if *d == 0 {
                write!(f, "[0, 1)")?;
            } else {
                write!(f, "[{a}, {})/{}^{d}", a + 1, self.base)?;
            }
        }
        write!(
            f,
            " holds {} point(s), {} expected",
            self.count, self.expected
        )
    }
}

/// Points reduced to their integer digits: `digits[i s + j] = floor(x_j(i) b^m)`.
struct Digits {
    digits: Vec<u64>,
    dims: usize,
    base: u64,
    m: u32,
    /// `pow[k] = b^k`, `k <= m`.
    pow: Vec<u64>,
}

impl Digits {
    /// Index of the cell of point `i` for `shape`, in mixed radix (dimension 0 most
    /// significant); `< b^(sum shape)`.
    #[inline]
    fn cell_index(&self, point: &[u64], shape: &[u32]) -> u64 {
        let mut idx = 0u64;
        if self.base == 2 {
            for (&d, &x) in shape.iter().zip(point) {
                idx = (idx << d) | (x >> (self.m - d));
            }
        } else {
            for (&d, &x) in shape.iter().zip(point) {
                let p = self.pow.get(d as usize).copied().unwrap_or(1);
                let q = self.pow.get((self.m - d) as usize).copied().unwrap_or(1);
                idx = idx * p + x / q;
            }
        }
        idx
    }

    /// Counts per cell of `shape` (size `rho`) into `counts` (resized to `b^rho`).
    fn count(&self, shape: &[u32], rho: u32, counts: &mut Vec<u32>) {
        let cells = self.pow.get(rho as usize).copied().unwrap_or(1) as usize;
        counts.clear();
        counts.resize(cells, 0);
        for p in self.digits.chunks_exact(self.dims) {
            let idx = self.cell_index(p, shape) as usize;
            if let Some(c) = counts.get_mut(idx) {
                *c = c.saturating_add(1);
            }
        }
    }

    /// Whether every shape of size `rho` is balanced (short-circuits on the first failure).
    /// Each shape reads the deadline of `stop` first (one clock reading per `O(N s)`
    /// count); a stopped search answers `false`, to be discarded by the caller.
    fn level_balanced(&self, rho: u32, stop: &Stop) -> bool {
        if rho == 0 {
            return true;
        }
        let expected = self.pow.get((self.m - rho) as usize).copied().unwrap_or(0);
        first_parts(self.dims, rho).into_par_iter().all(|d0| {
            let mut counts = Vec::new();
            let mut ok = true;
            for_each_shape(self.dims, rho, d0, |shape| {
                if stop.check() {
                    ok = false;
                    return false;
                }
                self.count(shape, rho, &mut counts);
                ok = counts.iter().all(|&c| u64::from(c) == expected);
                ok
            });
            ok
        })
    }

    /// The first `limit` unbalanced cells over the shapes of size `rho`, in shape order then
    /// cell order.
    fn failures(&self, rho: u32, limit: usize, stop: &Stop) -> Vec<IntervalFailure> {
        if limit == 0 {
            return Vec::new();
        }
        let expected = self.pow.get((self.m - rho) as usize).copied().unwrap_or(0);
        let per_task: Vec<Vec<IntervalFailure>> = first_parts(self.dims, rho)
            .into_par_iter()
            .map(|d0| {
                let mut counts = Vec::new();
                let mut found = Vec::new();
                for_each_shape(self.dims, rho, d0, |shape| {
                    if stop.check() {
                        return false;
                    }
                    self.count(shape, rho, &mut counts);
                    for (idx, &c) in counts.iter().enumerate() {
                        if u64::from(c) != expected {
                            found.push(IntervalFailure {
                                base: self.base as u32,
                                shape: shape.to_vec(),
                                cell: self.decode(idx as u64, shape),
                                count: u64::from(c),
                                expected,
                            });
                            if found.len() >= limit {
                                return false;
                            }
                        }
                    }
                    true
                });
                found
            })
            .collect();
        per_task.into_iter().flatten().take(limit).collect()
    }

    /// The per-dimension cell coordinates of a mixed-radix cell index.
    fn decode(&self, mut idx: u64, shape: &[u32]) -> Vec<u64> {
        let mut cell = vec![0u64; shape.len()];
        for (slot, &d) in cell.iter_mut().zip(shape).rev() {
            let p = self.pow.get(d as usize).copied().unwrap_or(1);
            *slot = idx % p;
            idx /= p;
        }
        cell
    }

    /// The largest `rho` whose shapes are all balanced, by binary search (balance at `rho`
    /// implies balance at every smaller size).
    ///
    /// # Errors
    /// [`Error::OutOfTime`] once the deadline of `stop` passes.
    fn strength(&self, stop: &Stop) -> Result<u32> {
        let (mut lo, mut hi) = (0u32, self.m); // balanced(lo) holds; answer in [lo, hi]
        while lo < hi {
            let mid = lo + (hi - lo).div_ceil(2);
            let balanced = self.level_balanced(mid, stop);
            stop.result()?;
            if balanced {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        Ok(lo)
    }
}

/// The values of `d_1` for shapes of size `rho` in `dims` dimensions (the parallel split).
pub(super) fn first_parts(dims: usize, rho: u32) -> Vec<u32> {
    if dims <= 1 {
        vec![rho]
    } else {
        (0..=rho).collect()
    }
}

/// Calls `f` on every shape `(d0, d_2, .., d_s)` of size `rho` in lexicographic order, until
/// `f` returns false.
pub(super) fn for_each_shape(dims: usize, rho: u32, d0: u32, mut f: impl FnMut(&[u32]) -> bool) {
    let mut shape = vec![0u32; dims];
    let Some((first, rest)) = shape.split_first_mut() else {
        return;
    };
    *first = d0;
    if let Some(last) = rest.last_mut() {
        *last = rho - d0;
    } else if d0 != rho {
        return;
    }
    loop {
        if !f(&shape) {
            return;
        }
        let Some((_, rest)) = shape.split_first_mut() else {
            return;
        };
        if !next_composition(rest) {
            return;
        }
    }
}

/// The lexicographic successor of a composition (fixed sum and length); false after the
/// last one, `(sum, 0, .., 0)`.
fn next_composition(c: &mut [u32]) -> bool {
    let k = c.len();
    if k < 2 {
        return false;
    }
    let last = c[k - 1];
    if last > 0 {
        c[k - 2] += 1;
        c[k - 1] = last - 1;
        return true;
    }
    let Some(j) = c[..k - 1].iter().rposition(|&x| x > 0) else {
        return false;
    };
    if j == 0 {
        return false;
    }
    let s = c[j];
    c[j] = 0;
    c[j - 1] += 1;
    c[k - 1] = s - 1;
    true
}

/// The name of the count in the errors of the budget.
const COUNTING: &str = "counting points in elementary intervals";

/// Validates `samples` as `2^m` points of `dims` 0.32 fractions.
fn check_u32(samples: &[u32], dims: usize, m: u32) -> Result<()> {
    if dims == 0 {
        return Err(Error::ZeroDimensions);
    }
    if m > 32 {
        return Err(Error::MTooLarge { m, max: 32 });
    }
    let expected = (1u64 << m)
        .checked_mul(dims as u64)
        .and_then(|e| usize::try_from(e).ok())
        .unwrap_or(usize::MAX);
    if samples.len() != expected {
        return Err(Error::BufferLength {
            expected,
            got: samples.len(),
        });
    }
    Ok(())
}

/// [`check_u32`], then reduces the samples to their top `m` bits.
fn digits_u32(samples: &[u32], dims: usize, m: u32) -> Result<Digits> {
    check_u32(samples, dims, m)?;
    let digits = samples.iter().map(|&x| u64::from(x) >> (32 - m)).collect();
    Ok(Digits {
        digits,
        dims,
        base: 2,
        m,
        pow: (0..=m).map(|k| 1u64 << k).collect(),
    })
}

/// The largest `m` with `b^m <= 2^53` (so that `f64` digits are exact).
fn max_m_f64(base: u64) -> u32 {
    let mut m = 0;
    let mut p = 1u64;
    while let Some(q) = p.checked_mul(base).filter(|&q| q <= 1 << 53) {
        p = q;
        m += 1;
    }
    m
}

/// `floor(x B)` for `0 <= x < 1` and an integer `B <= 2^53`, exact for the real product of
/// the stored double (a fused multiply-add gives the sign of `x B - c` exactly).
pub(super) fn exact_floor_mul(x: f64, b: f64) -> f64 {
    let mut c = (x * b).floor();
    if x.mul_add(b, -c) < 0.0 {
        c -= 1.0;
    } else if x.mul_add(b, -(c + 1.0)) >= 0.0 {
        c += 1.0;
    }
    c
}

/// Validates `points` as `b^m` points in `[0, 1)^s` and reduces them to their digits.
fn digits_f64(points: Points, base: u32, m: u32) -> Result<Digits> {
    if base < 2 {
        return Err(Error::BaseTooSmall { base });
    }
    let b = u64::from(base);
    let max = max_m_f64(b).min(32);
    if m > max {
        return Err(Error::MTooLarge { m, max });
    }
    let pow: Vec<u64> = (0..=m).map(|k| b.pow(k)).collect();
    let n = pow.last().copied().unwrap_or(1);
    let dims = points.dims();
    if points.len() as u64 != n {
        return Err(Error::BufferLength {
            expected: usize::try_from(n.saturating_mul(dims as u64)).unwrap_or(usize::MAX),
            got: points.as_slice().len(),
        });
    }
    let scale = n as f64; // exact: n <= 2^53
    let mut digits = Vec::with_capacity(points.as_slice().len());
    for (k, &x) in points.as_slice().iter().enumerate() {
        if x >= 1.0 {
            return Err(Error::CoordinateOutOfRange {
                point: k / dims,
                dim: k % dims,
            });
        }
        let c = exact_floor_mul(x, scale);
        digits.push((c as u64).min(n - 1));
    }
    Ok(Digits {
        digits,
        dims,
        base: b,
        m,
        pow,
    })
}

/// The t-value of `2^m` points given as 0.32 fractions (row-major, `dims` a point), by
/// counting points in elementary intervals; exact (the digits are the bits).
///
/// `t` is the smallest value such that every elementary interval of volume `2^(t - m)`
/// holds exactly `2^t` points (see the [module docs](super)). Works for any point set,
/// scrambled or not; only the top `m` bits of each coordinate matter.
///
/// Cost: a binary search over the interval size `rho = m - t`, about `log2 m` levels; a
/// level counts `N` points into `2^rho` cells for each of its `C(rho + s - 1, s - 1)` shapes,
/// `O(N s)` each, stopping at the first unbalanced shape (rayon over the first side):
/// [`count_steps`] at [`COUNT_RATE`] a second and core.
/// For `s = 2, m = 14`: about 60 shapes of 16 384 points, milliseconds. Memory `8 N s` bytes
/// of digits plus `4 * 2^rho` bytes of counts per thread.
///
/// # Errors
/// [`Error::ZeroDimensions`], [`Error::MTooLarge`] for `m > 32`, [`Error::BufferLength`]
/// unless `samples.len() == 2^m dims`; [`Error::OverBudget`] when [`t_value_cost`] without
/// an expected t-value (every level of the search counted whole) exceeds the budget of
/// `limits` (`&Budget::DEFAULT`: ten seconds), checked before the digits are made;
/// [`Error::OutOfTime`] past its deadline.
///
/// ```
/// use qmckit::analysis::tvalue::t_value_u32;
/// use qmckit::work::Budget;
/// use qmckit::{LarcherPillichshammer, Sampler};
/// let lp = LarcherPillichshammer::new(4)?;
/// let mut pts = vec![0u32; 2 * 16];
/// lp.fill(0, &mut pts)?;
/// assert_eq!(t_value_u32(&pts, 2, 4, &Budget::DEFAULT)?, 0); // LP is a (0, m, 2)-net
/// pts.swap(1, 17); // swap two y values: (0, 15/16), (1/2, 0)
/// assert!(t_value_u32(&pts, 2, 4, &Budget::DEFAULT)? > 0);
/// let pts = vec![0u32; 4 << 10]; // 2^10 points at the origin in 4D
/// assert_eq!(t_value_u32(&pts, 4, 10, &Budget::DEFAULT)?, 10);
/// let tiny = Budget::seconds(1e-6)?;
/// assert!(t_value_u32(&pts, 4, 10, &tiny).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn t_value_u32<'a>(
    samples: &[u32],
    dims: usize,
    m: u32,
    limits: impl Into<Limits<'a>>,
) -> Result<u32> {
    t_value_u32_expecting(samples, dims, m, None, limits)
}

/// [`t_value_u32`] for a set whose t-value is expected to be `expected_t` (e.g. a
/// scrambled net: Owen scrambling, digital shifts and linear matrix scrambles keep the
/// t-value of the net, which the rank test gives): the estimate, [`t_value_cost`], follows
/// the search such a set takes, so it is about the real time instead of the most any set
/// takes. The result does not depend on `expected_t`; a wrong guess only makes the estimate
/// wrong, and the deadline of the budget (started here if it was not) bounds the run.
///
/// # Errors
/// As [`t_value_u32`]; [`Error::OutOfTime`] past the deadline (read once per shape).
///
/// ```
/// use qmckit::work::Budget;
/// use qmckit::analysis::tvalue::t_value_u32_expecting;
/// let pts = vec![0u32; 2 << 12]; // 2^12 points at the origin in 2D: t = 12
/// assert_eq!(t_value_u32_expecting(&pts, 2, 12, Some(12), &Budget::DEFAULT)?, 12);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn t_value_u32_expecting<'a>(
    samples: &[u32],
    dims: usize,
    m: u32,
    expected_t: Option<u32>,
    limits: impl Into<Limits<'a>>,
) -> Result<u32> {
    let limits = limits.into();
    let budget = limits.budget();
    check_u32(samples, dims, m)?;
    budget.check(COUNTING, t_value_cost(1u64 << m, dims, m, 2, expected_t))?;
    let d = digits_u32(samples, dims, m)?;
    Ok(m - d.strength(&Stop::new(budget, COUNTING))?)
}

/// The t-value in base `base` of `base^m` points in `[0, 1)^s`, by counting points in
/// elementary intervals (see [`t_value_u32`] for the method and cost).
///
/// Each coordinate is reduced once to `floor(x b^m)`, computed exactly for the real value of
/// the stored double (a floor of the rounded product, corrected by the sign of an exact
/// fused multiply-add); the cell at resolution `b^-d` is then `floor(floor(x b^m) / b^(m-d))`,
/// exact too. For `b = 2` (or any power of two) dyadic inputs such as converted 0.32
/// fractions are therefore classified exactly. For other bases the *stored* value decides:
/// a point meant to be `a / 3^k` but stored (or truncated) just below it lands in the cell
/// below, so give such points as cell midpoints or offsets, not rounded boundaries.
///
/// # Errors
/// [`Error::BaseTooSmall`], [`Error::MTooLarge`] (beyond `b^m <= 2^53` or `m > 32`),
/// [`Error::BufferLength`] unless there are exactly `b^m` points, and
/// [`Error::CoordinateOutOfRange`] for a coordinate equal to 1 (it lies in no elementary
/// interval); [`Error::OverBudget`] past the budget of `limits` (`&Budget::DEFAULT`: ten
/// seconds; checked before counting), [`Error::OutOfTime`] past its deadline (read once per
/// shape counted).
///
/// ```
/// use qmckit::analysis::{Points, tvalue::t_value_points};
/// use qmckit::work::Budget;
/// // The 3 x 3 grid of cell centres is a (0, 2, 2)-net in base 3? No: t = 1
/// // (the interval [0, 1/9) x [0, 1) is empty); the 9 points (i/9 + 1/18, phi_3(i) + 1/18)
/// // of Hammersley in base 3 are a (0, 2, 2)-net.
/// let grid: Vec<f64> = (0..9).flat_map(|i| [(i / 3) as f64 / 3.0 + 1.0 / 6.0,
///                                           (i % 3) as f64 / 3.0 + 1.0 / 6.0]).collect();
/// assert_eq!(t_value_points(Points::new(&grid, 2)?, 3, 2, &Budget::DEFAULT)?, 1);
/// let ham: Vec<f64> = (0..9).flat_map(|i| [i as f64 / 9.0 + 1.0 / 18.0,
///                                          ((i % 3) * 3 + i / 3) as f64 / 9.0 + 1.0 / 18.0])
///                           .collect();
/// assert_eq!(t_value_points(Points::new(&ham, 2)?, 3, 2, &Budget::DEFAULT)?, 0);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn t_value_points<'a>(
    points: Points,
    base: u32,
    m: u32,
    limits: impl Into<Limits<'a>>,
) -> Result<u32> {
    let limits = limits.into();
    let budget = limits.budget();
    let d = digits_f64(points, base, m)?;
    let n = d.pow.last().copied().unwrap_or(1);
    budget.check(COUNTING, t_value_cost(n, d.dims, m, base, None))?;
    Ok(m - d.strength(&Stop::new(budget, COUNTING))?)
}

/// The first `limit` elementary intervals of volume `2^(t - m)` that do not hold exactly
/// `2^t` of the `2^m` points (0.32 fractions, row-major); empty if and only if the set is a
/// (t, m, s)-net. Ordered by shape (lexicographic in `(d_1, .., d_s)`), then by cell.
/// To name why a set has t-value `t`, ask for `t - 1`.
///
/// Cost: every shape of size `m - t`, `O(N s + 2^(m - t))` each (see [`t_value_u32`]).
///
/// # Errors
/// As [`t_value_u32`] (one level, [`failures_cost`], within the budget of `limits`, checked
/// before the digits are made), and [`Error::MTooLarge`] for `t > m` (reported as
/// `m: t, max: m`).
///
/// ```
/// use qmckit::analysis::tvalue::elementary_interval_failures_u32;
/// use qmckit::work::Budget;
/// // Four points all in [0, 1/2) x [0, 1/2): not a (0, 2, 2)-net, nor a (1, 2, 2)-net.
/// let pts = [0u32, 0, 1 << 29, 1 << 30, 1 << 30, 1 << 29, 3 << 29, 3 << 29];
/// let f = elementary_interval_failures_u32(&pts, 2, 2, 1, 10, &Budget::DEFAULT)?;
/// assert_eq!((f[0].shape.clone(), f[0].cell.clone(), f[0].count, f[0].expected),
///            (vec![0, 1], vec![0, 0], 4, 2));
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn elementary_interval_failures_u32<'a>(
    samples: &[u32],
    dims: usize,
    m: u32,
    t: u32,
    limit: usize,
    limits: impl Into<Limits<'a>>,
) -> Result<Vec<IntervalFailure>> {
    let limits = limits.into();
    let budget = limits.budget();
    check_u32(samples, dims, m)?;
    if t > m {
        return Err(Error::MTooLarge { m: t, max: m });
    }
    budget.check(COUNTING, failures_cost(1u64 << m, dims, m - t, 2))?;
    let d = digits_u32(samples, dims, m)?;
    let stop = Stop::new(budget, COUNTING);
    let found = d.failures(m - t, limit, &stop);
    stop.finish(found)
}

/// [`elementary_interval_failures_u32`] for `b^m` points given as `f64` in base `base`
/// (digits as in [`t_value_points`]).
///
/// # Errors
/// As [`t_value_points`] (one level, [`failures_cost`], within the budget of `limits`), and
/// [`Error::MTooLarge`] for `t > m`.
pub fn elementary_interval_failures<'a>(
    points: Points,
    base: u32,
    m: u32,
    t: u32,
    limit: usize,
    limits: impl Into<Limits<'a>>,
) -> Result<Vec<IntervalFailure>> {
    let limits = limits.into();
    let budget = limits.budget();
    let d = digits_f64(points, base, m)?;
    if t > m {
        return Err(Error::MTooLarge { m: t, max: m });
    }
    let n = d.pow.last().copied().unwrap_or(1);
    budget.check(COUNTING, failures_cost(n, d.dims, m - t, base))?;
    let stop = Stop::new(budget, COUNTING);
    let found = d.failures(m - t, limit, &stop);
    stop.finish(found)
}
