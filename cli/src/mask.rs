//! `qmckit mask void-and-cluster --size WxH [--seed S] [--sigma X] [--format u16|pgm|png]`:
//! a toroidal void-and-cluster rank mask (Ulichney 1993).

use std::io::Write;

use clap::{Args, Subcommand, ValueEnum};
use qmckit::blue_noise::{RankMask, VoidAndCluster};

use super::Failure;
use super::budget::BudgetArgs;

/// Text shown after the options of `qmckit mask void-and-cluster --help`.
pub const AFTER_HELP: &str = "\
The mask is a permutation of the ranks 0..W*H-1 on the torus (it tiles); the pixels of
rank below t*W*H form a blue-noise pattern of grey level t. Sides 1 to 4096, at most 2^22
pixels; the estimated time is checked against --max-seconds before anything runs.

Formats: u16 (default), text, one row of ranks per line, space-separated; past 65536
pixels the values are the 16-bit levels floor(rank * 65536 / (W*H)). pgm: binary 16-bit
PGM (P5, maxval 65535) of those levels; png: 16-bit greyscale PNG of the same levels.";

/// `qmckit mask KIND`.
#[derive(Subcommand, Debug)]
pub enum MaskCommand {
    /// Ulichney's void-and-cluster rank mask (Gaussian sigma 1.5 px), toroidal.
    #[command(after_help = AFTER_HELP)]
    VoidAndCluster(VoidAndClusterArgs),
}

/// Output format of a mask.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MaskFormat {
    /// Text: one row of ranks (16-bit levels past 65536 pixels) per line.
    U16,
    /// Binary 16-bit PGM (P5).
    Pgm,
    /// 16-bit greyscale PNG.
    Png,
}

/// Arguments of `qmckit mask void-and-cluster`.
#[derive(Args, Debug)]
pub struct VoidAndClusterArgs {
    /// Mask size, WxH (e.g. 64x64).
    #[arg(long, value_name = "WxH")]
    size: String,
    /// Seed of the initial random pattern [default: 0].
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Gaussian standard deviation in pixels, 0.5 to 8.
    #[arg(long, default_value_t = 1.5)]
    sigma: f64,
    /// Output format.
    #[arg(long, value_enum, default_value_t = MaskFormat::U16)]
    format: MaskFormat,
    #[command(flatten)]
    budget: BudgetArgs,
}

/// Parses `WxH`.
fn parse_size(text: &str) -> Result<(usize, usize), Failure> {
    let bad = || Failure::usage(format!("--size {text:?} is not WxH (e.g. 256x256)"));
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: usize = w.trim().parse().map_err(|_| bad())?;
    let h: usize = h.trim().parse().map_err(|_| bad())?;
    Ok((w, h))
}

/// Runs `qmckit mask`.
pub fn run(cmd: &MaskCommand) -> Result<(), Failure> {
    let MaskCommand::VoidAndCluster(args) = cmd;
    let (w, h) = parse_size(&args.size)?;
    let budget = args.budget.budget()?;
    let mask = VoidAndCluster::new(w, h)?
        .seed(args.seed)
        .sigma(args.sigma)?
        .generate(&budget)?;
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    write_mask(&mut out, &mask, args.format)?;
    out.flush()?;
    Ok(())
}

/// The value written for a rank: the rank itself up to 65536 pixels, else its 16-bit level.
fn level(rank: u32, pixels: usize) -> u16 {
    if pixels <= 1 << 16 {
        rank as u16
    } else {
        ((u64::from(rank) << 16) / pixels as u64) as u16
    }
}

/// The 16-bit image level of a rank: `floor(rank 65536 / pixels)`.
fn image_level(rank: u32, pixels: usize) -> u16 {
    ((u64::from(rank) << 16) / pixels as u64) as u16
}

fn write_mask(out: &mut impl Write, mask: &RankMask, format: MaskFormat) -> Result<(), Failure> {
    let (w, h) = (mask.width(), mask.height());
    let n = w * h;
    match format {
        MaskFormat::U16 => {
            // The header names the kind, so `qmckit plot` draws it as an image.
            writeln!(out, "# qmckit mask {w}x{h}: rank levels, one row a line")?;
            let mut line = String::new();
            for row in mask.ranks().chunks(w) {
                line.clear();
                for (i, &r) in row.iter().enumerate() {
                    use std::fmt::Write as _;
                    if i > 0 {
                        line.push(' ');
                    }
                    let _ = write!(line, "{}", level(r, n));
                }
                line.push('\n');
                out.write_all(line.as_bytes())?;
            }
        }
        MaskFormat::Pgm => {
            write!(out, "P5\n{w} {h}\n65535\n")?;
            // Row by row: 2 W bytes at a time, whatever the size.
            let mut bytes = Vec::new();
            qmckit::size::reserve(&mut bytes, qmckit::size::product("bytes", w as u64, 2)?)?;
            for row in mask.ranks().chunks(w.max(1)) {
                bytes.clear();
                bytes.extend(row.iter().flat_map(|&r| image_level(r, n).to_be_bytes()));
                out.write_all(&bytes)?;
            }
        }
        MaskFormat::Png => {
            let (pw, ph) = (u32::try_from(w), u32::try_from(h));
            let (Ok(pw), Ok(ph)) = (pw, ph) else {
                return Err(Failure::usage("mask too large for PNG"));
            };
            let mut enc = png::Encoder::new(&mut *out, pw, ph);
            enc.set_color(png::ColorType::Grayscale);
            enc.set_depth(png::BitDepth::Sixteen);
            // The encoder takes the image whole: 2 W H bytes (at most 8 MiB), checked.
            let mut bytes =
                qmckit::size::vec_with_capacity(qmckit::size::product("bytes", n as u64, 2)?)?;
            bytes.extend(
                mask.ranks()
                    .iter()
                    .flat_map(|&r| image_level(r, n).to_be_bytes()),
            );
            let mut writer = enc.write_header().map_err(|e| Failure {
                code: 1,
                message: format!("write failed: {e}"),
            })?;
            writer.write_image_data(&bytes).map_err(|e| Failure {
                code: 1,
                message: format!("write failed: {e}"),
            })?;
            writer.finish().map_err(|e| Failure {
                code: 1,
                message: format!("write failed: {e}"),
            })?;
        }
    }
    Ok(())
}
