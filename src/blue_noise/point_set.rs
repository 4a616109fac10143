//! A finite point set held in memory, the result of the blue-noise constructions.

use crate::sampler::{Sampler, check};
use crate::{Error, Result};

/// `len()` points of `dims()` coordinates, 0.32 fractions, row-major, in generation order.
///
/// ```
/// use qmckit::Sampler;
/// use qmckit::blue_noise::PointSet;
/// let s = PointSet::new(vec![0, 1 << 31, 1 << 30, 3 << 30], 2)?;
/// assert_eq!((s.len(), s.sample(1, 1)?), (2, 3 << 30));
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PointSet {
    coords: Vec<u32>,
    dims: usize,
}

impl PointSet {
    /// The set of the row-major `coords`, `dims` a point.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`], [`Error::ZeroPoints`], [`Error::RaggedPoints`],
    /// [`Error::TooManyPoints`] past 2^32 points.
    pub fn new(coords: Vec<u32>, dims: usize) -> Result<Self> {
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if coords.is_empty() {
            return Err(Error::ZeroPoints);
        }
        if !coords.len().is_multiple_of(dims) {
            return Err(Error::RaggedPoints {
                len: coords.len(),
                dims,
            });
        }
        let n = (coords.len() / dims) as u64;
        if n > 1 << 32 {
            return Err(Error::TooManyPoints {
                requested: n,
                max: 1 << 32,
            });
        }
        Ok(PointSet { coords, dims })
    }

    /// The coordinates, row-major.
    pub fn coords(&self) -> &[u32] {
        &self.coords
    }

    /// The coordinates as `f64` (exact: `c / 2^32`), row-major.
    pub fn to_f64(&self) -> Vec<f64> {
        self.coords
            .iter()
            .map(|&c| crate::bits::to_f64(c))
            .collect()
    }

    /// The number of points.
    pub fn count(&self) -> usize {
        self.coords.len() / self.dims
    }
}

impl Sampler for PointSet {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        self.count() as u64
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        check(index, self.len(), dim, self.dims)?;
        self.coords
            .get(index as usize * self.dims + dim)
            .copied()
            .ok_or(Error::IndexOutOfRange {
                index: u64::from(index),
                len: self.len(),
            })
    }

    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        let rows = crate::sampler::check_fill(self, start, out.len())?;
        let from = start as usize * self.dims;
        let src = self
            .coords
            .get(from..from + rows * self.dims)
            .ok_or(Error::IndexOutOfRange {
                index: u64::from(start) + rows as u64,
                len: self.len(),
            })?;
        out.copy_from_slice(src);
        Ok(())
    }
}
