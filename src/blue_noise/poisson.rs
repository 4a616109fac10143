//! Poisson-disk sampling: point sets in which no two points are closer than a radius `r`,
//! on the unit cube `[0, 1)^d` (Euclidean distance) or the unit torus (nearest-image
//! distance), by Bridson's algorithm, optionally filled up to a maximal set.
//!
//! * **By radius**: [`PoissonDisk::new`]. Bridson with `k = 30` candidates reaches a
//!   density `N r^2 ≈ 0.61` in 2D (relative radius `r / r_max ≈ 0.73`, `r_max =
//!   sqrt(2 / (sqrt(3) N))` the hexagonal spacing, Lagae & Dutré 2008); a maximal set
//!   ([`PoissonDisk::maximal`]: no disk of radius `r` fits anywhere) reaches about 0.69,
//!   the random-sequential-adsorption jamming density.
//! * **By count** ([`PoissonDisk::with_points`]): "about `N` points". The radius is first
//!   set from the packing fraction `phi = N V_d(r/2)` measured for the chosen options
//!   (2D Bridson torus: `phi ≈ 0.478`, i.e. `N r^2 ≈ 0.608`), one pilot set is drawn at
//!   that radius, and the radius is corrected by `(N_pilot / N)^(1/d)` for the final set:
//!   the count lands within a few per cent of `N` (the exact count is random).
//!
//! In 2D (radius below 1/6) the set grows by tiles of the background grid, four colours of
//! tiles one after the other and the tiles of a colour in parallel (rayon): cells of side
//! `1/g`, `g = ceil(sqrt(2) / r)`, split into `n = ceil(g / 128)` tiles a side (on the
//! torus `n` even and at least 2), tile `i` starting at cell `floor(i g / n)`. The set
//! depends on the seed only, not on the number of threads; its density matches the
//! sequential loop's, its spectrum keeps the low-frequency plateau, and the density across
//! tile borders is flat (tests). Other dimensions, and larger radii, run the sequential
//! loop.
//!
//! Every pair of the result is at least `r` apart, computed from the written 0.32
//! coordinates (`x = c / 2^32`) in `f64`. Cost: `O(N (k c_d + v))` for the `v` neighbour
//! cells of a full test (25 in 2D, 6095 in 5D, about 10^6 in 8D) and a rejected
//! candidate's test `c_d`, estimated before anything runs ([`PoissonDisk::cost`], the model
//! and its measured constants in `poisson_cost`) and checked against a [`Budget`]; the
//! budget's deadline then bounds the run whatever the estimate said. The maximal fill in 3
//! or more dimensions has no useful estimate (its cubes multiply at each split): there the
//! deadline is the bound.
//!
//! ```
//! use qmckit::blue_noise::PoissonDisk;
//! use qmckit::work::Budget;
//! let set = PoissonDisk::new(2, 0.05)?.torus(true).seed(7).generate(&Budget::DEFAULT)?;
//! assert!(set.count() > 150);
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::PointSet;
use super::bridson::{bridson, fill_maximal};
use super::grid::{Grid, cells_per_axis};
use super::poisson_cost;
use super::rng::Rng;
use super::tiles::bridson_tiled;
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The largest dimension [`PoissonDisk`] accepts.
pub const POISSON_MAX_DIMS: usize = 8;

/// The most points a set may be asked to hold (by its packing bound): 2^28.
pub const POISSON_MAX_POINTS: u64 = 1 << 28;

/// What the size of the set is given by.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Target {
    Radius(f64),
    Points(u64),
}

/// A Poisson-disk construction (builder); see the module text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoissonDisk {
    dims: usize,
    target: Target,
    torus: bool,
    seed: u64,
    candidates: u32,
    maximal: bool,
    surface: bool,
}

/// The volume of the `d`-ball of radius `rho`: `pi^(d/2) rho^d / Gamma(d/2 + 1)`.
pub(crate) fn ball_volume(d: usize, rho: f64) -> f64 {
    // V_0 = 1, V_1 = 2 rho, V_d = V_{d-2} 2 pi rho^2 / d.
    let mut v = [1.0, 2.0 * rho];
    let mut out = if d == 0 { 1.0 } else { 2.0 * rho };
    for k in 2..=d {
        let next = v[k % 2] * core::f64::consts::TAU * rho * rho / k as f64;
        v[k % 2] = next;
        out = next;
    }
    out
}

impl PoissonDisk {
    /// Points at least `radius` apart in `dims` dimensions (1 to [`POISSON_MAX_DIMS`]), on
    /// the unit cube, seed 0, `k = 30` candidates, not maximal.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`], [`Error::DimensionOutOfRange`]; [`Error::InvalidParameter`]
    /// for a radius that is not a number in `(0, 1]`; [`Error::TooLarge`] when the packing
    /// bound passes [`POISSON_MAX_POINTS`] (e.g. `r = 1e-6` in 2D: ~10^12 points).
    pub fn new(dims: usize, radius: f64) -> Result<Self> {
        check_dims(dims)?;
        if !(radius > 0.0 && radius <= 1.0) {
            return Err(Error::InvalidParameter {
                what: "a Poisson-disk radius must be a number in (0, 1]",
            });
        }
        let pd = PoissonDisk {
            dims,
            target: Target::Radius(radius),
            torus: false,
            seed: 0,
            candidates: 30,
            maximal: false,
            surface: false,
        };
        pd.max_points()?;
        Ok(pd)
    }

    /// About `n` points (see the module text for how the radius is chosen).
    ///
    /// # Errors
    /// As [`new`](Self::new); [`Error::ZeroPoints`] for `n = 0`, [`Error::TooManyPoints`]
    /// past [`POISSON_MAX_POINTS`] / 2.
    pub fn with_points(dims: usize, n: u64) -> Result<Self> {
        check_dims(dims)?;
        if n == 0 {
            return Err(Error::ZeroPoints);
        }
        if n > POISSON_MAX_POINTS / 2 {
            return Err(Error::TooManyPoints {
                requested: n,
                max: POISSON_MAX_POINTS / 2,
            });
        }
        Ok(PoissonDisk {
            dims,
            target: Target::Points(n),
            torus: false,
            seed: 0,
            candidates: 30,
            maximal: false,
            surface: false,
        })
    }

    /// On the torus (`true`) or the cube.
    pub fn torus(mut self, torus: bool) -> Self {
        self.torus = torus;
        self
    }

    /// The seed: equal seeds give equal sets.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// Bridson's candidates on the sphere of radius `1.001 r` around the active point
    /// (`true`; SciPy's `hypersphere="surface"`) or uniform in the shell `r <= |y - x| <
    /// 2r` (`false`, the default). Surface candidates pack the set more tightly (each new
    /// point touches its parent's disk).
    ///
    /// ```
    /// use qmckit::blue_noise::PoissonDisk;
    /// use qmckit::work::Budget;
    /// let shell = PoissonDisk::new(2, 0.05)?.seed(1).generate(&Budget::DEFAULT)?;
    /// let surface = PoissonDisk::new(2, 0.05)?.surface(true).seed(1).generate(&Budget::DEFAULT)?;
    /// assert!(surface.count() > shell.count());
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn surface(mut self, surface: bool) -> Self {
        self.surface = surface;
        self
    }

    /// Fill the set up to a maximal one (no further disk fits).
    pub fn maximal(mut self, maximal: bool) -> Self {
        self.maximal = maximal;
        self
    }

    /// Bridson's candidates per step, `k` (1 to 10^4; default 30).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn candidates(mut self, k: u32) -> Result<Self> {
        if !(1..=10_000).contains(&k) {
            return Err(Error::InvalidParameter {
                what: "Poisson-disk candidates must be 1 to 10000",
            });
        }
        self.candidates = k;
        Ok(self)
    }

    /// The dimension.
    pub fn dims(&self) -> usize {
        self.dims
    }

    /// The packing fraction `N V_d(r/2)` the options reach (measured, 2D exact to ~1%;
    /// higher dimensions a first guess that the pilot corrects).
    fn packing(&self) -> f64 {
        let phi2 = if self.maximal { 0.545 } else { 0.478 };
        // Random packings thin out with the dimension: a first guess (0.7 per dimension)
        // that the pilot set corrects.
        phi2 * 0.7f64.powi(self.dims as i32 - 2)
    }

    /// The radius a count target starts from.
    fn radius_for(&self, n: u64) -> f64 {
        // N V_d(r/2) = phi  =>  r = 2 (phi / (N V_d(1)))^(1/d).
        let d = self.dims as f64;
        2.0 * (self.packing() / (n as f64 * ball_volume(self.dims, 1.0))).powf(1.0 / d)
    }

    /// The packing bound on the number of points at radius `r`.
    fn bound(&self, r: f64) -> f64 {
        let room = if self.torus {
            1.0
        } else {
            (1.0 + r).powi(self.dims as i32)
        };
        room / ball_volume(self.dims, 0.5 * r)
    }

    /// The packing bound of the construction (its largest radius choice for a count).
    fn max_points(&self) -> Result<f64> {
        let r = match self.target {
            Target::Radius(r) => r,
            Target::Points(n) => 0.8 * self.radius_for(n),
        };
        let b = self.bound(r);
        if b.is_nan() || b > POISSON_MAX_POINTS as f64 {
            return Err(Error::TooLarge {
                what: "Poisson-disk points (packing bound)",
                requested: b.min(u64::MAX as f64) as u64,
                max: POISSON_MAX_POINTS,
            });
        }
        Ok(b)
    }

    /// The estimated running time (the `poisson_cost` model): the expected points of each
    /// construction (the pilot and the final set for a count target) times their measured
    /// cost a point, plus the grid. Calibrated within a factor 2 of measured runs for
    /// Bridson's loop in 1 to 8 dimensions and the 2D maximal fill
    /// (docs/budgets.md); the maximal fill in 3 or more dimensions has no useful
    /// estimate, and the deadline of [`generate`](Self::generate) bounds it.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn cost(&self) -> Result<Cost> {
        self.max_points()?;
        let (d, k) = (self.dims, self.candidates);
        let points = |r: f64| {
            let n = poisson_cost::expected_points(d, r, k, self.bound(r));
            if self.maximal {
                (1.15 * n).min(self.bound(r))
            } else {
                n
            }
        };
        let one = |r: f64| {
            let tiled = d == 2 && r < 1.0 / 6.0 && cells_per_axis(r, 2) >= 32.0;
            poisson_cost::seconds(d, r, self.torus, k, self.maximal, points(r), tiled)
        };
        let seconds = match self.target {
            Target::Radius(r) => one(r),
            Target::Points(n) => {
                let r0 = self.radius_for(n);
                let ratio = points(r0) / n as f64;
                let r1 = (r0 * ratio.powf(1.0 / d as f64)).min(1.0);
                one(r0) + one(r1)
            }
        };
        Ok(Cost::steps(seconds, Rate::per_second(1.0)))
    }

    /// The set, refused before it starts when [`cost`](Self::cost) exceeds `budget`, and
    /// stopped at the budget's deadline (started here if the caller has not): a run admitted
    /// under a budget of `B` seconds ends within about `1.25 B` whatever the estimate said.
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        let budget = budget.started();
        budget.check("Poisson-disk sampling", self.cost()?)?;
        let (set, _) = match self.target {
            Target::Radius(r) => self.run(r, &budget)?,
            Target::Points(n) => {
                let r1 = self.corrected_radius(n, &budget)?;
                self.run(r1, &budget)?
            }
        };
        Ok(set)
    }

    /// The radius of a radius target, or the radius a count target ends up using (which
    /// draws the pilot set: the cost of one construction).
    ///
    /// # Errors
    /// As [`generate`](Self::generate).
    pub fn radius(&self, budget: &Budget) -> Result<f64> {
        match self.target {
            Target::Radius(r) => Ok(r),
            Target::Points(n) => {
                let budget = budget.started();
                budget.check("Poisson-disk sampling", self.cost()?)?;
                self.corrected_radius(n, &budget)
            }
        }
    }

    /// The radius of a count target after its pilot set: `r0 (N_pilot / n)^(1/d)`, at most 1.
    fn corrected_radius(&self, n: u64, budget: &Budget) -> Result<f64> {
        let r0 = self.radius_for(n);
        let (pilot, _) = self.run(r0, budget)?;
        let ratio = pilot.count() as f64 / n as f64;
        Ok((r0 * ratio.powf(1.0 / self.dims as f64)).min(1.0))
    }

    /// One construction at radius `r`: the set and `r`.
    /// In 2D the tiled, parallel loop grows the set ([`super::tiles`]) where the grid is
    /// large enough; elsewhere the sequential loop. Every loop checks `budget`'s deadline.
    fn run(&self, r: f64, budget: &Budget) -> Result<(PointSet, f64)> {
        let (k, surface) = (self.candidates, self.surface);
        match self.dims {
            1 => self.run_d::<1>(r, budget, |g, rng| bridson(g, k, surface, rng, budget)),
            2 => self.run_d::<2>(r, budget, |g, rng| {
                if bridson_tiled(g, k, surface, self.seed, budget)? {
                    Ok(())
                } else {
                    bridson(g, k, surface, rng, budget)
                }
            }),
            3 => self.run_d::<3>(r, budget, |g, rng| bridson(g, k, surface, rng, budget)),
            4 => self.run_d::<4>(r, budget, |g, rng| bridson(g, k, surface, rng, budget)),
            5 => self.run_d::<5>(r, budget, |g, rng| bridson(g, k, surface, rng, budget)),
            6 => self.run_d::<6>(r, budget, |g, rng| bridson(g, k, surface, rng, budget)),
            7 => self.run_d::<7>(r, budget, |g, rng| bridson(g, k, surface, rng, budget)),
            _ => self.run_d::<8>(r, budget, |g, rng| bridson(g, k, surface, rng, budget)),
        }
    }

    fn run_d<const D: usize>(
        &self,
        r: f64,
        budget: &Budget,
        grow: impl FnOnce(&mut Grid<D>, &mut Rng) -> Result<()>,
    ) -> Result<(PointSet, f64)> {
        let bound = self.bound(r);
        if bound.is_nan() || bound > POISSON_MAX_POINTS as f64 {
            return Err(Error::TooLarge {
                what: "Poisson-disk points (packing bound)",
                requested: bound.min(u64::MAX as f64) as u64,
                max: POISSON_MAX_POINTS,
            });
        }
        let _ = cells_per_axis(r, D);
        // Reserve the expected count; the vector grows if a set is denser.
        let expect = (1.2 * self.packing() / ball_volume(D, 0.5 * r)).min(bound) as usize + 16;
        let mut grid = Grid::<D>::new(r, self.torus, expect, budget)?;
        let mut rng = Rng::new(self.seed, 0x5045_4953_534F_4E31 ^ D as u64);
        grow(&mut grid, &mut rng)?;
        if self.maximal {
            fill_maximal(&mut grid, &mut rng, budget)?;
        }
        let mut coords =
            crate::size::vec_zeroed::<u32>(crate::size::coordinates(grid.pts.len() as u64, D)?)?;
        for (row, p) in coords.chunks_exact_mut(D).zip(&grid.pts) {
            row.copy_from_slice(p);
        }
        Ok((PointSet::new(coords, D)?, r))
    }
}

fn check_dims(dims: usize) -> Result<()> {
    if dims == 0 {
        return Err(Error::ZeroDimensions);
    }
    if dims > POISSON_MAX_DIMS {
        return Err(Error::DimensionOutOfRange {
            dim: dims - 1,
            dims: POISSON_MAX_DIMS,
        });
    }
    Ok(())
}
