//! L2-type discrepancies and the diaphony: kernel quadrature errors of a point set.
//!
//! Every measure here is the worst-case integration error of the equal-weight rule
//! `Q(f) = (1/n) sum_i f(x_i)` over the unit ball of a reproducing-kernel Hilbert space with a
//! product kernel `K(x, y) = prod_k K1(x_k, y_k)`, which always expands as
//!
//! ```text
//! D^2 = int int K(x, y) dx dy  -  (2/n) sum_i int K(x_i, y) dy  +  (1/n^2) sum_{i,j} K(x_i, x_j)
//! ```
//!
//! so each costs one `O(n d)` pass plus an `O(n^2 d)` pair sum (halved by the symmetry of
//! `K`, split over rows with rayon). The exception is [`l2_star`], which has an exact
//! `O(n log^(d-1) n)` algorithm for many points in low dimension ([`l2_star_fast`]).
//!
//! | function | name | returns | convention of |
//! |---|---|---|---|
//! | [`l2_star`] | `l2-star` | `D` (square root taken) | SciPy `discrepancy(method="L2-star")` |
//! | [`centered`] | `cd` | `D^2` (squared) | SciPy `method="CD"` |
//! | [`wrap_around`] | `wd` | `D^2` (squared) | SciPy `method="WD"` |
//! | [`mixture`] | `md` | `D^2` (squared) | SciPy `method="MD"` |
//! | [`symmetric`] | `sl2` | `D` (square root taken) | UTK `SymmetricL2Discrepancy` |
//! | [`unanchored`] | `ul2` | `D` (square root taken) | UTK `UnanchoredL2Discrepancy` |
//! | [`generalized`] | `gl2` | `D` (square root taken) | UTK `GL2Discrepancy` |
//! | [`diaphony`] | `diaphony` | `F` (square root taken) | UTK `Diaphony` (Zinterhof) |
//!
//! The functions run without a time limit; [`L2Metric::eval`] estimates the cost
//! first ([`L2Metric::cost`], the models of [`cost`]), refuses what exceeds a [`Budget`](crate::work::Budget),
//! and reports progress.
//!
//! ## The pair sum
//!
//! The pair sum is one generic loop for all eight measures (module `kernel`): each
//! coordinate is first mapped to one or two features (e.g. `1 - x` for L2-star, `x / 2` and
//! `1/2 + |x - 1/2| / 2` for the centered discrepancy) so that a pair factor costs one to
//! six arithmetic operations, and the features are stored as structure of arrays in blocks
//! of 8 points. Point `i` is then evaluated against 8 points `j` at a time with fixed-size
//! array operations that compile to SIMD instructions; on x86-64 CPUs with AVX2 and FMA, or
//! AVX-512 (detected at run time), the same code runs compiled for them, with the same bits
//! (L2-star and the generalized L2, whose factor is one minimum, stay with AVX2). In one
//! and two dimensions the loop is compiled for the dimension and the products of four
//! blocks are summed in plain arithmetic before the compensated addition (otherwise the
//! summation would cost as much as the kernel); in higher dimensions the loop over the
//! coordinates multiplies the factors of even and odd coordinates in two chains. In eight
//! dimensions the centered, wrap-around, mixture and unanchored discrepancies instead run
//! a loop compiled for 8D in register tiles: four points `i` against each block of 8
//! points `j`, so each loaded block serves four rows. For 4096 points on one thread this
//! measured 7-35x faster than SciPy's `discrepancy(workers=1)` on the same points
//! (`scripts/time_discrepancy.py`, `examples/time_l2.rs`).
//!
//! ## Accuracy
//!
//! For good point sets the three terms above nearly cancel (for 1000 Sobol' points in 8
//! dimensions the wrap-around terms are about 10 and the result about 1e-3), so a plain sum
//! loses digits. Here every pair term is added to per-lane TwoSum accumulators (in one and
//! two dimensions, and in the 8D tiles, after plain sums of four terms), the lanes
//! and then the rows are summed with Neumaier compensation in a fixed order (so the result
//! does not depend on the number of threads), and
//! the three terms are combined in double-double arithmetic, with the constants `(13/12)^d`,
//! ... raised to the power `d` in double-double too. The result is accurate to a few units
//! in the last place of the exact value of the formula evaluated on the given `f64`
//! coordinates (up to the rounding of each pair product and, in one and two dimensions
//! and the 8D tiles, of the sums of four products), which is usually more accurate
//! than SciPy's plain double sums. A squared value that rounds below zero is clamped to
//! zero before a square root is taken (never a NaN).
//!
//! ## Range
//!
//! A product of `d` factors leaves the range of `f64` in high dimension: `(3/2)^d`
//! overflows from `d = 1751`, `3^-d` underflows from `d = 647`, the diaphony's
//! normalization `(1 + pi^2/3)^d` overflows from `d = 487`. Up to a dimension where no
//! product, term or constant can leave the range (512 for most measures, 224 for the
//! unanchored discrepancy, 384 for the diaphony; `measures::FAST_D`), the plain `f64` path
//! above runs unchanged. Above it the same pair loop tracks the binary exponent of every
//! product (renormalizing the partial product to `[1, 2)` every 8 coordinates with
//! integer operations; `kernel::wide_products`), scales the pair products by the largest
//! diagonal product (which bounds them all: the kernels are positive definite), and
//! carries the sums, the constants and the combination as double-doubles with a 64-bit
//! exponent, so every result is computed with the accuracy stated above whatever `d` is.
//! A result that is nonzero and outside the normal range of `f64` (above `f64::MAX`, or
//! below `2^-1022`, e.g. the L2-star discrepancy of a few points in 2000 dimensions,
//! about `2^-1400`) is [`Error::NotRepresentable`](crate::Error::NotRepresentable), never
//! an infinity, a NaN or a silent zero. The wide path costs 1.2-3.4x more time per pair
//! and coordinate than the plain one (measured on one thread, 1024 points in 1000 against
//! 500 dimensions: 1.2x for the mixture discrepancy, 1.6-1.8x for the centered,
//! wrap-around, symmetric and unanchored discrepancies and the diaphony, 2.7x and 3.4x
//! for the L2-star and generalized L2, whose plain factor is a single minimum).
//!
//! ## Fused multiply-adds
//!
//! The wrap-around, mixture and diaphony factors are written with [`f64::mul_add`] (e.g.
//! `fma(-t, 1 - t, 3/2)` for `3/2 - t (1 - t)`), which moves an addition of these add-bound
//! loops (for the wrap-around, three additions against two multiplications per coordinate)
//! to the multipliers, and rounds once fewer. `mul_add` is one correctly rounded operation
//! in every build: packed FMA instructions (`vfnmadd213pd` and the like) in the wide builds,
//! a call to the runtime library's correctly rounded `fma` in the portable one (on x86-64,
//! compiler-builtins' `fma`: the FMA instruction where the CPU has one, an exact software
//! fallback elsewhere), so the builds give the same bits (tested). The price is paid by
//! the portable build, used on x86-64 CPUs without AVX2 and FMA: one scalar call per
//! factor, about 4-8x slower for these three measures than without the FMA. Where the
//! baseline target has an FMA (e.g. aarch64) it is an instruction. The shape of the
//! expression matters to the vectorizer: `t.mul_add(t - 1, 1.5)`, the same value, compiled
//! to a partly scalar 8D loop 2.5x slower than the plain one, while
//! `(-t).mul_add(1 - t, 1.5)`, the shape of `1.5 - t * (1 - t)`, stays packed: check the
//! assembly when changing a factor.

mod arith;
pub mod cost;
mod kernel;
mod measures;
mod sums;
#[cfg(test)]
mod tests;
mod tree;

pub use measures::{
    centered, diaphony, generalized, l2_star, l2_star_direct, l2_star_fast, mixture, symmetric,
    unanchored, wrap_around,
};
pub use tree::TREE_MAX_D;

use super::Points;
use crate::Result;
use crate::work::Stop;
use crate::work::{Cost, Limits};
use kernel::{Build, Ticker};

/// The eight measures of this module, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum L2Metric {
    /// [`l2_star`] (`l2-star`, square root taken).
    L2Star,
    /// [`centered`] (`cd`, squared).
    Centered,
    /// [`wrap_around`] (`wd`, squared).
    WrapAround,
    /// [`mixture`] (`md`, squared).
    Mixture,
    /// [`symmetric`] (`sl2`, square root taken).
    Symmetric,
    /// [`unanchored`] (`ul2`, square root taken).
    Unanchored,
    /// [`generalized`] (`gl2`, square root taken).
    Generalized,
    /// [`diaphony`] (`diaphony`, square root taken).
    Diaphony,
}

impl L2Metric {
    /// All eight, in the order of the table in the module documentation.
    pub const ALL: [L2Metric; 8] = [
        L2Metric::L2Star,
        L2Metric::Centered,
        L2Metric::WrapAround,
        L2Metric::Mixture,
        L2Metric::Symmetric,
        L2Metric::Unanchored,
        L2Metric::Generalized,
        L2Metric::Diaphony,
    ];

    /// The command-line name: `l2-star`, `cd`, `wd`, `md`, `sl2`, `ul2`, `gl2`, `diaphony`.
    ///
    /// ```
    /// use qmckit::analysis::l2::L2Metric;
    /// let names: Vec<_> = L2Metric::ALL.iter().map(|m| m.name()).collect();
    /// assert_eq!(names, ["l2-star", "cd", "wd", "md", "sl2", "ul2", "gl2", "diaphony"]);
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            L2Metric::L2Star => "l2-star",
            L2Metric::Centered => "cd",
            L2Metric::WrapAround => "wd",
            L2Metric::Mixture => "md",
            L2Metric::Symmetric => "sl2",
            L2Metric::Unanchored => "ul2",
            L2Metric::Generalized => "gl2",
            L2Metric::Diaphony => "diaphony",
        }
    }

    /// What the measure is, in words (the subject of its error messages).
    fn what(self) -> &'static str {
        match self {
            L2Metric::L2Star => measures::L2_STAR,
            L2Metric::Centered => measures::CENTERED,
            L2Metric::WrapAround => measures::WRAP_AROUND,
            L2Metric::Mixture => measures::MIXTURE,
            L2Metric::Symmetric => measures::SYMMETRIC,
            L2Metric::Unanchored => measures::UNANCHORED,
            L2Metric::Generalized => measures::GENERALIZED,
            L2Metric::Diaphony => measures::DIAPHONY,
        }
    }

    /// The path's dimension limit (plain `f64` up to it, tracked exponents above).
    pub(crate) fn fast_d(self) -> usize {
        match self {
            L2Metric::Unanchored => measures::UNANCHORED_FAST_D,
            L2Metric::Diaphony => measures::DIAPHONY_FAST_D,
            _ => measures::FAST_D,
        }
    }

    /// The estimated time of [`eval`](Self::eval) on `n` points in `d`
    /// dimensions, on [`CORES`](crate::work::CORES) cores: the model of the path that runs
    /// (module [`l2::cost`](crate::analysis::l2::cost)): the pairs at this measure's
    /// [`pair_cost`](Self::pair_cost), or the features streamed from memory, or the
    /// L2-star divide and conquer's row operations. For example 30000 points in 8D: 0.38 s
    /// for the centered discrepancy, 0.22 s for the L2-star. `O(d)`.
    ///
    /// ```
    /// use qmckit::analysis::l2::L2Metric;
    /// let cd = L2Metric::Centered.cost(30_000, 8).seconds();
    /// assert!((0.3..0.5).contains(&cd));
    /// // 10^6 points in 10 dimensions: 5e11 pairs, about nine minutes.
    /// assert!(L2Metric::Centered.cost(1_000_000, 10).seconds() > 100.0);
    /// ```
    pub fn cost(self, n: usize, d: usize) -> Cost {
        cost::cost(self, n, d)
    }

    /// Evaluates the measure on `p` if its estimated cost ([`cost`](Self::cost)) fits in
    /// the budget of `limits` (`&Budget::UNLIMITED`: no limit, as the free function of the
    /// same name, e.g. [`centered`]), reporting `progress(rows done, n)` to the progress
    /// callback of `limits` about a hundred times during the pair sum (from `(0, n)` to
    /// `(n, n)`; only those two for the divide and conquer).
    ///
    /// ```
    /// use qmckit::{work::Budget, analysis::{Points, l2::L2Metric}};
    /// let data: Vec<f64> = (0..300).map(|i| (i as f64 * 0.618_033_988_749_895).fract()).collect();
    /// let p = Points::new(&data, 3)?;
    /// let budget = Budget::seconds(1.0)?;
    /// let cd = L2Metric::Centered.eval(p, &budget)?;
    /// assert_eq!(cd, L2Metric::Centered.eval(p, &Budget::UNLIMITED)?);
    /// // 10^6 points in 10 dimensions: 5e11 pairs, about nine minutes, refused at once.
    /// assert!(L2Metric::Centered.cost(1_000_000, 10).seconds() > 1.0);
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::OverBudget`](crate::Error::OverBudget) when the estimate exceeds the budget
    /// (before any work); [`Error::NotRepresentable`](crate::Error::NotRepresentable) for a
    /// value outside the normal range of `f64` (module documentation, "Range");
    /// [`Error::OutOfTime`](crate::Error::OutOfTime) past the deadline of the budget
    /// (started here if it was not), read once per task of the pair sum (`O(n d)` work) and
    /// once per node of at least 256 rows of the divide and conquer.
    pub fn eval<'a>(self, p: Points<'_>, limits: impl Into<Limits<'a>>) -> Result<f64> {
        let limits = limits.into();
        let (budget, progress) = (limits.budget(), limits.progress());
        budget.check(self.what(), self.cost(p.len(), p.dims()))?;
        let stop = Stop::new(budget, self.what());
        let t = &mut Ticker::with_stop(progress, p.len(), &stop);
        let value = match self {
            L2Metric::L2Star => measures::l2_star_with(p, t),
            L2Metric::Centered => measures::centered_with(p, Build::Avx512, t),
            L2Metric::WrapAround => measures::wrap_around_with(p, Build::Avx512, t),
            L2Metric::Mixture => measures::mixture_with(p, Build::Avx512, t),
            L2Metric::Symmetric => measures::symmetric_with(p, Build::Avx512, t),
            L2Metric::Unanchored => measures::unanchored_with(p, Build::Avx512, t),
            L2Metric::Generalized => measures::generalized_with(p, Build::Avx2, t),
            L2Metric::Diaphony => measures::diaphony_with(p, Build::Avx512, t),
        };
        // A stopped sum is meaningless: its error, not the value's.
        t.result(())?;
        value
    }
}
