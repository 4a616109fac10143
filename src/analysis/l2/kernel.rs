//! The blocked pair sum `sum_{i < j} prod_k k1(x_ik, x_jk)` shared by every measure: the
//! point features in blocks of [`LANES`] points, the row, grouped and tiled loops, the
//! builds for wider vectors and their run-time dispatch, and the wide-range products used
//! where a product of `d` factors can leave the range of `f64`.

use super::Points;
use super::arith::Acc;
use crate::dispatch::{Kernel, run_float};
use crate::work::Progress;
use crate::work::Stop;
use core::sync::atomic::{AtomicUsize, Ordering};
use rayon::prelude::*;

// The builds of the pair sum ([`run_float`]'s). All give the same bits: Rust never
// contracts `a * b + c` into an FMA, and the explicit `f64::mul_add` of some factors is one
// correctly rounded operation in every build (an FMA instruction in the wide ones, the
// library's `fma` in the portable one), so the instructions differ only in width.
//
// Which build each measure asks for: AVX2 for the measures whose pair factor is one minimum
// (L2-star, generalized L2), for which the AVX-512 build of the generic-dimension loop
// measured slower from 6 dimensions on (8D: 5.1 against 4.3 ms for 4096 points); AVX-512
// for the others, measured 1.3-2x faster than AVX2 for 4096 points in 2 to 12 dimensions.
pub(super) use crate::dispatch::FloatBuild as Build;

/// Points per block of the pair sum: the inner loop evaluates the kernel for one point
/// `i` against `LANES` points `j` as fixed-size array operations, which the compiler turns
/// into SIMD instructions (one AVX-512, 2 AVX2 or 4 SSE2 registers per array).
pub(super) const LANES: usize = 8;

/// The points as `F` per-coordinate features (`feat(x_ik)`, precomputed once so that the
/// kernel of a pair is a few operations per coordinate), in two layouts.
pub(super) struct Blocked<const F: usize> {
    pub(super) n: usize,
    pub(super) d: usize,
    /// `rows[i * d + k]`: the features of coordinate `k` of point `i` (the `i` side).
    pub(super) rows: Vec<[f64; F]>,
    /// `blocks[b * d + k][f][l]`: feature `f` of coordinate `k` of point `b * LANES + l`
    /// (the `j` side, structure of arrays); zero past the last point.
    blocks: Vec<[[f64; LANES]; F]>,
    /// `Some(e)`: the products are computed with their exponents tracked
    /// ([`wide_products`]) and returned times `2^-e`; `None`: plain products.
    pub(super) scale_exp: Option<i64>,
}

impl<const F: usize> Blocked<F> {
    /// Cost `O(n d)` time and memory.
    pub(super) fn new<P: Fn(f64) -> [f64; F]>(p: Points<'_>, feat: P) -> Self {
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
        Blocked {
            n,
            d,
            rows,
            blocks,
            scale_exp: None,
        }
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
pub(super) const GROUP: usize = 4;

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

/// The value of `D` that selects [`wide_products`] (the dimension a run-time value).
pub(super) const WIDE: usize = usize::MAX;

/// Coordinates per chunk of [`wide_products`]: a partial product in `[1, 2)` times 8
/// factors of magnitude at most `1 + pi^2 / 3 < 2^2.11` (the largest factor of the eight
/// measures, the diaphony's) stays below `2^18`, and times 8 factors of magnitude at least
/// `2^-127` above `2^-1016`, so neither overflows nor leaves the normal range.
const CHUNK: usize = 8;

/// [`block_products`], or [`wide_products`] for `D = WIDE`.
#[inline(always)]
fn products<const F: usize, const D: usize, K>(
    s: &Blocked<F>,
    a: &[[f64; F]],
    b: &[[[f64; LANES]; F]],
    k1: &K,
) -> [f64; LANES]
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    if D == WIDE {
        wide_products(a, b, k1, s.scale_exp.unwrap_or(0))
    } else {
        block_products::<F, D, K>(a, b, k1)
    }
}

/// `prod_k k1(a_k, b_k) 2^-e` for one point `a` against the `LANES` points of block `b`,
/// in any dimension: the factors of [`CHUNK`] coordinates at a time are multiplied into a
/// partial product that is then renormalized to `[1, 2)` (its binary exponent moved to an
/// integer per lane, bit operations only), and the final product is scaled by
/// `2^(exponent - e)`, flushed to zero below `2^-1022`. No partial product overflows or
/// underflows as long as every factor is zero or of magnitude at least `2^-127` (true for
/// every measure of this module except the unanchored kernel, whose factor
/// `min(x, y) min(1 - x, 1 - y)` is smaller where a coordinate is below about `2^-74`).
/// The product carries as many roundings as [`block_products`]' (one per
/// multiplication, in a different order; the renormalizations are exact). With `e` the largest exponent of a
/// diagonal product, every result is at most about 2: a product kernel that is positive
/// definite in each coordinate, as all eight are, has `|K(x, y)|^2 <= K(x, x) K(y, y)`.
/// Cost: [`block_products`]' plus about 8 integer operations per chunk and lane.
#[inline(always)]
fn wide_products<const F: usize, K>(
    a: &[[f64; F]],
    b: &[[[f64; LANES]; F]],
    k1: &K,
    e: i64,
) -> [f64; LANES]
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    const EXP: u64 = 0x7ff << 52;
    let d = a.len();
    let (a, b) = (&a[..d], &b[..d]);
    let mut m = [1.0f64; LANES];
    let mut ex = [0i64; LANES];
    for (ca, cb) in a.chunks(CHUNK).zip(b.chunks(CHUNK)) {
        // Two chains of multiplications (even and odd coordinates), as in
        // `block_products`, joined into the running product once per chunk.
        let (mut even, mut odd) = ([1.0f64; LANES], [1.0f64; LANES]);
        let pairs = ca.chunks_exact(2).zip(cb.chunks_exact(2));
        for (a2, b2) in pairs {
            let (fe, fo) = (factors(a2[0], &b2[0], k1), factors(a2[1], &b2[1], k1));
            for ((e, o), (x, y)) in even.iter_mut().zip(&mut odd).zip(fe.into_iter().zip(fo)) {
                *e *= x;
                *o *= y;
            }
        }
        if ca.len() % 2 == 1 {
            let last = ca.len() - 1;
            for (e, x) in even.iter_mut().zip(factors(ca[last], &cb[last], k1)) {
                *e *= x;
            }
        }
        for ((x, e), o) in m.iter_mut().zip(even).zip(odd) {
            *x *= e * o;
        }
        for (x, k) in m.iter_mut().zip(&mut ex) {
            let bits = x.to_bits();
            let biased = ((bits & EXP) >> 52) as i64;
            let normal = biased != 0;
            let unit = f64::from_bits((bits & !EXP) | (1023 << 52));
            *x = if normal { unit } else { 0.0 };
            *k += if normal { biased - 1023 } else { 0 };
        }
    }
    let mut out = [0.0; LANES];
    for ((o, &x), &k) in out.iter_mut().zip(&m).zip(&ex) {
        // 2^(k - e) from its bits; below 2^-1022 the bits are those of zero.
        let t = (k - e).clamp(-1023, 1023);
        *o = x * f64::from_bits(((t + 1023) as u64) << 52);
    }
    out
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
            acc.add(products::<F, D, K>(s, a, blk, k1));
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
    let mut prod = products::<F, D, K>(s, a, &s.blocks[b * d..(b + 1) * d], k1);
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

/// [`row_pair_portable`] as a [`Kernel`] for [`run_float`].
struct RowPair<'a, const F: usize, const D: usize, K> {
    s: &'a Blocked<F>,
    i: usize,
    k1: &'a K,
}

impl<const F: usize, const D: usize, K> Kernel for RowPair<'_, F, D, K>
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    type Output = Acc;
    #[inline(always)]
    fn run(self) -> Acc {
        row_pair_portable::<F, D, K>(self.s, self.i, self.k1)
    }
}

/// [`row_pair_portable`] in the requested build, or the widest narrower one the CPU runs.
#[inline]
fn row_pair<const F: usize, const D: usize, K>(
    s: &Blocked<F>,
    i: usize,
    k1: &K,
    build: Build,
) -> Acc
where
    K: Fn([f64; F], [f64; F]) -> f64,
{
    run_float(build, RowPair::<F, D, K> { s, i, k1 })
}

/// Which loop computes the pair sum in dimension [`TILED_D`], chosen per measure by
/// measurement (`scripts/time_discrepancy.py`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Loop {
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

/// Progress of a pair sum, shared by its tasks: reports `(rows done, rows)` to a
/// [`Progress`] about a hundred times in all (an atomic increment per task, a call per
/// hundredth), the last report `(n, n)`.
///
/// It carries the computation's deadline too: each task reads it before its rows (one
/// clock reading per `O(n d)` task) and, once it has passed, the remaining tasks return at
/// once; [`Ticker::result`] then turns the stop into [`crate::Error::OutOfTime`].
pub(super) struct Ticker<'a> {
    progress: Progress<'a>,
    done: AtomicUsize,
    tasks: usize,
    rows: usize,
    pub(super) stop: &'a Stop,
}

/// The stop of a computation without a deadline.
static NEVER: Stop = Stop::never("an L2 discrepancy");

impl<'a> Ticker<'a> {
    /// A ticker for the pair sum of `rows` points, not started, without a deadline.
    pub(super) fn new(progress: Progress<'a>, rows: usize) -> Self {
        Ticker::with_stop(progress, rows, &NEVER)
    }

    /// A ticker for the pair sum of `rows` points, not started, stopped by `stop`.
    pub(super) fn with_stop(progress: Progress<'a>, rows: usize, stop: &'a Stop) -> Self {
        Ticker {
            progress,
            done: AtomicUsize::new(0),
            tasks: 0,
            rows,
            stop,
        }
    }

    /// `value` unless the deadline stopped the computation.
    ///
    /// # Errors
    /// [`crate::Error::OutOfTime`].
    pub(super) fn result<T>(&self, value: T) -> crate::Result<T> {
        self.stop.finish(value)
    }

    fn start(&mut self, tasks: usize) {
        self.tasks = tasks.max(1);
        self.done = AtomicUsize::new(0);
        (self.progress)(0, self.rows);
    }

    /// Runs `f`, a computation without intermediate reports, between `(0, n)` and `(n, n)`.
    pub(super) fn whole<T>(&mut self, f: impl FnOnce() -> T) -> T {
        self.start(1);
        let out = f();
        self.tick();
        out
    }

    #[inline]
    fn tick(&self) {
        let done = self.done.fetch_add(1, Ordering::Relaxed) + 1;
        let step = self.tasks.div_ceil(100);
        if done.is_multiple_of(step) || done == self.tasks {
            let rows = (done as u128 * self.rows as u128 / self.tasks as u128) as usize;
            (self.progress)(rows, self.rows);
        }
    }
}

/// `sum_{i < j} K(x_i, x_j)`: rows `i` and `n - 1 - i` go to the same task so that every
/// task does about `n` pair evaluations (with [`Loop::Tiles`] in [`TILED_D`] dimensions,
/// row blocks `b` and `ceil(n / LANES) - 1 - b`). Row sums are merged in a fixed order, so
/// the result does not depend on the number of threads. Dimensions 1 and 2 run loops
/// compiled for that dimension (in 2D the loop overhead would cost as much as the kernel),
/// the others one loop over the coordinates (measured faster in 8D than an unrolled loop
/// of one row) or, in 8D with [`Loop::Tiles`], register tiles compiled for 8D. With
/// [`Blocked::scale_exp`] set, whatever the dimension, the products are
/// [`wide_products`] (scaled by `2^-e`). Each finished task ticks `ticker`.
pub(super) fn off_diagonal<const F: usize, K>(
    s: &Blocked<F>,
    k1: &K,
    build: Build,
    lp: Loop,
    ticker: &mut Ticker<'_>,
) -> Acc
where
    K: Fn([f64; F], [f64; F]) -> f64 + Sync,
{
    fn rows<const F: usize, const D: usize, K>(
        s: &Blocked<F>,
        k1: &K,
        build: Build,
        ticker: &mut Ticker<'_>,
    ) -> Vec<Acc>
    where
        K: Fn([f64; F], [f64; F]) -> f64 + Sync,
    {
        let units = if D == TILED_D {
            s.n.div_ceil(LANES)
        } else {
            s.n
        };
        ticker.start(units.div_ceil(2));
        let ticker = &*ticker;
        (0..units.div_ceil(2))
            .into_par_iter()
            .map(|i| {
                if ticker.stop.check() {
                    return Acc::default();
                }
                let acc = row_pair::<F, D, K>(s, i, k1, build);
                ticker.tick();
                acc
            })
            .collect()
    }
    let rows = match (s.d, lp) {
        _ if s.scale_exp.is_some() => rows::<F, WIDE, K>(s, k1, build, ticker),
        (1, _) => rows::<F, 1, K>(s, k1, build, ticker),
        (2, _) => rows::<F, 2, K>(s, k1, build, ticker),
        (TILED_D, Loop::Tiles) => rows::<F, TILED_D, K>(s, k1, build, ticker),
        _ => rows::<F, 0, K>(s, k1, build, ticker),
    };
    let mut total = Acc::default();
    for r in rows {
        total.merge(r);
    }
    total
}

/// `min(a, b)` as one `minpd` (no NaN handling: the coordinates are validated).
#[inline(always)]
pub(super) fn min(a: f64, b: f64) -> f64 {
    if b < a { b } else { a }
}
