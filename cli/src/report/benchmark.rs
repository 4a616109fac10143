//! The integration benchmark (`qmckit integration-test`) as a report section: random
//! Gaussians and random Heavisides in 2D, integrated by white noise, jittered points,
//! Owen-scrambled Sobol' and PMJ02 over a range of N, with the fitted rates beside the
//! theory's.

use crate::integration_test::{Plan, curves};
use crate::plot::{ConvergenceFigure, Curve};
use qmckit::analysis::integrate::Family;

use super::super::Failure;
use super::{Ctx, Section, WIDE, claims, row};

/// The samplers of the section, and their theoretical rates on smooth integrands and on a
/// Heaviside in 2D: `(spec, smooth, heaviside)`.
const SAMPLERS: [(&str, f64, f64); 4] = [
    ("independent", -0.5, -0.5),
    ("stratified", -1.0, -0.75),
    ("sobol+owen", -1.5, -0.75),
    ("pmj02", -1.5, -0.75),
];

/// The slides of this group.
pub fn sections(ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    let plan = |family| Plan {
        family,
        d: 2,
        min_m: 4,
        max_m: ctx.pick(10, 13),
        integrands: ctx.pick(64, 256),
        seed: 0,
    };
    let specs: Vec<String> = SAMPLERS.iter().map(|s| s.0.to_string()).collect();
    let mut s = Section::new(
        "integration-benchmark",
        "The integration benchmark: random Gaussians and Heavisides",
        format!(
            "The test graphics papers compare samplers with: {} random integrands with exact \
             integrals (anisotropic Gaussians; indicators of half-planes through random \
             points), each integrated with a fresh randomization of each sampler at N = 16 .. \
             {}; the curves are the root mean square errors, the rates their least-squares \
             slopes (qmckit integration-test).",
            plan(Family::Gaussian).integrands,
            1u64 << plan(Family::Gaussian).max_m
        ),
    );
    let mut notes = Vec::new();
    for (family, what, file) in [
        (Family::Gaussian, "smooth", "integration-gaussian.svg"),
        (Family::Heaviside, "Heaviside", "integration-heaviside.svg"),
    ] {
        ctx.budget.check_deadline("the integration benchmark")?;
        let blocks = curves(&specs, &plan(family), &ctx.budget)?;
        let fig = ConvergenceFigure {
            y_label: "RMSE".to_owned(),
            ..ConvergenceFigure::new(
                format!("random {} integrands, 2D", family.name()),
                blocks
                    .iter()
                    .map(|(label, c)| Curve {
                        label: label.clone(),
                        points: c.rmse.iter().map(|&(n, e)| (n as f64, e)).collect(),
                    })
                    .collect(),
            )
        };
        s.figures
            .push(ctx.figure(file, &fig, WIDE, format!("RMSE on {what} integrands"))?);
        let rates: Vec<(&str, Option<f64>, f64)> = SAMPLERS
            .iter()
            .zip(&blocks)
            .map(|(&(name, smooth, step), (_, c))| {
                let rate = if family == Family::Heaviside {
                    step
                } else {
                    smooth
                };
                (name, c.slope, rate)
            })
            .collect();
        for &(name, slope, rate) in &rates {
            s.rows.push(row(
                format!("{} rate, {name}", family.name()),
                slope.map_or_else(|| "-".to_owned(), |v| format!("{v:.2}")),
                format!("theory {rate}"),
            ));
        }
        notes.push(format!(
            "{}: {}",
            family.name(),
            claims::slopes_against_rates(&rates, 0.15)
        ));
    }
    s.note = format!(
        "The theory column holds the known rates (Monte Carlo -1/2; jittered -1 on smooth \
         integrands and -3/4 on a discontinuity in 2D; Owen-scrambled (0,2)-nets -3/2 up to \
         log factors, which flatten the fit at these N). {}.",
        notes.join("; ")
    );
    Ok(vec![s])
}
