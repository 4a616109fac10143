//! Error-free transformations, compensated sums, a minimal double-double ([`Dd`]) and a
//! double-double with a separate binary exponent ([`Wide`]) for values far outside the
//! range of `f64`.

use crate::{Error, Result};

/// `a + b = s + e` exactly (Knuth's TwoSum).
#[inline]
pub(super) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Splits `a` into two 26-bit halves (Veltkamp). Exact for `|a| < 2^996`.
#[inline]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let t = SPLITTER * a;
    let hi = t - (t - a);
    (hi, a - hi)
}

/// `a * b = p + e` exactly (Dekker), without relying on a hardware FMA. Exact when `a`
/// and `b` are below `2^996` and `a b` neither overflows nor underflows.
#[inline]
pub(super) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// A Neumaier (improved Kahan–Babuška) running sum: `s + c` carries the sum of the inputs
/// with an error of about one rounding of the result plus `n eps^2 sum |x|`.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Acc {
    pub(super) s: f64,
    pub(super) c: f64,
}

impl Acc {
    #[inline]
    pub(super) fn add(&mut self, x: f64) {
        let t = self.s + x;
        if self.s.abs() >= x.abs() {
            self.c += (self.s - t) + x;
        } else {
            self.c += (x - t) + self.s;
        }
        self.s = t;
    }

    /// Adds another accumulator (both of its parts).
    pub(super) fn merge(&mut self, other: Acc) {
        self.add(other.s);
        self.add(other.c);
    }

    pub(super) fn dd(self) -> Dd {
        Dd::from_sum(self.s, self.c)
    }
}

/// An unevaluated sum `hi + lo` with `|lo| <= ulp(hi) / 2`: about 106 bits.
#[derive(Clone, Copy, Debug)]
pub(super) struct Dd {
    pub(super) hi: f64,
    pub(super) lo: f64,
}

impl Dd {
    pub(super) const ONE: Dd = Dd { hi: 1.0, lo: 0.0 };

    pub(super) fn from_sum(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_sum(a, b);
        Dd { hi, lo }
    }

    /// `p / q` for numbers that `f64` holds exactly, to double-double precision.
    pub(super) fn ratio(p: f64, q: f64) -> Dd {
        let hi = p / q;
        let (m, e) = two_prod(hi, q);
        // p - hi q is exact (remainder of a correctly rounded quotient).
        let r = (p - m) - e;
        Dd::from_sum(hi, r / q)
    }

    pub(super) fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        Dd::from_sum(s, e + self.lo + o.lo)
    }

    pub(super) fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    pub(super) fn mul(self, o: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, o.hi);
        Dd::from_sum(p, e + self.hi * o.lo + self.lo * o.hi)
    }

    pub(super) fn scale(self, k: f64) -> Dd {
        let (p, e) = two_prod(self.hi, k);
        Dd::from_sum(p, e + self.lo * k)
    }

    pub(super) fn div(self, q: f64) -> Dd {
        let hi = self.hi / q;
        let (p, e) = two_prod(hi, q);
        let r = ((self.hi - p) - e + self.lo) / q;
        Dd::from_sum(hi, r)
    }

    /// `self^d` by repeated squaring.
    pub(super) fn powi(self, mut d: usize) -> Dd {
        let mut base = self;
        let mut acc = Dd::ONE;
        while d > 0 {
            if d & 1 == 1 {
                acc = acc.mul(base);
            }
            base = base.mul(base);
            d >>= 1;
        }
        acc
    }

    pub(super) fn value(self) -> f64 {
        self.hi + self.lo
    }

    /// Both parts times `2^k` (exact unless a part leaves the normal range).
    fn ldexp(self, k: i64) -> Dd {
        Dd {
            hi: ldexp(self.hi, k),
            lo: ldexp(self.lo, k),
        }
    }
}

/// `2^k` for `-1022 <= k <= 1023`, from its bits.
#[inline(always)]
pub(super) fn pow2i(k: i64) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// `x 2^k`, in steps that stay in the normal range (exact unless the result leaves it).
pub(super) fn ldexp(mut x: f64, mut k: i64) -> f64 {
    while k > 1000 {
        x *= pow2i(1000);
        k -= 1000;
    }
    while k < -1000 {
        x *= pow2i(-1000);
        k += 1000;
        if x == 0.0 {
            return x;
        }
    }
    x * pow2i(k)
}

/// `(m, e)` with `x = m 2^e` and `1 <= |m| < 2`, or `(0, 0)` for zero. `x` finite.
pub(super) fn frexp(x: f64) -> (f64, i64) {
    if x == 0.0 {
        return (x, 0);
    }
    let (x, bias) = if x.abs() < f64::MIN_POSITIVE {
        (x * pow2i(64), -64)
    } else {
        (x, 0)
    };
    let bits = x.to_bits();
    let ex = ((bits >> 52) & 0x7ff) as i64;
    let m = f64::from_bits((bits & !(0x7ff << 52)) | (1023 << 52));
    (m, ex - 1023 + bias)
}

/// `sum_i m_i 2^(e_i)` for terms `(m_i, e_i)` with `1 <= |m_i| < 2` or `m_i = 0`: the terms
/// are scaled by the largest exponent and added with compensation; a term below `2^-1074`
/// times the largest is dropped.
pub(super) fn wide_sum(terms: &[(f64, i64)]) -> Wide {
    let top = terms
        .iter()
        .filter(|t| t.0 != 0.0)
        .map(|t| t.1)
        .max()
        .unwrap_or(0);
    let mut acc = Acc::default();
    for &(m, e) in terms {
        if m != 0.0 {
            acc.add(ldexp(m, (e - top).max(-1100)));
        }
    }
    Wide::new(acc.dd(), top)
}

/// The product of `factors` as `(m, e)`, `1 <= |m| < 2` or `m = 0`, renormalized after
/// every factor (so no partial product leaves the range of `f64` whatever `d` is).
pub(super) fn wide_product(factors: impl Iterator<Item = f64>) -> (f64, i64) {
    let (mut m, mut e) = (1.0, 0i64);
    for f in factors {
        let (fm, fe) = frexp(f);
        let (pm, pe) = frexp(m * fm);
        m = pm;
        e += fe + pe;
        if m == 0.0 {
            return (0.0, 0);
        }
    }
    (m, e)
}

/// A double-double times a power of two, `v 2^e` with `1 <= |v.hi| < 2` (or `v = 0`,
/// `e = 0`): about 106 bits of precision and a 64-bit exponent, for the constants, sums
/// and results of the L2 measures in dimensions where they leave the range of `f64` (e.g.
/// `(3/2)^4000`). Cost: a few `Dd` operations per operation.
#[derive(Clone, Copy, Debug)]
pub(super) struct Wide {
    v: Dd,
    e: i64,
}

impl Wide {
    pub(super) const ZERO: Wide = Wide {
        v: Dd { hi: 0.0, lo: 0.0 },
        e: 0,
    };

    pub(super) const ONE: Wide = Wide { v: Dd::ONE, e: 0 };

    pub(super) const TWO: Wide = Wide { v: Dd::ONE, e: 1 };

    /// `v 2^e`, normalized. `v` finite.
    pub(super) fn new(v: Dd, e: i64) -> Wide {
        if v.hi == 0.0 {
            return Wide::ZERO;
        }
        let (_, k) = frexp(v.hi);
        Wide {
            v: v.ldexp(-k),
            e: e + k,
        }
    }

    #[cfg(test)]
    pub(super) fn from_f64(x: f64) -> Wide {
        Wide::new(Dd { hi: x, lo: 0.0 }, 0)
    }

    /// `2^k`.
    pub(super) fn pow2(k: i64) -> Wide {
        Wide { v: Dd::ONE, e: k }
    }

    /// `p / q` for numbers that `f64` holds exactly.
    pub(super) fn ratio(p: f64, q: f64) -> Wide {
        Wide::new(Dd::ratio(p, q), 0)
    }

    pub(super) fn from_dd(v: Dd) -> Wide {
        Wide::new(v, 0)
    }

    pub(super) fn neg(self) -> Wide {
        Wide {
            v: self.v.neg(),
            e: self.e,
        }
    }

    pub(super) fn mul(self, o: Wide) -> Wide {
        Wide::new(self.v.mul(o.v), self.e + o.e)
    }

    pub(super) fn add(self, o: Wide) -> Wide {
        if o.v.hi == 0.0 {
            return self;
        }
        if self.v.hi == 0.0 {
            return o;
        }
        let (big, small) = if self.e >= o.e { (self, o) } else { (o, self) };
        let k = small.e - big.e;
        if k < -1100 {
            return big;
        }
        Wide::new(big.v.add(small.v.ldexp(k)), big.e)
    }

    /// `self / n` for a positive count `n`.
    pub(super) fn div_count(self, n: usize) -> Wide {
        Wide::new(self.v.div(n as f64), self.e)
    }

    /// `self / o` (`o` nonzero), to about `f64` precision.
    pub(super) fn div(self, o: Wide) -> Wide {
        Wide::new(self.v.div(o.v.value()), self.e - o.e)
    }

    /// `self^d` by repeated squaring.
    pub(super) fn powi(self, mut d: usize) -> Wide {
        let mut base = self;
        let mut acc = Wide::pow2(0);
        while d > 0 {
            if d & 1 == 1 {
                acc = acc.mul(base);
            }
            base = base.mul(base);
            d >>= 1;
        }
        acc
    }

    /// The square root, a negative value (a rounded zero) clamped to zero.
    pub(super) fn sqrt(self) -> Wide {
        if self.v.hi <= 0.0 {
            return Wide::ZERO;
        }
        let odd = self.e.rem_euclid(2);
        let m = ldexp(self.v.value(), odd).sqrt();
        Wide::new(Dd { hi: m, lo: 0.0 }, (self.e - odd) / 2)
    }

    /// The value as a normal `f64` (or zero).
    ///
    /// # Errors
    /// [`Error::NotRepresentable`] naming `what` when the value is nonzero and its
    /// magnitude is above `f64::MAX` or below the smallest normal `f64`, `2^-1022`.
    pub(super) fn to_f64(self, what: &'static str) -> Result<f64> {
        let (m, k) = frexp(self.v.value());
        if m == 0.0 {
            return Ok(0.0);
        }
        let e = self.e + k;
        if !(-1022..=1023).contains(&e) {
            return Err(Error::NotRepresentable { what });
        }
        Ok(m * pow2i(e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dd_constants() {
        // (4/3)^2 = 16/9 to double-double: hi + lo carries more than 53 bits.
        let c = Dd::ratio(4.0, 3.0).powi(2);
        assert_eq!(c.hi, 16.0 / 9.0);
        let third = Dd::ratio(1.0, 3.0);
        // 3 * (1/3) = 1 to about 2^-106.
        let one = third.scale(3.0).add(Dd { hi: -1.0, lo: 0.0 });
        assert!(one.value().abs() < 1e-30);
    }

    #[test]
    fn two_prod_exact() {
        let (p, e) = two_prod(0.1, 0.7);
        assert_eq!(p, 0.1 * 0.7);
        assert!(e != 0.0 && e.abs() < 1e-17);
    }

    #[test]
    fn compensated_sum_beats_plain() {
        let mut acc = Acc::default();
        acc.add(1.0);
        for _ in 0..10 {
            acc.add(1e-17);
        }
        acc.add(-1.0);
        assert!((acc.dd().value() - 1e-16).abs() < 1e-30);
    }

    #[test]
    fn wide_powers_leave_and_reenter_the_f64_range() {
        // (3/2)^4000 / (3/2)^3990 = (3/2)^10 although both overflow f64.
        let a = Wide::ratio(3.0, 2.0).powi(4000);
        assert!(a.to_f64("x").is_err());
        let b = Wide::ratio(3.0, 2.0).powi(3990);
        let q = a.div(b).to_f64("x").unwrap();
        assert!((q - 1.5f64.powi(10)).abs() <= 1e-13 * q);
        // 3^-700 underflows; its square root 3^-350 does not.
        let t = Wide::ratio(1.0, 3.0).powi(700);
        assert!(t.to_f64("x").is_err());
        let r = t.sqrt().to_f64("x").unwrap();
        assert!((r - 3f64.powi(-350)).abs() <= 1e-13 * r);
        // x - x = 0, and a sum of very different magnitudes keeps the larger.
        assert_eq!(a.add(a.neg()).to_f64("x"), Ok(0.0));
        let s = Wide::from_f64(1.0).add(Wide::pow2(-2000)).to_f64("x");
        assert_eq!(s, Ok(1.0));
        assert_eq!(Wide::pow2(-1022).to_f64("x"), Ok(f64::MIN_POSITIVE));
        assert!(Wide::pow2(-1023).to_f64("x").is_err());
        assert_eq!(Wide::pow2(1023).to_f64("x"), Ok(2f64.powi(1023)));
        assert!(Wide::pow2(1024).to_f64("x").is_err());
    }

    #[test]
    fn wide_products_and_sums_are_exact_for_powers_of_two() {
        let (m, e) = wide_product(std::iter::repeat_n(0.5, 3000));
        assert_eq!((m, e), (1.0, -3000));
        let (m, e) = wide_product([3.0, 0.0, 5.0].into_iter());
        assert_eq!((m, e), (0.0, 0));
        let (m, e) = wide_product([-3.0, 5e-324].into_iter());
        assert_eq!((m, e), (-1.5, -1073));
        let s = wide_sum(&[(1.0, -3000), (1.0, -3000), (0.0, 0), (1.5, -3001)]);
        assert_eq!(s.e, -2999);
        assert_eq!(s.v.value(), 1.375);
        assert_eq!(frexp(5e-324), (1.0, -1074));
        assert_eq!(ldexp(1.0, -1074), 5e-324);
        assert_eq!(ldexp(1.0, 2000), f64::INFINITY);
    }
}
