//! L2-star discrepancy by divide and conquer instead of the pair sum (a child module of
//! [`super`], whose compensated-sum helpers it shares).

use super::{Acc, Dd, KernelSums, Points, combine, l2_star_direct, pow2, root, two_prod};
use rayon::prelude::*;

/// [`l2_star`](super::l2_star) by an exact `O(n log n)` algorithm in one and two dimensions (falls back to
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
