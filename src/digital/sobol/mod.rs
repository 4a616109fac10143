//! The Sobol' sequence (Sobol' 1967) with Joe & Kuo's direction numbers (2008): a digital
//! sequence in base 2 whose first `2^m` points form a `(t, m, d)`-net in every dimension
//! count, with good two-dimensional projections up to 21201 dimensions.
//!
//! Dimension `j` has a 32x32 generator matrix over GF(2) whose columns are the direction
//! numbers `V_1 .. V_32` (0.32 fractions; `V_k = m_k 2^-k` for the table's initial `m_k`,
//! then the primitive-polynomial recurrence). Point `i` is, in natural order,
//!
//! ```text
//! x_j(i) = XOR over the set bits k of i of V_(k+1)     (a 0.32 fraction)
//! ```
//!
//! Dimension 0 is the van der Corput sequence. In Gray-code order (SciPy's order) the `i`-th
//! point is the natural point of index `gray(i)`, and consecutive points differ by a single
//! direction number (Antonov & Saleev 1979), which [`SobolGray`] uses.
//!
//! The same sequence with hash-based Owen scrambling, for hot loops and per-pixel seeds, is
//! [`OwenSobol`] (and the free functions [`owen_sobol`], [`owen_sobol_f32`]): the same bits
//! as `Scrambled<Sobol, FastOwen>`.

use crate::bits::Affine;
use crate::bits::{gf2_mul, gray};
use crate::error::{Error, Result};
use crate::sampler::{Base2Digital, FULL_RANGE, Sampler, check};

pub mod interlaced;
mod owen;
mod table;

pub use owen::{OwenSobol, owen_sobol, owen_sobol_f32};
pub use table::SobolTable;
pub(crate) use table::byte_tables;

include!(concat!(env!("OUT_DIR"), "/sobol.rs"));

/// The direction numbers `[V_1, .., V_32]` of dimension `dim` (0-based).
///
/// # Errors
/// [`Error::DimensionOutOfRange`] past [`SOBOL_MAX_DIMS`] (enable `sobol-dims-1024` or
/// `sobol-dims-21201` for more).
///
/// ```
/// // Joe & Kuo's dimension 3 (0-based 2): s = 2, a = 1, m = (1, 3).
/// let v = qmckit::digital::sobol::directions(2)?;
/// assert_eq!(v[..2], [1 << 31, 3 << 30]);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub const fn directions(dim: usize) -> Result<&'static [u32; 32]> {
    if dim < SOBOL_MAX_DIMS {
        Ok(&SOBOL_DIRECTIONS[dim])
    } else {
        Err(Error::DimensionOutOfRange {
            dim,
            dims: SOBOL_MAX_DIMS,
        })
    }
}

/// `[V_1, V_1 ^ V_2, .., V_1 ^ .. ^ V_32]`: the natural-order increments (see
/// [`SobolDimension::increments`]).
const fn prefix_xors(v: &[u32; 32]) -> [u32; 32] {
    let mut p = [0u32; 32];
    let mut acc = 0u32;
    let mut k = 0;
    while k < 32 {
        acc ^= v[k];
        p[k] = acc;
        k += 1;
    }
    p
}

/// Dimensions advanced together by [`Sobol`]'s sequential fill.
const FILL_BLOCK: usize = 32;

/// One Sobol' dimension: its direction numbers, validated once; random access is then
/// infallible and `const`.
///
/// ```
/// use qmckit::digital::sobol::SobolDimension;
/// const Y: SobolDimension = match SobolDimension::new(1) { Ok(d) => d, Err(_) => panic!() };
/// // The second dimension's first points: 0, 1/2, 3/4, 1/4 (natural order).
/// let ys: Vec<u32> = (0..4).map(|i| Y.sample(i) >> 30).collect();
/// assert_eq!(ys, [0, 2, 3, 1]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct SobolDimension {
    /// Held by value (128 bytes), so a `const` dimension in firmware links only its own
    /// direction numbers, not the whole compiled-in table.
    v: [u32; 32],
}

impl SobolDimension {
    /// Dimension `dim` (0-based).
    ///
    /// # Errors
    /// [`Error::DimensionOutOfRange`] past [`SOBOL_MAX_DIMS`].
    pub const fn new(dim: usize) -> Result<Self> {
        match directions(dim) {
            Ok(v) => Ok(SobolDimension { v: *v }),
            Err(e) => Err(e),
        }
    }

    /// The direction numbers `[V_1, .., V_32]` (the generator matrix's columns).
    pub const fn directions(&self) -> &[u32; 32] {
        &self.v
    }

    /// Natural-order point `index`: the XOR of `V_(k+1)` over the set bits `k` of `index`.
    /// A branch-free loop over the 32 bits; `const`. Defined for every `u32` index.
    #[inline]
    pub const fn sample(&self, index: u32) -> u32 {
        gf2_mul(&self.v, index)
    }

    /// `P_t = V_1 ^ .. ^ V_(t+1)`: going from index `i` to `i + 1` flips the `t + 1` lowest
    /// bits of `i`, where `t` is its number of trailing ones, so `x(i + 1) = x(i) ^ P_t`.
    pub const fn increments(&self) -> [u32; 32] {
        prefix_xors(&self.v)
    }

    /// Fills every `stride`-th element of `out` with consecutive natural-order points from
    /// `start`: one table read and one XOR a value.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] past index `u32::MAX`; [`Error::BufferLength`] for a
    /// zero stride.
    pub fn fill_strided(&self, start: u32, out: &mut [u32], stride: usize) -> Result<()> {
        let count = checked_count(start, out.len(), stride)?;
        let p = self.increments();
        let mut x = self.sample(start);
        let mut i = start;
        for (k, slot) in out.iter_mut().step_by(stride).enumerate() {
            *slot = x;
            if k + 1 < count {
                x ^= p[(i.trailing_ones() & 31) as usize];
                i = i.wrapping_add(1);
            }
        }
        Ok(())
    }

    /// The Gray-code-order sequence from position `start` (SciPy's order): position `i`
    /// holds natural point `gray(i)`, and each step XORs one direction number.
    pub const fn gray_from(&self, start: u32) -> SobolGray {
        SobolGray {
            v: self.v,
            x: self.sample(gray(start)),
            next: start as u64,
        }
    }
}

/// Number of slots a strided fill writes, checked against the `u32` index range.
fn checked_count(start: u32, len: usize, stride: usize) -> Result<usize> {
    if stride == 0 {
        return Err(Error::BufferLength {
            expected: 1,
            got: 0,
        });
    }
    let count = len.div_ceil(stride);
    crate::radical_inverse::check_range(start, count as u64)?;
    Ok(count)
}

/// One Sobol' dimension in Gray-code order: yields `x(gray(i))` for `i = start, start + 1,
/// ...` up to `u32::MAX`, each step one XOR (Antonov & Saleev 1979).
///
/// ```
/// use qmckit::digital::sobol::SobolDimension;
/// let d = SobolDimension::new(5)?;
/// assert!(d.gray_from(100).take(50).zip(100u32..).all(|(x, i)| x == d.sample(i ^ (i >> 1))));
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct SobolGray {
    v: [u32; 32],
    x: u32,
    /// Position of `x` (2^32 once exhausted).
    next: u64,
}

impl Iterator for SobolGray {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        if self.next >= FULL_RANGE {
            return None;
        }
        let x = self.x;
        self.next += 1;
        // gray(i) ^ gray(i + 1) is bit tz(i + 1).
        let k = (self.next as u32).trailing_zeros() & 31;
        self.x ^= self.v[k as usize];
        Some(x)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = usize::try_from(FULL_RANGE - self.next).unwrap_or(usize::MAX);
        (left, Some(left))
    }
}

/// Point order of a [`Sobol`] sequence.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Order {
    /// Index `i` gives point `i` (the generator matrices applied to `i`).
    #[default]
    Natural,
    /// Index `i` gives natural point `gray(i)`: SciPy's and Antonov–Saleev's order. The
    /// first `2^m` points are the same set in both orders.
    Gray,
}

/// The Sobol' sequence in `dims` dimensions (Joe & Kuo direction numbers), unscrambled.
///
/// ```
/// use qmckit::{Sampler, digital::sobol::{Order, Sobol}};
/// let s = Sobol::new(3)?;
/// assert_eq!(s.sample(1, 2)?, 1 << 31); // every dimension starts 0, 1/2
/// let g = Sobol::with_order(3, Order::Gray)?;
/// assert_eq!(g.sample(2, 0)?, s.sample(3, 0)?); // gray(2) = 3
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Sobol {
    dims: usize,
    order: Order,
}

impl Sobol {
    /// Natural order, `1 <= dims <= SOBOL_MAX_DIMS`.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`], [`Error::DimensionOutOfRange`].
    pub const fn new(dims: usize) -> Result<Self> {
        Self::with_order(dims, Order::Natural)
    }

    /// The given order, `1 <= dims <= SOBOL_MAX_DIMS`.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`], [`Error::DimensionOutOfRange`].
    pub const fn with_order(dims: usize, order: Order) -> Result<Self> {
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if dims > SOBOL_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: dims - 1,
                dims: SOBOL_MAX_DIMS,
            });
        }
        Ok(Sobol { dims, order })
    }

    /// The order.
    pub const fn order(&self) -> Order {
        self.order
    }

    /// Coordinate `dim` of the point at `index` (in this sequence's order). `const`.
    ///
    /// # Errors
    /// [`Error::DimensionOutOfRange`].
    #[inline]
    pub const fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        if let Err(e) = check(index, FULL_RANGE, dim, self.dims) {
            return Err(e);
        }
        let i = match self.order {
            Order::Natural => index,
            Order::Gray => gray(index),
        };
        match SobolDimension::new(dim) {
            Ok(d) => Ok(d.sample(i)),
            Err(e) => Err(e),
        }
    }
}

impl Sobol {
    /// Fills dimensions `first .. first + block` (`block <= L`) of the row-major buffer `out`
    /// with consecutive points from `start`. The block's direction numbers are transposed to
    /// bit-major rows `T[k][lane]` (natural order: the prefix XORs `V_1 ^ .. ^ V_(k+1)`), so
    /// each point is one element-wise XOR of a contiguous row into `L` running values: Gray
    /// order uses row `tz(i + 1)`, natural order row `trailing_ones(i)`. `32 L` words of
    /// stack. The fold ([`Fold`]) is applied to the table rows and the start point only.
    fn fill_block<const L: usize>(
        &self,
        start: u32,
        out: &mut [u32],
        first: usize,
        block: usize,
        fold: Fold<'_, L>,
    ) {
        let Some(dirs) = SOBOL_DIRECTIONS.get(first..first + block) else {
            return; // unreachable: dims <= SOBOL_MAX_DIMS
        };
        let rows = out.len() / self.dims.max(1);
        // Steps from `start` to the last index change bits below `span` only (the indices
        // share their higher bits), so the table needs rows `0..span`: a pixel's 16 points
        // build 4 rows, not 32.
        let last = start.wrapping_add(rows.saturating_sub(1) as u32);
        let span = (32 - (start ^ last).leading_zeros()) as usize;
        let mut table = [[0u32; L]; 32];
        let mut x = [0u32; L];
        for (lane, v) in dirs.iter().enumerate().take(L) {
            let i0 = match self.order {
                Order::Gray => gray(start),
                Order::Natural => start,
            };
            // An affine scramble x -> M x ^ c folds in: rows M V_k, start M (C i0) ^ c. The
            // bit reversal is linear too; it is applied as `reverse_bits` (a dozen
            // operations) rather than as a matrix (32 masked XORs).
            let linear = |y: u32| match fold {
                Fold::None => y,
                Fold::Reverse => y.reverse_bits(),
                Fold::Maps(m) => m.get(lane).map_or(y, |m| m.linear(y)),
            };
            let mut acc = 0;
            for (row, &vk) in table.iter_mut().zip(v).take(span) {
                let vk = linear(vk);
                acc ^= vk;
                row[lane] = match self.order {
                    Order::Gray => vk,
                    Order::Natural => acc, // V_1 ^ .. ^ V_(k+1)
                };
            }
            let x0 = if i0 == 0 { 0 } else { gf2_mul(v, i0) };
            x[lane] = match fold {
                Fold::Maps(m) => m.get(lane).map_or(x0, |m| m.apply(x0)),
                _ => linear(x0),
            };
        }
        crate::dispatch::run(SobolRows {
            out,
            dims: self.dims.max(1),
            first,
            block,
            start,
            gray: self.order == Order::Gray,
            table: &table,
            x,
        });
    }
}

/// Rows a group of [`SobolRows`]: `2^GROUP_BITS`.
const GROUP_BITS: u32 = 3;
/// [`GROUP_BITS`] as a count.
const GROUP: usize = 1 << GROUP_BITS;

/// The row loop of [`Sobol::fill_block`]: lanes `first .. first + block` of consecutive
/// points from `start`, given the point at `start` (`x`) and the transposed step rows
/// (`table[k]`: Gray order `V_k`, natural order `V_0 ^ .. ^ V_k`).
///
/// Rows go in aligned groups of `G = 2^g` indices (`g` = [`GROUP_BITS`]): the generator
/// matrix `C` is linear and so is `gray`, so the point at `G q + r` (`r < G`) is
/// `x(G q) ^ T[r]` with `T[r] = C gray(r)` (natural order `C r`), the same `G` rows for
/// every group; from one group to the next the start point changes by
/// `C (gray(G (q + 1)) ^ gray(G q)) = V_(g-1) ^ V_(g+t)` (natural order
/// `V_g ^ .. ^ V_(g+t)`), `t = tz(q + 1)`: in both orders `table[g + t] ^ table[g - 1]`.
/// A group is `G` independent element-wise XORs (no chain from row to row), so it
/// vectorizes across rows; the rows before the first aligned index and after the last
/// whole group take the one-step recurrence. Compiled per build of [`crate::dispatch`].
struct SobolRows<'a, const L: usize> {
    out: &'a mut [u32],
    dims: usize,
    first: usize,
    block: usize,
    start: u32,
    gray: bool,
    table: &'a [[u32; L]; 32],
    x: [u32; L],
}

impl<const L: usize> SobolRows<'_, L> {
    /// The step row after index `i` (`i -> i + 1`).
    #[inline(always)]
    fn step(&self, i: u32) -> &[u32; L] {
        let k = if self.gray {
            i.wrapping_add(1).trailing_zeros()
        } else {
            i.trailing_ones()
        };
        &self.table[(k & 31) as usize]
    }
}

impl<const L: usize> crate::dispatch::Kernel for SobolRows<'_, L> {
    type Output = ();
    #[inline(always)]
    fn run(mut self) {
        // `dims >= 1` (the caller's `max(1)`), restated here and at each chunking (which an
        // inliner may see apart), so that no division or chunking by zero is left in the
        // build (the firmware's link-time panic proof).
        let (dims, first, block) = (self.dims.max(1), self.first, self.block);
        let out = core::mem::take(&mut self.out);
        let rows = out.len() / dims;
        // Rows before the first aligned index (all of them when no whole group follows),
        // the whole groups, then the rest.
        let to_aligned = (GROUP - self.start as usize % GROUP) % GROUP;
        let head = if rows < to_aligned + GROUP {
            rows
        } else {
            to_aligned
        };
        let groups = (rows - head) / GROUP;
        let (head_rows, rest) = out.split_at_mut((head * dims).min(out.len()));
        let (group_rows, tail_rows) = rest.split_at_mut((groups * GROUP * dims).min(rest.len()));
        let mut x = self.x;
        let mut i = self.start;
        let put = |row: &mut [u32], v: &[u32; L]| {
            if block == L {
                if let Some(dst) = row.get_mut(first..first + L) {
                    dst.copy_from_slice(v);
                }
            } else if let Some(dst) = row.get_mut(first..first + block) {
                for (o, v) in dst.iter_mut().zip(v) {
                    *o = *v;
                }
            }
        };
        // One step a row; `x` ends at the point after the last row.
        let one_by_one = |rows: &mut [u32], x: &mut [u32; L], i: &mut u32| {
            for row in rows.chunks_exact_mut(dims.max(1)) {
                put(row, x);
                let s = self.step(*i);
                for lane in 0..L {
                    x[lane] ^= s[lane];
                }
                *i = i.wrapping_add(1);
            }
        };
        one_by_one(head_rows, &mut x, &mut i);
        if groups > 0 {
            // The group table T[r] (row r of any aligned group, relative to its start).
            let mut t = [[0u32; L]; GROUP];
            for r in 1..GROUP {
                let s = self.step(r as u32 - 1);
                for lane in 0..L {
                    t[r][lane] = t[r - 1][lane] ^ s[lane];
                }
            }
            let low = self.table[(GROUP_BITS - 1) as usize];
            let mut q = i >> GROUP_BITS;
            let mut base = x;
            for group in group_rows.chunks_exact_mut(GROUP.saturating_mul(dims).max(1)) {
                if dims == L && block == L {
                    // Contiguous rows of L values: GROUP * L values in a row.
                    let (rows, _) = group.as_chunks_mut::<L>();
                    for (row, tr) in rows.iter_mut().zip(&t) {
                        *row = core::array::from_fn(|lane| base[lane] ^ tr[lane]);
                    }
                } else {
                    for (row, tr) in group.chunks_exact_mut(dims.max(1)).zip(&t) {
                        put(row, &core::array::from_fn(|lane| base[lane] ^ tr[lane]));
                    }
                }
                // To the next group: C (gray(G (q+1)) ^ gray(G q)).
                q = q.wrapping_add(1);
                let up = &self.table[((q.trailing_zeros() + GROUP_BITS) & 31) as usize];
                base = core::array::from_fn(|lane| base[lane] ^ up[lane] ^ low[lane]);
            }
            x = base;
            i = i.wrapping_add((groups * GROUP) as u32);
        }
        one_by_one(tail_rows, &mut x, &mut i);
    }
}

impl Sampler for Sobol {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        FULL_RANGE
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        Sobol::sample(self, index, dim)
    }

    /// Sequential fast path, row by row (the buffer is written once, in order), dimensions
    /// in blocks of up to 32 whose running values are updated by one element-wise XOR of a
    /// transposed row of direction numbers per point.
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        self.fill_maps(start, out, Maps::None).unwrap_or(Ok(()))
    }
}

impl Sobol {
    /// [`Sampler::fill`], with the dimensions' affine maps folded in when given; `None` when
    /// a map is `None` (then `out` is partly written).
    fn fill_maps(&self, start: u32, out: &mut [u32], maps: Maps<'_>) -> Option<Result<()>> {
        let rows = match crate::sampler::check_fill(self, start, out.len()) {
            Ok(rows) => rows,
            Err(e) => return Some(Err(e)),
        };
        if rows == 0 || self.dims == 0 {
            return Some(Ok(()));
        }
        let mut first = 0;
        while first < self.dims {
            let block = (self.dims - first).min(FILL_BLOCK);
            // Lanes rounded up to a power of two, so the XOR loop is a fixed-size one.
            match block {
                1..=2 => self.fill_mapped::<2>(start, out, first, block, maps),
                3..=4 => self.fill_mapped::<4>(start, out, first, block, maps),
                5..=8 => self.fill_mapped::<8>(start, out, first, block, maps),
                9..=16 => self.fill_mapped::<16>(start, out, first, block, maps),
                _ => self.fill_mapped::<32>(start, out, first, block, maps),
            }?;
            first += block;
        }
        Some(Ok(()))
    }

    /// [`fill_block`](Self::fill_block) with the block's maps gathered (identity past its
    /// end); `None` when a map is `None`.
    #[inline]
    fn fill_mapped<const L: usize>(
        &self,
        start: u32,
        out: &mut [u32],
        first: usize,
        block: usize,
        maps: Maps<'_>,
    ) -> Option<()> {
        match maps {
            Maps::None => self.fill_block::<L>(start, out, first, block, Fold::None),
            Maps::Reverse => self.fill_block::<L>(start, out, first, block, Fold::Reverse),
            Maps::Each(f) => {
                let mut m = [Affine::IDENTITY; L];
                for (lane, slot) in m.iter_mut().enumerate().take(block) {
                    *slot = f(first + lane)?;
                }
                self.fill_block::<L>(start, out, first, block, Fold::Maps(&m));
            }
        }
        Some(())
    }
}

/// The maps [`Sobol::fill_maps`] folds into the direction numbers: none, the bit reversal
/// (every dimension), or each dimension's affine map (`None` stops the fill).
#[derive(Clone, Copy)]
enum Maps<'a> {
    None,
    Reverse,
    Each(&'a dyn Fn(usize) -> Option<Affine>),
}

/// [`Maps`] gathered for one block of `L` dimensions.
#[derive(Clone, Copy)]
enum Fold<'a, const L: usize> {
    None,
    Reverse,
    Maps(&'a [Affine; L]),
}

/// Sobol' is a base-2 digital sequence: base-2 digital randomizations apply.
impl Base2Digital for Sobol {
    /// The scramble folded into the direction numbers: `(M C) i ^ c`, the cost of the plain
    /// fill plus `span + 1` map applications a dimension (`span`: the index bits the fill
    /// changes).
    fn fill_affine(
        &self,
        start: u32,
        out: &mut [u32],
        maps: &dyn Fn(usize) -> Option<Affine>,
    ) -> Option<Result<()>> {
        self.fill_maps(start, out, Maps::Each(maps))
    }

    /// Up to four dimensions in natural order on 64-bit targets: each point's reversed
    /// coordinates are four reads of the interleaved byte tables of the reversed direction
    /// numbers (the tables of [`OwenSobol`]), XORed, with no reversal a value. Otherwise
    /// (wider points, Gray order, and 32-bit targets, which keep their flash free of the
    /// 16 KiB of tables) the reversal is folded into the direction numbers like any linear
    /// map (`reverse(V_k)`, `reverse(x_start)`): the sequential fill's cost, no reversal a
    /// value.
    #[inline]
    fn fill_reversed(&self, start: u32, out: &mut [u32]) -> Option<Result<()>> {
        #[cfg(target_pointer_width = "64")]
        if self.order == Order::Natural && self.dims <= owen::TABLE_DIMS {
            return Some(
                crate::sampler::check_fill(self, start, out.len())
                    .map(|_| owen::fill_reversed(self.dims, start, out)),
            );
        }
        self.fill_maps(start, out, Maps::Reverse)
    }
}
