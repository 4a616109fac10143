//! # qmckit — quasi-Monte Carlo sampling from microcontrollers to servers
//!
//! Low-discrepancy sequences and nets (radical inverse, van der Corput, Halton, Hammersley,
//! Larcher–Pillichshammer, [`Sobol`] with Joe–Kuo's 21201 dimensions), their
//! randomizations ([`randomize`]: digital shift, Cranley–Patterson, Owen exact and
//! hash-based, linear matrix scrambling, index shuffling, base-`b` digit permutations), and
//! the classic random samplers they are measured against (independent, stratified/jittered,
//! Latin hypercube), all as pure random-access functions of `(index, dimension)`.
//!
//! ## The integer is the sample
//!
//! A coordinate is a `u32` read as the 0.32 fixed-point fraction `x / 2^32` in `[0, 1)`.
//! Constructions are integer-only and exact (the radical inverse is `floor(phi_b(i) 2^32)`
//! to the last bit), so a Cortex-M0 without an FPU and an x86 server produce the same bits.
//! [`bits`] converts to `f32` (never 1.0), `f64` and, with the `fixed` feature, `U0F32`.
//!
//! ## No panics, no allocation
//!
//! The core is `#![no_std]` (unless the `std` feature is on) and never allocates. Invalid
//! parameters are reported once, by the fallible constructors, as an [`Error`]; validated
//! values answer hot calls cheaply. Most constructors and `sample` methods are `const fn`,
//! so firmware can bake a pattern into flash:
//!
//! ```
//! use qmckit::Halton;
//! const H: Halton = match Halton::new(2) { Ok(h) => h, Err(_) => panic!() };
//! /// 16 Halton points, computed by the compiler and stored in flash.
//! const PATTERN: [[u32; 2]; 16] = {
//!     let mut p = [[0u32; 2]; 16];
//!     let mut i = 0;
//!     while i < 16 {
//!         p[i] = match (H.sample(i as u32, 0), H.sample(i as u32, 1)) {
//!             (Ok(x), Ok(y)) => [x, y],
//!             _ => panic!(), // a compile error, never a run-time panic
//!         };
//!         i += 1;
//!     }
//!     p
//! };
//! assert_eq!(PATTERN[3], [0xC000_0000, 0x1C71_C71C]); // (3/4, 1/9)
//! ```
//!
//! ## Features
//!
//! | feature | brings |
//! |---|---|
//! | `std` (default) | [`collect`] (`Vec`-returning helpers), run-time CPU dispatch, `std::error::Error` for [`Error`] |
//! | `analysis` | `analysis` (discrepancies, t-values, distances, spectra; rayon, rustfft); implies `std` |
//! | `sobol-dims-1024`, `sobol-dims-21201` | more Sobol' dimensions than the default 64 |
//! | `fixed` | [`bits::to_fixed`] to `fixed::types::U0F32`, fixed-point warps ([`warp::fixed`]) |
//! | `rand_core` | seeding from any `rand_core::Rng`, [`independent::fill_from_rng`] |
//! | `heapless` | [`buffer::points`]: fixed-capacity point buffers |
//! | `libm` | the float warps ([`warp`]: disk, sphere, triangle, spherical, gaussian), also in `no_std`; implied by `std` |
//! | `defmt` | `defmt::Format` on the public types |
#![cfg_attr(not(feature = "std"), no_std)]
#![cfg_attr(docsrs, feature(doc_cfg))]
#![deny(unsafe_code)]
#![warn(missing_docs)]

#[cfg(feature = "analysis")]
pub mod analysis;
pub mod bits;
pub mod blue_noise;
#[cfg(feature = "heapless")]
pub mod buffer;
#[cfg(feature = "std")]
pub mod collect;
pub mod digital;
pub(crate) mod dispatch;
pub mod error;
/// Deprecated path of the fixed-point warps: use [`warp::fixed`].
#[cfg(feature = "fixed")]
#[deprecated(note = "the fixed-point warps moved to `qmckit::warp::fixed`")]
pub mod fixed_warp {
    pub use crate::warp::fixed::*;
}
pub mod halton;
pub mod hammersley;
pub mod hash;
pub mod independent;
pub mod kronecker;
pub mod larcher_pillichshammer;
pub mod latin_hypercube;
pub mod lattice;
pub mod pixel;
pub mod pmj;
/// The former home of the Owen-scrambled Sobol' fast paths, now [`sobol::OwenSobol`].
#[deprecated(note = "use qmckit::sobol::OwenSobol (one type, cheap reseed)")]
pub mod owen_sobol {
    pub use crate::sobol::{OwenSobol, owen_sobol, owen_sobol_f32};
}
pub mod radical_inverse;
pub mod randomize;
pub mod sampler;
pub mod size;
pub mod sobol;
pub mod stratified;
pub mod van_der_corput;
#[cfg(any(feature = "libm", feature = "fixed"))]
pub mod warp;
pub mod work;

pub use error::{Error, Result};
pub use halton::{HALTON_MAX_DIMS, Halton};
pub use hammersley::Hammersley;
pub use independent::Independent;
pub use larcher_pillichshammer::LarcherPillichshammer;
pub use latin_hypercube::LatinHypercube;
pub use radical_inverse::{RadicalInverse, RadicalInverseIter};
pub use sampler::{Base2Digital, Sampler};
pub use sobol::{OwenSobol, SOBOL_MAX_DIMS, Sobol};
pub use stratified::{Jitter, Stratified};
pub use van_der_corput::VanDerCorput;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The toolbox guide's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "analysis"))]
#[doc = include_str!("../docs/toolbox.md")]
pub struct ToolboxDoctests;

/// The analysis guide's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/analysis.md")]
pub struct AnalysisDoctests;

/// The pixel-sampler guide's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/pixel-samplers.md")]
pub struct PixelSamplerDoctests;
