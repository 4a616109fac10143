//! Spectral slides: blue-noise dithering, the power spectrum of samples and its radial
//! average, colours of noise, low-discrepancy spectra, and power spectra with variance.

use crate::plot::{ImageFigure, PointsFigure, RadialFigure, SpectrumFigure};
use qmckit::analysis::Points;
use qmckit::analysis::spectrum::{Spectrum, SpectrumMean, spectrum_2d};
use qmckit::analysis::variance::{Measured, TorusIntegrand, predicted_variance, shifted_error};
use qmckit::blue_noise::{BestCandidate, GaussianBlueNoise, PoissonDisk, VoidAndCluster};
use qmckit::random::stratified::{Jitter, Stratified};
use qmckit::{Halton, Independent, OwenSobol, Sampler, Sobol, bits};

use super::super::Failure;
use super::{Ctx, PLOT, Section, WIDE, claims, flat, pts2, row, sig};

/// Size of a spectrum image (PNG).
const SPEC: (u32, u32) = (440, 360);

/// The slides of this group.
pub fn sections(ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    Ok(vec![
        dithering(ctx)?,
        power_spectrum(ctx)?,
        colours(ctx)?,
        ld_spectra(ctx)?,
    ])
}

/// The variance slide.
pub fn variance_sections(ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    Ok(vec![variance(ctx)?])
}

/// A point set as reals, flat.
type Set = Vec<f64>;

fn poisson(n: u64, seed: u64, ctx: &Ctx) -> Result<Set, Failure> {
    Ok(PoissonDisk::with_points(2, n)?
        .torus(true)
        .seed(seed)
        .generate(&ctx.budget)?
        .to_f64())
}

/// A blue-noise set of exactly `n` points (Mitchell's best candidate, 10 candidates per
/// point), the progressive cousin of the Poisson disk.
fn best_candidate(n: u64, seed: u64, ctx: &Ctx) -> Result<Set, Failure> {
    Ok(BestCandidate::new(n)?
        .candidates(10)?
        .seed(seed)
        .generate(&ctx.budget)?
        .to_f64())
}

fn sampler_set(s: &impl Sampler, n: u32) -> Result<Set, Failure> {
    Ok(flat(&pts2(s, n, (0, 1))?))
}

/// The mean periodogram of `sets` up to `k`.
fn mean_spectrum(sets: &[Set], k: usize, ctx: &Ctx) -> Result<Spectrum, Failure> {
    let mut mean = SpectrumMean::new();
    for s in sets {
        mean.add(&spectrum_2d(Points::new(s, 2)?, k, &ctx.budget)?)?;
    }
    Ok(mean.mean()?)
}

/// Mean power over the annuli `1 <= r < r_max`.
fn low_band(s: &Spectrum, r_max: f64) -> f64 {
    let bins: Vec<_> = s
        .radial()
        .into_iter()
        .filter(|b| b.radius >= 1 && (b.radius as f64) < r_max)
        .collect();
    bins.iter().map(|b| b.mean).sum::<f64>() / bins.len().max(1) as f64
}

fn radial_curve(s: &Spectrum) -> Vec<(f64, f64)> {
    s.radial()
        .iter()
        .skip(1)
        .map(|b| (b.frequency(s.points()), b.mean))
        .collect()
}

fn dithering(ctx: &Ctx) -> Result<Section, Failure> {
    let (w, h) = ctx.pick((128usize, 48usize), (256, 64));
    let mask_side = ctx.pick(32usize, 64);
    let mask = VoidAndCluster::new(mask_side, mask_side)?
        .seed(1)
        .generate(&ctx.budget)?;
    let ranks = mask.ranks();
    let cells = (mask_side * mask_side) as f64;
    let rng = Independent::new(1, 5)?;
    let grad: Vec<f64> = (0..w * h)
        .map(|i| (i % w) as f64 / (w - 1) as f64)
        .collect();
    let mut white = Vec::with_capacity(w * h);
    let mut blue = Vec::with_capacity(w * h);
    for (i, &g) in grad.iter().enumerate() {
        let (x, y) = (i % w, i / w);
        let u = bits::to_f64(rng.sample(i as u32, 0)?);
        white.push(if g > u { 1.0 } else { 0.0 });
        let t = (ranks[(y % mask_side) * mask_side + x % mask_side] as f64 + 0.5) / cells;
        blue.push(if g > t { 1.0 } else { 0.0 });
    }
    // RMS of the dithering error seen through a 5x5 box blur (the eye's low-pass).
    let blur_err = |d: &[f64]| {
        let (mut sum, mut count) = (0.0, 0usize);
        for y in 2..h - 2 {
            for x in 2..w - 2 {
                let mut m = 0.0;
                for dy in 0..5 {
                    for dx in 0..5 {
                        let j = (y + dy - 2) * w + x + dx - 2;
                        m += d[j] - grad[j];
                    }
                }
                sum += (m / 25.0) * (m / 25.0);
                count += 1;
            }
        }
        (sum / count as f64).sqrt()
    };
    let (ew, eb) = (blur_err(&white), blur_err(&blue));
    let mut s = Section::new(
        "blue-noise-dithering",
        "Blue-noise dithering (Ulichney): white vs blue",
        format!(
            "A {w}x{h} grey ramp thresholded against white noise (an independent uniform per pixel) \
         and against a {mask_side}x{mask_side} void-and-cluster rank mask (tiled). The error is \
         measured through a 5x5 box blur, a stand-in for the eye's low-pass filter."
        ),
    );
    let img = |t: &str, v: &[f64]| -> Result<ImageFigure, Failure> {
        Ok(ImageFigure::new(t, w, h, v.to_vec())
            .map_err(|e| Failure::usage(e.0))?
            .range(0.0, 1.0)
            .no_bar())
    };
    s.figures.push(ctx.figure(
        "dither-ramp.png",
        &img("ramp", &grad)?,
        (560, 250),
        "the ramp",
    )?);
    s.figures.push(ctx.figure(
        "dither-white.png",
        &img("white-noise threshold", &white)?,
        (560, 250),
        "white noise",
    )?);
    s.figures.push(ctx.figure(
        "dither-blue.png",
        &img("void-and-cluster threshold", &blue)?,
        (560, 250),
        "blue noise",
    )?);
    s.rows
        .push(row("blurred RMS error, white noise", sig(ew, 3), ""));
    s.rows
        .push(row("blurred RMS error, blue noise", sig(eb, 3), ""));
    Ok(s)
}

fn power_spectrum(ctx: &Ctx) -> Result<Section, Failure> {
    let n = ctx.pick(512u64, 1024);
    let k = ctx.pick(32usize, 64);
    let p = poisson(n, 1, ctx)?;
    let spec = mean_spectrum(std::slice::from_ref(&p), k, ctx)?;
    let pts: Vec<[f64; 2]> = p.chunks_exact(2).map(|q| [q[0], q[1]]).collect();
    let mut s = Section::new(
        "power-spectrum",
        "Power spectrum of samples and its radial average",
        format!(
            "{} Poisson-disk points (toroidal dart throwing), their periodogram \
         P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / N for |kx|, |ky| <= {k} (P(0) = N, circled), and its \
         radial average; frequency in units of sqrt(N).",
            pts.len()
        ),
    );
    s.figures.push(ctx.figure(
        "ps-points.svg",
        &PointsFigure::new(format!("{} Poisson-disk points", pts.len()), pts).radius(2),
        PLOT,
        "samples",
    )?);
    s.figures.push(ctx.figure(
        "ps-spectrum.png",
        &SpectrumFigure::from_spectrum("periodogram", &spec).ceiling(4.0),
        SPEC,
        "Fourier power, log scale",
    )?);
    let radial = RadialFigure {
        title: "radial power spectrum".into(),
        x_label: "|k| / sqrt(N)".into(),
        y_label: "mean power".into(),
        curves: vec![("Poisson disk".into(), radial_curve(&spec))],
    };
    s.figures
        .push(ctx.figure("ps-radial.svg", &radial, WIDE, "radial average")?);
    s.rows.push(row(
        "P(0, 0) (= N)",
        sig(spec.get(0, 0).unwrap_or(0.0), 6),
        "",
    ));
    s.rows.push(row(
        "mean power for |k| < sqrt(N)/2 (white noise: 1)",
        sig(low_band(&spec, (n as f64).sqrt() / 2.0), 3),
        "",
    ));
    Ok(s)
}

fn colours(ctx: &Ctx) -> Result<Section, Failure> {
    let n = ctx.pick(256u64, 1024);
    let sets = ctx.pick(8u64, 32);
    let k = ctx.pick(32usize, 64);
    let white: Vec<Set> = (0..sets)
        .map(|s| sampler_set(&Independent::new(2, s)?, n as u32))
        .collect::<Result<_, _>>()?;
    let blue: Vec<Set> = (0..sets)
        .map(|s| best_candidate(n, s, ctx))
        .collect::<Result<_, _>>()?;
    let (sw, sb) = (
        mean_spectrum(&white, k, ctx)?,
        mean_spectrum(&blue, k, ctx)?,
    );
    let mut s = Section::new(
        "colours-of-noise",
        "Colours of noise: white and blue",
        format!(
            "Mean periodograms of {sets} sets of {n} independent (white) and Poisson-disk-like (blue: Mitchell's best candidate) points."
        ),
    );
    let r = (n as f64).sqrt() / 2.0;
    let (lw, lb) = (low_band(&sw, r), low_band(&sb, r));
    s.figures.push(ctx.figure(
        "noise-white.png",
        &SpectrumFigure::from_spectrum("white noise", &sw).ceiling(4.0),
        SPEC,
        format!("white: mean power {} for |k| < sqrt(N)/2", sig(lw, 3)),
    )?);
    s.figures.push(ctx.figure(
        "noise-blue.png",
        &SpectrumFigure::from_spectrum("blue noise", &sb).ceiling(4.0),
        SPEC,
        format!("blue: mean power {} for |k| < sqrt(N)/2", sig(lb, 3)),
    )?);
    let radial = RadialFigure {
        title: "radial power".into(),
        x_label: "|k| / sqrt(N)".into(),
        y_label: "mean power".into(),
        curves: vec![
            ("white".into(), radial_curve(&sw)),
            ("blue (best candidate)".into(), radial_curve(&sb)),
        ],
    };
    s.figures
        .push(ctx.figure("noise-radial.svg", &radial, WIDE, "radial averages")?);
    s.rows.push(row(
        "white: mean power |k| < sqrt(N)/2",
        sig(lw, 3),
        "flat (1)",
    ));
    s.rows.push(row(
        "blue: mean power |k| < sqrt(N)/2",
        sig(lb, 3),
        "near 0",
    ));
    s.note = format!(
        "Below sqrt(N)/2 the blue sets' mean power is {} than the white sets' ({} against {}).",
        claims::factor(lb, lw),
        sig(lb, 3),
        sig(lw, 3)
    );
    Ok(s)
}

fn ld_spectra(ctx: &Ctx) -> Result<Section, Failure> {
    let n = ctx.pick(256u32, 1024);
    let side = ctx.pick(16u32, 32);
    let sets = ctx.pick(8u64, 32);
    let k = ctx.pick(32usize, 64);
    let jit: Vec<Set> = (0..sets)
        .map(|s| sampler_set(&Stratified::new(&[side, side], Jitter::Random(s))?, n))
        .collect::<Result<_, _>>()?;
    let owen: Vec<Set> = (0..sets)
        .map(|s| sampler_set(&OwenSobol::new(2, s)?, n))
        .collect::<Result<_, _>>()?;
    let all = [
        (
            "jittered",
            "spec-jittered.png",
            mean_spectrum(&jit, k, ctx)?,
        ),
        (
            "Halton",
            "spec-halton.png",
            mean_spectrum(&[sampler_set(&Halton::new(2)?, n)?], k, ctx)?,
        ),
        (
            "Sobol'",
            "spec-sobol.png",
            mean_spectrum(&[sampler_set(&Sobol::new(2)?, n)?], k, ctx)?,
        ),
        (
            "Owen-scrambled Sobol'",
            "spec-owen.png",
            mean_spectrum(&owen, k, ctx)?,
        ),
    ];
    let mut s = Section::new(
        "ld-spectra",
        "Spectra of jittered, Halton, Sobol' and Owen-scrambled Sobol'",
        format!(
            "Periodograms of {n} points (jittered and Owen-scrambled: mean of {sets} sets); the \
         largest value away from k = 0 shows how sharp the peaks of a structured set are."
        ),
    );
    let r = (n as f64).sqrt() / 2.0;
    let mut peaks = Vec::new();
    for (name, file, spec) in &all {
        s.figures.push(ctx.figure(
            file,
            &SpectrumFigure::from_spectrum(*name, spec).ceiling(8.0),
            SPEC,
            *name,
        )?);
        let peak = spec
            .iter()
            .filter(|&(x, y, _)| (x, y) != (0, 0))
            .map(|t| t.2)
            .fold(0.0, f64::max);
        s.rows.push(row(
            format!("{name}: mean power |k| < sqrt(N)/2"),
            sig(low_band(spec, r), 3),
            "",
        ));
        s.rows.push(row(
            format!("{name}: largest P(k), k != 0"),
            sig(peak, 3),
            "",
        ));
        peaks.push(peak);
    }
    // all: jittered, Halton, Sobol', Owen-scrambled Sobol'.
    let (halton, sobol, owen) = (peaks[1], peaks[2], peaks[3]);
    s.note = format!(
        "Largest P(k) away from k = 0 (white noise: about 1 on average): Halton {}, Sobol' {}, \
         Owen-scrambled Sobol' {}: with scrambling the largest peak of Sobol' is {}.",
        sig(halton, 3),
        sig(sobol, 3),
        sig(owen, 3),
        claims::factor(owen, sobol)
    );
    Ok(s)
}

fn variance(ctx: &Ctx) -> Result<Section, Failure> {
    let n = ctx.pick(256u64, 1024);
    let sets = ctx.pick(24u64, 64);
    let k = ctx.pick(24usize, 48);
    let side = (n as f64).sqrt() as u32;
    let f = TorusIntegrand::disk(0.25)?;
    let shifts = Independent::new(2, 99)?;
    let mut s = Section::new(
        "variance-spectra",
        "Power spectra and variance: jittered, Poisson disk, blue noise",
        format!(
            "Var I_N = (1/N) sum_(k != 0) |c_k|^2 E P(k) for a randomly torus-shifted set: predicted \
         from the periodograms of {sets} sets of {n} points (about {n} for the Poisson disk; |kx|, |ky| <= {k}, white beyond), and \
         measured as the mean squared error of the same {sets} shifted sets on the disk of radius 1/4."
        ),
    );
    let mut curves = Vec::new();
    let mut compared = Vec::new();
    let kinds: [(&str, &str); 3] = [
        ("jittered", "var-jittered.png"),
        ("Poisson disk", "var-poisson.png"),
        ("blue noise (Gaussian)", "var-blue.png"),
    ];
    for (idx, (name, file)) in kinds.iter().enumerate() {
        let mut group = Vec::new();
        for seed in 0..sets {
            group.push(match idx {
                0 => sampler_set(
                    &Stratified::new(&[side, side], Jitter::Random(seed))?,
                    side * side,
                )?,
                1 => poisson(n, seed, ctx)?,
                _ => GaussianBlueNoise::new(n)?
                    .seed(seed)
                    .generate(&ctx.budget)?
                    .to_f64(),
            });
        }
        // The shift variance of one set is (1/N_s) sum |c_k|^2 P_s(k): the mean of the
        // per-set predictions is exact when the sets differ in size (Poisson disk).
        let mut mean = SpectrumMean::new();
        let mut pred = 0.0;
        for g in &group {
            let one = spectrum_2d(Points::new(g, 2)?, k, &ctx.budget)?;
            pred += predicted_variance(&one, &f).variance / group.len() as f64;
            mean.add(&one)?;
        }
        let mean = mean.mean()?;
        let mut errors = Vec::new();
        for (j, g) in group.iter().enumerate() {
            let shift = [
                bits::to_f64(shifts.sample(j as u32 + 1000 * idx as u32, 0)?),
                bits::to_f64(shifts.sample(j as u32 + 1000 * idx as u32, 1)?),
            ];
            errors.push(shifted_error(Points::new(g, 2)?, &f, shift)?);
        }
        let measured = Measured::from_errors(&errors)?;
        s.figures.push(ctx.figure(
            file,
            &SpectrumFigure::from_spectrum(*name, &mean).ceiling(4.0),
            SPEC,
            *name,
        )?);
        curves.push((name.to_string(), radial_curve(&mean)));
        compared.push((*name, pred, measured.variance, measured.std_error));
        s.rows
            .push(row(format!("{name}: predicted variance"), sig(pred, 3), ""));
        s.rows.push(row(
            format!("{name}: measured variance (± std. error)"),
            format!(
                "{} ± {}",
                sig(measured.variance, 3),
                sig(measured.std_error, 2)
            ),
            "",
        ));
    }
    s.rows.push(row(
        "white noise: (pi R^2 - pi^2 R^4) / N",
        sig(f.white_noise_variance() / n as f64, 3),
        "",
    ));
    s.figures.push(ctx.figure(
        "var-radial.svg",
        &RadialFigure {
            title: "radial power".into(),
            x_label: "|k| / sqrt(N)".into(),
            y_label: "mean power".into(),
            curves,
        },
        WIDE,
        "radial averages",
    )?);
    s.note = format!(
        "The lecture shows these spectra without numbers. {}",
        claims::agreement(&compared, 2.0)
    );
    Ok(s)
}
