//! `qmckit spectrum [--k-max K] [--radial] [--average] [--method auto|direct|nufft]
//! [--tolerance E] [FILE|-]`: the Fourier power spectrum of 2D point sets read from text.

use std::io::{BufWriter, Write};

use clap::{Args, ValueEnum};
use qmckit::analysis::spectrum::{
    DEFAULT_TOLERANCE, Method, NUFFT_MIN_TOLERANCE, SPECTRUM_MAX_K, Spectrum, SpectrumMean,
    choose_method, estimated_cost, periodogram_2d, spectrum_2d,
};
use qmckit::work::Budget;

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

--average prints one block: the mean periodogram (or its radial average) over all the
point sets of the input, each normalized by its own size (sets may differ in size, as
Poisson-disk sets by count do; P(0) is then the mean size).

--method: 'direct' sums exactly (up to rounding), at N (K + 1)(2K + 1) complex
multiply-adds, about 1e9 a second; 'nufft' (type-1 non-uniform FFT, exponential-of-
semicircle kernel) is within --tolerance E times N (= P(0), the largest value) of it, at
about N w^2 + n^2 log2(n) with n ~ 4K and w ~ log10(1/E); 'auto' (the default) takes the
faster by estimate (the NUFFT from about K = 32 at N = 4096). E in [1e-14, 0.1], default
1e-9.

Values in scientific notation with 17 significant digits; with several point sets, each
block is preceded by a '# set K' line. Refused when the estimated time (of all sets, with
--average) exceeds --max-seconds (default 10: by direct sums, K = 64 admits 1.2 million
points); K at most 2048. Errors: 'qmckit: error: FILE: reason', exit code 2.";

/// `--method`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// The faster of the two by estimate.
    Auto,
    /// Direct sums (exact up to rounding).
    Direct,
    /// The non-uniform FFT (within --tolerance).
    Nufft,
}

/// Arguments of `qmckit spectrum`.
#[derive(Args, Debug)]
pub struct SpectrumArgs {
    /// Largest frequency along each axis: the periodogram covers [-K, K]^2.
    #[arg(long, default_value_t = 32, value_name = "K")]
    k_max: usize,
    /// Print the radial average and anisotropy instead of the periodogram.
    #[arg(long)]
    radial: bool,
    /// Print the mean over all point sets (one block) instead of one block a set.
    #[arg(long)]
    average: bool,
    /// How to compute the sums.
    #[arg(long, value_enum, default_value_t = MethodArg::Auto, value_name = "METHOD")]
    method: MethodArg,
    /// NUFFT accuracy: |P - P_exact| <= E * N.
    #[arg(long, default_value_t = DEFAULT_TOLERANCE, value_name = "E")]
    tolerance: f64,
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
    if !(NUFFT_MIN_TOLERANCE..=0.1).contains(&args.tolerance) {
        return Err(Failure::usage(format!(
            "--tolerance {}: must lie in [1e-14, 0.1]",
            args.tolerance
        )));
    }
    let (name, sets) = read_point_sets(&args.input)?;
    let methods: Vec<Method> = sets
        .iter()
        .map(|set| match args.method {
            MethodArg::Auto => choose_method(set.len(), args.k_max, args.tolerance),
            MethodArg::Direct => Method::Direct,
            MethodArg::Nufft => Method::Nufft,
        })
        .collect();
    if args.average {
        let total = sets
            .iter()
            .zip(&methods)
            .map(|(s, &m)| estimated_cost(s.len(), args.k_max, m, args.tolerance).seconds())
            .sum::<f64>();
        if total > budget.max_seconds() {
            return Err(Failure::usage(format!(
                "{name}: the spectra of {} sets: estimated {total:.3} s, more than \
                 --max-seconds {} (raise it to run them)",
                sets.len(),
                args.budget.max_seconds
            )));
        }
    }
    let mut out = BufWriter::new(std::io::stdout().lock());
    let mut mean = SpectrumMean::new();
    for (k, (set, &method)) in sets.iter().zip(&methods).enumerate() {
        let which = set_label(k, sets.len());
        let fail = |reason: String| Failure::usage(format!("{name}: {which}{reason}"));
        if set.dims != 2 {
            return Err(fail(format!(
                "the spectrum needs 2-dimensional points, not {}",
                set.dims
            )));
        }
        let p = set.points().map_err(|e| fail(e.to_string()))?;
        let s = with_spinner("spectrum", || compute(p, args, method, &budget)).map_err(|e| {
            fail(match e {
                qmckit::Error::TooManyPoints { max, .. } => format!(
                    "{} points are too many for --k-max {} (at most {max} within \
                     --max-seconds {}); estimated {:.3} s",
                    set.len(),
                    args.k_max,
                    args.budget.max_seconds,
                    estimated_cost(set.len(), args.k_max, Method::Direct, args.tolerance).seconds()
                ),
                other => super::budget::over_budget(other),
            })
        })?;
        if args.average {
            mean.add(&s).map_err(|e| fail(e.to_string()))?;
            continue;
        }
        if sets.len() > 1 {
            writeln!(out, "# set {}", k + 1)?;
        }
        write_spectrum(&mut out, &s, args.radial)?;
    }
    if args.average {
        writeln!(out, "# mean of {} sets", mean.sets())?;
        write_spectrum(&mut out, &mean.mean()?, args.radial)?;
    }
    out.flush()?;
    Ok(())
}

/// One periodogram by `method` (direct sums through [`spectrum_2d`], whose refusal
/// names the most points the budget admits).
fn compute(
    p: qmckit::analysis::Points<'_>,
    args: &SpectrumArgs,
    method: Method,
    budget: &Budget,
) -> qmckit::Result<Spectrum> {
    match method {
        Method::Direct => spectrum_2d(p, args.k_max, budget),
        m => periodogram_2d(p, args.k_max, m, args.tolerance, budget),
    }
}

/// The periodogram lines, or the radial lines.
fn write_spectrum(out: &mut impl Write, s: &Spectrum, radial: bool) -> std::io::Result<()> {
    if radial {
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
    Ok(())
}
