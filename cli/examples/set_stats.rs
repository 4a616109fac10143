//! The summary statistics of the point sets in one file, for comparing samplers of two
//! programs with one code path (`scripts/utk_compare.sh`): every file is parsed by
//! `qmckit::analysis::pointfile` (the parser of `qmckit discrepancy` and `qmckit spectrum`)
//! and measured by the library functions those commands call.
//!
//! Per set of `N` points in `d` dimensions (the spectra only in 2D, else `NaN`):
//! - `star`: the exact star discrepancy `D*_N` ([`qmckit::analysis::star::star_exact`]);
//! - `nn`: the mean distance from a point to its nearest neighbour in the unit cube
//!   ([`qmckit::analysis::distance::mean_min_distance`]), reported as `nn N^(1/d)`, so that
//!   sets of slightly different sizes (Poisson disk) compare; the hexagonal grid has
//!   `sqrt(2 / sqrt 3) = 1.0746`, independent uniform points about `1/2` (for large N,
//!   `1 / (2 sqrt N)` is the nearest-neighbour mean of a Poisson process);
//! - `low`: the mean of the radial power spectrum over the annuli `1 <= r <= sqrt(N) / 2`
//!   ([`qmckit::analysis::spectrum::periodogram_2d`], then `radial`): the low-frequency
//!   band, 1 for white noise, near 0 for blue noise;
//! - `mid`: the same over `sqrt(N) / 2 < r <= sqrt(N)` (where a blue-noise peak sits).
//!
//! Output: one line per file, `file sets n star star_se nn nn_se low low_se mid mid_se`,
//! means over the sets and their standard errors (`sd / sqrt(sets)`).
//!
//! Cost: per set `O(N^2)` for the 2D star sweep (1024 points: about a millisecond;
//! `O(N^(1 + d/2))` in `d` dimensions), the spectrum by direct sums or NUFFT at
//! `K = sqrt(N)`, and the nearest neighbours by a grid.
//! Files are refused above `qmckit::size::MAX_ALLOC_BYTES` (1 GiB) before they are read.
//!
//! `cargo run --release -p qmckit-cli --example set_stats -- FILE...`

use std::process::ExitCode;

use qmckit::analysis::{
    Points,
    distance::mean_min_distance,
    pointfile::parse_point_sets,
    spectrum::{DEFAULT_TOLERANCE, Method, periodogram_2d},
    star::star_exact,
};
use qmckit::work::Budget;

/// Mean and standard error of the mean.
fn mean_se(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let m = v.iter().sum::<f64>() / n;
    if v.len() < 2 {
        return (m, f64::NAN);
    }
    let var = v.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
    (m, (var / n).sqrt())
}

/// The statistics of one file, or the reason it could not be measured.
fn measure(path: &str) -> Result<String, String> {
    let len = std::fs::metadata(path).map_err(|e| e.to_string())?.len();
    if len > qmckit::size::MAX_ALLOC_BYTES {
        return Err(format!("{len} bytes, above the 1 GiB limit"));
    }
    let text = std::fs::read_to_string(path).map_err(|e| e.to_string())?;
    let sets = parse_point_sets(&text).map_err(|e| e.to_string())?;
    let budget = Budget::seconds(600.0).map_err(|e| e.to_string())?;
    let (mut star, mut nn, mut low, mut mid, mut sizes) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for set in &sets {
        let dims = set.dims;
        let p = Points::new(&set.data, dims).map_err(|e| e.to_string())?;
        let n = p.len();
        if n < 4 {
            return Err(format!("a set of {n} points; at least 4 expected"));
        }
        let root = (n as f64).sqrt();
        star.push(star_exact(p, &budget).map_err(|e| e.to_string())?);
        nn.push(mean_min_distance(p, false) * (n as f64).powf(1.0 / dims as f64));
        if dims == 2 {
            let k = root.ceil() as usize;
            let s = periodogram_2d(p, k, Method::Auto, DEFAULT_TOLERANCE, &budget)
                .map_err(|e| e.to_string())?;
            let radial = s.radial();
            let band = |lo: f64, hi: f64| {
                let bins: Vec<f64> = radial
                    .iter()
                    .filter(|b| (b.radius as f64) > lo && (b.radius as f64) <= hi)
                    .map(|b| b.mean)
                    .collect();
                bins.iter().sum::<f64>() / bins.len().max(1) as f64
            };
            low.push(band(0.5, root / 2.0));
            mid.push(band(root / 2.0, root));
        } else {
            low.push(f64::NAN);
            mid.push(f64::NAN);
        }
        sizes.push(n as f64);
    }
    let (s, s_se) = mean_se(&star);
    let (d, d_se) = mean_se(&nn);
    let (l, l_se) = mean_se(&low);
    let (m, m_se) = mean_se(&mid);
    let (n, _) = mean_se(&sizes);
    Ok(format!(
        "{path} {} {n:.0} {s:.6e} {s_se:.2e} {d:.5} {d_se:.1e} {l:.5} {l_se:.1e} {m:.5} {m_se:.1e}",
        sets.len()
    ))
}

fn main() -> ExitCode {
    let files: Vec<String> = std::env::args().skip(1).collect();
    if files.is_empty() {
        eprintln!("usage: set_stats FILE...");
        return ExitCode::from(2);
    }
    let mut status = ExitCode::SUCCESS;
    for f in &files {
        match measure(f) {
            Ok(line) => println!("{line}"),
            Err(e) => {
                eprintln!("set_stats: {f}: {e}");
                status = ExitCode::from(2);
            }
        }
    }
    status
}
