//! Nets: elementary intervals of 32 Sobol' points, (0,2)-sequence power-of-two runs,
//! blue-noise Sobol' (screen-space error of Morton-ordered Owen-scrambled Sobol').

use crate::plot::{ColourMap, ImageFigure, PointsFigure};
use qmckit::analysis::screen_error::{PixelIntegrand, screen_error};
use qmckit::analysis::tvalue::t_value_u32;
use qmckit::pixel::{IndependentPixels, Randomization, ZSobol};
use qmckit::work::Budget;
use qmckit::{Sampler, Sobol};

use super::super::Failure;
use super::{Ctx, Section, claims, error_caption, error_scale, pts2, row, sig};

/// The slides of this group.
pub fn sections(ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    Ok(vec![intervals(ctx)?, zero_two(ctx)?, blue_sobol(ctx)?])
}

/// The first `n` points of `s` in dimensions 0 and 1 as 0.32 numerators, interleaved.
fn raw(s: &impl Sampler, start: u32, n: u32) -> Result<Vec<u32>, Failure> {
    let mut v = Vec::with_capacity(2 * n as usize);
    for i in start..start + n {
        v.push(s.sample(i, 0)?);
        v.push(s.sample(i, 1)?);
    }
    Ok(v)
}

fn intervals(ctx: &Ctx) -> Result<Section, Failure> {
    let sobol = Sobol::new(2)?;
    let p = pts2(&sobol, 32, (0, 1))?;
    let t = t_value_u32(&raw(&sobol, 0, 32)?, 2, 5, &Budget::DEFAULT)?;
    let mut s = Section::new(
        "elementary-intervals",
        "32 2D Sobol' points and their elementary intervals (1x32 ... 32x1)",
        "The first 32 Sobol' points on each grid of elementary intervals of volume 1/32 (2^a \
         columns by 2^(5-a) rows), with the boxes holding exactly one point counted: a \
         (0,5,2)-net in base 2 has one point in every box of every grid.",
    );
    let mut full = 0;
    s.figures.push(ctx.figure(
        "sobol32.svg",
        &PointsFigure::new("32 Sobol' points", p.clone()),
        (300, 300),
        "32 Sobol' points",
    )?);
    for a in 0..=5u32 {
        let (c, r) = (1u32 << a, 1u32 << (5 - a));
        let fig = PointsFigure::new(format!("{c}x{r}"), p.clone()).intervals(c, r);
        let (good, cells) = fig.balanced_boxes().unwrap_or((0, 0));
        full += usize::from(cells > 0 && good == cells);
        s.figures.push(ctx.figure(
            &format!("sobol32-{c}x{r}.svg"),
            &fig,
            (300, 300),
            format!("elementary intervals {c}x{r}"),
        )?);
        s.rows.push(row(
            format!("boxes of the {c}x{r} grid holding exactly one point"),
            format!("{good} of {cells}"),
            "every box: one point",
        ));
    }
    s.rows.push(row(
        "t-value of the first 32 points (t_value_u32, m = 5)",
        t.to_string(),
        "0 (a (0,m,2)-net)",
    ));
    s.note = format!(
        "{}, and the t-value is {t}: the first 32 Sobol' points {} a (0,5,2)-net in base 2.",
        claims::count(full, 6, "grids", "every box holds exactly one point"),
        if full == 6 && t == 0 {
            "form"
        } else {
            "do not form"
        }
    );
    Ok(s)
}

fn zero_two(ctx: &Ctx) -> Result<Section, Failure> {
    let sobol = Sobol::new(2)?;
    let (runs, len) = (4u32, 16u32);
    let p = pts2(&sobol, runs * len, (0, 1))?;
    let mut s = Section::new(
        "zero-two-sequences",
        "(0,2)-sequences: power-of-two runs are nets too",
        format!(
            "The first {} 2D Sobol' points in {runs} colours, one per run of {len} consecutive \
         points, with the t-value of each run and of all {} together (t = 0: a (0,m,2)-net).",
            runs * len,
            runs * len
        ),
    );
    let mut nets = 0;
    s.figures.push(
        ctx.figure(
            "zero-two.svg",
            &PointsFigure::new("4 runs of 16 Sobol' points", p.clone())
                .groups(len as usize)
                .intervals(4, 4)
                .radius(4),
            (420, 420),
            "runs of 16 in colour, 4x4 grid",
        )?,
    );
    for k in 0..runs {
        let t = t_value_u32(&raw(&sobol, k * len, len)?, 2, 4, &Budget::DEFAULT)?;
        nets += usize::from(t == 0);
        s.rows.push(row(
            format!("t-value of points {}..{}", k * len, (k + 1) * len - 1),
            t.to_string(),
            "0",
        ));
    }
    let t64 = t_value_u32(&raw(&sobol, 0, 64)?, 2, 6, &Budget::DEFAULT)?;
    s.rows
        .push(row("t-value of the first 64 points", t64.to_string(), "0"));
    s.note = format!(
        "{}; the first {} points have t = {t64}{}.",
        claims::count(
            nets,
            runs as usize,
            &format!("runs of {len}"),
            "the points form a (0,4,2)-net by themselves (t = 0)"
        ),
        runs * len,
        if t64 == 0 {
            ", a (0,6,2)-net: consecutive runs fill each other's gaps"
        } else {
            ", not a (0,6,2)-net"
        }
    );
    Ok(s)
}

fn blue_sobol(ctx: &Ctx) -> Result<Section, Failure> {
    let side = ctx.pick(64u32, 128);
    let spp = 4;
    let f = PixelIntegrand::Step;
    let budget: Budget = ctx.budget;
    let white = screen_error(&IndependentPixels::new(side, side, spp, 3)?, f, &budget)?;
    let blue = screen_error(
        &ZSobol::new(side, side, spp, Randomization::FastOwen, 3)?,
        f,
        &budget,
    )?;
    let m = error_scale([&white.error[..], &blue.error[..]]);
    let mut s = Section::new(
        "blue-noise-sobol",
        "Blue-noise Sobol' (Ahmed & Wonka 2020)",
        format!(
            "Per-pixel error of a {side}x{side} image estimating a step integrand with {spp} samples a \
         pixel: independent samples against ZSobol (Morton-ordered, Owen-scrambled Sobol'). The \
         low band is the error's normalized power below a quarter of Nyquist (1 for white noise)."
        ),
    );
    for (name, e, file) in [
        ("independent", &white, "bns-white.png"),
        ("ZSobol", &blue, "bns-zsobol.png"),
    ] {
        let title = format!("error, {name} (±{})", sig(m, 2));
        let fig = ImageFigure::new(title, e.width, e.height, e.error.clone())
            .map_err(|x| Failure::usage(x.0))?
            .map(ColourMap::Diverging)
            .range(-m, m)
            .quantity("pixel error");
        s.figures.push(ctx.figure(
            file,
            &fig,
            (420, 360),
            format!("pixel {}", error_caption(name, m, 2)),
        )?);
        s.rows
            .push(row(format!("{name}: RMSE"), sig(e.rmse, 3), ""));
        s.rows.push(row(
            format!("{name}: low-band power (white noise: 1, blue noise: below 1)"),
            sig(e.low_band, 3),
            "",
        ));
    }
    s.note = format!(
        "ZSobol's per-pixel RMSE is {} than independent sampling's ({} against {}), and its \
         error's low-band power is {} ({} against {}; white noise: 1).",
        claims::factor(blue.rmse, white.rmse),
        sig(blue.rmse, 3),
        sig(white.rmse, 3),
        claims::factor(blue.low_band, white.low_band),
        sig(blue.low_band, 3),
        sig(white.low_band, 3),
    );
    Ok(s)
}
