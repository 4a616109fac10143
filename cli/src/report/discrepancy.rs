//! Discrepancy slides: three 2D point sets and their D*, the low-discrepancy rates, the
//! Koksma–Hlawka bound against the actual error, and measured QMC error against N.

use crate::plot::{ConvergenceFigure, Curve, PointsFigure};
use qmckit::analysis::integrate::Integrand;
use qmckit::random::stratified::{Jitter, Stratified};
use qmckit::{Halton, Hammersley, Independent, LarcherPillichshammer, OwenSobol, Sobol};

use super::super::Failure;
use super::constructions::rmse_curve;
use super::{Ctx, PLOT, Section, WIDE, claims, pts2, row, sig};

/// The slides of this group.
pub fn sections(ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    Ok(vec![
        three_sets(ctx)?,
        definition(ctx)?,
        koksma_hlawka(ctx)?,
        measured(ctx)?,
    ])
}

fn three_sets(ctx: &Ctx) -> Result<Section, Failure> {
    let n = 64u32;
    let seeds = ctx.pick(32u64, 256);
    let ind = pts2(&Independent::new(2, 1)?, n, (0, 1))?;
    let strat = pts2(&Stratified::new(&[8, 8], Jitter::Random(1))?, n, (0, 1))?;
    let lp = pts2(&LarcherPillichshammer::new(6)?, n, (0, 1))?;
    let (di, ds, dl) = (ctx.star(&ind)?, ctx.star(&strat)?, ctx.star(&lp)?);
    let mut mi = 0.0;
    let mut ms = 0.0;
    // The smallest and largest D* of the random sets over the seeds.
    let (mut ri, mut rs) = ((f64::INFINITY, 0.0f64), (f64::INFINITY, 0.0f64));
    for seed in 0..seeds {
        let i = ctx.star(&pts2(&Independent::new(2, seed + 100)?, n, (0, 1))?)?;
        let t = ctx.star(&pts2(
            &Stratified::new(&[8, 8], Jitter::Random(seed + 100))?,
            n,
            (0, 1),
        )?)?;
        (mi, ms) = (mi + i, ms + t);
        (ri, rs) = ((ri.0.min(i), ri.1.max(i)), (rs.0.min(t), rs.1.max(t)));
    }
    let mut s = Section::new(
        "three-point-sets",
        "Three 2D point sets and their discrepancy D*",
        format!(
            "{n} independent, jittered (8x8 strata) and Larcher-Pillichshammer points; D* is the \
         exact star discrepancy max over anchored boxes |n(x,y)/N - xy| (open and closed boxes), \
         for the drawn set and as a mean over {seeds} seeds."
        ),
    );
    s.figures.push(ctx.figure(
        "three-independent.svg",
        &PointsFigure::new(format!("Independent, D* = {}", sig(di, 3)), ind),
        PLOT,
        "independent",
    )?);
    s.figures.push(ctx.figure(
        "three-stratified.svg",
        &PointsFigure::new(format!("Stratified, D* = {}", sig(ds, 3)), strat).intervals(8, 8),
        PLOT,
        "stratified (jittered)",
    )?);
    s.figures.push(ctx.figure(
        "three-lp.svg",
        &PointsFigure::new(format!("Larcher-Pillichshammer, D* = {}", sig(dl, 3)), lp),
        PLOT,
        "Larcher-Pillichshammer",
    )?);
    s.rows
        .push(row("D* independent (this set)", sig(di, 3), "0.148"));
    s.rows.push(row(
        format!("D* independent (mean of {seeds} sets)"),
        sig(mi / seeds as f64, 3),
        "0.148",
    ));
    s.rows
        .push(row("D* stratified (this set)", sig(ds, 3), "0.081"));
    s.rows.push(row(
        format!("D* stratified (mean of {seeds} sets)"),
        sig(ms / seeds as f64, 3),
        "0.081",
    ));
    s.rows
        .push(row("D* Larcher-Pillichshammer", sig(dl, 3), "0.041"));
    let (mi, ms) = (mi / seeds as f64, ms / seeds as f64);
    s.note = format!(
        "The lecture does not state N or its random sets; its order is independent > \
         stratified > LP. At N = {n}, {}; {}. Over the {seeds} seeds D* ranges from {} to {} \
         (independent) and from {} to {} (stratified).",
        claims::order(
            "the drawn sets",
            &[("independent", di), ("stratified", ds), ("LP", dl)]
        ),
        claims::order(
            &format!("the means over {seeds} seeds"),
            &[("independent", mi), ("stratified", ms), ("LP", dl)]
        ),
        sig(ri.0, 3),
        sig(ri.1, 3),
        sig(rs.0, 3),
        sig(rs.1, 3),
    );
    Ok(s)
}

fn definition(ctx: &Ctx) -> Result<Section, Failure> {
    let m = ctx.pick(10, 12);
    let ns: Vec<u32> = (2..=m).map(|k| 1u32 << k).collect();
    let halton = Halton::new(2)?;
    let mut seq = Vec::new();
    let mut set = Vec::new();
    let mut rate = Vec::new();
    for &n in &ns {
        seq.push((n as f64, ctx.star(&pts2(&halton, n, (0, 1))?)?));
        set.push((
            n as f64,
            ctx.star(&pts2(&Hammersley::new(n as u64, 2)?, n, (0, 1))?)?,
        ));
        let l = (n as f64).ln();
        rate.push((n as f64, l / n as f64));
    }
    let fig = ConvergenceFigure {
        y_label: "D*".into(),
        reference: false,
        ..ConvergenceFigure::new(
            "star discrepancy against N",
            vec![
                Curve {
                    label: "Halton (sequence)".into(),
                    points: seq,
                },
                Curve {
                    label: "Hammersley (set)".into(),
                    points: set,
                },
                Curve {
                    label: "log N / N".into(),
                    points: rate,
                },
            ],
        )
    };
    let slopes = fig.slopes();
    let mut s = Section::new(
        "low-discrepancy-definition",
        "Low-discrepancy definition: D_n = O((log n)^d / n) for sequences, O((log n)^(d-1) / n) for sets",
        format!(
            "Exact D* of the first N Halton points (a 2D sequence) and of the N-point Hammersley \
         set (a 2D set), N = 4 .. 2^{m}, against log N / N."
        ),
    );
    s.figures
        .push(ctx.figure("ld-rates.svg", &fig, WIDE, "D* against N")?);
    let names = ["Halton", "Hammersley", "log N / N"];
    for (name, sl) in names.iter().zip(&slopes) {
        s.rows.push(row(
            format!("fitted slope of log D*, {name}"),
            sl.map_or("-".into(), |v| sig(v, 3)),
            "near -1 (up to log factors)",
        ));
    }
    if let [Some(seq), Some(set), Some(reference)] = slopes[..] {
        s.note = format!(
            "Over these N, log N / N itself fits a slope of {}. The Hammersley set's fitted \
             slope ({}) is {} the Halton sequence's ({}){}.",
            sig(reference, 3),
            sig(set, 3),
            if set < seq {
                "steeper than"
            } else {
                "not steeper than"
            },
            sig(seq, 3),
            if set < seq {
                ", as one power of log N less predicts"
            } else {
                ", although one power of log N less predicts a steeper one"
            }
        );
    }
    Ok(s)
}

fn koksma_hlawka(ctx: &Ctx) -> Result<Section, Failure> {
    let m = ctx.pick(10, 12);
    let ns: Vec<u32> = (2..=m).map(|k| 1u32 << k).collect();
    let sobol = Sobol::new(2)?;
    let (mut err, mut bound) = (Vec::new(), Vec::new());
    let mut worst_ratio = 0.0f64;
    let mut below = 0;
    for &n in &ns {
        let p = pts2(&sobol, n, (0, 1))?;
        // f(x, y) = x y: integral 1/4, Hardy-Krause variation (anchored at 1) 1 + 1 + 1 = 3.
        let e = (p.iter().map(|q| q[0] * q[1]).sum::<f64>() / n as f64 - 0.25).abs();
        let b = 3.0 * ctx.star(&p)?;
        worst_ratio = worst_ratio.max(e / b);
        below += usize::from(e <= b);
        err.push((n as f64, e));
        bound.push((n as f64, b));
    }
    let fig = ConvergenceFigure {
        reference: false,
        ..ConvergenceFigure::new(
            "f(x,y) = xy on Sobol' points",
            vec![
                Curve {
                    label: "bound V(f) D*".into(),
                    points: bound.clone(),
                },
                Curve {
                    label: "actual |error|".into(),
                    points: err.clone(),
                },
            ],
        )
    };
    let mut s = Section::new(
        "koksma-hlawka",
        "Koksma-Hlawka: |error| <= V(f) D_N, not a tight bound",
        "f(x, y) = xy (integral 1/4, Hardy-Krause variation V(f) = 3) integrated with the first N \
         Sobol' points: the bound 3 D* against the actual error.",
    );
    s.figures
        .push(ctx.figure("koksma-hlawka.svg", &fig, WIDE, "bound vs actual error")?);
    let last = ns.len() - 1;
    s.rows.push(row(
        format!("bound at N = {}", ns[last]),
        sig(bound[last].1, 3),
        "",
    ));
    s.rows.push(row(
        format!("actual error at N = {}", ns[last]),
        sig(err[last].1, 3),
        "",
    ));
    s.rows.push(row(
        "largest error / bound over N",
        sig(worst_ratio, 3),
        "not a tight bound (< 1)",
    ));
    s.note = format!(
        "{}; at its closest it is {} of the bound{}.",
        claims::count(
            below,
            ns.len(),
            "sizes N",
            "the actual error is at most the bound"
        ),
        sig(worst_ratio, 3),
        if worst_ratio < 0.5 {
            ", so here the bound is loose by more than a factor of 2 at every N"
        } else {
            ", within a factor of 2 at some N"
        }
    );
    Ok(s)
}

fn measured(ctx: &Ctx) -> Result<Section, Failure> {
    let m = ctx.pick(12, 16);
    let seeds = ctx.pick(16u64, 64);
    let ns: Vec<u32> = (2..=m).map(|k| 1u32 << k).collect();
    let squares: Vec<u32> = (1..=m / 2).map(|k| 1u32 << (2 * k)).collect();
    let f = Integrand::Gaussian;
    let mc = rmse_curve(|s| Independent::new(2, s), f, &ns, seeds)?;
    let mut jit = Vec::new();
    for &n in &squares {
        let k = (n as f64).sqrt() as u32;
        jit.extend(rmse_curve(
            |s| Stratified::new(&[k, k], Jitter::Random(s)),
            f,
            &[n],
            seeds,
        )?);
    }
    let halton = rmse_curve(|_| Halton::new(2), f, &ns, 1)?;
    let sobol = rmse_curve(|_| Sobol::new(2), f, &ns, 1)?;
    let owen = rmse_curve(|s| OwenSobol::new(2, s), f, &ns, seeds)?;
    let fig = ConvergenceFigure::new(
        "Gaussian peak, 2D: RMS error",
        vec![
            Curve {
                label: "MC".into(),
                points: mc,
            },
            Curve {
                label: "jittered".into(),
                points: jit,
            },
            Curve {
                label: "Halton".into(),
                points: halton,
            },
            Curve {
                label: "Sobol'".into(),
                points: sobol,
            },
            Curve {
                label: "Sobol' + fast-owen".into(),
                points: owen,
            },
        ],
    );
    let slopes = fig.slopes();
    let mut s = Section::new(
        "measured-qmc-error",
        "Measured quasi-Monte Carlo error",
        format!(
            "RMS error (over {seeds} seeds for the randomized samplers) of the 2D Gaussian peak \
         exp(-16|x-c|^2) against N = 4 .. 2^{m}; slopes are least-squares fits of log error on log N."
        ),
    );
    s.figures
        .push(ctx.figure("measured-error.svg", &fig, WIDE, "error against N")?);
    let expected = [
        "-0.5 (O(1/sqrt N))",
        "-1 (d = 2: N^-(1/2 + 1/d))",
        "~ -1 ((log N)^d / N)",
        "~ -1 ((log N)^d / N)",
        "-1.5 (smooth f)",
    ];
    let rates = [-0.5, -1.0, -1.0, -1.0, -1.5];
    let names = [
        "MC",
        "jittered",
        "Halton",
        "Sobol'",
        "Sobol' + fast-owen (hash-based Owen scrambling)",
    ];
    for ((name, sl), e) in names.iter().zip(&slopes).zip(expected) {
        s.rows.push(row(
            format!("fitted slope, {name}"),
            sl.map_or("-".into(), |v| sig(v, 3)),
            e,
        ));
    }
    let against: Vec<(&str, Option<f64>, f64)> = names
        .iter()
        .zip(&slopes)
        .zip(rates)
        .map(|((name, sl), rate)| (*name, *sl, rate))
        .collect();
    const TOLERANCE: f64 = 0.25;
    // Unscrambled Sobol' (index 3) steeper than its stated rate: the symmetry explains it.
    let lucky = slopes[3].is_some_and(|v| v < rates[3] - TOLERANCE);
    s.note = format!(
        "The lecture's plot has no printed slopes; the column gives the rates the lecture \
         states. {}{}",
        claims::slopes_against_rates(&against, TOLERANCE),
        if lucky {
            " Unscrambled Sobol' is steeper than its stated rate because the Gaussian peak is \
             symmetric about the centre, as are its 2^m-point nets; scrambling removes that luck."
        } else {
            ""
        }
    );
    Ok(s)
}
