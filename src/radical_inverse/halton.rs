//! The Halton sequence: `x_i = (phi_2(i), phi_3(i), phi_5(i), ...)`, one prime base a
//! dimension (Halton 1960).
//!
//! Infinite (every `u32` index) and extensible in dimension up to [`HALTON_MAX_DIMS`]; low
//! discrepancy, `D*_N = O((log N)^d / N)`. Beware of its high-dimensional 2D projections
//! (e.g. bases 29 and 31 are strongly correlated over the first points); scrambled variants
//! fix that. Unscrambled, it equals SciPy's `qmc.Halton(d, scramble=False)` (which also
//! starts at index 0, with the point at the origin) to within SciPy's float rounding.

use crate::bits::FromFraction;
use crate::error::{Error, Result};
#[cfg(target_pointer_width = "64")]
use crate::radical_inverse::RunFill;
use crate::radical_inverse::{RadicalInverse, RadicalInverseIter};
use crate::randomize::digits::DigitScramble;
use crate::sampler::{FULL_RANGE, Sampler, check};

include!(concat!(env!("OUT_DIR"), "/primes.rs"));

/// Radical-inverse constants for the first [`HALTON_MAX_DIMS`] primes, const-evaluated:
/// 104 bytes a base on 64-bit targets, 48 on 32-bit ones (104 / 48 KiB in all, linked only
/// when indexed at run time).
pub static HALTON_BASES: [RadicalInverse; HALTON_MAX_DIMS] = {
    let mut table = [match RadicalInverse::new(2) {
        Ok(r) => r,
        Err(_) => panic!("2 is a valid base"),
    }; HALTON_MAX_DIMS];
    let mut k = 0;
    while k < HALTON_MAX_DIMS {
        table[k] = match RadicalInverse::new(PRIMES[k] as u32) {
            Ok(r) => r,
            Err(_) => panic!("primes are valid bases"),
        };
        k += 1;
    }
    table
};

/// The `dim`-th prime (0-based: `prime(0) == Some(2)`), or `None` past the table.
///
/// ```
/// assert_eq!(qmckit::radical_inverse::halton::prime(1023), Some(8161));
/// ```
pub const fn prime(dim: usize) -> Option<u32> {
    if dim < HALTON_MAX_DIMS {
        Some(PRIMES[dim] as u32)
    } else {
        None
    }
}

/// The Halton sequence in `dims` dimensions.
///
/// ```
/// use qmckit::Halton;
/// let h = Halton::new(2)?;
/// // Point 1 is (1/2, 1/3); 1/3 rounds down to 0x5555_5555.
/// assert_eq!(h.sample(1, 0)?, 0x8000_0000);
/// assert_eq!(h.sample(1, 1)?, 0x5555_5555);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Halton {
    dims: usize,
    scramble: DigitScramble,
}

impl Halton {
    /// A Halton sequence with `dims` dimensions (bases: the first `dims` primes).
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`]; [`Error::DimensionOutOfRange`] past [`HALTON_MAX_DIMS`].
    pub const fn new(dims: usize) -> Result<Self> {
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if dims > HALTON_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: dims - 1,
                dims: HALTON_MAX_DIMS,
            });
        }
        Ok(Halton {
            dims,
            scramble: DigitScramble::None,
        })
    }

    /// A Halton sequence whose digits are scrambled (random permutations, Faure, or Owen in
    /// base `b`; see [`DigitScramble`]). Random permutations fix the poor 2D projections of
    /// high bases, e.g. `(phi_29, phi_31)`.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    ///
    /// ```
    /// use qmckit::{Halton, randomize::digits::DigitScramble};
    /// let h = Halton::with_scramble(10, DigitScramble::Permutations(7))?;
    /// assert_ne!(h.sample(0, 9)?, 0); // scrambled leading zeros: the origin moves
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub const fn with_scramble(dims: usize, scramble: DigitScramble) -> Result<Self> {
        match Self::new(dims) {
            Ok(h) => Ok(Halton { scramble, ..h }),
            Err(e) => Err(e),
        }
    }

    /// The digit scrambling.
    pub const fn scramble(&self) -> DigitScramble {
        self.scramble
    }

    /// Number of dimensions.
    pub const fn dims(&self) -> usize {
        self.dims
    }

    /// The radical inverse of dimension `dim`.
    ///
    /// # Errors
    /// [`Error::DimensionOutOfRange`].
    #[inline]
    pub const fn dimension(&self, dim: usize) -> Result<&'static RadicalInverse> {
        // `dims <= HALTON_MAX_DIMS` (checked by `new`), so the split never fails; it lets one
        // comparison per call guard both the dimension and the indexing (no panic path).
        let bases = match HALTON_BASES.split_at_checked(self.dims) {
            Some((bases, _)) => bases,
            None => &HALTON_BASES,
        };
        if dim < bases.len() {
            return Ok(&bases[dim]);
        }
        Err(Error::DimensionOutOfRange {
            dim,
            dims: self.dims,
        })
    }

    /// Coordinate `dim` of point `index`: `floor(phi_p(index) 2^32)` for the `dim`-th prime
    /// `p`. `const`, exact; cost as [`RadicalInverse::sample`].
    ///
    /// # Errors
    /// [`Error::DimensionOutOfRange`].
    #[inline(always)]
    pub const fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        match self.dimension(dim) {
            // The unscrambled case inline (the scrambled digit loop stays out of line).
            Ok(ri) if self.scramble.is_none() => Ok(ri.sample(index)),
            Ok(ri) => Ok(ri.sample_scrambled(index, &self.scramble, dim)),
            Err(e) => Err(e),
        }
    }

    /// A sequential iterator over points `start, start + 1, ...` as `[u32; D]` (`D` must
    /// equal `dims()`), bit-identical to [`sample`](Self::sample) and a few cycles a value.
    ///
    /// # Errors
    /// [`Error::BufferLength`] if `D != dims()`.
    ///
    /// ```
    /// use qmckit::Halton;
    /// let h = Halton::new(3)?;
    /// let p: Vec<[u32; 3]> = h.points::<3>(10)?.take(2).collect();
    /// assert_eq!(p[1][2], h.sample(11, 2)?);
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn points<const D: usize>(&self, start: u32) -> Result<HaltonPoints<D>> {
        if !self.scramble.is_none() {
            return Err(Error::Unsupported {
                what: "the sequential Halton iterator of a scrambled sequence (use sample/fill)",
            });
        }
        if D != self.dims {
            return Err(Error::BufferLength {
                expected: self.dims,
                got: D,
            });
        }
        Ok(HaltonPoints {
            dims: core::array::from_fn(|d| HALTON_BASES[d].iter_from(start)),
        })
    }
}

/// Iterator over Halton points as `[u32; D]`, from [`Halton::points`].
#[derive(Clone, Debug)]
pub struct HaltonPoints<const D: usize> {
    dims: [RadicalInverseIter; D],
}

impl<const D: usize> Iterator for HaltonPoints<D> {
    type Item = [u32; D];

    #[inline]
    fn next(&mut self) -> Option<[u32; D]> {
        let mut p = [0u32; D];
        for (slot, it) in p.iter_mut().zip(self.dims.iter_mut()) {
            *slot = it.next()?;
        }
        Some(p)
    }
}

impl Sampler for Halton {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        FULL_RANGE
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        check(index, FULL_RANGE, dim, self.dims)?;
        Halton::sample(self, index, dim)
    }

    /// Random access to a whole point: one pass over the bases, the scrambling checked once
    /// (faster than `dims()` calls of [`sample`](Sampler::sample)). Same bits.
    #[inline]
    fn point(&self, index: u32, out: &mut [u32]) -> Result<()> {
        if out.len() != self.dims {
            return Err(Error::BufferLength {
                expected: self.dims,
                got: out.len(),
            });
        }
        self.point_as(index, out);
        Ok(())
    }

    /// Sequential fast path, as [`fill_as`](Sampler::fill_as).
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        self.fill_as(start, out)
    }

    /// Sequential fast path in any coordinate type, converted as stored: one run state
    /// ([`RadicalInverse::fill_strided_as`]) per dimension, column by column; on 64-bit
    /// targets from 4 dimensions on, blocked (see `fill_blocked`).
    /// Scrambled sequences go point by point. Same values as [`sample`](Sampler::sample).
    fn fill_as<T: FromFraction>(&self, start: u32, out: &mut [T]) -> Result<()> {
        let rows = crate::sampler::check_fill(self, start, out.len())?;
        if rows == 0 {
            return Ok(());
        }
        #[cfg(feature = "std")]
        if super::permuted::is_per_place(&self.scramble) && self.dims > 0 {
            self.fill_permuted(start, out, rows);
            return Ok(());
        }
        if !self.scramble.is_none() && self.dims > 0 {
            for (k, row) in out.chunks_exact_mut(self.dims).enumerate() {
                self.point_as(start + k as u32, row);
            }
            return Ok(());
        }
        #[cfg(target_pointer_width = "64")]
        if self.dims >= BLOCKED_MIN_DIMS {
            return fill_blocked(self.dims, start, out, rows);
        }
        for (dim, ri) in HALTON_BASES.iter().take(self.dims).enumerate() {
            if let Some(column) = out.get_mut(dim..) {
                ri.fill_strided_as(start, column, self.dims)?;
            }
        }
        Ok(())
    }
}

/// Rows a block of the digit-permuted fill (its columns are written while the block's rows
/// are in cache).
#[cfg(feature = "std")]
const PERMUTED_BLOCK: usize = 2048;

impl Halton {
    /// The fill of a sequence scrambled by one permutation a digit place (already
    /// range-checked, `rows >= 1`): block by block of rows, each dimension from its
    /// resumable [`PermutedFill`](super::permuted::PermutedFill) when the fill has at least
    /// `base` rows (its tables are then paid for), else value by value. Same values as
    /// [`sample`](Sampler::sample).
    #[cfg(feature = "std")]
    fn fill_permuted<T: FromFraction>(&self, start: u32, out: &mut [T], rows: usize) {
        use super::permuted::PermutedFill;
        let dims = self.dims;
        let mut states: std::vec::Vec<Option<PermutedFill>> = HALTON_BASES
            .iter()
            .take(dims)
            .enumerate()
            .map(|(dim, ri)| {
                (rows as u64 >= ri.base() as u64)
                    .then(|| PermutedFill::new(ri, &self.scramble, dim, start))
            })
            .collect();
        for (b, block) in out.chunks_mut(PERMUTED_BLOCK * dims).enumerate() {
            let n = block.len() / dims;
            let first = start as usize + b * PERMUTED_BLOCK;
            for (dim, (state, ri)) in states.iter_mut().zip(HALTON_BASES.iter()).enumerate() {
                let Some(column) = block.get_mut(dim..) else {
                    continue;
                };
                match state {
                    Some(s) => s.fill_strided_as(column, dims, n),
                    None => {
                        for (k, slot) in column.iter_mut().step_by(dims).take(n).enumerate() {
                            // first + k < start + rows <= 2^32 (range-checked).
                            let index = (first + k) as u32;
                            *slot =
                                T::from_fraction(ri.sample_scrambled(index, &self.scramble, dim));
                        }
                    }
                }
            }
        }
    }

    /// Point `index` into `out`, converted: its first `out.len()` coordinates (callers pass
    /// `dims()` slots; no bound beyond the table's is needed, which keeps the loop simple).
    #[inline]
    fn point_as<T: FromFraction>(&self, index: u32, out: &mut [T]) {
        let bases = HALTON_BASES.iter();
        if self.scramble.is_none() {
            for (slot, ri) in out.iter_mut().zip(bases) {
                *slot = T::from_fraction(ri.sample(index));
            }
        } else {
            for (dim, (slot, ri)) in out.iter_mut().zip(bases).enumerate() {
                *slot = T::from_fraction(ri.sample_scrambled(index, &self.scramble, dim));
            }
        }
    }
}

/// Dimensions the blocked fill takes at once, rows a block, and the fewest dimensions for
/// which it is used (64-bit targets only: its state is `GROUP` run tables, about 12 KiB of
/// stack).
#[cfg(target_pointer_width = "64")]
const GROUP: usize = 8;
#[cfg(target_pointer_width = "64")]
const BLOCK: usize = 128;
#[cfg(target_pointer_width = "64")]
const BLOCKED_MIN_DIMS: usize = 4;

/// The unscrambled Halton fill of `rows` points from `start` (already range-checked) into
/// the row-major `out`, `GROUP` dimensions at a time and `BLOCK` rows at a time, so that
/// the `GROUP` columns of a block are written while its rows are in cache (a column at a
/// time over all rows touches every cache line of the buffer once per dimension), and each
/// block column is computed contiguously (the run arithmetic vectorizes) into a
/// `GROUP x BLOCK` scratch of `u32` (4 KiB) before it is transposed into the rows,
/// converted to `T` on the way (a full group's row is one fixed-size array, which for `f64`
/// compiles to two-lane conversions; converting in the scratch instead, into 8 KiB of `f64`,
/// measured slower). Each dimension of a group keeps its resumable run state ([`RunFill`],
/// base 2 included); the bases without one (above the run table) then fill their whole
/// column with `fill_strided_as`, over what the transposition left there. Same values as
/// the column-by-column fill.
#[cfg(target_pointer_width = "64")]
fn fill_blocked<T: FromFraction>(
    dims: usize,
    start: u32,
    out: &mut [T],
    rows: usize,
) -> Result<()> {
    let bases = HALTON_BASES.get(..dims).unwrap_or(&[]);
    for (g, group) in bases.chunks(GROUP).enumerate() {
        let first = g * GROUP;
        let mut tmp = [[0u32; BLOCK]; GROUP];
        let mut states: [Option<RunFill>; GROUP] = core::array::from_fn(|j| {
            group
                .get(j)
                .filter(|ri| ri.by_runs())
                .map(|ri| RunFill::new(ri, start))
        });
        let mut row = 0;
        while row < rows {
            let n = BLOCK.min(rows - row);
            // Each column of the block contiguously (vectorizes), then row by row into place.
            for (state, col) in states.iter_mut().zip(tmp.iter_mut()) {
                if let Some(state) = state {
                    state.write(col, 1, n);
                }
            }
            let block = out.get_mut(row * dims..).unwrap_or(&mut []);
            transpose(&tmp, block, dims, first, group.len(), n);
            row += n;
        }
        for (j, ri) in group.iter().enumerate() {
            if let Some(col) = out.get_mut(first + j..).filter(|_| !ri.by_runs()) {
                ri.fill_strided_as(start, col, dims)?;
            }
        }
    }
    Ok(())
}

/// Rows `0 .. n` of the first `width` scratch columns of a block into its points (`dims`
/// values each, from coordinate `first` on), converted. A full group (`width == GROUP`)
/// moves as one fixed-size array a point (8 loads and 8 stores, unrolled) with one bounds
/// check; a partial last group value by value.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn transpose<T: FromFraction>(
    tmp: &[[u32; BLOCK]; GROUP],
    block: &mut [T],
    dims: usize,
    first: usize,
    width: usize,
    n: usize,
) {
    let value = |j: usize, r: usize| T::from_fraction(tmp[j % GROUP].get(r).copied().unwrap_or(0));
    let mut pos = first;
    if width == GROUP {
        for r in 0..n.min(BLOCK) {
            if let Some(dst) = block
                .get_mut(pos..)
                .and_then(|s| s.first_chunk_mut::<GROUP>())
            {
                *dst = core::array::from_fn(|j| value(j, r));
            }
            pos += dims;
        }
    } else {
        for r in 0..n.min(BLOCK) {
            let dst = block.get_mut(pos..).unwrap_or(&mut []);
            for (j, slot) in dst.iter_mut().take(width.min(GROUP)).enumerate() {
                *slot = value(j, r);
            }
            pos += dims;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bits::to_f64;

    /// The sequential fill (column by column, or blocked with the transposition for
    /// `dims >= 4` on 64-bit targets), in `u32` and `f64`, against random access for every
    /// coordinate: group
    /// edges (7, 8, 9, 17 dims), the last prime base with a run table (dimension 54, base
    /// 251) and past it, all 1024 dimensions, row counts that are not a multiple of the block,
    /// and a range that ends at index `u32::MAX`.
    /// The digit-permuted fill (random permutations and Faure's; tables for the dimensions
    /// whose base is at most the row count, value by value above it) against random access:
    /// runs that start mid-table, blocks of rows, bases past the low table (b^c > 1024 at
    /// c = 1), and a range that ends at index `u32::MAX`.
    #[cfg(feature = "std")]
    #[test]
    fn permuted_fill_matches_random_access() {
        for scramble in [DigitScramble::Permutations(7), DigitScramble::Faure] {
            for dims in [1, 2, 8, 9, 200] {
                let h = Halton::with_scramble(dims, scramble).unwrap();
                for (start, rows) in [(0u32, 5000usize), (1234, 2049), (u32::MAX - 1300, 1301)] {
                    let mut out = vec![7u32; rows * dims];
                    let mut wide = vec![7f64; rows * dims];
                    Sampler::fill(&h, start, &mut out).unwrap();
                    h.fill_as(start, &mut wide).unwrap();
                    for (k, (point, wide)) in
                        out.chunks_exact(dims).zip(wide.chunks(dims)).enumerate()
                    {
                        for (dim, (&x, &y)) in point.iter().zip(wide).enumerate() {
                            let i = start + k as u32;
                            let u = h.sample(i, dim).unwrap();
                            assert_eq!(x, u, "{scramble:?} d {dims} i {i} dim {dim}");
                            assert_eq!(y.to_bits(), to_f64(u).to_bits());
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn fill_matches_random_access_across_blocks() {
        for dims in [1, 2, 3, 4, 7, 8, 9, 17, 32, 54, 55, 56, 130, 1024] {
            let h = Halton::new(dims).unwrap();
            for (start, rows) in [(0u32, 300usize), (5, 129), (u32::MAX - 260, 261)] {
                let rows = if dims > 200 { rows.min(140) } else { rows };
                let start = if start > u32::MAX - 300 {
                    u32::MAX - (rows as u32 - 1)
                } else {
                    start
                };
                let mut out = vec![7u32; rows * dims];
                let mut wide = vec![7f64; rows * dims];
                Sampler::fill(&h, start, &mut out).unwrap();
                h.fill_as(start, &mut wide).unwrap();
                for (k, (point, wide)) in out.chunks_exact(dims).zip(wide.chunks(dims)).enumerate()
                {
                    for (dim, (&x, &y)) in point.iter().zip(wide).enumerate() {
                        let i = start + k as u32;
                        let u = h.sample(i, dim).unwrap();
                        assert_eq!(x, u, "d {dims} i {i} dim {dim}");
                        assert_eq!(
                            y.to_bits(),
                            to_f64(u).to_bits(),
                            "f64: d {dims} i {i} dim {dim}"
                        );
                    }
                }
            }
        }
    }

    /// The typed fill of a scrambled sequence (point by point) converts each coordinate.
    #[test]
    fn scrambled_typed_fill_matches_random_access() {
        let h = Halton::with_scramble(5, DigitScramble::Permutations(3)).unwrap();
        let mut out = vec![0f32; 5 * 40];
        h.fill_as(11, &mut out).unwrap();
        for (k, point) in out.chunks(5).enumerate() {
            for (dim, &y) in point.iter().enumerate() {
                let u = h.sample(11 + k as u32, dim).unwrap();
                assert_eq!(y.to_bits(), crate::bits::to_f32(u).to_bits());
            }
        }
    }
}
