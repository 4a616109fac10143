//! Batch fills: consecutive indices by runs of the lowest digits (bases up to 256), by the
//! cached carry steps otherwise, and by bit reversal in base 2.

use super::sequential::advance;
use super::*;

impl RadicalInverse {
    /// A sequential iterator over `sample(start)`, `sample(start + 1)`, ... up to index
    /// `u32::MAX`: the same bits as [`sample`](Self::sample), a few cycles per value.
    pub const fn iter_from(&self, start: u32) -> RadicalInverseIter {
        RadicalInverseIter::new(*self, start)
    }

    /// Fills `out[k] = sample(start + k)`.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] if `start + out.len()` passes 2^32.
    pub fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        self.fill_strided(start, out, 1)
    }

    /// Fills every `stride`-th element of `out`, starting with `out[0]`, with consecutive
    /// samples from `start` on: the column of a row-major point buffer.
    ///
    /// The sequential fast path: the exact value is kept as an integer part and a remainder
    /// over `B` in registers, and each index adds a cached step (one add, compare and
    /// conditional subtract while the lowest digit does not wrap).
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] if the indices pass 2^32; [`Error::BufferLength`] for a
    /// zero stride.
    pub fn fill_strided(&self, start: u32, out: &mut [u32], stride: usize) -> Result<()> {
        self.fill_strided_as(start, out, stride)
    }

    /// [`fill_strided`](Self::fill_strided) into any coordinate type (`f64`, `f32`, ...),
    /// converted as each value is stored ([`FromFraction`]): the same values as converting
    /// the `u32` fill afterwards, without a second pass.
    ///
    /// ```
    /// use qmckit::RadicalInverse;
    /// let phi3 = RadicalInverse::new(3)?;
    /// let mut x = [0f64; 4];
    /// phi3.fill_strided_as(1, &mut x, 1)?;
    /// assert_eq!(x[1], qmckit::bits::to_f64(phi3.sample(2))); // 2/3, 32 bits
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`fill_strided`](Self::fill_strided).
    pub fn fill_strided_as<T: FromFraction>(
        &self,
        start: u32,
        out: &mut [T],
        stride: usize,
    ) -> Result<()> {
        if stride == 0 {
            return Err(Error::BufferLength {
                expected: 1,
                got: 0,
            });
        }
        let count = out.len().div_ceil(stride) as u64;
        check_range(start, count)?;
        if self.base == 2 {
            fill_base_2(start, out, stride);
            return Ok(());
        }
        if self.by_runs() {
            self.fill_runs(start, out, stride);
            return Ok(());
        }
        let seq = Sequential::new(self, start);
        let (mut index, mut low, mut q, mut r) = (seq.index, seq.low, seq.q, seq.r);
        let mut slots = out.iter_mut().step_by(stride);
        if let Some(first) = slots.next() {
            *first = T::from_fraction(q);
        }
        for slot in slots {
            (index, low, q, r) = advance(self, &seq.steps, index, low, q, r);
            *slot = T::from_fraction(q);
        }
        Ok(())
    }

    /// Whether the sequential fill goes by runs ([`RunFill`]): `2 <= b <= RUN_TABLE` (and
    /// `B <= 2^63`, true for these bases: `B < b 2^32`).
    #[inline]
    pub(crate) const fn by_runs(&self) -> bool {
        self.base >= 2 && self.base as usize <= RUN_TABLE && self.big <= 1 << 63
    }

    /// Sequential fill for bases `2 ..= RUN_TABLE`, by runs of the lowest `k` digits, with
    /// `L = b^k` the largest power of `b` up to [`RUN_TABLE`] (256, 243, 125, 49, 121, 169
    /// for bases 2, 3, 5, 7, 11, 13; `L = b` for the primes from 17 on). Needs `B <= 2^63`.
    ///
    /// Within a run, `phi_b(h L + e) = phi_b(h L) + n_e / L` exactly, where `n_e` is `e`
    /// with its `k` digits reversed. The table holds `2^32 n_e / L = P_e + s_e / L`
    /// (`P_e = floor`, `0 <= s_e < L`, built by a chain of exact additions of `2^32 / L`),
    /// and the run base is `q + r / B`. As `L` divides `B` (`k <= K`), with `U = B / L`,
    ///
    /// ```text
    /// floor(2^32 phi_b(h L + e)) = q + P_e + [r + s_e U >= B] = q + P_e + [s_e >= ceil((B - r) / U)]
    /// ```
    ///
    /// so each value is two table loads, a 32-bit compare against the run's threshold and
    /// two adds (no 64-bit work, no chain from value to value). Per run of `L` values: the
    /// run base steps by the last entry plus the carry step for the `t >= k` trailing zero
    /// digits of `(h + 1) L` (counted only when the next digit above the run wraps,
    /// probability `1/b`; cached for `t = k, k + 1`), and the threshold takes one multiply-high and one correction.
    /// Stack: `RUN_TABLE` `u32`s and as many bytes (1280 bytes).
    pub(super) fn fill_runs<T: FromFraction>(&self, start: u32, out: &mut [T], stride: usize) {
        let count = out.len().div_ceil(stride);
        RunFill::new(self, start).write(out, stride, count);
    }
}

/// The resumable state of [`RadicalInverse::fill_runs`] (see there for the math): the
/// tables of one base and the current run, so that a caller can fill a column block by
/// block (the Halton fill interleaves several dimensions this way). About 1.5 KiB.
pub(crate) struct RunFill {
    pq: [u32; RUN_TABLE],
    ps: [u8; RUN_TABLE],
    ri: RadicalInverse,
    /// `L = b^k`, `k`, and `L` as a table length.
    len: u32,
    k: u32,
    l: usize,
    /// `U = B / L` and `floor((2^64 - 1) / U)`.
    unit: u64,
    unit_magic: u64,
    /// `2^32 (L - 1) / L` as `(P, s U)`: the last entry, exact over `B`.
    last: (u32, u64),
    /// The carry steps for `t = k` and `t = k + 1` trailing zero digits (longer carries,
    /// probability `b^-2` a run, are computed on the spot).
    steps: [(u32, u64); 2],
    /// The current run: its first index `h L`, the lowest digit of `h`, its base
    /// `q + r / B`, its carry threshold, and the offset of the next value in it.
    run_index: u32,
    next_digit: u32,
    base_q: u32,
    base_r: u64,
    thr: u32,
    d0: usize,
}

impl RunFill {
    /// The state at index `start`, for `2 <= base <= RUN_TABLE` and `B <= 2^63`.
    pub(crate) fn new(ri: &RadicalInverse, start: u32) -> Self {
        // The caller guarantees 2 <= base <= RUN_TABLE; the clamps are no-ops that let the
        // compiler see every table index below in bounds (no panic path survives
        // inlining; tests/firmware/panic_proof.sh checks this at link time).
        let b = ri.base.clamp(2, RUN_TABLE as u32);
        let (mut len, mut k) = (b, 1u32);
        while len * b <= RUN_TABLE as u32 {
            len *= b;
            k += 1;
        }
        let l = (len as usize).clamp(2, RUN_TABLE);
        // U = B / L, exact as L = b^k with k <= K.
        let unit = div_u64(ri.big, len as u64);
        // (pq[e], ps[e]) = 2^32 rev_k(e) / L as integer part and remainder over L. Walk
        // n = 0, 1, .. L - 1 (adding 2^32 / L exactly each time) and keep e = rev_k(n): a
        // carry out of digit j of n moves e by b^(k-1-j).
        let (mut pq, mut ps) = ([0u32; RUN_TABLE], [0u8; RUN_TABLE]);
        let (step_q, step_s) = (
            div_u64(TWO_32, len as u64) as u32,
            rem_u64(TWO_32, len as u64) as u32,
        );
        let (mut q, mut s, mut e) = (0u32, 0u32, 0u32);
        let top = div_u32(len, b); // b^(k-1), the weight of digit 0 of n in e
        let mut digit = [0u32; 8]; // k <= 8 (b = 2), 5 for b >= 3
        for _ in 0..l {
            if let (Some(a), Some(c)) = (pq.get_mut(e as usize), ps.get_mut(e as usize)) {
                (*a, *c) = (q, s as u8); // s < L <= 256
            }
            (q, s) = (q.wrapping_add(step_q), s + step_s);
            if s >= len {
                (q, s) = (q.wrapping_add(1), s - len);
            }
            let mut place = top;
            for d in digit.iter_mut().take(k as usize) {
                *d += 1;
                e += place;
                if *d < b {
                    break;
                }
                *d = 0;
                e -= place * b;
                place = div_u32(place, b);
            }
        }
        let low = rem_u32(start, len) as usize;
        let run_index = start - low as u32; // h L
        let (base_q, base_r) = ri.scale(ri.numerator(run_index));
        let mut state = RunFill {
            last: (pq[l - 1], ps[l - 1] as u64 * unit),
            pq,
            ps,
            ri: *ri,
            len,
            k,
            l,
            unit,
            // floor((2^64 - 1) / U): ceil(y / U) for y <= B by one multiply-high and a fix.
            unit_magic: div_u64(u64::MAX, unit),
            steps: [ri.step(k), ri.step(k + 1)], // k + 1 < K: b^(k+1) <= 256 b < 2^32
            run_index,
            // The lowest digit of h (that of h + 1 decides whether a carry passes digit k).
            next_digit: rem_u32(div_u32(run_index, len), b),
            base_q,
            base_r,
            thr: 0,
            d0: low,
        };
        state.thr = state.threshold();
        state
    }

    /// `ceil((B - r) / U)` for the run base's remainder `r`, in `1 ..= L`.
    #[inline]
    pub(super) fn threshold(&self) -> u32 {
        let (y, unit) = (self.ri.big - self.base_r, self.unit); // 1 ..= B
        let q0 = ((y as u128 * self.unit_magic as u128) >> 64) as u64; // q - 1 or q
        let r0 = y - q0 * unit; // < 2 U
        let (q, r) = if r0 >= unit {
            (q0 + 1, r0 - unit)
        } else {
            (q0, r0)
        };
        (q + (r != 0) as u64) as u32
    }

    /// Moves to the next run; the caller guarantees a value of it is due (so its first
    /// index fits in `u32`).
    pub(super) fn next_run(&mut self) {
        let ri = &self.ri;
        // (h + 1) L ends in t >= k zero digits, t > k iff h + 1 ends in 0.
        self.run_index = self.run_index.wrapping_add(self.len);
        self.next_digit += 1;
        let t = if self.next_digit < ri.base {
            self.k
        } else {
            self.next_digit = 0;
            ri.trailing_zero_digits(self.run_index)
        };
        let step = match t.wrapping_sub(self.k) {
            0 => self.steps[0],
            1 => self.steps[1],
            _ => ri.step(t),
        };
        // The run base moved by the carry step minus the last run's (L - 1) / L part.
        (self.base_q, self.base_r) = add_exact(
            add_exact((self.base_q, self.base_r), self.last, ri.big),
            step,
            ri.big,
        );
        self.thr = self.threshold();
        self.d0 = 0;
    }

    /// Writes the next `count` values to `out[0], out[stride], ..` (those in bounds); the
    /// caller guarantees their indices stay within `u32`.
    #[inline]
    pub(crate) fn write<T: FromFraction>(&mut self, out: &mut [T], stride: usize, count: usize) {
        let mut done = 0;
        while done < count {
            if self.d0 >= self.l {
                self.next_run();
            }
            let (d0, base_q, thr) = (self.d0, self.base_q, self.thr);
            let n = (self.l - d0).min(count - done);
            let run = self.pq.get(d0..d0 + n).unwrap_or(&[]);
            let run_s = self.ps.get(d0..d0 + n).unwrap_or(&[]);
            let value = |p: u32, s: u8| {
                base_q
                    .wrapping_add(p)
                    .wrapping_add((s as u32 >= thr) as u32)
            };
            write_run(
                out,
                done,
                stride,
                run.iter().zip(run_s).map(|(&p, &s)| value(p, s)),
            );
            self.d0 = d0 + n;
            done += n;
        }
    }
}

/// Writes `values`, converted, to `out[(done + j) stride]`, `j = 0, 1, ..` (those in
/// bounds): a plain zip for `stride = 1` (which vectorizes), else indexed stores.
#[inline(always)]
pub(super) fn write_run<T: FromFraction>(
    out: &mut [T],
    done: usize,
    stride: usize,
    values: impl Iterator<Item = u32>,
) {
    if stride == 1 {
        for (slot, v) in out
            .get_mut(done..)
            .unwrap_or(&mut [])
            .iter_mut()
            .zip(values)
        {
            *slot = T::from_fraction(v);
        }
    } else {
        let mut pos = done.saturating_mul(stride);
        for v in values {
            if let Some(slot) = out.get_mut(pos) {
                *slot = T::from_fraction(v);
            }
            pos = pos.saturating_add(stride);
        }
    }
}

/// The base-2 sequential fill, by runs of `L = RUN_TABLE = 2^8` indices: for `e < L`,
/// `rev(h L + e) = rev(h L) | rev(e)` (the bit reversal `rev` of 32 bits maps the low 8
/// bits to the top 8 and the rest below them), with `rev(e)` from a table built by
/// `rev(e) = rev(e >> 1) >> 1 | (e & 1) << 31`. One load and one OR a value, one reversal a
/// run. Stack: 1 KiB. (The general [`RunFill`] also serves base 2 — the blocked Halton fill
/// uses it to keep one resumable state kind — but with its threshold compare and add it
/// measured 1.4x slower than this for the column fill of 2D Halton.)
pub(super) fn fill_base_2<T: FromFraction>(start: u32, out: &mut [T], stride: usize) {
    let mut rev = [0u32; RUN_TABLE];
    for e in 1..RUN_TABLE {
        rev[e] = rev[e >> 1] >> 1 | ((e as u32 & 1) << 31);
    }
    let mut run_index = start & !(RUN_TABLE as u32 - 1);
    let mut d0 = (start - run_index) as usize;
    let count = out.len().div_ceil(stride); // values due
    let mut done = 0; // values written
    loop {
        let base = reverse_bits(run_index);
        let n = (RUN_TABLE - d0).min(count - done);
        let run = rev.get(d0..d0 + n).unwrap_or(&[]);
        write_run(out, done, stride, run.iter().map(|&p| base | p));
        done += n;
        if done >= count {
            break;
        }
        // A value of the next run is still due, so its index fits in u32.
        run_index = run_index.wrapping_add(RUN_TABLE as u32);
        d0 = 0;
    }
}

/// Checks that indices `start .. start + count` all fit in `u32`.
pub(crate) const fn check_range(start: u32, count: u64) -> Result<()> {
    let end = start as u64 + count;
    if end > TWO_32 {
        return Err(Error::IndexOutOfRange {
            index: end - 1,
            len: TWO_32,
        });
    }
    Ok(())
}
