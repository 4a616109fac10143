//! The cost model of counting points in elementary intervals ([`super::t_value_u32`] and
//! the other counting functions): the steps of one level of the search, the levels the
//! binary search visits for a given t-value, and the calibrated rate.

use crate::work::{Cost, Rate};

/// Point-coordinate steps per second and core of the interval counters in base 2, in the
/// units of [`level_steps`] (one step: one coordinate of one point placed in its cell, or one
/// cell cleared or compared): `1.2e9`. Measured on one thread, Owen-scrambled Sobol' points
/// with every shape of a level counted: 1.6e9 in 2D, 1.2e9 to 1.4e9 in 3D, 4D (`2^16`
/// points), 6D (`2^12`) and 8D (`2^14`).
pub const COUNT_RATE: Rate = Rate::per_second(1.2e9);

/// How many times slower a coordinate is placed in a base other than 2 (a division by
/// `b^(m - d)` instead of a shift), in the units of [`level_steps`].
pub const OTHER_BASE_FACTOR: f64 = 4.0;

/// The size of the cell counts (4 bytes a cell, one array per thread) from which a point's
/// increment misses the level-2 cache: 2 MiB, the cache of a core of the calibration
/// machine (`b^rho >= 2^19` cells in base 2).
pub const COUNTS_CACHE_BYTES: f64 = 2.0 * 1024.0 * 1024.0;

/// The extra steps of a point's increment into counts past [`COUNTS_CACHE_BYTES`]: 7
/// (measured 4 to 6 ns, 2^21 points in 2D at `rho` = 19, 20 and 21; below 2 MiB of counts
/// the levels run at the model's speed).
pub const INCREMENT_MISS: f64 = 7.0;

/// The share of an unbalanced level's work the search does before it stops (each task stops
/// at its first unbalanced shape): 0.15. Measured 0 to 0.25 (Owen-scrambled Sobol' points:
/// 3D, `2^16` points, t = 1: about 0; 4D, `2^16`, t = 3: 0.25; 6D, `2^12`, t = 5: 0.10);
/// a set far from a net (random points) stops at once, about 0.
pub const UNBALANCED_SHARE: f64 = 0.15;

/// `C(rho + s - 1, s - 1)`: the shapes `(d_1, .., d_s)` of size `rho` (as `f64`, exact up to
/// `2^53`). `O(s)`.
fn shapes(s: usize, rho: u32) -> f64 {
    (1..s).fold(1.0, |c, k| c * (f64::from(rho) + k as f64) / k as f64)
}

/// The steps of counting `n` points of `s` coordinates in base `base` into the cells of
/// every shape of size `rho`: `C(rho + s - 1, s - 1) (n ((s + 1) f + c) + 2 b^rho)`, one
/// pass over the `n s` digits per shape (and an increment per point), then the `b^rho`
/// cells cleared and compared; `f = 1` in base 2 and [`OTHER_BASE_FACTOR`] otherwise,
/// `c` = [`INCREMENT_MISS`] when the `4 b^rho` bytes of counts reach
/// [`COUNTS_CACHE_BYTES`], else 0. `O(s)`.
pub fn level_steps(n: u64, s: usize, rho: u32, base: u32) -> f64 {
    let f = if base == 2 { 1.0 } else { OTHER_BASE_FACTOR };
    let cells = f64::from(base.max(2)).powi(rho.min(1024) as i32);
    let miss = if 4.0 * cells >= COUNTS_CACHE_BYTES {
        INCREMENT_MISS
    } else {
        0.0
    };
    shapes(s, rho) * (n as f64 * ((s as f64 + 1.0) * f + miss) + 2.0 * cells)
}

/// The levels `(rho, balanced)` the binary search of the counting t-value visits for `b^m`
/// points whose t-value is `t`: balanced exactly when `rho <= m - t`. With `t = 0` every
/// level is balanced and the search climbs `ceil(m / 2)`, then halfway to `m` each time, up
/// to `m`; any other `t` visits as many levels or fewer, none of them larger.
fn search_path(m: u32, t: u32) -> impl Iterator<Item = (u32, bool)> {
    let (mut lo, mut hi) = (0u32, m);
    core::iter::from_fn(move || {
        (lo < hi).then(|| {
            let mid = lo + (hi - lo).div_ceil(2);
            let balanced = mid + t.min(m) <= m;
            if balanced {
                lo = mid;
            } else {
                hi = mid - 1;
            }
            (mid, balanced)
        })
    })
}

/// The steps of the t-value's binary search over `n = b^m` points of `s` coordinates, for
/// a set whose t-value is `expected_t`: [`level_steps`] for every balanced level the search
/// visits and [`UNBALANCED_SHARE`] of it for every unbalanced one. Without
/// an expected t-value (`None`), every level visited is assumed balanced and counted whole:
/// the most any set costs (exactly a `(0, m, s)`-net's), about twice what the search does
/// on 2^16 Owen-scrambled Sobol' points in 4D (t = 3) and 14 times in 6D (2^12, t = 5). The
/// answer never depends on `expected_t`, only this estimate does. `O(s log m)`.
pub fn count_steps(n: u64, s: usize, m: u32, base: u32, expected_t: Option<u32>) -> f64 {
    search_path(m, expected_t.unwrap_or(0))
        .map(|(rho, balanced)| {
            let share = if balanced { 1.0 } else { UNBALANCED_SHARE };
            share * level_steps(n, s, rho, base)
        })
        .sum()
}

/// The estimated time of the t-value by counting
/// ([`t_value_u32_expecting`](super::t_value_u32_expecting),
/// [`t_value_points`](super::t_value_points)) of `n = b^m` points in base `base`:
/// [`count_steps`] at [`COUNT_RATE`] on [`CORES`](crate::work::CORES) cores (the shapes of a
/// level are split over rayon's threads). `O(s log m)`.
///
/// ```
/// use qmckit::analysis::tvalue::t_value_cost;
/// // 2^16 points in 4D whose t-value is 3 (Sobol'): levels 8, 12 and 13 counted, a share of
/// // level 14; about a fifth of a second on two cores.
/// let t3 = t_value_cost(1 << 16, 4, 16, 2, Some(3)).seconds();
/// assert!((0.1..0.3).contains(&t3));
/// // Not knowing t: as if every level were balanced, levels 8, 12, 14, 15 and 16.
/// assert!(t_value_cost(1 << 16, 4, 16, 2, None).seconds() > 2.0 * t3);
/// ```
pub fn t_value_cost(n: u64, s: usize, m: u32, base: u32, expected_t: Option<u32>) -> Cost {
    Cost::parallel(count_steps(n, s, m, base, expected_t), COUNT_RATE)
}

/// The estimated time of listing the unbalanced intervals of size `rho = m - t`
/// ([`elementary_interval_failures_u32`](super::elementary_interval_failures_u32)): the
/// level counted whole ([`level_steps`], at [`COUNT_RATE`] on
/// [`CORES`](crate::work::CORES) cores), the most it takes (the listing stops once it holds
/// `limit` intervals). `O(s)`.
pub fn failures_cost(n: u64, s: usize, rho: u32, base: u32) -> Cost {
    Cost::parallel(level_steps(n, s, rho, base), COUNT_RATE)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_search_path_is_the_binary_search() {
        let path = |m, t| search_path(m, t).collect::<Vec<_>>();
        // A (0, 16, s)-net: every level balanced, climbing to 16.
        let up = [(8, true), (12, true), (14, true), (15, true), (16, true)];
        assert_eq!(path(16, 0), up);
        // t = 3 (Sobol' in 4D): 14 fails, 13 holds.
        assert_eq!(
            path(16, 3),
            [(8, true), (12, true), (14, false), (13, true)]
        );
        // t = m: every level fails.
        assert_eq!(path(4, 4), [(2, false), (1, false)]);
        assert_eq!(path(0, 0), []);
        // No t visits more levels, or a larger level at any step, than t = 0.
        for m in 0..=32 {
            let top = path(m, 0);
            for t in 0..=m {
                let p = path(m, t);
                assert!(p.len() <= top.len(), "m {m} t {t}");
                assert!(p.iter().zip(&top).all(|(a, b)| a.0 <= b.0), "m {m} t {t}");
                // The last level visited decides t: the answer m - t is the last balanced
                // level, or below the first unbalanced one.
                let best = p.iter().filter(|l| l.1).map(|l| l.0).max().unwrap_or(0);
                assert_eq!(best, m - t, "m {m} t {t}: {p:?}");
            }
        }
    }

    #[test]
    fn the_estimate_without_t_bounds_every_t() {
        for (m, s) in [(10u32, 2usize), (16, 4), (20, 4), (12, 6), (14, 8)] {
            let n = 1u64 << m;
            let none = count_steps(n, s, m, 2, None);
            assert_eq!(none, count_steps(n, s, m, 2, Some(0)));
            for t in 0..=m {
                assert!(
                    count_steps(n, s, m, 2, Some(t)) <= none,
                    "m {m} s {s} t {t}"
                );
            }
        }
        // One level: C(rho + s - 1, s - 1) shapes of n (s + 1) steps and 2 b^rho cells.
        assert_eq!(level_steps(1 << 10, 3, 4, 2), 15.0 * (4096.0 + 32.0));
        assert_eq!(level_steps(125, 2, 3, 5), 4.0 * (125.0 * 3.0 * 4.0 + 250.0));
        // Past 2 MiB of counts (2^19 cells) each point's increment misses the cache.
        let n = 1u64 << 21;
        assert_eq!(
            level_steps(n, 2, 18, 2),
            19.0 * (n as f64 * 3.0 + 2.0 * 262144.0)
        );
        assert_eq!(
            level_steps(n, 2, 19, 2),
            20.0 * (n as f64 * (3.0 + INCREMENT_MISS) + 2.0 * 524288.0)
        );
    }

    /// The model against the least CPU time of one thread (`examples/time_costs.rs`, on the
    /// first `2^m` Owen-scrambled Sobol' points): every shape of one level (counts in and
    /// past the cache), and whole searches of sets with t = 0, 1, 3 and 5. Within 0.6 to
    /// 1.6 of the measured time.
    #[test]
    fn the_model_follows_the_measured_times() {
        let per_core = |steps: f64| steps / COUNT_RATE.steps_per_second();
        // (s, m, rho, seconds): one level.
        for (s, m, rho, seconds) in [
            (2usize, 16u32, 12u32, 0.0020),
            (2, 21, 18, 0.1220),
            (2, 21, 20, 0.4120),
            (4, 20, 16, 3.2999),
            (4, 16, 8, 0.0462),
            (4, 16, 12, 0.1293),
            (4, 16, 13, 0.1507),
            (6, 12, 7, 0.0155),
            (8, 14, 8, 0.664),
        ] {
            let ratio = seconds / per_core(level_steps(1 << m, s, rho, 2));
            assert!(
                (0.6..1.6).contains(&ratio),
                "s {s} m {m} rho {rho}: {ratio}"
            );
        }
        // (s, m, t, seconds): the t-value's search.
        for (s, m, t, seconds) in [
            (2usize, 18u32, 0u32, 0.0585),
            (3, 16, 1, 0.0797),
            (4, 16, 3, 0.3701),
            (6, 12, 5, 0.0315),
        ] {
            let ratio = seconds / per_core(count_steps(1 << m, s, m, 2, Some(t)));
            assert!((0.6..1.6).contains(&ratio), "s {s} m {m} t {t}: {ratio}");
        }
    }
}
