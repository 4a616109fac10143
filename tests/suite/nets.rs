//! Net properties and exact star discrepancies from the literature.

use crate::common;

use common::{first_net_failure, points_2d, star_discrepancy_2d_exact};
use qmckit::{Hammersley, LarcherPillichshammer};

#[test]
fn lp_is_a_0m2_net_for_m_1_to_16() {
    for m in 1..=16 {
        let lp = LarcherPillichshammer::new(m).unwrap();
        let pts = points_2d(&lp, 1 << m, (0, 1));
        assert_eq!(first_net_failure(&pts, m), None, "LP m = {m}");
    }
}

#[test]
fn hammersley_is_a_0m2_net_for_m_1_to_16() {
    for m in 1..=16 {
        let h = Hammersley::with_m(m, 2).unwrap();
        let pts = points_2d(&h, 1 << m, (0, 1));
        assert_eq!(first_net_failure(&pts, m), None, "Hammersley m = {m}");
    }
}

#[test]
fn the_net_checker_can_fail() {
    // Hammersley's (x, phi_3) projection is not a base-2 net.
    let h = Hammersley::with_m(6, 3).unwrap();
    assert!(first_net_failure(&points_2d(&h, 64, (0, 2)), 6).is_some());
    // Two copies of the first half of a net: the second half is missing.
    let lp = LarcherPillichshammer::new(4).unwrap();
    let mut pts = points_2d(&lp, 16, (0, 1));
    let first: Vec<[u32; 2]> = pts[..8].to_vec();
    pts[8..].copy_from_slice(&first);
    assert!(first_net_failure(&pts, 4).is_some());
}

#[test]
fn lp_star_discrepancy_matches_the_published_values() {
    // D* of the LP net for m = 2..6 (0.041 for 64 points).
    let want = [
        (2, 7, 16),
        (3, 1, 4),
        (4, 9, 64),
        (5, 19, 256),
        (6, 21, 512),
    ];
    for (m, num, den) in want {
        let lp = LarcherPillichshammer::new(m).unwrap();
        let (d, scale) = star_discrepancy_2d_exact(&points_2d(&lp, 1 << m, (0, 1)));
        assert_eq!(d * den, num * scale, "LP m = {m}");
    }
}

#[test]
fn hammersley_star_discrepancy_matches_de_clercks_formula() {
    // N D* = m/3 + 13/9 - (-1)^m 4 / (9 2^m), i.e. 9 2^m N D* = (3m + 13) 2^m - (-1)^m 4,
    // for m >= 2 (at m = 1 it would give D* = 1; the two points (0,0), (1/2,1/2) have 3/4).
    let h = Hammersley::with_m(1, 2).unwrap();
    let (d, scale) = star_discrepancy_2d_exact(&points_2d(&h, 2, (0, 1)));
    assert_eq!(4 * d, 3 * scale);
    for m in 2..=8u32 {
        let h = Hammersley::with_m(m, 2).unwrap();
        let (d, scale) = star_discrepancy_2d_exact(&points_2d(&h, 1 << m, (0, 1)));
        let n = 1i128 << m;
        let sign = if m % 2 == 0 { 1 } else { -1 };
        let rhs = (3 * m as i128 + 13) * n - sign * 4;
        // D* = d / scale and scale = N 2^64: 9 2^m N D* = 9 n d / 2^64.
        assert_eq!(9 * n * d * n, rhs * scale, "Hammersley m = {m}");
    }
}
