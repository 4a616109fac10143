//! Projective blue noise (Reinert, Ritschel, Seidel & Georgiev, "Projective Blue-Noise
//! Sampling", Computer Graphics Forum 35(1), 2016): `N` points of the unit torus
//! `[0, 1)^d` that are blue noise in the full space and in every axis-aligned projection of
//! one and of two dimensions, by dart throwing with one radius a subspace.
//!
//! ## The criterion
//!
//! A candidate `x` is accepted when, for every point `y` already accepted, with the
//! per-axis toroidal differences `t_k = min(|x_k - y_k|, 1 - |x_k - y_k|)`,
//!
//! * full space: `sum_k t_k^2 >= r_d^2`,
//! * every 1D projection `k`: `t_k >= r_1`,
//! * every 2D projection `(k, l)`, `k < l` (when `d > 2`): `t_k^2 + t_l^2 >= r_2^2`.
//!
//! Each radius is a fraction of the largest spacing `N` points can have in a space of that
//! dimension, the spacing of its densest lattice packing,
//! `r_max(N, m) = 2 (Delta_m / (N V_m))^(1/m)` (`V_m` the unit ball's volume, `Delta_m`
//! the packing density: 1 on the line, `pi / sqrt 12` for the hexagonal lattice,
//! `pi / sqrt 18` for FCC, then `D_4`, `D_5`, `E_6`, `E_7`, `E_8`; Conway & Sloane, table
//! 1.2): `r_d = rho r_max(N, d)` and `r_m = w rho r_max(N, m)` for the projections, `rho`
//! the relative radius shared by all spaces and `w` the projections' weight (default 1).
//! The paper measures every subspace by its own relative radius in this way; `w < 1`
//! trades blue noise in the projections for spacing in the full space.
//!
//! ## The radius schedule
//!
//! The set must hold exactly `N` points, but the largest `rho` at which dart throwing can
//! place them is not known in advance (smaller with each projection added). As in
//! relaxation dart throwing (McCool & Fiume, "Hierarchical Poisson disk sampling
//! distributions", Graphics Interface 1992) `rho` starts high (default 0.9) and is
//! multiplied by `s` (default 0.99) after `T` consecutive rejected candidates (default
//! 1000). Every point accepted satisfied the radii of its time, which never grow, so the
//! final `rho` holds for every pair: the result states it
//! ([`ProjectiveSet::relative_radius`]) with the radii it implies (tested against the
//! brute-force minimum distances). Candidates are 0.32 fractions and are tested as the
//! exact `f64` of the coordinates written. Measured final `rho` (seed 0, defaults, 1024
//! points): 0.51 in 2D, 0.38 in 3D, 0.31 in 4D; the full-space test alone reaches 0.69
//! to 0.71 (near the jamming limit of random sequential adsorption, Lagae & Dutré 2008).
//! The low-frequency power of the projections then falls from the white-noise level 1 to
//! about 0.1 (1D) in 2D and 0.2 to 0.3 (1D) and 0.35 to 0.5 (2D) in 3D and 4D
//! (tests; `T` = 5000 buys 10 to 20 per cent lower power at five times the time).
//!
//! `projections(0)` keeps only the full-space test (classic relaxation dart throwing,
//! whose projections are white noise: the contrast), `projections(1)` adds the 1D
//! projections, `projections(2)` (default) the 2D ones too.
//!
//! ## Range and cost
//!
//! `d` from 2 to 8, `N` from 1 to 2^16. Each candidate is tested only against the points
//! that can conflict with it, found in uniform toroidal grids, one for the full space and
//! one for each tested projection (module `projective_grid`, cells at least the starting
//! radius wide, at most `4 N` cells a grid): the same accepted set as testing all points
//! (a rejection is a true conflict, and every conflict lies in a neighbour cell; the
//! radii are checked on every pair in the tests), each test `O(d^2)` with the 2D projections, stopping at the first
//! conflict. About `a N` candidates are drawn (`a` from 0.15 `T` to 0.4 `T`, growing
//! with `d`), each visiting `O(3^d + d^2)` cells; small sets whose grids would have
//! fewer than 3 cells an axis take the all-pairs scan, `O(a N^2 d^2)`. The estimate
//! ([`ProjectiveBlueNoise::cost`]) keeps the all-pairs bound; checked against a
//! [`Budget`] and stopped at its deadline (checked every few thousand pair tests).
//! Measured (defaults, one core): 1024 points in 2D in 0.01 s of CPU (0.10 s with the
//! all-pairs scan). Memory `N d` values and the grids' `O(N d^2)` cells.
//!
//! ```
//! use qmckit::blue_noise::ProjectiveBlueNoise;
//! use qmckit::work::Budget;
//! let p = ProjectiveBlueNoise::new(256, 3)?.seed(5).run(&Budget::DEFAULT)?;
//! assert_eq!(p.points.count(), 256);
//! // Every 1D projection keeps its points r_1 apart: a fraction of the 1/N of a
//! // stratified (Latin hypercube) projection.
//! assert!(p.radius_1d.unwrap() > 0.2 / 256.0);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::poisson::ball_volume;
use super::projective_grid::AxisGrid;

/// A neighbour grid with its list links.
type Grid = (AxisGrid, Vec<u32>);
use super::rng::Rng;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The most points [`ProjectiveBlueNoise`] takes: 2^16 (the pair tests grow as `N^2`).
pub const PROJECTIVE_MAX_POINTS: u64 = 1 << 16;

/// The most dimensions [`ProjectiveBlueNoise`] takes (the packing densities known).
pub const PROJECTIVE_MAX_DIMS: usize = 8;

/// Pair slots a second, one core, release, in units of `pair_work / d` (a rejected
/// candidate stops at its first conflict, so a slot is about half a pair test; measured
/// 1.3e9 in 2D, 1e9 in 3D, 8.7e8 in 4D on a loaded machine, 1024 to 4096 points).
const PAIRS: Rate = Rate::per_second(1e9);

/// Densest known lattice packing densities in 1 to 8 dimensions (Conway & Sloane,
/// "Sphere packings, lattices and groups", table 1.2): Z, A2, A3 = D3, D4, D5, E6, E7, E8.
fn packing_density(m: usize) -> f64 {
    use core::f64::consts::PI;
    match m {
        1 => 1.0,
        2 => PI / 12f64.sqrt(),
        3 => PI / 18f64.sqrt(),
        4 => PI * PI / 16.0,
        5 => PI * PI * 2f64.sqrt() / 30.0,
        6 => PI * PI * PI * 3f64.sqrt() / 144.0,
        7 => PI * PI * PI / 105.0,
        _ => PI.powi(4) / 384.0,
    }
}

/// `r_max(N, m) = 2 (Delta_m / (N V_m))^(1/m)`: the spacing of `N` points of unit volume
/// packed as the densest lattice of dimension `m` (1 to 8).
pub fn max_spacing(n: u64, m: usize) -> f64 {
    let v = ball_volume(m, 1.0);
    2.0 * (packing_density(m) / (n.max(1) as f64 * v)).powf(1.0 / m as f64)
}

/// Projective blue-noise dart throwing (builder); see the module text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectiveBlueNoise {
    n: u64,
    dims: usize,
    projections: u8,
    start: f64,
    shrink: f64,
    trials: u32,
    weight: f64,
    seed: u64,
}

/// A projective blue-noise set with the radii it keeps.
#[derive(Clone, Debug, PartialEq)]
pub struct ProjectiveSet {
    /// The points, in the order they were accepted.
    pub points: PointSet,
    /// The final relative radius `rho`.
    pub relative_radius: f64,
    /// `r_d`: no two points are closer in the full space (toroidal distance).
    pub radius: f64,
    /// `r_1`, when the 1D projections were tested: no two points are closer along any axis.
    pub radius_1d: Option<f64>,
    /// `r_2`, when the 2D projections were tested (`d > 2`): no two points are closer in
    /// any pair of axes.
    pub radius_2d: Option<f64>,
    /// Candidates drawn.
    pub candidates: u64,
}

impl ProjectiveBlueNoise {
    /// `n` points (1 to [`PROJECTIVE_MAX_POINTS`]) in `dims` (2 to
    /// [`PROJECTIVE_MAX_DIMS`]) dimensions, 1D and 2D projections tested, `rho` from 0.9
    /// shrunk by 0.99 after 1000 rejections, weight 1, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`], [`Error::ZeroDimensions`],
    /// [`Error::InvalidParameter`] in 1D, [`Error::DimensionOutOfRange`] past 8.
    pub fn new(n: u64, dims: usize) -> Result<Self> {
        crate::size::points(n, PROJECTIVE_MAX_POINTS)?;
        if dims == 0 {
            return Err(Error::ZeroDimensions);
        }
        if dims == 1 {
            return Err(Error::InvalidParameter {
                what: "projective blue noise needs 2 or more dimensions (a 1D set has no projection)",
            });
        }
        if dims > PROJECTIVE_MAX_DIMS {
            return Err(Error::DimensionOutOfRange {
                dim: dims,
                dims: PROJECTIVE_MAX_DIMS,
            });
        }
        Ok(ProjectiveBlueNoise {
            n,
            dims,
            projections: 2,
            start: 0.9,
            shrink: 0.99,
            trials: 1000,
            weight: 1.0,
            seed: 0,
        })
    }

    /// The largest projection dimension tested: 0 (full space only), 1 (and every axis)
    /// or 2 (and every pair of axes; the default).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] past 2.
    pub fn projections(mut self, max_dims: u8) -> Result<Self> {
        if max_dims > 2 {
            return Err(Error::InvalidParameter {
                what: "projective blue noise tests projections of 0, 1 or 2 dimensions",
            });
        }
        self.projections = max_dims;
        Ok(self)
    }

    /// The schedule: `rho` starts at `start` (in `(0, 1]`), shrinks by `shrink` (in
    /// `[0.5, 1)`) after `trials` (1 to 10^6) consecutive rejections.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside those ranges (NaN included).
    pub fn schedule(mut self, start: f64, shrink: f64, trials: u32) -> Result<Self> {
        if !(start > 0.0 && start <= 1.0) {
            return Err(Error::InvalidParameter {
                what: "the starting relative radius must lie in (0, 1]",
            });
        }
        if !(0.5..1.0).contains(&shrink) {
            return Err(Error::InvalidParameter {
                what: "the radius shrink factor must lie in [0.5, 1)",
            });
        }
        if trials == 0 || trials > 1_000_000 {
            return Err(Error::InvalidParameter {
                what: "projective blue noise takes 1 to 10^6 rejections before a shrink",
            });
        }
        (self.start, self.shrink, self.trials) = (start, shrink, trials);
        Ok(self)
    }

    /// The projections' weight `w` in `(0, 1]`: `r_m = w rho r_max(N, m)`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside `(0, 1]` (NaN included).
    pub fn weight(mut self, w: f64) -> Result<Self> {
        if !(w > 0.0 && w <= 1.0) {
            return Err(Error::InvalidParameter {
                what: "the projections' weight must lie in (0, 1]",
            });
        }
        self.weight = w;
        Ok(self)
    }

    /// The seed.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// Pair tests of one projection set a candidate, relative to the full-space test.
    fn pair_work(&self) -> f64 {
        let d = self.dims as f64;
        match self.projections {
            0 => d,
            1 => 2.0 * d,
            _ => 2.0 * d + d * (d - 1.0) / 2.0,
        }
    }

    /// The estimated running time: `a N` candidates, `a = T (0.05 + 0.08 d)` (at least
    /// 30; measured `a / T` from 0.15 to 0.38 for 1024 to 4096 points in 2D to 4D), each
    /// against the `N` slots of the accepted points, a slot costing `pair_work / d`.
    pub fn cost(&self) -> Cost {
        let n = self.n as f64;
        let a = (f64::from(self.trials) * (0.05 + 0.08 * self.dims as f64)).max(30.0);
        let per_pair = self.pair_work() / self.dims as f64;
        Cost::steps(a * n * n * per_pair, PAIRS)
    }

    /// The points, refused before they start when [`cost`](Self::cost) exceeds `budget`,
    /// stopped at its deadline.
    ///
    /// # Errors
    /// As [`ProjectiveBlueNoise::run`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        Ok(self.run(budget)?.points)
    }

    /// The neighbour grids (full space, then each tested projection) sized for the
    /// starting radii; `None` when one of them would have fewer than 3 cells an axis (the
    /// all-pairs scan is used then).
    fn grids(&self, n: usize, full: f64, one: f64, two: f64) -> Result<Option<Vec<Grid>>> {
        let d = self.dims;
        let mut specs: Vec<(Vec<usize>, f64)> = vec![((0..d).collect(), self.start * full)];
        if one > 0.0 {
            specs.extend((0..d).map(|k| (vec![k], self.start * one)));
        }
        if two > 0.0 {
            for k in 0..d {
                specs.extend((k + 1..d).map(|l| (vec![k, l], self.start * two)));
            }
        }
        let mut grids = Vec::with_capacity(specs.len());
        for (axes, r) in specs {
            match AxisGrid::new(axes, r, n)? {
                Some(g) => grids.push((g, crate::size::vec_with_capacity::<u32>(n)?)),
                None => return Ok(None),
            }
        }
        Ok(Some(grids))
    }

    /// The points with their radii.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn run(&self, budget: &Budget) -> Result<ProjectiveSet> {
        const WHAT: &str = "projective blue noise";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let (n, d) = (self.n as usize, self.dims);
        let mut coords =
            crate::size::vec_with_capacity::<u32>(crate::size::coordinates(self.n, d)?)?;
        let mut xs = crate::size::vec_with_capacity::<f64>(coords.capacity())?;
        let full = max_spacing(self.n, d);
        let one = if self.projections >= 1 {
            self.weight * max_spacing(self.n, 1)
        } else {
            0.0
        };
        let two = if self.projections >= 2 && d > 2 {
            self.weight * max_spacing(self.n, 2)
        } else {
            0.0
        };
        let mut grids = self.grids(n, full, one, two)?;
        let mut rng = Rng::new(self.seed, 0x5052_4F4A_424E_4F49); // "PROJBNOI"
        let mut pacer = budget.pacer(WHAT);
        let mut rho = self.start;
        let (mut fails, mut candidates) = (0u32, 0u64);
        let mut cand = [0u32; PROJECTIVE_MAX_DIMS];
        let mut x = [0f64; PROJECTIVE_MAX_DIMS];
        while coords.len() < n * d {
            candidates += 1;
            for (c, v) in cand.iter_mut().zip(&mut x).take(d) {
                *c = rng.fraction();
                *v = crate::bits::to_f64(*c);
            }
            let radii = Radii {
                full: (rho * full).powi(2),
                one: rho * one,
                two: (rho * two).powi(2),
            };
            let m = coords.len() / d;
            let xc = &x[..d];
            let ok = if let Some(grids) = &grids {
                let mut visits = 0u32;
                let hit = grids.iter().any(|(grid, next)| {
                    grid.any(xc, next, |j| {
                        visits = visits.saturating_add(1);
                        xs.get(j * d..j * d + d)
                            .is_some_and(|y| !radii.apart(xc, y))
                    })
                });
                pacer.tick_n(visits.max(1))?;
                !hit
            } else {
                pacer.tick_n(u32::try_from(m).unwrap_or(u32::MAX))?;
                xs.chunks_exact(d).all(|y| radii.apart(xc, y))
            };
            if ok {
                coords.extend_from_slice(&cand[..d]);
                xs.extend_from_slice(&x[..d]);
                if let Some(grids) = &mut grids {
                    for (grid, next) in grids.iter_mut() {
                        grid.insert(&x[..d], m, next);
                    }
                }
                fails = 0;
            } else {
                fails += 1;
                if fails >= self.trials {
                    rho *= self.shrink;
                    fails = 0;
                }
            }
        }
        Ok(ProjectiveSet {
            points: PointSet::new(coords, d)?,
            relative_radius: rho,
            radius: rho * full,
            radius_1d: (self.projections >= 1).then_some(rho * one),
            radius_2d: (self.projections >= 2 && d > 2).then_some(rho * two),
            candidates,
        })
    }
}

/// The radii of one candidate's test: squared full, plain 1D, squared 2D (0: untested).
struct Radii {
    full: f64,
    one: f64,
    two: f64,
}

impl Radii {
    /// Whether `x` and `y` keep every radius (toroidal differences).
    #[inline]
    fn apart(&self, x: &[f64], y: &[f64]) -> bool {
        let mut t = [0f64; PROJECTIVE_MAX_DIMS];
        let mut sum = 0.0;
        for ((t, &a), &b) in t.iter_mut().zip(x).zip(y) {
            let delta = (a - b).abs();
            let w = delta.min(1.0 - delta);
            if w < self.one {
                return false;
            }
            *t = w * w;
            sum += *t;
        }
        if sum < self.full {
            return false;
        }
        if self.two > 0.0 {
            let t = &t[..x.len()];
            for (k, &a) in t.iter().enumerate() {
                if t.iter().skip(k + 1).any(|&b| a + b < self.two) {
                    return false;
                }
            }
        }
        true
    }
}
