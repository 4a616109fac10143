//! Low-discrepancy blue noise (Ahmed, Perrier, Coeurjolly, Ostromoukhov, Guo, Yan, Huang
//! & Deussen 2016, "Low-Discrepancy Blue Noise Sampling", ACM TOG 35(6)): the 2D Sobol'
//! `(0, 2k, 2)`-net written cell by cell from two van der Corput sequences, its in-cell
//! offsets permuted within the rows and columns of `16 x 16`-cell tiles by a look-up
//! table chosen offline for a blue-noise spectrum. The shipped table's permutations keep
//! the `(0, 2k, 2)`-net a `(0, 2k, 2)`-net.
//!
//! ## The template
//!
//! `N = 4^k` points, `K = 2^k` cells a side. The cell in column `X` and row `Y` holds
//! the point `((X + rev_k(Y)/K)/K, (Y + rev_k(X)/K)/K)`, `rev_k` the reversal of `k`
//! bits: with `i = X K + rev_k(Y)` that is `(i/N, rev_2k(i)/N)`, the Hammersley set,
//! which is the first `N` points of the 2D Sobol' sequence and a `(0, 2k, 2)`-net. In
//! column `X` the `x` offsets are the van der Corput values of the row indices; in row
//! `Y` the `y` offsets those of the column indices.
//!
//! ## The permutation
//!
//! With tiles of `t = 16` cells (`t = K` below `K = 16`), row `Y = 16 B + j` of column `X`
//! takes the `x` offset of row index `16 B + p_X(j)` instead of `Y`, where `p_X` is a
//! permutation of `0..16` read from the table (a *run*); columns likewise for `y`. So
//! `x = (X K + rev_k(16 B + p))/N` and the points stay on the `1/N` grid. Properties
//! (the tests count them):
//!
//! * every column `X` keeps its multiset of `x` offsets, so each of the `N` columns of
//!   width `1/N` holds one point, and each row of height `1/N` (the 1D projections are
//!   stratified as the net's); each of the `K x K` cells holds one point;
//! * the set is a `(3 - s, 2k, 2)`-net, `s` the table's [nesting](LdbnTable::nesting):
//!   in every run each aligned group of `2^r` entries, `r <= s`, has distinct low `r`
//!   bits. Proof: take an elementary interval `2^-(k + r) x 2^-(k - r - t)` (the other
//!   orientation is the same with rows for columns), `t = 3 - s`. For `r = 0` it is `2^t`
//!   cells. For `r > 0` it is a sub-column of column `X` where the offsets' top `r` bits,
//!   i.e. the low `r` bits of `16 B + p`, are fixed, over `2^(r + t)` aligned rows. If
//!   `r + t >= 4` the rows are whole runs, whose offsets are the template's, so the
//!   interval holds the template's `2^t` points. Otherwise `r <= s`, and the `2^(r + t)`
//!   aligned entries of one run are groups of `2^r` with distinct low `r` bits: `2^t`
//!   points again. Any table has `s >= 0`, a `(3, 2k, 2)`-net; the identity has `s = 3`,
//!   the `(0, 2k, 2)`-net itself. A `(t, m, 2)`-net's star discrepancy is
//!   `O(2^t log N / N)` (Niederreiter 1992, "Random Number Generation and Quasi-Monte
//!   Carlo Methods", Theorem 4.10): the low-discrepancy property the paper states.
//!
//! Below `K = 16` a column of the table has more values than the column has rows; the
//! `K` values are replaced by their ranks in the order of their offsets, which keeps the
//! points' order in the cell and makes the offsets `0..K`; an aligned group with distinct
//! low `r` bits of `p` has distinct top `r` bits of the ranks, so the properties hold
//! with tiles of `K` cells.
//!
//! ## The table
//!
//! [`LDBN_TABLE`] is `tables/ldbn-128.bin`: `128 x 128` bytes, entry `(X mod 128, Y mod
//! 128)` row-major, its low four bits `p_X(Y mod 16)` and high four bits `p_Y(X mod 16)`
//! (so every aligned run of 16 entries down a column has distinct low nibbles, and along a
//! row distinct high nibbles: checked when the crate is built, with its nesting,
//! [`LDBN_NESTING`] = 3, so the sets are `(0, 2k, 2)`-nets). It has the paper's shape (the paper's table is not reproduced):
//! made by `examples/ldbn_optimize.rs`, simulated annealing over the exchanges of two
//! entries of one run that keep the nesting, minimizing a Gaussian pair energy with a
//! hard core over the `128 x 128`-cell set on the torus (see that file).
//!
//! ## Seeds
//!
//! A seed picks, from its SplitMix64 draws, where the table is read (a shift by a
//! multiple of 16 cells in each axis, 64 choices: tiles onto tiles, so every property
//! above holds), one of the 8 symmetries of the square (reflections map elementary
//! intervals onto elementary intervals) and the bits of each coordinate below `1/N`
//! (uniform; an elementary interval's edges lie on the `1/N` grid). Statistics that see
//! distances only are the same for every symmetry.
//!
//! ## Range and cost
//!
//! `N = 4^k`, `k` from 1 to 13 (4 to 2^26 points); any seed. `O(N)`: a table read, two
//! bit reversals and two random words a point; memory `2N` words through [`crate::size`].
//! Estimated ([`Ldbn::cost`]) against a [`Budget`], the deadline read every 4096 rows.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::blue_noise::Ldbn;
//! use qmckit::work::Budget;
//! let set = Ldbn::new(256, 3)?.generate(&Budget::DEFAULT)?;
//! // One point in each of the 16 x 16 cells.
//! let mut cells = [0; 256];
//! for i in 0..256 {
//!     let (x, y) = (set.sample(i, 0)? >> 28, set.sample(i, 1)? >> 28);
//!     cells[(x * 16 + y) as usize] += 1;
//! }
//! assert!(cells.iter().all(|&c| c == 1));
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::rng::Rng;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The most points [`Ldbn`] takes: `4^13 = 2^26`.
pub const LDBN_MAX_POINTS: u64 = 1 << 26;

/// The tile side, in cells: permutations act within aligned runs of this many cells.
pub const LDBN_TILE: usize = 16;

/// The table's period, in cells, in each axis.
pub const LDBN_PERIOD: usize = 128;

/// The nesting of [`LDBN_TABLE`] ([`LdbnTable::nesting`]): 3, so its sets are
/// `(0, 2k, 2)`-nets, like the template.
pub const LDBN_NESTING: u32 = 3;

/// Points a second, one core, release (a table read, two bit reversals and two random
/// words a point; about 1.5e8 measured, taken lower).
const POINTS: Rate = Rate::per_second(3e7);

/// The stream of this construction's draws.
const STREAM: u64 = 0x1DB7;

/// The look-up table: [`LDBN_PERIOD`]`^2` bytes, entry `X + 128 Y` holding `p_X(Y mod
/// 16)` in its low four bits and `p_Y(X mod 16)` in its high four bits (see the module
/// documentation).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LdbnTable {
    entries: [u8; LDBN_PERIOD * LDBN_PERIOD],
}

/// Whether every aligned group of `g` (a power of two, at most 16) entries down each
/// column has distinct low nibbles mod `g`, and every such group along each row distinct
/// high nibbles mod `g`.
const fn groups_distinct(entries: &[u8; LDBN_PERIOD * LDBN_PERIOD], g: usize) -> bool {
    let full = (1u32 << g) - 1;
    let mut a = 0;
    while a < LDBN_PERIOD {
        let mut start = 0;
        while start < LDBN_PERIOD {
            let (mut down, mut along) = (0u32, 0u32);
            let mut j = 0;
            while j < g {
                down |= 1 << (entries[a + LDBN_PERIOD * (start + j)] as usize & (g - 1));
                along |= 1 << ((entries[start + j + LDBN_PERIOD * a] >> 4) as usize & (g - 1));
                j += 1;
            }
            if down != full || along != full {
                return false;
            }
            start += g;
        }
        a += 1;
    }
    true
}

/// Whether `entries` is a table: the low nibbles of each aligned run of 16 down a column
/// are distinct, and the high nibbles of each aligned run of 16 along a row.
const fn valid(entries: &[u8; LDBN_PERIOD * LDBN_PERIOD]) -> bool {
    groups_distinct(entries, LDBN_TILE)
}

/// The largest `s <= 3` such that in every run of `entries`, down the columns (low
/// nibbles) and along the rows (high nibbles), each aligned group of `2^r` entries,
/// `r <= s`, has distinct low `r` bits.
const fn nesting(entries: &[u8; LDBN_PERIOD * LDBN_PERIOD]) -> u32 {
    let mut s = 0;
    while s < 3 && groups_distinct(entries, 1 << (s + 1)) {
        s += 1;
    }
    s
}

impl LdbnTable {
    /// The identity permutations: the output is the template net (up to the seed's
    /// symmetry and low bits).
    pub const IDENTITY: LdbnTable = {
        let mut entries = [0u8; LDBN_PERIOD * LDBN_PERIOD];
        let mut i = 0;
        while i < entries.len() {
            let (x, y) = (i % LDBN_PERIOD, i / LDBN_PERIOD);
            entries[i] = ((y % 16) | ((x % 16) << 4)) as u8;
            i += 1;
        }
        LdbnTable { entries }
    };

    /// The table of `entries` (`128 x 128` bytes, row-major).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] unless there are `128^2` entries and every aligned run
    /// of 16 down a column has distinct low nibbles and along a row distinct high nibbles.
    pub fn new(entries: &[u8]) -> Result<Self> {
        let entries: [u8; LDBN_PERIOD * LDBN_PERIOD] =
            entries.try_into().map_err(|_| Error::InvalidParameter {
                what: "an LDBN table has 128 x 128 entries",
            })?;
        if !valid(&entries) {
            return Err(Error::InvalidParameter {
                what: "an LDBN table permutes each aligned run of 16 (low nibbles down a \
                       column, high nibbles along a row)",
            });
        }
        Ok(LdbnTable { entries })
    }

    /// The table's nesting `s` (0 to 3): in every run, each aligned group of `2^r`
    /// entries, `r <= s`, permutes distinct low `r` bits (so the offsets of any `2^r`
    /// aligned cells of a tile column still fall in distinct `2^-r` sub-columns). The set
    /// is then a `(3 - s, 2k, 2)`-net (module documentation).
    pub const fn nesting(&self) -> u32 {
        nesting(&self.entries)
    }

    /// The entries, row-major.
    pub const fn entries(&self) -> &[u8; LDBN_PERIOD * LDBN_PERIOD] {
        &self.entries
    }

    /// The entry of cell `(x, y)` (taken modulo 128).
    pub const fn get(&self, x: usize, y: usize) -> u8 {
        self.entries[(x % LDBN_PERIOD) + LDBN_PERIOD * (y % LDBN_PERIOD)]
    }
}

/// `tables/ldbn-128.bin`, checked at compile time.
const fn load(bytes: &[u8]) -> [u8; LDBN_PERIOD * LDBN_PERIOD] {
    assert!(
        bytes.len() == LDBN_PERIOD * LDBN_PERIOD,
        "tables/ldbn-128.bin: needs 128 x 128 bytes"
    );
    let mut out = [0u8; LDBN_PERIOD * LDBN_PERIOD];
    let mut i = 0;
    while i < out.len() {
        out[i] = bytes[i];
        i += 1;
    }
    assert!(valid(&out), "tables/ldbn-128.bin: not a permutation table");
    assert!(
        nesting(&out) >= LDBN_NESTING,
        "tables/ldbn-128.bin: less nested than LDBN_NESTING"
    );
    out
}

/// The optimized table, `tables/ldbn-128.bin` (see the module documentation).
pub static LDBN_TABLE: LdbnTable = LdbnTable {
    entries: load(include_bytes!("../../tables/ldbn-128.bin")),
};

/// Low-discrepancy blue noise (builder): `N = 4^k` points, a seed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ldbn {
    k: u32,
    seed: u64,
}

impl Ldbn {
    /// `n` points, a power of four from 4 to [`LDBN_MAX_POINTS`]; the table's window,
    /// the symmetry and the low bits drawn from `seed`.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::InvalidParameter`] unless
    /// `n` is a power of four of at least 4.
    pub fn new(n: u64, seed: u64) -> Result<Self> {
        crate::size::points(n, LDBN_MAX_POINTS)?;
        if n < 4 || !n.is_power_of_two() || !n.trailing_zeros().is_multiple_of(2) {
            return Err(Error::InvalidParameter {
                what: "LDBN takes a power of four of at least 4 points (N = 4^k)",
            });
        }
        Ok(Ldbn {
            k: n.trailing_zeros() / 2,
            seed,
        })
    }

    /// The estimated running time: `N` points.
    pub fn cost(&self) -> Cost {
        Cost::steps((1u64 << (2 * self.k)) as f64, POINTS)
    }

    /// The set with [`LDBN_TABLE`], point `X + K Y` in cell `(X, Y)` before the seed's
    /// symmetry; refused before it starts when [`cost`](Self::cost) exceeds `budget`.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::OutOfTime`], [`Error::TooLarge`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        self.generate_with(&LDBN_TABLE, budget)
    }

    /// The set with `table` instead of [`LDBN_TABLE`] (the optimizer's candidates;
    /// [`LdbnTable::IDENTITY`] gives the template net).
    ///
    /// # Errors
    /// As [`generate`](Self::generate).
    pub fn generate_with(&self, table: &LdbnTable, budget: &Budget) -> Result<PointSet> {
        const WHAT: &str = "low-discrepancy blue noise";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let k = self.k;
        let side = 1usize << k;
        let mut rng = Rng::new(self.seed, STREAM);
        let tiles = (LDBN_PERIOD / LDBN_TILE) as u64;
        let wx = (rng.next_u64() % tiles) as usize * LDBN_TILE;
        let wy = (rng.next_u64() % tiles) as usize * LDBN_TILE;
        let symmetry = rng.next_u64() & 7;
        let entry = |x: usize, y: usize| table.get(x + wx, y + wy);
        let mut pts = crate::size::vec_zeroed::<u32>(crate::size::coordinates(1 << (2 * k), 2)?)?;
        let (u, v) = if side >= LDBN_TILE {
            (Vec::new(), Vec::new())
        } else {
            small_offsets(side, &entry)
        };
        // k >= 1, so at most 30 low bits.
        let low_bits = 32 - 2 * k;
        let low_mask = (1u32 << low_bits) - 1;
        for y in 0..side {
            if y % 4096 == 0 {
                budget.check_deadline(WHAT)?;
            }
            for x in 0..side {
                let (ou, ov) = if side >= LDBN_TILE {
                    let e = entry(x, y);
                    let iu = (y & !(LDBN_TILE - 1)) | (e & 15) as usize;
                    let iv = (x & !(LDBN_TILE - 1)) | (e >> 4) as usize;
                    (reverse(iu, k), reverse(iv, k))
                } else {
                    let c = x + side * y;
                    (
                        u.get(c).copied().unwrap_or(0),
                        v.get(c).copied().unwrap_or(0),
                    )
                };
                // x N = X K + offset, in the top 2k bits; random bits below.
                let word = rng.next_u64();
                let px = (((x << k) | ou) as u32) << low_bits | (word as u32 & low_mask);
                let py = (((y << k) | ov) as u32) << low_bits | ((word >> 32) as u32 & low_mask);
                let (px, py) = symmetric(px, py, symmetry);
                let c = 2 * (x + side * y);
                if let Some(p) = pts.get_mut(c..c + 2) {
                    p[0] = px;
                    p[1] = py;
                }
            }
        }
        PointSet::new(pts, 2)
    }
}

/// `i` (below `2^k`) with its `k` bits reversed.
fn reverse(i: usize, k: u32) -> usize {
    if k == 0 {
        0
    } else {
        ((i as u32).reverse_bits() >> (32 - k)) as usize
    }
}

/// One of the 8 symmetries of the square on 0.32 coordinates: bit 0 reflects `x`, bit 1
/// `y`, bit 2 exchanges them (`1 - x` is `!x` on the `2^-32` grid).
fn symmetric(x: u32, y: u32, symmetry: u64) -> (u32, u32) {
    let x = if symmetry & 1 == 1 { !x } else { x };
    let y = if symmetry & 2 == 2 { !y } else { y };
    if symmetry & 4 == 4 { (y, x) } else { (x, y) }
}

/// Below `K = 16`: the offsets (`0..K`, in `1/N` units) of the cells, row-major: in each
/// column the ranks of the rows' `rev_4(p)` values, in each row those of the columns'.
fn small_offsets(side: usize, entry: &impl Fn(usize, usize) -> u8) -> (Vec<usize>, Vec<usize>) {
    let mut u = vec![0usize; side * side];
    let mut v = vec![0usize; side * side];
    let key = |e: u8| reverse(e as usize, 4);
    for a in 0..side {
        for b in 0..side {
            let mine_u = key(entry(a, b) & 15);
            let mine_v = key(entry(b, a) >> 4);
            // Column a, row b: rank among the column's rows; row a, column b likewise.
            u[a + side * b] = (0..side)
                .filter(|&o| key(entry(a, o) & 15) < mine_u)
                .count();
            v[b + side * a] = (0..side)
                .filter(|&o| key(entry(o, a) >> 4) < mine_v)
                .count();
        }
    }
    (u, v)
}
