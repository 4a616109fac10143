//! Stand-in for `scenes.rs` until `qmckit::analysis::scene` is merged: the five rendered
//! slides with the lecture's numbers and a note that the renders are not built in.
//! TODO(integrator): delete this file once `mod scenes;` compiles (see report/mod.rs).

use super::{Ctx, Section, row};
use crate::Failure;

/// A slide: id, title, and (sampler, the lecture's relative MSE) pairs.
type Slide = (
    &'static str,
    &'static str,
    &'static [(&'static str, &'static str)],
);

/// The slides of this group.
pub fn sections(_ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    let slides: [Slide; 5] = [
        (
            "mse-tables-n16",
            "MSE tables at n = 16",
            &[
                ("stratified", "1/2.41x, 1/2.12x"),
                ("Sobol'", "1/3.38x, 1/3.95x"),
            ],
        ),
        ("quad-light", "Warping samples to a quad light", &[]),
        (
            "motion-blur-defocus",
            "Sampling motion blur + defocus",
            &[("Halton", "1/1.13x"), ("Sobol'", "1/1.80x")],
        ),
        ("pixel-light", "Pixel x light sampling", &[]),
        (
            "ambient-occlusion",
            "Ambient occlusion: white vs blue noise",
            &[],
        ),
    ];
    Ok(slides
        .iter()
        .map(|(id, title, numbers)| {
            let mut s = Section::new(
                id,
                title,
                "Not rendered in this build: the scene studies (qmckit::analysis::scene) are not \
                 part of it yet.",
            );
            for (what, lecture) in numbers.iter() {
                s.rows.push(row(
                    format!("MSE relative to independent, {what}"),
                    "not measured",
                    *lecture,
                ));
            }
            s
        })
        .collect())
}
