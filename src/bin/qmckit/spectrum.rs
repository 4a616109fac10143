//! `qmckit spectrum [--k-max K] [--radial] [FILE|-]`: the Fourier power spectrum of 2D point
//! sets read from text.

use std::io::{BufWriter, Write};

use clap::Args;
use qmckit::analysis::spectrum::{SPECTRUM_MAX_K, spectrum_2d_within};

use super::Failure;
use super::budget::BudgetArgs;
use super::input::{InputArgs, read_point_sets, set_label};
use super::progress::with_spinner;

/// Text shown after the options of `qmckit spectrum --help`.
pub const AFTER_HELP: &str = "\
Input: as for 'qmckit discrepancy': one 2D point a line, coordinates in [0, 1] separated by
spaces/tabs or by single commas; '#' starts a comment; a line holding only '#' separates
point sets.

Output: the periodogram P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / N at every integer frequency
k = (kx, ky) in [-K, K]^2, one 'kx ky P' line each (ky, then kx, ascending), after a
'# kx ky power' header. P(0, 0) = N; white noise (independent uniform points) has P about 1
everywhere else, blue noise near 0 at low |k|.

--radial prints the radial average instead: 'radius count mean anisotropy' lines for
r = 1..K, over the frequencies with round(|k|) = r; anisotropy = variance / mean^2 over the
annulus (1 for white noise; 10 log10 of it is Ulichney's anisotropy in dB).

Values in scientific notation with 17 significant digits; with several point sets, each
block is preceded by a '# set K' line. Cost N (K + 1)(2K + 1) complex multiply-adds at
about 1e9 a second, refused when that exceeds --max-seconds (default 10: K = 64 admits 1.2
million points); K at most 2048. Errors:
'qmckit: error: FILE: reason', exit code 2.";

/// Arguments of `qmckit spectrum`.
#[derive(Args, Debug)]
pub struct SpectrumArgs {
    /// Largest frequency along each axis: the periodogram covers [-K, K]^2.
    #[arg(long, default_value_t = 32, value_name = "K")]
    k_max: usize,
    /// Print the radial average and anisotropy instead of the periodogram.
    #[arg(long)]
    radial: bool,
    #[command(flatten)]
    budget: BudgetArgs,
    #[command(flatten)]
    input: InputArgs,
}

/// Runs `qmckit spectrum`.
pub fn run(args: &SpectrumArgs) -> Result<(), Failure> {
    let budget = args.budget.budget()?;
    if args.k_max > SPECTRUM_MAX_K {
        return Err(Failure::usage(format!(
            "--k-max {}: at most {SPECTRUM_MAX_K}",
            args.k_max
        )));
    }
    let (name, sets) = read_point_sets(&args.input)?;
    let mut out = BufWriter::new(std::io::stdout().lock());
    for (k, set) in sets.iter().enumerate() {
        let which = set_label(k, sets.len());
        let fail = |reason: String| Failure::usage(format!("{name}: {which}{reason}"));
        if set.dims != 2 {
            return Err(fail(format!(
                "the spectrum needs 2-dimensional points, not {}",
                set.dims
            )));
        }
        let p = set.points().map_err(|e| fail(e.to_string()))?;
        let s = with_spinner("spectrum", || spectrum_2d_within(p, args.k_max, &budget)).map_err(
            |e| {
                fail(match e {
                    qmckit::Error::TooManyPoints { max, .. } => format!(
                        "{} points are too many for --k-max {} (at most {max} within \
                     --max-seconds {})",
                        set.len(),
                        args.k_max,
                        args.budget.max_seconds
                    ),
                    other => other.to_string(),
                })
            },
        )?;
        if sets.len() > 1 {
            writeln!(out, "# set {}", k + 1)?;
        }
        if args.radial {
            writeln!(out, "# radius count mean anisotropy")?;
            for b in s.radial() {
                writeln!(
                    out,
                    "{} {} {:.16e} {:.16e}",
                    b.radius, b.count, b.mean, b.anisotropy
                )?;
            }
        } else {
            writeln!(out, "# kx ky power")?;
            for (kx, ky, power) in s.iter() {
                writeln!(out, "{kx} {ky} {power:.16e}")?;
            }
        }
    }
    out.flush()?;
    Ok(())
}
