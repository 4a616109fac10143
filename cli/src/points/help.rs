//! The text of `qmckit points --help` after its options: which option applies to which
//! sampler, the limits, the formats and the sets built whole.

/// Text shown after the options of `qmckit points --help`.
pub const AFTER_HELP: &str = "\
Options that apply (any other is an error that names it):
  --seed      independent, latin, pmj02, stratified (without --centered), and every --scramble
  --base      vdc            --strata, --centered   stratified
  --total     the finite sets: stratified, latin, hammersley, lp
  --order     sobol (gray: SciPy's order)
  --vector, --korobov   lattice (--total N: the N-point rule in linear order)
  --scramble  shift, shift-tent: lattice, kronecker; owen, perm, faure: faure (base b)
  --scramble  xor, fast-owen, fast-owen-lk, lms, shuffle-owen: base-2 digital
              constructions (sobol, lp, vdc base 2); owen: those and halton, hammersley,
              vdc (in base b); rotate: any; perm, faure: halton, hammersley, vdc

Limits: indices start..start+n-1 must lie in the construction (2^32 for the sequences;
--total for the sets); a point holds at most 2^27 coordinates (1 GiB at 8 bytes each);
halton at most 1024 dimensions, sobol as many as compiled in (21201 in the command).
Output is written in batches of about 1 MiB, so memory stays bounded for any N.

Formats: decimal (default), one point a line, the coordinates x / 2^32 as the shortest
decimals that parse back to the exact value (every one is an f64), separated by spaces;
u32, the integers x * 2^32 (the numerators) separated by spaces; csv, the decimals
separated by commas; npy, float64 of shape (N, D). 'qmckit discrepancy' and 'qmckit
spectrum' read all four back with default options.

Blue-noise sets (built whole; -n is the set size; --start, --total, --scramble, --warp do
not apply):
  poisson              Bridson Poisson disk: --radius R or -n N (about N points), -d D
                       (1 to 8), --torus, --maximal (no further disk fits), --candidates K
  best-candidate       Mitchell best candidate on the torus, 2D: -n N, --candidates M
  gaussian-blue-noise  Ahmed-Ren-Wonka Gaussian blue noise on the torus, 2D: -n N,
                       --iterations I
  lloyd, ccvt          Lloyd relaxation (exact Voronoi cells in 2D and 3D) / capacity-
                       constrained Voronoi (dense sample of 64 points a site; also Lloyd
                       in other -d), any -d to 64: -n N, --iterations I, --torus
  sot                  sliced optimal transport in the cube, any -d to 64: -n N,
                       --iterations I, --projective (every other direction in a 1D or
                       2D axis subspace: the projections are spread too)
  projective-blue-noise  dart throwing with radii in the full space and in every 1D and
                       2D axis projection, on the torus, -d 2 to 8: -n N
  forced-random        forced random sampling, 2D, constant density: the N cells of
                       lowest rank of a 256 x 256 void-and-cluster matrix: -n N
  bnot                 blue noise through optimal transport (equal-area power cells),
                       2D: -n N, --iterations I (default 50), --torus
  ldbn                 low-discrepancy blue noise, 2D: -n N a power of four (4 to 2^26): the
                       Sobol' net's offsets permuted in 16 x 16 tiles by a table, still a net
  penrose              Penrose-tiling sampling (Ostromoukhov et al. 2004), 2D: -n N (the
                       N points of lowest rank), --seed (rotation and offset)
  aa-patterns          AA patterns (after Ahmed et al. 2015), 2D: -n N a perfect square, one
                       point a cell of a turned square lattice, displaced by a table indexed
                       by an automaton's label
  art                  adaptive regular tiles (after Ahmed et al. 2017), 2D: -n N (the N
                       samples of lowest rank of a 4 x 4 subdivision), --seed (a torus shift)
  step-blue-noise, single-peak-blue-noise
                       spectrum-controlled blue noise on the torus (Heck et al. 2013),
                       -d 1 to 6: -n N, --iterations I
  kde-blue-noise       kernel-density blue noise on the torus (Fattal 2011), -d 1 to 5:
                       -n N, --iterations I (sweeps a level), --temperature T
  --max-seconds S refuses, before starting, a set whose estimated time exceeds S
  (also pmj02bn, lloyd, ccvt, sot, projective-blue-noise, forced-random, bnot, ldbn,
  penrose, aa-patterns, art, step-blue-noise, single-peak-blue-noise, kde-blue-noise).

Other sets: cmj (Kensler's correlated multi-jitter, --total N, -d any, --seed);
cascaded-sobol (Paulin et al.'s cascaded Sobol', --total N a power of two, -d to 65536,
--seed: every consecutive pair of dimensions a (0, m, 2)-net, Owen-scrambled);
hex (hexagonal grid on the torus, 2D, --total N even; --scramble shift for a random
shift).";
