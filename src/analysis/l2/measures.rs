//! The eight measures: each maps a coordinate to its features and states its pair factor,
//! its one-point factor and its constant term, and runs the fast `f64` path up to the
//! dimension where that path provably stays in range, the wide path above it.

use super::Points;
use super::arith::{Dd, Wide};
use super::kernel::{Build, Loop, Ticker, min};
use super::sums::{checked, combine, combine_wide, kernel_sums, pow2, root, wide_kernel_sums};
use super::tree::{TREE_MAX_D, l2_star_fast_with, tree_pays_off};
use crate::Result;
use crate::work::Stop;
use crate::work::no_progress;

/// The largest dimension computed in plain `f64` products by the L2-star, centered,
/// wrap-around, mixture, symmetric and generalized L2 discrepancies (above it, with
/// tracked exponents). Up to it no product, sum or constant overflows (the largest
/// factors are `15/8`, mixture: `(15/8)^512 < 2^465`, and `2`, generalized L2: `2^512`;
/// sums of `n^2` of them stay below `2^996` for any feasible `n`), and the constants stay
/// above `2^-812` (L2-star, `3^-512`); a product that underflows is below `2^-1022` in
/// absolute value, which changes the result by less than its rounding unless the result
/// itself is below about `2^-960`.
pub(super) const FAST_D: usize = 512;

/// [`FAST_D`] for the unanchored discrepancy, whose constant is `12^-d` (`12^-224 > 2^-804`)
/// and whose pair factors are at most `1/4`.
pub(super) const UNANCHORED_FAST_D: usize = 224;

/// [`FAST_D`] for the diaphony, whose factors reach `1 + pi^2 / 3 < 2^2.11` and whose
/// normalization is `(1 + pi^2 / 3)^d - 1` (`< 2^811` at `d = 384`).
pub(super) const DIAPHONY_FAST_D: usize = 384;

pub(super) const L2_STAR: &str = "the L2-star discrepancy";
pub(super) const CENTERED: &str = "the centered L2 discrepancy (squared)";
pub(super) const WRAP_AROUND: &str = "the wrap-around L2 discrepancy (squared)";
pub(super) const MIXTURE: &str = "the mixture L2 discrepancy (squared)";
pub(super) const SYMMETRIC: &str = "the symmetric L2 discrepancy";
pub(super) const UNANCHORED: &str = "the unanchored L2 discrepancy";
pub(super) const GENERALIZED: &str = "the generalized L2 discrepancy";
pub(super) const DIAPHONY: &str = "the diaphony";

// ---------------------------------------------------------------------------------------
// The SciPy family.
// ---------------------------------------------------------------------------------------

/// L2-star discrepancy (Warnock's formula), **square root taken**, as SciPy's
/// `qmc.discrepancy(sample, method="L2-star")`.
///
/// The L2 norm over anchored boxes `[0, t)` of the local discrepancy
/// `#{x_i in [0, t)} / n - vol([0, t))`:
///
/// ```text
/// D^2 = 3^-d - (2^(1-d) / n) sum_i prod_k (1 - x_ik^2)
///            + (1 / n^2) sum_{i,j} prod_k (1 - max(x_ik, x_jk))
/// ```
///
/// (T. T. Warnock, "Computational investigations of low discrepancy point sets", 1972.)
/// Not invariant under the reflections `x_k -> 1 - x_k` (the boxes are anchored at the
/// origin). All points at `(1, ..., 1)` give `D^2 = 3^-d`.
///
/// Cost: `O(n^2 d)` by the pair sum, split over threads; from the point count where it
/// measured faster (256 points in one and two dimensions, more in three to five, never
/// above five) it switches to the exact `O(n log^(d-1) n)` divide and conquer
/// [`l2_star_fast`] (the values agree to about 1e-14 relative).
/// [`l2_star_direct`] always uses the pair sum.
///
/// One point at `x` in one dimension: `D^2 = 1/3 - (1 - x^2) + (1 - x) = x^2 - x + 1/3`,
/// so at `x = 1/2`, `D^2 = 1/12`:
///
/// ```
/// use qmckit::analysis::{l2::l2_star, Points};
/// let d = l2_star(Points::new(&[0.5], 1)?)?;
/// assert!((d - (1.0f64 / 12.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn l2_star(p: Points<'_>) -> Result<f64> {
    l2_star_with(p, &mut Ticker::new(&no_progress, p.len()))
}

/// [`l2_star`] reporting the pair sum's progress to `ticker`.
pub(super) fn l2_star_with(p: Points<'_>, ticker: &mut Ticker<'_>) -> Result<f64> {
    if tree_pays_off(p.dims(), p.len()) {
        let stop = ticker.stop;
        ticker.whole(|| checked(l2_star_fast_with(p, p.dims() <= 2, stop), L2_STAR))
    } else {
        l2_star_direct_with(p, Build::Avx2, ticker)
    }
}

/// [`l2_star`] by the `O(n^2 d)` pair sum, whatever the dimension.
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn l2_star_direct(p: Points<'_>) -> Result<f64> {
    l2_star_direct_with(p, Build::Avx2, &mut Ticker::new(&no_progress, p.len()))
}

/// [`l2_star_direct`] in the given build. The pair factor `1 - max(x, y)` is computed as
/// `min(1 - x, 1 - y)` on `u = 1 - x` precomputed (the same value: rounding is monotone).
pub(super) fn l2_star_direct_with(p: Points<'_>, build: Build, t: &mut Ticker<'_>) -> Result<f64> {
    let (n, d) = (p.len(), p.dims());
    let g1 = |x: f64| 1.0 - x * x;
    let feat = |x: f64| [1.0 - x];
    let pair = |a: [f64; 1], b: [f64; 1]| min(a[0], b[0]);
    if d > FAST_D {
        let sums = wide_kernel_sums(p, g1, feat, pair, build, t);
        let sq = combine_wide(
            Wide::ratio(1.0, 3.0).powi(d),
            Wide::pow2(1 - d as i64),
            Wide::ONE,
            &sums,
            n,
        );
        return sq.sqrt().to_f64(L2_STAR);
    }
    let sums = kernel_sums(p, g1, feat, pair, build, Loop::Rows, t);
    checked(
        root(combine(
            Dd::ratio(1.0, 3.0).powi(d),
            pow2(1 - d as i32),
            1.0,
            &sums,
            n,
        )),
        L2_STAR,
    )
}

/// [`l2_star`](l2_star) by exact divide and conquer, in `O(n log^(d-1) n)` time
/// (`O(n log n)` in one and two dimensions) instead of the `O(n^2 d)` pair sum.
///
/// Warnock's formula needs `S = sum_{i,j} prod_k min(u_ik, u_jk)` with `u = 1 - x`
/// (`1 - max(x, y) = min(1 - x, 1 - y)`). This is a dominance sum, computed as in
/// S. Heinrich, "Efficient algorithms for computing the L2-discrepancy", Math. Comp. 65
/// (1996), and K. Frank & S. Heinrich, "Computing discrepancies of Smolyak quadrature
/// rules", J. Complexity 12 (1996). After sorting by `u_1`, the pairs across a split into
/// halves have `min(u_i1, u_j1)` equal to the lower half's `u_j1`, which becomes a weight:
/// those pairs are a weighted problem between two colours (lower and upper half) on the
/// other `d - 1` coordinates. That one is split the same way on its first coordinate
/// (within each half: the same problem; across: two such problems in one dimension less)
/// down to one coordinate, where a sweep in ascending order with running sums of `|w| u`
/// costs `O(n)`. Every recursion is a merge sort: it gets its rows sorted by its first
/// coordinate and returns them sorted by its second, so the halves merged by the second
/// coordinate are the cross problems already sorted by their first (no sort or median
/// search inside the recursion). Small sub-problems are summed pair by pair; large ones
/// run in parallel.
///
/// In one and two dimensions the same idea is a single merge sort: with `u = 1 - x`,
/// `v = 1 - y`,
///
/// ```text
/// sum_{i,j} min(u_i, u_j) min(v_i, v_j)
///   = sum_i u_i v_i + 2 sum_{i, j: u_j <= u_i, j before i} u_j min(v_i, v_j)
/// ```
///
/// (in one dimension `v = 1`). After sorting by `u`, a merge sort on `v` adds for every
/// `i` of the right half, with the `j` of the left half,
/// `sum_{v_j <= v_i} u_j v_j + v_i sum_{v_j > v_i} u_j` from running sums.
///
/// Cost: `O(n log^(d-1) n)` work, about `n (log2 n)^(d-1) / (d-1)!` row operations, and
/// `O(n d^2)` memory; the factor grows quickly with `d`, so [`l2_star`] only takes this path
/// from the point count where it measured faster than the pair sum (4096 points for
/// `d = 3`, 24576 for `d = 4`, 196608 for `d = 5`, never from `d = 6` on). Above
/// [`TREE_MAX_D`](super::TREE_MAX_D) dimensions, where the recursion would only be deeper
/// and slower, this function returns [`l2_star_direct`]'s pair sum instead. Estimated by
/// [`cost::tree_rows`](super::cost::tree_rows) at [`TREE_RATE`](super::cost::TREE_RATE).
/// All sums are compensated and every term is non-negative, so the value agrees with
/// [`l2_star_direct`] up to the rounding of the products (about 1e-14 relative for
/// random sets of up to `2^16` points).
///
/// ```
/// use qmckit::analysis::{l2::{l2_star_direct, l2_star_fast}, Points};
/// // 300 points of a 3D lattice-like set.
/// let data: Vec<f64> = (0..900).map(|i| (i as f64 * 0.618_033_988_749_895).fract()).collect();
/// let p = Points::new(&data, 3)?;
/// let (fast, direct) = (l2_star_fast(p)?, l2_star_direct(p)?);
/// assert!((fast - direct).abs() <= 1e-13 * direct);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) as
/// [`l2_star`](l2_star).
pub fn l2_star_fast(p: Points<'_>) -> Result<f64> {
    if p.dims() > TREE_MAX_D {
        return l2_star_direct(p);
    }
    let stop = Stop::never(L2_STAR);
    checked(l2_star_fast_with(p, p.dims() <= 2, &stop), L2_STAR)
}

/// Centered L2 discrepancy, **squared** (no square root), as SciPy's `method="CD"`.
///
/// ```text
/// CD^2 = (13/12)^d - (2/n) sum_i prod_k (1 + |x_ik - 1/2| / 2 - |x_ik - 1/2|^2 / 2)
///      + (1/n^2) sum_{i,j} prod_k (1 + |x_ik - 1/2| / 2 + |x_jk - 1/2| / 2 - |x_ik - x_jk| / 2)
/// ```
///
/// (F. J. Hickernell, "A generalized discrepancy and quadrature error bound", Math. Comp.
/// 67, 1998; eq. 9 of Zhou, Fang & Ning, "Mixture discrepancy for quasi-random point sets",
/// J. Complexity 29, 2013.) Invariant under the reflections `x_k -> 1 - x_k`. Cost
/// `O(n^2 d)`.
///
/// One point at the center in one dimension: `13/12 - 2 + 1 = 1/12`:
///
/// ```
/// use qmckit::analysis::{l2::centered, Points};
/// let cd = centered(Points::new(&[0.5], 1)?)?;
/// assert!((cd - 1.0 / 12.0).abs() < 1e-16);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn centered(p: Points<'_>) -> Result<f64> {
    centered_with(p, Build::Avx512, &mut Ticker::new(&no_progress, p.len()))
}

/// [`centered`] in the given build. With `h = x / 2` and `a = 1/2 + |x - 1/2| / 2`
/// precomputed, the pair factor is `a_i + a_j - |h_i - h_j|` (four operations).
pub(super) fn centered_with(p: Points<'_>, build: Build, t: &mut Ticker<'_>) -> Result<f64> {
    let (n, d) = (p.len(), p.dims());
    let g1 = |x: f64| {
        let a = (x - 0.5).abs();
        1.0 + 0.5 * a - 0.5 * a * a
    };
    let feat = |x: f64| [0.5 * x, 0.5 + 0.5 * (x - 0.5).abs()];
    let pair = |a: [f64; 2], b: [f64; 2]| a[1] + b[1] - (a[0] - b[0]).abs();
    if d > FAST_D {
        let sums = wide_kernel_sums(p, g1, feat, pair, build, t);
        return combine_wide(
            Wide::ratio(13.0, 12.0).powi(d),
            Wide::TWO,
            Wide::ONE,
            &sums,
            n,
        )
        .to_f64(CENTERED);
    }
    let sums = kernel_sums(p, g1, feat, pair, build, Loop::Tiles, t);
    checked(
        combine(Dd::ratio(13.0, 12.0).powi(d), 2.0, 1.0, &sums, n),
        CENTERED,
    )
}

/// Wrap-around L2 discrepancy, **squared**, as SciPy's `method="WD"`.
///
/// ```text
/// WD^2 = -(4/3)^d + (1/n^2) sum_{i,j} prod_k (3/2 - |x_ik - x_jk| (1 - |x_ik - x_jk|))
/// ```
///
/// (Hickernell 1998; eq. 10 of Zhou, Fang & Ning 2013.) Depends only on the differences of
/// coordinates modulo 1: invariant under toroidal shifts. Range `[0, (3/2)^d - (4/3)^d]`.
/// Each pair factor is one fused multiply-add, `fma(-t, 1 - t, 3/2)` with
/// `t = |x_ik - x_jk|` (see the module documentation: the same bits in every build, one
/// rounding fewer than `3/2 - t (1 - t)`). Cost `O(n^2 d)`: for 4096 points in 8D about
/// 11 ms on one thread with AVX2 and FMA, about 260 ms in the portable build (one `fma`
/// call per factor).
///
/// One point in one dimension, anywhere: `-4/3 + 3/2 = 1/6`:
///
/// ```
/// use qmckit::analysis::{l2::wrap_around, Points};
/// let wd = wrap_around(Points::new(&[0.3], 1)?)?;
/// assert!((wd - 1.0 / 6.0).abs() < 1e-16);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn wrap_around(p: Points<'_>) -> Result<f64> {
    wrap_around_with(p, Build::Avx512, &mut Ticker::new(&no_progress, p.len()))
}

/// [`wrap_around`] in the given build.
pub(super) fn wrap_around_with(p: Points<'_>, build: Build, t: &mut Ticker<'_>) -> Result<f64> {
    let (n, d) = (p.len(), p.dims());
    let g1 = |_: f64| 0.0;
    let feat = |x: f64| [x];
    let pair = |a: [f64; 1], b: [f64; 1]| {
        let t = (a[0] - b[0]).abs();
        (-t).mul_add(1.0 - t, 1.5)
    };
    if d > FAST_D {
        let sums = wide_kernel_sums(p, g1, feat, pair, build, t);
        return combine_wide(
            Wide::ratio(4.0, 3.0).powi(d).neg(),
            Wide::ZERO,
            Wide::ONE,
            &sums,
            n,
        )
        .to_f64(WRAP_AROUND);
    }
    let sums = kernel_sums(p, g1, feat, pair, build, Loop::Tiles, t);
    checked(
        combine(Dd::ratio(4.0, 3.0).powi(d).neg(), 0.0, 1.0, &sums, n),
        WRAP_AROUND,
    )
}

/// Mixture L2 discrepancy, **squared**, as SciPy's `method="MD"`.
///
/// ```text
/// MD^2 = (19/12)^d - (2/n) sum_i prod_k (5/3 - |x_ik - 1/2| / 4 - |x_ik - 1/2|^2 / 4)
///      + (1/n^2) sum_{i,j} prod_k (15/8 - |x_ik - 1/2| / 4 - |x_jk - 1/2| / 4
///                                   - 3 |x_ik - x_jk| / 4 + |x_ik - x_jk|^2 / 2)
/// ```
///
/// (Zhou, Fang & Ning, "Mixture discrepancy for quasi-random point sets", J. Complexity
/// 29, 2013, eq. 18.) Cost `O(n^2 d)`.
///
/// One point at the center in one dimension: `19/12 - 2 (5/3) + 15/8 = 1/8`:
///
/// ```
/// use qmckit::analysis::{l2::mixture, Points};
/// let md = mixture(Points::new(&[0.5], 1)?)?;
/// assert!((md - 0.125).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn mixture(p: Points<'_>) -> Result<f64> {
    mixture_with(p, Build::Avx512, &mut Ticker::new(&no_progress, p.len()))
}

/// [`mixture`] in the given build. With `m = 15/16 - |x - 1/2| / 4` precomputed, the pair
/// factor `m_i + m_j - t (3/4 - t / 2)`, `t = |x_i - x_j|`, is evaluated as
/// `fma(-t, fma(-1/2, t, 3/4), m_i + m_j)` (two fused multiply-adds; module documentation).
pub(super) fn mixture_with(p: Points<'_>, build: Build, t: &mut Ticker<'_>) -> Result<f64> {
    let (n, d) = (p.len(), p.dims());
    let g1 = |x: f64| {
        let a = (x - 0.5).abs();
        5.0 / 3.0 - 0.25 * a - 0.25 * a * a
    };
    let feat = |x: f64| [x, 15.0 / 16.0 - 0.25 * (x - 0.5).abs()];
    let pair = |a: [f64; 2], b: [f64; 2]| {
        let t = (a[0] - b[0]).abs();
        (-t).mul_add((-0.5f64).mul_add(t, 0.75), a[1] + b[1])
    };
    if d > FAST_D {
        let sums = wide_kernel_sums(p, g1, feat, pair, build, t);
        return combine_wide(
            Wide::ratio(19.0, 12.0).powi(d),
            Wide::TWO,
            Wide::ONE,
            &sums,
            n,
        )
        .to_f64(MIXTURE);
    }
    let sums = kernel_sums(p, g1, feat, pair, build, Loop::Tiles, t);
    checked(
        combine(Dd::ratio(19.0, 12.0).powi(d), 2.0, 1.0, &sums, n),
        MIXTURE,
    )
}

// ---------------------------------------------------------------------------------------
// The UTK family (Hickernell 1998 kernels).
// ---------------------------------------------------------------------------------------

/// Symmetric L2 discrepancy, **square root taken** (UTK's `SymmetricL2Discrepancy`).
///
/// ```text
/// SL2^2 = (4/3)^d - (2/n) sum_i prod_k (1 + 2 x_ik - 2 x_ik^2)
///       + (2^d / n^2) sum_{i,j} prod_k (1 - |x_ik - x_jk|)
/// ```
///
/// The kernel is `prod_k 2 (1 - |x_k - y_k|)` (Hickernell 1998, "A generalized discrepancy
/// and quadrature error bound", Math. Comp. 67). Invariant under every reflection
/// `x_k -> 1 - x_k`. Cost `O(n^2 d)`.
///
/// One point at `x` in one dimension: `4/3 - 2 (1 + 2x - 2x^2) + 2 = 4x^2 - 4x + 4/3`; at
/// `x = 1/2` that is `1/3`:
///
/// ```
/// use qmckit::analysis::{l2::symmetric, Points};
/// let sl2 = symmetric(Points::new(&[0.5], 1)?)?;
/// assert!((sl2 - (1.0f64 / 3.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn symmetric(p: Points<'_>) -> Result<f64> {
    symmetric_with(p, Build::Avx512, &mut Ticker::new(&no_progress, p.len()))
}

/// [`symmetric`] in the given build.
pub(super) fn symmetric_with(p: Points<'_>, build: Build, t: &mut Ticker<'_>) -> Result<f64> {
    let (n, d) = (p.len(), p.dims());
    let g1 = |x: f64| 1.0 + 2.0 * x - 2.0 * x * x;
    let feat = |x: f64| [x];
    let pair = |a: [f64; 1], b: [f64; 1]| 1.0 - (a[0] - b[0]).abs();
    if d > FAST_D {
        let sums = wide_kernel_sums(p, g1, feat, pair, build, t);
        let sq = combine_wide(
            Wide::ratio(4.0, 3.0).powi(d),
            Wide::TWO,
            Wide::pow2(d as i64),
            &sums,
            n,
        );
        return sq.sqrt().to_f64(SYMMETRIC);
    }
    let sums = kernel_sums(p, g1, feat, pair, build, Loop::Rows, t);
    checked(
        root(combine(
            Dd::ratio(4.0, 3.0).powi(d),
            2.0,
            pow2(d as i32),
            &sums,
            n,
        )),
        SYMMETRIC,
    )
}

/// Unanchored L2 discrepancy, **square root taken** (UTK's `UnanchoredL2Discrepancy`).
///
/// The L2 norm of the local discrepancy over all boxes `[a, b)` in the cube:
///
/// ```text
/// UL2^2 = 12^-d - (2^(1-d) / n) sum_i prod_k x_ik (1 - x_ik)
///       + (1 / n^2) sum_{i,j} prod_k min(x_ik, x_jk) (1 - max(x_ik, x_jk))
/// ```
///
/// (Hickernell 1998; Lemieux, "Monte Carlo and Quasi-Monte Carlo Sampling", 2009.)
/// The kernel is `prod_k (min(x_k, y_k) - x_k y_k)`. Cost `O(n^2 d)`.
///
/// One point at `x` in one dimension: `1/12 - x(1 - x) + x(1 - x)`, so `1/12` anywhere:
///
/// ```
/// use qmckit::analysis::{l2::unanchored, Points};
/// let ul2 = unanchored(Points::new(&[0.2], 1)?)?;
/// assert!((ul2 - (1.0f64 / 12.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn unanchored(p: Points<'_>) -> Result<f64> {
    unanchored_with(p, Build::Avx512, &mut Ticker::new(&no_progress, p.len()))
}

/// [`unanchored`] in the given build (`1 - max(x, y) = min(1 - x, 1 - y)`, precomputed).
pub(super) fn unanchored_with(p: Points<'_>, build: Build, t: &mut Ticker<'_>) -> Result<f64> {
    let (n, d) = (p.len(), p.dims());
    let g1 = |x: f64| x * (1.0 - x);
    let feat = |x: f64| [x, 1.0 - x];
    let pair = |a: [f64; 2], b: [f64; 2]| min(a[0], b[0]) * min(a[1], b[1]);
    if d > UNANCHORED_FAST_D {
        let sums = wide_kernel_sums(p, g1, feat, pair, build, t);
        let sq = combine_wide(
            Wide::ratio(1.0, 12.0).powi(d),
            Wide::pow2(1 - d as i64),
            Wide::ONE,
            &sums,
            n,
        );
        return sq.sqrt().to_f64(UNANCHORED);
    }
    let sums = kernel_sums(p, g1, feat, pair, build, Loop::Tiles, t);
    checked(
        root(combine(
            Dd::ratio(1.0, 12.0).powi(d),
            pow2(1 - d as i32),
            1.0,
            &sums,
            n,
        )),
        UNANCHORED,
    )
}

/// Generalized L2-star discrepancy, **square root taken** (UTK's `GL2Discrepancy`).
///
/// ```text
/// GL2^2 = (4/3)^d - (2/n) sum_i prod_k (3 - x_ik^2) / 2
///       + (1/n^2) sum_{i,j} prod_k (2 - max(x_ik, x_jk))
/// ```
///
/// The kernel `prod_k (2 - max(x_k, y_k))` sums the L2-star discrepancies of all the
/// projections of the set onto coordinate subsets (Hickernell 1998; Lemieux 2009, p. 185).
/// Cost `O(n^2 d)`.
///
/// One point at `x` in one dimension: `4/3 - (3 - x^2) + (2 - x) = x^2 - x + 1/3`, the
/// same as the one-dimensional L2-star; at `x = 0` that is `1/3`:
///
/// ```
/// use qmckit::analysis::{l2::generalized, Points};
/// let gl2 = generalized(Points::new(&[0.0], 1)?)?;
/// assert!((gl2 - (1.0f64 / 3.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn generalized(p: Points<'_>) -> Result<f64> {
    generalized_with(p, Build::Avx2, &mut Ticker::new(&no_progress, p.len()))
}

/// [`generalized`] in the given build (`2 - max(x, y) = min(2 - x, 2 - y)`, precomputed).
pub(super) fn generalized_with(p: Points<'_>, build: Build, t: &mut Ticker<'_>) -> Result<f64> {
    let (n, d) = (p.len(), p.dims());
    let g1 = |x: f64| 0.5 * (3.0 - x * x);
    let feat = |x: f64| [2.0 - x];
    let pair = |a: [f64; 1], b: [f64; 1]| min(a[0], b[0]);
    if d > FAST_D {
        let sums = wide_kernel_sums(p, g1, feat, pair, build, t);
        let sq = combine_wide(
            Wide::ratio(4.0, 3.0).powi(d),
            Wide::TWO,
            Wide::ONE,
            &sums,
            n,
        );
        return sq.sqrt().to_f64(GENERALIZED);
    }
    let sums = kernel_sums(p, g1, feat, pair, build, Loop::Rows, t);
    checked(
        root(combine(Dd::ratio(4.0, 3.0).powi(d), 2.0, 1.0, &sums, n)),
        GENERALIZED,
    )
}

/// Diaphony (Zinterhof 1976), normalized to `[0, 1]`, **square root taken** (UTK's
/// `Diaphony`).
///
/// ```text
/// F^2 = [ (1/n^2) sum_{i,j} prod_k (1 + 2 pi^2 B2({x_ik - x_jk})) - 1 ] / ((1 + pi^2/3)^d - 1)
/// ```
///
/// with `B2(t) = t^2 - t + 1/6` the second Bernoulli polynomial and `{.}` the fractional
/// part (`B2({-t}) = B2({t})`, so `|x_ik - x_jk|` serves). Equivalently
/// `F^2 = sum_{h != 0} r(h)^-2 |(1/n) sum_i exp(2 pi i h.x_i)|^2 / sum_{h != 0} r(h)^-2`
/// with `r(h) = prod_k max(1, |h_k|)`: a weighted spectral (torus) measure, invariant under
/// toroidal shifts. One point gives `F = 1`. Cost `O(n^2 d)`.
///
/// ```
/// use qmckit::analysis::{l2::diaphony, Points};
/// assert!((diaphony(Points::new(&[0.7, 0.1], 2)?)? - 1.0).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::NotRepresentable`](crate::Error::NotRepresentable) when the value is nonzero
/// and outside the normal range of `f64` (see the module documentation, "Range").
pub fn diaphony(p: Points<'_>) -> Result<f64> {
    diaphony_with(p, Build::Avx512, &mut Ticker::new(&no_progress, p.len()))
}

/// [`diaphony`] in the given build. The pair factor `1 + 2 pi^2 B2(t)`, `t = |x_i - x_j|`,
/// is evaluated as `fma(2 pi^2, fma(-t, 1 - t, 1/6), 1)` (two fused multiply-adds; module
/// documentation).
pub(super) fn diaphony_with(p: Points<'_>, build: Build, t: &mut Ticker<'_>) -> Result<f64> {
    const TWO_PI2: f64 = 2.0 * core::f64::consts::PI * core::f64::consts::PI;
    let (n, d) = (p.len(), p.dims());
    let g1 = |_: f64| 0.0;
    let feat = |x: f64| [x];
    let pair = |a: [f64; 1], b: [f64; 1]| {
        let t = (a[0] - b[0]).abs();
        TWO_PI2.mul_add((-t).mul_add(1.0 - t, 1.0 / 6.0), 1.0)
    };
    if d > DIAPHONY_FAST_D {
        let sums = wide_kernel_sums(p, g1, feat, pair, build, t);
        let sq = combine_wide(Wide::ONE.neg(), Wide::ZERO, Wide::ONE, &sums, n);
        // The normalization `(1 + pi^2/3)^d - 1` from the diagonal factor as the kernel
        // computes it (`pair` at `t = 0`), so that the diagonal terms, which dominate in
        // high dimension, and the normalization carry the same rounding of the base.
        let base = pair(feat(0.0), feat(0.0));
        let norm = Wide::from_dd(Dd { hi: base, lo: 0.0 })
            .powi(d)
            .add(Wide::ONE.neg());
        return sq.div(norm).sqrt().to_f64(DIAPHONY);
    }
    let sums = kernel_sums(p, g1, feat, pair, build, Loop::Rows, t);
    let sq = combine(Dd::ONE.neg(), 0.0, 1.0, &sums, n);
    let norm = (1.0 + TWO_PI2 / 6.0).powi(d as i32) - 1.0;
    checked(root(sq / norm), DIAPHONY)
}
