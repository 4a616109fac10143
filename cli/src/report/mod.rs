//! `qmckit report --out DIR [--quick]`: the lecture "Monte Carlo 2" regenerated from the
//! crate: `DIR/index.html`, one `<section id=...>` per slide, each with its figures and the
//! numbers measured in this run beside the lecture's own (labelled "lecture").
//!
//! The slide groups live in one file each: [`constructions`] (radical inverse to Owen
//! scrambling, warps), [`discrepancy`] (D*, the Koksma–Hlawka bound, measured error),
//! [`nets`] (elementary intervals, (0,2)-sequences, blue-noise Sobol'), [`spectra`]
//! (dithering, spectra, variance), `scenes` (the rendered studies) and [`benchmark`] (the
//! integration benchmark of random Gaussians and Heavisides, beyond the lecture).

mod benchmark;
mod claims;
mod constructions;
mod discrepancy;
mod html;
mod nets;
mod scenes;
mod spectra;

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use crate::plot::{Figure, Format, render};
use clap::Args;
use qmckit::work::Budget;

use super::Failure;
use super::budget::BudgetArgs;
use super::progress::with_progress;

/// Text shown after the options of `qmckit report --help`.
pub const AFTER_HELP: &str = "\
Writes DIR/index.html and its figures (SVG for plots, PNG for images and spectra): one
section per slide of the lecture 'Monte Carlo 2' (radical inverse, van der Corput, Halton,
Hammersley, permuted and Owen-scrambled radical inverses, discrepancy of three point sets,
the Koksma-Hlawka bound, measured QMC error, elementary intervals, (0,2)-sequences,
rendered MSE studies, blue-noise dithering, spectra, variance), and the integration
benchmark (random Gaussians and Heavisides). Every number is computed in
the run; the lecture's own numbers stand beside ours, labelled 'lecture', with a sentence
where they differ.

--quick uses fewer points and seeds (under a minute on 2 cores); the full report takes a
few minutes. Each super-linear step (discrepancies, spectra, masks, blue noise) checks its
estimated time against --max-seconds (default 600), and one deadline, 1.25 times it from
the start, bounds the whole report: past it the report stops with one line and writes
nothing. A progress bar shows on a terminal. Errors: one
line; exit code 1 for an unwritable DIR.";

/// Arguments of `qmckit report`.
#[derive(Args, Debug)]
pub struct ReportArgs {
    /// Output directory (created if missing).
    #[arg(long, short = 'o', value_name = "DIR")]
    pub out: String,
    /// Smaller sizes and fewer seeds: under a minute.
    #[arg(long)]
    pub quick: bool,
    /// Write every figure as PNG (plots too), e.g. to embed them where SVG is not shown.
    #[arg(long)]
    pub png: bool,
    /// The time budget of the whole report: each super-linear step is refused past it, and
    /// the report stops (one line, nothing written) at 1.25 times it ('inf': no limit).
    #[arg(long, default_value_t = REPORT_SECONDS, value_name = "SECONDS")]
    pub max_seconds: f64,
}

/// The default budget of the whole report: ten minutes (the full report takes a few on two
/// idle cores, the quick one under a minute).
pub const REPORT_SECONDS: f64 = 600.0;

/// One measured number beside the lecture's.
pub struct Row {
    /// What is measured.
    pub what: String,
    /// Our value, as text.
    pub ours: String,
    /// The lecture's value (empty where the slide shows only a picture).
    pub lecture: String,
}

/// Builds a [`Row`].
pub fn row(what: impl Into<String>, ours: impl Into<String>, lecture: impl Into<String>) -> Row {
    Row {
        what: what.into(),
        ours: ours.into(),
        lecture: lecture.into(),
    }
}

/// A figure file and its caption.
pub struct Fig {
    /// The file name inside DIR.
    pub file: String,
    /// The caption.
    pub caption: String,
}

/// One slide.
pub struct Section {
    /// The `id` of the `<section>`.
    pub id: &'static str,
    /// The slide's title.
    pub title: String,
    /// What was computed, one paragraph.
    pub text: String,
    /// The figures.
    pub figures: Vec<Fig>,
    /// The numbers.
    pub rows: Vec<Row>,
    /// Why our numbers differ from the lecture's, if they do.
    pub note: String,
}

impl Section {
    /// An empty section.
    pub fn new(id: &'static str, title: &str, text: impl Into<String>) -> Self {
        Section {
            id,
            title: title.to_owned(),
            text: text.into(),
            figures: Vec::new(),
            rows: Vec::new(),
            note: String::new(),
        }
    }
}

/// What every slide builder gets: where to write, how big, and the budget.
pub struct Ctx {
    /// The output directory.
    pub dir: PathBuf,
    /// `--quick`.
    pub quick: bool,
    /// The time budget of each super-linear step.
    pub budget: Budget,
    /// `--png`: plots as PNG too.
    pub png: bool,
    /// Files written so far (for the summary).
    written: Mutex<Vec<String>>,
}

impl Ctx {
    /// `quick` or `full`, by the run's size.
    pub fn pick<T>(&self, quick: T, full: T) -> T {
        if self.quick { quick } else { full }
    }

    /// The exact star discrepancy of 2D points, refused past the budget (`star_cost`).
    pub fn star(&self, p: &[[f64; 2]]) -> Result<f64, Failure> {
        let data = flat(p);
        let points = qmckit::analysis::Points::new(&data, 2)?;
        Ok(qmckit::analysis::star::star_exact(points, &self.budget)?)
    }

    /// Renders `fig` into `DIR/name` (format from the extension) and returns its [`Fig`].
    pub fn figure<F: Figure>(
        &self,
        name: &str,
        fig: &F,
        size: (u32, u32),
        caption: impl Into<String>,
    ) -> Result<Fig, Failure> {
        let png_name;
        let name = match name.strip_suffix(".svg") {
            Some(stem) if self.png => {
                png_name = format!("{stem}.png");
                png_name.as_str()
            }
            _ => name,
        };
        let format = Format::from_path(name).map_err(|e| Failure::usage(e.0))?;
        let bytes = render(fig, format, size.0, size.1)
            .map_err(|e| Failure::usage(format!("figure {name}: {e}")))?;
        write(&self.dir.join(name), &bytes)?;
        if let Ok(mut w) = self.written.lock() {
            w.push(name.to_owned());
        }
        Ok(Fig {
            file: name.to_owned(),
            caption: caption.into(),
        })
    }
}

/// Writes a file; a failure is the environment's (exit code 1).
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    std::fs::write(path, bytes).map_err(|e| Failure {
        code: 1,
        message: format!("{}: {e}", path.display()),
    })
}

/// Formats a number with `digits` significant digits.
pub fn sig(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let mag = x.abs().log10().floor() as i32;
    if (-3..5).contains(&mag) {
        let decimals = (digits as i32 - 1 - mag).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.prec$e}", prec = digits.saturating_sub(1))
    }
}

/// The quantile of `|error|` that [`error_scale`] maps to full colour.
pub const ERROR_QUANTILE: f64 = 0.99;

/// The colour scale of error images shown side by side: the [`ERROR_QUANTILE`] quantile of
/// `|error|` over all their finite pixels, so the bulk of the error shows in colour and only
/// the largest 1% saturate (the largest value alone leaves almost every pixel white when a
/// few pixels, e.g. on edges, err by much more). Falls back to the largest `|error|` when
/// the quantile is zero, and is at least `1e-12`.
pub fn error_scale<'a>(images: impl IntoIterator<Item = &'a [f64]>) -> f64 {
    let mut all: Vec<f64> = images
        .into_iter()
        .flatten()
        .map(|v| v.abs())
        .filter(|v| v.is_finite())
        .collect();
    if all.is_empty() {
        return 1e-12;
    }
    let largest = all.iter().copied().fold(0.0, f64::max);
    let k = ((all.len() - 1) as f64 * ERROR_QUANTILE).round() as usize;
    let (_, q, _) = all.select_nth_unstable_by(k, f64::total_cmp);
    let q = if *q > 0.0 { *q } else { largest };
    q.max(1e-12)
}

/// The caption of error image `name` drawn at `±scale` among `count` compared images.
pub fn error_caption(name: &str, scale: f64, count: usize) -> String {
    format!(
        "error, {name}: colour scale ±{}, the {}th percentile of |error| over the {count} \
         images compared (larger errors saturate)",
        sig(scale, 2),
        (ERROR_QUANTILE * 100.0).round()
    )
}

/// A slide group's builder.
type Builder = fn(&Ctx) -> Result<Vec<Section>, Failure>;

/// The slide groups, in the lecture's order.
const GROUPS: [(&str, Builder); 7] = [
    ("warps and constructions", constructions::sections),
    ("discrepancy and error", discrepancy::sections),
    ("nets", nets::sections),
    ("rendered studies", scenes::sections),
    ("spectra", spectra::sections),
    ("variance", spectra::variance_sections),
    ("integration benchmark", benchmark::sections),
];

/// Runs `qmckit report`.
pub fn run(args: &ReportArgs) -> Result<(), Failure> {
    let budget = BudgetArgs {
        max_seconds: args.max_seconds,
    }
    .budget()?;
    // Assembled out of sight and moved into place at the end: a failed or stopped report
    // leaves the user's files (and an earlier report) as they were.
    let staged = super::atomic::StagedDir::new("--out", &PathBuf::from(&args.out))?;
    let ctx = Ctx {
        dir: staged.path().to_path_buf(),
        quick: args.quick,
        budget,
        png: args.png,
        written: Mutex::new(Vec::new()),
    };
    let started = std::time::Instant::now();
    let sections = with_progress("report", |progress| {
        let mut all = Vec::new();
        for (k, (_, build)) in GROUPS.iter().enumerate() {
            // One deadline for the whole report: each group's loops read it too.
            ctx.budget.check_deadline("the report")?;
            progress(k, GROUPS.len());
            all.extend(build(&ctx)?);
        }
        progress(GROUPS.len(), GROUPS.len());
        Ok::<_, Failure>(all)
    })?;
    let files = ctx.written.lock().map(|w| w.len()).unwrap_or(0);
    let page = html::page(
        &sections,
        files,
        args.quick,
        started.elapsed().as_secs_f64(),
    );
    write(&ctx.dir.join("index.html"), page.as_bytes())?;
    staged.commit()
}

/// The first `n` points of `s` in the dimensions `dims`, as reals.
pub fn pts2<S: qmckit::Sampler + ?Sized>(
    s: &S,
    n: u32,
    dims: (usize, usize),
) -> Result<Vec<[f64; 2]>, Failure> {
    (0..n)
        .map(|i| {
            Ok([
                qmckit::bits::to_f64(s.sample(i, dims.0)?),
                qmckit::bits::to_f64(s.sample(i, dims.1)?),
            ])
        })
        .collect()
}

/// Points as the flat row-major slice the analysis functions read.
pub fn flat(p: &[[f64; 2]]) -> Vec<f64> {
    p.iter().flat_map(|q| [q[0], q[1]]).collect()
}

/// Size of a point or curve figure (SVG).
pub const PLOT: (u32, u32) = (420, 420);
/// Size of a wide curve figure.
pub const WIDE: (u32, u32) = (560, 420);

#[cfg(test)]
mod tests {
    use super::{error_caption, error_scale};

    #[test]
    fn error_scale_is_a_robust_top_shared_by_the_images() {
        // 990 pixels err by 0.01 or less, 10 edge pixels by 1: the scale is the bulk's, not
        // the edges' (which would leave the bulk at 1% of full colour).
        let bulk: Vec<f64> = (0..990).map(|i| 0.01 * (i % 2) as f64 - 0.005).collect();
        let edges = [1.0; 10];
        let m = error_scale([&bulk[..], &edges[..]]);
        assert_eq!(m, 0.005);
        // The same scale whichever image holds the edges.
        assert_eq!(error_scale([&edges[..], &bulk[..]]), m);
        // All zero but a few: the largest; all zero or nothing: a tiny positive scale.
        let mut sparse = vec![0.0; 1000];
        sparse[3] = -0.25;
        assert_eq!(error_scale([&sparse[..]]), 0.25);
        assert_eq!(error_scale([&[0.0, f64::NAN][..]]), 1e-12);
        assert_eq!(error_scale(std::iter::empty::<&[f64]>()), 1e-12);
        let c = error_caption("ZSobol", 0.0123, 3);
        assert!(c.contains("±0.012") && c.contains("99th percentile") && c.contains("3 images"));
    }
}
