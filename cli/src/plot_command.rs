//! `qmckit plot [--kind auto|points|spectrum|radial|convergence|image] --out FILE.svg|FILE.png
//! [--intervals AxB] [--warp disk|hemisphere|triangle] [FILE|-]`: a figure of a point file, a
//! spectrum, a convergence table or an image, read from a file or a pipe.

use crate::plot::{
    ColourMap, ConvergenceFigure, Curve, Domain, Figure, Format, ImageFigure, PlotError,
    PointsFigure, RadialFigure, SpectrumFigure, decode_image, parse_blocks, parse_table, render,
};
use clap::{Args, ValueEnum};
use qmckit::analysis::pointfile::parse_point_sets;

use super::Failure;

/// Text shown after the options of `qmckit plot --help`.
pub const AFTER_HELP: &str = "\
Input (FILE, or standard input for '-' or none), by --kind (auto: from the first bytes):
  points       a point file as 'qmckit points' writes it (real or u32 coordinates); the
               first two coordinates of each point are drawn (1D files are refused)
  spectrum     'qmckit spectrum' output ('# kx ky power' lines): a log-scaled image with
               the DC term circled and a colour bar in dB
  radial       'qmckit spectrum --radial' output ('# radius count mean anisotropy')
  pcf          'qmckit pcf' output ('# radius g'): g(r) against r
  convergence  'qmckit convergence' output ('# n rmse' lines), log-log with the fitted slope
  image        PGM (P2/P5), PNG, or text rows of numbers ('qmckit mask' output, headed
               '# qmckit mask'), with a colour bar
auto reads '# kx ky', '# radius g', '# radius', '# n rmse', '# qmckit mask' headers,
PNG/PGM/npy signatures, and points otherwise (text or .npy, as 'qmckit points' writes
them); 'qmckit pixel' output (headed '# qmckit pixel') is refused in one line. Several sets (split by lines holding only '#', or '# set K') are drawn as
separate curves, named by a '# label: NAME' line in the set or 'set K' (radial,
convergence), or the first is drawn (points, spectrum).

--intervals AxB overlays the A x B grid of elementary intervals (A columns, B rows) and
counts the boxes holding exactly N/(AB) points; --warp maps the points to the unit disk
(concentric), the cosine-weighted hemisphere seen from above, or a triangle; --groups G
colours runs of G consecutive points.

The format follows --out's extension: .svg (vector, text as text) or .png (text drawn with
the embedded DejaVu Sans: no fonts needed). At most 2^22 drawn elements. Errors: one line
on stderr, exit code 2 for bad input or options, 1 for an unwritable --out.";

/// `--kind`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Kind {
    /// From the input's first bytes.
    Auto,
    /// A point set.
    Points,
    /// A 2D spectrum.
    Spectrum,
    /// Radial spectra.
    Radial,
    /// A pair correlation function ('qmckit pcf' output).
    Pcf,
    /// Error against N.
    Convergence,
    /// An image.
    Image,
}

/// `--warp`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum WarpName {
    /// The unit disk (concentric map).
    Disk,
    /// The cosine-weighted hemisphere, from above.
    Hemisphere,
    /// An equilateral triangle.
    Triangle,
}

/// `--colours` of an image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MapName {
    /// Black to white.
    Grey,
    /// Dark blue to yellow.
    Viridis,
    /// Blue-white-red about 0.
    Diverging,
}

/// Arguments of `qmckit plot`.
#[derive(Args, Debug)]
pub struct PlotArgs {
    /// The figure file: .svg or .png.
    #[arg(long, short = 'o', value_name = "FILE")]
    pub out: String,
    /// What the input holds.
    #[arg(long, value_enum, default_value_t = Kind::Auto)]
    pub kind: Kind,
    /// Elementary-interval grid, A columns by B rows (points only).
    #[arg(long, value_name = "AxB")]
    pub intervals: Option<String>,
    /// Warp the points to another domain (points only).
    #[arg(long, value_enum)]
    pub warp: Option<WarpName>,
    /// Colour runs of G consecutive points (points only).
    #[arg(long, value_name = "G")]
    pub groups: Option<usize>,
    /// Colour map of an image.
    #[arg(long, value_enum, default_value_t = MapName::Grey)]
    pub colours: MapName,
    /// Figure size in pixels, WxH.
    #[arg(long, default_value = "640x640", value_name = "WxH")]
    pub size: String,
    /// Caption (default: from the input).
    #[arg(long)]
    pub title: Option<String>,
    /// Input file; '-' or none reads standard input.
    pub file: Option<String>,
}

/// Parses `AxB` with both positive and at most `max`.
fn pair(text: &str, option: &str, max: u32) -> Result<(u32, u32), Failure> {
    let bad = || {
        Failure::usage(format!(
            "{option} must be AxB with A, B in 1..={max}, not {text:?}"
        ))
    };
    let (a, b) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let a: u32 = a.trim().parse().map_err(|_| bad())?;
    let b: u32 = b.trim().parse().map_err(|_| bad())?;
    if a == 0 || b == 0 || a > max || b > max {
        return Err(bad());
    }
    Ok((a, b))
}

/// Reads the input through the bounded reader; empty input is refused.
fn read(file: Option<&str>) -> Result<(String, Vec<u8>), Failure> {
    let (name, bytes) = super::input::read_bounded(file, super::input::DATA)?;
    if bytes.iter().all(u8::is_ascii_whitespace) {
        return Err(Failure::usage(format!("{name}: empty input")));
    }
    Ok((name, bytes))
}

/// The kind `auto` picks for these bytes, or why it cannot tell (an output of the tool
/// that is not a figure's input).
fn detect(bytes: &[u8]) -> Result<Kind, String> {
    if bytes.starts_with(b"\x89PNG") || bytes.starts_with(b"P5") || bytes.starts_with(b"P2") {
        return Ok(Kind::Image);
    }
    if bytes.starts_with(b"\x93NUMPY") {
        return Ok(Kind::Points);
    }
    let head = String::from_utf8_lossy(&bytes[..bytes.len().min(4096)]);
    for line in head.lines().map(str::trim) {
        if line.starts_with("# qmckit mask") {
            return Ok(Kind::Image);
        }
        if line.starts_with("# qmckit pixel") {
            return Err(
                "'qmckit pixel' output (one pixel's samples: index, 1D and 2D values) is not a \
                 figure's input; write the points with 'qmckit points' to plot them"
                    .to_owned(),
            );
        }
        if line.starts_with("# radius g") {
            return Ok(Kind::Pcf);
        }
        if line.starts_with("# kx ky") {
            return Ok(Kind::Spectrum);
        }
        if line.starts_with("# radius") {
            return Ok(Kind::Radial);
        }
        if line.starts_with("# n rmse") || line.starts_with("# n ") {
            return Ok(Kind::Convergence);
        }
        if !line.is_empty() && !line.starts_with('#') {
            break;
        }
    }
    Ok(Kind::Points)
}

/// Runs `qmckit plot`.
pub fn run(args: &PlotArgs) -> Result<(), Failure> {
    let format = Format::from_path(&args.out).map_err(|e| Failure::usage(e.0))?;
    let (w, h) = pair(&args.size, "--size", 8192)?;
    let intervals = args
        .intervals
        .as_deref()
        .map(|t| pair(t, "--intervals", 4096))
        .transpose()?;
    let (name, bytes) = read(args.file.as_deref())?;
    let kind = match args.kind {
        Kind::Auto => detect(&bytes).map_err(|e| Failure::usage(format!("{name}: {e}")))?,
        k => k,
    };
    if kind != Kind::Points && (intervals.is_some() || args.warp.is_some() || args.groups.is_some())
    {
        return Err(Failure::usage(
            "--intervals, --warp and --groups apply to point sets only",
        ));
    }
    let input = |e: PlotError| Failure::usage(format!("{name}: {e}"));
    let text = || {
        std::str::from_utf8(&bytes).map_err(|_| Failure::usage(format!("{name}: not UTF-8 text")))
    };
    let title = |default: &str| args.title.clone().unwrap_or_else(|| default.to_owned());
    // What the figure leaves out, told once the file is written.
    let mut note = None;
    let out = match kind {
        Kind::Points | Kind::Auto => {
            let sets = if bytes.starts_with(b"\x93NUMPY") {
                vec![
                    super::input::read_npy(&bytes)
                        .map_err(|e| Failure::usage(format!("{name}: {e}")))?,
                ]
            } else {
                parse_point_sets(text()?).map_err(|e| Failure::usage(format!("{name}: {e}")))?
            };
            let set = &sets[0];
            if set.dims < 2 {
                return Err(Failure::usage(format!(
                    "{name}: a point plot needs 2D points, this set has {} coordinate a point",
                    set.dims
                )));
            }
            let pts: Vec<[f64; 2]> = set
                .data
                .chunks_exact(set.dims)
                .map(|p| [p[0], if set.dims > 1 { p[1] } else { 0.5 }])
                .collect();
            let mut fig = PointsFigure::new(title(&format!("{} points", pts.len())), pts);
            if let Some((a, b)) = intervals {
                fig = fig.intervals(a, b);
            }
            if let Some(g) = args.groups {
                if g == 0 {
                    return Err(Failure::usage("--groups must be at least 1"));
                }
                fig = fig.groups(g);
            }
            if let Some(wp) = args.warp {
                fig = fig.domain(match wp {
                    WarpName::Disk => Domain::Disk,
                    WarpName::Hemisphere => Domain::Hemisphere,
                    WarpName::Triangle => Domain::Triangle,
                });
            }
            let outside = fig.outside();
            if outside > 0 {
                note = Some(format!(
                    "{outside} points outside the plotted domain, not drawn"
                ));
            }
            draw(&fig, format, w, h, &name)?
        }
        Kind::Spectrum => {
            let block = &parse_table(text()?, 3).map_err(input)?[0];
            let (k, values) =
                spectrum_grid(block).map_err(|e| Failure::usage(format!("{name}: {e}")))?;
            let fig = SpectrumFigure::new(title("power spectrum"), k, values).map_err(input)?;
            draw(&fig, format, w, h, &name)?
        }
        Kind::Radial => {
            let blocks = parse_blocks(text()?, 3).map_err(input)?;
            let curves = blocks
                .iter()
                .enumerate()
                .map(|(i, b)| {
                    (
                        curve_label(b, i),
                        b.rows.iter().map(|r| (r[0], r[2])).collect(),
                    )
                })
                .collect();
            let fig = RadialFigure {
                title: title("radial power spectrum"),
                x_label: "radius |k|".into(),
                y_label: "mean power".into(),
                curves,
            };
            draw(&fig, format, w, h, &name)?
        }
        Kind::Pcf => {
            let blocks = parse_blocks(text()?, 2).map_err(input)?;
            let curves = blocks
                .iter()
                .enumerate()
                .map(|(i, b)| {
                    (
                        curve_label(b, i),
                        b.rows.iter().map(|r| (r[0], r[1])).collect(),
                    )
                })
                .collect();
            let fig = RadialFigure {
                title: title("pair correlation g(r)"),
                x_label: "distance r".into(),
                y_label: "g(r)".into(),
                curves,
            };
            draw(&fig, format, w, h, &name)?
        }
        Kind::Convergence => {
            let blocks = parse_blocks(text()?, 2).map_err(input)?;
            let curves = blocks
                .iter()
                .enumerate()
                .map(|(i, b)| Curve {
                    label: curve_label(b, i),
                    points: b.rows.iter().map(|r| (r[0], r[1])).collect(),
                })
                .collect();
            let fig = ConvergenceFigure::new(title("integration error"), curves);
            let left = fig.left_out();
            if left > 0 {
                note = Some(format!(
                    "{left} (n, error) pairs not drawn (a value not positive, not finite, or \
                     below {:e}: no logarithm)",
                    f64::MIN_POSITIVE
                ));
            }
            draw(&fig, format, w, h, &name)?
        }
        Kind::Image => {
            let (iw, ih, px) = decode_image(&bytes).map_err(input)?;
            let fig = ImageFigure::new(title(&format!("{iw}x{ih} image")), iw, ih, px)
                .map_err(input)?
                .map(match args.colours {
                    MapName::Grey => ColourMap::Grey,
                    MapName::Viridis => ColourMap::Viridis,
                    MapName::Diverging => ColourMap::Diverging,
                });
            draw(&fig, format, w, h, &name)?
        }
    };
    super::atomic::write_bytes(std::path::Path::new(&args.out), &out)?;
    if let Some(n) = note {
        eprintln!("qmckit: note: {name}: {n}");
    }
    Ok(())
}

fn draw<F: Figure>(
    fig: &F,
    format: Format,
    w: u32,
    h: u32,
    name: &str,
) -> Result<Vec<u8>, Failure> {
    render(fig, format, w, h).map_err(|e| Failure::usage(format!("{name}: {e}")))
}

/// The `(2K + 1)^2` powers of a `kx ky power` table as `(K, values)`, laid out as
/// [`SpectrumFigure::values`]: every integer frequency of `[-K, K]^2` exactly once, `K`
/// found without overflow (the row count bounds it: at most 2^22 rows, so `K < 1024`).
fn spectrum_grid(block: &[Vec<f64>]) -> Result<(usize, Vec<f64>), String> {
    let kf = block
        .iter()
        .map(|r| r[0].abs().max(r[1].abs()))
        .fold(0.0, f64::max);
    // (2K + 1)^2 rows: K is at most sqrt(rows) / 2.
    let bound = (block.len() as f64).sqrt() / 2.0;
    let bad = |k: &dyn std::fmt::Display, want: &dyn std::fmt::Display| {
        format!(
            "a spectrum needs 'kx ky power' lines at every integer frequency of [-K, K]^2, once \
             each ({want} for K = {k}), found {}",
            block.len()
        )
    };
    if kf > bound {
        return Err(bad(&kf, &"(2K + 1)^2"));
    }
    let k = kf as usize; // kf <= 2^10: exact
    let side = 2 * k + 1;
    let n = side * side;
    if block.len() != n {
        return Err(bad(&k, &n));
    }
    let mut values: Vec<f64> = qmckit::size::vec_zeroed(n).map_err(|e| e.to_string())?;
    let mut seen: Vec<bool> = qmckit::size::vec_zeroed(n).map_err(|e| e.to_string())?;
    for r in block {
        if r[0].fract() != 0.0 || r[1].fract() != 0.0 {
            return Err(bad(&k, &n));
        }
        // |kx|, |ky| <= K: whole numbers in 0..side after the shift.
        let (kx, ky) = ((r[0] + k as f64) as usize, (r[1] + k as f64) as usize);
        let at = ky * side + kx;
        match seen.get_mut(at) {
            Some(s) if !*s => *s = true,
            _ => return Err(bad(&k, &n)),
        }
        if let Some(v) = values.get_mut(at) {
            *v = r[2];
        }
    }
    Ok((k, values))
}

/// A curve's legend: the block's `# label:` or `set K`.
fn curve_label(b: &crate::plot::Block, i: usize) -> String {
    b.label.clone().unwrap_or_else(|| format!("set {}", i + 1))
}
