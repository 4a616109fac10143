//! The three terms of a kernel discrepancy and their combination: the sums of a product
//! kernel over a point set in `f64` range (the fast path) or with tracked exponents (the
//! wide path, for dimensions where products of `d` factors leave the range of `f64`), and
//! the checked conversion of the result.

use super::Points;
use super::arith::{Acc, Dd, Wide, wide_product, wide_sum};
use super::kernel::{Blocked, Build, Loop, Ticker, off_diagonal};
use crate::{Error, Result};

/// Sums of a product kernel over a point set: `s1 = sum_i prod_k g1(x_ik)` and
/// `s2 = sum_{i,j} prod_k k1(x_ik, x_jk)` (all ordered pairs, diagonal included).
pub(super) struct KernelSums {
    pub(super) s1: Dd,
    pub(super) s2: Dd,
}

/// [`KernelSums`] with a binary exponent each ([`Wide`]).
pub(super) struct WideSums {
    s1: Wide,
    s2: Wide,
}

/// The two sums of a symmetric product kernel, the pair kernel written on precomputed
/// features: `k1(x, y) = pair(feat(x), feat(y))`, the pair sum by the loop `lp`. Cost
/// `O(n d)` plus `n (n - 1) / 2` kernel products of `d` factors, `LANES` at a time. The
/// products must stay in the normal range of `f64` (the callers' dimension limits).
pub(super) fn kernel_sums<const F: usize, G, P, K>(
    p: Points<'_>,
    g1: G,
    feat: P,
    pair: K,
    build: Build,
    lp: Loop,
    ticker: &mut Ticker<'_>,
) -> KernelSums
where
    G: Fn(f64) -> f64,
    P: Fn(f64) -> [f64; F],
    K: Fn([f64; F], [f64; F]) -> f64 + Sync,
{
    let s = Blocked::new(p, feat);
    let mut s1 = Acc::default();
    let mut diag = Acc::default();
    for (x, f) in p.iter().zip(s.rows.chunks_exact(s.d)) {
        s1.add(x.iter().map(|&t| g1(t)).product());
        diag.add(f.iter().map(|&a| pair(a, a)).product());
    }
    let off = off_diagonal(&s, &pair, build, lp, ticker).dd().scale(2.0);
    KernelSums {
        s1: s1.dd(),
        s2: diag.dd().add(off),
    }
}

/// [`kernel_sums`] for any dimension: every product of `d` factors is computed with its
/// binary exponent tracked (the `O(n d)` terms renormalized after every factor, the pair
/// products after every 8, see `kernel::wide_products`), and the pair products are scaled
/// by `2^-e`, `e` the largest exponent of the diagonal products, which bounds them all (the
/// kernels are positive definite); a pair product below `2^-1022` times the largest
/// diagonal one is dropped, far below the rounding of the sum, which holds the diagonal.
/// Cost: that of [`kernel_sums`] plus about one eighth.
pub(super) fn wide_kernel_sums<const F: usize, G, P, K>(
    p: Points<'_>,
    g1: G,
    feat: P,
    pair: K,
    build: Build,
    ticker: &mut Ticker<'_>,
) -> WideSums
where
    G: Fn(f64) -> f64,
    P: Fn(f64) -> [f64; F],
    K: Fn([f64; F], [f64; F]) -> f64 + Sync,
{
    let mut s = Blocked::new(p, feat);
    let s1: Vec<(f64, i64)> = p
        .iter()
        .map(|x| wide_product(x.iter().map(|&t| g1(t))))
        .collect();
    let diag: Vec<(f64, i64)> = s
        .rows
        .chunks_exact(s.d)
        .map(|f| wide_product(f.iter().map(|&a| pair(a, a))))
        .collect();
    let top = diag
        .iter()
        .filter(|t| t.0 != 0.0)
        .map(|t| t.1)
        .max()
        .unwrap_or(0);
    s.scale_exp = Some(top);
    let off = off_diagonal(&s, &pair, build, Loop::Rows, ticker)
        .dd()
        .scale(2.0);
    WideSums {
        s1: wide_sum(&s1),
        s2: wide_sum(&diag).add(Wide::new(off, top)),
    }
}

/// `c - a s1 / n + b s2 / n^2` in double-double.
pub(super) fn combine(c: Dd, a: f64, b: f64, sums: &KernelSums, n: usize) -> f64 {
    let n = n as f64;
    let t1 = sums.s1.div(n).scale(-a);
    let t2 = sums.s2.div(n).div(n).scale(b);
    c.add(t1).add(t2).value()
}

/// [`combine`] with exponents: `c - a s1 / n + b s2 / n^2`.
pub(super) fn combine_wide(c: Wide, a: Wide, b: Wide, sums: &WideSums, n: usize) -> Wide {
    let t1 = a.mul(sums.s1).div_count(n).neg();
    let t2 = b.mul(sums.s2).div_count(n).div_count(n);
    c.add(t1).add(t2)
}

/// Square root of a squared discrepancy, clamping a rounded-negative value to zero.
pub(super) fn root(sq: f64) -> f64 {
    sq.max(0.0).sqrt()
}

/// `2^e` for a small signed exponent (exact).
pub(super) fn pow2(e: i32) -> f64 {
    2f64.powi(e)
}

/// `x` if it is zero or a finite normal `f64`.
///
/// # Errors
/// [`Error::NotRepresentable`] naming `what` otherwise.
pub(super) fn checked(x: f64, what: &'static str) -> Result<f64> {
    if x.is_finite() && (x == 0.0 || x.abs() >= f64::MIN_POSITIVE) {
        Ok(x)
    } else {
        Err(Error::NotRepresentable { what })
    }
}
