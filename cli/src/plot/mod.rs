//! Figures of sampling patterns and their measurements, as SVG or PNG (`qmckit plot`).
//!
//! One builder per kind of picture, each a plain struct of data that implements [`Figure`]:
//!
//! | builder | shows |
//! |---|---|
//! | [`PointsFigure`] | a 2D point set in the unit square, optionally with an elementary-interval grid (`a x b` boxes), coloured groups (e.g. consecutive power-of-two runs), or warped to a disk, the cosine-weighted hemisphere (seen from above) or a triangle |
//! | [`SpectrumFigure`] | a 2D periodogram `P(kx, ky)` on `[-K, K]^2` as a log-scaled image with the DC term marked |
//! | [`RadialFigure`] | radial averages of spectra as curves |
//! | [`ConvergenceFigure`] | error against the number of points on log-log axes, each curve with its fitted slope |
//! | [`ImageFigure`] | a grey-level or diverging image (a dither mask, a render, an error image) with a colour bar |
//!
//! [`render`] draws a figure into [`Format::Svg`] (vector; text stays text) or
//! [`Format::Png`] (RGB, 8 bits). Cost: linear in what is drawn (points, pixels, curve
//! points); figures refuse more than [`MAX_ELEMENTS`] elements rather than grow without
//! bound.
//!
//! # Text without font files
//!
//! PNG text needs glyph outlines. Rather than depending on fonts installed on the machine
//! (or rendering SVG through a second rasterizer such as resvg, a much larger dependency),
//! the module embeds DejaVu Sans (`cli/src/plot/font/`, Bitstream Vera licence, permissive) with
//! `include_bytes!` and hands it to plotters' `ab_glyph` text renderer; SVG output writes
//! `<text>` elements whose size is laid out with the same font, so both formats agree.
//!
//! ```
//! use qmckit_cli::plot::{Format, PointsFigure, render};
//! let pts: Vec<[f64; 2]> = (0..16).map(|i| [(i as f64 + 0.5) / 16.0, ((i * 5 % 16) as f64 + 0.5) / 16.0]).collect();
//! let fig = PointsFigure::new("16 points", pts).intervals(4, 4);
//! let svg = render(&fig, Format::Svg, 400, 400)?;
//! assert!(svg.starts_with(b"<svg"));
//! let png = render(&fig, Format::Png, 200, 200)?;
//! assert_eq!(&png[1..4], b"PNG");
//! # Ok::<(), qmckit_cli::plot::PlotError>(())
//! ```

mod backend;
mod colour;
mod convergence;
mod decode;
mod image;
mod points;
mod spectrum;

pub use backend::{Figure, Format, MAX_ELEMENTS, PlotError, render};
pub use colour::{grey, viridis};
pub use convergence::{ConvergenceFigure, Curve};
pub use decode::{Block, Decoded, decode_image, parse_blocks, parse_table};
pub use image::{ColourMap, ImageFigure};
pub use points::{Domain, MAX_RADIUS, PointsFigure};
pub use spectrum::{RadialFigure, SpectrumFigure};
