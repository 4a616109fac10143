//! A sort of distinct `u64` keys whose upper bits are spread over their range (the keys
//! `(q << 32) | i` of sliced optimal transport: `q` a 32-bit fixed-point projection,
//! `i` the point's index), and the order-preserving 32-bit key of a value in a range.
//!
//! A distribution sort (Knuth, TAOCP vol. 3, 5.2.5 and exercise 5.2-13, "bucket
//! sorting"): the keys are counted into `B` buckets, `B` the power of two at or above
//! `2 N`, by their top `log2 B` bits, and scattered in order into the other buffer; the
//! inversions left (within buckets) are then removed by one insertion-sort pass when no
//! bucket holds more than [`INSERTION_MAX`] keys (so `O(N INSERTION_MAX)` at worst),
//! else by the standard library's sort. For keys spread over their range (a bucket
//! holds about one key) this is about three reads and two writes of the keys, `O(N)`;
//! clustered keys fall back to the `O(N log N)` comparison sort. The result is the keys
//! in increasing order.

/// `B`, the buckets for `n` keys: the power of two at or above `2 n`, so that most keys
/// have a bucket of their own (and the insertion pass's branch is mostly predicted).
fn buckets(n: usize) -> usize {
    n.max(1).saturating_mul(2).next_power_of_two()
}

/// The largest bucket of the insertion pass.
const INSERTION_MAX: usize = 32;

/// The buffers of [`KeySort::sort`] for up to `n` keys.
pub(crate) struct KeySort {
    start: Vec<usize>,
    tmp: Vec<u64>,
}

impl KeySort {
    /// Buffers for up to `n` keys (`B + n` words).
    ///
    /// # Errors
    /// [`crate::Error::TooLarge`] when they do not fit.
    pub(crate) fn new(n: usize) -> crate::Result<Self> {
        Ok(KeySort {
            start: crate::size::vec_zeroed(buckets(n))?,
            tmp: crate::size::vec_zeroed(n)?,
        })
    }

    /// Sorts the distinct `keys` increasingly (at most the `n` of [`KeySort::new`]; more
    /// are sorted by the standard library's sort).
    pub(crate) fn sort(&mut self, keys: &mut [u64]) {
        let n = keys.len();
        let buckets = buckets(n);
        let bits = buckets.trailing_zeros();
        let (Some(tmp), Some(start)) = (self.tmp.get_mut(..n), self.start.get_mut(..buckets))
        else {
            keys.sort_unstable();
            return;
        };
        if n < 2 {
            return;
        }
        let shift = 64 - bits;
        // Bucket sizes, then (in place) the bucket starts, then (after the scatter) ends.
        let count = &mut start[..buckets];
        count.fill(0);
        for &k in keys.iter() {
            count[(k >> shift) as usize] += 1;
        }
        let largest = count.iter().copied().max().unwrap_or(0);
        let mut sum = 0;
        for c in count.iter_mut() {
            let here = *c;
            *c = sum;
            sum += here;
        }
        for &k in keys.iter() {
            let slot = &mut count[(k >> shift) as usize];
            tmp[*slot] = k;
            *slot += 1;
        }
        // Sorted by bucket: what is left are the inversions within buckets.
        if largest <= INSERTION_MAX {
            for j in 1..n {
                let k = tmp[j];
                let mut i = j;
                while i > 0 && tmp[i - 1] > k {
                    tmp[i] = tmp[i - 1];
                    i -= 1;
                }
                tmp[i] = k;
            }
        } else {
            tmp.sort_unstable();
        }
        keys.copy_from_slice(tmp);
    }
}

/// The 32-bit key of `v` in `[lo, hi]`: `floor((v - lo) / (hi - lo) (2^32 - 1))`,
/// monotone in `v` (0 when `hi <= lo`).
#[inline]
pub(crate) fn key32(v: f64, lo: f64, scale: f64) -> u64 {
    // `as` saturates: values at the ends map to 0 and 2^32 - 1.
    u64::from(((v - lo) * scale) as u32)
}

/// The scale of [`key32`] for the range `[lo, hi]`.
pub(crate) fn key_scale(lo: f64, hi: f64) -> f64 {
    if hi > lo && (hi - lo).is_finite() {
        4_294_967_295.0 / (hi - lo)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against the standard library's sort: pseudo-random keys with many equal upper
    /// halves (one large bucket), spread keys, and keys differing only in the top byte.
    #[test]
    fn matches_a_comparison_sort() {
        let mut state = 0x0123_4567_89AB_CDEFu64;
        for (n, spread) in [(0usize, 1u64), (1, 1), (7, 3), (1000, 1 << 32), (5000, 50)] {
            let mut keys: Vec<u64> = (0..n as u64)
                .map(|i| {
                    state = state
                        .wrapping_mul(6_364_136_223_846_793_005)
                        .wrapping_add(1_442_695_040_888_963_407);
                    ((state >> 11) % spread) << 32 | i
                })
                .collect();
            let mut want = keys.clone();
            want.sort_unstable();
            KeySort::new(n).unwrap().sort(&mut keys);
            assert_eq!(keys, want, "n {n} spread {spread}");
        }
        // Keys differing only in the top byte (a few full buckets).
        let mut keys: Vec<u64> = (0..300u64).map(|i| ((299 - i) << 56) | i).collect();
        let mut want = keys.clone();
        want.sort_unstable();
        KeySort::new(300).unwrap().sort(&mut keys);
        // More keys than the buffers: the fallback.
        let mut more: Vec<u64> = (0..50u64).rev().collect();
        KeySort::new(10).unwrap().sort(&mut more);
        assert_eq!(more, (0..50u64).collect::<Vec<_>>());
        assert_eq!(keys, want);
    }

    #[test]
    fn keys_are_monotone() {
        let s = key_scale(-1.5, 2.0);
        let vs = [-1.5, -1.0, 0.0, 1e-9, 0.5, 1.999_999, 2.0];
        let ks: Vec<u64> = vs.iter().map(|&v| key32(v, -1.5, s)).collect();
        assert!(ks.windows(2).all(|w| w[0] <= w[1]), "{ks:?}");
        assert_eq!(ks[0], 0);
        assert_eq!(ks[6], u64::from(u32::MAX));
        assert_eq!(key_scale(1.0, 1.0), 0.0);
    }
}
