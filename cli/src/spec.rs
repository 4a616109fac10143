//! The sampler a command names: the construction, its randomization, order and sizes
//! (`qmckit points`, `tvalue`, `convergence` and the toolbox build from it).

use clap::ValueEnum;

/// The constructions `points` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SamplerName {
    /// Independent uniform random points (hash of seed, index, dimension).
    Independent,
    /// Jittered stratified grid, one point in each of k^d cells.
    Stratified,
    /// Latin hypercube: one point in each of the n slabs of every axis.
    Latin,
    /// Van der Corput sequence, 1D (base 2; other bases in `points`).
    Vdc,
    /// Halton sequence: radical inverses in the first d primes.
    Halton,
    /// Hammersley set of N points: (i/N, phi_2(i), phi_3(i), ...).
    Hammersley,
    /// Larcher–Pillichshammer (0,m,2)-net, 2D, N a power of two.
    Lp,
    /// Sobol' sequence, Joe–Kuo direction numbers, up to 21201 dimensions.
    Sobol,
    /// Rank-1 lattice: Kuo's extensible vector (2^20 points, radical-inverse order).
    Lattice,
    /// Kronecker sequence frac(i alpha), alpha from the generalized golden ratio R_d.
    Kronecker,
    /// Faure (0,s)-sequence in a prime base b >= d (by default the smallest).
    Faure,
    /// Poisson disk (Bridson): --radius R or -n N (about N), -d D, --torus, --maximal.
    Poisson,
    /// Mitchell's best candidate on the torus, 2D (--candidates M).
    BestCandidate,
    /// Gaussian blue noise (Ahmed, Ren, Wonka 2022) on the torus, 2D (--iterations I).
    GaussianBlueNoise,
    /// PMJ02: progressive multi-jittered (0,2)-sequence, 2D, seeded (stochastic generation).
    Pmj02,
    /// PMJ02BN: PMJ02 spread by nested flips to blue noise, every prefix a (0,2)-net; 2D, seeded.
    Pmj02bn,
}

impl SamplerName {
    /// `-d` as given, else the construction's default: 1 for vdc, 2 otherwise.
    pub fn dims(self, d: Option<usize>) -> usize {
        d.unwrap_or(if self == SamplerName::Vdc { 1 } else { 2 })
    }
}

/// Randomization (`--scramble`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ScrambleName {
    /// No randomization.
    None,
    /// Random digital shift (XOR), base 2.
    Xor,
    /// Cranley–Patterson rotation (x + u mod 1), any construction; does not keep nets.
    Rotate,
    /// Owen scrambling: exact nested uniform in base 2; in base b for halton, hammersley, vdc.
    Owen,
    /// Hash-based Owen scrambling (Vegdahl's hash), base 2.
    FastOwen,
    /// Hash-based Owen scrambling (Laine–Karras hash), base 2.
    FastOwenLk,
    /// Random linear matrix scramble plus digital shift (SciPy's Sobol' scrambling), base 2.
    Lms,
    /// Burley's shuffled, hash-Owen-scrambled Sobol' (index shuffle + fast-owen), base 2.
    ShuffleOwen,
    /// Random digit permutations per digit position (halton, hammersley, vdc).
    Perm,
    /// Faure's digit permutations (halton, hammersley, vdc, faure).
    Faure,
    /// Random shift modulo 1 (lattice, kronecker; the same as rotate).
    Shift,
    /// Random shift, then the baker's (tent) transform 1 - |2x - 1| (lattice, kronecker).
    ShiftTent,
}

/// Point order (`--order`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum OrderName {
    /// Line k is point start+k.
    Natural,
    /// Gray-code order (Sobol' only): SciPy's qmc.Sobol order.
    Gray,
}

/// What `points::build` needs to construct a sampler: shared by `points`, `tvalue` and
/// the toolbox.
#[derive(Clone, Debug)]
pub struct Spec {
    /// Which construction.
    pub sampler: SamplerName,
    /// Number of points asked for (the default set size of finite sets).
    pub n: u64,
    /// Dimensions [default: 1 for vdc, 2 otherwise].
    pub d: Option<usize>,
    /// Size of finite sets [default: n].
    pub total: Option<u64>,
    /// Seed of randomized samplers and scrambles.
    pub seed: u64,
    /// Randomization.
    pub scramble: ScrambleName,
    /// Point order.
    pub order: OrderName,
    /// Base of the van der Corput sequence.
    pub base: u32,
    /// Strata per dimension for stratified (`8x4`).
    pub strata: Option<String>,
    /// Stratified: cell centers instead of jitter.
    pub centered: bool,
    /// Lattice: a generating-vector file.
    pub vector: Option<std::path::PathBuf>,
    /// Lattice: a Korobov parameter.
    pub korobov: Option<u64>,
    /// The time budget of sets built whole at super-linear cost (pmj02bn).
    pub budget: qmckit::work::Budget,
}

impl Spec {
    /// The spec of an unordered, unwarped base-2 set of `n` points of `d` dimensions.
    pub fn base2(
        sampler: SamplerName,
        n: u64,
        d: usize,
        scramble: ScrambleName,
        seed: u64,
    ) -> Self {
        Spec {
            sampler,
            n,
            d: Some(d),
            total: None,
            seed,
            scramble,
            order: OrderName::Natural,
            // Faure's base 0 picks the smallest prime at least d.
            base: if sampler == SamplerName::Faure { 0 } else { 2 },
            strata: None,
            centered: false,
            vector: None,
            korobov: None,
            budget: qmckit::work::Budget::DEFAULT,
        }
    }
}

/// The command-line name of a value (`fast-owen`, `sobol`).
pub fn value_name(v: &impl ValueEnum) -> String {
    v.to_possible_value()
        .map(|v| v.get_name().to_owned())
        .unwrap_or_default()
}
