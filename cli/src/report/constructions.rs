//! Slides on warps and the radical-inverse constructions: warping, radical inverse,
//! van der Corput, Halton, Hammersley, permuted radical inverse, Owen scrambling.

use crate::plot::{ConvergenceFigure, Curve, Domain, PointsFigure};
use qmckit::analysis::Points;
use qmckit::analysis::integrate::{Integrand, integration_error};
use qmckit::randomize::digits::DigitScramble;
use qmckit::{Halton, Hammersley, RadicalInverse, Sobol, VanDerCorput, bits};

use super::super::Failure;
use super::{Ctx, PLOT, Section, WIDE, claims, flat, pts2, row, sig};

/// The slides of this group.
pub fn sections(ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    Ok(vec![
        warping(ctx)?,
        radical_inverse()?,
        van_der_corput(ctx)?,
        halton(ctx)?,
        hammersley(ctx)?,
        permuted(ctx)?,
        owen(ctx)?,
    ])
}

fn warping(ctx: &Ctx) -> Result<Section, Failure> {
    let n = 256;
    let p = pts2(&Sobol::new(2)?, n, (0, 1))?;
    let mut s = Section::new(
        "warping",
        "Warping samples for MC integration",
        format!(
            "{n} Sobol' points of [0,1)^2 mapped to the unit disk (theta = 2 pi xi1, r = sqrt(xi2) \
         is the polar map; we draw the area-preserving concentric map), to the cosine-weighted \
         hemisphere (seen from above) and to a triangle."
        ),
    );
    let fig = |d: Domain| {
        PointsFigure::new(format!("{n} Sobol' points"), p.clone())
            .domain(d)
            .radius(2)
    };
    s.figures
        .push(ctx.figure("warp-square.svg", &fig(Domain::Square), PLOT, "unit square")?);
    s.figures.push(ctx.figure(
        "warp-disk.svg",
        &fig(Domain::Disk),
        PLOT,
        "disk (concentric)",
    )?);
    s.figures.push(ctx.figure(
        "warp-hemisphere.svg",
        &fig(Domain::Hemisphere),
        PLOT,
        "cosine-weighted hemisphere, from above",
    )?);
    s.figures.push(ctx.figure(
        "warp-triangle.svg",
        &fig(Domain::Triangle),
        PLOT,
        "triangle",
    )?);
    // The fraction of disk points within radius 1/2 is the area fraction 1/4 for a uniform map.
    let inner = p
        .iter()
        .filter(|q| {
            let d = Domain::Disk.map(**q);
            d[0] * d[0] + d[1] * d[1] < 0.25
        })
        .count();
    s.rows.push(row(
        "fraction of disk points within r < 1/2 (uniform: 1/4)",
        sig(inner as f64 / n as f64, 4),
        "",
    ));
    Ok(s)
}

fn radical_inverse() -> Result<Section, Failure> {
    let mut s = Section::new(
        "radical-inverse",
        "The radical inverse (bases 2 and 3)",
        "Phi_b(n) mirrors the base-b digits of n about the radix point; qmckit computes \
         floor(Phi_b(n) 2^32) exactly, shown here as a decimal.",
    );
    let r2 = RadicalInverse::new(2)?;
    let r3 = RadicalInverse::new(3)?;
    let lecture2 = [
        "0", "0.5", "0.25", "0.75", "0.125", "0.625", "0.375", "0.875",
    ];
    let lecture3 = [
        "0", "0.333..", "0.666...", "0.111...", "0.444...", "0.777...", "0.222...", "0.555...",
        "0.888...",
    ];
    for (n, l) in lecture2.iter().enumerate() {
        let v = bits::to_f64(r2.sample(n as u32));
        s.rows
            .push(row(format!("Phi_2({n}), n = {n:b}_2"), sig(v, 6), *l));
    }
    for (n, l) in lecture3.iter().enumerate() {
        let v = bits::to_f64(r3.sample(n as u32));
        s.rows.push(row(format!("Phi_3({n})"), sig(v, 6), *l));
    }
    s.note = "Base 3 values are floor(Phi_3(n) 2^32) / 2^32, below the repeating decimal by less \
              than 2^-32."
        .into();
    Ok(s)
}

fn van_der_corput(ctx: &Ctx) -> Result<Section, Failure> {
    let n = 16u32;
    let v = VanDerCorput::new(2)?;
    let p: Vec<[f64; 2]> = (0..n)
        .map(|i| [bits::to_f64(v.value(i)), (i as f64 + 0.5) / n as f64])
        .collect();
    let mut s = Section::new(
        "van-der-corput",
        "1D low discrepancy: van der Corput",
        "The first 16 points Phi_2(i), drawn at height (i + 1/2)/16: each prefix of 2^k points \
         fills the 2^k intervals [j/2^k, (j+1)/2^k) once.",
    );
    s.figures.push(ctx.figure(
        "vdc.svg",
        &PointsFigure::new("van der Corput: value (x) vs index (y)", p.clone()),
        PLOT,
        "van der Corput, index upwards",
    )?);
    let d = qmckit::analysis::star::star_1d(Points::new(
        &p.iter().map(|q| q[0]).collect::<Vec<_>>(),
        1,
    )?)?;
    s.rows
        .push(row("Phi_2(6)", sig(bits::to_f64(v.value(6)), 6), "0.375"));
    s.rows.push(row(
        "D* of the first 16 points (exact: 1/16)",
        sig(d, 6),
        "",
    ));
    Ok(s)
}

fn halton(ctx: &Ctx) -> Result<Section, Failure> {
    let n = ctx.pick(256, 1024);
    let h = Halton::new(2)?;
    let p = pts2(&h, n, (0, 1))?;
    let mut s = Section::new(
        "halton",
        "The Halton sequence",
        format!(
            "(Phi_2(i), Phi_3(i)) for i < {n}: relatively prime bases, any number of points and dimensions."
        ),
    );
    s.figures.push(ctx.figure(
        "halton.svg",
        &PointsFigure::new(format!("Halton, {n} points"), p.clone()).radius(2),
        PLOT,
        "Halton bases 2, 3",
    )?);
    s.rows.push(row(
        format!("D* of {n} Halton points"),
        sig(ctx.star(&p)?, 4),
        "",
    ));
    Ok(s)
}

fn hammersley(ctx: &Ctx) -> Result<Section, Failure> {
    let n = ctx.pick(256u32, 1024);
    let hm = Hammersley::new(n as u64, 2)?;
    let p = pts2(&hm, n, (0, 1))?;
    let hp = pts2(&Halton::new(2)?, n, (0, 1))?;
    let mut s = Section::new(
        "hammersley",
        "The Hammersley point set",
        format!("(i/N, Phi_2(i)) for N = {n}: with N known in advance one dimension becomes i/N."),
    );
    s.figures.push(ctx.figure(
        "hammersley.svg",
        &PointsFigure::new(format!("Hammersley, {n} points"), p.clone()).radius(2),
        PLOT,
        "Hammersley",
    )?);
    let dh = ctx.star(&p)?;
    let dt = ctx.star(&hp)?;
    s.rows
        .push(row(format!("D* Hammersley, N = {n}"), sig(dh, 4), ""));
    s.rows
        .push(row(format!("D* Halton, N = {n}"), sig(dt, 4), ""));
    s.rows.push(row(
        "Hammersley lower than Halton?",
        if dh < dt { "yes" } else { "no" },
        "slightly lower discrepancy than Halton",
    ));
    Ok(s)
}

fn permuted(ctx: &Ctx) -> Result<Section, Failure> {
    let n = ctx.pick(512, 1024);
    // Dimensions 9 and 10 of Halton have the bases 29 and 31.
    let plain = pts2(&Halton::new(11)?, n, (9, 10))?;
    let scr = pts2(
        &Halton::with_scramble(11, DigitScramble::Permutations(7))?,
        n,
        (9, 10),
    )?;
    let mut s = Section::new(
        "permuted-radical-inverse",
        "Low-dimensional projections: (Phi_29, Phi_31), unscrambled and with random digit permutations",
        format!(
            "{n} points of the Halton dimensions with bases 29 and 31: unscrambled they lie on \
         a few lines; random permutations of the digits sigma_i(d_i) break the lines."
        ),
    );
    s.figures.push(ctx.figure(
        "phi29-31.svg",
        &PointsFigure::new("(Phi_29, Phi_31) unscrambled", plain.clone()).radius(2),
        PLOT,
        "unscrambled",
    )?);
    s.figures.push(ctx.figure(
        "phi29-31-perm.svg",
        &PointsFigure::new("(Phi_29, Phi_31) permuted", scr.clone()).radius(2),
        PLOT,
        "random digit permutations",
    )?);
    let d0 = ctx.star(&plain)?;
    let d1 = ctx.star(&scr)?;
    s.rows
        .push(row(format!("D* unscrambled (N = {n})"), sig(d0, 4), ""));
    s.rows.push(row(
        format!("D* with random digit permutations (N = {n})"),
        sig(d1, 4),
        "",
    ));
    s.note = format!(
        "With random digit permutations D* is {} than unscrambled ({} against {}).",
        claims::factor(d1, d0),
        sig(d1, 4),
        sig(d0, 4)
    );
    Ok(s)
}

/// RMSE over `seeds` of the 2D estimate of `f` by `make(seed)`'s first N points.
pub fn rmse_curve<S: qmckit::Sampler>(
    make: impl Fn(u64) -> qmckit::Result<S>,
    f: Integrand,
    ns: &[u32],
    seeds: u64,
) -> Result<Vec<(f64, f64)>, Failure> {
    let mut out = Vec::new();
    let samplers: Vec<S> = (0..seeds).map(&make).collect::<qmckit::Result<_>>()?;
    for &n in ns {
        let mut sum = 0.0;
        for s in &samplers {
            let p = pts2(s, n, (0, 1))?;
            let e = integration_error(Points::new(&flat(&p), 2)?, f);
            sum += e * e;
        }
        out.push((n as f64, (sum / seeds as f64).sqrt()));
    }
    Ok(out)
}

fn owen(ctx: &Ctx) -> Result<Section, Failure> {
    let m = ctx.pick(12, 15);
    let seeds = ctx.pick(16, 64);
    let ns: Vec<u32> = (2..=m).map(|k| 1u32 << k).collect();
    let f = Integrand::Gaussian;
    let plain = rmse_curve(|_| Halton::new(2), f, &ns, 1)?;
    let perm = rmse_curve(
        |s| Halton::with_scramble(2, DigitScramble::Permutations(s)),
        f,
        &ns,
        seeds,
    )?;
    let ow = rmse_curve(
        |s| Halton::with_scramble(2, DigitScramble::Owen(s)),
        f,
        &ns,
        seeds,
    )?;
    let owsob = rmse_curve(|s| qmckit::OwenSobol::new(2, s), f, &ns, seeds)?;
    let fig = ConvergenceFigure::new(
        "Gaussian peak, 2D",
        vec![
            Curve {
                label: "Halton".into(),
                points: plain,
            },
            Curve {
                label: "Halton + permutations".into(),
                points: perm,
            },
            Curve {
                label: "Halton + Owen".into(),
                points: ow,
            },
            Curve {
                label: "Owen-scrambled Sobol'".into(),
                points: owsob,
            },
        ],
    );
    let slopes = fig.slopes();
    let mut s = Section::new(
        "owen-scrambling",
        "Owen scrambling and its error",
        format!(
            "Owen scrambling permutes each digit by a permutation chosen by the digits before it. \
         RMS error over {seeds} seeds of the 2D Gaussian peak exp(-16|x-c|^2) against N = 4 .. 2^{m}."
        ),
    );
    s.figures
        .push(ctx.figure("owen-error.svg", &fig, WIDE, "error with Owen scrambling")?);
    let names = [
        "Halton",
        "Halton + random digit permutations",
        "Halton + Owen",
        "Owen-scrambled Sobol'",
    ];
    let mut fitted = Vec::new();
    for (name, sl) in names.iter().zip(slopes) {
        s.rows.push(row(
            format!("fitted slope of log error, {name}"),
            sl.map_or("-".into(), |v| sig(v, 3)),
            "",
        ));
        if let Some(v) = sl {
            fitted.push(format!("{name} {}", claims::nearer(v, -1.5, -1.0)));
        }
    }
    s.note = format!(
        "Owen scrambling of a (0,m,2)-net gives RMSE O(N^-3/2 (log N)^(1/2)) on smooth \
         integrands; Halton is not a base-2 net at these N. Fitted slopes: {}.",
        fitted.join("; ")
    );
    Ok(s)
}
