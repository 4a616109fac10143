//! The quality parameter `t` of nets: exactly, from base-2 generator matrices (the rank
//! test, [`crate::digital::rank`], on a [`crate::digital::DigitalNet2`]), or from the points
//! themselves (counting points in elementary intervals, here).
//!
//! # Definitions
//!
//! An *elementary interval* in base `b` of shape `(d_1, .., d_s)` is a box
//!
//! ```text
//! E = prod_j [a_j b^-d_j, (a_j + 1) b^-d_j),    0 <= a_j < b^d_j,
//! ```
//!
//! of volume `b^-(d_1 + .. + d_s)`. A set of `N = b^m` points in `[0, 1)^s` is a
//! *(t, m, s)-net in base b* (Niederreiter 1987) when every elementary interval of volume
//! `b^(t - m)` holds exactly `b^t` points, i.e. for every shape with `d_1 + .. + d_s = m - t`.
//! A (t, m, s)-net is also a (t + 1, m, s)-net (each interval of volume `b^(t + 1 - m)` is a
//! disjoint union of `b` intervals of volume `b^(t - m)`), so the *t-value* of a set, the
//! smallest such `t`, is well defined (`t <= m` always holds: the unit cube holds all
//! points). `t = 0` is the best possible: every box of volume `1/N` holds one point.
//!
//! # The rank test (base 2)
//!
//! A *digital net* in base 2 has one generator matrix `C_j` over GF(2) per dimension; point
//! `i = sum_k i_k 2^k` has coordinates `x_j(i) = sum_r y_(j,r) 2^-(r+1)` with
//! `y_j = C_j (i_0, i_1, .., i_(m-1))^T`. It is a (t, m, s)-net if and only if, for every
//! shape with `d_1 + .. + d_s = m - t`, the `m - t` rows formed by the first `d_j` rows of
//! each `C_j` (restricted to the first `m` columns) are linearly independent over GF(2)
//! (Niederreiter 1992, Lemma 4.52; Pirsic & Schmid 2001, "Calculation of the quality
//! parameter of digital nets and application to their construction", J. Complexity 17).
//! [`crate::digital::rank::t_value`] searches shapes depth-first with incremental Gaussian
//! elimination (shapes that share a prefix share the elimination) for the smallest
//! *dependent* shape; its size is `m - t + 1`. It is pure linear algebra over GF(2), so it
//! lives with the constructions, in [`crate::digital`], and needs no `analysis`; the
//! matrix conventions are those of [`crate::digital::DigitalNet2`].
//!
//! # Counting (any base, any point set)
//!
//! [`t_value_u32`] (base 2, 0.32 fractions, exact) and [`t_value_points`] (base `b`, `f64`)
//! find the largest `rho` such that every shape of size `rho` is balanced (every cell holds
//! `b^(m - rho)` points) by a binary search on `rho` (balance at `rho` implies balance below
//! it), then `t = m - rho`. [`elementary_interval_failures_u32`] and
//! [`elementary_interval_failures`] name the intervals that break a given `t`.
//! [`t_value_block`] counts a block of `b^m` points of a base-`b` digital sequence
//! ([`crate::digital::DigitalNetB`]) from its exact coordinates.

mod block;
mod cost;
mod count;

pub use block::t_value_block;
pub use cost::{
    COUNT_RATE, COUNTS_CACHE_BYTES, INCREMENT_MISS, OTHER_BASE_FACTOR, UNBALANCED_SHARE,
    count_steps, failures_cost, level_steps, t_value_cost,
};
pub use count::{
    IntervalFailure, elementary_interval_failures, elementary_interval_failures_u32,
    t_value_points, t_value_u32, t_value_u32_expecting,
};

#[cfg(test)]
mod tests {
    use super::count::{exact_floor_mul, first_parts, for_each_shape};
    use super::*;
    use crate::Error;
    use crate::analysis::Points;

    #[test]
    fn compositions_are_all_enumerated_once() {
        for dims in 1..=4usize {
            for rho in 0..=6u32 {
                let mut seen = Vec::new();
                for d0 in first_parts(dims, rho) {
                    for_each_shape(dims, rho, d0, |s| {
                        assert_eq!(s.iter().sum::<u32>(), rho);
                        seen.push(s.to_vec());
                        true
                    });
                }
                let n = seen.len();
                seen.sort();
                seen.dedup();
                assert_eq!(seen.len(), n);
                // C(rho + dims - 1, dims - 1)
                let mut c = 1u64;
                for i in 0..(dims as u64 - 1) {
                    c = c * (u64::from(rho) + 1 + i) / (i + 1);
                }
                assert_eq!(n as u64, c, "dims {dims} rho {rho}");
            }
        }
    }

    #[test]
    fn exact_floor_corrects_rounding() {
        // 0.1 * 10 rounds to 1.0, but the stored 0.1 is above 1/10: floor is 1.
        assert_eq!(exact_floor_mul(0.1, 10.0), 1.0);
        // The double just below 1/3 times 3 rounds to 1.0; the real product is below 1.
        let x = 1.0f64 / 3.0; // below 1/3
        assert_eq!(exact_floor_mul(x, 3.0), 0.0);
        assert_eq!(exact_floor_mul(0.5, 8.0), 4.0);
    }

    #[test]
    fn validation() {
        assert!(t_value_u32(&[0; 3], 1, 2, &crate::work::Budget::DEFAULT).is_err());
        assert!(t_value_u32(&[0; 4], 0, 2, &crate::work::Budget::DEFAULT).is_err());
        let p = [0.5; 4];
        let pts = Points::new(&p, 1).unwrap();
        assert_eq!(
            t_value_points(pts, 1, 2, &crate::work::Budget::DEFAULT),
            Err(Error::BaseTooSmall { base: 1 })
        );
        assert!(t_value_points(pts, 3, 2, &crate::work::Budget::DEFAULT).is_err());
        let one = [0.0, 1.0];
        assert!(
            t_value_points(
                Points::new(&one, 1).unwrap(),
                2,
                1,
                &crate::work::Budget::DEFAULT
            )
            .is_err()
        );
    }
}
