//! The mean periodogram over many point sets: the expected spectrum `E P(k)` of a sampler,
//! the quantity whose pictures tell samplers apart and from which
//! [`crate::analysis::variance`] predicts integration variance.
//!
//! `mean P(k) = (1/S) sum_s P_s(k)` over `S` sets, each periodogram normalized by its own
//! size `N_s` (so sets of a sampler whose count varies, as Poisson disk by count, average
//! too; the mean's [`Spectrum::points`] is the rounded mean size), summed in the order the
//! sets are added (so the result does not depend on threads). Its standard error at one
//! `k` is about `mean / sqrt(S)` for white-noise-like sets. Cost: `(2K + 1)^2` additions a
//! set, on top of each set's periodogram.

use super::Spectrum;
use crate::{Error, Result};

/// A running sum of periodograms of equal `K`; [`SpectrumMean::mean`] is their average.
///
/// ```
/// use qmckit::analysis::{Points, spectrum::{SpectrumMean, spectrum_2d}};
/// let mut mean = SpectrumMean::new();
/// for x in [0.1, 0.4] {
///     mean.add(&spectrum_2d(Points::new(&[x, 0.5, 0.9, 0.2], 2)?, 2, &qmckit::work::Budget::DEFAULT)?)?;
/// }
/// let m = mean.mean()?;
/// assert_eq!((mean.sets(), m.points(), m.get(0, 0)), (2, 2, Some(2.0)));
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SpectrumMean {
    sets: usize,
    points: usize,
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
    /// [`Error::InvalidParameter`] when its `K` differs from the first one added.
    pub fn add(&mut self, s: &Spectrum) -> Result<()> {
        match &mut self.sum {
            None => self.sum = Some(s.clone()),
            Some(sum) => {
                if sum.k_max != s.k_max {
                    return Err(Error::InvalidParameter {
                        what: "averaged spectra must have the same k_max",
                    });
                }
                for (a, &b) in sum.power.iter_mut().zip(&s.power) {
                    *a += b;
                }
            }
        }
        self.sets += 1;
        self.points = self.points.saturating_add(s.points);
        Ok(())
    }

    /// The mean periodogram (`P(0)` the mean size; `points()` that size, rounded).
    ///
    /// # Errors
    /// [`Error::ZeroPoints`] when nothing was added.
    pub fn mean(&self) -> Result<Spectrum> {
        let sum = self.sum.as_ref().ok_or(Error::ZeroPoints)?;
        let inv = 1.0 / self.sets as f64;
        Ok(Spectrum {
            k_max: sum.k_max,
            points: (self.points as f64 * inv).round() as usize,
            power: sum.power.iter().map(|&p| p * inv).collect(),
        })
    }
}
