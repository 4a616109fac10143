//! Measuring point sets (feature `analysis`): discrepancies, net quality, distances.
//!
//! Every measure takes a [`Points`] view: `n` points of `d` coordinates, row-major in one
//! `f64` slice, each coordinate in the closed unit interval `[0, 1]` (validated once by
//! [`Points::new`]). Integer samples convert exactly with [`Points::from_u32`].
//!
//! | module | measures |
//! |---|---|
//! | [`l2`] | L2-star (Warnock), centered, wrap-around, mixture, symmetric, unanchored, generalized L2 discrepancies, diaphony |
//! | [`star`] | star discrepancy: exact (1D closed form, 2D sweep, d-D by the Dobkin–Eppstein–Mitchell decomposition in [`star::dem`]), guaranteed bounds ([`star::thiemard`], threshold accepting), extreme discrepancy in 2D |
//! | [`tvalue`] | t-values of point sets and of blocks of base-`b` digital sequences, by counting points in elementary intervals (the rank test on generator matrices is [`crate::digital::rank`]) |
//! | [`distance`] | minimum distance, optionally on the torus |
//! | [`spacing`] | minimum distance through a grid, within a budget, and normalized by the packing bound (the relative radius) |
//! | [`integrate`] | integration error on test integrands with closed-form integrals (Genz's Gaussian peak and oscillatory, ball and half-space indicators), and integration with an error estimate (replicated randomized QMC, Student-t intervals) on a suite of test problems |
//! | [`spectrum`] | Fourier power spectrum of 2D point sets (periodogram by direct sums or a type-1 NUFFT), mean over sets, radial average and anisotropy |
//! | [`variance`] | integration variance predicted from a mean spectrum (torus-shifted samplers, disk and Gaussian integrands) and measured beside it |
//! | [`pcf`] | pair correlation function of 2D point sets (UTK's definition, optionally toroidal) and the structure factor from it |
//! | [`pointfile`] | reading point sets from text (the `qmckit discrepancy` input format) |
//! | [`transport`] | the semi-discrete optimal-transport distance `W_2` between 2D points and the uniform square (exact Laguerre cells, damped Newton) |
//! | [`screen_error`] | screen-space error of a pixel sampler: the error image of a per-pixel integrand and its low-frequency power |

pub mod distance;
pub mod integrate;
pub mod l2;
pub mod pcf;
pub mod pointfile;
pub mod screen_error;
pub mod spacing;
pub mod spectrum;
pub mod star;
pub mod transport;
pub mod tvalue;
pub mod variance;

use crate::{Error, Result};

/// A validated, borrowed set of `n` points in `[0, 1]^d`, row-major.
#[derive(Clone, Copy, Debug)]
pub struct Points<'a> {
    data: &'a [f64],
    dims: usize,
}

impl<'a> Points<'a> {
    /// Views `data` as points of `dims` coordinates each.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`] for `dims == 0`, [`Error::ZeroPoints`] for an empty slice,
    /// [`Error::RaggedPoints`] when `data.len()` is not a multiple of `dims`, and
    /// [`Error::CoordinateOutOfRange`] (naming the first offender) for a coordinate outside
    /// `[0, 1]` or NaN. Cost: one pass over `data`.
    ///
    /// ```
    /// use qmckit::analysis::Points;
    /// let p = Points::new(&[0.25, 0.5, 0.75, 1.0], 2)?;
    /// assert_eq!((p.len(), p.dims()), (2, 2));
    /// assert!(Points::new(&[0.5, f64::NAN], 2).is_err());
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn new(data: &'a [f64], dims: usize) -> Result<Self> {
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if data.is_empty() {
            return Err(Error::ZeroPoints);
        }
        if !data.len().is_multiple_of(dims) {
            return Err(Error::RaggedPoints {
                len: data.len(),
                dims,
            });
        }
        if let Some(k) = data.iter().position(|x| !(0.0..=1.0).contains(x)) {
            return Err(Error::CoordinateOutOfRange {
                point: k / dims,
                dim: k % dims,
            });
        }
        Ok(Points { data, dims })
    }

    /// Converts 0.32 fixed-point samples (row-major, `dims` a point) to exact `f64`s, for
    /// use with [`Points::new`].
    pub fn from_u32(samples: &[u32]) -> Vec<f64> {
        samples.iter().map(|&x| crate::bits::to_f64(x)).collect()
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.data.len() / self.dims
    }

    /// Always `false`: a validated set has at least one point.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Coordinates per point.
    pub fn dims(&self) -> usize {
        self.dims
    }

    /// Point `i` (panics past [`Points::len`], as slice indexing does).
    pub fn point(&self, i: usize) -> &'a [f64] {
        &self.data[i * self.dims..(i + 1) * self.dims]
    }

    /// All points, in order.
    pub fn iter(&self) -> core::slice::ChunksExact<'a, f64> {
        self.data.chunks_exact(self.dims)
    }

    /// The flat row-major coordinates.
    pub fn as_slice(&self) -> &'a [f64] {
        self.data
    }
}
