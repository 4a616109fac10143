//! The sequential fill of a radical inverse scrambled digit by digit with one permutation
//! a digit place ([`DigitScramble::Permutations`], [`DigitScramble::Faure`]): the same
//! values as [`RadicalInverse::sample_scrambled`], by runs of the lowest digits.
//!
//! With such a scramble the exact numerator `N(i) = sum_(j=1..K) sigma_j(d_j) b^(K-j)`
//! splits at `c` digits: for `i = h b^c + e` (`e < b^c`), `N(i) = L(e) + H(h)` where `L`
//! sums the places `1..=c` (a table of `b^c` entries, built once) and `H` the places
//! `c+1..=K` (once a run of `b^c` consecutive indices). A value is then one load, one add
//! and [`RadicalInverse::scale`], instead of `K` divisions and `K` keyed permutations.
//! The tables cost `K b` permutations and `b^c` additions, so a dimension takes this path
//! only for fills of at least `b` indices. `std` only (the tables are allocated).

use std::vec::Vec;

use super::RadicalInverse;
use super::fill::write_run;
use crate::bits::{FromFraction, div_u64, rem_u64};
use crate::randomize::digits::DigitScramble;

/// Largest low-digit table (`b^c` entries, at least `b`).
const LOW_TABLE: u64 = 1024;

/// True when `scramble` permutes each digit place independently of the other digits (so
/// [`PermutedFill`] applies).
pub(crate) const fn is_per_place(scramble: &DigitScramble) -> bool {
    matches!(
        scramble,
        DigitScramble::Permutations(_) | DigitScramble::Faure
    )
}

/// The resumable state of the fill of one dimension: its tables and the next index.
pub(crate) struct PermutedFill {
    ri: RadicalInverse,
    /// `b^c`.
    low_len: u64,
    /// `L(e)`, `e < b^c`.
    low: Vec<u64>,
    /// `sigma_j(d) b^(K-j)` for the places `j = c+1 ..= K`, `b` entries a place.
    high: Vec<u64>,
    /// The next index.
    index: u64,
}

impl PermutedFill {
    /// The state at index `start` of `ri` scrambled by `scramble` (per place, see
    /// [`is_per_place`]) in dimension `dim`.
    pub(crate) fn new(
        ri: &RadicalInverse,
        scramble: &DigitScramble,
        dim: usize,
        start: u32,
    ) -> Self {
        let b = ri.base as u64;
        let places = ri.digits as u32;
        // c >= 1 places in the low table, b^c <= max(LOW_TABLE, b), c <= K.
        let (mut c, mut low_len) = (1u32, b);
        while c < places && low_len * b <= LOW_TABLE {
            c += 1;
            low_len *= b;
        }
        // weights[j - 1] = b^(K - j).
        let mut weights = Vec::with_capacity(places as usize);
        let mut w = div_u64(ri.big, b);
        for _ in 0..places {
            weights.push(w);
            w = div_u64(w, b);
        }
        let place_table = |j: u32| -> Vec<u64> {
            let w = weights.get(j as usize - 1).copied().unwrap_or(0);
            (0..ri.base)
                .map(|d| scramble.digit(ri.base, dim, j, 0, d) as u64 * w)
                .collect()
        };
        // L(e) place by place: L_j(e) = L_(j-1)(e mod b^(j-1)) + sigma_j(digit j of e).
        let mut low = Vec::with_capacity(low_len as usize);
        low.push(0u64);
        for j in 1..=c {
            let t = place_table(j);
            let prev = low.len();
            let mut next = Vec::with_capacity(prev * ri.base as usize);
            for &s in &t {
                next.extend(low.iter().map(|&l| l + s));
            }
            low = next;
            debug_assert_eq!(low.len(), prev * ri.base as usize);
        }
        let mut high = Vec::with_capacity(((places - c) * ri.base) as usize);
        for j in c + 1..=places {
            high.extend(place_table(j));
        }
        PermutedFill {
            ri: *ri,
            low_len,
            low,
            high,
            index: start as u64,
        }
    }

    /// `H(h)`: the places above the low table.
    fn high_sum(&self, mut h: u64) -> u64 {
        let b = self.ri.base as u64;
        let mut acc = 0u64;
        for place in self.high.chunks_exact(self.ri.base as usize) {
            let d = rem_u64(h, b) as usize;
            h = div_u64(h, b);
            acc += place.get(d).copied().unwrap_or(0);
        }
        acc
    }

    /// The next `count` values into `out[0]`, `out[stride]`, ..., converted; the index
    /// advances by `count` (the caller checked the range).
    pub(crate) fn fill_strided_as<T: FromFraction>(
        &mut self,
        out: &mut [T],
        stride: usize,
        count: usize,
    ) {
        let mut done = 0usize;
        while done < count {
            let h = self.index / self.low_len;
            let e0 = (self.index % self.low_len) as usize;
            let n = (self.low_len as usize - e0).min(count - done);
            let hs = self.high_sum(h);
            let ri = &self.ri;
            let run = self.low.get(e0..e0 + n).unwrap_or(&[]);
            write_run(out, done, stride, run.iter().map(|&l| ri.scale(l + hs).0));
            done += n;
            self.index += n as u64;
        }
    }
}
