//! The optimized and tiled blue-noise constructions of [`super::SAMPLERS`]: relaxations
//! (Lloyd, CCVT, sliced and semi-discrete optimal transport), projective and forced-random
//! blue noise, the tiled sets (LDBN, Penrose, AA patterns, ART) and the spectral and
//! kernel-density samplers. Each is built whole, within the time budget.

use super::{
    BUDGET, DIMS_2, POINTS, SEED, SPECTRAL_DIMS, SPECTRAL_ITERATIONS, SPECTRAL_POINTS,
    SamplerEntry, SamplerKind,
};
use crate::catalog::{Entry, alias, param};

/// The entries, in the order of the command's list.
pub(super) const ENTRIES: [SamplerEntry; 13] = [
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
            BUDGET,
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
            BUDGET,
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
            BUDGET,
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
            BUDGET,
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
        params: &[DIMS_2, POINTS, SEED, BUDGET],
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
            BUDGET,
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
            BUDGET,
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
            BUDGET,
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
            BUDGET,
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
            BUDGET,
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
        summary: "spectrum-controlled blue noise, step profile: power 0 below |k| = 0.5639 sqrt(N) (2D, just inside the realizability bound), 1 above; torus, 1 to 6 dimensions, built whole",
        math: "G_0 = 1 - (u_0/rho)^(d/2) J_{d/2}(2 pi u_0 rho) (Hankel transform of the step); L-BFGS descent on sum_b rho_b^(d-1) (G_b - G_0b)^2 (Heck, Schlömer & Deussen 2013)",
        params: &[
            SPECTRAL_DIMS,
            SPECTRAL_POINTS,
            SEED,
            SPECTRAL_ITERATIONS,
            BUDGET,
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
        math: "P = G_sigma * (p_0 delta(u - u_0) + H(u - u_0)), p_0 = 0.3, sigma = 0.08; its G_0 by the d-dimensional Hankel transform; L-BFGS descent on the PCF mismatch (Heck, Schlömer & Deussen 2013)",
        params: &[
            SPECTRAL_DIMS,
            SPECTRAL_POINTS,
            SEED,
            SPECTRAL_ITERATIONS,
            BUDGET,
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
            BUDGET,
        ],
        item: "qmckit::blue_noise::KdeBlueNoise",
    },
];
