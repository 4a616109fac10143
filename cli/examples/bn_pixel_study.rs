//! The screen-space error of the blue-noise pixel samplers (`bn-sobol`, `bn-lattice`)
//! against ZSobol, per-pixel independent Owen-Sobol' (`padded-sobol`) and independent
//! random pixels (`independent`), on `qmckit::analysis::screen_error`'s integrands: the
//! numbers and figures of docs/pixel-samplers.md.
//!
//! ```text
//! cargo run --release -p qmckit-cli --example bn_pixel_study -- [--side 128] [--seeds 16] [--figures DIR]
//! ```
//!
//! Prints, for the Gaussian bump, the fixed step and the moving "visibility" step at 1, 4
//! and 16 samples a pixel, the mean over seeds `0..seeds` of each sampler's low-band error
//! power (`low_band_absolute`, the band `1 <= |k| < side / 8`) and RMSE, divided by
//! `padded-sobol`'s, and the normalized low band (white noise 1). With `--figures`, writes
//! `bn-pixel-errors.png` (the step's error images at 4 spp, seed 0, and below them the
//! same blurred by a Gaussian of 2 pixels, times 4) and `bn-pixel-spectra.png` (the step's
//! radial error spectra at 4 spp, mean over the seeds, white noise 1).

use qmckit::analysis::screen_error::{PixelIntegrand, ScreenError, screen_error};
use qmckit::catalog::{self, PixelParams};
use qmckit::pixel::PixelSampler;
use qmckit::work::Budget;
use qmckit_cli::plot::{ColourMap, Format, ImageFigure, RadialFigure, render};

const SAMPLERS: [(&str, Option<&str>); 5] = [
    ("independent", None),
    ("padded-sobol", Some("fast-owen")),
    ("zsobol", Some("fast-owen")),
    ("bn-sobol", None),
    ("bn-lattice", None),
];

fn sampler(name: &str, r: Option<&str>, side: u32, spp: u32, seed: u64) -> Box<dyn PixelSampler> {
    let p = PixelParams {
        width: side,
        height: side,
        spp,
        seed,
    };
    let entry = catalog::pixel_sampler(name).expect("a catalog pixel sampler");
    let r = r.map(|r| catalog::randomizer(r).expect("a catalog randomizer"));
    catalog::build_pixel(entry, r, &p).expect("the sampler builds")
}

/// The mean normalized power at each integer radius `0..side / 2` (cycles per image side).
fn radial(e: &ScreenError) -> Vec<f64> {
    let (w, h) = (e.width, e.height);
    let half = w.min(h) / 2;
    let (mut s, mut n) = (vec![0.0; half], vec![0usize; half]);
    for ky in 0..h {
        for kx in 0..w {
            let fx = if kx <= w / 2 {
                kx as f64
            } else {
                kx as f64 - w as f64
            };
            let fy = if ky <= h / 2 {
                ky as f64
            } else {
                ky as f64 - h as f64
            };
            let r = (fx * fx + fy * fy).sqrt().round() as usize;
            if r < half {
                s[r] += e.spectrum[ky * w + kx];
                n[r] += 1;
            }
        }
    }
    s.iter()
        .zip(&n)
        .map(|(s, &n)| s / n.max(1) as f64)
        .collect()
}

/// `e` blurred by a Gaussian of `sigma` pixels on the torus.
fn blur(e: &[f64], side: usize, sigma: f64) -> Vec<f64> {
    let r = (3.0 * sigma).ceil() as i64;
    let k: Vec<f64> = (-r..=r)
        .map(|d| (-((d * d) as f64) / (2.0 * sigma * sigma)).exp())
        .collect();
    let norm: f64 = k.iter().sum();
    let pass = |src: &[f64], horizontal: bool| -> Vec<f64> {
        let mut out = vec![0.0; side * side];
        for y in 0..side {
            for x in 0..side {
                let mut acc = 0.0;
                for (t, w) in (-r..=r).zip(&k) {
                    let (xx, yy) = if horizontal {
                        ((x as i64 + t).rem_euclid(side as i64) as usize, y)
                    } else {
                        (x, (y as i64 + t).rem_euclid(side as i64) as usize)
                    };
                    acc += w * src[yy * side + xx];
                }
                out[y * side + x] = acc / norm;
            }
        }
        out
    };
    pass(&pass(e, true), false)
}

/// Writes `bytes` beside `path`, then renames it into place (no half-written figure).
fn write(path: &std::path::Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = path.with_extension("tmp");
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(tmp, path)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mut side, mut seeds, mut figures) = (128u32, 16u64, None::<std::path::PathBuf>);
    let mut k = 0;
    while k < args.len() {
        let v = args.get(k + 1).ok_or("a flag needs a value")?;
        match args[k].as_str() {
            "--side" => side = v.parse()?,
            "--seeds" => seeds = v.parse()?,
            "--figures" => figures = Some(v.into()),
            f => return Err(format!("unknown flag {f}").into()),
        }
        k += 2;
    }
    let u = Budget::UNLIMITED;
    println!(
        "side {side}, seeds 0..{seeds}; low band and RMSE over padded-sobol's; normalized low band (white 1)"
    );
    println!(
        "| integrand | spp | sampler | low band / padded | low band / independent | RMSE / padded | normalized low band |"
    );
    println!("|---|---|---|---|---|---|---|");
    for f in [
        PixelIntegrand::GaussianBump,
        PixelIntegrand::Step,
        PixelIntegrand::Visibility,
    ] {
        for spp in [1u32, 4, 16] {
            // [rmse^2, low band absolute, normalized low band] per sampler
            let mut acc = [[0.0f64; 3]; SAMPLERS.len()];
            for seed in 0..seeds {
                for (a, (name, r)) in acc.iter_mut().zip(SAMPLERS) {
                    let e = screen_error(&sampler(name, r, side, spp, seed), f, &u)?;
                    a[0] += e.rmse * e.rmse / seeds as f64;
                    a[1] += e.low_band_absolute / seeds as f64;
                    a[2] += e.low_band / seeds as f64;
                }
            }
            for (k, (name, _)) in SAMPLERS.iter().enumerate() {
                println!(
                    "| {f:?} | {spp} | {name} | {:.3} | {:.3} | {:.3} | {:.3} |",
                    acc[k][1] / acc[1][1],
                    acc[k][1] / acc[0][1],
                    (acc[k][0] / acc[1][0]).sqrt(),
                    acc[k][2]
                );
            }
        }
    }
    let Some(dir) = figures else { return Ok(()) };
    let (spp, f, s) = (4u32, PixelIntegrand::Step, side as usize);
    let shown = &SAMPLERS[1..];
    let gap = 6;
    let cols = shown.len();
    let (w, h) = (cols * s + (cols - 1) * gap, 2 * s + gap);
    let mut pixels = vec![0.0f64; w * h];
    let mut curves = Vec::new();
    let mut m = 0.0f64;
    for (c, (name, r)) in shown.iter().enumerate() {
        let e = screen_error(&sampler(name, *r, side, spp, 0), f, &u)?;
        let b = blur(&e.error, s, 2.0);
        for y in 0..s {
            for x in 0..s {
                let col = c * (s + gap) + x;
                pixels[y * w + col] = e.error[y * s + x];
                pixels[(s + gap + y) * w + col] = 4.0 * b[y * s + x];
            }
        }
        m = m.max(e.rmse);
        let mut mean = vec![0.0; s / 2];
        for seed in 0..seeds {
            let e = screen_error(&sampler(name, *r, side, spp, seed), f, &u)?;
            for (a, v) in mean.iter_mut().zip(radial(&e)) {
                *a += v / seeds as f64;
            }
        }
        curves.push((
            name.to_string(),
            mean.iter()
                .enumerate()
                .skip(1)
                .map(|(k, &v)| (k as f64, v))
                .collect(),
        ));
    }
    let range = 2.5 * m;
    let fig = ImageFigure::new(
        format!(
            "step, {spp} spp, {side}x{side}: {} (top: error; bottom: blurred, sigma 2 px, x4)",
            shown.iter().map(|s| s.0).collect::<Vec<_>>().join(", ")
        ),
        w,
        h,
        pixels,
    )?
    .map(ColourMap::Diverging)
    .range(-range, range)
    .quantity("pixel error");
    let png = render(&fig, Format::Png, 1100, 560)?;
    write(&dir.join("bn-pixel-errors.png"), &png)?;
    let fig = RadialFigure {
        title: format!(
            "step, {spp} spp: radial error spectrum, mean of {seeds} seeds (white noise 1)"
        ),
        x_label: format!("frequency (cycles per {side} pixels)"),
        y_label: "mean normalized power".into(),
        curves,
    };
    let png = render(&fig, Format::Png, 800, 500)?;
    write(&dir.join("bn-pixel-spectra.png"), &png)?;
    println!(
        "wrote {}/bn-pixel-errors.png, bn-pixel-spectra.png",
        dir.display()
    );
    Ok(())
}
