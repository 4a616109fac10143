//! The running-time model of [`super::PoissonDisk`], calibrated on measured runs (release
//! build, two cores; the table and the script that makes it are in
//! docs/budgets.md).
//!
//! One construction at radius `r` in `d` dimensions with `k` candidates costs
//!
//! `T = N (k c_d f + v t_v) m(N) / p + g^d t_c + s^d d t_e`
//!
//! * `N` the points it places: `phi_d (k / 30)^(d / 50) / V_d(r / 2)` ([`PHI`], measured
//!   on the torus; the cube of side 1 holds the same density), at most the packing bound;
//! * `c_d` the test of a rejected candidate ([`CANDIDATE_NS`], measured per dimension: it
//!   stops at the first neighbour closer than `r`, nearest cells first);
//! * `v` the neighbour cells an accepted candidate's test reads: the offsets of the grid
//!   (those whose nearest corner is closer than `r`, counted exactly below as the grid
//!   builds them) weighted, in the box, by the fraction of cells for which the offset stays
//!   inside (an offset that leaves costs a quarter of a visit); `f = v / offsets` scales
//!   the rejected tests the same way; `t_v` per dimension, [`VISIT_NS`];
//! * `m(N)` the memory factor: past [`CACHE_POINTS`] points the active list and the cells
//!   no longer fit in cache, and each step's random reads miss ([`CACHE_SLOPE`] per
//!   doubling);
//! * in the box, a factor per dimension ([`CUBE_FACTOR`], 0.7 to 1);
//! * `p` the parallel speed-up of the 2D tiles (two cores, [`TILE_SPEEDUP`]), 1 elsewhere;
//! * `g^d` cells allocated and cleared ([`CELL_NS`]), `s^d` offset candidates enumerated
//!   ([`ENUM_NS`] a coordinate).
//!
//! The maximal fill adds `N v t_v M_d` ([`MAXIMAL`]): calibrated in 1 and 2 dimensions; in
//! 3 and more the cubes along the intersections of sphere boundaries multiply at each
//! split, its cost is not bounded usefully by any estimate, and the deadline is the bound.

/// Packing fraction `N V_d(r/2)` of Bridson's loop with `k = 30` on the torus, per
/// dimension (measured: 1D 9518 points at `r = 7e-5`; 2D 1.0e6 at `7.8e-4`; 3D 90224 at
/// 0.0186; 4D 75128 at 0.0525; 5D 18015 at 0.127; 6D to 8D from smaller sets).
pub(crate) const PHI: [f64; 8] = [0.666, 0.481, 0.302, 0.176, 0.099, 0.054, 0.029, 0.015];

/// The test of one rejected candidate, in nanoseconds, per dimension (torus).
pub(crate) const CANDIDATE_NS: [f64; 8] =
    [25.0, 35.0, 75.0, 290.0, 1100.0, 3800.0, 14000.0, 50000.0];

/// One neighbour-cell visit of a full free test, in nanoseconds, per dimension (in 7 and
/// 8 dimensions the offsets, tens of megabytes, stream from memory).
pub(crate) const VISIT_NS: [f64; 8] = [13.0, 13.0, 14.0, 14.0, 12.0, 12.0, 17.0, 24.0];

/// Points up to which the construction stays in cache.
pub(crate) const CACHE_POINTS: f64 = 262_144.0;

/// The memory factor's growth per doubling of the points past [`CACHE_POINTS`].
pub(crate) const CACHE_SLOPE: f64 = 0.15;

/// The cost a point in the box relative to the torus, per dimension: past 2D most cells
/// lie within reach of a face, where the torus wraps every offset (a division a
/// coordinate) and the box drops it at the first coordinate that leaves.
pub(crate) const CUBE_FACTOR: [f64; 8] = [1.0, 1.0, 0.9, 0.8, 0.7, 0.7, 0.8, 0.8];

/// The speed-up of the 2D tiles on two cores.
pub(crate) const TILE_SPEEDUP: f64 = 1.5;

/// One grid cell allocated, cleared and (for the maximal fill) scanned, in nanoseconds.
pub(crate) const CELL_NS: f64 = 3.0;

/// One coordinate of one candidate offset enumerated, in nanoseconds.
pub(crate) const ENUM_NS: f64 = 1.5;

/// The maximal fill, in full free tests a point, per dimension.
pub(crate) const MAXIMAL: [f64; 8] = [2.0, 8.0, 20.0, 80.0, 320.0, 1280.0, 5120.0, 20480.0];

/// The shape of the background grid at radius `r` (as [`super::grid::Grid::new`] builds
/// it): cells a side, axis offsets a side, offsets, and the cells a full test visits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Shape {
    pub(crate) g: f64,
    pub(crate) span: f64,
    pub(crate) offsets: f64,
    pub(crate) visits: f64,
}

/// The grid's shape in `d` dimensions (1 to 8) at radius `r` (in `(0, 1]` or the pilot's
/// radius, at most about 2): `O(d 9 * 72)` work, a dynamic programme over the squared gap
/// in cells (at most `8 * 4^2`).
pub(crate) fn shape(d: usize, r: f64, torus: bool) -> Shape {
    let gf = ((d as f64).sqrt() / r).ceil().max(1.0);
    let reach = (r * gf).ceil().clamp(0.0, 8.0) as i64;
    let g = gf.min(1e9) as i64;
    let axis: (i64, i64) = if torus && 2 * reach + 1 > g {
        (-((g - 1) / 2), g / 2)
    } else {
        let m = if torus { reach } else { reach.min(g - 1) };
        (-m, m)
    };
    let side2 = 1.0 / (gf * gf);
    const SUMS: usize = 8 * 64 + 1;
    // counts[s]: offsets so far whose squared gap is s cells^2; inside[s]: weighted by the
    // fraction of cells they stay in the box from.
    let mut counts = [0f64; SUMS];
    let mut inside = [0f64; SUMS];
    counts[0] = 1.0;
    inside[0] = 1.0;
    for _ in 0..d {
        let mut c2 = [0f64; SUMS];
        let mut i2 = [0f64; SUMS];
        for (s, (&c, &w)) in counts.iter().zip(&inside).enumerate() {
            if c == 0.0 {
                continue;
            }
            for o in axis.0..=axis.1 {
                let u = (o.abs() - 1).max(0) as usize;
                let t = s + u * u;
                if t >= SUMS || (t as f64) * side2 >= r * r {
                    continue;
                }
                let stay = if torus {
                    1.0
                } else {
                    (g - o.abs()).max(0) as f64 / g as f64
                };
                c2[t] += c;
                i2[t] += w * stay;
            }
        }
        counts = c2;
        inside = i2;
    }
    let offsets: f64 = counts.iter().sum();
    let stay: f64 = inside.iter().sum();
    Shape {
        g: gf,
        span: (axis.1 - axis.0 + 1) as f64,
        offsets,
        visits: stay + 0.25 * (offsets - stay),
    }
}

/// The seconds of one construction placing about `points` points (see the module text).
pub(crate) fn seconds(
    d: usize,
    r: f64,
    torus: bool,
    k: u32,
    maximal: bool,
    points: f64,
    tiled: bool,
) -> f64 {
    let s = shape(d, r, torus);
    let i = d.clamp(1, 8) - 1;
    let f = if s.offsets > 0.0 {
        s.visits / s.offsets
    } else {
        1.0
    };
    let cand = CANDIDATE_NS.get(i).copied().unwrap_or(5e4);
    let visit = VISIT_NS.get(i).copied().unwrap_or(20.0);
    let mut per_point = f64::from(k) * cand * f + s.visits * visit;
    if !torus {
        per_point *= CUBE_FACTOR.get(i).copied().unwrap_or(1.0);
    }
    if maximal {
        per_point += s.visits * visit * MAXIMAL.get(i).copied().unwrap_or(4e4);
    }
    let memory = 1.0 + CACHE_SLOPE * (points / CACHE_POINTS).log2().max(0.0);
    let speedup = if tiled { TILE_SPEEDUP } else { 1.0 };
    let setup = s.g.powi(d as i32) * CELL_NS + s.span.powi(d as i32) * d as f64 * ENUM_NS;
    1e-9 * (points * per_point * memory / speedup + setup)
}

/// The points Bridson's loop places at radius `r` with `k` candidates: the measured
/// packing fraction over the volume of a disk of radius `r / 2`, in the box of side 1 (the
/// disks of points near a face stick out, which the packing bound's `(1 + r)^d` counts).
pub(crate) fn expected_points(d: usize, r: f64, k: u32, bound: f64) -> f64 {
    let i = d.clamp(1, 8) - 1;
    let phi = PHI.get(i).copied().unwrap_or(0.015) * (f64::from(k) / 30.0).powf(d as f64 / 50.0);
    (phi / super::poisson::ball_volume(d, 0.5 * r))
        .min(bound)
        .max(1.0)
}
