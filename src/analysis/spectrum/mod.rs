//! Fourier power spectrum of 2D point sets: the periodogram, its radial average and its
//! anisotropy, the plots by which blue-noise and low-discrepancy patterns are told apart.
//!
//! The points are Dirac impulses on the unit torus; at an integer frequency `k = (kx, ky)`
//!
//! ```text
//! P(k) = |sum_j exp(-2 pi i k . x_j)|^2 / N
//! ```
//!
//! (Ulichney, "Dithering with blue noise", Proc. IEEE 1988; Lagae & Dutré, "A comparison of
//! methods for generating Poisson disk distributions", CGF 2008; the `Fourier` tool of UTK).
//! `P(0) = N`, `P(-k) = P(k)`, and for `N` independent uniform points `E P(k) = 1` at every
//! `k != 0`: 1 is the white-noise level. Blue noise keeps `P` near 0 at low `|k|`; a lattice
//! concentrates it on its dual lattice (a regular `n x n` grid: `P = N` where `n` divides
//! both `kx` and `ky`, else 0).
//!
//! The radial average over the annulus `round(|k|) = r` (`k != 0`, `1 <= r <= K`, so the
//! annulus lies inside the computed square) is the radial power spectrum; its anisotropy is
//! the sample variance over the annulus divided by the squared mean (Ulichney 1988): 1 (0 dB)
//! for white noise, whose periodogram values are exponentially distributed, and below 1 for
//! radially uniform spectra.
//!
//! Two ways to compute it, chosen by [`Method`]: the direct sums of [`direct`] (exact up to
//! rounding, `N (K + 1)(2K + 1)` complex multiply-adds) and the type-1 non-uniform FFT of
//! [`nufft`] (within a stated tolerance of `P(0) = N`, `N w^2 + O(n^2 log n)` with
//! `n ~ 4K`); [`Method::Auto`] takes whichever is estimated faster. [`average`] averages
//! periodograms over many sets, [`radial`] states the radial conventions.
//!
//! Measured (two cores): 4096 points at `K = 128` (1.4e8 multiply-adds) by direct sums in
//! 0.13 s, so the budget [`SPECTRUM_WORK_BUDGET`] of 1e10 is about ten seconds there.

pub mod average;
pub mod direct;
pub mod nufft;
pub mod radial;

pub use average::SpectrumMean;
pub use nufft::NUFFT_MIN_TOLERANCE;

use super::Points;
use crate::work::Stop;
use crate::work::{Budget, Cost, Limits, Rate};
use crate::{Error, Result};

/// Complex multiply-adds above which [`spectrum_2d`] refuses: [`SPECTRUM_RATE`] times the
/// default budget of ten seconds.
pub const SPECTRUM_WORK_BUDGET: f64 = 1e10;

/// Complex multiply-adds a second of the direct sums (two threads; measured at 1.1e9 to
/// 1.6e9 for K = 32 to 512), the rate [`spectrum_2d`] turns its budget into work with.
pub const SPECTRUM_RATE: Rate = Rate::per_second(1e9);

/// Largest `K` [`spectrum_2d`] accepts: the `(2K + 1)^2` powers, the half plane of complex
/// sums and the phase tables then take about 300 MB.
pub const SPECTRUM_MAX_K: usize = 2048;

/// The periodogram of a 2D point set on the frequencies `[-K, K]^2`, from [`spectrum_2d`].
#[derive(Clone, Debug, PartialEq)]
pub struct Spectrum {
    k_max: usize,
    points: usize,
    /// `P(kx, ky)` at `(ky + K) (2K + 1) + kx + K`.
    power: Vec<f64>,
}

/// One annulus of the radial spectrum, from [`Spectrum::radial`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RadialBin {
    /// The integer radius `r`: frequencies with `round(|k|) = r`.
    pub radius: usize,
    /// How many frequencies the annulus holds (both of each pair `k`, `-k`).
    pub count: usize,
    /// Mean of `P(k)` over the annulus.
    pub mean: f64,
    /// Sample variance over the annulus divided by the squared mean (0 when the mean is 0);
    /// `10 log10` of it is Ulichney's anisotropy in dB.
    pub anisotropy: f64,
}

impl Spectrum {
    /// The largest frequency `K` along each axis.
    pub fn k_max(&self) -> usize {
        self.k_max
    }

    /// `N`, the number of points (also `P(0, 0)`).
    pub fn points(&self) -> usize {
        self.points
    }

    /// `P(kx, ky)`, or `None` outside `[-K, K]^2`.
    pub fn get(&self, kx: i64, ky: i64) -> Option<f64> {
        let k = self.k_max as i64;
        if kx.unsigned_abs() > k as u64 || ky.unsigned_abs() > k as u64 {
            return None;
        }
        let side = 2 * k + 1;
        self.power.get(((ky + k) * side + kx + k) as usize).copied()
    }

    /// `(kx, ky, P)` for every frequency, `ky` then `kx` ascending from `-K`.
    pub fn iter(&self) -> impl Iterator<Item = (i64, i64, f64)> + '_ {
        let (k, side) = (self.k_max as i64, 2 * self.k_max + 1);
        self.power
            .iter()
            .enumerate()
            .map(move |(at, &p)| ((at % side) as i64 - k, (at / side) as i64 - k, p))
    }
}

/// The periodogram of a 2D point set on the frequencies `[-K, K]^2` (`K = k_max`), exact
/// up to rounding (direct sums, no FFT: the points need not lie on a grid). See the module
/// documentation for the definition and the cost.
///
/// The limits: the time budget (`&Budget::DEFAULT`, ten seconds, for the usual requests):
/// the `N (K + 1)(2K + 1)` complex multiply-adds at [`SPECTRUM_RATE`] must fit in it,
/// checked before any work or allocation.
///
/// # Errors
/// [`Error::Unsupported`] unless `points.dims() == 2`, or for `k_max` above
/// [`SPECTRUM_MAX_K`]; [`Error::TooManyPoints`] when the estimate exceeds the budget (`max`:
/// the most points the budget admits for this `K`; [`SPECTRUM_WORK_BUDGET`] steps for
/// the default); [`Error::OutOfTime`] past the deadline of the budget (started here if it
/// was not), read once per row of each block of 256 points.
///
/// ```
/// use qmckit::{work::Budget, analysis::{Points, spectrum::spectrum_2d}};
/// // The 2 x 2 grid of cell centres: P = N = 4 where both frequencies are even, else 0.
/// let p = Points::new(&[0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75], 2)?;
/// let s = spectrum_2d(p, 2, &Budget::DEFAULT)?;
/// assert!((s.get(2, -2).unwrap() - 4.0).abs() < 1e-12);
/// assert!(s.get(1, 0).unwrap().abs() < 1e-12);
/// assert_eq!(s.get(0, 0), Some(4.0));
/// let p = Points::new(&[0.5; 2000], 2)?; // 1000 points
/// assert!(spectrum_2d(p, 64, &Budget::seconds(10.0)?).is_ok());
/// assert!(spectrum_2d(p, 2048, &Budget::seconds(0.1)?).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn spectrum_2d<'a>(
    points: Points<'_>,
    k_max: usize,
    limits: impl Into<Limits<'a>>,
) -> Result<Spectrum> {
    let limits = limits.into();
    let budget = limits.budget();
    if points.dims() != 2 {
        return Err(Error::Unsupported {
            what: "a spectrum of points that are not 2-dimensional",
        });
    }
    if k_max > SPECTRUM_MAX_K {
        return Err(Error::Unsupported {
            what: "a spectrum with k_max above 2048",
        });
    }
    let n = points.len();
    let side = 2 * k_max + 1;
    let per_point = (k_max as f64 + 1.0) * side as f64;
    let work = budget.steps(SPECTRUM_RATE);
    if n as f64 * per_point > work {
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max: (work / per_point) as u64,
        });
    }
    direct::direct_sum(points, k_max, &Stop::new(budget, "the spectrum"))
}

/// How [`periodogram_2d`] computes the sums.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Method {
    /// Whichever of the two is estimated faster ([`estimated_cost`]).
    #[default]
    Auto,
    /// Direct sums: exact up to rounding.
    Direct,
    /// The non-uniform FFT: within the tolerance of `P(0)`.
    Nufft,
}

/// Default tolerance of the NUFFT path: `|P - P_exact| <= 1e-9 N`.
pub const DEFAULT_TOLERANCE: f64 = 1e-9;

/// Spreading multiply-adds a second of the NUFFT (one thread; measured, conservative).
pub const NUFFT_SPREAD_RATE: Rate = Rate::per_second(2e8);

/// FFT work units (`length * log2(length)` per transform) a second (two threads; measured,
/// conservative).
pub const NUFFT_FFT_RATE: Rate = Rate::per_second(5e8);

/// The estimated running time of one periodogram of `n` points on `[-K, K]^2` by `method`
/// (for [`Method::Auto`]: the faster one), with the NUFFT at `tolerance` (clamped into
/// `[1e-14, 0.5]` for the estimate; NaN counts as `1e-14`). `O(1)` and total: every `n`,
/// `K` (beyond [`SPECTRUM_MAX_K`], where no plan is built, the grid is taken as
/// `2 (2K + 1)` nodes) and tolerance give a number of seconds, `+inf` at worst.
///
/// ```
/// use qmckit::analysis::spectrum::{Method, estimated_cost};
/// let direct = estimated_cost(4096, 256, Method::Direct, 1e-9).seconds();
/// let nufft = estimated_cost(4096, 256, Method::Nufft, 1e-9).seconds();
/// assert!(nufft * 10.0 < direct);
/// assert_eq!(estimated_cost(4096, 256, Method::Auto, 1e-9).seconds(), nufft);
/// ```
pub fn estimated_cost(n: usize, k_max: usize, method: Method, tolerance: f64) -> Cost {
    let side = 2.0 * k_max as f64 + 1.0;
    let direct = Cost::steps(n as f64 * (k_max as f64 + 1.0) * side, SPECTRUM_RATE);
    // NaN counts as the tightest tolerance (the widest kernel).
    let tolerance = if tolerance.is_nan() {
        NUFFT_MIN_TOLERANCE
    } else {
        tolerance.clamp(NUFFT_MIN_TOLERANCE, 0.5)
    };
    let (w, g) = if k_max <= SPECTRUM_MAX_K {
        let plan = nufft::Plan::new(k_max, tolerance);
        (plan.width as f64, plan.grid as f64)
    } else {
        // No plan is built past the largest K (refused anyway): the widest kernel and
        // a grid of 2 (2K + 1) nodes, in O(1).
        let plan = nufft::Plan::new(SPECTRUM_MAX_K, tolerance);
        (plan.width as f64, 2.0 * side)
    };
    let spread = Cost::steps(n as f64 * w * (w + 2.0), NUFFT_SPREAD_RATE);
    let ffts = Cost::steps(
        (g / 2.0 + k_max as f64 + 1.0) * g * g.log2() + g * g,
        NUFFT_FFT_RATE,
    );
    let fast = spread.plus(ffts);
    match method {
        Method::Direct => direct,
        Method::Nufft => fast,
        Method::Auto => {
            if fast.seconds() < direct.seconds()
                && 8.0 * g * g + 16.0 * g * (k_max as f64 + 1.0)
                    <= crate::size::MAX_ALLOC_BYTES as f64
            {
                fast
            } else {
                direct
            }
        }
    }
}

/// The method [`Method::Auto`] resolves to for `n` points on `[-K, K]^2`.
pub fn choose_method(n: usize, k_max: usize, tolerance: f64) -> Method {
    let auto = estimated_cost(n, k_max, Method::Auto, tolerance);
    if auto == estimated_cost(n, k_max, Method::Direct, tolerance) {
        Method::Direct
    } else {
        Method::Nufft
    }
}

/// The periodogram of a 2D point set on `[-K, K]^2` by `method`, within `budget`:
/// exact up to rounding by direct sums, within `tolerance * N` of it by the NUFFT
/// (`tolerance` in `[1e-14, 0.1]`; ignored by direct sums).
///
/// # Errors
/// [`Error::Unsupported`] unless `points.dims() == 2`, or for `k_max` above
/// [`SPECTRUM_MAX_K`]; [`Error::InvalidParameter`] for a tolerance outside
/// `[1e-14, 0.1]` or NaN; [`Error::OverBudget`] when the estimate of [`estimated_cost`]
/// exceeds `budget`; [`Error::TooLarge`] when the NUFFT grid does not fit in memory;
/// [`Error::OutOfTime`] past the deadline of `budget` (started here if it was not).
///
/// ```
/// use qmckit::{work::Budget, analysis::{Points, spectrum::{Method, periodogram_2d}}};
/// let p = Points::new(&[0.1, 0.2, 0.5, 0.7, 0.9, 0.35], 2)?;
/// let s = periodogram_2d(p, 4, Method::Nufft, 1e-12, &Budget::DEFAULT)?;
/// // Checked against the direct sum: P(1, 1) = 2.8074200179768365.
/// assert!((s.get(1, 1).unwrap() - 2.8074200179768365).abs() < 3e-12);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn periodogram_2d(
    points: Points<'_>,
    k_max: usize,
    method: Method,
    tolerance: f64,
    budget: &Budget,
) -> Result<Spectrum> {
    if points.dims() != 2 {
        return Err(Error::Unsupported {
            what: "a spectrum of points that are not 2-dimensional",
        });
    }
    if k_max > SPECTRUM_MAX_K {
        return Err(Error::Unsupported {
            what: "a spectrum with k_max above 2048",
        });
    }
    if !(NUFFT_MIN_TOLERANCE..=0.1).contains(&tolerance) {
        return Err(Error::InvalidParameter {
            what: "the spectrum tolerance must lie in [1e-14, 0.1]",
        });
    }
    let method = match method {
        Method::Auto => choose_method(points.len(), k_max, tolerance),
        m => m,
    };
    budget.check(
        "the spectrum",
        estimated_cost(points.len(), k_max, method, tolerance),
    )?;
    let stop = Stop::new(budget, "the spectrum");
    match method {
        Method::Nufft => nufft::nufft(points, k_max, tolerance, &stop),
        _ => direct::direct_sum(points, k_max, &stop),
    }
}
