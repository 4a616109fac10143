//! # qmckit — quasi-Monte Carlo sampling from microcontrollers to servers
//!
//! Low-discrepancy sequences and nets (radical inverse, van der Corput, Halton, Hammersley,
//! Larcher–Pillichshammer, [`Sobol`] with Joe–Kuo's 21201 dimensions, Faure, rank-1
//! lattices, Kronecker sequences), their randomizations ([`randomize`]: digital shift,
//! Cranley–Patterson, Owen exact and hash-based, linear matrix scrambling, index shuffling,
//! base-`b` digit permutations), and the classic random samplers they are measured against
//! (independent, stratified/jittered, Latin hypercube), all as pure random-access functions
//! of `(index, dimension)`. [`prelude`] brings the [`Sampler`] trait, the main samplers and
//! [`Error`]/[`Result`] into scope.
//!
//! ## The tree, by layer
//!
//! Each layer builds on the ones above it. The exceptions reach into [`randomize`], which
//! itself needs only the core: constructions apply some randomizations inside them (the
//! base-`b` digit scrambles of [`RadicalInverse`], [`OwenSobol`]'s hash-based Owen
//! scrambling), and [`Base2Digital::fill_affine`] takes its affine maps ([`bits::Affine`]).
//! No module outside `analysis` imports `analysis` (but `catalog`, above it); run-time CPU
//! dispatch is a leaf that imports nothing of the crate. `scripts/check_layers.py` checks
//! this in CI: no import cycle, and every import goes to the module's own layer or an
//! earlier one in the order core, randomize, constructions, uses, analysis, `catalog`.
//!
//! | layer | modules |
//! |---|---|
//! | core | [`bits`] (0.32 fractions, conversions), [`hash`] (integer hashes and keyed permutations), [`error`], [`size`] (checked sizes and allocations), [`work`] (cost estimates, budgets, deadlines), run-time CPU dispatch; [`sampler`] (the [`Sampler`] trait) |
//! | constructions | [`radical_inverse`] (with van der Corput, Halton, Hammersley), [`digital`] (Sobol', Larcher–Pillichshammer, Faure, base-`b` nets, base-2 nets and their t-values by the rank test), [`lattice`] (rank-1 lattices, Kronecker), [`random`] (independent, stratified, Latin hypercube), [`pmj`] (progressive multi-jittered) |
//! | randomizations | [`randomize`] (shifts, Owen scrambling, matrix scrambling, shuffles, the tent map) |
//! | uses | [`pixel`] (renderers' pixel samplers), [`blue_noise`] (blue-noise sets and dither masks), [`warp`] (to disks, spheres, triangles, Gaussians), [`collect`] (`Vec`s of points), `buffer` (fixed-capacity points, feature `heapless`) |
//! | measurements | `analysis` (feature `analysis`: discrepancies, t-values by counting, spectra, integration error) |
//!
//! The `qmckit` command (generation, measurement, figures, the lecture's report) is not
//! part of this library: it is the package `qmckit-cli` in the repository's `cli/`.
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
//! | `analysis` | `analysis` (discrepancies, t-values, distances, spectra, integration; rayon, rustfft) and the blue-noise point sets; implies `std` |
//! | `sobol-dims-1024`, `sobol-dims-21201` | more Sobol' dimensions than the default 64 |
//! | `fixed` | `bits::to_fixed` to `fixed::types::U0F32`, fixed-point warps (`warp::fixed`) |
//! | `rand_core` | seeding from any `rand_core::Rng`, `random::independent::fill_from_rng` |
//! | `heapless` | `buffer::points`: fixed-capacity point buffers |
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
pub mod catalog;
#[cfg(feature = "std")]
pub mod collect;
pub mod digital;
pub(crate) mod dispatch;
pub mod error;
pub mod hash;
pub mod lattice;
pub mod pixel;
pub mod pmj;
pub mod prelude;
pub mod radical_inverse;
pub mod random;
pub mod randomize;
pub mod sampler;
pub mod size;
#[cfg(any(feature = "libm", feature = "fixed"))]
pub mod warp;
pub mod work;

pub use digital::lp::LarcherPillichshammer;
pub use digital::sobol::{OwenSobol, SOBOL_MAX_DIMS, Sobol};
pub use error::{Error, Result};
pub use radical_inverse::halton::{HALTON_MAX_DIMS, Halton};
pub use radical_inverse::hammersley::Hammersley;
pub use radical_inverse::van_der_corput::VanDerCorput;
pub use radical_inverse::{RadicalInverse, RadicalInverseIter};
pub use random::independent::Independent;
pub use random::latin_hypercube::LatinHypercube;
pub use random::stratified::{Jitter, Stratified};
pub use sampler::{Base2Digital, Sampler};

/// The README's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "analysis"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// The toolbox guide's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "analysis"))]
#[doc = include_str!("../docs/toolbox.md")]
pub struct ToolboxDoctests;

/// The analysis guide's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "analysis"))]
#[doc = include_str!("../docs/analysis.md")]
pub struct AnalysisDoctests;

/// The pixel-sampler guide's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/pixel-samplers.md")]
pub struct PixelSamplerDoctests;
