//! Spectra: the 2D periodogram as a log image with the DC term marked, and radial curves.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::backend::{
    Figure, MAX_ELEMENTS, PlotError, caption_font, clean, drawing, label_font, linear_axis,
};
use super::colour::{PALETTE, viridis};
use qmckit::analysis::spectrum::Spectrum;

/// A 2D power spectrum `P(kx, ky)`, `kx, ky` in `[-K, K]`, as an image of
/// `log10 P` between `log10 floor` and `log10 max P` (values below `floor` at its colour),
/// with `(0, 0)` (where `P = N`) circled, and a colour bar in decibels `10 log10 P`.
#[derive(Clone, Debug)]
pub struct SpectrumFigure {
    /// The caption.
    pub title: String,
    /// `K`.
    pub k_max: usize,
    /// `P` at `(kx, ky)`, row-major from `ky = -K` (bottom) and `kx = -K` (left):
    /// `values[(ky + K) (2K + 1) + (kx + K)]`.
    pub values: Vec<f64>,
    /// The smallest value shown (default `1e-2`).
    pub floor: f64,
    /// Clip the top of the colour range at this value (e.g. a few times the white level,
    /// one) so the DC peak `P(0) = N` does not squeeze the rest; `None`: the largest
    /// value other than DC.
    pub ceiling: Option<f64>,
}

impl SpectrumFigure {
    /// From `values` laid out as documented on [`values`](Self::values).
    ///
    /// # Errors
    /// A [`PlotError`] unless `values.len() = (2K + 1)^2` (computed without overflow, so
    /// any `K` is answered).
    pub fn new(
        title: impl Into<String>,
        k_max: usize,
        values: Vec<f64>,
    ) -> Result<Self, PlotError> {
        side(k_max, values.len())?;
        Ok(SpectrumFigure {
            title: title.into(),
            k_max,
            values,
            floor: 1e-2,
            ceiling: None,
        })
    }

    /// From a computed [`Spectrum`] (which already holds its `(2K + 1)^2` values).
    pub fn from_spectrum(title: impl Into<String>, s: &Spectrum) -> Self {
        let k = i64::try_from(s.k_max()).unwrap_or(i64::MAX / 4);
        let mut values = Vec::new();
        for ky in -k..=k {
            for kx in -k..=k {
                values.push(s.get(kx, ky).unwrap_or(0.0));
            }
        }
        SpectrumFigure {
            title: title.into(),
            k_max: k as usize,
            values,
            floor: 1e-2,
            ceiling: None,
        }
    }

    /// Sets the top of the colour range.
    pub fn ceiling(mut self, c: f64) -> Self {
        self.ceiling = Some(c);
        self
    }
}

/// `2K + 1` for a spectrum of `len` values, checked: `(2K + 1)^2 = len`, at most
/// [`MAX_ELEMENTS`].
fn side(k_max: usize, len: usize) -> Result<usize, PlotError> {
    let side = k_max
        .checked_mul(2)
        .and_then(|t| t.checked_add(1))
        .filter(|&s| s.checked_mul(s) == Some(len) && len <= MAX_ELEMENTS);
    side.ok_or_else(|| {
        PlotError::new(format!(
            "a spectrum with K = {k_max} has (2K + 1)^2 values (at most {MAX_ELEMENTS}), not {len}"
        ))
    })
}

impl Figure for SpectrumFigure {
    fn elements(&self) -> usize {
        self.values.len() + 64
    }

    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let side = side(self.k_max, self.values.len())?;
        let k = self.k_max as i64; // at most 2^10 (checked by `side`)
        let centre = self.k_max * side + self.k_max;
        let top = match self.ceiling {
            Some(c) => c,
            None => self
                .values
                .iter()
                .enumerate()
                .filter(|&(i, _)| i != centre)
                .map(|(_, &v)| v)
                .fold(self.floor * 10.0, f64::max),
        };
        if !(top.is_finite() && self.floor > 0.0 && self.floor.is_finite()) {
            return Err(PlotError::new(
                "a spectrum's values must be finite and non-negative",
            ));
        }
        let (lo, hi) = linear_axis(
            self.floor.log10(),
            top.log10().max(self.floor.log10() + 1.0),
            "log10 power",
        )?;
        let scale = |v: f64| ((v.max(self.floor).log10() - lo) / (hi - lo)).clamp(0.0, 1.0);
        let (w, _) = area.dim_in_pixel();
        let (left, right) = area.split_horizontally(w.saturating_sub(90).max(1));
        let kf = k as f64 + 0.5;
        let mut chart = ChartBuilder::on(&left)
            .caption(clean(&self.title), caption_font())
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(40)
            .build_cartesian_2d(-kf..kf, -kf..kf)
            .map_err(drawing)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("kx")
            .y_desc("ky")
            .x_label_formatter(&|v| format!("{v:.0}"))
            .y_label_formatter(&|v| format!("{v:.0}"))
            .label_style(label_font())
            .draw()
            .map_err(drawing)?;
        let cells = self.values.iter().enumerate().map(|(i, &v)| {
            let kx = (i % side) as f64 - k as f64;
            let ky = (i / side) as f64 - k as f64;
            Rectangle::new(
                [(kx - 0.5, ky - 0.5), (kx + 0.5, ky + 0.5)],
                viridis(scale(v)).filled(),
            )
        });
        chart.draw_series(cells).map_err(drawing)?;
        let mark = (k as f64 / 12.0).max(1.2);
        chart
            .draw_series(std::iter::once(Circle::new(
                (0.0, 0.0),
                6,
                RED.stroke_width(2),
            )))
            .map_err(drawing)?;
        chart
            .draw_series(std::iter::once(Text::new(
                "DC",
                (mark, mark),
                ("sans-serif", 13).into_font().color(&RED),
            )))
            .map_err(drawing)?;
        colour_bar(&right, lo * 10.0, hi * 10.0, "dB", viridis)
    }
}

/// A vertical colour bar from `lo` to `hi` (labels in the given unit).
pub(crate) fn colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    lo: f64,
    hi: f64,
    unit: &str,
    colour: impl Fn(f64) -> RGBColor,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let (lo, hi) = linear_axis(lo, hi, unit)?;
    let mut bar = ChartBuilder::on(area)
        .margin_top(40)
        .margin_bottom(40)
        .margin_right(8)
        .y_label_area_size(50)
        .caption(unit, label_font())
        .build_cartesian_2d(0.0..1.0, lo..hi)
        .map_err(drawing)?;
    bar.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_labels(6)
        .label_style(label_font())
        .draw()
        .map_err(drawing)?;
    let steps = 64;
    let strips = (0..steps).map(|s| {
        let a = lo + (hi - lo) * s as f64 / steps as f64;
        let b = lo + (hi - lo) * (s + 1) as f64 / steps as f64;
        Rectangle::new(
            [(0.0, a), (1.0, b)],
            colour((s as f64 + 0.5) / steps as f64).filled(),
        )
    });
    bar.draw_series(strips).map_err(drawing)?;
    Ok(())
}

/// Radial averages of spectra: `(frequency, mean power)` curves, power on a linear axis
/// from 0 (white noise sits at 1, drawn dashed), frequency in cycles per unit length or
/// divided by `sqrt(N)` (then the blue-noise peak of any `N` sits near 1).
///
/// The axes run from `min(0, smallest value)` to the largest frequency and to
/// `1.05 max(1.5, largest power)`; values must be finite and both spans finite (refused
/// otherwise).
#[derive(Clone, Debug)]
pub struct RadialFigure {
    /// The caption.
    pub title: String,
    /// The x-axis label.
    pub x_label: String,
    /// The y-axis label ("mean power" for a spectrum, "g(r)" for a pair correlation).
    pub y_label: String,
    /// One `(label, points)` curve per spectrum.
    pub curves: Vec<(String, Vec<(f64, f64)>)>,
}

impl Figure for RadialFigure {
    fn elements(&self) -> usize {
        self.curves.iter().map(|c| c.1.len()).sum::<usize>() + 16
    }

    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let all = self.curves.iter().flat_map(|c| c.1.iter());
        let (mut x0, mut x1, mut y0, mut y1) = (0.0f64, 0.0f64, 0.0f64, 1.5f64);
        for &(x, y) in all {
            if !(x.is_finite() && y.is_finite()) {
                return Err(PlotError::new("radial spectrum values must be finite"));
            }
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if x1 <= 0.0 {
            return Err(PlotError::new(
                "a radial spectrum needs a positive frequency",
            ));
        }
        let (x0, x1) = linear_axis(x0, x1, "frequency")?;
        let (y0, y1) = linear_axis(y0, y1 * 1.05, "power")?;
        let mut chart = ChartBuilder::on(area)
            .caption(clean(&self.title), caption_font())
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(44)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(drawing)?;
        chart
            .configure_mesh()
            .light_line_style(RGBColor(235, 235, 235))
            .x_desc(clean(&self.x_label))
            .y_desc(clean(&self.y_label))
            .label_style(label_font())
            .draw()
            .map_err(drawing)?;
        chart
            .draw_series(DashedLineSeries::new(
                vec![(x0, 1.0), (x1, 1.0)],
                6,
                4,
                RGBColor(120, 120, 120).stroke_width(1),
            ))
            .map_err(drawing)?;
        for (i, (label, pts)) in self.curves.iter().enumerate() {
            let c = PALETTE[i % PALETTE.len()];
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), c.stroke_width(2)))
                .map_err(drawing)?
                .label(clean(label))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], c.stroke_width(2))
                });
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .label_font(label_font())
            .position(SeriesLabelPosition::LowerRight)
            .draw()
            .map_err(drawing)?;
        Ok(())
    }
}
