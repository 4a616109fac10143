//! The mean periodogram over many point sets of one size: the expected spectrum `E P(k)`
//! of a sampler, the quantity whose pictures tell samplers apart and from which
//! [`crate::analysis::variance`] predicts integration variance.
//!
//! `mean P(k) = (1/S) sum_s P_s(k)` over `S` sets of `N` points each, summed in the order
//! the sets are added (so the result does not depend on threads). Its standard error at one
//! `k` is about `mean / sqrt(S)` for white-noise-like sets. Cost: `(2K + 1)^2` additions a
//! set, on top of each set's periodogram.

use super::Spectrum;
use crate::{Error, Result};

/// A running sum of periodograms of equal `K` and `N`; [`SpectrumMean::mean`] is their
/// average.
///
/// ```
/// use qmckit::analysis::{Points, spectrum::{SpectrumMean, spectrum_2d}};
/// let mut mean = SpectrumMean::new();
/// for x in [0.1, 0.4] {
///     mean.add(&spectrum_2d(Points::new(&[x, 0.5, 0.9, 0.2], 2)?, 2)?)?;
/// }
/// let m = mean.mean()?;
/// assert_eq!((mean.sets(), m.points(), m.get(0, 0)), (2, 2, Some(2.0)));
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SpectrumMean {
    sets: usize,
    sum: Option<Spectrum>,
}

impl SpectrumMean {
    /// An empty sum.
    pub fn new() -> Self {
        SpectrumMean::default()
    }

    /// How many periodograms were added.
    pub fn sets(&self) -> usize {
        self.sets
    }

    /// Adds one periodogram.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] when its `K` or `N` differs from the first one added.
    pub fn add(&mut self, s: &Spectrum) -> Result<()> {
        match &mut self.sum {
            None => self.sum = Some(s.clone()),
            Some(sum) => {
                if sum.k_max != s.k_max || sum.points != s.points {
                    return Err(Error::InvalidParameter {
                        what: "averaged spectra must have the same k_max and number of points",
                    });
                }
                for (a, &b) in sum.power.iter_mut().zip(&s.power) {
                    *a += b;
                }
            }
        }
        self.sets += 1;
        Ok(())
    }

    /// The mean periodogram (`P(0) = N`).
    ///
    /// # Errors
    /// [`Error::ZeroPoints`] when nothing was added.
    pub fn mean(&self) -> Result<Spectrum> {
        let sum = self.sum.as_ref().ok_or(Error::ZeroPoints)?;
        let inv = 1.0 / self.sets as f64;
        Ok(Spectrum {
            k_max: sum.k_max,
            points: sum.points,
            power: sum.power.iter().map(|&p| p * inv).collect(),
        })
    }
}
