//! The sequential fill of a base-`b` digital net: each point's output digits from the
//! previous point's.
//!
//! Going from index `i` to `i + 1` turns the `c` lowest index digits (all `b - 1`) into 0
//! and raises digit `c` by one. Over `F_b` that adds `-(b - 1) = 1` to each of the digits
//! `0..c` and `1` to digit `c`, so the output digits change by the column prefix sum
//!
//! ```text
//! y(i + 1) = y(i) + S_c  (mod b),     S_c = C e_0 + C e_1 + ... + C e_c,
//! ```
//!
//! the base-`b` form of the Gray-code-free Sobol' recurrence (in base 2 it is
//! `y(i + 1) = y(i) ^ S_c` with `c` the trailing ones of `i`). A value then costs `K`
//! additions with a conditional subtraction, against `K x m` multiply-adds by random access,
//! plus the combination of the `K` digits (and their scramble, if any). The fill runs
//! dimension by dimension over blocks of [`BLOCK`] points, each block started from the
//! exact digits of its first index, so nothing needs more than `O(K^2)` stack.

use super::{DigitalNetB, MAX_DIGITS};
use crate::error::Result;
use crate::sampler::check_fill;

/// Points a block: each dimension's digits are set up once a block (`K x m` products and
/// the `K x m` prefix sums), which is noise against its `BLOCK x K` additions.
const BLOCK: usize = 1024;

/// [`crate::Sampler::fill`] of a [`DigitalNetB`]: the same bits as random access.
pub(super) fn fill<M: AsRef<[u16]>>(
    net: &DigitalNetB<M>,
    start: u32,
    out: &mut [u32],
) -> Result<()> {
    let rows = check_fill(net, start, out.len())?;
    // check_fill refuses zero dimensions; restated so that chunking cannot panic.
    let dims = net.dims.max(1);
    let (b, k, cols) = (
        net.base,
        net.digits.min(MAX_DIGITS),
        net.cols.min(MAX_DIGITS),
    );
    let per_dim = net.digits * net.cols;
    let all = net.matrices.as_ref();
    // Base 2 unscrambled: the digits packed in one word, the step an exclusive or.
    let packed = b == 2 && k == 32 && net.scramble.is_none();
    for (block, chunk) in out
        .chunks_mut(BLOCK * dims)
        .enumerate()
        .take(rows.div_ceil(BLOCK))
    {
        let first = start as u64 + (block * BLOCK) as u64;
        for dim in 0..dims {
            let matrix = all.get(dim * per_dim..(dim + 1) * per_dim).unwrap_or(&[]);
            // S[c][r]: row r's sum of columns 0..=c, mod b.
            let mut s = [[0u32; MAX_DIGITS]; MAX_DIGITS];
            for (r, row) in matrix.chunks_exact(net.cols).take(k).enumerate() {
                let mut acc = 0u32;
                for (sc, &e) in s.iter_mut().zip(row) {
                    acc += e as u32;
                    if acc >= b {
                        acc -= b;
                    }
                    if let Some(slot) = sc.get_mut(r) {
                        *slot = acc;
                    }
                }
            }
            // The digits of the block's first index (least significant first) and its
            // output digits, by random access.
            let mut a = [0u32; MAX_DIGITS];
            let mut rest = first;
            for slot in a.iter_mut().take(cols) {
                *slot = (rest % b as u64) as u32;
                rest /= b as u64;
            }
            let mut y = [0u32; MAX_DIGITS];
            for (slot, row) in y.iter_mut().zip(matrix.chunks_exact(net.cols)).take(k) {
                let sum = row
                    .iter()
                    .zip(&a)
                    .fold(0u64, |acc, (&c, &ak)| acc + c as u64 * ak as u64);
                *slot = (sum % b as u64) as u32;
            }
            let column = chunk.iter_mut().skip(dim).step_by(dims);
            if packed {
                let word =
                    |d: &[u32; MAX_DIGITS]| d.iter().fold(0u32, |w, &bit| (w << 1) | (bit & 1));
                let steps: [u32; MAX_DIGITS] = core::array::from_fn(|c| s.get(c).map_or(0, word));
                let mut v = word(&y);
                for (t, slot) in column.enumerate() {
                    if t > 0 {
                        // Index first + t: its predecessor's trailing ones.
                        let c = ((first + t as u64).trailing_zeros() as usize).min(MAX_DIGITS - 1);
                        v ^= steps.get(c).copied().unwrap_or(0);
                    }
                    *slot = v;
                }
                continue;
            }
            for (t, slot) in column.enumerate() {
                if t > 0 {
                    // Carry through the trailing digits b - 1; the index stays below
                    // b^cols (check_fill), so the carry ends inside the m digits.
                    let mut c = 0;
                    while c + 1 < cols && a.get(c) == Some(&(b - 1)) {
                        if let Some(d) = a.get_mut(c) {
                            *d = 0;
                        }
                        c += 1;
                    }
                    if let Some(d) = a.get_mut(c) {
                        *d += 1;
                    }
                    if let Some(step) = s.get(c) {
                        for (yr, &sr) in y.iter_mut().zip(step).take(k) {
                            let v = *yr + sr;
                            *yr = if v >= b { v - b } else { v };
                        }
                    }
                }
                *slot = net.to_fraction(net.combine(dim, y.get(..k).unwrap_or(&[])));
            }
        }
    }
    Ok(())
}
