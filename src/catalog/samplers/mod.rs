//! The sampler constructions: one entry each, their families (which decide the
//! randomizers that apply), their sizes and their dimensions.

use super::{Entry, Param, alias, param};

mod kind;
mod optimized;

pub use kind::{Family, SamplerKind, Size};

/// An entry of [`SAMPLERS`].
pub type SamplerEntry = Entry<SamplerKind>;

impl Entry<SamplerKind> {
    /// The entry's family for `base` ([`SamplerKind::family`]).
    pub const fn family(&self, base: Option<u32>) -> Family {
        self.kind.family(base)
    }
}

const DIMS: Param = param(
    "dims",
    "coordinates of each point",
    "2",
    "1 to 2^27 (the construction may allow fewer)",
);
const DIMS_1: Param = param("dims", "coordinates of each point", "1", "1");
const DIMS_2: Param = param("dims", "coordinates of each point", "2", "2");
const SEED: Param = param(
    "seed",
    "seed of the construction's own randomness",
    "0",
    "any u64",
);
/// The time budget of a set built whole (the command's `--max-seconds`).
const BUDGET: Param = param(
    "budget",
    "time budget of the construction",
    "10 s",
    "positive seconds",
);
/// Points and dimensions of the spectral samplers.
const SPECTRAL_DIMS: Param = param("dims", "coordinates of each point", "2", "1 to 6");
const SPECTRAL_POINTS: Param = param(
    "points",
    "the set size N",
    "none: needed",
    "2 to 2^22 (below 12.32^d a shorter correlation range)",
);
/// The energy evaluations of the spectral samplers' descent.
const SPECTRAL_ITERATIONS: Param = param(
    "iterations",
    "energy evaluations of the quasi-Newton descent",
    "200",
    "0 to 10^5",
);
const POINTS: Param = param(
    "points",
    "the size N of the set",
    "none: needed",
    "1 to 2^32",
);

/// Every sampler construction, in the order of the command's list: the sequences, nets,
/// lattices and stratified and Poisson-disk sets, then the optimized and tiled blue-noise
/// sets (`samplers/optimized.rs`).
pub static SAMPLERS: &[SamplerEntry] = &ALL;

static ALL: [SamplerEntry; 33] = join(&SEQUENCES_AND_SETS, &optimized::ENTRIES);

/// `a` then `b`, at compile time (`N = A + B`; both non-empty).
const fn join<const A: usize, const B: usize, const N: usize>(
    a: &[SamplerEntry; A],
    b: &[SamplerEntry; B],
) -> [SamplerEntry; N] {
    assert!(A + B == N && A > 0);
    let mut out = [a[0]; N];
    let mut i = 0;
    while i < N {
        out[i] = if i < A { a[i] } else { b[i - A] };
        i += 1;
    }
    out
}

/// The sequences, nets, lattices, stratified and Poisson-disk constructions.
const SEQUENCES_AND_SETS: [SamplerEntry; 20] = [
    Entry {
        kind: SamplerKind::Independent,
        name: "independent",
        aliases: &[
            alias("random", "the usual name of plain Monte Carlo points"),
            alias("white-noise", "the rendering literature's name"),
        ],
        summary: "independent uniform random points (a hash of seed, index and dimension)",
        math: "x_ik = hash(seed, i, k) 2^-32: plain Monte Carlo (Metropolis & Ulam 1949)",
        params: &[DIMS, SEED],
        item: "qmckit::Independent",
    },
    Entry {
        kind: SamplerKind::Stratified,
        name: "stratified",
        aliases: &[
            alias("jittered", "qmckit variance; Cook 1986's jittered sampling"),
            alias("jitter", "a short form of jittered"),
        ],
        summary: "jittered stratified grid, one point in each of k^d cells (or at its centre)",
        math: "x = (c + u) / k in cell c, u uniform (Cook, Porter & Carpenter 1984; Cook 1986)",
        params: &[
            DIMS,
            param(
                "points",
                "the size N = k^d of the set",
                "the product of strata",
                "a d-th power",
            ),
            param(
                "strata",
                "strata per dimension (their product is N)",
                "k = N^(1/d) in each",
                "d counts >= 1",
            ),
            param(
                "centered",
                "each point at its cell's centre (no randomness)",
                "false",
                "bool",
            ),
            SEED,
        ],
        item: "qmckit::Stratified",
    },
    Entry {
        kind: SamplerKind::Latin,
        name: "latin",
        aliases: &[
            alias("latin-hypercube", "SciPy qmc.LatinHypercube"),
            alias("lhs", "the usual abbreviation"),
        ],
        summary: "Latin hypercube: one point in each of the N slabs of every axis",
        math: "x_ik = (pi_k(i) + u_ik) / N, pi_k random permutations (McKay, Beckman & Conover 1979)",
        params: &[DIMS, POINTS, SEED],
        item: "qmckit::LatinHypercube",
    },
    Entry {
        kind: SamplerKind::Vdc,
        name: "vdc",
        aliases: &[alias("van-der-corput", "the sequence's full name")],
        summary: "van der Corput sequence, 1D, in base b (base 2: Sobol' dimension 0, bit for bit)",
        math: "phi_b(i) = sum_j a_j b^(-j-1) for i = sum_j a_j b^j (van der Corput 1935)",
        params: &[DIMS_1, param("base", "the base b", "2", "2 to 2^32 - 1")],
        item: "qmckit::VanDerCorput",
    },
    Entry {
        kind: SamplerKind::Halton,
        name: "halton",
        aliases: &[alias("halton-sequence", "the sequence's full name")],
        summary: "Halton sequence: radical inverses in the first d primes (SciPy qmc.Halton)",
        math: "x_i = (phi_2(i), phi_3(i), ..., phi_(p_d)(i)) (Halton 1960)",
        params: &[param("dims", "coordinates of each point", "2", "1 to 1024")],
        item: "qmckit::Halton",
    },
    Entry {
        kind: SamplerKind::Hammersley,
        name: "hammersley",
        aliases: &[alias("hammersley-set", "the set's full name")],
        summary: "Hammersley set of N points",
        math: "x_i = (i/N, phi_2(i), ..., phi_(p_(d-1))(i)), i < N (Hammersley 1960)",
        params: &[DIMS, POINTS],
        item: "qmckit::Hammersley",
    },
    Entry {
        kind: SamplerKind::Lp,
        name: "lp",
        aliases: &[alias("larcher-pillichshammer", "the net's authors")],
        summary: "Larcher–Pillichshammer (0, m, 2)-net, 2D, N a power of two",
        math: "x_i = (i/N, C i over GF(2)), C the all-ones upper triangle (Larcher & Pillichshammer 2001)",
        params: &[
            DIMS_2,
            param(
                "points",
                "the size N of the net",
                "none: needed",
                "a power of two <= 2^32",
            ),
        ],
        item: "qmckit::LarcherPillichshammer",
    },
    Entry {
        kind: SamplerKind::Sobol,
        name: "sobol",
        aliases: &[alias("sobol-sequence", "the sequence's full name")],
        summary: "Sobol' sequence with Joe–Kuo direction numbers (SciPy qmc.Sobol)",
        math: "x_k(i) = C_k i over GF(2), C_k from primitive polynomials (Sobol' 1967; Joe & Kuo 2008)",
        params: &[
            param(
                "dims",
                "coordinates of each point",
                "2",
                "1 to SOBOL_MAX_DIMS (64, 1024 or 21201 by feature)",
            ),
            param(
                "order",
                "natural, or gray (SciPy's Gray-code order)",
                "natural",
                "natural, gray",
            ),
        ],
        item: "qmckit::Sobol",
    },
    Entry {
        kind: SamplerKind::Lattice,
        name: "lattice",
        aliases: &[alias("rank-1-lattice", "the rule's full name")],
        summary: "rank-1 lattice (QMCPy Lattice): Kuo's extensible vector, a Korobov vector or a given one",
        math: "x_i = frac(phi_2(i) z) (extensible) or frac(i z / N) (Korobov 1959; Cools, Kuo & Nuyens 2006)",
        params: &[
            param(
                "dims",
                "coordinates of each point",
                "2",
                "1 to 9125 (Kuo's vector) or the vector's length",
            ),
            param(
                "points",
                "N of the rule in linear order",
                "none: extensible, 2^20 points, radical-inverse order",
                "1 to 2^32",
            ),
            param(
                "korobov",
                "the Korobov vector (1, a, a^2, ...) mod N (needs points)",
                "none",
                "any u64",
            ),
            param(
                "vector",
                "a generating vector and its modulus",
                "none: Kuo's 33002 vector",
                "at least dims components",
            ),
        ],
        item: "qmckit::lattice::Rank1Lattice",
    },
    Entry {
        kind: SamplerKind::Kronecker,
        name: "kronecker",
        aliases: &[
            alias("rd", "Roberts' R_d sequence"),
            alias("additive-recurrence", "the sequence's other name"),
        ],
        summary: "Kronecker sequence frac(i alpha), alpha from the generalized golden ratio R_d",
        math: "x_i = frac(i alpha), alpha_k = phi_d^-k, phi_d^(d+1) = phi_d + 1 (Roberts 2018)",
        params: &[DIMS],
        item: "qmckit::lattice::kronecker::Kronecker",
    },
    Entry {
        kind: SamplerKind::Faure,
        name: "faure",
        aliases: &[alias("faure-sequence", "the sequence's full name")],
        summary: "Faure (0, s)-sequence in a prime base b >= d",
        math: "x_k(i) = P^(k-1) i over F_b, P the Pascal matrix mod b (Faure 1982)",
        params: &[
            DIMS,
            param(
                "base",
                "the prime base b",
                "the smallest prime >= max(d, 2)",
                "a prime from d to MAX_BASE",
            ),
        ],
        item: "qmckit::digital::DigitalNetB::faure",
    },
    Entry {
        kind: SamplerKind::Poisson,
        name: "poisson",
        aliases: &[
            alias("poisson-disk", "SciPy qmc.PoissonDisk"),
            alias("bridson", "the algorithm's author"),
        ],
        summary: "Poisson disk (Bridson), built whole: about N points, or a radius",
        math: "no two points closer than r, grown by dart throwing around active points (Bridson 2007)",
        params: &[
            param("dims", "coordinates of each point", "2", "1 to 8"),
            param(
                "points",
                "about how many points",
                "none: points or radius",
                "1 to 2^32",
            ),
            SEED,
            param(
                "radius",
                "the disk radius, instead of points",
                "none",
                "positive",
            ),
            param("torus", "toroidal distance", "false", "bool"),
            param("maximal", "fill until no disk fits", "false", "bool"),
            param("candidates", "candidates per step", "30", "at least 1"),
            BUDGET,
        ],
        item: "qmckit::blue_noise::PoissonDisk",
    },
    Entry {
        kind: SamplerKind::BestCandidate,
        name: "best-candidate",
        aliases: &[alias("mitchell", "the algorithm's author")],
        summary: "Mitchell's best candidate on the torus, 2D, built whole",
        math: "point i is the farthest of m i uniform candidates from points 0..i (Mitchell 1991)",
        params: &[
            DIMS_2,
            POINTS,
            SEED,
            param("candidates", "the multiplier m", "10", "at least 1"),
            BUDGET,
        ],
        item: "qmckit::blue_noise::BestCandidate",
    },
    Entry {
        kind: SamplerKind::GaussianBlueNoise,
        name: "gaussian-blue-noise",
        aliases: &[alias("gbn", "the paper's abbreviation")],
        summary: "Gaussian blue noise on the torus, 2D, built whole",
        math: "gradient descent on sum_(i,j) exp(-|x_i - x_j|^2 / (2 s^2)) (Ahmed, Ren & Wonka 2022)",
        params: &[
            DIMS_2,
            POINTS,
            SEED,
            param(
                "iterations",
                "gradient-descent iterations",
                "500",
                "at least 1",
            ),
            BUDGET,
        ],
        item: "qmckit::blue_noise::GaussianBlueNoise",
    },
    Entry {
        kind: SamplerKind::Pmj02,
        name: "pmj02",
        aliases: &[alias(
            "progressive-multi-jittered",
            "the construction's name",
        )],
        summary: "PMJ02: progressive multi-jittered (0, 2)-sequence, 2D, seeded",
        math: "every prefix of 2^m points a (0, m, 2)-net, chosen at random (Christensen, Kensler & Kilpatrick 2018)",
        params: &[DIMS_2, SEED],
        item: "qmckit::pmj::Pmj02",
    },
    Entry {
        kind: SamplerKind::Pmj02bn,
        name: "pmj02bn",
        aliases: &[alias("pmj02-blue-noise", "what bn stands for")],
        summary: "PMJ02BN: PMJ02 spread by nested flips to blue noise, 2D, built whole",
        math: "PMJ02 with the subdivisions' choices flipped to maximize spacing (Christensen, Kensler & Kilpatrick 2018)",
        params: &[
            DIMS_2,
            param(
                "points",
                "the size N of the set",
                "none: needed",
                "1 to 2^32",
            ),
            SEED,
            BUDGET,
        ],
        item: "qmckit::pmj::bn",
    },
    Entry {
        kind: SamplerKind::Cmj,
        name: "cmj",
        aliases: &[
            alias("correlated-multi-jittered", "Kensler 2013's title"),
            alias("multi-jittered", "the family (Chiu, Shirley & Wang 1994)"),
        ],
        summary: "correlated multi-jittered: N-rooks and m x n strata at once, random access; \
                  pairs of dimensions are independent 2D patterns, an odd last one a 1D stratified draw",
        math: "x = (sx + (sy + jx)/n)/m, y = (s + jy)/N, sx, sy one shared permutation of columns and of rows (Kensler 2013)",
        params: &[DIMS, POINTS, SEED],
        item: "qmckit::random::cmj::CorrelatedMultiJitter",
    },
    Entry {
        kind: SamplerKind::CascadedSobol,
        name: "cascaded-sobol",
        aliases: &[alias("cascaded", "Paulin et al. 2021's title, short")],
        summary: "cascaded Sobol': every consecutive pair of dimensions a (0, m, 2)-net, every \
                  dimension stratified, N a power of two, Owen-scrambled from the seed",
        math: "x_0 = O_0(phi_2(i)), x_(j+1) = O_(j+1)(P rev_m(Q_j(x_j))), P Sobol's Pascal matrix, O_j, Q_j nested uniform scrambles (Paulin et al. 2021)",
        params: &[
            param("dims", "coordinates of each point", "2", "1 to 65536"),
            param(
                "points",
                "the size N = 2^m of the set",
                "none: needed",
                "a power of two <= 2^32",
            ),
            SEED,
        ],
        item: "qmckit::digital::cascaded::CascadedSobol",
    },
    Entry {
        kind: SamplerKind::Hex,
        name: "hex",
        aliases: &[
            alias("hexagonal", "the lattice's name"),
            alias("hexagonal-grid", "the full name"),
        ],
        summary: "hexagonal grid on the torus, 2D, N even (rows r even, r/c nearest 2/sqrt 3); \
                  random shift by the shift randomizer",
        math: "x = (4j + 1 + 2 (i mod 2))/(4c), y = (2i + 1)/(2r): the densest packing of the plane (Thue 1910)",
        params: &[
            DIMS_2,
            param(
                "points",
                "the size N = r c of the grid",
                "none: needed",
                "even, 2 to 2^32",
            ),
        ],
        item: "qmckit::lattice::hex::HexGrid",
    },
    Entry {
        kind: SamplerKind::MaximinLattice,
        name: "maximin-lattice",
        aliases: &[
            alias("max-min-lattice", "the criterion's other spelling"),
            alias(
                "rank1-maximin",
                "UTK's Rank1 sampler (its default search is approximate)",
            ),
        ],
        summary: "rank-1 lattice of N points, 2D, with the largest minimum distance on the torus \
                  (exact search); random shift by the shift randomizer",
        math: "x_i = frac(i (1, a) / N), a maximizing lambda_1 of {y = a x mod N} by Lagrange-Gauss \
               reduction (Dammertz & Keller 2006)",
        params: &[
            DIMS_2,
            param(
                "points",
                "the size N of the rule",
                "none: needed",
                "1 to 2^32 - 1",
            ),
        ],
        item: "qmckit::lattice::maximin::max_min_distance",
    },
];
