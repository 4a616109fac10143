//! Pieces of [`super::dem`]: the cell bounds, sorted prefixes and the knapsack.

/// `S` such that `N vol - count <= V - R - S` for every open box of a cell, where
/// `V = N prod_k A_k(hi_k)` is its largest volume (times `N`), `R` its points below in every
/// coordinate, and `tables` its per-coordinate tables `big` (see `Ctx::tables` in [`super::dem`]: `big[c]`,
/// non-decreasing, is the largest `A_k` counting `c` slab points, `big[m] = A_k(hi_k)`).
///
/// With `r_k = big_k[c_k] / big_k[m_k]` in `[rho_k, 1]`, `rho_k = big_k[0] / big_k[m_k]`, the
/// product is at most the linear `1 - a sum_k (1 - r_k)` for
/// `a = (1 - prod_k rho_k) / sum_k (1 - rho_k)`: the difference is multilinear, so it is
/// largest at a vertex of the box, where coordinates `S` sit at `rho`, and
/// `(1 - prod_S rho) / sum_S (1 - rho)` only falls as `S` grows (adding `x = 1 - rho_j` to `S`
/// keeps the ratio or lowers it exactly when `P (1 + X) <= 1` for `P = prod_S rho`,
/// `X = sum_S (1 - rho)`, and `P <= e^-X`). So
/// `N vol - count <= V - R - sum_k (a V (1 - r_k) + c_k)`, and each coordinate gives up at
/// least `min_c (a V (1 - r_k[c]) + c)`: `S` is the sum of these minima. `V > 0`.
///
/// `tables` pairs each table with `1 / big[m]`. Every minimum is non-negative, so the sum
/// stops once it reaches `enough` (the caller only asks whether `S >= enough`).
pub(super) fn open_slack<'a>(
    v: f64,
    enough: f64,
    tables: impl Iterator<Item = (&'a [f64], f64)> + Clone,
) -> f64 {
    let (mut prod, mut sum) = (1.0, 0.0);
    for (t, inv_top) in tables.clone() {
        let rho = t[0] * inv_top;
        prod *= rho;
        sum += 1.0 - rho;
    }
    let av = if sum > 0.0 { v * (1.0 - prod) / sum } else { v };
    let mut slack = 0.0;
    for (t, inv_top) in tables {
        let scale = av * inv_top;
        slack += t
            .iter()
            .enumerate()
            .map(|(c, &x)| av - x * scale + c as f64)
            .fold(f64::INFINITY, f64::min);
        if slack >= enough {
            break;
        }
    }
    slack
}

/// `M` such that `count - N vol <= R - W + M` for every closed box of a cell, where
/// `W = N prod_k B_k(lo_k) > 0` is its smallest volume (times `N`), `R` its points below in
/// every coordinate and `tables` its tables `small` (see `Ctx::tables` in [`super::dem`]: `small[c]`,
/// non-decreasing, is the smallest `B_k` counting `c` slab points, `small[0] = B_k(lo_k)`).
///
/// With `w_k = small_k[c_k] / small_k[0] >= 1`, `prod_k w_k >= 1 + sum_k (w_k - 1)` (expand the
/// product: every other term is non-negative), so
/// `count - N vol <= R - W + sum_k (c_k - W (w_k - 1))`: `M` is the sum over the coordinates
/// of the largest `c - W (w_k[c] - 1)` (at most the coordinate's slab count). `tables` pairs
/// each table with `1 / small[0]`.
pub(super) fn closed_slack<'a>(w: f64, tables: impl Iterator<Item = (&'a [f64], f64)>) -> f64 {
    tables
        .map(|(t, inv_bottom)| {
            let scale = w * inv_bottom;
            t.iter()
                .enumerate()
                .map(|(c, &x)| c as f64 - (x * scale - w))
                .fold(f64::NEG_INFINITY, f64::max)
        })
        .sum()
}

/// A list sorted by a key, made from a prefix of some source list that grows between
/// calls of [`extend`](Self::extend): only the items new to the prefix are sorted, then
/// merged in (`O(new log new + len)` instead of a full sort). [`reset`](Self::reset) when
/// the source list changes.
#[derive(Default)]
pub(super) struct SortedPrefix<T> {
    pub(super) list: Vec<T>,
    /// Source items already in `list`.
    merged: usize,
    /// Scratch: the items new to `list`.
    fresh: Vec<T>,
}

impl<T: Copy + Default> SortedPrefix<T> {
    pub(super) fn reset(&mut self) {
        self.list.clear();
        self.merged = 0;
    }

    /// Makes `list` the items `map(s)` of `prefix`, sorted by `key`. `prefix` extends the
    /// previous call's (a shorter one starts over).
    pub(super) fn extend<S>(
        &mut self,
        prefix: &[S],
        map: impl Fn(&S) -> T,
        key: impl Fn(&T) -> u32,
    ) {
        if self.merged > prefix.len() {
            self.reset();
        }
        self.fresh.clear();
        self.fresh.extend(prefix[self.merged..].iter().map(map));
        self.fresh.sort_unstable_by_key(&key);
        merge_sorted(&mut self.list, &self.fresh, key);
        self.merged = prefix.len();
    }
}

impl<T> core::ops::Deref for SortedPrefix<T> {
    type Target = [T];

    fn deref(&self) -> &[T] {
        &self.list
    }
}

/// Merges `more` into `list`, both sorted by `key`, from the back, in place.
pub(super) fn merge_sorted<T: Copy + Default>(
    list: &mut Vec<T>,
    more: &[T],
    key: impl Fn(&T) -> u32,
) {
    let mut i = list.len();
    list.resize(i + more.len(), T::default());
    let mut j = more.len();
    let mut out = list.len();
    while j > 0 {
        out -= 1;
        if i > 0 && key(&list[i - 1]) > key(&more[j - 1]) {
            i -= 1;
            list[out] = list[i];
        } else {
            j -= 1;
            list[out] = more[j];
        }
    }
}

/// `out[a + b] = max over a, b of x[a] * y[b]` (non-negative entries).
pub(super) fn convolve_max(x: &[f64], y: &[f64], out: &mut Vec<f64>) {
    convolve(x, y, out, 0.0, |p, o| if p > o { p } else { o });
}

/// `out[a + b] = min over a, b of x[a] * y[b]`.
pub(super) fn convolve_min(x: &[f64], y: &[f64], out: &mut Vec<f64>) {
    convolve(x, y, out, f64::INFINITY, |p, o| if p < o { p } else { o });
}

/// `out[a + b] = pick over a, b of x[a] * y[b]` for the associative `pick` with identity
/// `none`; `y` is not empty.
#[inline(always)]
fn convolve(x: &[f64], y: &[f64], out: &mut Vec<f64>, none: f64, pick: impl Fn(f64, f64) -> f64) {
    out.clear();
    let Some((&y0, rest)) = y.split_first() else {
        return;
    };
    // The first row sets the entries; the tables `y` are short (a coordinate's slab
    // points), the prefixes `x` long: the inner loop runs over `x`, contiguous, so it
    // vectorizes.
    out.extend(x.iter().map(|&xa| xa * y0));
    out.resize(x.len() + y.len() - 1, none);
    for (b, &yb) in rest.iter().enumerate() {
        for (o, &xa) in out[b + 1..].iter_mut().zip(x) {
            *o = pick(xa * yb, *o);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{closed_slack, open_slack};

    /// Random non-decreasing positive tables from a small LCG.
    fn tables(seed: u64, count: usize) -> Vec<Vec<f64>> {
        let mut s = seed;
        let mut next = move || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..count)
            .map(|_| {
                let len = 1 + (next() * 4.0) as usize;
                let mut t: Vec<f64> = (0..len).map(|_| 0.05 + next()).collect();
                t.sort_by(f64::total_cmp);
                t
            })
            .collect()
    }

    /// Every choice of one entry per table (its index is its count), as
    /// `(sum of counts, product of entry / reference)`.
    fn choices(t: &[Vec<f64>], reference: impl Fn(&[f64]) -> f64) -> Vec<(f64, f64)> {
        let mut all = vec![(0.0, 1.0)];
        for table in t {
            let r = reference(table);
            all = all
                .iter()
                .flat_map(|&(c, p)| {
                    table
                        .iter()
                        .enumerate()
                        .map(move |(k, &x)| (c + k as f64, p * x / r))
                })
                .collect();
        }
        all
    }

    #[test]
    fn slacks_bound_every_box_and_are_tight_for_one_table() {
        for seed in 0..300 {
            let t = tables(seed, 1 + seed as usize % 4);
            let v = 1.0 + seed as f64 * 0.37;
            let tops = || t.iter().map(|x| (&x[..], 1.0 / x[x.len() - 1]));
            let bottoms = || t.iter().map(|x| (&x[..], 1.0 / x[0]));
            // Open: N vol - count = v prod(r) - sum(c) <= v - slack.
            let slack = open_slack(v, f64::INFINITY, tops());
            let open = choices(&t, |x| x[x.len() - 1]);
            let open_max = open
                .iter()
                .map(|&(c, p)| v * p - c)
                .fold(f64::MIN, f64::max);
            assert!(
                open_max <= v - slack + 1e-12,
                "seed {seed}: {open_max} > {v} - {slack}"
            );
            // Closed: count - N vol = sum(c) - w prod(w_k) <= -w + most.
            let most = closed_slack(v, bottoms());
            let closed = choices(&t, |x| x[0]);
            let closed_max = closed
                .iter()
                .map(|&(c, p)| c - v * p)
                .fold(f64::MIN, f64::max);
            assert!(
                closed_max <= most - v + 1e-12,
                "seed {seed}: {closed_max} > {most} - {v}"
            );
            if t.len() == 1 {
                // One coordinate: both bounds are the exact maxima.
                assert!((open_max - (v - slack)).abs() < 1e-9);
                assert!((closed_max - (most - v)).abs() < 1e-9);
            }
        }
    }
}
