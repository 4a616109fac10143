//! Screen-space error: render a per-pixel integrand with a [`PixelSampler`], and measure how
//! the error is distributed over the image (Heitz & Belcour 2019; Ahmed & Wonka 2020).
//!
//! Each pixel estimates `I = ∫_{[0,1)^2} f(u) du` by the mean of `f` over its `spp` pixel
//! samples (`get_pixel_2d` at dimension 0); the error image is `E(x, y) = estimate - I`.
//! Its power spectrum `P(k) = |DFT(E)(k)|^2 / (W H var(E))` is 1 on average for white noise
//! (independent pixels); a blue-noise sampler pushes the error to high frequencies, so
//! `P` is small near `k = 0`. [`ScreenError::low_band`] is the mean of `P` over
//! `1 <= |k| < min(W, H) / 8` (below a quarter of the Nyquist frequency), `high_band` over
//! `min(W, H) / 4 <= |k| < min(W, H) / 2`.

use crate::error::{Error, Result};
use crate::pixel::PixelSampler;
use crate::work::Stop;
use crate::work::{Budget, Cost, Rate};

/// A test integrand on the unit square, with its exact integral.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PixelIntegrand {
    /// `exp(-((u - 0.5)^2 + (v - 0.5)^2) / (2 s^2))` with `s = 0.2` (smooth).
    GaussianBump,
    /// `1` where `u + 0.37 v < 0.61`, else 0 (a visibility-like edge).
    Step,
    /// `1` where `u + 0.37 v < t(x, y)`, else 0, with a threshold varying smoothly over the
    /// image, `t = 0.675 + 0.25 sin(2 pi x / W) cos(2 pi y / H)` at the pixel centre: the
    /// "ambient occlusion" case, where the edge moves across the image (per-pixel integral
    /// `t - 0.185`, the line meeting both `v = 0` and `v = 1` inside the square).
    Visibility,
}

impl PixelIntegrand {
    /// `f(u, v)` (for [`Visibility`](Self::Visibility), at the image centre, `t = 0.675`).
    pub fn eval(self, u: f64, v: f64) -> f64 {
        self.eval_at(0.5, 0.5, u, v)
    }

    /// The threshold of [`Visibility`](Self::Visibility) at image position `(px, py)` in
    /// `[0, 1)^2`.
    fn threshold(px: f64, py: f64) -> f64 {
        let tau = 2.0 * core::f64::consts::PI;
        0.675 + 0.25 * (tau * px).sin() * (tau * py).cos()
    }

    /// `f(u, v)` in the pixel whose centre is at `(px, py)` in `[0, 1)^2` of the image.
    pub fn eval_at(self, px: f64, py: f64, u: f64, v: f64) -> f64 {
        match self {
            PixelIntegrand::Visibility => {
                if u + 0.37 * v < Self::threshold(px, py) {
                    1.0
                } else {
                    0.0
                }
            }
            PixelIntegrand::GaussianBump => {
                let (a, b) = (u - 0.5, v - 0.5);
                (-(a * a + b * b) / (2.0 * 0.04)).exp()
            }
            PixelIntegrand::Step => {
                if u + 0.37 * v < 0.61 {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }

    /// The exact integral over `[0, 1)^2` (for [`Visibility`](Self::Visibility), at the
    /// image centre).
    pub fn exact(self) -> f64 {
        self.exact_at(0.5, 0.5)
    }

    /// The exact integral in the pixel centred at `(px, py)`.
    pub fn exact_at(self, px: f64, py: f64) -> f64 {
        match self {
            PixelIntegrand::Visibility => Self::threshold(px, py) - 0.185,
            // (∫_0^1 exp(-(t - 1/2)^2 / (2 s^2)) dt)^2 = (s sqrt(2 pi) erf(1 / (2 sqrt(2) s)))^2
            PixelIntegrand::GaussianBump => {
                let s = 0.2f64;
                let one = s * (2.0 * core::f64::consts::PI).sqrt() * erf(0.5 / (2f64.sqrt() * s));
                one * one
            }
            // The area of {u < 0.61 - 0.37 v}: the line meets u = 0.61 at v = 0 and u = 0.24 at
            // v = 1, inside the square, so the area is the mean of the two, 0.425.
            PixelIntegrand::Step => 0.425,
        }
    }
}

/// `erf(x)` for `x >= 0` by its Taylor series (enough terms for `x <= 3`: error below 1e-15).
fn erf(x: f64) -> f64 {
    let mut term = x;
    let mut sum = x;
    let x2 = x * x;
    for n in 1..80 {
        term *= -x2 / n as f64;
        sum += term / (2 * n + 1) as f64;
    }
    sum * 2.0 / core::f64::consts::PI.sqrt()
}

/// An error image and its measurements.
#[derive(Clone, Debug, PartialEq)]
pub struct ScreenError {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// `E(x, y)` row-major (`y * width + x`).
    pub error: Vec<f64>,
    /// `P(kx, ky)` normalized by `W H var(E)`, row-major, `k` in `0..W` x `0..H` (DFT order).
    pub spectrum: Vec<f64>,
    /// Root mean square of `E`.
    pub rmse: f64,
    /// Mean normalized power over `1 <= |k| < min(W, H) / 8`.
    pub low_band: f64,
    /// Mean normalized power over `min(W, H) / 4 <= |k| < min(W, H) / 2`.
    pub high_band: f64,
    /// Mean unnormalized power `|DFT(E)|^2 / (W H)` over the low band (comparable between
    /// samplers whose RMSE differs).
    pub low_band_absolute: f64,
}

/// Steps of the separable DFT a second (complex multiply-adds; conservative).
const DFT_RATE: Rate = Rate::per_second(2e8);

/// Renders `f` with `sampler` over its whole image and measures the error.
/// Cost: `W H spp` evaluations and a separable DFT of `W H (W + H)` steps, estimated first.
///
/// # Errors
/// [`Error::OverBudget`] past `budget`; [`Error::InvalidParameter`] for an image smaller
/// than 8 x 8 (no low band) or a constant error image (no spectrum to normalize);
/// [`Error::OutOfTime`] past the deadline of `budget` (started here if it was not), read
/// once per image row and once per row and column of the DFT.
///
/// ```
/// use qmckit::work::Budget;
/// use qmckit::analysis::screen_error::{PixelIntegrand, screen_error};
/// use qmckit::pixel::{PaddedSobol, Randomization, ZSobol};
/// let z = ZSobol::new(32, 32, 4, Randomization::FastOwen, 0)?;
/// let p = PaddedSobol::new(32, 32, 4, Randomization::FastOwen, 0)?;
/// let ez = screen_error(&z, PixelIntegrand::GaussianBump, &Budget::DEFAULT)?;
/// let ep = screen_error(&p, PixelIntegrand::GaussianBump, &Budget::DEFAULT)?;
/// assert!(ez.low_band < ep.low_band); // ZSobol's error is blue
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn screen_error<S: PixelSampler>(
    sampler: &S,
    f: PixelIntegrand,
    budget: &Budget,
) -> Result<ScreenError> {
    let g = sampler.grid();
    let (w, h) = (g.width as usize, g.height as usize);
    if w < 8 || h < 8 {
        return Err(Error::InvalidParameter {
            what: "screen-space error needs an image of at least 8 x 8 pixels",
        });
    }
    let px = (w as f64) * (h as f64);
    let steps = px * (g.spp as f64) + px * ((w + h) as f64) * 4.0;
    budget.check("screen-space error", Cost::steps(steps, DFT_RATE))?;
    let stop = Stop::new(budget, "screen-space error");
    let mut error: Vec<f64> = crate::size::vec_with_capacity(w.saturating_mul(h))?;
    for y in 0..g.height {
        stop.budget_check()?;
        let py = (y as f64 + 0.5) / h as f64;
        for x in 0..g.width {
            let px = (x as f64 + 0.5) / w as f64;
            let mut sum = 0.0;
            for i in 0..g.spp {
                let [u, v] = sampler.start_pixel_sample(x, y, i)?.get_pixel_2d_f32();
                sum += f.eval_at(px, py, u as f64, v as f64);
            }
            error.push(sum / g.spp as f64 - f.exact_at(px, py));
        }
    }
    ScreenError::measure(error, w, h, &stop)
}

impl ScreenError {
    /// The measurements of an error image `E` (`w x h`, row-major): its spectrum normalized
    /// by `W H var(E)`, the RMSE and the band powers. Cost: a separable DFT, `W H (W + H)`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for an image smaller than 8 x 8 or of the wrong length,
    /// or a constant image (no spectrum to normalize).
    pub fn from_error(error: Vec<f64>, w: usize, h: usize) -> Result<ScreenError> {
        ScreenError::measure(error, w, h, &Stop::never("screen-space error"))
    }

    /// [`from_error`](Self::from_error) under the deadline of `stop`, read once per row
    /// and column of the DFT.
    fn measure(error: Vec<f64>, w: usize, h: usize, stop: &Stop) -> Result<ScreenError> {
        if w < 8 || h < 8 || error.len() != w * h {
            return Err(Error::InvalidParameter {
                what: "an error image needs at least 8 x 8 pixels and w h values",
            });
        }
        let px = (w as f64) * (h as f64);
        let mean = error.iter().sum::<f64>() / px;
        let var = error.iter().map(|e| (e - mean) * (e - mean)).sum::<f64>() / px;
        if var <= 0.0 {
            return Err(Error::InvalidParameter {
                what: "a constant error image has no spectrum to normalize",
            });
        }
        let rmse = (error.iter().map(|e| e * e).sum::<f64>() / px).sqrt();
        let power = dft_power(&error, w, h, stop)?;
        let spectrum: Vec<f64> = power.iter().map(|p| p / (px * var)).collect();
        let side = w.min(h) as f64;
        let band = |lo: f64, hi: f64, norm: bool| {
            let (mut s, mut n) = (0.0, 0usize);
            for ky in 0..h {
                for kx in 0..w {
                    let fx = if kx <= w / 2 {
                        kx as f64
                    } else {
                        kx as f64 - w as f64
                    };
                    let fy = if ky <= h / 2 {
                        ky as f64
                    } else {
                        ky as f64 - h as f64
                    };
                    // Frequencies in cycles per min(W, H) pixels, so the bands are radial.
                    let r =
                        ((fx * side / w as f64).powi(2) + (fy * side / h as f64).powi(2)).sqrt();
                    if r >= lo && r < hi {
                        let k = ky * w + kx;
                        s += if norm { spectrum[k] } else { power[k] / px };
                        n += 1;
                    }
                }
            }
            if n == 0 { 0.0 } else { s / n as f64 }
        };
        Ok(ScreenError {
            width: w,
            height: h,
            low_band: band(1.0, side / 8.0, true),
            high_band: band(side / 4.0, side / 2.0, true),
            low_band_absolute: band(1.0, side / 8.0, false),
            error,
            spectrum,
            rmse,
        })
    }
}

/// `|DFT(e)|^2` of a real `w x h` image, row-major, by a separable DFT (rows, then columns)
/// with exact twiddles `exp(-2 pi i j k / n)` taken modulo `n`.
fn dft_power(e: &[f64], w: usize, h: usize, stop: &Stop) -> Result<Vec<f64>> {
    let twiddles = |n: usize| -> Vec<(f64, f64)> {
        (0..n)
            .map(|j| {
                let a = -2.0 * core::f64::consts::PI * j as f64 / n as f64;
                (a.cos(), a.sin())
            })
            .collect()
    };
    let (tw, th) = (twiddles(w), twiddles(h));
    // Rows.
    let mut rows = vec![(0.0f64, 0.0f64); w * h];
    for y in 0..h {
        stop.budget_check()?;
        for kx in 0..w {
            let (mut re, mut im) = (0.0, 0.0);
            for x in 0..w {
                let (c, s) = tw[(kx * x) % w];
                let v = e[y * w + x];
                re += v * c;
                im += v * s;
            }
            rows[y * w + kx] = (re, im);
        }
    }
    // Columns.
    let mut out = vec![0.0; w * h];
    for kx in 0..w {
        stop.budget_check()?;
        for ky in 0..h {
            let (mut re, mut im) = (0.0, 0.0);
            for y in 0..h {
                let (c, s) = th[(ky * y) % h];
                let (a, b) = rows[y * w + kx];
                re += a * c - b * s;
                im += a * s + b * c;
            }
            out[ky * w + kx] = re * re + im * im;
        }
    }
    Ok(out)
}
