//! Random access: `phi_b(i)` of one index by chunked digit peeling, nested floors, flat
//! multiply-highs or the exact numerator (see the parent module for the math).

use super::*;

impl RadicalInverse {
    /// `floor(phi_b(index) * 2^32)`, exact. Defined for every `u32` index.
    ///
    /// On 64-bit targets, short indices of bases without a reversal table (`b <= 256`:
    /// below `b^3` for `b <= 40`, below `b^2` up to 256) take one branch-free formula (two
    /// multiplications for two digits, six for three; see `flat`). Otherwise indices of up
    /// to three chunks of `c` digits (`c = 5, 3, 2, 2, 2` for bases 3, 5, 7, 11, 13; 1
    /// otherwise), for `b^c <= 2^16`, go by nested floors (see `nest`): three
    /// multiplications per chunk, one for the last. Longer indices (and bases above 2^16)
    /// build the exact numerator `N` over `B = b^K` from all chunk quotients at once (see
    /// `numerator_wide`: about 16 multiplications, none waiting on another, no branch) and
    /// scale it once (two more); that is on 64-bit targets, inline, except for the composite
    /// bases 4 to 15 (more than 8 chunks). 32-bit targets build `N` chunk by chunk (four
    /// multiplications per chunk), out of line, for flash. Base 2 is one bit reversal.
    #[inline(always)]
    pub const fn sample(&self, index: u32) -> u32 {
        #[cfg(target_pointer_width = "64")]
        if index <= self.flat[3] as u32 {
            return self.flat(index);
        }
        if self.base == 2 {
            return reverse_bits(index);
        }
        let q = self.chunk;
        if index <= self.short_max {
            // index < q^3: up to three chunks by nested floors, unrolled.
            if index < q {
                return self.nest(index, 0) as u32;
            }
            let (n1, r0) = self.peel(index);
            if n1 < q {
                return self.two_chunks(r0, n1);
            }
            let (n2, r1) = self.peel(n1);
            return self.three_chunks(r0, r1, n2);
        }
        self.sample_long(index)
    }

    /// `floor(phi_b(i) 2^32)` for a short index of a base without a reversal table
    /// (`c = 1`, `q = b`), branch-free. With `Q_1 = floor(i / q)`, `Q_2 = floor(i / q^2)` the
    /// digits are `i - q Q_1`, `Q_1 - q Q_2`, `Q_2`, so for `i < q^3`
    ///
    /// ```text
    /// phi_b(i) = X / q^3,  X = (i - q Q_1) q^2 + (Q_1 - q Q_2) q + Q_2
    ///                        = i q^2 - (q^3 - q) Q_1 - (q^2 - 1) Q_2
    /// ```
    ///
    /// and for `i < q^2` (`Q_2 = 0`) `phi_b(i) = X / q^2` with `X = i q - (q^2 - 1) Q_1`; one-
    /// and two-digit indices need no branch (their high digits are 0), and index 0 gives 0
    /// for every base (all coefficients are 0 where the formula does not apply).
    ///
    /// Every product is a single 64-bit multiplication (the integer multiplier, not the
    /// number of instructions, bounds this loop): `Q_1 = floor(i M / 2^32)` with
    /// `M = floor(chunk_magic / 2^32) + 1 = (2^32 + e) / q`, `0 < e <= q`, errs by
    /// `i e / (q 2^32) < 1 / q` (as `i q < 2^32` here), less than the gap from `i / q` up to
    /// an integer, so it is exact; `Q_2` likewise from `ceil(2^64 / q^2)`. The result is
    /// `floor(X M' / 2^32)` for `M' = ceil(2^64 / q^3)` (`q <= 40`), exact as in
    /// [`three_chunks`](Self::three_chunks), and `X M' < 2^64` (`X < q^3`,
    /// `M' < 2^64 / q^3 + 1`), so the low product suffices. Cost: six multiplications.
    ///
    /// Two digits (`40 < q <= 256`, `i < q^2`) take one widening multiplication instead:
    /// with `R = ceil(2^64 / q) = (2^64 + e) / q`, `0 <= e < q`, the product
    /// `i R = 2^64 Q_1 + L` gives `Q_1` as its high half and `L = 2^64 d_0 / q + i e / q` as
    /// its low half (`d_0 = i - q Q_1`), so with `R_2 = ceil(2^64 / q^2) = (2^64 + e') / q^2`
    ///
    /// ```text
    /// S = L + Q_1 R_2 = 2^64 (d_0 q + Q_1) / q^2 + E,   E = i e / q + Q_1 e' / q^2 < q^2 + q,
    /// ```
    ///
    /// and `floor(S / 2^32) = floor(2^32 X / q^2)` because `E / 2^32 < 1 / q^2` (the gap of
    /// `2^32 X / q^2` below the next integer) whenever `q^4 + q^3 < 2^32`, i.e. `q <= 255`
    /// (`q = 256` has `e = e' = 0`); `S < 2^64`, so wrapping addition is exact. Cost: one
    /// widening multiplication and one 64-bit one (the integer multiplier bounds this loop).
    #[cfg(target_pointer_width = "64")]
    #[inline(always)]
    pub(super) const fn flat(&self, index: u32) -> u32 {
        let i = index as u64;
        let [a, a1, a2, _] = self.flat;
        if a2 == 0 {
            // Two digits, one widening multiplication and one more: see above.
            let p = i as u128 * self.chunk_magic as u128;
            let (q1, low) = ((p >> 64) as u64, p as u64);
            return (low.wrapping_add(q1 * self.power_magic[0]) >> 32) as u32;
        }
        let q1 = (i * ((self.chunk_magic >> 32) + 1)) >> 32;
        let x = (i * a as u64).wrapping_sub(q1 * a1 as u64);
        let q2 = (i * ((self.power_magic[0] >> 32) + 1)) >> 32;
        let x = x.wrapping_sub(q2 * a2 as u64);
        (x.wrapping_mul(self.power_magic[1]) >> 32) as u32 // X / q^3
    }

    /// `floor(phi_b(i) 2^32)` for an index of two chunks `r0 + q r1` (`q = b^c <= 2^16`).
    ///
    /// On 64-bit targets with `q <= 256`, in one division: `phi_b(i) = X / q^2` with
    /// `X = rev(r0) q + rev(r1) < q^2`, and the multiply-high of `X 2^32` by
    /// `ceil(2^64 / q^2) = (2^64 + e) / q^2` (`e < q^2`) errs by less than `q^2 / 2^32 <=
    /// 1 / q^2`, the smallest gap from `X 2^32 / q^2` up to an integer, so the floor is
    /// exact. Otherwise two nested floors.
    #[inline(always)]
    pub(super) const fn two_chunks(&self, r0: u32, r1: u32) -> u32 {
        #[cfg(target_pointer_width = "64")]
        if self.chunk <= 256 {
            let x = self.reverse_chunk(r0) * self.chunk + self.reverse_chunk(r1);
            return mul_hi_64(self.power_magic[0], (x as u64) << 32);
        }
        self.nest(r0, self.nest(r1, 0)) as u32
    }

    /// `floor(phi_b(i) 2^32)` for an index of three chunks `r0 + q r1 + q^2 r2`
    /// (`q = b^c <= 2^16`): as [`two_chunks`](Self::two_chunks) with `X < q^3` over `q^3`,
    /// exact for `q^6 <= 2^32`, i.e. `q <= 40` (on 64-bit targets); otherwise nested floors.
    #[inline(always)]
    pub(super) const fn three_chunks(&self, r0: u32, r1: u32, r2: u32) -> u32 {
        #[cfg(target_pointer_width = "64")]
        if self.chunk <= 40 {
            let q = self.chunk;
            let x =
                (self.reverse_chunk(r0) * q + self.reverse_chunk(r1)) * q + self.reverse_chunk(r2);
            return mul_hi_64(self.power_magic[1], (x as u64) << 32);
        }
        self.nest(r0, self.nest(r1, self.nest(r2, 0))) as u32
    }

    /// [`sample`](Self::sample) for indices of four or more chunks, and for all indices
    /// when `b^c > 2^16`: the exact numerator, then one scaling. Inline on 64-bit targets
    /// (the branch-free wide numerator overlaps neighbouring calls' work); out of line on
    /// 32-bit ones, where flash is dear and the serial numerator serves.
    #[cfg_attr(target_pointer_width = "64", inline(always))]
    #[cfg_attr(not(target_pointer_width = "64"), inline(never))]
    pub(super) const fn sample_long(&self, index: u32) -> u32 {
        self.scale(self.numerator(index)).0
    }

    /// `(n / b^c, n mod b^c)` by a multiply-high (exact for every `u32` `n`).
    #[inline(always)]
    pub(super) const fn peel(&self, n: u32) -> (u32, u32) {
        let q = ((self.chunk_magic as u128 * n as u128) >> 64) as u32;
        (q, n - q * self.chunk)
    }

    /// One nested-floor step `floor((rev(r) 2^32 + f) / b^c)` for a chunk `r < b^c`,
    /// `f < 2^32` and `b^c <= 2^16`.
    ///
    /// With the index's chunks `C_0, ..., C_m` (`c` digits each, lowest first) and `rev` the
    /// `c`-digit reversal, `phi_b(i) = (rev(C_0) + (rev(C_1) + ... ) / b^c) / b^c`, and
    /// because `floor((a + floor(y)) / q) = floor((a + y) / q)` for integers `a`, `q > 0`,
    ///
    /// ```text
    /// F_m = floor(rev(C_m) 2^32 / b^c),   F_j = floor((rev(C_j) 2^32 + F_(j+1)) / b^c),
    /// floor(phi_b(i) 2^32) = F_0.
    /// ```
    ///
    /// Each step divides `t = rev 2^32 + F < b^c 2^32` by `b^c` with one multiply-high by
    /// `ceil(2^64 / b^c) = (2^64 + e) / b^c`, `0 <= e < b^c`: the error `t e / (b^c 2^64)` is
    /// below `1 / b^c` (the smallest gap from `t / b^c` up to an integer) as `b^c <= 2^16`, so
    /// the floor is exact. No final scaling is needed.
    #[inline(always)]
    pub(super) const fn nest(&self, r: u32, f: u64) -> u64 {
        let t = ((self.reverse_chunk(r) as u64) << 32) | f;
        ((self.chunk_magic as u128 * t as u128) >> 64) as u64
    }

    /// The `c`-digit reversal of a chunk `r < b^c` (the chunk itself when `c = 1`).
    #[inline(always)]
    pub(super) const fn reverse_chunk(&self, r: u32) -> u32 {
        if self.table == 0 {
            return r;
        }
        reverse_in(self.reversal_table(), r)
    }

    /// This base's digit-reversal table (empty when `c = 1`).
    #[inline(always)]
    pub(super) const fn reversal_table(&self) -> &'static [u8] {
        // Guarded indexing (no panic path): an unknown id means no table.
        let id = self.table as usize;
        if id < REVERSAL.len() {
            REVERSAL[id]
        } else {
            &[]
        }
    }

    /// `floor(phi'_b(index) 2^32)` for the digit-scrambled radical inverse
    /// `phi'_b(i) = sum_(j=1..K) sigma_j(d_j) b^-j` (see [`DigitScramble`]), exact for that
    /// `K`-digit sum. `dim` keys the random permutations. `const`.
    ///
    /// Cost: `K` digit steps (all digit places, since scrambled leading zeros are not zero),
    /// each a division and, for the random kinds, a keyed permutation.
    ///
    /// ```
    /// use qmckit::RadicalInverse;
    /// use qmckit::randomize::digits::DigitScramble;
    /// let phi5 = RadicalInverse::new(5)?;
    /// assert_eq!(phi5.sample_scrambled(123, &DigitScramble::None, 0), phi5.sample(123));
    /// // Faure's sigma_5 = (0, 3, 2, 1, 4): phi'_5(1) = 3/5.
    /// assert_eq!(phi5.sample_scrambled(1, &DigitScramble::Faure, 0) as u64, (3u64 << 32) / 5);
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub const fn sample_scrambled(&self, index: u32, scramble: &DigitScramble, dim: usize) -> u32 {
        if scramble.is_none() {
            return self.sample(index);
        }
        self.scale(self.exact_scrambled(index, scramble, dim)).0
    }

    /// The exact numerator `N` of the (scrambled) radical inverse over
    /// [`denominator`](Self::denominator): `phi'_b(index) = N / B`. For users who need the
    /// value beyond 32 bits (e.g. an `f64` with 53) or exact arithmetic.
    ///
    /// ```
    /// use qmckit::{RadicalInverse, randomize::digits::DigitScramble};
    /// let phi3 = RadicalInverse::new(3)?;
    /// let n = phi3.exact_scrambled(1000, &DigitScramble::None, 0);
    /// assert_eq!(n as u128 * 2187, 760 * phi3.denominator() as u128); // 760/2187
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub const fn exact_scrambled(&self, index: u32, scramble: &DigitScramble, dim: usize) -> u64 {
        if scramble.is_none() {
            return self.numerator(index);
        }
        let b = self.base as u64;
        let mut n = index as u64;
        let mut weight = div_u64(self.big, b); // b^(K-1)
        let (mut prefix, mut place) = (0u64, 1u64); // index mod b^(j-1), and b^(j-1)
        let mut acc = 0u64;
        let mut j = 1;
        while j <= self.digits as u32 {
            let d = rem_u64(n, b) as u32;
            n = div_u64(n, b);
            let s = scramble.digit(self.base, dim, j, prefix, d);
            acc += s as u64 * weight; // < B
            prefix += d as u64 * place;
            place = place.wrapping_mul(b);
            weight = div_u64(weight, b);
            j += 1;
        }
        acc
    }

    /// `B = b^K`, the denominator of [`exact_scrambled`](Self::exact_scrambled).
    pub const fn denominator(&self) -> u64 {
        self.big
    }

    /// `N` with `phi_b(index) = N / B`: the digits of `index` reversed into `K` places.
    /// 64-bit targets build it from all chunk quotients at once (for at most `WIDE` chunks,
    /// every prime base); 32-bit targets (microcontrollers without a 64-bit multiplier,
    /// where that code would cost a kilobyte of flash) chunk by chunk. Same value.
    #[inline(always)]
    pub(super) const fn numerator(&self, index: u32) -> u64 {
        #[cfg(target_pointer_width = "64")]
        if self.weight[0] != 0 {
            return self.numerator_wide(index);
        }
        self.numerator_serial(index)
    }

    /// [`numerator`](Self::numerator) with all chunk quotients at once, for `m <= WIDE`
    /// chunks of `c` digits (`q = b^c`, `W_j = q^(m-1-j)`).
    ///
    /// The quotients `Q_j = floor(n / q^j)` do not wait on each other: `Q_1 .. Q_4` are one
    /// multiply-high of `n` each, `Q_5 .. Q_7` one of `Q_4` (`floor(floor(n/a)/b) =
    /// floor(n/(ab))`); each magic `ceil(2^64/d)` is exact for numerators below 2^32 and
    /// `d < 2^32`, and is 0 where `q^j >= 2^32` (then `Q_j = 0` indeed). Chunk `j` is
    /// `Q_j - q Q_(j+1)`, so
    ///
    /// ```text
    /// N = sum_(j<6) rev(Q_j - q Q_(j+1)) W_j                   (reversal table, c > 1)
    /// N = W_0 n - (b^2 - 1) sum_(j>=1) W_j Q_j  (mod 2^64)    (c = 1, rev = identity)
    /// ```
    ///
    /// the second because `b W_j = W_(j-1)`, so in `sum_j (Q_j - b Q_(j+1)) W_j` the
    /// coefficient of `Q_j` (`j >= 1`) is `W_j - W_(j-2) = (1 - b^2) W_j` (`W_(-1) = b^m`).
    /// Wrapping arithmetic is exact as `N < 2^64`. Cost: 7 multiply-highs
    /// and 8 (c = 1) or 12 (tabled) multiplications, no loop and one branch (table or
    /// not), so the work of one index overlaps the next one's.
    #[cfg(target_pointer_width = "64")]
    #[inline(always)]
    pub(super) const fn numerator_wide(&self, n: u32) -> u64 {
        let [m2, m3, m4] = self.power_magic;
        let q1 = mul_hi(self.chunk_magic, n);
        let q2 = mul_hi(m2, n);
        let q3 = mul_hi(m3, n);
        let q4 = mul_hi(m4, n);
        let q5 = mul_hi(self.chunk_magic, q4);
        let q6 = mul_hi(m2, q4);
        let q7 = mul_hi(m3, q4);
        let w = &self.weight;
        if self.table == 0 {
            let s = (w[1] as u64 * q1 as u64)
                .wrapping_add(w[2] as u64 * q2 as u64)
                .wrapping_add(w[3] as u64 * q3 as u64)
                .wrapping_add(w[4] as u64 * q4 as u64)
                .wrapping_add(w[5] as u64 * q5 as u64)
                .wrapping_add(w[6] as u64 * q6 as u64)
                .wrapping_add(w[7] as u64 * q7 as u64);
            let b = self.base as u64;
            return (w[0] as u64 * n as u64).wrapping_sub((b * b - 1).wrapping_mul(s));
        }
        // The tabled bases have at most 6 chunks (49^6 >= 2^32 for base 7; 5 for the
        // others): chunks 6 and 7 are zero.
        let (t, q) = (self.reversal_table(), self.chunk);
        rev_weighted(t, q, q1, n, w[0])
            + rev_weighted(t, q, q2, q1, w[1])
            + rev_weighted(t, q, q3, q2, w[2])
            + rev_weighted(t, q, q4, q3, w[3])
            + rev_weighted(t, q, q5, q4, w[4])
            + rev_weighted(t, q, q6, q5, w[5])
    }

    /// [`numerator`](Self::numerator) chunk by chunk (on 64-bit targets only for the bases
    /// with more than `WIDE` chunks, the composites 4 to 15): each chunk weighted by
    /// `b^(K-c)`, `b^(K-2c)`, ..., the weight stepped down by the inverse of `b^c` modulo
    /// 2^64 (an exact division). Four multiplications a chunk, each waiting on the last.
    #[inline(never)]
    pub(super) const fn numerator_serial(&self, index: u32) -> u64 {
        #[cfg(target_pointer_width = "64")]
        let inv = inverse_mod_2_64((self.chunk >> self.chunk_shift) as u64);
        #[cfg(not(target_pointer_width = "64"))]
        let inv = self.chunk_inv;
        let shift = self.chunk_shift;
        let (mut n, mut acc) = (index, 0u64);
        let mut weight = (self.big >> shift).wrapping_mul(inv); // b^(K-c)
        let table = self.reversal_table(); // looked up once, not per chunk
        loop {
            let (q, r) = self.peel(n);
            // The chunk's c digits reversed (with c = 1 there is no table: r itself).
            acc += reverse_in(table, r) as u64 * weight; // sum < B: no overflow
            if q == 0 {
                return acc;
            }
            weight = (weight >> shift).wrapping_mul(inv); // exact: weight / b^c
            n = q;
        }
    }

    /// `(q, r)` with `n * 2^32 = q * B + r`, `0 <= r < B`, for `n < B` (so `q < 2^32`).
    #[inline]
    pub(super) const fn scale(&self, n: u64) -> (u32, u64) {
        // q0 <= q and q0 > n 2^32 / B - 1, so q is q0 or q0 + 1.
        let q0 = ((n as u128 * self.recip as u128) >> 64) as u64;
        if self.big <= 1 << 63 {
            // r0 = n 2^32 - q0 B lies in [0, 2B) within 2^64: wrapping arithmetic is exact.
            let r0 = (n << 32).wrapping_sub(q0.wrapping_mul(self.big));
            if r0 >= self.big {
                ((q0 + 1) as u32, r0 - self.big)
            } else {
                (q0 as u32, r0)
            }
        } else {
            let r0 = ((n as u128) << 32) - q0 as u128 * self.big as u128;
            if r0 >= self.big as u128 {
                ((q0 + 1) as u32, (r0 - self.big as u128) as u64)
            } else {
                (q0 as u32, r0 as u64)
            }
        }
    }

    /// `2^32 b^-j` modulo 2^32 as `(q, r)` over `B`, for `1 <= j <= K`.
    pub(super) const fn power(&self, j: u32) -> (u32, u64) {
        let inv = inverse_mod_2_64((self.base >> self.base.trailing_zeros()) as u64);
        let shift = self.base.trailing_zeros();
        let mut w = self.big;
        let mut k = 0;
        while k < j {
            w = (w >> shift).wrapping_mul(inv); // exact: b^(K-k) / b
            k += 1;
        }
        self.scale(w)
    }

    /// The exact change of `phi_b(i) * 2^32` (mod 2^32) from `i` to `i + 1` when `i + 1` ends
    /// in `t` zero digits: `2^32 (b^-t + b^-(t+1))` mod 2^32, for `t < K`.
    pub(super) const fn step(&self, t: u32) -> (u32, u64) {
        let hi = self.power(t + 1);
        if t == 0 {
            return hi;
        }
        add_exact(hi, self.power(t), self.big)
    }

    /// The steps for `t = 0 .. STEPS` (those with `t < K`).
    pub(super) const fn steps(&self) -> [(u32, u64); STEPS] {
        let mut steps = [(0u32, 0u64); STEPS];
        if self.base != 2 {
            let mut t = 0;
            while t < STEPS {
                if (t as u32) < self.digits as u32 {
                    steps[t] = self.step(t as u32);
                }
                t += 1;
            }
        }
        steps
    }

    /// Number of trailing zero base-`b` digits of `m > 0`.
    pub(super) const fn trailing_zero_digits(&self, mut m: u32) -> u32 {
        let mut t = 0;
        while m != 0 && rem_u32(m, self.base) == 0 {
            m = div_u32(m, self.base);
            t += 1;
        }
        t
    }

    /// Inverse of [`sample`](Self::sample) on indices with at most `digits` base-`b` digits:
    /// the `i < b^digits` whose radical inverse rounds down to `value`.
    ///
    /// For a `value` that is not such an output, returns the `i < b^digits` with the
    /// smallest `phi_b(i) >= value / 2^32` (modulo `b^digits`). Cost: `digits` divisions.
    ///
    /// # Errors
    /// [`Error::TooManyDigits`] when `b^digits > 2^32` (outputs of longer indices can
    /// collide in 32 bits, so they cannot be inverted).
    pub const fn inverse(&self, value: u32, digits: u32) -> Result<u32> {
        let b = self.base as u64;
        let mut bk = 1u64;
        let mut k = 0;
        while k < digits {
            bk *= b;
            k += 1;
            if bk > TWO_32 {
                // The largest m with b^m <= 2^32 is k - 1.
                return Err(Error::TooManyDigits { digits, max: k - 1 });
            }
        }
        // value = floor(a 2^32 / b^k) for the reversed-digit integer a, so
        // a = ceil(value b^k / 2^32); value * b^k + 2^32 - 1 < 2^64.
        let mut a = rem_u64((value as u64 * bk + (TWO_32 - 1)) >> 32, bk);
        let mut index = 0u64;
        k = 0;
        while k < digits {
            index = index * b + rem_u64(a, b);
            a = div_u64(a, b);
            k += 1;
        }
        Ok(index as u32)
    }
}
