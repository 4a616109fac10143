//! The rank test: the exact t-value of a base-2 digital net from its generator matrices, as
//! a depth-first search over shapes on an explicit stack, with its cost estimated first.
//!
//! A base-2 digital net ([`DigitalNet2`]) with `2^m` points is a (t, m, s)-net if and only
//! if, for every shape `(d_1, .., d_s)` with `d_1 + .. + d_s = m - t`, the first `d_j` rows
//! of each generator matrix `C_j` (restricted to the first `m` columns) are linearly
//! independent over GF(2) (Niederreiter 1992, Lemma 4.52; Pirsic & Schmid 2001). The search
//! looks for the smallest *dependent* shape; its size is `m - t + 1`.

use super::DigitalNet2;
use crate::Result;
use crate::work::{Budget, Cost, Limits, Progress, Rate, Stop, no_progress};

/// Steps per second of the rank test's search: a step is one row inserted into the
/// elimination (at most `m` XORs) or one search node entered (a 128-byte copy). Measured
/// `4.5e7` to `4.7e7` a second on Sobol' nets with `m = 32`, `d = 8, 10, 12` (1.5e7 to
/// 4.1e7 steps in 0.33 to 0.88 s; release build, one core of two shared).
pub const RANK_TEST_RATE: Rate = Rate::per_second(4e7);

/// The `total` of the rank test's progress reports.
pub const PROGRESS_STEPS: usize = 1000;

/// The part of the budget (at most this many seconds, and at most an eighth of it) spent on
/// each of the searches that bound the full search's cost before it is estimated: those
/// over the first dimensions, and a first slice of the full search.
const SEED_SECONDS: f64 = 0.1;

/// An echelon basis of GF(2) row vectors of width <= 32, indexed by leading bit.
#[derive(Clone, Copy)]
struct Basis([u32; 32]);

impl Basis {
    /// Adds `v`; false if `v` is in the span (the rows became dependent). At most 32 XORs.
    fn insert(&mut self, mut v: u32) -> bool {
        while v != 0 {
            let p = 31 - v.leading_zeros() as usize;
            match self.0.get_mut(p) {
                Some(slot) if *slot == 0 => {
                    *slot = v;
                    return true;
                }
                Some(slot) => v ^= *slot,
                None => return false,
            }
        }
        false
    }
}

/// The exact t-value of a base-2 digital net by the rank test (see the [module docs](self)),
/// within the budget of `limits` (`&Budget::DEFAULT`: ten seconds), reporting
/// `progress(done, PROGRESS_STEPS)` now and then (from the calling thread) when `limits`
/// has a progress callback.
///
/// Searches the shapes `(d_1, .., d_s)` depth-first, dimension by dimension, adding the
/// rows of each `C_j` one at a time to an incremental Gaussian elimination (rows are `m`-bit
/// masks, one insertion at most `m` XORs), so shapes sharing a prefix share their work; a
/// branch stops at its first dependent row, and shapes as large as the smallest dependent
/// shape found so far are pruned. The result is `m + 1 - (size of the smallest dependent
/// shape)`, or 0 when every shape of size `m` is independent.
///
/// Microseconds for `s = 2, 3` and `m <= 32`, about 20 000 nodes for `s = 5, m = 16`.
/// Memory `O(s)` (an explicit stack, no recursion).
///
/// # Cost
/// The search visits a node `(j, (d_1, .., d_j))` only while its size can still grow below
/// the smallest dependent shape `S` found so far, so with `P = |S| - 1` there are at most
/// `sum_(j <= s) C(P + j, j) = C(P + s + 1, s)` nodes that insert rows, each with at most
/// `m + 1` steps ([`RANK_TEST_RATE`]). Before the search, `S` is bounded by a dependent
/// shape of the first `1, 2, 4, ..` dimensions (a dependent shape of a projection is one of
/// the whole net), each found by the same search within a small part of the budget; the
/// full search is then started with that bound, which leaves its result unchanged (every
/// shape smaller than the bound is visited in the same order). After a first slice of it
/// (at most 0.1 s, or an eighth of the budget), the rest is refused if
/// `C(P + s + 1, s) (m + 2)` steps, with the bound found so far, exceed the budget. For Sobol' nets: `m = 2` in 21201
/// dimensions (`P = 0`) takes milliseconds; `m = 32` in 50 dimensions or `m = 20` in 1000 are
/// refused in milliseconds (more than `10^15` steps).
///
/// # Errors
/// [`crate::Error::OverBudget`] when the estimate exceeds the budget; [`crate::Error::TooLarge`] when the
/// search's rows (`4 m s` bytes) or stack (`140 s` bytes) would pass
/// [`crate::size::MAX_ALLOC_BYTES`]; [`crate::Error::OutOfTime`] past the deadline of
/// the budget (started here if it was not), read every 4096 steps of the search.
///
/// ```
/// use qmckit::work::Budget;
/// use qmckit::digital::{DigitalNet2, rank::t_value};
/// // Larcher–Pillichshammer and Hammersley are (0, m, 2)-nets; 2D Sobol' too.
/// assert_eq!(t_value(&DigitalNet2::larcher_pillichshammer(4)?, &Budget::DEFAULT)?, 0);
/// assert_eq!(t_value(&DigitalNet2::from_sobol(2, 10)?, &Budget::DEFAULT)?, 0);
/// // Joe–Kuo Sobol' in 3D has t = 1 for m >= 2.
/// let net = DigitalNet2::from_sobol(3, 10)?;
/// assert_eq!(t_value(&net, &Budget::DEFAULT)?, 1);
/// let big = DigitalNet2::from_sobol(50, 32)?;
/// assert!(t_value(&big, &Budget::DEFAULT).is_err()); // at once
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn t_value<'a>(net: &DigitalNet2, limits: impl Into<Limits<'a>>) -> Result<u32> {
    let limits = limits.into();
    let search = dependent_search(net, limits.budget(), limits.progress())?;
    Ok(net.m() + 1 - search.best)
}

/// The smallest shape `(d_1, .., d_s)` whose rows are linearly dependent, whose size is
/// `m - t + 1` for [`t_value`] `t`, i.e. the shape of the elementary intervals (of volume
/// `2^(t - 1 - m)`) that the net fails to balance; `None` for a (0, m, s)-net. The first
/// such shape in the depth-first order of [`t_value`] (same cost, same budget).
///
/// # Errors
/// As [`t_value`].
///
/// ```
/// use qmckit::digital::{DigitalNet2, rank::dependent_shape};
/// use qmckit::work::Budget;
/// assert_eq!(dependent_shape(&DigitalNet2::hammersley(6)?, &Budget::DEFAULT)?, None);
/// let s = dependent_shape(&DigitalNet2::from_sobol(3, 6)?, &Budget::DEFAULT)?.unwrap();
/// assert_eq!(s.iter().sum::<u32>(), 6); // t = 1: a shape of size m - t + 1 = 6
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn dependent_shape<'a>(
    net: &DigitalNet2,
    limits: impl Into<Limits<'a>>,
) -> Result<Option<Vec<u32>>> {
    let limits = limits.into();
    Ok(dependent_search(net, limits.budget(), limits.progress())?.shape)
}

/// An upper bound on the steps of the search over `s` dimensions of `m` rows when it only
/// visits shapes smaller than `best`: `C(P + s + 1, s) (m + 2)`, `P = best - 2` (no step
/// when `best <= 1`).
pub fn rank_test_steps(m: u32, s: usize, best: u32) -> f64 {
    if best < 2 {
        return 1.0;
    }
    // C(P + s + 1, P + 1) = prod_(i = 1..=P+1) (s + i) / i.
    let mut c = 1.0f64;
    for i in 1..=(best - 1) {
        c *= (s as f64 + f64::from(i)) / f64::from(i);
    }
    c * f64::from(m + 2)
}

/// The result of a search: the size of the smallest dependent shape (`m + 1` if none) and
/// the first such shape in depth-first order.
struct Found {
    best: u32,
    shape: Option<Vec<u32>>,
}

/// The rows of `net`: `rows[j][r]` is row `r` of dimension `j` as an `m`-bit mask.
fn rows_of(net: &DigitalNet2) -> Result<Vec<Vec<u32>>> {
    let m = net.m();
    crate::size::bytes(net.dims(), core::mem::size_of::<Vec<u32>>())?;
    crate::size::bytes(
        crate::size::product("rows", u64::from(m), net.dims() as u64)?,
        4,
    )?;
    Ok((0..net.dims())
        .map(|j| (0..m).map(|r| net.row(j, r)).collect())
        .collect())
}

/// The bounded search of [`t_value`]: seeds from the first dimensions, a first
/// slice of the full search, the estimate of the rest, then the rest.
fn dependent_search(net: &DigitalNet2, budget: &Budget, progress: Progress<'_>) -> Result<Found> {
    let m = net.m();
    let s = net.dims();
    crate::size::bytes(s + 1, core::mem::size_of::<Frame>())?;
    let rows = rows_of(net)?;
    let stop = Stop::new(budget, "the rank test (t-value)");
    let budget_steps = budget.steps(RANK_TEST_RATE);
    let slice = (budget_steps / 8.0).min(SEED_SECONDS * RANK_TEST_RATE.steps_per_second());
    // Seeds: searches over the first 1, 2, 4, .. dimensions, each bounded by the last.
    let mut best = m + 1;
    let mut k = 1usize;
    while k < s {
        if rank_test_steps(m, k, best) > slice {
            break;
        }
        let mut seed = Searcher::new(rows.get(..k).unwrap_or(&[]), best);
        seed.run(u64::MAX, &no_progress, 0.0, &stop)?;
        best = seed.found.best;
        k *= 2;
    }
    // The bound seeds the full search one above the seed's size, so that a shape of that
    // size is still found in depth-first order.
    let start = if best <= m { best + 1 } else { m + 1 };
    let mut full = Searcher::new(&rows, start);
    let total = rank_test_steps(m, s, start);
    // A first slice of the search often finds smaller dependent shapes, which tighten the
    // bound on the rest.
    if !full.run(slice as u64, progress, total, &stop)? {
        let rest = rank_test_steps(m, s, full.found.best);
        budget.check("the rank test (t-value)", Cost::steps(rest, RANK_TEST_RATE))?;
        full.run(u64::MAX, progress, rest + full.steps as f64, &stop)?;
    }
    progress(PROGRESS_STEPS, PROGRESS_STEPS);
    Ok(full.found)
}

/// A node of the search: dimension `j`, the basis of the rows of dimensions `< j` (and, once
/// `r > 0`, the first `r` rows of dimension `j`), the size so far, and `r`: `None` before
/// the child with `d_j = 0`, then the next row count to try.
#[derive(Clone, Copy)]
struct Frame {
    j: usize,
    size: u32,
    basis: Basis,
    r: Option<u32>,
}

/// Depth-first search over the shapes of `rows` for the smallest dependent one, visiting
/// only shapes smaller than `found.best` (start with `m + 1` for no bound), on an explicit
/// stack, resumable. The order is that of the recursion "child `d_j = 0`, then
/// `d_j = 1, 2, ..` with the rows added one at a time, stopping at the first dependent row
/// or the size bound". A node whose size cannot grow below the bound has no dependent shape
/// below it and is skipped.
struct Searcher<'a> {
    rows: &'a [Vec<u32>],
    found: Found,
    current: Vec<u32>,
    stack: Vec<Frame>,
    steps: u64,
}

impl<'a> Searcher<'a> {
    fn new(rows: &'a [Vec<u32>], best: u32) -> Self {
        let mut stack = Vec::with_capacity(rows.len().min(1 << 16) + 1);
        stack.push(Frame {
            j: 0,
            size: 0,
            basis: Basis([0; 32]),
            r: None,
        });
        Searcher {
            rows,
            found: Found { best, shape: None },
            current: vec![0; rows.len()],
            stack,
            steps: 0,
        }
    }

    /// Runs at most `max_steps` more steps; true once the search is complete. `progress`
    /// gets `steps / total` in [`PROGRESS_STEPS`] now and then; the deadline of `stop` is
    /// read every 4096 steps.
    ///
    /// # Errors
    /// [`crate::Error::OutOfTime`] once the deadline passes.
    fn run(
        &mut self,
        max_steps: u64,
        progress: Progress<'_>,
        total: f64,
        stop: &Stop,
    ) -> Result<bool> {
        let s = self.rows.len();
        let end = self.steps.saturating_add(max_steps);
        while let Some(f) = self.stack.last_mut() {
            if self.steps >= end {
                return Ok(false);
            }
            self.steps += 1;
            if self.steps.is_multiple_of(4096) && stop.check() {
                return Err(stop.error());
            }
            if self.steps.is_multiple_of(1 << 16) && total > 0.0 {
                let done = (self.steps as f64 / total * PROGRESS_STEPS as f64) as usize;
                progress(done.min(PROGRESS_STEPS - 1), PROGRESS_STEPS);
            }
            let j = f.j;
            if j >= s {
                self.stack.pop();
                continue;
            }
            if f.size + 1 >= self.found.best {
                // No row can be added below the bound: nothing below this node is smaller.
                if let Some(slot) = self.current.get_mut(j) {
                    *slot = 0;
                }
                self.stack.pop();
                continue;
            }
            let Some(r) = f.r else {
                // d_j = 0.
                f.r = Some(0);
                let child = Frame {
                    j: j + 1,
                    size: f.size,
                    basis: f.basis,
                    r: None,
                };
                self.stack.push(child);
                continue;
            };
            let row = self.rows.get(j).and_then(|x| x.get(r as usize)).copied();
            let next = f.size + r + 1;
            let Some(row) = row.filter(|_| next < self.found.best) else {
                // No row left in this dimension, or the bound: d_j is done.
                if let Some(slot) = self.current.get_mut(j) {
                    *slot = 0;
                }
                self.stack.pop();
                continue;
            };
            if let Some(slot) = self.current.get_mut(j) {
                *slot = r + 1;
            }
            if !f.basis.insert(row) {
                self.found.best = next;
                self.found.shape = Some(self.current.clone());
                if let Some(slot) = self.current.get_mut(j) {
                    *slot = 0;
                }
                self.stack.pop();
                continue;
            }
            f.r = Some(r + 1);
            let child = Frame {
                j: j + 1,
                size: next,
                basis: f.basis,
                r: None,
            };
            self.stack.push(child);
        }
        Ok(true)
    }
}
