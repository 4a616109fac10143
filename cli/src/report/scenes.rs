//! The rendered studies (MSE tables at n = 16, quad light, motion blur + defocus, pixel x
//! light, ambient occlusion) through `crate::scene`: a small analytic scene
//! (spheres and a plane, exact intersections), a reference at a high sample count, MSE over
//! many seeds.

use crate::plot::{ColourMap, ImageFigure, PointsFigure};
use crate::scene::samplers::{SOBOL_OWEN, ZSOBOL};
use crate::scene::{self, SceneImage, SceneStudy, Study, StudyOptions, quad_light_uv};
use qmckit::work::{Cost, Rate};

use super::super::Failure;
use super::{Ctx, Section, claims, error_caption, error_scale, row, sig};

/// The rate of [`scene::cost`]'s unit, integrand samples (a camera ray and at most one
/// secondary ray): a few million a second on two cores.
const SCENE_RATE: Rate = Rate::per_second(3e6);

/// Image size of a render figure.
const RENDER: (u32, u32) = (360, 320);

/// The slides of this group.
pub fn sections(ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    let o = if ctx.quick {
        StudyOptions::quick()
    } else {
        StudyOptions::full()
    };
    // scene::cost counts all five studies; each is one step of the budget.
    let each = scene::cost(&o) as f64 / 5.0;
    ctx.budget
        .check("each rendered study", Cost::steps(each, SCENE_RATE))?;
    let area = Study::PixelArea.run(&o, &ctx.budget)?;
    let shadow = Study::SoftShadow.run(&o, &ctx.budget)?;
    let mut mse = Section::new(
        "mse-tables-n16",
        "MSE tables at n = 16: independent, stratified, Sobol'",
        "Two renders at 16 samples a pixel: the MSE against a high-sample reference, over several \
         seeds, relative to independent sampling (1/Rx: R times lower).",
    );
    add_study(
        ctx,
        &mut mse,
        "mse-area",
        &area,
        &[("1x", 0), ("1/2.41x", 1), ("1/3.38x", 2)],
    )?;
    add_study(
        ctx,
        &mut mse,
        "mse-shadow",
        &shadow,
        &[("1x", 0), ("1/2.12x", 1), ("1/3.95x", 2)],
    )?;
    mse.note = format!(
        "Our scene (spheres on a plane) and integrands differ from the lecture's, so the ratios \
         differ; the lecture's order of the MSE is independent > stratified > Sobol'. {}.",
        [&area, &shadow]
            .iter()
            .map(|st| mse_order(st))
            .collect::<Vec<_>>()
            .join("; ")
    );

    let mut quad = Section::new(
        "quad-light",
        "Warping samples to a quad light: 4x4 stratified vs 16 Sobol'",
        "16 samples of the unit square, as they are warped to the rectangular area light (the \
         area map is affine, so the pattern lands unchanged): 4x4 stratified and the first 16 \
         Owen-scrambled Sobol' points, with the soft-shadow renders that use them.",
    );
    let (strat, sob) = quad_light_uv(16, 1)?;
    quad.figures.push(ctx.figure(
        "quad-stratified.svg",
        &PointsFigure::new("4x4 stratified", strat).intervals(4, 4),
        (320, 320),
        "4x4 stratified",
    )?);
    quad.figures.push(ctx.figure(
        "quad-sobol.svg",
        &PointsFigure::new("16 Sobol'", sob).intervals(4, 4),
        (320, 320),
        "16 Sobol'",
    )?);
    add_renders(ctx, &mut quad, "quad", &shadow)?;

    let motion = Study::MotionDefocus.run(&o, &ctx.budget)?;
    let mut md = Section::new(
        "motion-blur-defocus",
        "Sampling motion blur + defocus: independent, Halton, Sobol'",
        "Four dimensions a sample (pixel x, y, lens u, v, and time); MSE relative to independent.",
    );
    add_study(
        ctx,
        &mut md,
        "motion",
        &motion,
        &[("1x", 0), ("1/1.13x", 1), ("1/1.80x", 2)],
    )?;
    md.note = format!(
        "A different scene and shutter/aperture than the lecture's; the ratios are ours. {}.",
        mse_order(&motion)
    );

    let pl = Study::PixelLight.run(&o, &ctx.budget)?;
    let mut pls = Section::new(
        "pixel-light",
        "Pixel x light sampling",
        "The pixel area and the area light sampled jointly (4D) at each sample count.",
    );
    add_study(ctx, &mut pls, "pixel-light", &pl, &[])?;

    let ao = Study::AmbientOcclusion.run(&o, &ctx.budget)?;
    let mut aos = Section::new(
        "ambient-occlusion",
        "Ambient occlusion: white vs blue-noise error distribution",
        "AO = integral of V(w) cos(theta) dw over the hemisphere, rendered with independent, \
         Owen-scrambled Sobol' and ZSobol (blue-noise) samples: the MSE, and where the error's \
         power lies (compare the error images).",
    );
    add_study(ctx, &mut aos, "ao", &ao, &[])?;
    aos.note = blue_against_white(&ao, &SOBOL_OWEN.name(), &ZSOBOL.name());
    Ok(vec![mse, quad, md, pls, aos])
}

fn image(title: &str, im: &SceneImage, map: ColourMap) -> Result<ImageFigure, Failure> {
    let fig = ImageFigure::new(
        title,
        im.width as usize,
        im.height as usize,
        im.pixels.clone(),
    )
    .map_err(|e| Failure::usage(e.0))?;
    Ok(fig.map(map))
}

/// The reference, the renders and their errors as figures.
fn add_renders(ctx: &Ctx, s: &mut Section, stem: &str, st: &SceneStudy) -> Result<(), Failure> {
    let top = st
        .reference
        .pixels
        .iter()
        .copied()
        .fold(0.0f64, f64::max)
        .max(1e-9);
    s.figures.push(
        ctx.figure(
            &format!("{stem}-reference.png"),
            &image("reference", &st.reference, ColourMap::Grey)?
                .range(0.0, top)
                .quantity("pixel value"),
            RENDER,
            format!("{}: reference", st.name),
        )?,
    );
    for (k, (name, im)) in st.renders.iter().enumerate() {
        s.figures.push(
            ctx.figure(
                &format!("{stem}-render-{k}.png"),
                &image(name, im, ColourMap::Grey)?
                    .range(0.0, top)
                    .quantity("pixel value"),
                RENDER,
                format!("{name}, {} spp", st.spp),
            )?,
        );
    }
    // One scale for the error images compared side by side.
    let m = error_scale(st.errors.iter().map(|e| &e.1.pixels[..]));
    for (k, (name, im)) in st.errors.iter().enumerate() {
        let title = format!("error, {name} (±{})", sig(m, 2));
        s.figures.push(
            ctx.figure(
                &format!("{stem}-error-{k}.png"),
                &image(&title, im, ColourMap::Diverging)?
                    .range(-m, m)
                    .quantity("render - reference"),
                RENDER,
                error_caption(name, m, st.errors.len()),
            )?,
        );
    }
    Ok(())
}

/// The study's measured MSE order, samplers as listed (the expected order, largest first).
fn mse_order(st: &SceneStudy) -> String {
    let values: Vec<(&str, f64)> = st.mse.iter().map(|e| (e.sampler.as_str(), e.mse)).collect();
    claims::order(&format!("MSE in {}", st.name), &values)
}

/// Sampler `blue` against `white` in one study: whether their MSEs differ by more than two
/// standard errors, and their error power at low frequencies.
fn blue_against_white(st: &SceneStudy, white: &str, blue: &str) -> String {
    let find = |name: &str| st.mse.iter().find(|e| e.sampler == name);
    let (Some(w), Some(b)) = (find(white), find(blue)) else {
        return String::new();
    };
    let se = w.mse_stderr.hypot(b.mse_stderr);
    let z = claims::z_score(b.mse, w.mse, se);
    format!(
        "MSE: {blue} {}, {white} {}, {} standard errors of their difference apart ({}). Error \
         power below a quarter of Nyquist (white noise: 1): {blue} {}, {white} {}, {} for {blue}.",
        sig(b.mse, 3),
        sig(w.mse, 3),
        sig(z, 3),
        if z <= 2.0 {
            "equal within 2 standard errors"
        } else {
            "a difference beyond 2 standard errors"
        },
        sig(b.low_band, 3),
        sig(w.low_band, 3),
        claims::factor(b.low_band, w.low_band),
    )
}

/// The renders and the MSE rows; `lecture[k]` is the lecture's ratio for entry `k`.
fn add_study(
    ctx: &Ctx,
    s: &mut Section,
    stem: &str,
    st: &SceneStudy,
    lecture: &[(&str, usize)],
) -> Result<(), Failure> {
    add_renders(ctx, s, stem, st)?;
    for (k, e) in st.mse.iter().enumerate() {
        let theirs = lecture.iter().find(|l| l.1 == k).map_or("", |l| l.0);
        s.rows.push(row(
            format!(
                "{}: {}, {} spp, {} seeds: MSE {}",
                st.name,
                e.sampler,
                st.spp,
                st.seeds,
                sig(e.mse, 3)
            ),
            if k == 0 {
                "1x".to_owned()
            } else {
                format!("1/{}x", sig(e.relative, 3))
            },
            theirs,
        ));
    }
    for e in &st.mse {
        s.rows.push(row(
            format!(
                "{}: {}: error power below a quarter of Nyquist (white = 1)",
                st.name, e.sampler
            ),
            sig(e.low_band, 3),
            "",
        ));
    }
    Ok(())
}
