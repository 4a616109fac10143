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
//! The pair sum is one generic loop for all eight measures: each coordinate is first
//! mapped to one or two features (e.g. `1 - x` for L2-star, `x / 2` and
//! `1/2 + |x - 1/2| / 2` for the centered discrepancy) so that a pair factor costs one to
//! six arithmetic operations, and the features are stored as structure of arrays in blocks
//! of 8 points. Point `i` is then evaluated against 8 points `j` at a time with fixed-size
//! array operations that compile to SIMD instructions; on x86-64 CPUs with AVX2 and FMA, or
//! AVX-512 (detected at run time), the same code runs compiled for them, with the same bits
//! (L2-star and the generalized L2, whose factor is one minimum, stay with AVX2: see
//! `Build`). In one
//! and two dimensions the loop is compiled for the dimension and the products of four
//! blocks are summed in plain arithmetic before the compensated addition (otherwise the
//! summation would cost as much as the kernel); in higher dimensions the loop over the
//! coordinates multiplies the factors of even and odd coordinates in two chains. In eight
//! dimensions the centered, wrap-around, mixture and unanchored discrepancies instead run
//! a loop compiled for 8D in register tiles: four points `i` against each block of 8
//! points `j`, so each loaded block serves four rows, and the four products per lane are
//! summed before the compensated addition. For 4096 points on one thread
//! (`scripts/time_discrepancy.py`, README for the table) this measured, against SciPy's
//! `discrepancy(workers=1)`, on a shared, loaded machine (four runs): in 2D L2-star
//! 35-69x (by the fast path), CD 19-36x, WD 11-23x, MD 15-31x; in 8D L2-star 8-17x, CD
//! 14-17x, MD 13-16x but WD only 7-9x (SciPy's cheapest loop) before the 8D tiles. With
//! them (2026-11-30, four runs, loaded machine): 8D CD 17.2-20.8x, WD 8.6-10.9x, MD
//! 14.0-20.9x (the previous build, timed in the same session: 11.4-13.5x, 6.2-8.7x,
//! 10.7-14.4x); the wrap-around loop itself went from 19-22 ms to 12.5-13.1 ms. With the
//! fused multiply-adds below (2026-11-30, late evening, three runs, loaded machine): 2D WD
//! 10.6-15.4x, MD 14.4-18.9x; 8D WD 10.1-10.3x, MD 18.2-18.7x (CD, L2-star unchanged);
//! timed against the build without them in alternation (`examples/time_l2.rs`, best of
//! nine runs): WD 1.19x faster in 8D and 1.16x in 2D, MD 1.24x and 1.26x, diaphony 1.17x
//! and 1.95x. On an idle AMD Zen 5 (2026-12-01, three runs, pinned) with the AVX-512 build:
//! 2D L2-star 21x, CD 20-22x, WD 20-22x, MD 25x; 8D L2-star 10.0-10.2x (AVX2 build), CD 29x,
//! WD 28x, MD 33x (before the AVX-512 build, same machine: CD 17x, WD 14x, MD 18x in 8D).
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
//! ## Fused multiply-adds
//!
//! The wrap-around, mixture and diaphony factors are written with [`f64::mul_add`] (e.g.
//! `fma(-t, 1 - t, 3/2)` for `3/2 - t (1 - t)`), which moves an addition of these add-bound
//! loops (for the wrap-around, three additions against two multiplications per coordinate)
//! to the multipliers, and rounds once fewer. `mul_add` is one correctly rounded operation
//! in every build: packed FMA instructions (`vfnmadd213pd` and the like) in the wide builds,
//! a call to the runtime library's correctly rounded `fma` in the portable one (on x86-64,
//! compiler-builtins' `fma`: the FMA instruction where the CPU has one, an exact software
//! fallback elsewhere), so the two builds still give the same bits (tested). The price is
//! paid by the portable build, used on x86-64 CPUs without AVX2 and FMA: one scalar call per
//! factor, about 4-8x slower for these three measures than without the FMA (8D wrap-around
//! of 4096 points on one thread: 259 ms against 63 ms, measured with the FMA instruction
//! behind the call; the software fallback is slower still; the AVX2 build: 11-13 ms). Where
//! the baseline target has an FMA (e.g. aarch64) it is an instruction. The shape of the
//! expression matters to the vectorizer: `t.mul_add(t - 1, 1.5)`, the same value, compiled
//! (release profile, 16 codegen units) to a partly scalar 8D loop 2.5x slower than the plain
//! one, while `(-t).mul_add(1 - t, 1.5)`, the shape of `1.5 - t * (1 - t)`, stays packed:
//! check the assembly when changing a factor.

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

/// Which build of the pair-sum loop runs: the same code compiled for wider vectors. A
/// build the CPU lacks falls back to the next narrower one it has (detected at run time,
/// x86-64 only; elsewhere every build is the portable one). All builds give the same bits:
/// Rust never contracts `a * b + c` into an FMA, and the explicit [`f64::mul_add`] of some
/// factors is one correctly rounded operation in every build (an FMA instruction in the
/// wide ones, the library's `fma` in the portable one), so the instructions differ only in
/// width.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Build {
    /// The portable build (baseline target features: SSE2 on x86-64). Only the tests ask
    /// for it explicitly, to compare it with the others.
    #[cfg_attr(not(test), allow(dead_code))]
    Portable,
    /// AVX2 and FMA (4 lanes a register): the measures whose pair factor is one minimum
    /// (L2-star, generalized L2), for which the AVX-512 build of the generic-dimension loop
    /// measured slower from 6 dimensions on (8D: 5.1 against 4.3 ms for 4096 points).
    Avx2,
    /// AVX-512 (F, VL) and FMA (8 lanes, one register a block of [`LANES`] points): the
    /// other measures, 1.3-2x faster than AVX2 on a Zen 5 for 4096 points in 2 to 12
    /// dimensions.
    Avx512,
}

/// Points per block of the pair sum: the inner loop evaluates the kernel for one point
/// `i` against `LANES` points `j` as fixed-size array operations, which the compiler turns
/// into SIMD instructions (one AVX-512, 2 AVX2 or 4 SSE2 registers per array).
const LANES: usize = 8;

/// The points as `F` per-coordinate features (`feat(x_ik)`, precomputed once so that the
/// kernel of a pair is a few operations per coordinate), in two layouts.
struct Blocked<const F: usize> {
    n: usize,
    d: usize,
    /// `rows[i * d + k]`: the features of coordinate `k` of point `i` (the `i` side).
    rows: Vec<[f64; F]>,
    /// `blocks[b * d + k][f][l]`: feature `f` of coordinate `k` of point `b * LANES + l`
    /// (the `j` side, structure of arrays); zero past the last point.
    blocks: Vec<[[f64; LANES]; F]>,
}

impl<const F: usize> Blocked<F> {
    /// Cost `O(n d)` time and memory.
    fn new<P: Fn(f64) -> [f64; F]>(p: Points<'_>, feat: P) -> Self {
        let (n, d) = (p.len(), p.dims());
        let rows: Vec<[f64; F]> = p.as_slice().iter().map(|&x| feat(x)).collect();
        let mut blocks = vec![[[0.0; LANES]; F]; n.div_ceil(LANES) * d];
        for (i, row) in rows.chunks_exact(d).enumerate() {
            let (b, l) = (i / LANES, i % LANES);
            for (blk, r) in blocks[b * d..(b + 1) * d].iter_mut().zip(row) {
                for (lane, &v) in blk.iter_mut().zip(r) {
                    lane[l] = v;
                }
            }
        }
        Blocked { n, d, rows, blocks }
    }
}

/// Per-lane compensated sums: lane `l` holds `s[l] + c[l]`, updated by TwoSum (branch-free,
/// so it vectorizes like the kernel). After `m` additions of non-negative terms the error
/// of a lane is about `m eps^2` times its sum, far below the roundings of the terms.
#[derive(Clone, Copy)]
struct Lanes {
    s: [f64; LANES],
    c: [f64; LANES],
}

impl Lanes {
    const ZERO: Lanes = Lanes {
        s: [0.0; LANES],
        c: [0.0; LANES],
    };

    #[inline(always)]
    fn add(&mut self, x: [f64; LANES]) {
        for ((s, c), x) in self.s.iter_mut().zip(&mut self.c).zip(x) {
            let t = *s + x;
            let bb = t - *s;
            *c += (*s - (t - bb)) + (x - bb);
            *s = t;
        }
    }

    /// The lanes summed in a fixed order.
    #[inline(always)]
    fn total(&self) -> Acc {
        let mut acc = Acc::default();
        for &s in &self.s {
            acc.add(s);
        }
        for &c in &self.c {
            acc.add(c);
        }
        acc
    }
}

/// In one and two dimensions, where the compensated summation would cost as much as the
/// kernel, the products of `GROUP` consecutive full blocks are added in plain `f64`
/// arithmetic, as the tree `(p0 + p1) + (p2 + p3)`, before one TwoSum per lane into
/// [`Lanes`]. The tree errs by at most `2u (|p0| + |p1| + |p2| + |p3|)` (`u = 2^-53`, to
/// first order): an error of the order of the rounding of a product of `d <= 2` kernel
/// factors, after which the TwoSum accumulation loses nothing more. In three and more
/// dimensions every block goes to the TwoSum directly (the kernel dominates there, and for
/// 1000 Sobol' points in 3D the grouped sums cost the mixture discrepancy its 1e-12
/// relative accuracy: a product of three factors carries only two roundings of its
/// multiplications, so the `2u` of the tree is of the same size), except in the 8D tiles
/// ([`add_row_block`]), where a product carries seven.
const GROUP: usize = 4;

/// `prod_k k1(a_k, b_k)` for one point `a` against the `LANES` points of a block `b`:
/// `d` kernel evaluations per lane, as array operations. `D > 0` fixes the dimension at
/// compile time (the loop unrolls); `D = 0` takes it from `a.len()`. The factors of even
/// and of odd `k` multiply into two partial products, multiplied together at the end, so
/// that the dependent multiplications form two chains instead of one (for `d <= 2` this
/// is the plain product).
#[inline(always)]
fn block_products<const F: usize, const D: usize, K>(
    a: &[[f64; F]],
    b: &[[[f64; LANES]; F]],
    k1: &K,
) -> [f64; LANES]
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    let d = if D == 0 { a.len() } else { D };
    let (a, b) = (&a[..d], &b[..d]);
    let mut even = factors(a[0], &b[0], k1);
    if d == 1 {
        return even;
    }
    let mut odd = factors(a[1], &b[1], k1);
    let mut k = 2;
    while k + 1 < d {
        let (fe, fo) = (factors(a[k], &b[k], k1), factors(a[k + 1], &b[k + 1], k1));
        for ((e, o), (x, y)) in even.iter_mut().zip(&mut odd).zip(fe.into_iter().zip(fo)) {
            *e *= x;
            *o *= y;
        }
        k += 2;
    }
    if k < d {
        for (e, x) in even.iter_mut().zip(factors(a[k], &b[k], k1)) {
            *e *= x;
        }
    }
    for (e, o) in even.iter_mut().zip(odd) {
        *e *= o;
    }
    even
}

/// `k1(a, b_l)` for the `LANES` points `b_l` of one coordinate of a block.
#[inline(always)]
fn factors<const F: usize, K>(a: [f64; F], b: &[[f64; LANES]; F], k1: &K) -> [f64; LANES]
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    core::array::from_fn(|l| k1(a, core::array::from_fn(|f| b[f][l])))
}

/// Adds `prod_k k1(x_ik, x_jk)` for `j > i` to `acc`: the block holding `i + 1` and the
/// last, partial block with the lanes outside `i < j < n` multiplied by zero, the full
/// blocks between them one by one or, for `D = 1, 2`, in groups of [`GROUP`].
#[inline(always)]
fn add_row<const F: usize, const D: usize, K>(s: &Blocked<F>, i: usize, k1: &K, acc: &mut Lanes)
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    let d = s.d;
    let a = &s.rows[i * d..(i + 1) * d];
    let first = (i + 1) / LANES;
    if first * LANES >= s.n {
        return;
    }
    let full_end = s.n / LANES;
    acc.add(masked_products::<F, D, K>(s, a, first, i, k1));
    let mid = (first + 1).min(full_end)..full_end;
    let mid = &s.blocks[mid.start * d..mid.end * d];
    if !(D == 1 || D == 2) {
        for blk in mid.chunks_exact(d) {
            acc.add(block_products::<F, D, K>(a, blk, k1));
        }
    } else {
        add_grouped::<F, D, K>(a, mid, k1, acc);
    }
    if full_end > first && full_end * LANES < s.n {
        acc.add(masked_products::<F, D, K>(s, a, full_end, i, k1));
    }
}

/// Adds the products of `a` against the blocks `mid` to `acc` in groups of [`GROUP`]
/// blocks summed in plain arithmetic, the remaining blocks one by one.
#[inline(always)]
fn add_grouped<const F: usize, const D: usize, K>(
    a: &[[f64; F]],
    mid: &[[[f64; LANES]; F]],
    k1: &K,
    acc: &mut Lanes,
) where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    let d = a.len();
    let groups = mid.chunks_exact(GROUP * d);
    let rest = groups.remainder();
    for g in groups {
        let (g01, g23) = g.split_at(2 * d);
        let (g0, g1) = g01.split_at(d);
        let (g2, g3) = g23.split_at(d);
        let p0 = block_products::<F, D, K>(a, g0, k1);
        let p1 = block_products::<F, D, K>(a, g1, k1);
        let p2 = block_products::<F, D, K>(a, g2, k1);
        let p3 = block_products::<F, D, K>(a, g3, k1);
        let mut sum = [0.0; LANES];
        for l in 0..LANES {
            sum[l] = (p0[l] + p1[l]) + (p2[l] + p3[l]);
        }
        acc.add(sum);
    }
    for blk in rest.chunks_exact(d) {
        acc.add(block_products::<F, D, K>(a, blk, k1));
    }
}

/// [`block_products`] of row `a` (point `i`) against block `b`, with the lanes outside
/// `i < j < n` multiplied by zero.
#[inline(always)]
fn masked_products<const F: usize, const D: usize, K>(
    s: &Blocked<F>,
    a: &[[f64; F]],
    b: usize,
    i: usize,
    k1: &K,
) -> [f64; LANES]
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    let d = s.d;
    let mut prod = block_products::<F, D, K>(a, &s.blocks[b * d..(b + 1) * d], k1);
    let j0 = b * LANES;
    for (l, p) in prod.iter_mut().enumerate() {
        *p *= f64::from(u8::from(j0 + l > i && j0 + l < s.n));
    }
    prod
}

/// The dimension whose pair sum runs in register tiles ([`add_row_block`]): the loop is
/// compiled for it, and every loaded block of `j` points serves [`TILE`] rows `i`.
const TILED_D: usize = 8;

/// Rows `i` per register tile in dimension [`TILED_D`].
const TILE: usize = 4;

/// `prod_k k1(a_rk, b_k)` for the [`TILE`] points `a_r` against the `LANES` points of block
/// `b`, the dimension `D` fixed at compile time: `TILE * LANES` independent products (so
/// one chain of multiplications per row and register is enough), each block coordinate
/// loaded once for the `TILE` rows. The factors are those of [`block_products`]; only the
/// order of the multiplications differs (one left-to-right chain instead of two), hence
/// the rounding of the products. Cost `TILE * LANES * D` kernel evaluations.
#[inline(always)]
fn tile_products<const F: usize, const D: usize, K>(
    a: [&[[f64; F]]; TILE],
    b: &[[[f64; LANES]; F]],
    k1: &K,
) -> [[f64; LANES]; TILE]
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    let b = &b[..D];
    let mut p = [[1.0; LANES]; TILE];
    for (k, bk) in b.iter().enumerate() {
        for (pr, ar) in p.iter_mut().zip(&a) {
            for (x, f) in pr.iter_mut().zip(factors(ar[k], bk, k1)) {
                *x *= f;
            }
        }
    }
    p
}

/// Adds `prod_k k1(x_ik, x_jk)` for all `j > i` of the `LANES` rows `i` of row block `rb`
/// (points `rb * LANES ..`) to `acc`: the diagonal block and the last, partial block row by
/// row with masks ([`masked_products`]), the full blocks between them in tiles of [`TILE`]
/// rows whose four products per lane are added as the tree `(p0 + p1) + (p2 + p3)` before
/// one TwoSum. The tree errs by at most `2u` times the sum of the (non-negative, or in
/// absolute value) products, `u = 2^-53`, to first order: each product already carries
/// `D - 1 = 7` roundings of its multiplications plus those of its factors, so the bound
/// on the rounding error per pair grows by at most `2/7`, and the TwoSum accumulation adds
/// nothing of that order (see [`GROUP`] for why lower dimensions keep one TwoSum per
/// product).
#[inline(always)]
fn add_row_block<const F: usize, const D: usize, K>(
    s: &Blocked<F>,
    rb: usize,
    k1: &K,
    acc: &mut Lanes,
) where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    let d = s.d;
    let full_end = s.n / LANES;
    let rows = rb * LANES..((rb + 1) * LANES).min(s.n);
    // Two masked blocks per row: the generic loop (`D = 0`) is enough there.
    for i in rows.clone() {
        let a = &s.rows[i * d..(i + 1) * d];
        acc.add(masked_products::<F, 0, K>(s, a, rb, i, k1));
    }
    if rb + 1 < full_end {
        // A full row block (`rb < full_end`): `LANES` rows, `LANES / TILE` tiles.
        let mid = &s.blocks[(rb + 1) * d..full_end * d];
        for i0 in rows.clone().step_by(TILE) {
            let a: [&[[f64; F]]; TILE] =
                core::array::from_fn(|r| &s.rows[(i0 + r) * d..(i0 + r + 1) * d]);
            for blk in mid.chunks_exact(d) {
                let [p0, p1, p2, p3] = tile_products::<F, D, K>(a, blk, k1);
                acc.add(core::array::from_fn(|l| (p0[l] + p1[l]) + (p2[l] + p3[l])));
            }
        }
    }
    if full_end > rb && full_end * LANES < s.n {
        for i in rows {
            let a = &s.rows[i * d..(i + 1) * d];
            acc.add(masked_products::<F, 0, K>(s, a, full_end, i, k1));
        }
    }
}

/// Rows `i` and `n - 1 - i` (about `n` pairs together), summed in a fixed order; for
/// `D = TILED_D`, the row blocks `i` and `ceil(n / LANES) - 1 - i` (about `LANES n` pairs).
#[inline(always)]
fn row_pair_portable<const F: usize, const D: usize, K>(s: &Blocked<F>, i: usize, k1: &K) -> Acc
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    let mut acc = Lanes::ZERO;
    if D == TILED_D {
        // `i` is a row block: blocks `i` and `nb - 1 - i` together.
        add_row_block::<F, D, K>(s, i, k1, &mut acc);
        let mirror = s.n.div_ceil(LANES) - 1 - i;
        if mirror != i {
            add_row_block::<F, D, K>(s, mirror, k1, &mut acc);
        }
        return acc.total();
    }
    add_row::<F, D, K>(s, i, k1, &mut acc);
    let mirror = s.n - 1 - i;
    if mirror != i {
        add_row::<F, D, K>(s, mirror, k1, &mut acc);
    }
    acc.total()
}

/// [`row_pair_portable`] compiled with AVX2 and FMA (4 lanes a register instead of 2).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn row_pair_avx2<const F: usize, const D: usize, K>(s: &Blocked<F>, i: usize, k1: &K) -> Acc
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    row_pair_portable::<F, D, K>(s, i, k1)
}

/// [`row_pair_portable`] compiled with AVX-512 (F, VL) and FMA (8 lanes a register).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
fn row_pair_avx512<const F: usize, const D: usize, K>(s: &Blocked<F>, i: usize, k1: &K) -> Acc
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    row_pair_portable::<F, D, K>(s, i, k1)
}

/// [`row_pair_portable`] in the requested build, or the widest narrower one the CPU runs.
fn row_pair<const F: usize, const D: usize, K>(
    s: &Blocked<F>,
    i: usize,
    k1: &K,
    build: Build,
) -> Acc
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        let avx2 = has!("avx2") && has!("fma");
        if build == Build::Avx512 && avx2 && has!("avx512f") && has!("avx512vl") {
            // SAFETY: `row_pair_avx512` is safe code whose only requirement is that the
            // CPU supports AVX-512F, AVX-512VL, AVX2 and FMA, all detected at run time on
            // this very CPU just above.
            #[allow(unsafe_code)]
            return unsafe { row_pair_avx512::<F, D, K>(s, i, k1) };
        }
        if build != Build::Portable && avx2 {
            // SAFETY: `row_pair_avx2` is safe code whose only requirement is that the CPU
            // supports AVX2 and FMA, both detected at run time on this very CPU just above.
            #[allow(unsafe_code)]
            return unsafe { row_pair_avx2::<F, D, K>(s, i, k1) };
        }
    }
    let _ = build;
    row_pair_portable::<F, D, K>(s, i, k1)
}

/// Which loop computes the pair sum in dimension [`TILED_D`], chosen per measure by
/// measurement (`scripts/time_discrepancy.py`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Loop {
    /// One row against all blocks ([`add_row`]), the dimension a run-time value.
    Rows,
    /// Tiles of [`TILE`] rows compiled for [`TILED_D`] ([`add_row_block`]). For 4096
    /// points in 8D, timed against [`Loop::Rows`] in alternation (`examples/time_l2.rs`):
    /// the centered discrepancy 1.2-1.6x faster, wrap-around 1.3-1.5x, mixture 1.2-1.5x,
    /// unanchored 1.4-2x, diaphony about the same; but L2-star 2-3x slower, symmetric
    /// 1.6-2.4x and generalized L2 about 3x slower: for these the compiler vectorizes the
    /// tile badly (partly 128-bit and scalar code, spilled accumulators), so they keep
    /// the row loop.
    Tiles,
}

/// `sum_{i < j} K(x_i, x_j)`: rows `i` and `n - 1 - i` go to the same task so that every
/// task does about `n` pair evaluations (with [`Loop::Tiles`] in [`TILED_D`] dimensions,
/// row blocks `b` and `ceil(n / LANES) - 1 - b`). Row sums are merged in a fixed order, so
/// the result does not depend on the number of threads. Dimensions 1 and 2 run loops
/// compiled for that dimension (in 2D the loop overhead would cost as much as the kernel),
/// the others one loop over the coordinates (measured faster in 8D than an unrolled loop
/// of one row) or, in 8D with [`Loop::Tiles`], register tiles compiled for 8D.
fn off_diagonal<const F: usize, K>(s: &Blocked<F>, k1: &K, build: Build, lp: Loop) -> Acc
where
    K: Fn([f64; F], [f64; F]) -> f64 + Sync,
{
    fn rows<const F: usize, const D: usize, K>(s: &Blocked<F>, k1: &K, build: Build) -> Vec<Acc>
    where
        K: Fn([f64; F], [f64; F]) -> f64 + Sync,
    {
        let units = if D == TILED_D {
            s.n.div_ceil(LANES)
        } else {
            s.n
        };
        (0..units.div_ceil(2))
            .into_par_iter()
            .map(|i| row_pair::<F, D, K>(s, i, k1, build))
            .collect()
    }
    let rows = match (s.d, lp) {
        (1, _) => rows::<F, 1, K>(s, k1, build),
        (2, _) => rows::<F, 2, K>(s, k1, build),
        (TILED_D, Loop::Tiles) => rows::<F, TILED_D, K>(s, k1, build),
        _ => rows::<F, 0, K>(s, k1, build),
    };
    let mut total = Acc::default();
    for r in rows {
        total.merge(r);
    }
    total
}

/// The two sums of a symmetric product kernel, the pair kernel written on precomputed
/// features: `k1(x, y) = pair(feat(x), feat(y))`, the pair sum by the loop `lp`. Cost
/// `O(n d)` plus `n (n - 1) / 2` kernel products of `d` factors, `LANES` at a time.
fn kernel_sums<const F: usize, G, P, K>(
    p: Points<'_>,
    g1: G,
    feat: P,
    pair: K,
    build: Build,
    lp: Loop,
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
    let off = off_diagonal(&s, &pair, build, lp).dd().scale(2.0);
    KernelSums {
        s1: s1.dd(),
        s2: diag.dd().add(off),
    }
}

/// `min(a, b)` as one `minpd` (no NaN handling: the coordinates are validated).
#[inline(always)]
fn min(a: f64, b: f64) -> f64 {
    if b < a { b } else { a }
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
/// let d = l2_star(Points::new(&[0.5], 1)?);
/// assert!((d - (1.0f64 / 12.0).sqrt()).abs() < 1e-15);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn l2_star(p: Points<'_>) -> f64 {
    if l2_star_tree::tree_pays_off(p.dims(), p.len()) {
        l2_star_fast(p)
    } else {
        l2_star_direct(p)
    }
}

/// [`l2_star`] by the `O(n^2 d)` pair sum, whatever the dimension.
pub fn l2_star_direct(p: Points<'_>) -> f64 {
    l2_star_direct_with(p, Build::Avx2)
}

/// [`l2_star_direct`] in the given build. The pair factor `1 - max(x, y)` is computed as
/// `min(1 - x, 1 - y)` on `u = 1 - x` precomputed (the same value: rounding is monotone).
fn l2_star_direct_with(p: Points<'_>, build: Build) -> f64 {
    let d = p.dims();
    let sums = kernel_sums(
        p,
        |x| 1.0 - x * x,
        |x| [1.0 - x],
        |a, b| min(a[0], b[0]),
        build,
        Loop::Rows,
    );
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
    centered_with(p, Build::Avx512)
}

/// [`centered`] in the given build. With `h = x / 2` and `a = 1/2 + |x - 1/2| / 2`
/// precomputed, the pair factor is `a_i + a_j - |h_i - h_j|` (four operations).
fn centered_with(p: Points<'_>, build: Build) -> f64 {
    let sums = kernel_sums(
        p,
        |x| {
            let a = (x - 0.5).abs();
            1.0 + 0.5 * a - 0.5 * a * a
        },
        |x| [0.5 * x, 0.5 + 0.5 * (x - 0.5).abs()],
        |a, b| a[1] + b[1] - (a[0] - b[0]).abs(),
        build,
        Loop::Tiles,
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
/// let wd = wrap_around(Points::new(&[0.3], 1)?);
/// assert!((wd - 1.0 / 6.0).abs() < 1e-16);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn wrap_around(p: Points<'_>) -> f64 {
    wrap_around_with(p, Build::Avx512)
}

/// [`wrap_around`] in the given build.
fn wrap_around_with(p: Points<'_>, build: Build) -> f64 {
    let sums = kernel_sums(
        p,
        |_| 0.0,
        |x| [x],
        |a, b| {
            let t = (a[0] - b[0]).abs();
            (-t).mul_add(1.0 - t, 1.5)
        },
        build,
        Loop::Tiles,
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
    mixture_with(p, Build::Avx512)
}

/// [`mixture`] in the given build. With `m = 15/16 - |x - 1/2| / 4` precomputed, the pair
/// factor `m_i + m_j - t (3/4 - t / 2)`, `t = |x_i - x_j|`, is evaluated as
/// `fma(-t, fma(-1/2, t, 3/4), m_i + m_j)` (two fused multiply-adds; module documentation).
fn mixture_with(p: Points<'_>, build: Build) -> f64 {
    let sums = kernel_sums(
        p,
        |x| {
            let a = (x - 0.5).abs();
            5.0 / 3.0 - 0.25 * a - 0.25 * a * a
        },
        |x| [x, 15.0 / 16.0 - 0.25 * (x - 0.5).abs()],
        |a, b| {
            let t = (a[0] - b[0]).abs();
            (-t).mul_add((-0.5f64).mul_add(t, 0.75), a[1] + b[1])
        },
        build,
        Loop::Tiles,
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
    symmetric_with(p, Build::Avx512)
}

/// [`symmetric`] in the given build.
fn symmetric_with(p: Points<'_>, build: Build) -> f64 {
    let d = p.dims();
    let sums = kernel_sums(
        p,
        |x| 1.0 + 2.0 * x - 2.0 * x * x,
        |x| [x],
        |a, b| 1.0 - (a[0] - b[0]).abs(),
        build,
        Loop::Rows,
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
    unanchored_with(p, Build::Avx512)
}

/// [`unanchored`] in the given build (`1 - max(x, y) = min(1 - x, 1 - y)`, precomputed).
fn unanchored_with(p: Points<'_>, build: Build) -> f64 {
    let d = p.dims();
    let sums = kernel_sums(
        p,
        |x| x * (1.0 - x),
        |x| [x, 1.0 - x],
        |a, b| min(a[0], b[0]) * min(a[1], b[1]),
        build,
        Loop::Tiles,
    );
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
    generalized_with(p, Build::Avx2)
}

/// [`generalized`] in the given build (`2 - max(x, y) = min(2 - x, 2 - y)`, precomputed).
fn generalized_with(p: Points<'_>, build: Build) -> f64 {
    let sums = kernel_sums(
        p,
        |x| 0.5 * (3.0 - x * x),
        |x| [2.0 - x],
        |a, b| min(a[0], b[0]),
        build,
        Loop::Rows,
    );
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
    diaphony_with(p, Build::Avx512)
}

/// [`diaphony`] in the given build. The pair factor `1 + 2 pi^2 B2(t)`, `t = |x_i - x_j|`,
/// is evaluated as `fma(2 pi^2, fma(-t, 1 - t, 1/6), 1)` (two fused multiply-adds; module
/// documentation).
fn diaphony_with(p: Points<'_>, build: Build) -> f64 {
    const TWO_PI2: f64 = 2.0 * core::f64::consts::PI * core::f64::consts::PI;
    let sums = kernel_sums(
        p,
        |_| 0.0,
        |x| [x],
        |a, b| {
            let t = (a[0] - b[0]).abs();
            TWO_PI2.mul_add((-t).mul_add(1.0 - t, 1.0 / 6.0), 1.0)
        },
        build,
        Loop::Rows,
    );
    let minus_one = Dd { hi: -1.0, lo: 0.0 };
    let sq = combine(minus_one, 0.0, 1.0, &sums, p.len());
    let norm = (1.0 + TWO_PI2 / 6.0).powi(p.dims() as i32) - 1.0;
    root(sq / norm)
}

#[path = "l2_star_tree.rs"]
mod l2_star_tree;
pub use l2_star_tree::l2_star_fast;

#[cfg(test)]
mod kernel_tests {
    use super::*;

    /// The reference pair sum `sum_{i<j} prod_k kernel(x_ik, x_jk)`: a plain double loop
    /// with Neumaier's compensation, sharing nothing with the blocked kernels.
    pub(super) fn neumaier_pair_sum(p: Points<'_>, kernel: impl Fn(f64, f64) -> f64) -> f64 {
        let (mut plain, mut comp) = (0.0f64, 0.0f64);
        for i in 0..p.len() {
            for j in i + 1..p.len() {
                let (a, b) = (p.point(i), p.point(j));
                let x: f64 = a.iter().zip(b).map(|(&x, &y)| kernel(x, y)).product();
                let t = plain + x;
                comp += if plain.abs() >= x.abs() {
                    (plain - t) + x
                } else {
                    (x - t) + plain
                };
                plain = t;
            }
        }
        plain + comp
    }

    /// The pair sum over `i < j` with rows long enough for the groups of [`GROUP`] blocks,
    /// their remainders and the masked first and last blocks (every `n mod LANES`, both
    /// specialized dimensions and the generic loop with odd and even `d`, and both loops
    /// in 8D: rows and tiles, with the row blocks' masked diagonal and last blocks),
    /// against a double loop over the pairs summed with Neumaier compensation.
    #[test]
    fn grouped_pair_sum_equals_plain_loop() {
        let kernel = |x: f64, y: f64| 1.5 - (x - y).abs() * (1.0 - (x - y).abs());
        let ns = (1..=3 * GROUP * LANES + 9)
            .step_by(5)
            .chain([LANES * (GROUP + 2) + 1]);
        for n in ns {
            for (d, lp) in [
                (1, Loop::Rows),
                (2, Loop::Rows),
                (3, Loop::Rows),
                (8, Loop::Rows),
                (8, Loop::Tiles),
            ] {
                let data: Vec<f64> = (0..n * d)
                    .map(|i| ((i as f64) * 0.754_877_666_246_692_7).fract())
                    .collect();
                let p = Points::new(&data, d).unwrap();
                let plain = neumaier_pair_sum(p, kernel);
                let s = Blocked::new(p, |x| [x]);
                let k1 = |a: [f64; 1], b: [f64; 1]| kernel(a[0], b[0]);
                let portable = off_diagonal(&s, &k1, Build::Portable, lp).dd().value();
                assert!(
                    (portable - plain).abs() <= 1e-14 * plain.max(1.0),
                    "n={n} d={d} {lp:?}: {portable} vs {plain}"
                );
                for build in [Build::Avx2, Build::Avx512] {
                    let wide = off_diagonal(&s, &k1, build, lp).dd().value();
                    assert_eq!(
                        portable.to_bits(),
                        wide.to_bits(),
                        "n={n} d={d} {lp:?} {build:?}"
                    );
                }
            }
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
    use super::kernel_tests::neumaier_pair_sum;
    use super::*;

    /// Every measure by the pair sum in the given build.
    fn direct_with(m: L2Metric, p: Points<'_>, build: Build) -> f64 {
        match m {
            L2Metric::L2Star => l2_star_direct_with(p, build),
            L2Metric::Centered => centered_with(p, build),
            L2Metric::WrapAround => wrap_around_with(p, build),
            L2Metric::Mixture => mixture_with(p, build),
            L2Metric::Symmetric => symmetric_with(p, build),
            L2Metric::Unanchored => unanchored_with(p, build),
            L2Metric::Generalized => generalized_with(p, build),
            L2Metric::Diaphony => diaphony_with(p, build),
        }
    }

    fn golden_ratio_points(len: usize) -> Vec<f64> {
        (0..len)
            .map(|i| ((i as f64) * 0.618_033_988_749_895).fract())
            .collect()
    }

    #[test]
    fn every_build_gives_the_portable_bits() {
        // On an x86-64 CPU this compares the AVX2+FMA and AVX-512 builds of the pair sum (each
        // where the CPU has it, else the next narrower one: the log says which ran) with the
        // portable one; elsewhere all three are the portable build. The `f64::mul_add` of the
        // wrap-around, mixture and diaphony factors is a packed FMA instruction in the wide
        // builds and an `fma` call in the portable one; (300, 8) and (301, 2) run several
        // full 8D tile row blocks and 2D groups of blocks.
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::is_x86_feature_detected as has;
            eprintln!(
                "avx2+fma: {}, avx512f+vl: {}",
                has!("avx2") && has!("fma"),
                has!("avx512f") && has!("avx512vl")
            );
        }
        for (n, d) in [
            (1, 1),
            (7, 3),
            (9, 2),
            (33, 2),
            (100, 8),
            (257, 5),
            (300, 8),
            (301, 2),
        ] {
            let data = golden_ratio_points(n * d);
            let p = Points::new(&data, d).unwrap();
            for m in L2Metric::ALL {
                let portable = direct_with(m, p, Build::Portable);
                for build in [Build::Avx2, Build::Avx512] {
                    let wide = direct_with(m, p, build);
                    assert_eq!(
                        portable.to_bits(),
                        wide.to_bits(),
                        "{} n={n} d={d} {build:?}",
                        m.name()
                    );
                }
            }
        }
    }

    #[test]
    fn blocked_pair_sum_equals_plain_loop() {
        // Every n mod LANES and the masks of the first and last blocks, against a plain
        // double loop over i < j of the original kernel.
        let kernel = |x: f64, y: f64| 1.5 - (x - y).abs() * (1.0 - (x - y).abs());
        for n in 1..=2 * LANES + 3 {
            for d in [1, 3] {
                let data = golden_ratio_points(n * d);
                let p = Points::new(&data, d).unwrap();
                let plain = neumaier_pair_sum(p, kernel);
                let s = Blocked::new(p, |x| [x]);
                for build in [Build::Portable, Build::Avx2, Build::Avx512] {
                    let got = off_diagonal(
                        &s,
                        &|a: [f64; 1], b: [f64; 1]| kernel(a[0], b[0]),
                        build,
                        Loop::Rows,
                    )
                    .dd()
                    .value();
                    assert!((got - plain).abs() <= 1e-14 * plain.max(1.0), "n={n} d={d}");
                }
            }
        }
    }

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
