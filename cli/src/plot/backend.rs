//! Output: SVG (a string of text elements) or PNG (an RGB raster encoded with `png`).

use std::fmt;

use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;

/// The embedded font (DejaVu Sans; see `cli/src/plot/font/LICENSE-DejaVu`).
static FONT: &[u8] = include_bytes!("font/DejaVuSans.ttf");

/// The largest number of elements (points, pixels, curve vertices) one figure draws.
pub const MAX_ELEMENTS: usize = 1 << 22;

/// The largest width or height of a figure, in pixels.
const MAX_SIDE: u32 = 8192;

/// Why a figure could not be drawn.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlotError(pub String);

impl fmt::Display for PlotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for PlotError {}

impl PlotError {
    /// An error with this message.
    pub fn new(message: impl Into<String>) -> Self {
        PlotError(message.into())
    }
}

/// Any drawing error of plotters, as text.
pub(crate) fn drawing<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> PlotError {
    PlotError(format!("drawing failed: {e}"))
}

/// An output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Scalable vector graphics; text as `<text>` elements.
    Svg,
    /// An 8-bit RGB PNG.
    Png,
}

impl Format {
    /// The format a file name asks for by its extension (`.svg` or `.png`, any case).
    ///
    /// # Errors
    /// A [`PlotError`] naming the extension otherwise.
    pub fn from_path(path: &str) -> Result<Self, PlotError> {
        let lower = path.to_ascii_lowercase();
        if lower.ends_with(".svg") {
            Ok(Format::Svg)
        } else if lower.ends_with(".png") {
            Ok(Format::Png)
        } else {
            Err(PlotError::new(format!(
                "{path:?}: unknown figure format (use a .svg or .png file name)"
            )))
        }
    }
}

/// A picture that can draw itself on any plotters backend.
pub trait Figure {
    /// Number of elements drawn (checked against [`MAX_ELEMENTS`] before drawing).
    fn elements(&self) -> usize;
    /// Draws the figure on `area` (already filled white).
    ///
    /// # Errors
    /// A [`PlotError`] for data that cannot be drawn or a backend failure.
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static;
}

/// Registers the embedded font once (plotters keeps a global font table).
fn font() -> Result<(), PlotError> {
    static DONE: OnceLock<Result<(), String>> = OnceLock::new();
    DONE.get_or_init(|| {
        plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
            .map_err(|_| "the embedded font could not be read".to_owned())?;
        plotters::style::register_font("sans-serif", FontStyle::Bold, FONT)
            .map_err(|_| "the embedded font could not be read".to_owned())
    })
    .clone()
    .map_err(PlotError)
}

/// Draws `figure` at `width x height` pixels and returns the file's bytes (SVG text or PNG).
///
/// # Errors
/// A [`PlotError`] for a size of 0 or above 8192, a figure of more than [`MAX_ELEMENTS`]
/// elements, or a drawing failure. Cost: linear in the elements and (PNG) the pixels.
pub fn render<F: Figure>(
    figure: &F,
    format: Format,
    width: u32,
    height: u32,
) -> Result<Vec<u8>, PlotError> {
    if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
        return Err(PlotError::new(format!(
            "figure size {width}x{height} is outside 1..={MAX_SIDE} pixels a side"
        )));
    }
    if figure.elements() > MAX_ELEMENTS {
        return Err(PlotError::new(format!(
            "the figure has {} elements, more than the {MAX_ELEMENTS} drawn at most",
            figure.elements()
        )));
    }
    font()?;
    match format {
        Format::Svg => {
            let mut text = String::new();
            {
                let root = SVGBackend::with_string(&mut text, (width, height)).into_drawing_area();
                root.fill(&WHITE).map_err(drawing)?;
                figure.draw(&root)?;
                root.present().map_err(drawing)?;
            }
            // Every text went through `clean`; this keeps the file well-formed XML even if a
            // future figure forgets (plotters escapes markup, not control characters).
            text.retain(xml_char);
            Ok(text.into_bytes())
        }
        Format::Png => {
            let len = qmckit::size::product("bytes", u64::from(width) * 3, u64::from(height))
                .map_err(|e| PlotError(e.to_string()))?;
            let mut rgb: Vec<u8> =
                qmckit::size::vec_zeroed(len).map_err(|e| PlotError(e.to_string()))?;
            {
                let root =
                    BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area();
                root.fill(&WHITE).map_err(drawing)?;
                figure.draw(&root)?;
                root.present().map_err(drawing)?;
            }
            encode_png(&rgb, width, height)
        }
    }
}

/// Encodes an RGB buffer as PNG.
fn encode_png(rgb: &[u8], width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let fail = |e: png::EncodingError| PlotError(format!("PNG encoding failed: {e}"));
        let mut w = enc.write_header().map_err(fail)?;
        w.write_image_data(rgb).map_err(fail)?;
        w.finish().map_err(fail)?;
    }
    Ok(out)
}

/// Whether `c` may appear in an XML 1.0 document (`#x9 | #xA | #xD | [#x20-#xD7FF] |
/// [#xE000-#xFFFD] | [#x10000-#x10FFFF]`; a Rust `char` is never a surrogate).
fn xml_char(c: char) -> bool {
    matches!(c, '\t' | '\n' | '\r') || !(c.is_control() || matches!(c, '\u{fffe}' | '\u{ffff}'))
}

/// Text as drawn: tabs and line breaks become spaces, other control characters (C0, DEL,
/// C1) and the non-characters U+FFFE, U+FFFF are dropped, so a caption or label is
/// well-formed in SVG (whose markup plotters escapes) and has no invisible glyphs in PNG.
/// `O(len)`.
pub(crate) fn clean(text: &str) -> String {
    text.chars()
        .filter_map(|c| match c {
            '\t' | '\n' | '\r' => Some(' '),
            c if xml_char(c) => Some(c),
            _ => None,
        })
        .collect()
}

/// A linear axis `lo..hi`: both finite, `lo < hi`, and `hi - lo` finite (plotters' tick
/// search does not end on an infinite or NaN span).
///
/// # Errors
/// A [`PlotError`] naming `what` and the range otherwise.
pub(crate) fn linear_axis(lo: f64, hi: f64, what: &str) -> Result<(f64, f64), PlotError> {
    if lo.is_finite() && hi.is_finite() && lo < hi && (hi - lo).is_finite() {
        Ok((lo, hi))
    } else {
        Err(PlotError::new(format!(
            "the {what} range {lo:e} to {hi:e} cannot be drawn (it must be finite, \
             increasing, and its width below {:e})",
            f64::MAX
        )))
    }
}

/// A logarithmic axis `lo..hi`: `0 < lo < hi`, both finite, and `hi / lo` finite (at most
/// about 308 decades; plotters' tick search runs in the ratio's decades, and forever when it
/// is infinite).
///
/// # Errors
/// A [`PlotError`] naming `what` and the range otherwise.
pub(crate) fn log_axis(lo: f64, hi: f64, what: &str) -> Result<(f64, f64), PlotError> {
    if lo > 0.0 && lo < hi && hi.is_finite() && (hi / lo).is_finite() {
        Ok((lo, hi))
    } else {
        Err(PlotError::new(format!(
            "the {what} range {lo:e} to {hi:e} cannot be drawn on a log axis (it must be \
             positive, finite, and span at most {:e} times)",
            f64::MAX
        )))
    }
}

/// A range around the single value `v` (a constant image): `v +- max(1/2, |v| 2^-20)`, moved
/// inside the finite floats near `+-f64::MAX`.
pub(crate) fn widen(v: f64) -> (f64, f64) {
    let d = (v.abs() * (1.0 / 1_048_576.0)).max(0.5);
    match (v - d, v + d) {
        (a, b) if a.is_finite() && b.is_finite() => (a, b),
        _ if v > 0.0 => (v - 2.0 * d, v),
        _ => (v, v + 2.0 * d),
    }
}

/// The caption font.
pub(crate) fn caption_font() -> TextStyle<'static> {
    ("sans-serif", 18).into_font().color(&BLACK)
}

/// The axis-label font.
pub(crate) fn label_font() -> TextStyle<'static> {
    ("sans-serif", 13).into_font().color(&BLACK)
}
