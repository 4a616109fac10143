//! Base-2 digital nets given by their generator matrices ([`DigitalNet2`]), as the rank test
//! ([`super::rank`]) reads them.

use crate::{Error, Result};

/// A digital net in base 2 with `2^m` points: one generator matrix per dimension, each given
/// by its first `m` columns as 0.32 fractions.
///
/// Column `k` of a dimension is the image of index digit `i_k` (weight `2^k`, `i_0` the least
/// significant), as [`crate::digital::sobol::SobolDimension::directions`] holds them; row `r`
/// of the matrix (output digit `r`, weight `2^-(r+1)`) is bit `31 - r` of each column. Point
/// `i`'s coordinate is the XOR of the columns `k` with `i_k = 1`, exactly what
/// [`crate::bits::gf2_mul`] computes. [`rank::t_value`](super::rank::t_value) gives its exact
/// t-value.
///
/// ```
/// use qmckit::digital::{DigitalNet2, rank::t_value};
/// // Hammersley in 2D with 2^4 points: (i / 16, phi_2(i)), a (0, 4, 2)-net.
/// let h = DigitalNet2::hammersley(4)?;
/// assert_eq!(h.point(3), vec![3 << 28, 0xC000_0000]); // (3/16, 3/4)
/// assert_eq!(t_value(&h, &qmckit::work::Budget::DEFAULT)?, 0);
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
            .map(|&d| crate::digital::sobol::directions(d).copied())
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
    pub(super) fn row(&self, j: usize, r: u32) -> u32 {
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
    /// use qmckit::digital::DigitalNet2;
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
    use super::*;

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
    }
}
