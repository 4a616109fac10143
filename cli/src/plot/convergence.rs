//! Convergence: error against the number of points, log-log, with fitted slopes.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::backend::{Figure, PlotError, caption_font, clean, drawing, label_font, log_axis};
use super::colour::PALETTE;
use qmckit::analysis::variance::fit_slope;

/// One curve: its label and `(n, error)` pairs (both positive).
#[derive(Clone, Debug)]
pub struct Curve {
    /// The legend label (the fitted slope is appended).
    pub label: String,
    /// `(n, error)` pairs.
    pub points: Vec<(f64, f64)>,
}

/// Errors against `N` on log-log axes; each curve's legend gives the least-squares slope
/// `a` of `log error = a log N + c` (−1/2 for Monte Carlo, near −1 for QMC on smooth
/// integrands, −3/2 for Owen-scrambled nets), and an optional reference line `N^-1/2`
/// through the first curve's first point, dashed (cut where it leaves the axes). Pairs with
/// a value that is not positive, not finite, or subnormal (below `f64::MIN_POSITIVE`, about
/// 2.2e-308: numerically zero) are left out (an exact estimate has no logarithm);
/// [`left_out`](Self::left_out) counts them.
///
/// The axes are logarithmic, so the drawn `N` and errors must each span a finite ratio
/// (at most about 308 decades, the errors with a factor 1.5 of margin each side); wider
/// data is refused, never drawn for ever.
#[derive(Clone, Debug)]
pub struct ConvergenceFigure {
    /// The caption.
    pub title: String,
    /// The curves.
    pub curves: Vec<Curve>,
    /// The y-axis label.
    pub y_label: String,
    /// Draw the dashed `N^-1/2` reference line (default true).
    pub reference: bool,
}

impl ConvergenceFigure {
    /// The figure of `curves`.
    pub fn new(title: impl Into<String>, curves: Vec<Curve>) -> Self {
        ConvergenceFigure {
            title: title.into(),
            curves,
            y_label: "error".to_owned(),
            reference: true,
        }
    }

    /// The least-squares slope of each curve (`None` where fewer than two usable pairs).
    pub fn slopes(&self) -> Vec<Option<f64>> {
        self.curves
            .iter()
            .map(|c| {
                let ok: Vec<(f64, f64)> = usable(&c.points).collect();
                fit_slope(&ok).ok()
            })
            .collect()
    }

    /// How many pairs are not drawn (a value not positive, not finite or subnormal).
    pub fn left_out(&self) -> usize {
        self.curves
            .iter()
            .map(|c| c.points.len() - usable(&c.points).count())
            .sum()
    }
}

/// A value a log axis can place: positive, normal and finite.
fn placeable(v: f64) -> bool {
    v >= f64::MIN_POSITIVE && v.is_finite()
}

fn usable(p: &[(f64, f64)]) -> impl Iterator<Item = (f64, f64)> + '_ {
    p.iter()
        .copied()
        .filter(|&(n, e)| placeable(n) && placeable(e))
}

impl Figure for ConvergenceFigure {
    fn elements(&self) -> usize {
        self.curves.iter().map(|c| c.points.len()).sum::<usize>() + 16
    }

    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for c in &self.curves {
            for (n, e) in usable(&c.points) {
                x0 = x0.min(n);
                x1 = x1.max(n);
                y0 = y0.min(e);
                y1 = y1.max(e);
            }
        }
        if x0 >= x1 || y0 > y1 {
            return Err(PlotError::new(
                "a convergence plot needs at least two different N with an error that is positive, \
                 finite and not subnormal",
            ));
        }
        if y0 == y1 {
            y0 /= 2.0;
            y1 *= 2.0;
        }
        let (x0, x1) = log_axis(x0, x1, "N")?;
        let (ylo, yhi) = log_axis(y0 / 1.5, y1 * 1.5, "error")?;
        let mut chart = ChartBuilder::on(area)
            .caption(clean(&self.title), caption_font())
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(60)
            .build_cartesian_2d((x0..x1).log_scale(), (ylo..yhi).log_scale())
            .map_err(drawing)?;
        chart
            .configure_mesh()
            .light_line_style(RGBColor(235, 235, 235))
            .x_desc("N (points)")
            .y_desc(clean(&self.y_label))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .x_label_formatter(&|v| format!("{v:.0}"))
            .label_style(label_font())
            .draw()
            .map_err(drawing)?;
        let slopes = self.slopes();
        for (i, c) in self.curves.iter().enumerate() {
            let col = PALETTE[i % PALETTE.len()];
            let label = match slopes.get(i).copied().flatten() {
                Some(s) => format!("{} (slope {s:.2})", clean(&c.label)),
                None => clean(&c.label),
            };
            chart
                .draw_series(LineSeries::new(usable(&c.points), col.stroke_width(2)))
                .map_err(drawing)?
                .label(label)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], col.stroke_width(2))
                });
            chart
                .draw_series(usable(&c.points).map(|p| Circle::new(p, 3, col.filled())))
                .map_err(drawing)?;
        }
        if let Some((n, e)) = self
            .curves
            .first()
            .and_then(|c| usable(&c.points).next())
            .filter(|_| self.reference)
        {
            // e sqrt(n / x) falls to the bottom of the axes, ylo, at x = n (e / ylo)^2.
            let x_end = x1.min(n * (e / ylo) * (e / ylo));
            let r = vec![(n, e), (x_end, (e * (n / x_end).sqrt()).max(ylo))];
            chart
                .draw_series(DashedLineSeries::new(
                    r,
                    6,
                    4,
                    RGBColor(120, 120, 120).stroke_width(1),
                ))
                .map_err(drawing)?
                .label("N^-1/2")
                .legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], RGBColor(120, 120, 120))
                });
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .label_font(label_font())
            .position(SeriesLabelPosition::LowerLeft)
            .draw()
            .map_err(drawing)?;
        Ok(())
    }
}
