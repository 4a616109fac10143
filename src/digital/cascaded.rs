//! Cascaded Sobol' sampling (Paulin, Coeurjolly, Iehl, Bonneel, Keller & Ostromoukhov
//! 2021, "Cascaded Sobol' Sampling", ACM TOG 40(6)): `N = 2^m` points in `d` dimensions
//! whose every consecutive pair of coordinates `(x_j, x_(j+1))` is a `(0, m, 2)`-net in
//! base 2 and every coordinate is stratified (one point in each interval `[k/N, (k+1)/N)`).
//!
//! ## The cascade
//!
//! The 2D Sobol' sequence `(phi_2(k), P k)` (van der Corput and Sobol's second dimension,
//! `P` the upper-triangular Pascal matrix mod 2, `P[r][c] = C(c, r) mod 2`) is a
//! `(0, 2)`-sequence: its first `2^m` points are a `(0, m, 2)`-net. Its first coordinate
//! `phi_2(k)` has the top `m` digits of `w` exactly when `k = rev_m(w)`, the top `m` binary
//! digits of `w` read backwards as an integer. The cascade chains one such net per pair of
//! dimensions; each output coordinate is scrambled by its own nested uniform (Owen)
//! scramble `O_j`, and each link reads its index through a second independent one, `Q_j`:
//!
//! ```text
//! x_0(i)     = O_0(phi_2(i)),                          i < N,
//! x_(j+1)(i) = O_(j+1)(P rev_m(Q_j(x_j(i)))),          j = 0 .. d - 2.
//! ```
//!
//! **Why every consecutive pair is a net.** By induction `x_j` is stratified (true for
//! `x_0`; `P` is a bijection of the `m`-bit integers, and an Owen scramble permutes the
//! intervals of width `2^-m`), so `k = rev_m(Q_j(x_j(i)))` runs over all of `0 .. N - 1` as
//! `i` does. The top `a` digits of `x_j(i)` are a bijective image (nested: `Q_j^-1`'s) of the
//! top `a` digits of `phi_2(k)`, and the top `b` digits of `x_(j+1)(i)` of those of `P k`
//! (`O_(j+1)`'s). Every elementary interval `2^-a x 2^-b`, `a + b = m`, therefore holds as
//! many points as an interval of the Sobol' net `{(phi_2(k), P k)}`: one. As a set, the pair
//! is that net with both coordinates Owen-scrambled (`Q_j^-1` on the first, `O_(j+1)` on
//! the second); without `Q_j` the first coordinate's scramble would only relabel the
//! points and the pair would be the net scrambled in its second coordinate alone, which
//! keeps Sobol's visible structure.
//!
//! **Why the scrambles are needed.** Without them the cascade is linear, `x_j = P^j i`
//! (digits), and `P^2 = I` over GF(2) (`sum_k C(k, r) C(c, k) = 2^(c-r) C(c, r)`), so
//! `x_2 = x_0`: the unscrambled cascade repeats itself every two dimensions. Independent
//! scrambles per dimension, as in the paper, break that while keeping each pair a net
//! (Owen scrambling keeps nets). The scrambles are [`ExactOwen`] of the seed (`O_j`:
//! dimension `j`; `Q_j`: dimension `j` of a second key hashed from the seed); the digits
//! below `2^-m` come out uniform at random. The set is a set (the index `rev_m` depends
//! on `m`), not an extensible sequence. Non-consecutive pairs and higher projections
//! carry no guarantee. The paper's optimized initialization of the 2D nets is not
//! reproduced: every link uses the Sobol' pair `(phi_2, P)`.
//!
//! ## Range and cost
//!
//! `N` a power of two from 1 to `2^32`, 1 to [`CASCADED_MAX_DIMS`] dimensions, any seed.
//! [`sample`](Sampler::sample)`(i, j)` walks the chain, `O(j)`: `2j + 1` scrambles of 32
//! hashes each; [`fill`](Sampler::fill) walks it once a point, `O(d)` a point. No
//! allocation, no table; linear, so no work budget.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::digital::cascaded::CascadedSobol;
//! let s = CascadedSobol::new(16, 3, 7)?;
//! // Dimensions 1 and 2: one point in each of the 4 x 4 squares (a (0, 4, 2)-net).
//! let mut cells = [0; 16];
//! for i in 0..16 {
//!     let (x, y) = (s.sample(i, 1)? >> 30, s.sample(i, 2)? >> 30);
//!     cells[(x * 4 + y) as usize] += 1;
//! }
//! assert!(cells.iter().all(|&c| c == 1));
//! # Ok::<(), qmckit::Error>(())
//! ```

use crate::bits::reverse_bits;
use crate::error::{Error, Result};
use crate::randomize::ExactOwen;
use crate::sampler::{Sampler, check, check_fill};

/// Mixed into the seed for the index scrambles `Q_j` ("CASCADE" in ASCII, any constant).
const INDEX_KEY: u64 = 0x0043_4153_4341_4445;

/// The most dimensions [`CascadedSobol`] takes: 2^16 (a coordinate costs `O(dim)`).
pub const CASCADED_MAX_DIMS: usize = 1 << 16;

/// Column `c` of the Pascal matrix mod 2 as a 0.32 fraction: bit `31 - r` set when
/// `C(c, r)` is odd, i.e. when the bits of `r` are a subset of those of `c` (Lucas).
const fn pascal_columns() -> [u32; 32] {
    let mut cols = [0u32; 32];
    let mut c = 0;
    while c < 32 {
        let mut r = 0;
        while r <= c {
            if r & c == r {
                cols[c] |= 1 << (31 - r);
            }
            r += 1;
        }
        c += 1;
    }
    cols
}

const PASCAL: [u32; 32] = pascal_columns();

/// `P k` over GF(2) as a 0.32 fraction: Sobol's second dimension of index `k` (Sobol'
/// 1967; the primitive polynomial `x + 1`).
///
/// ```
/// use qmckit::digital::cascaded::pascal;
/// // k = 3: columns 0 and 1 of P: 1/2 + (1/2 + 1/4) = 1/4 (xor).
/// assert_eq!(pascal(3), 1 << 30);
/// ```
pub const fn pascal(k: u32) -> u32 {
    let mut y = 0;
    let mut c = 0;
    while c < 32 {
        if (k >> c) & 1 == 1 {
            y ^= PASCAL[c];
        }
        c += 1;
    }
    y
}

/// `N = 2^m` cascaded Sobol' points in `dims` dimensions, scrambled from `seed`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CascadedSobol {
    m: u32,
    dims: usize,
    owen: ExactOwen,
    index_owen: ExactOwen,
}

impl CascadedSobol {
    /// `n` points (a power of two, 1 to 2^32) in `dims` (1 to [`CASCADED_MAX_DIMS`]),
    /// scrambles from `seed`.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::NotPowerOfTwo`],
    /// [`Error::ZeroDimensions`], [`Error::DimensionOutOfRange`].
    pub const fn new(n: u64, dims: usize, seed: u64) -> Result<Self> {
        if let Err(e) = crate::sampler::check_set(n, dims) {
            return Err(e);
        }
        if !n.is_power_of_two() {
            return Err(Error::NotPowerOfTwo { n });
        }
        if dims > CASCADED_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: dims,
                dims: CASCADED_MAX_DIMS,
            });
        }
        Ok(CascadedSobol {
            m: n.trailing_zeros(),
            dims,
            owen: ExactOwen::new(seed),
            index_owen: ExactOwen::new(crate::hash::mix64(seed ^ INDEX_KEY)),
        })
    }

    /// `m`, with `N = 2^m` points.
    pub const fn m(&self) -> u32 {
        self.m
    }

    /// The index of the 2D net that continues coordinate `x` of dimension `j`:
    /// `rev_m(Q_j(x))`.
    const fn next_index(&self, x: u32, j: usize) -> u32 {
        if self.m == 0 {
            0
        } else {
            reverse_bits(self.index_owen.scramble(x, j)) & (u32::MAX >> (32 - self.m))
        }
    }

    /// Coordinate 0 of point `i`, then each next one from the last: `f(j, x_j)` for
    /// `j = 0 .. upto`.
    fn walk(&self, index: u32, upto: usize, mut f: impl FnMut(usize, u32)) {
        let mut x = self.owen.scramble(reverse_bits(index), 0);
        f(0, x);
        for j in 1..upto {
            x = self.owen.scramble(pascal(self.next_index(x, j - 1)), j);
            f(j, x);
        }
    }
}

impl Sampler for CascadedSobol {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        1u64 << self.m
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        check(index, self.len(), dim, self.dims)?;
        let mut out = 0;
        self.walk(index, dim + 1, |j, x| {
            if j == dim {
                out = x;
            }
        });
        Ok(out)
    }

    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        check_fill(self, start, out.len())?;
        for (row, chunk) in out.chunks_exact_mut(self.dims).enumerate() {
            let index = start.wrapping_add(row as u32);
            self.walk(index, self.dims, |j, x| {
                if let Some(c) = chunk.get_mut(j) {
                    *c = x;
                }
            });
        }
        Ok(())
    }
}
