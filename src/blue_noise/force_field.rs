//! The forced-random dither matrix (Purgathofer, Tobler & Geiler, "Forced random
//! dithering: improved threshold matrices for ordered dithering", ICIP 1994), the forcing
//! matrix of forced random sampling (Cornel et al. 2017).
//!
//! ## The construction
//!
//! An `R x R` toroidal matrix is filled with the ranks `0, 1, ..., R^2 - 1` one cell at a
//! time. Every placed cell `p` adds the repulsive force `f(|c - p|)` to every cell `c`
//! (toroidal distance, in cells), with the heavy-tailed
//!
//! ```text
//! f(r) = exp(-sqrt(2 r / w)),
//! ```
//!
//! (the paper's force at width `w = 1`; a wider `w` spaces the sparse thresholds more
//! evenly and the dense ones less)//!
//! and rank `k` goes to the free cell of least accumulated force among a random half of
//! the free cells (a fresh half each rank; the random choice keeps the matrix from locking
//! into a lattice). The force decays slowly enough that the first ranks, spaced many
//! cells apart, still repel each other: every threshold `{c : rank(c) < t R^2}` is an
//! evenly spaced, blue-noise pattern, the sparse ones included (which a Gaussian kernel of
//! fixed width, as in void-and-cluster, spaces less well).
//!
//! ## Cost
//!
//! `R^2` ranks, each a pass over the `R^2` cells to add the force and find the least:
//! `2 R^4` simple integer steps (256 x 256: about 8.6e9, about 20 s), estimated against
//! a [`Budget`] and stopped at its deadline. Memory `3 R^2` words. The forces are fixed
//! point (`2^20` for `f(0)`; the sum of `f` over the plane is below 20, so no cell passes
//! `2^26` for `w <= 4`), so the matrix is the same on every machine.
//!
//! ```
//! use qmckit::blue_noise::force_field::force_field_ranks;
//! use qmckit::work::Budget;
//! let ranks = force_field_ranks(16, 1.0, 1, &Budget::DEFAULT)?;
//! let mut sorted = ranks.clone();
//! sorted.sort_unstable();
//! assert!(sorted.iter().enumerate().all(|(i, &r)| r == i as u32)); // a permutation
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::rng::Rng;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// Cell updates a second (one force addition and one comparison) on one core.
const UPDATES: Rate = Rate::per_second(5e8);

/// `f(0)` in fixed point.
const ONE: f64 = (1u32 << 20) as f64;

/// The forced-random matrix of side `side` (8 to 1024), force width `width` (0.25 to 4;
/// 1 is the paper's) and `seed`: row-major ranks, a permutation of `0..side^2`.
///
/// # Errors
/// [`Error::InvalidParameter`] for a side outside 8 to 1024 or a width outside 0.25 to 4
/// (NaN included); [`Error::OverBudget`] when the
/// `2 side^4` updates exceed `budget`; [`Error::OutOfTime`] past its deadline.
pub fn force_field_ranks(side: usize, width: f64, seed: u64, budget: &Budget) -> Result<Vec<u32>> {
    if !(8..=1024).contains(&side) {
        return Err(Error::InvalidParameter {
            what: "a forced-random matrix's side must be 8 to 1024",
        });
    }
    if !(0.25..=4.0).contains(&width) {
        return Err(Error::InvalidParameter {
            what: "a forced-random matrix's force width must be 0.25 to 4",
        });
    }
    let cells = side * side;
    budget.check(
        "the forced-random matrix",
        Cost::steps(2.0 * (cells as f64) * (cells as f64), UPDATES),
    )?;
    let budget = budget.started();
    // The force of a cell at offset (dx, dy), toroidal, as a table over the torus.
    let mut kernel = crate::size::vec_zeroed::<u32>(cells)?;
    for (i, k) in kernel.iter_mut().enumerate() {
        let (dx, dy) = (i % side, i / side);
        let (dx, dy) = (dx.min(side - dx) as f64, dy.min(side - dy) as f64);
        let r = (dx * dx + dy * dy).sqrt();
        *k = (ONE * (-(2.0 * r / width).sqrt()).exp()).round() as u32;
    }
    let mut field = crate::size::vec_zeroed::<u32>(cells)?;
    // u32::MAX marks a free cell.
    let mut ranks = vec_filled(cells, u32::MAX)?;
    // The random halves: a fixed random bit per cell and rank pattern, read at a random
    // toroidal offset and bit each rank.
    let mut rng = Rng::new(seed, 0x4652_4447_4954_4852); // "FRDGITHR"
    let mut bits = crate::size::vec_zeroed::<u64>(cells)?;
    for b in bits.iter_mut() {
        *b = rng.next_u64();
    }
    for rank in 0..cells {
        if rank % 64 == 0 {
            budget.check_deadline("the forced-random matrix")?;
        }
        let (offset, bit) = (rng.below(cells), rng.below(64));
        // The least force among the free cells of this rank's half (all free cells when
        // the half holds none, near the end).
        let mut best: Option<(u32, usize)> = None;
        let mut any: Option<(u32, usize)> = None;
        let (head, tail) = bits.split_at(offset.min(cells));
        let half = tail.iter().chain(head);
        for (c, ((&f, &r), &b)) in field.iter().zip(ranks.iter()).zip(half).enumerate() {
            if r != u32::MAX {
                continue;
            }
            if any.is_none_or(|(g, _)| f < g) {
                any = Some((f, c));
            }
            if (b >> bit) & 1 == 1 && best.is_none_or(|(g, _)| f < g) {
                best = Some((f, c));
            }
        }
        let Some((_, p)) = best.or(any) else {
            break; // unreachable: a free cell remains while rank < cells
        };
        if let Some(slot) = ranks.get_mut(p) {
            *slot = rank as u32;
        }
        // Add the force of p: the kernel shifted to p, row by row.
        let (px, py) = (p % side, p / side);
        for (y, row) in field.chunks_exact_mut(side).enumerate() {
            let ky = (y + side - py) % side;
            let krow = kernel.get(ky * side..(ky + 1) * side).unwrap_or(&[]);
            // Cells x >= px take kernel entries 0.., the others side - px...
            let (left, right) = row.split_at_mut(px.min(side));
            let (kl, kr) = krow.split_at((side - px).min(krow.len()));
            for (v, &k) in right.iter_mut().zip(kl) {
                *v = v.saturating_add(k);
            }
            for (v, &k) in left.iter_mut().zip(kr) {
                *v = v.saturating_add(k);
            }
        }
    }
    Ok(ranks)
}

/// `len` copies of `value`, through the checked allocation.
fn vec_filled(len: usize, value: u32) -> Result<Vec<u32>> {
    let mut v = crate::size::vec_zeroed::<u32>(len)?;
    v.fill(value);
    Ok(v)
}
