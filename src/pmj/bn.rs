//! PMJ02BN: a blue-noise progressive multi-jittered (0, 2)-sequence. The stochastic PMJ02
//! of the [parent module](super) (Helmer, Christensen & Kensler 2021), then nested flips
//! chosen to push the points of every power-of-two prefix apart ([`super::spread`]).
//!
//! Every aligned block of `2^m` points is a (0, m, 2)-net, as in PMJ02 (a nested flip maps
//! elementary intervals onto elementary intervals). The spacing is what best candidate
//! (Christensen, Kensler & Kilpatrick 2018, [`super::christensen`]) promises and, in a
//! balanced (0, 2)-sequence, does not deliver. Mean nearest-neighbour distance over the
//! hexagonal spacing, toroidal, 4 seeds (`tests/suite/pmj.rs`):
//!
//! | prefix | 2^8 | 2^9 | 2^10 | 2^11 | 2^12 | 3 · 2^10 |
//! |---|---|---|---|---|---|---|
//! | PMJ02 (stochastic) | 0.611 | 0.635 | 0.609 | 0.603 | 0.603 | 0.593 |
//! | best candidate, 100 trials | 0.610 | 0.626 | 0.609 | 0.615 | 0.604 | 0.595 |
//! | PMJ02BN (this module) | 0.652 | 0.655 | 0.692 | 0.675 | 0.712 | 0.674 |
//!
//! The flips are chosen for all the prefixes up to the length asked for, so a shorter fill
//! is not a prefix of a longer one: fill the longest length needed and take its prefixes
//! (as a renderer takes a pixel's samples from one table).
//!
//! Cost: `O(n)` for PMJ02 plus [`super::spread`]'s `O(log n)` a point; storage the
//! caller's, [`workspace_len`]`(n)` words. Seeded and deterministic.
//!
//! ```
//! use qmckit::pmj::bn;
//! let mut pts = [[0u32; 2]; 64];
//! let mut work = [0u32; 512];
//! assert!(bn::workspace_len(64)? <= work.len());
//! bn::fill(7, &mut pts, &mut work, &qmckit::work::Budget::UNLIMITED)?;
//! // One point in every cell of the 8 x 8 grid.
//! let mut seen = [false; 64];
//! for p in &pts { seen[((p[1] >> 29) * 8 + (p[0] >> 29)) as usize] = true; }
//! assert!(seen.iter().all(|&s| s));
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::spread;
use crate::error::Result;
use crate::work::Budget;

/// The longest sequence [`fill`] generates, `2^30` points.
pub const MAX_POINTS: usize = spread::MAX_POINTS;

/// The words of workspace [`fill`] needs for `n` points: [`spread::workspace_len`]`(n)`,
/// `8n` to `16n`.
///
/// # Errors
/// [`crate::Error::TooManyPoints`] past [`MAX_POINTS`].
pub const fn workspace_len(n: usize) -> Result<usize> {
    spread::workspace_len(n)
}

/// The first `out.len()` points of the PMJ02BN sequence of `seed` for that length (see the
/// [module documentation](self)); `work` is scratch of at least [`workspace_len`]`(out.len())`
/// words. Every aligned block of `2^m` points is a (0, m, 2)-net.
///
/// # Errors
/// [`crate::Error::TooManyPoints`] past [`MAX_POINTS`]; [`crate::Error::BufferLength`] for
/// a short `work`; [`crate::Error::OutOfTime`] past the deadline of `budget` (started on
/// entry if it was not; `out` is then not the sequence: discard it). The spread,
/// `O(n log n)`, checks the deadline ([`spread::spread`]); the `O(n)` PMJ02 fill before it
/// does not. Within the deadline ([`Budget::UNLIMITED`] has none) the points are the same
/// bit for bit whatever the budget.
pub fn fill(seed: u64, out: &mut [[u32; 2]], work: &mut [u32], budget: &Budget) -> Result<()> {
    spread::workspace_len(out.len())?;
    spread::check_work(out.len(), work.len())?;
    let budget = budget.started();
    super::fill(seed, out)?;
    spread::spread(out, work, &budget)
}
