//! Digital nets and sequences: points whose digits are linear images of the index's digits.
//!
//! | item | construction |
//! |---|---|
//! | [`sobol`] | Sobol' (base 2; Joe & Kuo's direction numbers), Owen-scrambled and interlaced variants |
//! | [`lp`] | Larcher–Pillichshammer's (0, m, 2)-nets and sequence (base 2) |
//! | [`cascaded`] | cascaded Sobol' (Paulin et al. 2021): every consecutive pair of dimensions a (0, m, 2)-net, Owen-scrambled |
//! | [`DigitalNet2`], [`rank`] | any base-2 net from its generator matrices (Sobol', LP, Hammersley, van der Corput), and its exact t-value by the rank test (`std`) |
//! | [`DigitalNetB`], [`faure_matrices`] | digital nets and sequences in a prime base `b` from generator matrices, Faure's (0, s)-sequences |
//!
//! The t-value of a block of a base-`b` sequence is counted from its points by
//! `analysis::tvalue::t_value_block` (feature `analysis`).
//!
//! # The construction in base `b`
//!
//! A digital sequence in base `b` (Niederreiter 1987) has one generator matrix `C_j` over
//! the field `F_b` per dimension. Index `i = sum_c a_c b^c` (digits `a_c`, least
//! significant first) has coordinates
//!
//! ```text
//! y_j = C_j (a_0, a_1, ..)^T  (mod b),     x_j(i) = sum_r y_(j,r) b^-(r+1).
//! ```
//!
//! Faure's sequence (Faure 1982) in prime base `b >= s` takes `C_j = P^j` (0-based `j`),
//! `P` the upper-triangular Pascal matrix: `P^j[r][c] = C(c, r) j^(c - r) mod b`, so `C_0`
//! is the identity (van der Corput in base `b`). Every block of `b^m` consecutive points
//! starting at a multiple of `b^m` is a `(0, m, s)`-net in base `b`: every elementary
//! interval of volume `b^-m` holds exactly one point. Base 2, `s = 2` is 2D Sobol'.
//! Niederreiter or Niederreiter–Xing matrices, given as entries, use the same machinery.
//!
//! # Precision
//!
//! `K` output digits are used, the fewest with `b^K >= 2^32` (21 in base 3); the index has
//! at most `K` digits too. The coordinate is the exact rational `v / b^K`,
//! `v = sum_(r < K) y_r b^(K-1-r)` ([`DigitalNetB::value`]), and the 0.32 sample is
//! `floor(v 2^32 / b^K)`: exact to the last bit (values such as `1/3` round down), so
//! counting elementary intervals should use [`DigitalNetB::value`].
//!
//! # Scrambling
//!
//! The base-`b` digit scrambles of the radical inverse ([`DigitScramble`]: random digit
//! permutations per position, Faure's permutations, Owen's nested uniform scrambling in
//! base `b`) apply to the output digits `y_(j,r)` before they are combined, with all `K`
//! digits scrambled (so Owen's scramble makes each point uniform to 32 bits). Digit
//! permutations and Owen scrambling keep every `(t, m, s)`-net a `(t, m, s)`-net.
//!
//! Cost per value: `K x m` multiply-adds (`m` the index's digits; at most 21 x 21 in
//! base 3), one reduction mod `b` per output digit and, scrambled, one hash a digit.
//!
//! ```
//! use qmckit::Sampler;
//! use qmckit::digital::DigitalNetB;
//! let f = DigitalNetB::faure(3, 3)?;
//! // Point 3 of Faure in base 3 is (1/9, 4/9, 7/9).
//! assert_eq!(f.value(3, 1)?, 4 * 3u64.pow(19)); // 4/9 = 4 3^19 / 3^21, exact
//! assert_eq!(f.sample(3, 2)?, ((7u64 << 32) / 9) as u32);
//! # Ok::<(), qmckit::Error>(())
//! ```

pub mod cascaded;
mod faure;
#[cfg(feature = "std")]
mod file;
mod fill;
pub mod lp;
#[cfg(feature = "std")]
mod net2;
#[cfg(feature = "std")]
pub mod rank;
pub mod sobol;

pub use faure::faure_matrices;
#[cfg(feature = "std")]
pub use file::parse_dnet;
#[cfg(feature = "std")]
pub use net2::DigitalNet2;

use crate::error::{Error, Result};
use crate::randomize::digits::DigitScramble;
use crate::sampler::{FULL_RANGE, Sampler, check};

/// Largest base accepted (entries are `u16`).
pub const MAX_BASE: u32 = 65521;

/// Most output digits (`K` for base 2).
pub const MAX_DIGITS: usize = 32;

/// `true` when `n` is prime, exactly, for every `u32`.
///
/// Trial division by the primes up to 37 settles `n < 41^2 = 1681`; above, a deterministic
/// Miller–Rabin test with the bases 2, 7 and 61, which no odd composite below
/// 4 759 123 141 > 2^32 passes (Jaeschke 1993). Products of residues below `n < 2^32` fit
/// in 64 bits, so nothing overflows. Cost: `O(log n)` 64-bit multiplications (about 100),
/// whatever `n`.
///
/// ```
/// use qmckit::digital::is_prime;
/// assert!(is_prime(65521) && is_prime(4_294_967_291)); // the largest primes below 2^16, 2^32
/// assert!(!is_prime(561) && !is_prime(4_294_967_295)); // a Carmichael number; 2^32 - 1
/// ```
pub const fn is_prime(n: u32) -> bool {
    const SMALL: [u32; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    let mut i = 0;
    while i < SMALL.len() {
        let p = SMALL[i];
        if n == p {
            return true;
        }
        if n.is_multiple_of(p) {
            return false;
        }
        i += 1;
    }
    if n < 41 * 41 {
        return true;
    }
    // n - 1 = d 2^s with d odd (n is odd and above 1681 here).
    let m = n as u64;
    let s = (n - 1).trailing_zeros();
    let d = ((n - 1) >> s) as u64;
    let bases = [2u64, 7, 61];
    let mut k = 0;
    'witness: while k < bases.len() {
        let mut x = pow_mod(bases[k], d, m);
        k += 1;
        if x == 1 || x == m - 1 {
            continue;
        }
        let mut r = 1;
        while r < s {
            x = x * x % m;
            if x == m - 1 {
                continue 'witness;
            }
            r += 1;
        }
        return false;
    }
    true
}

/// `a^e mod m` for `m < 2^32` (so every product of residues fits in 64 bits).
const fn pow_mod(a: u64, mut e: u64, m: u64) -> u64 {
    let mut base = a % m;
    let mut acc = 1 % m;
    while e > 0 {
        if e & 1 == 1 {
            acc = acc * base % m;
        }
        base = base * base % m;
        e >>= 1;
    }
    acc
}

/// `K`, the fewest base-`b` digits with `b^K >= 2^32`, and `b^K`, for `b >= 2` (at most 32
/// steps; `b^K < 2^32 b` fits in 64 bits for every `u32` base).
///
/// # Errors
/// [`Error::BaseTooSmall`] for `b < 2`, which has no such `K`.
///
/// ```
/// use qmckit::digital::output_digits;
/// assert_eq!(output_digits(2)?, (32, 1 << 32));
/// assert_eq!(output_digits(3)?, (21, 3u64.pow(21)));
/// assert!(output_digits(1).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
pub const fn output_digits(b: u32) -> Result<(usize, u64)> {
    if b < 2 {
        return Err(Error::BaseTooSmall { base: b });
    }
    let mut k = 0;
    let mut p = 1u64;
    while p < FULL_RANGE {
        // p < 2^32 and b < 2^32: the product is below 2^64.
        p *= b as u64;
        k += 1;
    }
    Ok((k, p))
}

/// A digital net or sequence in prime base `b`: `dims` generator matrices of `K` rows
/// (output digits, the first the most significant) and `cols` columns (index digits),
/// stored row-major per dimension in `M` (`matrices[(j K + r) cols + c]`; `&[u16]`,
/// `Vec<u16>`, an array).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DigitalNetB<M> {
    matrices: M,
    base: u32,
    dims: usize,
    cols: usize,
    digits: usize,
    scale: u64,
    len: u64,
    scramble: DigitScramble,
}

impl<M: AsRef<[u16]>> DigitalNetB<M> {
    /// The net with generator matrices `matrices` (`dims x K x cols` entries below `base`,
    /// `K` = [`output_digits`]`(base).0`; rows past the `K`-th would not change 32 bits).
    /// It has `min(base^cols, 2^32)` points.
    ///
    /// # Errors
    /// [`Error::BaseTooSmall`]; [`Error::InvalidParameter`] for a base that is not prime or
    /// is above [`MAX_BASE`], `cols` of 0 or above `K`, or an entry `>= base`;
    /// [`Error::BufferLength`] unless `matrices` has `dims x K x cols` entries;
    /// [`Error::ZeroDimensions`].
    pub fn new(base: u32, dims: usize, cols: usize, matrices: M) -> Result<Self> {
        if base < 2 {
            return Err(Error::BaseTooSmall { base });
        }
        if base > MAX_BASE || !is_prime(base) {
            return Err(Error::InvalidParameter {
                what: "a digital net's base must be a prime of at most 65521",
            });
        }
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        let (digits, scale) = output_digits(base)?;
        if cols == 0 || cols > digits {
            return Err(Error::InvalidParameter {
                what: "a digital net needs 1 to K index digits (b^K >= 2^32)",
            });
        }
        let expected = dims.checked_mul(digits * cols).ok_or(Error::TooLarge {
            what: "matrix entries",
            requested: u64::MAX,
            max: usize::MAX as u64,
        })?;
        let m = matrices.as_ref();
        if m.len() != expected {
            return Err(Error::BufferLength {
                expected,
                got: m.len(),
            });
        }
        if m.iter().any(|&e| e as u32 >= base) {
            return Err(Error::InvalidParameter {
                what: "a generator matrix entry is not a digit of the base",
            });
        }
        let len = (base as u64)
            .checked_pow(cols as u32)
            .map_or(FULL_RANGE, |n| n.min(FULL_RANGE));
        Ok(DigitalNetB {
            matrices,
            base,
            dims,
            cols,
            digits,
            scale,
            len,
            scramble: DigitScramble::None,
        })
    }

    /// The same net with its output digits scrambled by `scramble` (see the module docs).
    pub fn with_scramble(mut self, scramble: DigitScramble) -> Self {
        self.scramble = scramble;
        self
    }

    /// The base.
    pub const fn base(&self) -> u32 {
        self.base
    }

    /// `K`: output digits per coordinate.
    pub const fn digits(&self) -> usize {
        self.digits
    }

    /// The exact coordinate `dim` of point `index` as the integer `v` with `x = v / b^K`
    /// (after the scramble, if any).
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::DimensionOutOfRange`].
    pub fn value(&self, index: u32, dim: usize) -> Result<u64> {
        check(index, self.len, dim, self.dims)?;
        let b = self.base as u64;
        // The index's digits, least significant first; only the `used` lowest can be
        // non-zero, so the columns past them add nothing.
        let mut a = [0u64; MAX_DIGITS];
        let (mut rest, mut used) = (index as u64, 0usize);
        for slot in a.iter_mut().take(self.cols) {
            if rest == 0 {
                break;
            }
            *slot = rest % b;
            rest /= b;
            used += 1;
        }
        let digits = a.get(..used).unwrap_or(&[]);
        let block = self.digits * self.cols;
        let matrix = self
            .matrices
            .as_ref()
            .get(dim * block..(dim + 1) * block)
            .unwrap_or(&[]);
        let mut y = [0u32; MAX_DIGITS];
        for (slot, row) in y.iter_mut().zip(matrix.chunks_exact(self.cols)) {
            // One reduction a row: each product is below b^2 < 2^32 and a row has at most
            // 32 of them, so the sum stays below 2^37.
            let sum = row
                .iter()
                .zip(digits)
                .fold(0u64, |acc, (&c, &ak)| acc + c as u64 * ak);
            // Base 2 (Faure's s <= 2, Sobol'-like nets) without a division.
            *slot = (if b == 2 { sum & 1 } else { sum % b }) as u32;
        }
        let v = self.combine(dim, y.get(..self.digits).unwrap_or(&[]));
        Ok(v)
    }

    /// `v = sum_r y'_r b^(K-1-r)` from the output digits `y` (first the most significant),
    /// each scrambled (`y'_r`) by the net's [`DigitScramble`] given the scrambled digits
    /// above it. Cost: `K` multiply-adds, and one hash a digit when scrambled.
    #[inline]
    fn combine(&self, dim: usize, y: &[u32]) -> u64 {
        let b = self.base as u64;
        if matches!(self.scramble, DigitScramble::None) {
            return y.iter().fold(0u64, |v, &d| v * b + d as u64);
        }
        let (mut v, mut prefix, mut weight) = (0u64, 0u64, 1u64);
        for (r, &d) in y.iter().enumerate() {
            let d = self.scramble.digit(self.base, dim, r as u32 + 1, prefix, d) as u64;
            v = v * b + d;
            // The digits above this one, as the radical inverse's index prefix.
            prefix += d * weight;
            weight = weight.saturating_mul(b);
        }
        v
    }

    /// The 0.32 sample `floor(v 2^32 / b^K)` of an exact value `v < b^K`.
    #[inline]
    fn to_fraction(&self, v: u64) -> u32 {
        if self.scale == FULL_RANGE {
            // Base 2: b^K = 2^32 and the quotient is v itself.
            return v as u32;
        }
        // v < b^K, so the quotient is below 2^32.
        ((v as u128) << 32).wrapping_div(self.scale as u128) as u32
    }
}

impl<M: AsRef<[u16]>> Sampler for DigitalNetB<M> {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        self.len
    }

    /// `floor(v 2^32 / b^K)` of [`DigitalNetB::value`].
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        Ok(self.to_fraction(self.value(index, dim)?))
    }

    /// Sequentially, each dimension's output digits updated from the previous point's
    /// (`src/digital/fill.rs`: `K` additions mod `b` a value, not `K x m` products); the
    /// same bits as [`sample`](Self::sample).
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        fill::fill(self, start, out)
    }
}
