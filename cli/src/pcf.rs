//! `qmckit pcf [--torus] [--r-max R] [--bins B] [--sigma S] [--average] [FILE|-]`: the pair
//! correlation function of 2D point sets read from text.

use std::io::{BufWriter, Write};

use clap::Args;
use qmckit::analysis::pcf::{PcfBin, PcfOptions, pcf_2d, pcf_cost};

use super::Failure;
use super::budget::BudgetArgs;
use super::input::{InputArgs, read_point_sets, set_label};
use super::progress::with_spinner;

/// Text shown after the options of `qmckit pcf --help`.
pub const AFTER_HELP: &str = "\
Input: as for 'qmckit spectrum' (2D points; '#' lines separate sets).

Output: 'radius g' lines after a '# radius g' header, at the B bin centres
r = R (b + 1/2) / B, of the pair correlation function (UTK's definition)
  g(r) = sum_{i != j} k(r - |x_i - x_j|) / (N (N - 1) 2 pi r e(r)),
k the Gaussian of standard deviation --sigma (default the bin width R / B), e(r) =
1 - 4r/pi + r^2/pi the unit square's edge correction, or 1 with --torus (nearest-image
distances; R at most 0.5). g = 1 for independent uniform points, 0 below the minimum
distance of a Poisson-disk set. With several sets, a '# set K' line before each block;
--average prints their mean only. Values with 17 significant digits. Cost about N^2 / 2
distances plus kernel values for the close pairs, refused past --max-seconds. Errors:
one line, exit code 2.";

/// Arguments of `qmckit pcf`.
#[derive(Args, Debug)]
pub struct PcfArgs {
    /// Toroidal (nearest-image) distances, no edge correction.
    #[arg(long)]
    torus: bool,
    /// Largest radius R.
    #[arg(long, default_value_t = 0.15, value_name = "R")]
    r_max: f64,
    /// Number of bins B.
    #[arg(long, default_value_t = 200, value_name = "B")]
    bins: usize,
    /// Kernel standard deviation [default: R / B].
    #[arg(long, value_name = "S")]
    sigma: Option<f64>,
    /// Print the mean over all point sets instead of one block a set.
    #[arg(long)]
    average: bool,
    #[command(flatten)]
    budget: BudgetArgs,
    #[command(flatten)]
    input: InputArgs,
}

/// Runs `qmckit pcf`.
pub fn run(args: &PcfArgs) -> Result<(), Failure> {
    let budget = args.budget.budget()?;
    let mut opts = PcfOptions::new(args.r_max, args.bins, args.torus);
    if let Some(s) = args.sigma {
        opts.sigma = s;
    }
    let limit = if args.torus { 0.5 } else { 1.0 };
    if !(args.r_max > 0.0 && args.r_max <= limit) {
        return Err(Failure::usage(format!(
            "--r-max {}: must lie in (0, {limit}]{}",
            args.r_max,
            if args.torus { " with --torus" } else { "" }
        )));
    }
    if args.bins == 0 || args.bins > 1_000_000 {
        return Err(Failure::usage(format!(
            "--bins {}: must lie in 1..=1000000",
            args.bins
        )));
    }
    if let Err(e) = opts.validate() {
        return Err(Failure::usage(match args.sigma {
            Some(s) if s != 0.0 && !(1e-4..1e15).contains(&s.abs()) => {
                format!("--sigma {s:e}: {e}")
            }
            Some(s) => format!("--sigma {s}: {e}"),
            None => format!("--r-max {} --bins {}: {e}", args.r_max, args.bins),
        }));
    }
    let (name, sets) = read_point_sets(&args.input)?;
    let total: f64 = sets
        .iter()
        .map(|s| pcf_cost(s.len(), &opts).seconds())
        .sum();
    if total > budget.max_seconds() {
        return Err(Failure::usage(format!(
            "{name}: the pair correlation of {} set(s): estimated {total:.3} s, more than \
             --max-seconds {} (raise it to run it)",
            sets.len(),
            args.budget.max_seconds
        )));
    }
    let mut out = BufWriter::new(std::io::stdout().lock());
    let mut sum: Vec<PcfBin> = Vec::new();
    for (k, set) in sets.iter().enumerate() {
        let which = set_label(k, sets.len());
        let fail = |reason: String| Failure::usage(format!("{name}: {which}{reason}"));
        if set.dims != 2 {
            return Err(fail(format!(
                "the pair correlation needs 2-dimensional points, not {}",
                set.dims
            )));
        }
        let p = set.points().map_err(|e| fail(e.to_string()))?;
        let g = with_spinner("pcf", || pcf_2d(p, &opts, &budget))
            .map_err(|e| fail(super::budget::over_budget(e)))?;
        if args.average {
            if sum.is_empty() {
                sum = g;
            } else {
                for (a, b) in sum.iter_mut().zip(&g) {
                    a.g += b.g;
                }
            }
            continue;
        }
        if sets.len() > 1 {
            writeln!(out, "# set {}", k + 1)?;
        }
        write_bins(&mut out, &g, 1.0)?;
    }
    if args.average {
        writeln!(out, "# mean of {} sets", sets.len())?;
        write_bins(&mut out, &sum, 1.0 / sets.len().max(1) as f64)?;
    }
    out.flush()?;
    Ok(())
}

/// The `radius g` lines, `g` scaled by `scale`.
fn write_bins(out: &mut impl Write, g: &[PcfBin], scale: f64) -> std::io::Result<()> {
    writeln!(out, "# radius g")?;
    for b in g {
        writeln!(out, "{:.16e} {:.16e}", b.radius, b.g * scale)?;
    }
    Ok(())
}
