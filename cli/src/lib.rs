//! The `qmckit` command: generate and judge sampling patterns.
//!
//! Errors go to stderr as one line, `qmckit: error: ...`, with exit code 2 for bad usage or
//! input and 1 for failures of the environment (e.g. an unwritable output).
//!
//! The binary is [`threads`] then [`run_cli`]; the tests and fuzz targets call [`run_cli`]
//! in-process. Beside the commands, this library holds what only the command draws and
//! renders: [`plot`] (figures as SVG or PNG) and [`scene`] (the analytic render studies).
#![deny(unsafe_code)]
#![warn(missing_docs)]

mod atomic;
mod blue_noise;
mod budget;
mod convergence;
mod discrepancy;
mod input;
mod integration_test;
mod mask;
mod names;
mod output;
mod pcf;
mod pixel;
pub mod plot;
mod plot_command;
mod points;
mod progress;
mod report;
pub mod scene;
mod spectrum;
mod toolbox;
mod tvalue;
mod variance;
mod warp;

use std::io::Write;

use clap::{Parser, Subcommand};

/// Quasi-Monte Carlo sampling patterns: low-discrepancy sequences and nets.
#[derive(Parser, Debug)]
#[command(name = "qmckit", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Write N points of a sampler, one point per line (natural order: line k is index start+k).
    #[command(after_help = points::AFTER_HELP)]
    Points(Box<points::PointsArgs>),
    /// Discrepancies of point sets read from a text file or stdin: 'metric value' lines.
    #[command(after_help = discrepancy::AFTER_HELP)]
    Discrepancy(discrepancy::DiscrepancyArgs),
    /// Integration error of a sampler on a test integrand against the number of points.
    #[command(after_help = convergence::AFTER_HELP)]
    Convergence(convergence::ConvergenceArgs),
    /// The integration benchmark: samplers against thousands of random integrands, RMSE and rate.
    #[command(after_help = integration_test::AFTER_HELP)]
    IntegrationTest(integration_test::IntegrationTestArgs),
    /// Fourier power spectrum (periodogram) of 2D point sets read from a file or stdin.
    #[command(after_help = spectrum::AFTER_HELP)]
    Spectrum(spectrum::SpectrumArgs),
    /// Pair correlation function of 2D point sets read from a file or stdin.
    #[command(after_help = pcf::AFTER_HELP)]
    Pcf(pcf::PcfArgs),
    /// The t-value of the first 2^m points of a base-2 net or sequence.
    #[command(after_help = tvalue::AFTER_HELP)]
    Tvalue(tvalue::TvalueArgs),
    /// Integration variance of a torus-shifted sampler: predicted from its spectrum, and measured.
    #[command(after_help = variance::AFTER_HELP)]
    Variance(variance::VarianceArgs),
    /// Dither masks: 'mask void-and-cluster --size WxH', a toroidal rank image.
    #[command(subcommand)]
    Mask(mask::MaskCommand),
    /// The samples of one pixel from a renderer's pixel sampler (pbrt-v4 compatible).
    #[command(after_help = pixel::AFTER_HELP)]
    Pixel(pixel::PixelArgs),
    /// A figure (SVG or PNG) of a point file, a spectrum, a convergence table or an image.
    #[command(after_help = plot_command::AFTER_HELP)]
    Plot(plot_command::PlotArgs),
    /// The lecture's figures and tables regenerated: DIR/index.html and its figures.
    #[command(after_help = report::AFTER_HELP)]
    Report(report::ReportArgs),
}

/// A failure to report: one line and an exit code.
#[derive(Debug)]
pub struct Failure {
    /// 2: bad usage or input; 1: the environment failed.
    pub code: u8,
    /// One line, no trailing newline.
    pub message: String,
}

impl Failure {
    /// Bad usage or input (exit code 2).
    pub fn usage(message: impl Into<String>) -> Self {
        Failure {
            code: 2,
            message: message.into(),
        }
    }
}

impl From<qmckit::Error> for Failure {
    fn from(e: qmckit::Error) -> Self {
        Failure::usage(budget::over_budget(e))
    }
}

impl From<std::io::Error> for Failure {
    fn from(e: std::io::Error) -> Self {
        Failure {
            code: 1,
            message: format!("write failed: {e}"),
        }
    }
}

/// clap's multi-line error report folded into one line.
fn one_line(err: &clap::Error) -> String {
    let text = err.render().to_string();
    let parts: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("Usage:") && !l.starts_with("For more"))
        .map(|l| l.strip_prefix("error: ").unwrap_or(l))
        .collect();
    parts.join(" ")
}

/// Writes `qmckit: error: MESSAGE` on stderr, ignoring a stderr that cannot be written (a
/// full disk, a closed descriptor): the exit code still tells.
fn report(message: &str) {
    let _ = writeln!(
        std::io::stderr().lock(),
        "qmckit: error: {}",
        one_line_text(message)
    );
}

/// `message` on one line: the one-line rule is kept here, where every error leaves, so a
/// multi-line text from a dependency (a parser's report) cannot break it. Line breaks and
/// other control characters become single spaces.
fn one_line_text(message: &str) -> String {
    message
        .split(|c: char| c.is_control())
        .map(str::trim)
        .filter(|part| !part.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}

/// The most worker threads a core that `RAYON_NUM_THREADS` may ask for (at least 256 in all).
pub const MAX_THREADS_PER_CORE: usize = 64;

/// Installs the interruption handler of the command: on SIGINT, SIGTERM or SIGHUP the
/// temporary outputs in progress (a figure's temporary file, the report's staging
/// directory) are removed, one line is printed and the process exits with status 130.
/// The binary calls it first; tests that run the command in process do not.
pub fn on_termination() {
    atomic::on_termination();
}

/// Builds the global worker pool before any command starts, so that a `RAYON_NUM_THREADS`
/// the system cannot honour (more threads than its memory or limits allow) is a one-line
/// note and a working run with the default number of threads, not a panic inside the first
/// parallel loop. The count is tried on a private pool first, because a failed global build
/// cannot be retried; a count past [`MAX_THREADS_PER_CORE`] threads a core is not tried at
/// all (thousands of threads can exhaust memory inside the runtime, beyond any recovery).
pub fn threads() {
    let works = |n: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .is_ok()
    };
    let requested = std::env::var("RAYON_NUM_THREADS").ok();
    let default = std::thread::available_parallelism().map_or(1, |n| n.get());
    let wanted = match requested.as_deref().map(str::trim).map(str::parse::<usize>) {
        Some(Ok(n)) if n > 0 => n,
        _ => default,
    };
    let ceiling = default.saturating_mul(MAX_THREADS_PER_CORE).max(256);
    let used = [wanted, default, 1]
        .into_iter()
        .find(|&n| n <= ceiling && works(n))
        .unwrap_or(1);
    let global = rayon::ThreadPoolBuilder::new()
        .num_threads(used)
        .build_global();
    if used != wanted || global.is_err() {
        let _ = writeln!(
            std::io::stderr().lock(),
            "qmckit: note: could not start {wanted} worker threads (RAYON_NUM_THREADS={}); \
             using {used}",
            requested.unwrap_or_default()
        );
    }
}

/// Runs the command line `args` (the program name first) and returns the exit code: 0,
/// 1 (the environment failed) or 2 (bad usage or input, one line on stderr).
pub fn run_cli<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(err) => {
            use clap::error::ErrorKind;
            if matches!(
                err.kind(),
                ErrorKind::DisplayHelp | ErrorKind::DisplayVersion
            ) {
                let _ = err.print();
                return 0;
            }
            if err.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                report(
                    "a command is needed: points, pixel, discrepancy, tvalue, convergence, \
                     integration-test, spectrum, pcf, variance, mask, plot or report (see 'qmckit --help')",
                );
                return 2;
            }
            report(&one_line(&err));
            return 2;
        }
    };
    let result = match cli.command {
        Command::Points(args) => points::run(&args),
        Command::Discrepancy(args) => discrepancy::run(&args),
        Command::Convergence(args) => convergence::run(&args),
        Command::IntegrationTest(args) => integration_test::run(&args),
        Command::Spectrum(args) => spectrum::run(&args),
        Command::Pcf(args) => pcf::run(&args),
        Command::Tvalue(args) => tvalue::run(&args),
        Command::Variance(args) => variance::run(&args),
        Command::Mask(args) => mask::run(&args),
        Command::Pixel(args) => pixel::run(&args),
        Command::Plot(args) => plot_command::run(&args),
        Command::Report(args) => report::run(&args),
    };
    match result {
        Ok(()) => 0,
        Err(f) if f.code == 1 && f.message.contains("Broken pipe") => 0,
        Err(f) => {
            let _ = std::io::stdout().flush();
            report(&f.message);
            f.code
        }
    }
}

impl From<qmckit::catalog::CatalogError> for Failure {
    fn from(e: qmckit::catalog::CatalogError) -> Self {
        match e {
            qmckit::catalog::CatalogError::Build(e) => Failure::from(e),
            other => Failure::usage(names::flag_text(&other)),
        }
    }
}
