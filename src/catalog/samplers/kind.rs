//! What a sampler construction is: its kind, its family (which decides the randomizers
//! that apply), its size (a sequence, a set of a given size, or a set built whole) and its
//! dimensions.

/// A sampler construction of [`SAMPLERS`](super::SAMPLERS).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SamplerKind {
    /// Independent uniform points.
    Independent,
    /// Jittered (or centred) stratified grid.
    Stratified,
    /// Latin hypercube.
    Latin,
    /// Van der Corput sequence.
    Vdc,
    /// Halton sequence.
    Halton,
    /// Hammersley set.
    Hammersley,
    /// Larcher–Pillichshammer net.
    Lp,
    /// Sobol' sequence.
    Sobol,
    /// Rank-1 lattice.
    Lattice,
    /// Kronecker sequence.
    Kronecker,
    /// Faure sequence.
    Faure,
    /// Poisson disk (Bridson), built whole.
    Poisson,
    /// Mitchell's best candidate, built whole.
    BestCandidate,
    /// Gaussian blue noise, built whole.
    GaussianBlueNoise,
    /// Progressive multi-jittered (0, 2)-sequence.
    Pmj02,
    /// PMJ02 with blue noise, built whole.
    Pmj02bn,
    /// Correlated multi-jittered sampling.
    Cmj,
    /// Hexagonal grid on the torus.
    Hex,
    /// Two-dimensional rank-1 lattice of maximal minimum distance.
    MaximinLattice,
    /// Lloyd relaxation, built whole.
    Lloyd,
    /// Capacity-constrained Voronoi tessellation, built whole.
    Ccvt,
    /// Sliced optimal transport sampling, built whole.
    Sot,
    /// Blue noise through optimal transport (BNOT), built whole.
    Bnot,
    /// Projective blue noise (dart throwing in the full space and its projections), built
    /// whole.
    ProjectiveBlueNoise,
    /// Forced random sampling (a blue-noise rank matrix thresholded), built whole.
    ForcedRandom,
    /// Cascaded Sobol': consecutive pairs of dimensions are (0, m, 2)-nets.
    CascadedSobol,
    /// Low-discrepancy blue noise: a Sobol' net rearranged by a look-up table, built whole.
    Ldbn,
    /// Penrose-tiling sampling (ranked subdivision), built whole.
    Penrose,
    /// AA patterns: one point a grid cell, displaced by a table indexed by an additive
    /// automaton's label, built whole.
    AaPatterns,
    /// Adaptive regular tiles: one point a tile of a `4 x 4` subdivision, ranked, built
    /// whole.
    Art,
    /// Step blue noise (spectrum-controlled), built whole.
    StepBlueNoise,
    /// Single-peak blue noise (spectrum-controlled), built whole.
    SinglePeakBlueNoise,
    /// Kernel-density blue noise at a temperature, built whole.
    KdeBlueNoise,
}

/// What a construction is, as far as randomizers care ([`applies`](crate::catalog::applies)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// Base-2 digital: every coordinate is `C_k i` over GF(2) (sobol, lp, vdc in base 2):
    /// [`crate::Base2Digital`], which every base-2 randomizer keeps a net.
    Base2Digital,
    /// Radical inverses in base `b` with a digit scramble inside (halton, hammersley, vdc
    /// in a base other than 2): [`crate::randomize::digits::DigitScramble`].
    RadicalInverse,
    /// A digital net in a prime base `b` (faure): base-`b` digit scrambles.
    BaseBNet,
    /// Lattice rules and Kronecker sequences: random shifts modulo 1.
    Lattice,
    /// Random constructions whose randomness is their own (independent, stratified,
    /// latin, pmj02, pmj02bn, cmj, cascaded-sobol).
    Random,
    /// Blue-noise sets built whole (poisson, best-candidate, gaussian-blue-noise, lloyd,
    /// ccvt, sot, projective-blue-noise, forced-random, bnot, ldbn, penrose, aa-patterns, art,
    /// step-blue-noise, single-peak-blue-noise, kde-blue-noise).
    BlueNoise,
}

impl Family {
    /// The family in words, with its members.
    pub const fn describe(self) -> &'static str {
        match self {
            Family::Base2Digital => "base-2 digital constructions (sobol, lp, vdc base 2)",
            Family::RadicalInverse => "radical inverses (halton, hammersley, vdc base b)",
            Family::BaseBNet => "base-b digital nets (faure)",
            Family::Lattice => "lattices (lattice, kronecker, hex)",
            Family::Random => {
                "random constructions (independent, stratified, latin, pmj02, pmj02bn, cmj, cascaded-sobol)"
            }
            Family::BlueNoise => {
                "blue-noise sets (poisson, best-candidate, gaussian-blue-noise, lloyd, ccvt, sot, \
                 projective-blue-noise, forced-random, bnot, ldbn, penrose, aa-patterns, art, \
                 step-blue-noise, single-peak-blue-noise, kde-blue-noise)"
            }
        }
    }
}

/// How many points a construction has and who says so.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Size {
    /// A sequence of `2^32` points: `points` does not apply.
    Sequence,
    /// A finite set of `points` points (needed; stratified may take it from `strata`).
    Set,
    /// A lattice rule: without `points` the extensible rule (radical-inverse order, `2^20`
    /// points), with it the `points`-point rule in linear order.
    Rule,
    /// A set built whole, at super-linear cost, within the time budget: about `points`
    /// points (poisson may take a radius instead).
    Whole,
}

impl SamplerKind {
    /// The family, which decides the randomizers. Van der Corput depends on its base:
    /// base-2 digital in base 2 (the default), a radical inverse otherwise.
    pub const fn family(self, base: Option<u32>) -> Family {
        match self {
            SamplerKind::Sobol | SamplerKind::Lp => Family::Base2Digital,
            SamplerKind::Vdc => match base {
                None | Some(2) => Family::Base2Digital,
                Some(_) => Family::RadicalInverse,
            },
            SamplerKind::Halton | SamplerKind::Hammersley => Family::RadicalInverse,
            SamplerKind::Faure => Family::BaseBNet,
            SamplerKind::Lattice
            | SamplerKind::Kronecker
            | SamplerKind::Hex
            | SamplerKind::MaximinLattice => Family::Lattice,
            SamplerKind::Independent
            | SamplerKind::Stratified
            | SamplerKind::Latin
            | SamplerKind::Pmj02
            | SamplerKind::Pmj02bn
            | SamplerKind::Cmj
            | SamplerKind::CascadedSobol => Family::Random,
            SamplerKind::Poisson
            | SamplerKind::BestCandidate
            | SamplerKind::GaussianBlueNoise
            | SamplerKind::Lloyd
            | SamplerKind::Ccvt
            | SamplerKind::Sot
            | SamplerKind::Bnot
            | SamplerKind::ProjectiveBlueNoise
            | SamplerKind::ForcedRandom
            | SamplerKind::Ldbn
            | SamplerKind::Penrose
            | SamplerKind::AaPatterns
            | SamplerKind::Art
            | SamplerKind::StepBlueNoise
            | SamplerKind::SinglePeakBlueNoise
            | SamplerKind::KdeBlueNoise => Family::BlueNoise,
        }
    }

    /// Its size rule.
    pub const fn size(self) -> Size {
        match self {
            SamplerKind::Stratified
            | SamplerKind::Latin
            | SamplerKind::Hammersley
            | SamplerKind::Lp
            | SamplerKind::Cmj
            | SamplerKind::CascadedSobol
            | SamplerKind::Hex
            | SamplerKind::MaximinLattice => Size::Set,
            SamplerKind::Lattice => Size::Rule,
            SamplerKind::Pmj02bn
            | SamplerKind::Poisson
            | SamplerKind::BestCandidate
            | SamplerKind::GaussianBlueNoise
            | SamplerKind::Lloyd
            | SamplerKind::Ccvt
            | SamplerKind::Sot
            | SamplerKind::Bnot
            | SamplerKind::ProjectiveBlueNoise
            | SamplerKind::ForcedRandom
            | SamplerKind::Ldbn
            | SamplerKind::Penrose
            | SamplerKind::AaPatterns
            | SamplerKind::Art
            | SamplerKind::StepBlueNoise
            | SamplerKind::SinglePeakBlueNoise
            | SamplerKind::KdeBlueNoise => Size::Whole,
            _ => Size::Sequence,
        }
    }

    /// The dimensions when `dims` is not given: 1 for vdc, 2 otherwise.
    pub const fn default_dims(self) -> usize {
        match self {
            SamplerKind::Vdc => 1,
            _ => 2,
        }
    }

    /// The only dimension count the construction has, if it has one (vdc 1; lp, pmj02,
    /// pmj02bn, best-candidate, gaussian-blue-noise, forced-random, bnot, hex,
    /// maximin-lattice, ldbn, penrose,
    /// aa-patterns and art 2).
    pub const fn fixed_dims(self) -> Option<usize> {
        match self {
            SamplerKind::Vdc => Some(1),
            SamplerKind::Lp
            | SamplerKind::Pmj02
            | SamplerKind::Pmj02bn
            | SamplerKind::BestCandidate
            | SamplerKind::GaussianBlueNoise
            | SamplerKind::ForcedRandom
            | SamplerKind::Bnot
            | SamplerKind::Hex
            | SamplerKind::MaximinLattice
            | SamplerKind::Ldbn
            | SamplerKind::Penrose
            | SamplerKind::AaPatterns
            | SamplerKind::Art => Some(2),
            _ => None,
        }
    }

    /// Whether the points depend on the seed without a randomizer.
    pub const fn is_random(self) -> bool {
        matches!(self.family(None), Family::Random | Family::BlueNoise)
    }
}
