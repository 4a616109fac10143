//! Point sets: the unit square with an elementary-interval overlay, or a warped domain.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::backend::{Figure, PlotError, caption_font, clean, drawing, label_font};
use super::colour::PALETTE;
use qmckit::warp;

/// Where the points of `[0, 1)^2` are drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Domain {
    /// The unit square, as given.
    #[default]
    Square,
    /// The unit disk, by the concentric (Shirley–Chiu) map, area-preserving.
    Disk,
    /// The cosine-weighted hemisphere (Malley: concentric disk lifted), seen from above:
    /// the plotted `(x, y)` are the direction's first two coordinates.
    Hemisphere,
    /// The equilateral triangle with corners `(0, 0)`, `(1, 0)`, `(1/2, sqrt(3)/2)`, by the
    /// area-preserving barycentric map.
    Triangle,
}

impl Domain {
    /// The image of `u` in `[0, 1)^2` (plot coordinates).
    pub fn map(self, u: [f64; 2]) -> [f64; 2] {
        let f = [u[0] as f32, u[1] as f32];
        match self {
            Domain::Square => u,
            Domain::Disk => {
                let p = warp::disk::sample_uniform_disk_concentric(f);
                [p[0] as f64, p[1] as f64]
            }
            Domain::Hemisphere => {
                let w = warp::sphere::sample_cosine_hemisphere(f);
                [w[0] as f64, w[1] as f64]
            }
            Domain::Triangle => {
                let b = warp::triangle::sample_uniform_triangle(f);
                // b weights the corners (0,0), (1,0), (1/2, sqrt 3/2).
                let h = 3f64.sqrt() / 2.0;
                [b[1] as f64 + 0.5 * b[2] as f64, h * b[2] as f64]
            }
        }
    }
}

/// A 2D point set.
///
/// Draws `points` (coordinates in `[0, 1]`) mapped through [`Domain`]; with
/// [`intervals`](Self::intervals)`(a, b)` (square domain only) the grid of `a x b`
/// elementary intervals `[i/a, (i+1)/a) x [j/b, (j+1)/b)`, and the count of boxes holding
/// exactly `N / (a b)` points in the caption; with [`groups`](Self::groups)`(g)` the points
/// `k g .. (k + 1) g` in the k-th colour (e.g. the power-of-two runs of a (0,2)-sequence).
///
/// A point whose image lies outside the domain's box (or is not finite) is not drawn; the
/// caption says how many ([`outside`](Self::outside)). Drawing refuses a zero interval
/// count, a group size of 0, and a radius outside `1..=`[`MAX_RADIUS`] (the fields are
/// public, so they are checked when drawing, not only by the builders).
#[derive(Clone, Debug)]
pub struct PointsFigure {
    /// The caption.
    pub title: String,
    /// The points.
    pub points: Vec<[f64; 2]>,
    /// The elementary-interval grid `(columns, rows)`.
    pub intervals: Option<(u32, u32)>,
    /// The domain.
    pub domain: Domain,
    /// Colour runs of this many consecutive points.
    pub groups: Option<usize>,
    /// Dot radius in pixels (default 3).
    pub radius: u32,
}

/// The largest dot radius, in pixels.
pub const MAX_RADIUS: u32 = 1024;

impl PointsFigure {
    /// A plot of `points` in the unit square.
    pub fn new(title: impl Into<String>, points: Vec<[f64; 2]>) -> Self {
        PointsFigure {
            title: title.into(),
            points,
            intervals: None,
            domain: Domain::Square,
            groups: None,
            radius: 3,
        }
    }

    /// Overlays the `columns x rows` elementary-interval grid.
    pub fn intervals(mut self, columns: u32, rows: u32) -> Self {
        self.intervals = Some((columns, rows));
        self
    }

    /// Draws the points in `domain`.
    pub fn domain(mut self, domain: Domain) -> Self {
        self.domain = domain;
        self
    }

    /// Colours runs of `g` consecutive points (`g >= 1`; 0 is refused when drawing).
    pub fn groups(mut self, g: usize) -> Self {
        self.groups = Some(g);
        self
    }

    /// The dot radius in pixels (`1..=`[`MAX_RADIUS`]; others are refused when drawing).
    pub fn radius(mut self, r: u32) -> Self {
        self.radius = r;
        self
    }

    /// The plotted box `(x0, x1, y0, y1)` of the domain.
    fn plot_box(&self) -> (f64, f64, f64, f64) {
        match self.domain {
            Domain::Square => (0.0, 1.0, 0.0, 1.0),
            Domain::Disk | Domain::Hemisphere => (-1.0, 1.0, -1.0, 1.0),
            Domain::Triangle => (0.0, 1.0, 0.0, 3f64.sqrt() / 2.0),
        }
    }

    /// The image of point `p` in plot coordinates, if it lies in the plotted box (with a
    /// margin of `1e-6` for the rounding of the `f32` warps).
    fn placed(&self, p: [f64; 2]) -> Option<(f64, f64)> {
        const MARGIN: f64 = 1e-6;
        let (x0, x1, y0, y1) = self.plot_box();
        let q = self.domain.map(p);
        let inside = (x0 - MARGIN..=x1 + MARGIN).contains(&q[0])
            && (y0 - MARGIN..=y1 + MARGIN).contains(&q[1]);
        inside.then_some((q[0], q[1]))
    }

    /// How many points are not drawn because their image lies outside the plotted box or
    /// is not finite. `O(N)`.
    pub fn outside(&self) -> usize {
        self.points
            .iter()
            .filter(|&&p| self.placed(p).is_none())
            .count()
    }

    /// How many of the `a x b` boxes hold exactly `N / (a b)` points (all of them for a
    /// net whose every such box is an elementary interval of the right volume).
    pub fn balanced_boxes(&self) -> Option<(u64, u64)> {
        let (a, b) = self.intervals?;
        let cells = a as u64 * b as u64;
        if cells == 0 || cells > 1 << 22 {
            return None;
        }
        let mut count: Vec<u64> = qmckit::size::vec_zeroed(cells as usize).ok()?;
        for p in &self.points {
            // Float-to-integer casts saturate (NaN reads 0), so the box is always valid.
            let i = ((p[0] * a as f64) as u64).min(a as u64 - 1);
            let j = ((p[1] * b as f64) as u64).min(b as u64 - 1);
            if let Some(c) = count.get_mut((j * a as u64 + i) as usize) {
                *c += 1;
            }
        }
        let n = self.points.len() as u64;
        let good = if n.is_multiple_of(cells) {
            count.iter().filter(|&&c| c == n / cells).count() as u64
        } else {
            0
        };
        Some((good, cells))
    }
}

impl Figure for PointsFigure {
    fn elements(&self) -> usize {
        let grid = self
            .intervals
            .map_or(0, |(a, b)| a as usize + b as usize + 2);
        self.points.len() + grid
    }

    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        if self.groups == Some(0) {
            return Err(PlotError::new("a group of points needs at least 1 point"));
        }
        if !(1..=MAX_RADIUS).contains(&self.radius) {
            return Err(PlotError::new(format!(
                "a dot radius must be 1 to {MAX_RADIUS} pixels, not {}",
                self.radius
            )));
        }
        if let Some((a, b)) = self.intervals {
            if a == 0 || b == 0 {
                return Err(PlotError::new("--intervals needs two positive counts, AxB"));
            }
            if self.domain != Domain::Square {
                return Err(PlotError::new(
                    "elementary intervals are drawn in the unit square only (no warp)",
                ));
            }
        }
        let (x0, x1, y0, y1) = self.plot_box();
        let mut caption = clean(&self.title);
        if let Some((good, cells)) = self.balanced_boxes() {
            caption = format!("{caption} ({good}/{cells} boxes balanced)");
        }
        let outside = self.outside();
        if outside > 0 {
            caption = format!("{caption} ({outside} outside, not drawn)");
        }
        let mut chart = ChartBuilder::on(area)
            .caption(caption, caption_font())
            .margin(12)
            .x_label_area_size(28)
            .y_label_area_size(40)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(drawing)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_labels(5)
            .y_labels(5)
            .label_style(label_font())
            .draw()
            .map_err(drawing)?;
        // The domain's outline.
        let outline: Vec<(f64, f64)> = match self.domain {
            Domain::Square => vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)],
            Domain::Disk | Domain::Hemisphere => (0..=128)
                .map(|k| {
                    let t = k as f64 / 128.0 * std::f64::consts::TAU;
                    (t.cos(), t.sin())
                })
                .collect(),
            Domain::Triangle => vec![(0.0, 0.0), (1.0, 0.0), (0.5, y1), (0.0, 0.0)],
        };
        let grey = RGBColor(150, 150, 150);
        chart
            .draw_series(std::iter::once(PathElement::new(
                outline,
                grey.stroke_width(1),
            )))
            .map_err(drawing)?;
        if let Some((a, b)) = self.intervals {
            let line = RGBColor(120, 160, 220).stroke_width(1);
            let vertical = (1..a).map(|i| {
                let x = i as f64 / a as f64;
                PathElement::new(vec![(x, 0.0), (x, 1.0)], line)
            });
            chart.draw_series(vertical).map_err(drawing)?;
            let horizontal = (1..b).map(|j| {
                let y = j as f64 / b as f64;
                PathElement::new(vec![(0.0, y), (1.0, y)], line)
            });
            chart.draw_series(horizontal).map_err(drawing)?;
        }
        let r = self.radius as i32;
        let dots = self.points.iter().enumerate().filter_map(|(i, &p)| {
            let q = self.placed(p)?;
            let c = match self.groups {
                Some(g) => PALETTE[(i / g.max(1)) % PALETTE.len()],
                None => BLACK,
            };
            Some(Circle::new(q, r, c.filled()))
        });
        chart.draw_series(dots).map_err(drawing)?;
        Ok(())
    }
}
