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

mod count;
mod rank;

pub use count::{
    COUNT_RATE, IntervalFailure, count_steps, elementary_interval_failures,
    elementary_interval_failures_u32, elementary_interval_failures_u32_within, t_value_points,
    t_value_points_within, t_value_u32, t_value_u32_within,
};
pub use rank::{
    PROGRESS_STEPS, RANK_TEST_RATE, dependent_shape, dependent_shape_within, rank_test_steps,
    t_value, t_value_within,
};

use crate::{Error, Result};

/// A digital net in base 2 with `2^m` points: one generator matrix per dimension, each given
/// by its first `m` columns as 0.32 fractions (see the [module docs](self) for the
/// conventions).
///
/// ```
/// use qmckit::analysis::tvalue::{DigitalNet2, t_value};
/// // Hammersley in 2D with 2^4 points: (i / 16, phi_2(i)), a (0, 4, 2)-net.
/// let h = DigitalNet2::hammersley(4)?;
/// assert_eq!(h.point(3), vec![3 << 28, 0xC000_0000]); // (3/16, 3/4)
/// assert_eq!(t_value(&h)?, 0);
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
    /// [`Error::TooLarge`] when the `2^m s` values (4 bytes each) would pass
    /// [`crate::size::MAX_ALLOC_BYTES`] or the system refuses the allocation (e.g. `m = 32`
    /// in 2D: 32 GiB).
    ///
    /// ```
    /// use qmckit::analysis::tvalue::DigitalNet2;
    /// assert_eq!(DigitalNet2::hammersley(2)?.points()?.len(), 8);
    /// assert!(DigitalNet2::from_sobol(2, 32)?.points().is_err());
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn points(&self) -> Result<Vec<u32>> {
        let n = 1u64 << self.m;
        let total = crate::size::coordinates(n, self.dims())?;
        let bytes = crate::size::bytes(total, core::mem::size_of::<u32>())?;
        let mut out = Vec::new();
        out.try_reserve_exact(total).map_err(|_| Error::TooLarge {
            what: "bytes",
            requested: bytes as u64,
            max: crate::size::MAX_ALLOC_BYTES,
        })?;
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

#[cfg(test)]
mod tests {
    use super::count::{exact_floor_mul, first_parts, for_each_shape};
    use super::*;
    use crate::analysis::Points;

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
