//! Sequential state: `phi_b(i) 2^32` as an integer part and an exact remainder, advanced
//! by cached carry steps, and the iterator built on it.

use super::*;

/// State of the sequential radical inverse for a base other than 2: `phi_b(i) 2^32` as
/// `q + r / B`, the lowest digit of the index, and the cached steps.
#[derive(Clone, Debug)]
pub(super) struct Sequential {
    /// Index of the value held.
    pub(super) index: u32,
    /// The two lowest base-`b` digits of `index`, `(d_1, d_2)`.
    pub(super) low: (u32, u32),
    /// Integer part of `phi_b(index) 2^32`.
    pub(super) q: u32,
    /// Remainder of `phi_b(index) 2^32`, over `B`.
    pub(super) r: u64,
    pub(super) steps: [(u32, u64); STEPS],
}

impl Sequential {
    pub(super) const fn new(ri: &RadicalInverse, start: u32) -> Self {
        let (q, r) = ri.scale(ri.numerator(start));
        Sequential {
            index: start,
            low: (
                rem_u32(start, ri.base),
                rem_u32(div_u32(start, ri.base), ri.base),
            ),
            q,
            r,
            steps: ri.steps(),
        }
    }

    /// Moves to the next index; the caller guarantees `index < u32::MAX`.
    #[inline(always)]
    pub(super) fn advance(&mut self, ri: &RadicalInverse) {
        (self.index, self.low, self.q, self.r) =
            advance(ri, &self.steps, self.index, self.low, self.q, self.r);
    }
}

/// One sequential step on the state `(index, low, q, r)`, as a pure function so that a
/// loop can keep the state in registers.
#[inline(always)]
pub(super) fn advance(
    ri: &RadicalInverse,
    steps: &[(u32, u64); STEPS],
    index: u32,
    low: (u32, u32),
    q: u32,
    r: u64,
) -> (u32, (u32, u32), u32, u64) {
    let index = index.wrapping_add(1);
    let (low, (dq, dr)) = if low.0 + 1 < ri.base {
        ((low.0 + 1, low.1), steps[0])
    } else if low.1 + 1 < ri.base {
        ((0, low.1 + 1), steps[1])
    } else {
        ((0, 0), carry(ri, steps, index))
    };
    let (r, overflow) = r.overflowing_add(dr);
    let wrap = overflow || r >= ri.big;
    let r = if wrap { r.wrapping_sub(ri.big) } else { r };
    (index, low, q.wrapping_add(dq).wrapping_add(wrap as u32), r)
}

/// The two lowest digits wrapped: the step for the `t >= 2` trailing zero digits of
/// `index` (probability `b^-2`).
#[cold]
#[inline(never)]
pub(super) fn carry(ri: &RadicalInverse, steps: &[(u32, u64); STEPS], index: u32) -> (u32, u64) {
    let t = ri.trailing_zero_digits(index);
    if (t as usize) < STEPS {
        steps[t as usize]
    } else {
        ri.step(t)
    }
}

/// Sequential radical inverse: yields `phi_b(start)`, `phi_b(start + 1)`, ... (as 0.32
/// fractions) up to index `u32::MAX`, bit-identical to [`RadicalInverse::sample`].
///
/// Keeps `phi_b(i) 2^32` exactly as an integer part and a remainder over `B`, plus the
/// lowest digit of `i`; a step adds a cached increment.
///
/// ```
/// use qmckit::RadicalInverse;
/// let phi5 = RadicalInverse::new(5).unwrap();
/// assert!(phi5.iter_from(17).take(1000).zip(17..).all(|(x, i)| x == phi5.sample(i)));
/// ```
#[derive(Clone, Debug)]
pub struct RadicalInverseIter {
    ri: RadicalInverse,
    seq: Sequential,
    /// Values left to yield (2^32 - start at the beginning).
    left: u64,
}

impl RadicalInverseIter {
    pub(super) const fn new(ri: RadicalInverse, start: u32) -> Self {
        let seq = if ri.base == 2 {
            Sequential {
                index: start,
                low: (0, 0),
                q: reverse_bits(start),
                r: 0,
                steps: [(0, 0); STEPS],
            }
        } else {
            Sequential::new(&ri, start)
        };
        RadicalInverseIter {
            ri,
            seq,
            left: TWO_32 - start as u64,
        }
    }
}

impl Iterator for RadicalInverseIter {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        if self.left == 0 {
            return None;
        }
        let value = self.seq.q;
        self.left -= 1;
        if self.left > 0 {
            if self.ri.base == 2 {
                self.seq.index += 1;
                self.seq.q = reverse_bits(self.seq.index);
            } else {
                self.seq.advance(&self.ri);
            }
        }
        Some(value)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = usize::try_from(self.left).unwrap_or(usize::MAX);
        (left, usize::try_from(self.left).ok())
    }
}
