//! `qmckit pixel SAMPLER --resolution WxH --spp S [--seed K] --pixel X,Y [--dim D]
//! [--randomize KIND] [--format decimal|u32|csv]`: the samples of one pixel, as pbrt-v4's
//! samplers return them.

use std::io::{BufWriter, Write};

use clap::{Args, ValueEnum};
use qmckit::catalog::{self, CatalogError, PixelEntry, PixelParams, RandomizerEntry};
use qmckit::pixel::PixelSampler;

use super::{Failure, names};

/// Text shown after the options of `qmckit pixel --help`.
pub const AFTER_HELP: &str = "\
One line per sample index i = 0..S-1 of the pixel: the global sample index (the index into
the Sobol' sequence for zsobol and sobol; '-' where the sampler has none), the 1D value at
dimension D and the 2D value at dimension D: pbrt-v4's Get1D and Get2D called with the
dimension counter at D (ZSobolSampler, SobolSampler, PaddedSobolSampler; bit-identical).
halton is HaltonSampler and stratified is StratifiedSampler (bit-identical; their csv
floats are pbrt's float arithmetic, not a rounding of the exact value); halton's 2D value at
D is Get2D with the counter at max(D, 2), its pixel position is not printed. stratified splits
S into xs x ys strata as pbrt does given a sample count. independent is qmckit's hashed white noise, not pbrt's PCG stream; pmj02 reads one shared
65,536-point PMJ02 table through a per-pixel, per-dimension index shuffle and Owen
scrambles (every power-of-two prefix of a pixel's points a (0,m,2)-net; --spp at most 65536); pmj02bn is pbrt's PMJ02BNSampler layout on a generated
65,536-point PMJ02BN table (seeded by --seed): the 2D value at D is Get2D with the counter at
max(D, 2), and the pixel position (GetPixel2D, a tile of the table) is not printed.

--randomize (zsobol, sobol, padded-sobol): none, xor (pbrt's PermuteDigits), fast-owen (the
default), owen; halton: none, xor (the default), owen; stratified: none (the strata's
centres; jittered without --randomize). --spp must be a power of two for zsobol. --seed is a u64; below 2^32 it is
pbrt's int seed as 32 bits (bit-identical).

Formats: decimal (default): 'index v1 x y', the values v / 2^32 exactly, as the shortest
decimals that parse back to them (every one is an f64); u32: 'index v1 x y', the values as
integers v * 2^32; csv: 'index,v1,x,y' with the floats pbrt returns (min(float(v) 2^-32,
1 - 2^-24)), shortest round-trip text.";

/// `--format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum PixelFormat {
    /// The exact values v / 2^32 as shortest round-trip decimals, space-separated.
    Decimal,
    /// Integers v * 2^32.
    U32,
    /// pbrt's floats, comma-separated.
    Csv,
}

/// `qmckit pixel` arguments.
#[derive(Args, Debug)]
pub struct PixelArgs {
    /// The sampler (a catalog pixel sampler or alias, any case).
    #[arg(value_parser = names::pixel_samplers())]
    pub sampler: &'static PixelEntry,
    /// Image size, WxH (e.g. 1920x1080).
    #[arg(long)]
    pub resolution: String,
    /// Samples per pixel.
    #[arg(long)]
    pub spp: u32,
    /// Seed (below 2^32, pbrt's int seed as 32 bits).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// The pixel, X,Y (0-based).
    #[arg(long)]
    pub pixel: String,
    /// The dimension counter D.
    #[arg(long, default_value_t = 0)]
    pub dim: usize,
    /// Randomization of the Sobol' samplers [default: fast-owen], of halton [default: xor],
    /// none for stratified's strata centres [default: jittered].
    #[arg(long, value_parser = names::randomizers().only(
        |r| r.kind.pixel().is_some(),
        "the pixel samplers take none, xor, fast-owen and owen",
    ))]
    pub randomize: Option<&'static RandomizerEntry>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = PixelFormat::Decimal)]
    pub format: PixelFormat,
}

/// Two unsigned integers separated by `sep` (`--resolution 16x9`, `--pixel 3,5`).
fn pair(flag: &str, text: &str, sep: char) -> Result<(u32, u32), Failure> {
    let bad = || {
        Failure::usage(format!(
            "{flag} {}: expected two non-negative integers as A{sep}B",
            text.escape_debug()
        ))
    };
    let (a, b) = text.split_once(sep).ok_or_else(bad)?;
    let a = a.trim().parse::<u32>().map_err(|_| bad())?;
    let b = b.trim().parse::<u32>().map_err(|_| bad())?;
    Ok((a, b))
}

/// Runs `qmckit pixel`.
pub fn run(args: &PixelArgs) -> Result<(), Failure> {
    let (w, h) = pair("--resolution", &args.resolution, 'x')?;
    let (x, y) = pair("--pixel", &args.pixel, ',')?;
    let spp = args.spp;
    if args.sampler.kind.needs_power_of_two() && !spp.is_power_of_two() {
        return Err(Failure::usage(format!(
            "--spp {spp}: {} needs a power of two",
            args.sampler.name
        )));
    }
    let params = PixelParams {
        width: w,
        height: h,
        spp,
        seed: args.seed,
    };
    let sampler =
        catalog::build_pixel(args.sampler, args.randomize, &params).map_err(|e| match e {
            CatalogError::NotApplicable {
                randomizer,
                sampler,
                rule,
                ..
            } if args.randomize.is_some() => {
                if args.sampler.kind.takes_randomizer() {
                    Failure::usage(format!(
                        "--randomize {randomizer} does not apply to {sampler}: it applies to {rule}"
                    ))
                } else {
                    Failure::usage(format!(
                        "--randomize does not apply to {sampler} (its randomness is its own)"
                    ))
                }
            }
            other => Failure::from(other),
        })?;
    // Checks the pixel once, so an error comes before any output.
    PixelSampler::start_pixel_sample(&sampler, x, y, 0)?;
    let mut out = BufWriter::new(std::io::stdout().lock());
    // The header names the kind, so `qmckit plot` refuses it instead of drawing points.
    writeln!(
        out,
        "# qmckit pixel {} {w}x{h} pixel {x},{y} spp {spp} dim {}: index v1 x y",
        args.sampler.name, args.dim
    )?;
    for i in 0..spp {
        let start = PixelSampler::start_pixel_sample(&sampler, x, y, i)?.with_dimension(args.dim);
        let index = match start.sample_index() {
            Some(k) => k.to_string(),
            None => "-".to_string(),
        };
        let (mut one, mut two) = (start, start); // both with the counter at D
        let v = one.get_1d();
        let [a, b] = two.get_2d();
        // pbrt's floats, from the sampler (Halton's and Stratified's are float arithmetic).
        let (mut one, mut two) = (start, start);
        let (fv, [fa, fb]) = (one.get_1d_f32(), two.get_2d_f32());
        match args.format {
            PixelFormat::Decimal => {
                use qmckit::bits::to_f64;
                writeln!(out, "{index} {} {} {}", to_f64(v), to_f64(a), to_f64(b))?
            }
            PixelFormat::U32 => writeln!(out, "{index} {v} {a} {b}")?,
            PixelFormat::Csv => writeln!(out, "{index},{fv},{fa},{fb}")?,
        }
    }
    out.flush()?;
    Ok(())
}
