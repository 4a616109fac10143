//! Warps: maps from the unit square to the domains renderers and simulations integrate over,
//! each with its density and its inverse, so that stratified and low-discrepancy samples
//! keep their structure on the target domain.
//!
//! Every warp comes as a triple, in pbrt-v4's style: `sample_*(u)` maps `u` in `[0, 1)^2` to
//! the domain, `*_pdf` is the density of the result (per unit area or solid angle), and
//! `invert_*` maps a point of the domain back to `u`. Inputs are `f32` fractions (convert
//! samples with [`crate::bits::to_f32`]); math goes through the `libm` crate, so the results
//! are the same bits on every platform, with or without an FPU.
//!
//! * [`disk`]: uniform disk by the polar map (`theta = 2 pi u0`, `r = sqrt(u1)`) and by
//!   Shirley & Chiu's concentric map (1997), which keeps strata compact.
//! * [`sphere`]: uniform sphere, uniform and cosine-weighted hemisphere (Malley's method on
//!   the concentric disk), and uniform cone.
//! * [`triangle`]: uniform triangle by Heitz's low-distortion map (2019).
//! * [`spherical`]: uniform directions toward a rectangle (Ureña et al. 2013, for quad
//!   lights) or a triangle (Arvo 1995), by solid angle.
//! * [`gaussian`]: standard normal by Box–Muller and by the inverse CDF.
//! * [`fixed`]: the disk, hemisphere and triangle warps in integer arithmetic (Q30), for
//!   targets without an FPU.
//!
//! The float warps need the `libm` feature (implied by `std`); [`fixed`] needs only the
//! `fixed` feature.
// Without `fixed` the fixed-point warps are absent and their links above are text.
#![cfg_attr(not(feature = "fixed"), allow(rustdoc::broken_intra_doc_links))]

#[cfg(feature = "libm")]
pub mod disk;
#[cfg(feature = "fixed")]
pub mod fixed;
#[cfg(feature = "libm")]
pub mod gaussian;
#[cfg(feature = "libm")]
pub mod sphere;
#[cfg(feature = "libm")]
pub mod spherical;
#[cfg(feature = "libm")]
pub mod triangle;

/// pi as `f32`.
#[cfg(feature = "libm")]
pub(crate) const PI: f32 = core::f32::consts::PI;

/// The largest coordinate magnitude the geometric warps accept ([`triangle::Triangle`],
/// [`spherical::SphericalRectangle`], [`spherical::SphericalTriangle`]): `2^64`. Every
/// point they produce (a convex combination of vertices, or a corner plus fractions of
/// two edges) is then a finite `f32`, and every product of up to six coordinates stays far
/// inside the `f64` range used for the spherical maps.
#[cfg(feature = "libm")]
pub const MAX_COORDINATE: f32 = 18_446_744_073_709_551_616.0;

/// The largest `f32` below 1: `1 - 2^-24`.
pub const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// `atan2(y, x) / (2 pi)` wrapped into `[0, 1)`: the fraction of a turn of the direction
/// `(x, y)` (0 for the origin).
#[cfg(feature = "libm")]
#[inline]
pub(crate) fn turn_fraction(y: f32, x: f32) -> f32 {
    let t = libm::atan2f(y, x) / (2.0 * PI);
    let t = if t < 0.0 { t + 1.0 } else { t };
    if t >= 1.0 { 0.0 } else { t }
}
