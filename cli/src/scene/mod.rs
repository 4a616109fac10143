//! Analytic scenes for the lecture's render slides: spheres on a ground plane under a quad
//! light, rendered per pixel with qmckit's samplers, and the MSE of each sampler against
//! a high-sample reference (the lecture's "MSE 1x / 1/2.41x / 1/3.38x" tables).
//!
//! * [`geometry`]: rays, (moving) spheres, the ground plane and the quad light, with exact
//!   intersections (the quadratic for spheres).
//! * [`camera`]: pinhole, thin lens (defocus) and shutter time (motion blur).
//! * [`integrands`]: the per-pixel integrands (film area, light area by area sampling with
//!   the `cos cos / r^2` geometry term, lens and time, cosine-weighted ambient occlusion) and
//!   Lambert's closed-form polygon irradiance they are checked against.
//! * [`samplers`]: how independent, stratified, Halton, Sobol', Sobol' fast-owen and ZSobol points
//!   feed a pixel's dimensions, with a seed per pixel.
//! * [`study`] (re-exported here): reference image, renders, MSE over seeds and the error
//!   images' low-frequency power.
//!
//! Everything is deterministic for a seed. A study renders `W H` pixels with
//! `spp x seeds x samplers + reference_spp` samples each ([`Study::cost`], [`cost`]); a
//! sample is one camera ray plus at most one shadow or occlusion ray against three spheres
//! and a plane (a few million samples a second on two cores). Options are validated by
//! [`check`]: zero sizes, non-power-of-two sample counts or more than
//! [`MAX_STUDY_SAMPLES`] samples give an `Err`.
//!
//! ```
//! use qmckit_cli::scene::{StudyOptions, soft_shadow_study};
//! let o = StudyOptions { width: 16, height: 16, spp: 16, seeds: 2, reference_spp: 256 };
//! let s = soft_shadow_study(&o)?;
//! assert_eq!(s.mse[0].sampler, "independent");
//! assert!(s.mse[2].mse < s.mse[0].mse); // Sobol' fast-owen beats independent points
//! assert!(soft_shadow_study(&StudyOptions { spp: 12, ..o }).is_err());
//! # Ok::<(), qmckit::Error>(())
//! ```

pub mod camera;
pub mod geometry;
pub mod integrands;
pub mod samplers;
pub mod study;

pub use study::{
    MAX_PIXELS, MAX_STUDY_SAMPLES, MseEntry, PatternPair, REFERENCE_SEED, SceneImage, SceneStudy,
    Study, StudyOptions, ambient_occlusion_study, check, cost, low_band, motion_defocus_study,
    pixel_area_study, pixel_light_study, quad_light_extent, quad_light_points, quad_light_uv,
    reference_image, soft_shadow_study,
};
