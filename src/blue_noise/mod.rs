//! Blue-noise constructions: point sets and dither masks whose power spectra are low at low
//! frequencies.
//!
//! * [`PoissonDisk`] — Bridson's algorithm in 1 to 8 dimensions, on the cube or the torus,
//!   by radius or by an approximate count, optionally maximal.
//! * [`BestCandidate`] — Mitchell's best-candidate sampling on the torus (progressive).
//! * [`GaussianBlueNoise`] — Ahmed, Ren & Wonka's Gaussian blue noise on the torus.
//! * [`Lloyd`] — Lloyd relaxation and capacity-constrained Voronoi tessellations (CCVT,
//!   Balzer, Schlömer & Deussen 2009) in any dimension, in the cube or on the torus;
//!   Lloyd in 2D and 3D on exact Voronoi cells ([`power`], [`voronoi3`]).
//! * [`Bnot`] — blue noise through optimal transport (de Goes et al. 2012) in the square
//!   or on the torus, 2D, on exact power diagrams ([`power`]) with equal capacities solved
//!   by damped Newton ([`transport`]).
//! * [`ProjectiveBlueNoise`] — projective blue noise (Reinert et al. 2016): dart throwing
//!   that keeps radii in the full space and in every 1D and 2D axis projection, 2 to 8
//!   dimensions, on the torus.
//! * [`Sot`] — sliced optimal transport sampling (Paulin et al. 2020) in the cube,
//!   optionally projective (directions also drawn in the 1D and 2D axis subspaces).
//! * [`ForcedRandom`] — forced random sampling (Cornel et al. 2017): a blue-noise rank
//!   matrix thresholded against an importance density, 2D.
//! * [`Ldbn`] — low-discrepancy blue noise (Ahmed et al. 2016): the Sobol' (0, m, 2)-net,
//!   its in-cell offsets permuted within `16 x 16`-cell tiles by an optimized look-up
//!   table, still a net.
//! * [`Penrose`] — one sample a tile of a subdivided Penrose tiling, ranked for
//!   thresholding (Ostromoukhov, Donohue & Jodoin 2004); [`penrose::importance`] samples a
//!   density; [`penrose_train`] makes its correction table.
//! * [`AaPattern`] — AA patterns (after Ahmed, Huang & Deussen 2015): one point a grid
//!   cell, displaced by a table indexed by the cell's label under a discrete irrational
//!   rotation of the lattice (an additive automaton).
//! * [`Art`] — adaptive regular tiles (after Ahmed, Niese, Huang & Deussen 2017): one
//!   point a tile of a recursive `4 x 4` subdivision, offsets from a table indexed by the
//!   tile's word, progressive by ranks; [`art::importance`] follows a density.
//! * [`SpectralBlueNoise`] — step and single-peak blue noise (Heck, Schlömer & Deussen
//!   2013): a target radial spectrum, its pair correlation by the Hankel transform, points
//!   by gradient descent on the mismatch, on the torus in 1 to 6 dimensions.
//! * [`KdeBlueNoise`] — kernel-density blue noise (Fattal 2011): a Gibbs sample at
//!   temperature `T` of the model whose energy is the kernel density estimate's mismatch,
//!   on the torus in 1 to 5 dimensions.
//! * [`VoidAndCluster`] — Ulichney's void-and-cluster rank masks, toroidal, up to 2048².
//! * [`mask64`] — a 64×64 void-and-cluster rank mask as a static table, in `no_std` too.
//!
//! The set constructions need the `analysis` feature (they are budgeted like every
//! super-linear computation of the crate, see [`crate::work`]); they return a
//! [`PointSet`], a finite [`Sampler`](crate::Sampler) of 0.32 fractions in generation order.
// Without `analysis` the set constructions are absent and their links above are text.
#![cfg_attr(not(feature = "analysis"), allow(rustdoc::broken_intra_doc_links))]

pub mod mask64;

#[cfg(feature = "analysis")]
pub mod aa;
#[cfg(feature = "analysis")]
pub mod art;
#[cfg(feature = "analysis")]
mod bessel;
#[cfg(feature = "analysis")]
pub mod best_candidate;
#[cfg(feature = "analysis")]
pub mod bnot;
#[cfg(feature = "analysis")]
mod bridson;
#[cfg(feature = "analysis")]
mod cell3;
#[cfg(feature = "analysis")]
pub mod force_field;
#[cfg(feature = "analysis")]
pub mod forced_random;
#[cfg(feature = "analysis")]
pub mod gaussian;
#[cfg(feature = "analysis")]
mod grid;
#[cfg(feature = "analysis")]
pub mod kde;
#[cfg(feature = "analysis")]
mod kdtree;
#[cfg(feature = "analysis")]
mod keysort;
#[cfg(feature = "analysis")]
mod lbfgs;
#[cfg(feature = "analysis")]
pub mod ldbn;
#[cfg(feature = "analysis")]
pub mod lloyd;
#[cfg(feature = "analysis")]
pub mod lloyd_projective;
#[cfg(feature = "analysis")]
pub mod penrose;
#[cfg(feature = "analysis")]
pub mod penrose_train;
#[cfg(feature = "analysis")]
mod point_set;
#[cfg(feature = "analysis")]
pub mod poisson;
#[cfg(feature = "analysis")]
mod poisson_cost;
#[cfg(feature = "analysis")]
pub mod power;
#[cfg(feature = "analysis")]
pub mod projective;
#[cfg(feature = "analysis")]
mod projective_grid;
#[cfg(feature = "analysis")]
mod rng;
#[cfg(feature = "analysis")]
mod shell;
#[cfg(feature = "analysis")]
mod sites;
#[cfg(feature = "analysis")]
pub mod sot;
#[cfg(feature = "analysis")]
pub mod spectral;
#[cfg(feature = "analysis")]
mod tiles;
#[cfg(feature = "analysis")]
mod torus_cells;
#[cfg(feature = "analysis")]
mod tournament;
#[cfg(feature = "analysis")]
pub mod transport;
#[cfg(feature = "analysis")]
mod verlet;
#[cfg(feature = "analysis")]
pub mod void_and_cluster;
#[cfg(feature = "analysis")]
pub mod voronoi3;

#[cfg(feature = "analysis")]
pub use aa::AaPattern;
#[cfg(feature = "analysis")]
pub use art::Art;
#[cfg(feature = "analysis")]
pub use best_candidate::BestCandidate;
#[cfg(feature = "analysis")]
pub use bnot::{BNOT_DEFAULT_RESIDUAL, Bnot, BnotTrace};
#[cfg(feature = "analysis")]
pub use forced_random::{FORCING_MATRIX, FORCING_SIDE, ForcedRandom};
#[cfg(feature = "analysis")]
pub use gaussian::GaussianBlueNoise;
#[cfg(feature = "analysis")]
pub use kde::{KDE_MAX_DENSITY_RATIO, KDE_MAX_LEVELS, KdeBlueNoise};
#[cfg(feature = "analysis")]
pub use ldbn::Ldbn;
#[cfg(feature = "analysis")]
pub use lloyd::{Lloyd, LloydTrace};
#[cfg(feature = "analysis")]
pub use penrose::Penrose;
#[cfg(feature = "analysis")]
pub use point_set::PointSet;
#[cfg(feature = "analysis")]
pub use poisson::PoissonDisk;
#[cfg(feature = "analysis")]
pub use projective::{ProjectiveBlueNoise, ProjectiveSet};
#[cfg(feature = "analysis")]
pub use sot::Sot;
#[cfg(feature = "analysis")]
pub use spectral::SpectralBlueNoise;
#[cfg(feature = "analysis")]
pub use void_and_cluster::{RankMask, VoidAndCluster};
