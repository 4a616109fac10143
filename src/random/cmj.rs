//! Correlated multi-jittered sampling (Kensler 2013, "Correlated Multi-Jittered
//! Sampling", Pixar Technical Memo 13-01): `N` points of the unit square stratified both
//! in the `m x n` grid of cells and in the `N` columns and `N` rows of the N-rooks grid,
//! random access, no table.
//!
//! ## The construction (the paper's final form, with stretch and clip)
//!
//! For `N` points and pattern index `p` (a `u32`), `m = floor(sqrt(N))` columns and
//! `n = ceil(N / m)` rows (aspect 1), so `m n >= N`. Sample `s` is first shuffled,
//! `s' = permute(s, N, p c_0)`; then, with one permutation of the columns and one of the
//! rows shared by every cell (the "correlated" shuffle of multi-jittering),
//!
//! ```text
//! sx = permute(s' mod m, m, p c_1)      sy = permute(floor(s' / m), n, p c_2)
//! x  = (sx + (sy + jx) / n) / m         y  = (s' + jy) / N
//! ```
//!
//! with jitters `jx = randfloat(s', p c_3)`, `jy = randfloat(s', p c_4)` in `[0, 1)` and
//! the paper's odd multipliers `c_0..c_4`. When `N = m n` every cell of the `m x n` grid
//! (cell `(sx, floor(s'/m))`) and every column `sx n + sy` and row `s'` of the `N x N`
//! grid holds exactly one point; when `m n > N` the rows are stretched to cover `[0, 1)`
//! (`y` is stratified into `N` rows) and the last `m n - N` cells stay empty ("clip").
//!
//! `permute(i, l, p)` is the paper's keyed bijection of `[0, l)`: an invertible mixer on
//! `k`-bit integers (`2^(k-1) < l <= 2^k`: xors with the key, multiplications by odd
//! constants, xor-shifts of the masked value) iterated until the value falls below `l`
//! (cycle walking), then offset by `p` modulo `l`. The mixer permutes `[0, 2^k)`, so the
//! walk from `i < l` stays on `i`'s cycle and meets `[0, l)` again within `2^k - l + 1`
//! steps; the loop is bounded by that count (fewer than 2 rounds are expected, since
//! `l > 2^k / 2`), so it is total. `randfloat(i, p)` is the paper's 32-bit hash; its value
//! is used directly as a 0.32 fraction (the paper scales it to a `float` below 1).
//!
//! ## More than two dimensions
//!
//! The paper's patterns are 2D. Dimensions `2j, 2j + 1` are an independent 2D pattern of
//! the same `N` with its own pattern index `p_j`, a 32-bit hash of the seed and `j` (not
//! the seed itself: `p = 0` zeroes every multiplied key, so both jitters coincide);
//! since the first shuffle `s' = permute(s, N, p_j c_0)` depends on `p_j`, the pairs are
//! decorrelated (point `s` sits in unrelated cells of different pairs). An odd last
//! dimension is a 1D stratified, permuted draw, `(permute(s, N, p_j c_0) + jy) / N`: one
//! point in each of `N` slabs. Every coordinate is `O(1)` expected, no allocation.

use crate::bits::in_cell;
use crate::error::{Error, Result};
use crate::hash::hash3;
use crate::sampler::{Sampler, check, check_set};

/// The paper's multipliers of the pattern index: the sample shuffle, the column and row
/// permutations, and the two jitters.
const SHUFFLE: u32 = 0x5163_3e2d;
const COLUMNS: u32 = 0x68bc_21eb;
const ROWS: u32 = 0x02e5_be93;
const JITTER_X: u32 = 0x967a_889b;
const JITTER_Y: u32 = 0x368c_c8b7;

/// Kensler's keyed bijection of `[0, l)`: the image of `i` (`i < l`, `1 <= l <= 2^32`),
/// by cycle walking an invertible mixer on the `k`-bit integers, `2^(k-1) < l <= 2^k`.
///
/// Total: the walk is bounded by `2^k` rounds, which the cycle argument of the module
/// documentation shows it never needs (it returns within `2^k - l + 1`). For `i >= l` the
/// result is `i mod l`'s image; `l == 0` gives 0.
///
/// ```
/// use qmckit::random::cmj::permute;
/// let mut seen = [false; 37];
/// for i in 0..37 { seen[permute(i, 37, 7) as usize] = true; }
/// assert!(seen.iter().all(|&s| s));
/// ```
pub const fn permute(i: u32, l: u64, p: u32) -> u32 {
    if l <= 1 {
        return 0;
    }
    let l = if l > 1 << 32 { 1 << 32 } else { l };
    let mut w = (l - 1) as u32;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    let mut i = (i as u64 % l) as u32;
    // At most 2^k rounds (w + 1 = 2^k); the walk returns below l within 2^k - l + 1.
    let mut rounds = w as u64 + 1;
    loop {
        i = crate::hash::pbrt::permutation_round(i, w, p);
        rounds -= 1;
        if (i as u64) < l || rounds == 0 {
            break;
        }
    }
    // `rounds == 0` with `i >= l` cannot happen (see above); the remainder keeps the
    // result below `l` regardless.
    // The sum in 64 bits: the paper's 32-bit `(i + p) % l` (and pbrt's) is no bijection
    // when the sum wraps (e.g. l = 3, p = 2^32 - 1; tested).
    ((i as u64 + p as u64) % l) as u32
}

/// Kensler's `randfloat(i, p)` as a 0.32 fraction: a keyed 32-bit hash of `i`.
///
/// ```
/// use qmckit::random::cmj::randfloat;
/// assert_ne!(randfloat(1, 5), randfloat(2, 5));
/// ```
pub const fn randfloat(i: u32, p: u32) -> u32 {
    let mut i = i ^ p;
    i ^= i >> 17;
    i ^= i >> 10;
    i = i.wrapping_mul(0xb365_34e5);
    i ^= i >> 12;
    i ^= i >> 21;
    i = i.wrapping_mul(0x93fc_4795);
    i ^= 0xdf6e_307f;
    i ^= i >> 17;
    i.wrapping_mul(1 | p >> 18)
}

/// `N` correlated multi-jittered points in `dims` dimensions (pairs of dimensions are
/// independent 2D patterns; an odd last dimension is a 1D stratified draw).
///
/// ```
/// use qmckit::{Sampler, random::cmj::CorrelatedMultiJitter};
/// let s = CorrelatedMultiJitter::new(16, 2, 3)?;
/// // One point in each of the 16 columns and each of the 4 x 4 cells.
/// let (mut cols, mut cells) = ([0; 16], [0; 16]);
/// for i in 0..16 {
///     let (x, y) = (s.sample(i, 0)? as u64, s.sample(i, 1)? as u64);
///     cols[(x * 16 >> 32) as usize] += 1;
///     cells[((x * 4 >> 32) + 4 * (y * 4 >> 32)) as usize] += 1;
/// }
/// assert!(cols.iter().chain(&cells).all(|&c| c == 1));
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CorrelatedMultiJitter {
    n: u64,
    m: u64,
    rows: u64,
    dims: usize,
    seed: u64,
}

impl CorrelatedMultiJitter {
    /// `n` points (`1..=2^32`) in `dims >= 1` dimensions, patterns from `seed`:
    /// `m = floor(sqrt(n))` columns, `ceil(n / m)` rows.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::ZeroDimensions`].
    pub const fn new(n: u64, dims: usize, seed: u64) -> Result<Self> {
        if let Err(e) = check_set(n, dims) {
            return Err(e);
        }
        let m = isqrt(n);
        Ok(CorrelatedMultiJitter {
            n,
            m,
            rows: n.div_ceil(m),
            dims,
            seed,
        })
    }

    /// `n` points in an explicit `m x rows` grid (`n <= m rows <= 2^32`): the paper's
    /// pattern with aspect `m / rows`.
    ///
    /// # Errors
    /// As [`CorrelatedMultiJitter::new`]; [`Error::InvalidParameter`] when the grid has
    /// fewer than `n` cells or a side of 0.
    pub const fn with_grid(n: u64, m: u64, rows: u64, dims: usize, seed: u64) -> Result<Self> {
        if let Err(e) = check_set(n, dims) {
            return Err(e);
        }
        let cells = m as u128 * rows as u128;
        if m == 0 || rows == 0 || cells < n as u128 || cells > 1 << 32 {
            return Err(Error::InvalidParameter {
                what: "the m x n grid of correlated multi-jitter needs N <= m n <= 2^32",
            });
        }
        Ok(CorrelatedMultiJitter {
            n,
            m,
            rows,
            dims,
            seed,
        })
    }

    /// The grid `(m, n)`: columns and rows of the coarse stratification.
    pub const fn grid(&self) -> (u64, u64) {
        (self.m, self.rows)
    }

    /// The pattern index `p_j` of the dimension pair `j` (dimensions `2j`, `2j + 1`): a
    /// hash of seed and `j`.
    pub const fn pattern(&self, j: u64) -> u32 {
        (hash3(self.seed, j, 0x434d_4a00) >> 32) as u32 // "CMJ"
    }

    /// Coordinate `dim` of point `index`. `O(1)` expected.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::DimensionOutOfRange`].
    pub const fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        if let Err(e) = check(index, self.n, dim, self.dims) {
            return Err(e);
        }
        let p = self.pattern((dim / 2) as u64);
        let s = permute(index, self.n, p.wrapping_mul(SHUFFLE));
        let pair = dim.is_multiple_of(2) && dim + 1 < self.dims;
        Ok(if pair {
            let sx = permute((s as u64 % self.m) as u32, self.m, p.wrapping_mul(COLUMNS));
            let sy = permute((s as u64 / self.m) as u32, self.rows, p.wrapping_mul(ROWS));
            let jx = randfloat(s, p.wrapping_mul(JITTER_X));
            let cells = self.m * self.rows;
            in_cell(sx as u64 * self.rows + sy as u64, cells, jx)
        } else {
            in_cell(s as u64, self.n, randfloat(s, p.wrapping_mul(JITTER_Y)))
        })
    }
}

/// `floor(sqrt(n))` for `n <= 2^32` (at least 1 for `n >= 1`).
const fn isqrt(n: u64) -> u64 {
    let mut r = 0u64;
    let mut bit = 1u64 << 16;
    while bit > 0 {
        let t = r | bit;
        if t * t <= n {
            r = t;
        }
        bit >>= 1;
    }
    if r == 0 { 1 } else { r }
}

impl Sampler for CorrelatedMultiJitter {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        self.n
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        CorrelatedMultiJitter::sample(self, index, dim)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permute_is_a_bijection_for_any_length() {
        for l in [1u64, 2, 3, 5, 16, 17, 31, 33, 100, 257, 1000] {
            for p in [0u32, 1, 0xdead_beef, u32::MAX] {
                let mut seen = std::vec![false; l as usize];
                for i in 0..l as u32 {
                    let j = permute(i, l, p) as usize;
                    assert!(!seen[j], "l {l} p {p}: {j} twice");
                    seen[j] = true;
                }
            }
        }
    }

    #[test]
    fn isqrt_is_the_floor() {
        for n in 1..5000u64 {
            let r = isqrt(n);
            assert!(r * r <= n && (r + 1) * (r + 1) > n, "{n}");
        }
        assert_eq!(isqrt(1 << 32), 1 << 16);
    }
}
