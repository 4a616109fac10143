//! The quality parameter `t` of nets: exactly, from base-2 generator matrices (the rank
//! test), or from the points themselves (counting points in elementary intervals).
//!
//! # Definitions
//!
//! An *elementary interval* in base `b` of shape `(d_1, .., d_s)` is a box
//!
//! ```text
//! E = prod_j [a_j b^-d_j, (a_j + 1) b^-d_j),    0 <= a_j < b^d_j,
//! ```
//!
//! of volume `b^-(d_1 + .. + d_s)`. A set of `N = b^m` points in `[0, 1)^s` is a
//! *(t, m, s)-net in base b* (Niederreiter 1987) when every elementary interval of volume
//! `b^(t - m)` holds exactly `b^t` points, i.e. for every shape with `d_1 + .. + d_s = m - t`.
//! A (t, m, s)-net is also a (t + 1, m, s)-net (each interval of volume `b^(t + 1 - m)` is a
//! disjoint union of `b` intervals of volume `b^(t - m)`), so the *t-value* of a set, the
//! smallest such `t`, is well defined (`t <= m` always holds: the unit cube holds all
//! points). `t = 0` is the best possible: every box of volume `1/N` holds one point.
//!
//! # The rank test (base 2)
//!
//! A *digital net* in base 2 has one generator matrix `C_j` over GF(2) per dimension; point
//! `i = sum_k i_k 2^k` has coordinates `x_j(i) = sum_r y_(j,r) 2^-(r+1)` with
//! `y_j = C_j (i_0, i_1, .., i_(m-1))^T`. It is a (t, m, s)-net if and only if, for every
//! shape with `d_1 + .. + d_s = m - t`, the `m - t` rows formed by the first `d_j` rows of
//! each `C_j` (restricted to the first `m` columns) are linearly independent over GF(2)
//! (Niederreiter 1992, Lemma 4.52; Pirsic & Schmid 2001, "Calculation of the quality
//! parameter of digital nets and application to their construction", J. Complexity 17).
//! [`t_value`] searches shapes depth-first with incremental Gaussian elimination (shapes
//! that share a prefix share the elimination) for the smallest *dependent* shape; its
//! size is `m - t + 1`.
//!
//! # Matrix conventions ([`DigitalNet2`])
//!
//! A dimension is given by its columns as `u32` 0.32 fractions, as
//! [`crate::sobol::SobolDimension::directions`] holds them: column `k` is the image of index
//! digit `i_k` (weight `2^k`, `i_0` the least significant), and row `r` of the matrix
//! (output digit `r`, weight `2^-(r+1)`) is bit `31 - r` of each column. Point `i`'s
//! coordinate is the XOR of the columns `k` with `i_k = 1`, exactly what
//! [`crate::bits::gf2_mul`] computes.
//!
//! # Counting (any base, any point set)
//!
//! [`t_value_u32`] (base 2, 0.32 fractions, exact) and [`t_value_points`] (base `b`, `f64`)
//! find the largest `rho` such that every shape of size `rho` is balanced (every cell holds
//! `b^(m - rho)` points) by a binary search on `rho` (balance at `rho` implies balance below
//! it), then `t = m - rho`. [`elementary_interval_failures_u32`] and
//! [`elementary_interval_failures`] name the intervals that break a given `t`.

use super::Points;
use crate::{Error, Result};
use core::fmt;
use rayon::prelude::*;

/// A digital net in base 2 with `2^m` points: one generator matrix per dimension, each given
/// by its first `m` columns as 0.32 fractions (see the [module docs](self) for the
/// conventions).
///
/// ```
/// use qmckit::analysis::tvalue::{DigitalNet2, t_value};
/// // Hammersley in 2D with 2^4 points: (i / 16, phi_2(i)), a (0, 4, 2)-net.
/// let h = DigitalNet2::hammersley(4)?;
/// assert_eq!(h.point(3), vec![3 << 28, 0xC000_0000]); // (3/16, 3/4)
/// assert_eq!(t_value(&h), 0);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DigitalNet2 {
    m: u32,
    columns: Vec<[u32; 32]>,
}

/// Column `k` of the reversed identity for `2^m` points: `i / 2^m`, index digit `k` lands
/// on output digit `m - 1 - k`.
fn reversed_identity(m: u32) -> [u32; 32] {
    core::array::from_fn(|k| {
        let k = k as u32;
        if k < m { 1u32 << (32 - m + k) } else { 0 }
    })
}

/// The identity (van der Corput): index digit `k` lands on output digit `k`.
fn identity() -> [u32; 32] {
    core::array::from_fn(|k| 1u32 << (31 - k))
}

impl DigitalNet2 {
    /// The net with `2^m` points whose dimension `j` has the generator columns
    /// `columns[j]`; columns `k >= m` are ignored (set to zero).
    ///
    /// # Errors
    /// [`Error::MTooLarge`] for `m > 32`, [`Error::ZeroDimensions`] for no columns.
    pub fn new(m: u32, mut columns: Vec<[u32; 32]>) -> Result<Self> {
        if m > 32 {
            return Err(Error::MTooLarge { m, max: 32 });
        }
        if columns.is_empty() {
            return Err(Error::ZeroDimensions);
        }
        for c in &mut columns {
            for (k, col) in c.iter_mut().enumerate() {
                if k as u32 >= m {
                    *col = 0;
                }
            }
        }
        Ok(DigitalNet2 { m, columns })
    }

    /// The first `2^m` points of the Sobol' sequence in its first `dims` dimensions (Joe &
    /// Kuo's direction numbers).
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`], [`Error::DimensionOutOfRange`] past
    /// [`crate::SOBOL_MAX_DIMS`], [`Error::MTooLarge`].
    pub fn from_sobol(dims: usize, m: u32) -> Result<Self> {
        let dims: Vec<usize> = (0..dims).collect();
        Self::from_sobol_dimensions(&dims, m)
    }

    /// The first `2^m` points of the given Sobol' dimensions (0-based, any of those compiled
    /// in), e.g. `&[3, 17]` for a 2D projection.
    ///
    /// # Errors
    /// As [`from_sobol`](Self::from_sobol).
    pub fn from_sobol_dimensions(dims: &[usize], m: u32) -> Result<Self> {
        let columns = dims
            .iter()
            .map(|&d| crate::sobol::directions(d).copied())
            .collect::<Result<Vec<_>>>()?;
        Self::new(m, columns)
    }

    /// The 2D Larcher–Pillichshammer net: `x = i / 2^m` (the reversed identity) and `y` with
    /// the upper-triangular all-ones matrix (output digit `r` is the parity of the index
    /// digits `r..m`); a (0, m, 2)-net (Larcher & Pillichshammer 2001). The same points as
    /// [`crate::LarcherPillichshammer`].
    ///
    /// # Errors
    /// [`Error::MTooLarge`] for `m > 32`.
    pub fn larcher_pillichshammer(m: u32) -> Result<Self> {
        let y = core::array::from_fn(|k| u32::MAX << (31 - k));
        Self::new(m, vec![reversed_identity(m), y])
    }

    /// The 2D Hammersley net in base 2: `x = i / 2^m` (reversed identity), `y = phi_2(i)`
    /// (identity); a (0, m, 2)-net. The same points as the first two dimensions of
    /// [`crate::Hammersley::with_m`].
    ///
    /// # Errors
    /// [`Error::MTooLarge`] for `m > 32`.
    pub fn hammersley(m: u32) -> Result<Self> {
        Self::new(m, vec![reversed_identity(m), identity()])
    }

    /// The first `2^m` points of the base-2 van der Corput sequence (1D, the identity
    /// matrix): the multiples of `2^-m`, a (0, m, 1)-net.
    ///
    /// # Errors
    /// [`Error::MTooLarge`] for `m > 32`.
    pub fn van_der_corput(m: u32) -> Result<Self> {
        Self::new(m, vec![identity()])
    }

    /// `m`: the net has `2^m` points.
    pub fn m(&self) -> u32 {
        self.m
    }

    /// Number of dimensions `s`.
    pub fn dims(&self) -> usize {
        self.columns.len()
    }

    /// The generator columns, one `[u32; 32]` per dimension (columns `k >= m` zero).
    pub fn columns(&self) -> &[[u32; 32]] {
        &self.columns
    }

    /// Row `r` (output digit `r`, 0 = most significant) of dimension `j`'s matrix restricted
    /// to the first `m` columns, as a bitmask: bit `k` is entry `(r, k)`.
    fn row(&self, j: usize, r: u32) -> u32 {
        let Some(cols) = self.columns.get(j) else {
            return 0;
        };
        let mut row = 0u32;
        for (k, col) in cols.iter().enumerate().take(self.m as usize) {
            row |= ((col >> (31 - r)) & 1) << k;
        }
        row
    }

    /// Point `index` (its `s` coordinates as 0.32 fractions); index digits at and above `m`
    /// are ignored.
    pub fn point(&self, index: u32) -> Vec<u32> {
        self.columns
            .iter()
            .map(|c| crate::bits::gf2_mul(c, index))
            .collect()
    }

    /// All `2^m` points, row-major (`s` values a point), for the interval counters.
    ///
    /// # Errors
    /// [`Error::TooManyPoints`] when `2^m * s` values do not fit in memory indexing
    /// (`usize`).
    pub fn points(&self) -> Result<Vec<u32>> {
        let n = 1u64 << self.m;
        let total = n
            .checked_mul(self.dims() as u64)
            .and_then(|t| usize::try_from(t).ok())
            .ok_or(Error::TooManyPoints {
                requested: n,
                max: (usize::MAX / self.dims().max(1)) as u64,
            })?;
        let mut out = Vec::with_capacity(total);
        for i in 0..n {
            out.extend(
                self.columns
                    .iter()
                    .map(|c| crate::bits::gf2_mul(c, i as u32)),
            );
        }
        Ok(out)
    }
}

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

/// The exact t-value of a base-2 digital net by the rank test (see the [module docs](self)).
///
/// Searches the shapes `(d_1, .., d_s)` depth-first, dimension by dimension, adding the
/// rows of each `C_j` one at a time to an incremental Gaussian elimination (rows are `m`-bit
/// masks, one insertion at most `m` XORs), so shapes sharing a prefix share their work; a
/// branch stops at its first dependent row, and shapes as large as the smallest dependent
/// shape found so far are pruned. The result is `m + 1 - (size of the smallest dependent
/// shape)`, or 0 when every shape of size `m` is independent.
///
/// Cost: at most one node per shape of size `<= m - t + 1`, about
/// `C(m - t + 1 + s, s)` nodes of `O(m)` word operations and a 128-byte copy each:
/// microseconds for `s = 2, 3` and `m <= 32`, about 20 000 nodes for `s = 5, m = 16`. Memory
/// `O(s)` stack frames.
///
/// ```
/// use qmckit::analysis::tvalue::{DigitalNet2, t_value};
/// // Larcher–Pillichshammer and Hammersley are (0, m, 2)-nets; 2D Sobol' too.
/// assert_eq!(t_value(&DigitalNet2::larcher_pillichshammer(4)?), 0);
/// assert_eq!(t_value(&DigitalNet2::from_sobol(2, 10)?), 0);
/// // Joe–Kuo Sobol' in 3D has t = 1 for m >= 2.
/// assert_eq!(t_value(&DigitalNet2::from_sobol(3, 10)?), 1);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn t_value(net: &DigitalNet2) -> u32 {
    let m = net.m;
    let search = dependent_search(net);
    m + 1 - search.best
}

/// The smallest shape `(d_1, .., d_s)` whose rows are linearly dependent, whose size is
/// `m - t + 1` for [`t_value`] `t`, i.e. the shape of the elementary intervals (of volume
/// `2^(t - 1 - m)`) that the net fails to balance; `None` for a (0, m, s)-net. The first
/// such shape in the depth-first order of [`t_value`] (same cost).
///
/// ```
/// use qmckit::analysis::tvalue::{DigitalNet2, dependent_shape};
/// assert_eq!(dependent_shape(&DigitalNet2::hammersley(6)?), None);
/// let s = dependent_shape(&DigitalNet2::from_sobol(3, 6)?).unwrap();
/// assert_eq!(s.iter().sum::<u32>(), 6); // t = 1: a shape of size m - t + 1 = 6
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn dependent_shape(net: &DigitalNet2) -> Option<Vec<u32>> {
    dependent_search(net).shape
}

/// State of the depth-first search for the smallest dependent shape.
struct Search {
    /// `rows[j][r]`: row `r` of dimension `j` as an `m`-bit mask.
    rows: Vec<Vec<u32>>,
    /// Size of the smallest dependent shape found, `m + 1` if none.
    best: u32,
    shape: Option<Vec<u32>>,
    current: Vec<u32>,
}

fn dependent_search(net: &DigitalNet2) -> Search {
    let m = net.m;
    let rows = (0..net.dims())
        .map(|j| (0..m).map(|r| net.row(j, r)).collect())
        .collect();
    let mut search = Search {
        rows,
        best: m + 1,
        shape: None,
        current: vec![0; net.dims()],
    };
    dfs(&mut search, 0, Basis([0; 32]), 0);
    search
}

fn dfs(search: &mut Search, j: usize, basis: Basis, size: u32) {
    if j >= search.rows.len() {
        return;
    }
    // d_j = 0.
    dfs(search, j + 1, basis, size);
    // d_j = 1, 2, ...: add the rows of C_j one at a time.
    let mut b = basis;
    let count = search.rows.get(j).map_or(0, Vec::len);
    for r in 0..count {
        let next = size + r as u32 + 1;
        if next >= search.best {
            break; // anything found below is no smaller
        }
        let row = search.rows.get(j).and_then(|rows| rows.get(r)).copied();
        if let Some(slot) = search.current.get_mut(j) {
            *slot = r as u32 + 1;
        }
        if !b.insert(row.unwrap_or(0)) {
            search.best = next;
            search.shape = Some(search.current.clone());
            break;
        }
        dfs(search, j + 1, b, next);
    }
    if let Some(slot) = search.current.get_mut(j) {
        *slot = 0;
    }
}

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
    fn level_balanced(&self, rho: u32) -> bool {
        if rho == 0 {
            return true;
        }
        let expected = self.pow.get((self.m - rho) as usize).copied().unwrap_or(0);
        first_parts(self.dims, rho).into_par_iter().all(|d0| {
            let mut counts = Vec::new();
            let mut ok = true;
            for_each_shape(self.dims, rho, d0, |shape| {
                self.count(shape, rho, &mut counts);
                ok = counts.iter().all(|&c| u64::from(c) == expected);
                ok
            });
            ok
        })
    }

    /// The first `limit` unbalanced cells over the shapes of size `rho`, in shape order then
    /// cell order.
    fn failures(&self, rho: u32, limit: usize) -> Vec<IntervalFailure> {
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
    fn strength(&self) -> u32 {
        let (mut lo, mut hi) = (0u32, self.m); // balanced(lo) holds; answer in [lo, hi]
        while lo < hi {
            let mid = lo + (hi - lo).div_ceil(2);
            if self.level_balanced(mid) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        lo
    }
}

/// The values of `d_1` for shapes of size `rho` in `dims` dimensions (the parallel split).
fn first_parts(dims: usize, rho: u32) -> Vec<u32> {
    if dims <= 1 {
        vec![rho]
    } else {
        (0..=rho).collect()
    }
}

/// Calls `f` on every shape `(d0, d_2, .., d_s)` of size `rho` in lexicographic order, until
/// `f` returns false.
fn for_each_shape(dims: usize, rho: u32, d0: u32, mut f: impl FnMut(&[u32]) -> bool) {
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

/// Validates `samples` as `2^m` points of `dims` 0.32 fractions and reduces them to their
/// top `m` bits.
fn digits_u32(samples: &[u32], dims: usize, m: u32) -> Result<Digits> {
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
fn exact_floor_mul(x: f64, b: f64) -> f64 {
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
/// holds exactly `2^t` points (see the [module docs](self)). Works for any point set,
/// scrambled or not; only the top `m` bits of each coordinate matter.
///
/// Cost: a binary search over the interval size `rho = m - t`, about `log2 m` levels; a
/// level counts `N` points into `2^rho` cells for each of its `C(rho + s - 1, s - 1)` shapes,
/// `O(N s)` each, stopping at the first unbalanced shape (rayon over the first side).
/// For `s = 2, m = 14`: about 60 shapes of 16 384 points, milliseconds. Memory `8 N s` bytes
/// of digits plus `4 * 2^rho` bytes of counts per thread.
///
/// # Errors
/// [`Error::ZeroDimensions`], [`Error::MTooLarge`] for `m > 32`, [`Error::BufferLength`]
/// unless `samples.len() == 2^m dims`.
///
/// ```
/// use qmckit::analysis::tvalue::t_value_u32;
/// use qmckit::{LarcherPillichshammer, Sampler};
/// let lp = LarcherPillichshammer::new(4)?;
/// let mut pts = vec![0u32; 2 * 16];
/// lp.fill(0, &mut pts)?;
/// assert_eq!(t_value_u32(&pts, 2, 4)?, 0); // LP is a (0, m, 2)-net
/// pts.swap(1, 17); // swap two y values: (0, 15/16), (1/2, 0)
/// assert!(t_value_u32(&pts, 2, 4)? > 0);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn t_value_u32(samples: &[u32], dims: usize, m: u32) -> Result<u32> {
    let d = digits_u32(samples, dims, m)?;
    Ok(m - d.strength())
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
/// interval).
///
/// ```
/// use qmckit::analysis::{Points, tvalue::t_value_points};
/// // The 3 x 3 grid of cell centres is a (0, 2, 2)-net in base 3? No: t = 1
/// // (the interval [0, 1/9) x [0, 1) is empty); the 9 points (i/9 + 1/18, phi_3(i) + 1/18)
/// // of Hammersley in base 3 are a (0, 2, 2)-net.
/// let grid: Vec<f64> = (0..9).flat_map(|i| [(i / 3) as f64 / 3.0 + 1.0 / 6.0,
///                                           (i % 3) as f64 / 3.0 + 1.0 / 6.0]).collect();
/// assert_eq!(t_value_points(Points::new(&grid, 2)?, 3, 2)?, 1);
/// let ham: Vec<f64> = (0..9).flat_map(|i| [i as f64 / 9.0 + 1.0 / 18.0,
///                                          ((i % 3) * 3 + i / 3) as f64 / 9.0 + 1.0 / 18.0])
///                           .collect();
/// assert_eq!(t_value_points(Points::new(&ham, 2)?, 3, 2)?, 0);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn t_value_points(points: Points, base: u32, m: u32) -> Result<u32> {
    let d = digits_f64(points, base, m)?;
    Ok(m - d.strength())
}

/// The first `limit` elementary intervals of volume `2^(t - m)` that do not hold exactly
/// `2^t` of the `2^m` points (0.32 fractions, row-major); empty if and only if the set is a
/// (t, m, s)-net. Ordered by shape (lexicographic in `(d_1, .., d_s)`), then by cell.
/// To name why a set has t-value `t`, ask for `t - 1`.
///
/// Cost: every shape of size `m - t`, `O(N s + 2^(m - t))` each (see [`t_value_u32`]).
///
/// # Errors
/// As [`t_value_u32`], and [`Error::MTooLarge`] for `t > m` (reported as `m: t, max: m`).
///
/// ```
/// use qmckit::analysis::tvalue::elementary_interval_failures_u32;
/// // Four points all in [0, 1/2) x [0, 1/2): not a (0, 2, 2)-net, nor a (1, 2, 2)-net.
/// let pts = [0u32, 0, 1 << 29, 1 << 30, 1 << 30, 1 << 29, 3 << 29, 3 << 29];
/// let f = elementary_interval_failures_u32(&pts, 2, 2, 1, 10)?;
/// assert_eq!((f[0].shape.clone(), f[0].cell.clone(), f[0].count, f[0].expected),
///            (vec![0, 1], vec![0, 0], 4, 2));
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn elementary_interval_failures_u32(
    samples: &[u32],
    dims: usize,
    m: u32,
    t: u32,
    limit: usize,
) -> Result<Vec<IntervalFailure>> {
    let d = digits_u32(samples, dims, m)?;
    if t > m {
        return Err(Error::MTooLarge { m: t, max: m });
    }
    Ok(d.failures(m - t, limit))
}

/// [`elementary_interval_failures_u32`] for `b^m` points given as `f64` in base `base`
/// (digits as in [`t_value_points`]).
///
/// # Errors
/// As [`t_value_points`], and [`Error::MTooLarge`] for `t > m`.
pub fn elementary_interval_failures(
    points: Points,
    base: u32,
    m: u32,
    t: u32,
    limit: usize,
) -> Result<Vec<IntervalFailure>> {
    let d = digits_f64(points, base, m)?;
    if t > m {
        return Err(Error::MTooLarge { m: t, max: m });
    }
    Ok(d.failures(m - t, limit))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compositions_are_all_enumerated_once() {
        for dims in 1..=4usize {
            for rho in 0..=6u32 {
                let mut seen = Vec::new();
                for d0 in first_parts(dims, rho) {
                    for_each_shape(dims, rho, d0, |s| {
                        assert_eq!(s.iter().sum::<u32>(), rho);
                        seen.push(s.to_vec());
                        true
                    });
                }
                let n = seen.len();
                seen.sort();
                seen.dedup();
                assert_eq!(seen.len(), n);
                // C(rho + dims - 1, dims - 1)
                let mut c = 1u64;
                for i in 0..(dims as u64 - 1) {
                    c = c * (u64::from(rho) + 1 + i) / (i + 1);
                }
                assert_eq!(n as u64, c, "dims {dims} rho {rho}");
            }
        }
    }

    #[test]
    fn exact_floor_corrects_rounding() {
        // 0.1 * 10 rounds to 1.0, but the stored 0.1 is above 1/10: floor is 1.
        assert_eq!(exact_floor_mul(0.1, 10.0), 1.0);
        // The double just below 1/3 times 3 rounds to 1.0; the real product is below 1.
        let x = 1.0f64 / 3.0; // below 1/3
        assert_eq!(exact_floor_mul(x, 3.0), 0.0);
        assert_eq!(exact_floor_mul(0.5, 8.0), 4.0);
    }

    #[test]
    fn rows_follow_the_conventions() {
        let h = DigitalNet2::hammersley(3).unwrap();
        // x = i / 8: row 0 (digit 1/2) is index bit 2.
        assert_eq!(h.row(0, 0), 0b100);
        // y = identity.
        assert_eq!(h.row(1, 0), 0b001);
        assert_eq!(h.row(1, 2), 0b100);
    }

    #[test]
    fn validation() {
        assert_eq!(
            DigitalNet2::new(33, vec![[0; 32]]),
            Err(Error::MTooLarge { m: 33, max: 32 })
        );
        assert_eq!(DigitalNet2::new(3, vec![]), Err(Error::ZeroDimensions));
        assert!(t_value_u32(&[0; 3], 1, 2).is_err());
        assert!(t_value_u32(&[0; 4], 0, 2).is_err());
        let p = [0.5; 4];
        let pts = Points::new(&p, 1).unwrap();
        assert_eq!(
            t_value_points(pts, 1, 2),
            Err(Error::BaseTooSmall { base: 1 })
        );
        assert!(t_value_points(pts, 3, 2).is_err());
        let one = [0.0, 1.0];
        assert!(t_value_points(Points::new(&one, 1).unwrap(), 2, 1).is_err());
    }
}
