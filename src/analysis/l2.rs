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
//! `K`, split over rows with rayon). The exception is [`l2_star`] in one and two dimensions,
//! which has an exact `O(n log n)` algorithm ([`l2_star_fast`]).
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
//! ## Accuracy
//!
//! For good point sets the three terms above nearly cancel (for 1000 Sobol' points in 8
//! dimensions the wrap-around terms are about 10 and the result about 1e-3), so a plain sum
//! loses digits. Here every row sum and the sum over rows are compensated (Neumaier), and
//! the three terms are combined in double-double arithmetic, with the constants `(13/12)^d`,
//! ... raised to the power `d` in double-double too. The result is accurate to a few units
//! in the last place of the exact value of the formula evaluated on the given `f64`
//! coordinates (up to the rounding of each pair product), which is usually more accurate
//! than SciPy's plain double sums. A squared value that rounds below zero is clamped to
//! zero before a square root is taken (never a NaN).

use super::Points;
use rayon::prelude::*;

// ---------------------------------------------------------------------------------------
// Error-free transformations, compensated sums and a minimal double-double.
// ---------------------------------------------------------------------------------------

/// `a + b = s + e` exactly (Knuth's TwoSum).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Splits `a` into two 26-bit halves (Veltkamp).
#[inline]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let t = SPLITTER * a;
    let hi = t - (t - a);
    (hi, a - hi)
}

/// `a * b = p + e` exactly (Dekker), without relying on a hardware FMA.
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// A Neumaier (improved Kahan–Babuška) running sum: `s + c` carries the sum of the inputs
/// with an error of about one rounding of the result plus `n eps^2 sum |x|`.
#[derive(Clone, Copy, Debug, Default)]
struct Acc {
    s: f64,
    c: f64,
}

impl Acc {
    #[inline]
    fn add(&mut self, x: f64) {
        let t = self.s + x;
        if self.s.abs() >= x.abs() {
            self.c += (self.s - t) + x;
        } else {
            self.c += (x - t) + self.s;
        }
        self.s = t;
    }

    /// Adds another accumulator (both of its parts).
    fn merge(&mut self, other: Acc) {
        self.add(other.s);
        self.add(other.c);
    }

    fn dd(self) -> Dd {
        Dd::from_sum(self.s, self.c)
    }
}

/// An unevaluated sum `hi + lo` with `|lo| <= ulp(hi) / 2`: about 106 bits.
#[derive(Clone, Copy, Debug)]
struct Dd {
    hi: f64,
    lo: f64,
}

impl Dd {
    fn from_sum(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_sum(a, b);
        Dd { hi, lo }
    }

    /// `p / q` for integers that `f64` holds exactly, to double-double precision.
    fn ratio(p: f64, q: f64) -> Dd {
        let hi = p / q;
        let (m, e) = two_prod(hi, q);
        // p - hi q is exact (remainder of a correctly rounded quotient).
        let r = (p - m) - e;
        Dd::from_sum(hi, r / q)
    }

    fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        Dd::from_sum(s, e + self.lo + o.lo)
    }

    fn mul(self, o: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, o.hi);
        Dd::from_sum(p, e + self.hi * o.lo + self.lo * o.hi)
    }

    fn scale(self, k: f64) -> Dd {
        let (p, e) = two_prod(self.hi, k);
        Dd::from_sum(p, e + self.lo * k)
    }

    fn div(self, q: f64) -> Dd {
        let hi = self.hi / q;
        let (p, e) = two_prod(hi, q);
        let r = ((self.hi - p) - e + self.lo) / q;
        Dd::from_sum(hi, r)
    }

    /// `self^d` by repeated squaring.
    fn powi(self, mut d: usize) -> Dd {
        let mut base = self;
        let mut acc = Dd { hi: 1.0, lo: 0.0 };
        while d > 0 {
            if d & 1 == 1 {
                acc = acc.mul(base);
            }
            base = base.mul(base);
            d >>= 1;
        }
        acc
    }

    fn value(self) -> f64 {
        self.hi + self.lo
    }
}

// ---------------------------------------------------------------------------------------
// The generic kernel discrepancy.
// ---------------------------------------------------------------------------------------

/// Sums of a product kernel over a point set: `s1 = sum_i prod_k g1(x_ik)` and
/// `s2 = sum_{i,j} prod_k k1(x_ik, x_jk)` (all ordered pairs, diagonal included).
struct KernelSums {
    s1: Dd,
    s2: Dd,
}

/// `prod_k k1(a_k, b_k)`.
#[inline]
fn pair_product<K: Fn(f64, f64) -> f64>(a: &[f64], b: &[f64], k1: &K) -> f64 {
    a.iter().zip(b).map(|(&x, &y)| k1(x, y)).product()
}

/// `sum_{j > i} prod_k k1(x_ik, x_jk)`, compensated.
fn row_sum<K: Fn(f64, f64) -> f64>(p: Points<'_>, i: usize, k1: &K) -> Acc {
    let d = p.dims();
    let xi = p.point(i);
    let mut acc = Acc::default();
    for xj in p.as_slice()[(i + 1) * d..].chunks_exact(d) {
        acc.add(pair_product(xi, xj, k1));
    }
    acc
}

/// `sum_{i < j} K(x_i, x_j)`: rows `i` and `n - 1 - i` go to the same task so that every
/// task does about `n` pair evaluations. Row sums are merged in a fixed order, so the
/// result does not depend on the number of threads.
fn off_diagonal<K: Fn(f64, f64) -> f64 + Sync>(p: Points<'_>, k1: &K) -> Acc {
    let n = p.len();
    let rows: Vec<Acc> = (0..n.div_ceil(2))
        .into_par_iter()
        .map(|i| {
            let mut acc = row_sum(p, i, k1);
            let mirror = n - 1 - i;
            if mirror != i {
                acc.merge(row_sum(p, mirror, k1));
            }
            acc
        })
        .collect();
    let mut total = Acc::default();
    for r in rows {
        total.merge(r);
    }
    total
}

/// The two sums of a symmetric product kernel. Cost `O(n d)` plus `n (n - 1) / 2` kernel
/// products of `d` factors.
fn kernel_sums<G, K>(p: Points<'_>, g1: G, k1: K) -> KernelSums
where
    G: Fn(f64) -> f64,
    K: Fn(f64, f64) -> f64 + Sync,
{
    let mut s1 = Acc::default();
    let mut diag = Acc::default();
    for x in p.iter() {
        s1.add(x.iter().map(|&t| g1(t)).product());
        diag.add(pair_product(x, x, &k1));
    }
    let off = off_diagonal(p, &k1).dd().scale(2.0);
    KernelSums {
        s1: s1.dd(),
        s2: diag.dd().add(off),
    }
}

/// `c - a s1 / n + b s2 / n^2` in double-double.
fn combine(c: Dd, a: f64, b: f64, sums: &KernelSums, n: usize) -> f64 {
    let n = n as f64;
    let t1 = sums.s1.div(n).scale(-a);
    let t2 = sums.s2.div(n).div(n).scale(b);
    c.add(t1).add(t2).value()
}

/// Square root of a squared discrepancy, clamping a rounded-negative value to zero.
fn root(sq: f64) -> f64 {
    sq.max(0.0).sqrt()
}

/// `2^e` for a small signed exponent (exact).
fn pow2(e: i32) -> f64 {
    2f64.powi(e)
}

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
/// Cost: `O(n^2 d)` in general, split over threads; in one and two dimensions with
/// `n >= 256` it switches to the exact `O(n log n)` [`l2_star_fast`] (the values agree to
/// about 1e-15 relative). [`l2_star_direct`] always uses the pair sum.
///
/// One point at `x` in one dimension: `D^2 = 1/3 - (1 - x^2) + (1 - x) = x^2 - x + 1/3`,
/// so at `x = 1/2`, `D^2 = 1/12`:
///
/// ```
/// use qmckit::analysis::{l2::l2_star, Points};
/// let d = l2_star(Points::new(&[0.5], 1)?);
/// assert!((d - (1.0f64 / 12.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn l2_star(p: Points<'_>) -> f64 {
    if p.dims() <= 2 && p.len() >= FAST_MIN_POINTS {
        l2_star_fast(p)
    } else {
        l2_star_direct(p)
    }
}

/// Point count from which [`l2_star`] uses the `O(n log n)` algorithm in 1 and 2 dimensions.
const FAST_MIN_POINTS: usize = 256;

/// [`l2_star`] by the `O(n^2 d)` pair sum, whatever the dimension.
pub fn l2_star_direct(p: Points<'_>) -> f64 {
    let d = p.dims();
    let sums = kernel_sums(p, |x| 1.0 - x * x, |x, y| 1.0 - x.max(y));
    let c = Dd::ratio(1.0, 3.0).powi(d);
    root(combine(c, pow2(1 - d as i32), 1.0, &sums, p.len()))
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
/// let cd = centered(Points::new(&[0.5], 1)?);
/// assert!((cd - 1.0 / 12.0).abs() < 1e-16);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn centered(p: Points<'_>) -> f64 {
    let sums = kernel_sums(
        p,
        |x| {
            let a = (x - 0.5).abs();
            1.0 + 0.5 * a - 0.5 * a * a
        },
        |x, y| 1.0 + 0.5 * (x - 0.5).abs() + 0.5 * (y - 0.5).abs() - 0.5 * (x - y).abs(),
    );
    let c = Dd::ratio(13.0, 12.0).powi(p.dims());
    combine(c, 2.0, 1.0, &sums, p.len())
}

/// Wrap-around L2 discrepancy, **squared**, as SciPy's `method="WD"`.
///
/// ```text
/// WD^2 = -(4/3)^d + (1/n^2) sum_{i,j} prod_k (3/2 - |x_ik - x_jk| (1 - |x_ik - x_jk|))
/// ```
///
/// (Hickernell 1998; eq. 10 of Zhou, Fang & Ning 2013.) Depends only on the differences of
/// coordinates modulo 1: invariant under toroidal shifts. Range `[0, (3/2)^d - (4/3)^d]`.
/// Cost `O(n^2 d)`.
///
/// One point in one dimension, anywhere: `-4/3 + 3/2 = 1/6`:
///
/// ```
/// use qmckit::analysis::{l2::wrap_around, Points};
/// let wd = wrap_around(Points::new(&[0.3], 1)?);
/// assert!((wd - 1.0 / 6.0).abs() < 1e-16);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn wrap_around(p: Points<'_>) -> f64 {
    let sums = kernel_sums(
        p,
        |_| 0.0,
        |x, y| {
            let t = (x - y).abs();
            1.5 - t * (1.0 - t)
        },
    );
    let c = Dd::ratio(4.0, 3.0).powi(p.dims());
    let minus_c = Dd {
        hi: -c.hi,
        lo: -c.lo,
    };
    combine(minus_c, 0.0, 1.0, &sums, p.len())
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
/// let md = mixture(Points::new(&[0.5], 1)?);
/// assert!((md - 0.125).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn mixture(p: Points<'_>) -> f64 {
    let sums = kernel_sums(
        p,
        |x| {
            let a = (x - 0.5).abs();
            5.0 / 3.0 - 0.25 * a - 0.25 * a * a
        },
        |x, y| {
            let t = (x - y).abs();
            15.0 / 8.0 - 0.25 * (x - 0.5).abs() - 0.25 * (y - 0.5).abs() - 0.75 * t + 0.5 * t * t
        },
    );
    let c = Dd::ratio(19.0, 12.0).powi(p.dims());
    combine(c, 2.0, 1.0, &sums, p.len())
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
/// let sl2 = symmetric(Points::new(&[0.5], 1)?);
/// assert!((sl2 - (1.0f64 / 3.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn symmetric(p: Points<'_>) -> f64 {
    let d = p.dims();
    let sums = kernel_sums(
        p,
        |x| 1.0 + 2.0 * x - 2.0 * x * x,
        |x, y| 1.0 - (x - y).abs(),
    );
    let c = Dd::ratio(4.0, 3.0).powi(d);
    root(combine(c, 2.0, pow2(d as i32), &sums, p.len()))
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
/// let ul2 = unanchored(Points::new(&[0.2], 1)?);
/// assert!((ul2 - (1.0f64 / 12.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn unanchored(p: Points<'_>) -> f64 {
    let d = p.dims();
    let sums = kernel_sums(p, |x| x * (1.0 - x), |x, y| x.min(y) * (1.0 - x.max(y)));
    let c = Dd::ratio(1.0, 12.0).powi(d);
    root(combine(c, pow2(1 - d as i32), 1.0, &sums, p.len()))
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
/// let gl2 = generalized(Points::new(&[0.0], 1)?);
/// assert!((gl2 - (1.0f64 / 3.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn generalized(p: Points<'_>) -> f64 {
    let sums = kernel_sums(p, |x| 0.5 * (3.0 - x * x), |x, y| 2.0 - x.max(y));
    let c = Dd::ratio(4.0, 3.0).powi(p.dims());
    root(combine(c, 2.0, 1.0, &sums, p.len()))
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
/// assert!((diaphony(Points::new(&[0.7, 0.1], 2)?) - 1.0).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn diaphony(p: Points<'_>) -> f64 {
    const TWO_PI2: f64 = 2.0 * core::f64::consts::PI * core::f64::consts::PI;
    let sums = kernel_sums(
        p,
        |_| 0.0,
        |x, y| {
            let t = (x - y).abs();
            1.0 + TWO_PI2 * (t * t - t + 1.0 / 6.0)
        },
    );
    let minus_one = Dd { hi: -1.0, lo: 0.0 };
    let sq = combine(minus_one, 0.0, 1.0, &sums, p.len());
    let norm = (1.0 + TWO_PI2 / 6.0).powi(p.dims() as i32) - 1.0;
    root(sq / norm)
}

// ---------------------------------------------------------------------------------------
// L2-star in one and two dimensions in O(n log n).
// ---------------------------------------------------------------------------------------

/// [`l2_star`] by an exact `O(n log n)` algorithm in one and two dimensions (falls back to
/// [`l2_star_direct`] for `d >= 3`).
///
/// With `u = 1 - x`, `v = 1 - y`, the pair term is `1 - max(x_i, x_j) = min(u_i, u_j)`, so
///
/// ```text
/// sum_{i,j} min(u_i, u_j) min(v_i, v_j)
///   = sum_i u_i v_i + 2 sum_{i, j: u_j <= u_i, j before i} u_j min(v_i, v_j)
/// ```
///
/// (in one dimension `v = 1`). After sorting by `u`, a merge sort on `v` (divide and
/// conquer, the halves in parallel) adds for every `i` of the right half, with the `j` of
/// the left half, `sum_{v_j <= v_i} u_j v_j + v_i sum_{v_j > v_i} u_j` from running
/// compensated sums: `O(n log n)` work, `O(n)` memory. The values agree with the pair sum
/// up to the rounding of the pair products (about 1e-15 relative for random sets).
///
/// Heinrich's algorithm (1996) extends this to `O(n log^d n)` in any dimension; it is not
/// implemented here.
pub fn l2_star_fast(p: Points<'_>) -> f64 {
    if p.dims() > 2 {
        return l2_star_direct(p);
    }
    let mut uv: Vec<(f64, f64)> = p
        .iter()
        .map(|x| (1.0 - x[0], x.get(1).map_or(1.0, |&y| 1.0 - y)))
        .collect();
    let mut s1 = Acc::default();
    let mut diag = Acc::default();
    for x in p.iter() {
        s1.add(x.iter().map(|&t| 1.0 - t * t).product());
    }
    for &(u, v) in &uv {
        diag.add(u * v);
    }
    uv.par_sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let mut scratch = vec![(0.0, 0.0); uv.len()];
    let cross = cross_sum(&mut uv, &mut scratch);
    let sums = KernelSums {
        s1: s1.dd(),
        s2: diag.dd().add(cross.dd().scale(2.0)),
    };
    let d = p.dims();
    let c = Dd::ratio(1.0, 3.0).powi(d);
    root(combine(c, pow2(1 - d as i32), 1.0, &sums, p.len()))
}

/// Below this length the cross sum is done pair by pair.
const CROSS_LEAF: usize = 32;
/// Above this length the two halves are done in parallel.
const CROSS_PARALLEL: usize = 1 << 14;

/// For `pts` sorted by `u`: `sum_{j < i} u_j min(v_i, v_j)`. Leaves `pts` sorted by `v`.
fn cross_sum(pts: &mut [(f64, f64)], scratch: &mut [(f64, f64)]) -> Acc {
    let n = pts.len();
    if n <= CROSS_LEAF {
        return leaf_cross_sum(pts);
    }
    let mid = n / 2;
    let (left, right) = pts.split_at_mut(mid);
    let (sl, sr) = scratch.split_at_mut(mid);
    let (mut acc, other) = if n >= CROSS_PARALLEL {
        rayon::join(|| cross_sum(left, sl), || cross_sum(right, sr))
    } else {
        (cross_sum(left, sl), cross_sum(right, sr))
    };
    acc.merge(other);
    acc.merge(between_halves(left, right));
    merge_by_v(left, right, scratch);
    pts.copy_from_slice(scratch);
    acc
}

/// The pair sum inside a short run sorted by `u`, then sorts the run by `v`.
fn leaf_cross_sum(pts: &mut [(f64, f64)]) -> Acc {
    let mut acc = Acc::default();
    for i in 1..pts.len() {
        let vi = pts[i].1;
        for &(uj, vj) in &pts[..i] {
            acc.add(uj * vi.min(vj));
        }
    }
    pts.sort_unstable_by(|a, b| a.1.total_cmp(&b.1));
    acc
}

/// `sum_{i in right, j in left} u_j min(v_i, v_j)` for halves sorted by `v` (every `u_j`
/// of the left half is at most every `u_i` of the right half).
fn between_halves(left: &[(f64, f64)], right: &[(f64, f64)]) -> Acc {
    let mut acc = Acc::default();
    // sum over v_j <= v_i of u_j v_j, ascending in v_i.
    let mut below = Acc::default();
    let mut j = 0;
    for &(_, vi) in right {
        while j < left.len() && left[j].1 <= vi {
            below.add(left[j].0 * left[j].1);
            j += 1;
        }
        acc.merge(below);
    }
    // v_i times the sum over v_j > v_i of u_j, descending in v_i.
    let mut above = Acc::default();
    let mut j = left.len();
    for &(_, vi) in right.iter().rev() {
        while j > 0 && left[j - 1].1 > vi {
            above.add(left[j - 1].0);
            j -= 1;
        }
        let (p, e) = two_prod(vi, above.s);
        acc.add(p);
        acc.add(e + vi * above.c);
    }
    acc
}

/// Merges two runs sorted by `v` into `out`.
fn merge_by_v(left: &[(f64, f64)], right: &[(f64, f64)], out: &mut [(f64, f64)]) {
    let (mut a, mut b) = (0, 0);
    for slot in out.iter_mut() {
        let take_left = b == right.len() || (a < left.len() && left[a].1 <= right[b].1);
        if take_left {
            *slot = left[a];
            a += 1;
        } else {
            *slot = right[b];
            b += 1;
        }
    }
}

// ---------------------------------------------------------------------------------------
// The metric list, for the command line.
// ---------------------------------------------------------------------------------------

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

    /// Evaluates the measure on `p`.
    pub fn eval(self, p: Points<'_>) -> f64 {
        match self {
            L2Metric::L2Star => l2_star(p),
            L2Metric::Centered => centered(p),
            L2Metric::WrapAround => wrap_around(p),
            L2Metric::Mixture => mixture(p),
            L2Metric::Symmetric => symmetric(p),
            L2Metric::Unanchored => unanchored(p),
            L2Metric::Generalized => generalized(p),
            L2Metric::Diaphony => diaphony(p),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dd_constants() {
        // (4/3)^2 = 16/9 to double-double: hi + lo carries more than 53 bits.
        let c = Dd::ratio(4.0, 3.0).powi(2);
        assert_eq!(c.hi, 16.0 / 9.0);
        let third = Dd::ratio(1.0, 3.0);
        // 3 * (1/3) = 1 to about 2^-106.
        let one = third.scale(3.0).add(Dd { hi: -1.0, lo: 0.0 });
        assert!(one.value().abs() < 1e-30);
    }

    #[test]
    fn two_prod_exact() {
        let (p, e) = two_prod(0.1, 0.7);
        assert_eq!(p, 0.1 * 0.7);
        assert!(e != 0.0 && e.abs() < 1e-17);
    }

    #[test]
    fn compensated_sum_beats_plain() {
        let mut acc = Acc::default();
        acc.add(1.0);
        for _ in 0..10 {
            acc.add(1e-17);
        }
        acc.add(-1.0);
        assert!((acc.dd().value() - 1e-16).abs() < 1e-30);
    }

    #[test]
    fn fast_equals_direct_small() {
        let data: Vec<f64> = (0..600)
            .map(|i| ((i as f64) * 0.618_033_988_749_895).fract())
            .collect();
        for d in [1, 2] {
            let p = Points::new(&data, d).unwrap();
            let (a, b) = (l2_star_fast(p), l2_star_direct(p));
            assert!((a - b).abs() <= 1e-13 * b, "d={d}: {a} vs {b}");
        }
    }

    #[test]
    fn names_round_trip() {
        for m in L2Metric::ALL {
            assert_eq!(
                L2Metric::ALL
                    .iter()
                    .filter(|x| x.name() == m.name())
                    .count(),
                1
            );
        }
    }
}
