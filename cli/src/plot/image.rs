//! Images (masks, renders, error images) with a colour bar.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::backend::{Figure, PlotError, caption_font, clean, drawing, linear_axis, widen};
use super::colour::{diverging, grey, viridis};
use super::spectrum::colour_bar;

/// How values become colours.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ColourMap {
    /// Black (low) to white (high).
    #[default]
    Grey,
    /// Dark blue to yellow (viridis-like).
    Viridis,
    /// Blue (negative) through white (0) to red (positive), symmetric about 0: for signed
    /// errors.
    Diverging,
}

/// A `width x height` image of real values (row-major, row 0 at the top) drawn with a
/// colour map over `[lo, hi]` (default: the data's range, widened to
/// `v +- max(1/2, |v| 2^-20)` for a constant image `v`; for [`ColourMap::Diverging`]
/// `[-m, m]` with `m` the largest magnitude) and a colour bar.
///
/// The colour range must be finite with `hi - lo` finite (so `|m| <= f64::MAX / 2` for the
/// diverging map); a wider range, a `range` with `lo >= hi`, or pixels that do not match
/// `width x height` are refused when drawing (the fields are public, so drawing checks
/// them again). Cost: one pass over the pixels, one rectangle each.
#[derive(Clone, Debug)]
pub struct ImageFigure {
    /// The caption.
    pub title: String,
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// `width * height` values, row-major, row 0 at the top.
    pub pixels: Vec<f64>,
    /// The colour map.
    pub map: ColourMap,
    /// The value range; `None`: from the data.
    pub range: Option<(f64, f64)>,
    /// Draw the colour bar (default true).
    pub bar: bool,
    /// What the colour bar's values are (default "value"): "error", "radiance", "rank".
    pub quantity: String,
}

impl ImageFigure {
    /// An image of `pixels`.
    ///
    /// # Errors
    /// A [`PlotError`] for a zero side, `pixels.len() != width * height` or a value that is
    /// not finite.
    pub fn new(
        title: impl Into<String>,
        width: usize,
        height: usize,
        pixels: Vec<f64>,
    ) -> Result<Self, PlotError> {
        if width == 0 || height == 0 || width.checked_mul(height) != Some(pixels.len()) {
            return Err(PlotError::new(format!(
                "an image of {width}x{height} pixels needs {} values, not {}",
                width.saturating_mul(height),
                pixels.len()
            )));
        }
        if let Some(v) = pixels.iter().find(|v| !v.is_finite()) {
            return Err(PlotError::new(format!("image value {v} is not finite")));
        }
        Ok(ImageFigure {
            title: title.into(),
            width,
            height,
            pixels,
            map: ColourMap::Grey,
            range: None,
            bar: true,
            quantity: "value".into(),
        })
    }

    /// Sets the colour map.
    pub fn map(mut self, map: ColourMap) -> Self {
        self.map = map;
        self
    }

    /// Sets the value range.
    pub fn range(mut self, lo: f64, hi: f64) -> Self {
        self.range = Some((lo, hi));
        self
    }

    /// Names the quantity the colour bar shows.
    pub fn quantity(mut self, quantity: impl Into<String>) -> Self {
        self.quantity = quantity.into();
        self
    }

    /// Hides the colour bar.
    pub fn no_bar(mut self) -> Self {
        self.bar = false;
        self
    }

    /// The colour range, checked (see the type's documentation).
    fn bounds(&self) -> Result<(f64, f64), PlotError> {
        if self.width == 0 || self.width.checked_mul(self.height) != Some(self.pixels.len()) {
            return Err(PlotError::new(format!(
                "an image of {}x{} pixels needs {} values, not {}",
                self.width,
                self.height,
                self.width.saturating_mul(self.height),
                self.pixels.len()
            )));
        }
        if let Some(v) = self.pixels.iter().find(|v| !v.is_finite()) {
            return Err(PlotError::new(format!("image value {v} is not finite")));
        }
        if let Some((lo, hi)) = self.range {
            return linear_axis(lo, hi, "colour");
        }
        let lo = self.pixels.iter().copied().fold(f64::MAX, f64::min);
        let hi = self.pixels.iter().copied().fold(f64::MIN, f64::max);
        let (lo, hi) = match self.map {
            ColourMap::Diverging => {
                let m = lo.abs().max(hi.abs()).max(f64::MIN_POSITIVE);
                (-m, m)
            }
            _ if hi > lo => (lo, hi),
            _ => widen(lo),
        };
        linear_axis(lo, hi, "colour")
    }
}

impl Figure for ImageFigure {
    fn elements(&self) -> usize {
        self.pixels.len() + 64
    }

    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let (lo, hi) = self.bounds()?;
        let span = hi - lo; // positive and finite (checked)
        let map = self.map;
        let colour = move |t: f64| match map {
            ColourMap::Grey => grey(t),
            ColourMap::Viridis => viridis(t),
            ColourMap::Diverging => diverging(2.0 * t - 1.0),
        };
        let (w, _) = area.dim_in_pixel();
        let (left, right) = if self.bar {
            let (l, r) = area.split_horizontally(w.saturating_sub(90).max(1));
            (l, Some(r))
        } else {
            (area.clone(), None)
        };
        let (wf, hf) = (self.width as f64, self.height as f64);
        let mut chart = ChartBuilder::on(&left)
            .caption(clean(&self.title), caption_font())
            .margin(10)
            .build_cartesian_2d(0.0..wf, 0.0..hf)
            .map_err(drawing)?;
        let cells = self.pixels.iter().enumerate().map(|(i, &v)| {
            let x = (i % self.width) as f64;
            let y = hf - 1.0 - (i / self.width) as f64;
            let c = colour((v - lo) / span);
            Rectangle::new([(x, y), (x + 1.0, y + 1.0)], c.filled())
        });
        chart.draw_series(cells).map_err(drawing)?;
        if let Some(r) = right {
            colour_bar(&r, lo, hi, &clean(&self.quantity), colour)?;
        }
        Ok(())
    }
}
