//! Forced random sampling (Cornel, Tobler, Sakai, Luksch & Wimmer, "Forced Random
//! Sampling: fast generation of importance-guided blue-noise samples", The Visual Computer
//! 33, 2017): about `N` points of the unit square distributed by an importance density
//! `f`, by thresholding a precomputed blue-noise rank matrix against `f`.
//!
//! ## The method
//!
//! A forcing matrix `M` is an `R x R` toroidal image holding a permutation of
//! `0..R^2` such that every threshold `{c : M(c) < t R^2}` is a blue-noise pattern. The
//! paper builds it by placing matrix cells one after another where a repulsive force
//! field of the cells placed so far is lowest, once, and ships it. By default the matrix
//! is the shipped `256 x 256` table [`FORCING_MATRIX`], built that way
//! ([`super::force_field`], force `exp(-sqrt(1.25 r))` (width 1.6), wider than the paper's so
//! that the sparse thresholds of a few thousand points are evenly spaced;
//! `examples/gen_forcing_matrix.rs` writes it), and the seed
//! picks one of its `8 x 256^2` images under the symmetries of the square and toroidal
//! shifts (each as blue), plus the positions within cells: nothing is built per run.
//! [`ForcedRandom::matrix_side`] builds a seeded void-and-cluster mask
//! ([`super::VoidAndCluster`], same role: every threshold blue) of another side per run
//! instead.
//!
//! The square is cut into a `G x G` grid of cells, `G = k R`, the matrix tiled `k x k`
//! times over it. With `f_c` the density at the centre of cell `c` and
//! `t_c = N f_c / sum_c' f_c'` (the expected number of points of the cell; `sum_c t_c =
//! N`), cell `c` is taken when `M(c mod R) + 1/2 < t_c R^2`, and its point is drawn
//! uniformly in the cell. In a region where `f` is constant a fraction `t` of the matrix
//! cells pass, spread as the matrix's threshold `t` is: the counts follow `N` times the
//! integral of `f` over the region (up to the midpoint rule on the grid and one cell's
//! rounding a tile), and the pattern is blue noise (tests). `k` is the smallest power of
//! two with every `t_c <= 1/4` (at most 64); a density too peaked for that (`t_c > 1`
//! even at `k = 64`) is refused, not clamped. With constant `f` and `N <= R^2 / 4` the
//! grid is the matrix itself and the set holds exactly `N` points (`ceil`: the cells of
//! rank below `N`).
//!
//! ## Range and cost
//!
//! `N` from 1 to 2^22, `R` from 16 to 1024 (default 256, the shipped table: `R^2` steps
//! to move it). A built matrix costs what [`super::VoidAndCluster::cost`] says (128 x 128:
//! about 0.1 s); for the constant density with `N <= R^2 / 10` only its initial pattern
//! is built and ranked, which skips the filling of the other nine tenths, most of that
//! cost; the sampling evaluates `f`
//! at the `G^2 <= 2^26` cell centres (one pass, one more per doubling of `k`) and is
//! linear in them; estimated with the matrix against a [`Budget`], stopped at its
//! deadline. Memory `G^2` values.
//!
//! ```
//! use qmckit::blue_noise::ForcedRandom;
//! use qmckit::work::Budget;
//! let set = ForcedRandom::new(500)?.seed(2).generate(&Budget::DEFAULT)?;
//! assert_eq!(set.count(), 500);
//! // Four times the density on the right half: about 4/5 of the points there.
//! let f = |p: [f64; 2]| if p[0] < 0.5 { 1.0 } else { 4.0 };
//! let set = ForcedRandom::new(1000)?.sample(&f, &Budget::DEFAULT)?;
//! let right = set.to_f64().chunks(2).filter(|p| p[0] >= 0.5).count();
//! assert!((780..=820).contains(&right));
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::rng::Rng;
use super::{PointSet, VoidAndCluster};
use crate::work::{Budget, Cost, Rate};
use crate::{Error, Result};

/// The most points [`ForcedRandom`] takes: 2^22.
pub const FORCED_MAX_POINTS: u64 = 1 << 22;

/// The most grid cells: 2^26.
const MAX_CELLS: usize = 1 << 26;

/// Grid cells a second (a density evaluation and a comparison; the density's own cost
/// unknown, taken slow).
const CELLS: Rate = Rate::per_second(5e7);

/// Forced random sampling (builder); see the module text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForcedRandom {
    n: u64,
    side: usize,
    seed: u64,
    /// `None`: the shipped table ([`FORCING_MATRIX`]); `Some`: a mask built per run.
    matrix: Option<VoidAndCluster>,
}

/// The side of the shipped forcing matrix.
pub const FORCING_SIDE: usize = 256;

/// The shipped forcing matrix: `256 x 256` ranks, row-major, a permutation of `0..65536`
/// (`tables/forcing-256.bin`, written by `examples/gen_forcing_matrix.rs`: this crate's
/// void-and-cluster mask, `sigma = 5` cells, seed 0).
pub static FORCING_MATRIX: [u16; FORCING_SIDE * FORCING_SIDE] =
    le_u16s(include_bytes!("../../tables/forcing-256.bin"));

const fn le_u16s<const N: usize>(bytes: &[u8]) -> [u16; N] {
    let mut out = [0u16; N];
    let mut i = 0;
    while i < N && 2 * i + 1 < bytes.len() {
        out[i] = u16::from_le_bytes([bytes[2 * i], bytes[2 * i + 1]]);
        i += 1;
    }
    out
}

impl ForcedRandom {
    /// About `n` points (1 to [`FORCED_MAX_POINTS`]), the shipped 256 x 256 matrix, seed 0.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`], [`Error::TooManyPoints`].
    pub fn new(n: u64) -> Result<Self> {
        crate::size::points(n, FORCED_MAX_POINTS)?;
        Ok(ForcedRandom {
            n,
            side: FORCING_SIDE,
            seed: 0,
            matrix: None,
        })
    }

    /// A matrix of side `R` (16 to 1024) built per run from the seed: Ulichney's
    /// void-and-cluster mask, `sigma = 1.5` cells (instead of the shipped table).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn matrix_side(mut self, side: usize) -> Result<Self> {
        if !(16..=1024).contains(&side) {
            return Err(Error::InvalidParameter {
                what: "the forcing matrix side must be 16 to 1024 cells",
            });
        }
        self.side = side;
        self.matrix = Some(VoidAndCluster::new(side, side)?);
        Ok(self)
    }

    /// The seed: the positions within cells, and the matrix (the shipped one turned by one
    /// of its 8 symmetries of the square and shifted toroidally by a uniform offset;
    /// a built one seeded).
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The estimated running time: the matrix, and `G^2` cells with `G^2` about
    /// `max(R^2, 4 N)` (for a constant density; a peaked one refines further).
    pub fn cost(&self) -> Cost {
        let r2 = (self.side * self.side) as f64;
        let cells = r2.max(4.0 * self.n as f64);
        let matrix = self.matrix.map_or(Cost::steps(r2, CELLS), |m| m.cost());
        matrix.plus(Cost::steps(2.0 * cells, CELLS))
    }

    /// About `n` points of the uniform density.
    ///
    /// # Errors
    /// As [`ForcedRandom::sample`].
    pub fn generate(&self, budget: &Budget) -> Result<PointSet> {
        // Constant density, N <= R^2 / 4: the grid is the matrix and only the cells of rank
        // below N are taken, so only those ranks are built.
        let r2 = self.side * self.side;
        let limit = if self.n as usize <= r2 / 4 {
            self.n as usize
        } else {
            r2
        };
        self.sample_ranked(&|_| 1.0, limit, budget)
    }

    /// About `n` points following `density` (finite, non-negative, not zero everywhere on
    /// the cell centres; any scale: it is normalized).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a negative or non-finite density value, a density
    /// zero at every cell centre, or one too peaked for the finest grid; [`Error::ZeroPoints`]
    /// when no cell passes; [`Error::OverBudget`], [`Error::TooLarge`],
    /// [`Error::OutOfTime`].
    pub fn sample(&self, density: &dyn Fn([f64; 2]) -> f64, budget: &Budget) -> Result<PointSet> {
        self.sample_ranked(density, self.side * self.side, budget)
    }

    /// The shipped matrix moved by the seed: rank of cell `(i, j)` is the table's at
    /// `sigma((i + a) mod R, (j + b) mod R)`, `sigma` one of the 8 symmetries of the square
    /// (identity, the flips, the transposition and their products), `(a, b)` uniform.
    /// Blue noise is isotropic and the matrix toroidal, so each image is as good a forcing
    /// matrix as the table.
    fn shipped_ranks(&self) -> Result<Vec<u32>> {
        let r = FORCING_SIDE;
        let mut rng = Rng::new(self.seed, 0x464F_5243_454D_4154); // "FORCEMAT"
        let (a, b) = (rng.below(r), rng.below(r));
        let sym = rng.below(8);
        let mut ranks = crate::size::vec_zeroed::<u32>(r * r)?;
        for (c, v) in ranks.iter_mut().enumerate() {
            let (mut x, mut y) = ((c % r + a) % r, (c / r + b) % r);
            if sym & 1 == 1 {
                x = r - 1 - x;
            }
            if sym & 2 == 2 {
                y = r - 1 - y;
            }
            if sym & 4 == 4 {
                core::mem::swap(&mut x, &mut y);
            }
            *v = u32::from(FORCING_MATRIX.get(y * r + x).copied().unwrap_or(u16::MAX));
        }
        Ok(ranks)
    }

    /// [`ForcedRandom::sample`] with the matrix's ranks built only below `limit` (the
    /// others never pass: callers make sure no cell needs them).
    fn sample_ranked(
        &self,
        density: &dyn Fn([f64; 2]) -> f64,
        limit: usize,
        budget: &Budget,
    ) -> Result<PointSet> {
        const WHAT: &str = "forced random sampling";
        let budget = budget.started();
        budget.check(WHAT, self.cost())?;
        let r = self.side;
        let ranks = match self.matrix {
            Some(m) => m.seed(self.seed).ranks_below(limit, &budget)?,
            None => self.shipped_ranks()?,
        };
        let n = self.n as f64;
        let mut pacer = budget.pacer(WHAT);
        // The grid: the smallest power-of-two number of tiles with every t_c <= 1/4.
        let mut k = 1usize;
        let (f, total) = loop {
            let g = k * r;
            let cells = g * g;
            if cells > MAX_CELLS {
                return Err(Error::InvalidParameter {
                    what: "the density is too peaked for the forced random grid (2^26 cells)",
                });
            }
            let mut f = crate::size::vec_zeroed::<f64>(cells)?;
            let mut total = 0.0;
            for (c, v) in f.iter_mut().enumerate() {
                pacer.tick()?;
                let p = [
                    ((c % g) as f64 + 0.5) / g as f64,
                    ((c / g) as f64 + 0.5) / g as f64,
                ];
                let x = density(p);
                if !(x.is_finite() && x >= 0.0) {
                    return Err(Error::InvalidParameter {
                        what: "a density must be finite and non-negative",
                    });
                }
                *v = x;
                total += x;
            }
            if !(total > 0.0 && total.is_finite()) {
                return Err(Error::InvalidParameter {
                    what: "the density is zero at every cell centre (or its sum overflows)",
                });
            }
            let peak = f.iter().fold(0.0f64, |a, &b| a.max(b)) * n / total;
            if peak <= 0.25 {
                break (f, total);
            }
            if k >= 64 {
                if peak <= 1.0 {
                    break (f, total);
                }
                return Err(Error::InvalidParameter {
                    what: "the density is too peaked for the forced random grid (64 tiles a side)",
                });
            }
            k *= 2;
        };
        let g = k * r;
        let scale = n * (r * r) as f64 / total;
        let mut rng = Rng::new(self.seed, 0x464F_5243_4544_524E); // "FORCEDRN"
        let mut coords = Vec::new();
        let cell = 1.0 / g as f64;
        for (c, &v) in f.iter().enumerate() {
            pacer.tick()?;
            let (i, j) = (c % g, c / g);
            let rank = ranks.get((j % r) * r + i % r).copied().unwrap_or(u32::MAX);
            if f64::from(rank) + 0.5 < v * scale {
                crate::size::reserve(&mut coords, 2)?;
                for (at, u) in [(i, rng.unit()), (j, rng.unit())] {
                    let x = (at as f64 + u) * cell;
                    coords.push(super::lloyd::to_fraction(x.min(1.0)));
                }
            }
        }
        if coords.is_empty() {
            return Err(Error::ZeroPoints);
        }
        PointSet::new(coords, 2)
    }
}
