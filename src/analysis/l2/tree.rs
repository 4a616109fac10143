//! L2-star discrepancy by Warnock's formula with the pair sum replaced by an exact divide
//! and conquer (Heinrich 1996): the algorithm of [`l2_star_fast`](super::l2_star_fast),
//! whose entry point (with its fallback to the pair sum) is in `measures`; this module
//! depends on no measure.

use super::Points;
use super::arith::{Acc, Dd, two_prod};
use super::sums::{KernelSums, combine, pow2, root};
use crate::work::Stop;
use rayon::prelude::*;

/// Nodes of the recursions with at least this many rows read the deadline (each does
/// `Ω(rows)` work, so the readings cost well under a percent).
const CHECK_ROWS: usize = 256;

/// The largest dimension in which [`l2_star_fast`](super::l2_star_fast) runs the divide and
/// conquer: the recursion is `d` levels deep over the coordinates, and from 6 dimensions on
/// it is slower than the pair sum for every feasible point count anyway.
pub const TREE_MAX_D: usize = 16;

/// Point count from which [`l2_star`](super::l2_star) uses
/// [`l2_star_fast`](super::l2_star_fast) in `d` dimensions: about where the two ran equally
/// fast on one thread on uniform random points (`examples/time_l2_star.rs`, best of
/// repeated runs on an x86-64 machine with AVX2 for the pair sum). Measured, in seconds (tree / pair sum): `d = 3`: `2^12` points
/// 0.0089 / 0.0084, `2^13` 0.029 / 0.051, `2^18` 1.7 / 82; `d = 4`: `2^14` 0.35 / 0.24,
/// `2^15` 0.81 / 1.02, `2^16` 3.4 / 6.5; `d = 5`: `2^15` 2.8 / 0.83, `2^16` 11.8 / 6.5, and
/// the ratio shrinks like `log^4 n / n`, to 1 near `2^17.4`. From `d = 6` on the same
/// model puts the crossover near or beyond `2^20` points, so there the pair sum is always
/// used (`None`).
pub(super) fn crossover(d: usize) -> Option<usize> {
    match d {
        1 | 2 => Some(256),
        3 => Some(1 << 12),
        4 => Some(3 << 13),
        5 => Some(3 << 16),
        _ => None,
    }
}

/// Does [`l2_star_fast`](super::l2_star_fast) beat the pair sum for `n` points in `d`
/// dimensions?
pub(super) fn tree_pays_off(d: usize, n: usize) -> bool {
    crossover(d).is_some_and(|c| n >= c)
}

/// [`l2_star_fast`](super::l2_star_fast) by the merge sort of one and two dimensions
/// (`plane`, only for `d <= 2`) or by the general recursion.
pub(super) fn l2_star_fast_with(p: Points<'_>, plane: bool, stop: &Stop) -> f64 {
    let d = p.dims();
    let mut s1 = Acc::default();
    let mut diag = Acc::default();
    for x in p.iter() {
        s1.add(x.iter().map(|&t| 1.0 - t * t).product());
        diag.add(x.iter().map(|&t| 1.0 - t).product());
    }
    let cross = if plane {
        debug_assert!(d <= 2, "the plane path is for d <= 2");
        let mut uv: Vec<(f64, f64)> = p
            .iter()
            .map(|x| (1.0 - x[0], x.get(1).map_or(1.0, |&y| 1.0 - y)))
            .collect();
        uv.par_sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let mut scratch = vec![(0.0, 0.0); uv.len()];
        cross_sum(&mut uv, &mut scratch, stop)
    } else {
        let u: Vec<f64> = p.as_slice().iter().map(|&t| 1.0 - t).collect();
        tree_off_diagonal(&u, d, stop)
    };
    let sums = KernelSums {
        s1: s1.dd(),
        s2: diag.dd().add(cross.dd().scale(2.0)),
    };
    let c = Dd::ratio(1.0, 3.0).powi(d);
    root(combine(c, pow2(1 - d as i32), 1.0, &sums, p.len()))
}

/// Below this length the cross sum is done pair by pair.
const CROSS_LEAF: usize = 32;
/// Above this length the two halves are done in parallel.
const CROSS_PARALLEL: usize = 1 << 14;

/// For `pts` sorted by `u`: `sum_{j < i} u_j min(v_i, v_j)`. Leaves `pts` sorted by `v`.
fn cross_sum(pts: &mut [(f64, f64)], scratch: &mut [(f64, f64)], stop: &Stop) -> Acc {
    let n = pts.len();
    if n <= CROSS_LEAF {
        return leaf_cross_sum(pts);
    }
    if n >= CHECK_ROWS && stop.check() {
        return Acc::default();
    }
    let mid = n / 2;
    let (left, right) = pts.split_at_mut(mid);
    let (sl, sr) = scratch.split_at_mut(mid);
    let (mut acc, other) = if n >= CROSS_PARALLEL {
        rayon::join(|| cross_sum(left, sl, stop), || cross_sum(right, sr, stop))
    } else {
        (cross_sum(left, sl, stop), cross_sum(right, sr, stop))
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
// Any dimension: divide and conquer over the coordinates (Heinrich 1996).
// ---------------------------------------------------------------------------------------

/// Up to this many points the one-colour problem is summed pair by pair.
const MONO_LEAF: usize = 32;
/// Up to this many points a two-colour problem is summed pair by pair.
const BI_LEAF: usize = 24;
/// From this many points the sub-problems run in parallel.
pub(super) const TREE_PARALLEL: usize = 1 << 12;

/// `sum_{i < j} prod_k min(u_ik, u_jk)` over all `n (n - 1) / 2` pairs, for any `d >= 1`.
fn tree_off_diagonal(u: &[f64], d: usize, stop: &Stop) -> Acc {
    let n = u.len() / d;
    let mut order: Vec<usize> = (0..n).collect();
    order.par_sort_unstable_by(|&a, &b| u[a * d].total_cmp(&u[b * d]));
    let mut rows: Vec<f64> = Vec::with_capacity(u.len());
    for &i in &order {
        rows.extend_from_slice(&u[i * d..(i + 1) * d]);
    }
    drop(order);
    let mut scratch = vec![0.0; rows.len()];
    one_colour(&mut rows, &mut scratch, d, stop)
}

/// `prod_k min(a_k, b_k)`.
#[inline]
fn min_product(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(&x, &y)| x.min(y)).product()
}

/// Sorts rows of `stride` numbers by column `key` (a short run: through an index).
fn sort_rows(rows: &mut [f64], scratch: &mut [f64], stride: usize, key: usize) {
    let n = rows.len() / stride;
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_unstable_by(|&a, &b| rows[a * stride + key].total_cmp(&rows[b * stride + key]));
    for (slot, &i) in scratch.chunks_exact_mut(stride).zip(&order) {
        slot.copy_from_slice(&rows[i * stride..(i + 1) * stride]);
    }
    rows.copy_from_slice(scratch);
}

/// Merges two runs of rows sorted by column `key`, calling `visit(row, from_left)` in
/// merged order (left first on ties).
#[inline]
fn merge_rows(
    l: &[f64],
    r: &[f64],
    stride: usize,
    key: usize,
    mut visit: impl FnMut(&[f64], bool),
) {
    let (mut a, mut b) = (0, 0);
    while a < l.len() || b < r.len() {
        if b == r.len() || (a < l.len() && l[a + key] <= r[b + key]) {
            visit(&l[a..a + stride], true);
            a += stride;
        } else {
            visit(&r[b..b + stride], false);
            b += stride;
        }
    }
}

/// The one-colour problem: for rows `u_i` of `d` numbers sorted by column 0, returns
/// `sum_{i < j} prod_k min(u_ik, u_jk)` and leaves the rows sorted by column 1 (by
/// column 0 if `d = 1`).
///
/// The two halves `L` (smaller `u_0`) and `R` recurse; a pair `j in L`, `i in R` has
/// `min(u_i0, u_j0) = u_j0`, so the pairs across the split are the two-colour problem on
/// columns `1..d` with weight `u_j0` on `L` (colour B) and `1` on `R` (colour A), whose
/// rows come out of the merge of the halves sorted by its first coordinate.
fn one_colour(rows: &mut [f64], scratch: &mut [f64], d: usize, stop: &Stop) -> Acc {
    let n = rows.len() / d;
    let key = d.min(2) - 1;
    if n >= CHECK_ROWS && stop.check() {
        return Acc::default();
    }
    if n <= MONO_LEAF {
        let mut acc = Acc::default();
        for i in 1..n {
            let a = &rows[i * d..(i + 1) * d];
            for b in rows[..i * d].chunks_exact(d) {
                acc.add(min_product(a, b));
            }
        }
        sort_rows(rows, scratch, d, key);
        return acc;
    }
    let mid = n / 2;
    let mut acc = {
        let (l, r) = rows.split_at_mut(mid * d);
        let (sl, sr) = scratch.split_at_mut(mid * d);
        let (mut acc, other) = if n >= TREE_PARALLEL {
            rayon::join(|| one_colour(l, sl, d, stop), || one_colour(r, sr, d, stop))
        } else {
            (one_colour(l, sl, d, stop), one_colour(r, sr, d, stop))
        };
        acc.merge(other);
        acc
    };
    // Merge the halves by `key`: into `scratch` as they are, and into `cross` as
    // two-colour rows (columns 1..d, then the signed weight).
    let mut cross = Vec::with_capacity(n * d);
    let (l, r) = rows.split_at(mid * d);
    let mut out = scratch.chunks_exact_mut(d);
    merge_rows(l, r, d, key, |row, left| {
        if let Some(o) = out.next() {
            o.copy_from_slice(row);
        }
        cross.extend_from_slice(&row[1..]);
        cross.push(if left { -row[0] } else { 1.0 });
    });
    rows.copy_from_slice(scratch);
    let mut cross_scratch = vec![0.0; cross.len()];
    acc.merge(two_colour(&mut cross, &mut cross_scratch, d - 1, stop));
    acc
}

/// Is this signed weight on colour B? (The sign bit, so that `-0.0` is B.)
#[inline]
fn colour_b(w: f64) -> bool {
    w.is_sign_negative()
}

/// The two-colour problem: rows `[u_1 .. u_m, w]` of `m` coordinates and a signed weight
/// (sign bit set: colour B, else colour A), sorted by `u_1`; returns
/// `sum_{a in A, b in B} |w_a| |w_b| prod_k min(u_ak, u_bk)` and leaves the rows sorted
/// by `u_2` (if `m >= 2`).
///
/// The halves `L` (smaller `u_1`) and `R` recurse on the same `m` coordinates; across the
/// split the `L` point has the smaller `u_1`, so its weight takes the factor `u_1` and
/// the pairs `(L B, R A)` and `(L A, R B)` are two two-colour problems on `u_2 .. u_m`,
/// sorted by `u_2` by the merge of the halves. With one coordinate left the problem is a
/// sweep in ascending order; with two, the sweeps of both cross problems run inside the
/// merge ([`merge_sweep`]); with none, it is a product of two sums.
fn two_colour(rows: &mut [f64], scratch: &mut [f64], m: usize, stop: &Stop) -> Acc {
    let s = m + 1;
    let n = rows.len() / s;
    if n >= CHECK_ROWS && stop.check() {
        return Acc::default();
    }
    match m {
        0 => return product_of_sums(rows),
        1 => return sweep(rows),
        _ => {}
    }
    if n <= BI_LEAF {
        let acc = two_colour_pairs(rows, m);
        sort_rows(rows, scratch, s, 1);
        return acc;
    }
    let mid = n / 2;
    let mut acc = {
        let (l, r) = rows.split_at_mut(mid * s);
        let (sl, sr) = scratch.split_at_mut(mid * s);
        let (mut acc, other) = if n >= TREE_PARALLEL {
            rayon::join(|| two_colour(l, sl, m, stop), || two_colour(r, sr, m, stop))
        } else {
            (two_colour(l, sl, m, stop), two_colour(r, sr, m, stop))
        };
        acc.merge(other);
        acc
    };
    let (l, r) = rows.split_at(mid * s);
    if m == 2 {
        acc.merge(merge_sweep(l, r, scratch));
        rows.copy_from_slice(scratch);
        return acc;
    }
    // Group X = (L B) + (R A) first, then group Y = (L A) + (R B); `L` weights times u_1
    // (the sign, hence the colour, is kept: u_1 >= 0).
    let in_x = |row: &[f64], left: bool| colour_b(row[m]) == left;
    let nx = l.chunks_exact(s).filter(|row| in_x(row, true)).count()
        + r.chunks_exact(s).filter(|row| in_x(row, false)).count();
    let mut cross = vec![0.0; n * m];
    let (x, y) = cross.split_at_mut(nx * m);
    let (mut xs, mut ys) = (x.chunks_exact_mut(m), y.chunks_exact_mut(m));
    let mut out = scratch.chunks_exact_mut(s);
    merge_rows(l, r, s, 1, |row, left| {
        if let Some(o) = out.next() {
            o.copy_from_slice(row);
        }
        let dest = if in_x(row, left) {
            xs.next()
        } else {
            ys.next()
        };
        if let Some(c) = dest {
            c[..m - 1].copy_from_slice(&row[1..m]);
            c[m - 1] = if left { row[m] * row[0] } else { row[m] };
        }
    });
    rows.copy_from_slice(scratch);
    let mut cross_scratch = vec![0.0; n * m];
    let (x, y) = cross.split_at_mut(nx * m);
    let (sx, sy) = cross_scratch.split_at_mut(nx * m);
    let (a, b) = if n >= TREE_PARALLEL {
        rayon::join(
            || two_colour(x, sx, m - 1, stop),
            || two_colour(y, sy, m - 1, stop),
        )
    } else {
        (
            two_colour(x, sx, m - 1, stop),
            two_colour(y, sy, m - 1, stop),
        )
    };
    acc.merge(a);
    acc.merge(b);
    acc
}

/// The cross pairs of [`two_colour`] with two coordinates, rows `[u_1, u_2, w]`, for
/// halves `l` and `r` sorted by `u_2`: merges them by `u_2` into `out` and, in merged
/// order, pairs each row with the earlier rows of the other half and the other colour
/// (whose `u_2` is the smaller): an `r` row adds `|w|` times the running sum of
/// `|w| u_1 u_2` over such `l` rows, an `l` row adds `|w| u_1` times the running sum of
/// `|w| u_2` over such `r` rows.
fn merge_sweep(l: &[f64], r: &[f64], out: &mut [f64]) -> Acc {
    let mut acc = Acc::default();
    // Running sums by colour (A = 0, B = 1): over l rows of |w| u_1 u_2, over r rows of
    // |w| u_2.
    let mut seen_l = [Acc::default(); 2];
    let mut seen_r = [Acc::default(); 2];
    let (mut a, mut b) = (0, 0);
    for o in out.chunks_exact_mut(3) {
        let left = b == r.len() || (a < l.len() && l[a + 1] <= r[b + 1]);
        let row = if left {
            a += 3;
            &l[a - 3..a]
        } else {
            b += 3;
            &r[b - 3..b]
        };
        o.copy_from_slice(row);
        let c = colour_b(row[2]) as usize;
        let w = row[2].abs();
        if left {
            let wu = w * row[0];
            add_product(&mut acc, wu, seen_r[1 - c]);
            seen_l[c].add(wu * row[1]);
        } else {
            add_product(&mut acc, w, seen_l[1 - c]);
            seen_r[c].add(w * row[1]);
        }
    }
    acc
}

/// `acc += w (s.s + s.c)`, the leading product exactly.
#[inline]
fn add_product(acc: &mut Acc, w: f64, s: Acc) {
    let (p, e) = two_prod(w, s.s);
    acc.add(p);
    acc.add(e + w * s.c);
}

/// [`two_colour`] pair by pair.
fn two_colour_pairs(rows: &[f64], m: usize) -> Acc {
    let s = m + 1;
    let mut acc = Acc::default();
    for (i, a) in rows.chunks_exact(s).enumerate() {
        let ca = colour_b(a[m]);
        for b in rows[(i + 1) * s..].chunks_exact(s) {
            if colour_b(b[m]) != ca {
                acc.add(a[m].abs() * b[m].abs() * min_product(&a[..m], &b[..m]));
            }
        }
    }
    acc
}

/// [`two_colour`] with one coordinate, rows `[u, w]` sorted by `u`: each row pairs with
/// the earlier rows of the other colour, whose `u` is the smaller, so it adds `|w|` times
/// their running sum of `|w| u`.
fn sweep(rows: &[f64]) -> Acc {
    let mut acc = Acc::default();
    // Running sums of |w| u, for colour A (index 0) and B (index 1).
    let mut seen = [Acc::default(); 2];
    for r in rows.chunks_exact(2) {
        let c = colour_b(r[1]) as usize;
        let w = r[1].abs();
        add_product(&mut acc, w, seen[1 - c]);
        seen[c].add(w * r[0]);
    }
    acc
}

/// [`two_colour`] with no coordinate left: `(sum_A |w|) (sum_B |w|)`.
fn product_of_sums(rows: &[f64]) -> Acc {
    let mut sums = [Acc::default(); 2];
    for &w in rows {
        sums[colour_b(w) as usize].add(w.abs());
    }
    let [a, b] = sums;
    let mut acc = Acc::default();
    add_product(&mut acc, a.s, b);
    acc.add(a.c * b.s);
    acc
}

#[cfg(test)]
mod tests {
    fn never() -> Stop {
        Stop::new(&crate::work::Budget::UNLIMITED, "test")
    }

    use super::*;

    /// SplitMix64 uniforms in `[0, 1)`.
    fn uniform(len: usize, seed: u64) -> Vec<f64> {
        let mut s = seed;
        (0..len)
            .map(|_| {
                s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
                let mut z = s;
                z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
                z ^= z >> 31;
                (z >> 11) as f64 / (1u64 << 53) as f64
            })
            .collect()
    }

    /// `S - diag` by the definition, pair by pair, in a plain loop.
    fn off_diagonal_by_pairs(u: &[f64], d: usize) -> f64 {
        let n = u.len() / d;
        let mut s = 0.0;
        for i in 0..n {
            for j in 0..i {
                s += (0..d)
                    .map(|k| u[i * d + k].min(u[j * d + k]))
                    .product::<f64>();
            }
        }
        s
    }

    #[test]
    fn tree_off_diagonal_equals_pair_loop() {
        // Every leaf size and the first levels of both recursions, with ties.
        for d in 1..=5 {
            for n in [1, 2, 3, 7, 31, 32, 33, 47, 48, 49, 64, 65, 97, 200] {
                for grid in [0.0, 4.0] {
                    let mut u = uniform(n * d, (n * 10 + d) as u64);
                    if grid > 0.0 {
                        u.iter_mut()
                            .for_each(|t| *t = (*t * (grid + 1.0)).floor() / grid);
                    }
                    let want = off_diagonal_by_pairs(&u, d);
                    let got = tree_off_diagonal(&u, d, &never()).dd().value();
                    assert!(
                        (got - want).abs() <= 1e-13 * want.max(1e-300),
                        "d={d} n={n} grid={grid}: {got:e} vs {want:e}"
                    );
                }
            }
        }
    }

    #[test]
    fn crossover_table() {
        assert!(tree_pays_off(2, 256) && !tree_pays_off(2, 255));
        assert!(!tree_pays_off(3, 4) && tree_pays_off(3, 1 << 20));
        assert!(!tree_pays_off(40, 1 << 20));
    }
}
