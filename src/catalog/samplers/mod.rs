//! The sampler constructions: one entry each, their families (which decide the
//! randomizers that apply), their sizes and their dimensions.

use super::{Entry, Param, alias, param};

mod kind;

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
const POINTS: Param = param(
    "points",
    "the size N of the set",
    "none: needed",
    "1 to 2^32",
);

/// Every sampler construction, in the order of the command's list.
pub static SAMPLERS: &[SamplerEntry] = &[
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
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
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
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
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
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
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
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
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
    Entry {
        kind: SamplerKind::Lloyd,
        name: "lloyd",
        aliases: &[
            alias("cvt", "centroidal Voronoi tessellation"),
            alias("lloyd-relaxation", "the algorithm's usual name"),
        ],
        summary: "Lloyd relaxation, any dimension, cube or torus, exact Voronoi cells in 2D and 3D (a dense sample otherwise), built whole",
        math: "s_i <- centroid of its Voronoi cell (exact in 2D and 3D; of the dense-sample points nearest s_i otherwise); E = int min_i |x - s_i|^2 never increases (Lloyd 1982)",
        params: &[
            param("dims", "coordinates of each point", "2", "1 to 64"),
            POINTS,
            SEED,
            param("iterations", "relaxation iterations", "30", "0 to 10^5"),
            param("torus", "periodic distances", "false", "bool"),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::Lloyd",
    },
    Entry {
        kind: SamplerKind::Ccvt,
        name: "ccvt",
        aliases: &[alias(
            "capacity-constrained",
            "Balzer, Schlömer & Deussen 2009's title",
        )],
        summary: "capacity-constrained Voronoi tessellation: Lloyd with equal cell capacities, by site swaps, built whole",
        math: "each site owns 64 sample points; swap pairs while h_i + h_j > 0, then centroids (Balzer, Schlömer & Deussen 2009)",
        params: &[
            param("dims", "coordinates of each point", "2", "1 to 64"),
            POINTS,
            SEED,
            param("iterations", "swap-and-move iterations", "30", "0 to 10^5"),
            param("torus", "periodic distances", "false", "bool"),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::Lloyd::capacity_constrained",
    },
    Entry {
        kind: SamplerKind::Sot,
        name: "sot",
        aliases: &[alias(
            "sliced-optimal-transport",
            "Paulin et al. 2020's title",
        )],
        summary: "sliced optimal transport sampling in the cube, any dimension to 64, built whole; \
                  projective: half the directions in the 1D and 2D axis subspaces",
        math: "x_i += mean over L directions of (t_rank(i) - <theta, x_i>) theta, t the projected cube's quantile blocks (Paulin et al. 2020)",
        params: &[
            param("dims", "coordinates of each point", "2", "1 to 64"),
            POINTS,
            SEED,
            param(
                "iterations",
                "iterations of 16 directions",
                "100",
                "0 to 10^5",
            ),
            param(
                "projective",
                "every other direction in an axis-aligned 1D or 2D subspace, so the projections are spread too",
                "false",
                "bool",
            ),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::Sot",
    },
    Entry {
        kind: SamplerKind::ProjectiveBlueNoise,
        name: "projective-blue-noise",
        aliases: &[alias(
            "projective",
            "Reinert, Ritschel, Seidel & Georgiev 2016's title",
        )],
        summary: "projective blue noise on the torus, 2 to 8 dimensions: dart throwing with radii in the \
                  full space and in every 1D and 2D axis projection, built whole",
        math: "accept x if |x - y| >= r_d, |x_k - y_k| >= r_1, |(x_k, x_l) - (y_k, y_l)| >= r_2 for all y; \
               r_m = rho r_max(N, m), rho shrunk by 0.99 after 1000 rejections (Reinert et al. 2016)",
        params: &[
            param("dims", "coordinates of each point", "2", "2 to 8"),
            POINTS,
            SEED,
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::ProjectiveBlueNoise",
    },
    Entry {
        kind: SamplerKind::ForcedRandom,
        name: "forced-random",
        aliases: &[alias(
            "forced-random-sampling",
            "Cornel et al. 2017's title",
        )],
        summary: "forced random sampling, 2D, constant density: the N cells of lowest rank of a \
                  128 x 128 void-and-cluster matrix, a uniform point in each, built whole",
        math: "cell c taken iff M(c mod R) + 1/2 < t_c R^2, t_c = N f_c / sum f (Cornel et al. 2017); here f = 1",
        params: &[
            DIMS_2,
            POINTS,
            SEED,
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::ForcedRandom",
    },
    Entry {
        kind: SamplerKind::Bnot,
        name: "bnot",
        aliases: &[alias(
            "blue-noise-optimal-transport",
            "de Goes et al. 2012's title",
        )],
        summary: "blue noise through optimal transport: centroids of equal-area power cells, 2D, square or torus, built whole",
        math: "solve w: |Laguerre cell_i(w)| = 1/N (damped Newton), then x_i <- centroid; W2^2 never increases (de Goes, Breeden, Ostromoukhov & Desbrun 2012)",
        params: &[
            DIMS_2,
            POINTS,
            SEED,
            param("iterations", "solve-and-move iterations", "50", "0 to 10^4"),
            param("torus", "periodic cells", "false", "bool"),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::Bnot",
    },
    Entry {
        kind: SamplerKind::Ldbn,
        name: "ldbn",
        aliases: &[alias(
            "low-discrepancy-blue-noise",
            "Ahmed et al. 2016's title",
        )],
        summary: "low-discrepancy blue noise: the Sobol' (0, m, 2)-net, N = 4^k, its in-cell offsets \
                  permuted within the columns and rows of 16 x 16-cell tiles by an optimized look-up \
                  table; still a (0, m, 2)-net",
        math: "x = (X K + rev_k(16 floor(Y/16) + p_X(Y mod 16)))/N, y likewise, p from LDBN_TABLE (Ahmed et al. 2016)",
        params: &[
            DIMS_2,
            param(
                "points",
                "the size N = 4^k of the set",
                "none: needed",
                "a power of four, 4 to 2^26",
            ),
            SEED,
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::Ldbn",
    },
    Entry {
        kind: SamplerKind::Penrose,
        name: "penrose",
        aliases: &[alias(
            "penrose-tiling",
            "Ostromoukhov, Donohue & Jodoin 2004's tiling",
        )],
        summary: "Penrose-tiling sampling, 2D: one point a Robinson triangle of a subdivided \
                  Penrose tiling, moved by a learned correction vector, the N of lowest rank \
                  (progressive), built whole",
        math: "triangles shrink by phi a level (F(2h+1), F(2h+2) leaves); ranks interleave the children in proportion; keep rank < N; x = centroid + table[band][class] in the leaf's frame (Ostromoukhov, Donohue & Jodoin 2004)",
        params: &[
            DIMS_2,
            POINTS,
            param(
                "seed",
                "rotation and offset of the square in the tiling",
                "0",
                "any u64",
            ),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::Penrose",
    },
    Entry {
        kind: SamplerKind::AaPatterns,
        name: "aa-patterns",
        aliases: &[alias("aa", "Ahmed, Huang & Deussen 2015's AA patterns")],
        summary: "AA patterns, 2D: one point in each cell of a K x K grid (N = K^2), displaced \
                  inside it by a table indexed by the cell's label under a discrete irrational \
                  rotation of the lattice (an additive automaton), built whole",
        math: "l(x, y) = s + x R e_1 + y R e_2 mod 1, cos theta = 1/phi; p = ((x + 1/2, y + 1/2) + AA_TABLE[bin(l)]) / K (after Ahmed, Huang & Deussen 2015)",
        params: &[
            DIMS_2,
            param(
                "points",
                "the size N = K^2 of the set",
                "none: needed",
                "a perfect square, 1 to 2^24",
            ),
            param("seed", "the automaton's start label s", "0", "any u64"),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::AaPattern",
    },
    Entry {
        kind: SamplerKind::Art,
        name: "art",
        aliases: &[alias(
            "adaptive-regular-tiles",
            "Ahmed, Niese, Huang & Deussen 2017's ART",
        )],
        summary: "adaptive regular tiles, 2D: one sample a tile of a recursive 4 x 4 \
                  subdivision, offsets from a table indexed by the tile's word (child numbers \
                  and a Thue-Morse bit), the N of lowest rank (progressive), built whole",
        math: "sample = corner + 4^-j ART_TABLE[c + 16 i + 256 t] unless inherited (i: the inheriting sibling); rank = sum_j Bayer digit_j 16^(j-1); keep rank < N (after Ahmed, Niese, Huang & Deussen 2017)",
        params: &[
            DIMS_2,
            param("points", "the set size N", "none: needed", "1 to 2^24"),
            param("seed", "toroidal shift of the set", "0", "any u64"),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::Art",
    },
    Entry {
        kind: SamplerKind::StepBlueNoise,
        name: "step-blue-noise",
        aliases: &[alias(
            "step",
            "Heck, Schlömer & Deussen 2013's step blue noise",
        )],
        summary: "spectrum-controlled blue noise, step profile: power 0 below |k| = 0.5 sqrt(N) (2D), 1 above; torus, 1 to 6 dimensions, built whole",
        math: "G_0 = 1 - (u_0/rho)^(d/2) J_{d/2}(2 pi u_0 rho) (Hankel transform of the step); gradient descent on sum_b rho_b^(d-1) (G_b - G_0b)^2 (Heck, Schlömer & Deussen 2013)",
        params: &[
            param("dims", "coordinates of each point", "2", "1 to 6"),
            param(
                "points",
                "the set size N",
                "none: needed",
                "2 to 2^22 (below 12.32^d a shorter correlation range)",
            ),
            SEED,
            param("iterations", "descent iterations", "1000", "0 to 10^5"),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::spectral::Profile::step",
    },
    Entry {
        kind: SamplerKind::SinglePeakBlueNoise,
        name: "single-peak-blue-noise",
        aliases: &[alias(
            "single-peak",
            "Heck, Schlömer & Deussen 2013's single-peak blue noise",
        )],
        summary: "spectrum-controlled blue noise, single peak: power 0 below, a smoothed peak at |k| = 0.75 sqrt(N) (2D), 1 above; torus, 1 to 6 dimensions, built whole",
        math: "P = G_sigma * (p_0 delta(u - u_0) + H(u - u_0)), p_0 = 0.3, sigma = 0.08; its G_0 by the d-dimensional Hankel transform; gradient descent on the PCF mismatch (Heck, Schlömer & Deussen 2013)",
        params: &[
            param("dims", "coordinates of each point", "2", "1 to 6"),
            param(
                "points",
                "the set size N",
                "none: needed",
                "2 to 2^22 (below 12.32^d a shorter correlation range)",
            ),
            SEED,
            param("iterations", "descent iterations", "1000", "0 to 10^5"),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::spectral::Profile::single_peak",
    },
    Entry {
        kind: SamplerKind::KdeBlueNoise,
        name: "kde-blue-noise",
        aliases: &[alias("fattal", "Fattal 2011, kernel density model")],
        summary: "kernel-density blue noise: a Gibbs sample at temperature T of the KDE-mismatch energy; torus, 1 to 5 dimensions, built whole",
        math: "p(X) ∝ exp(-E/T), E = sum_{i<j} exp(-|x_i - x_j|^2 / (4 sigma^2 s^2)), multi-scale Langevin relaxation, 3 levels (Fattal 2011)",
        params: &[
            param("dims", "coordinates of each point", "2", "1 to 5"),
            param("points", "the set size N", "none: needed", "2 to 2^22"),
            SEED,
            param("iterations", "sweeps a level", "60", "0 to 10^5"),
            param(
                "temperature",
                "the temperature T (energy units of one pair's overlap)",
                "0.001",
                "0 to 100",
            ),
            param(
                "budget",
                "time budget of the construction",
                "10 s",
                "positive seconds",
            ),
        ],
        item: "qmckit::blue_noise::KdeBlueNoise",
    },
];
