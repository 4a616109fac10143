//! The periodogram by direct sums: `S(k) = sum_j exp(-2 pi i k . x_j)` at every frequency of
//! the half plane `ky >= 0`, the other half by `P(-k) = P(k)`.
//!
//! Cost: `N (3K + 2)` sines and cosines, then `N (K + 1)(2K + 1)` complex multiply-adds,
//! rows of frequencies split over threads. Each row sums the points in index order, so the
//! result does not depend on the number of threads. Exact up to rounding (about `|k|` ulps
//! of a turn per phase, `1e-14 N` in `P`).

use rayon::prelude::*;

use super::Spectrum;
use crate::Result;
use crate::analysis::Points;
use crate::work::Stop;

/// Points whose phase tables are computed at once (`2 * BLOCK * (2K + 1)` `f64`s each for
/// the `x` and `y` factors).
const BLOCK: usize = 256;

/// `(cos, sin)` of `-2 pi k x` for the frequencies `ks`, the phase reduced to `[0, 1)` turns
/// first (`k x` is rounded once, so the phase errs by about `|k|` ulps of 1).
fn phases(x: f64, ks: core::ops::RangeInclusive<i64>, re: &mut [f64], im: &mut [f64]) {
    for ((kk, r), i) in ks.zip(re.iter_mut()).zip(im.iter_mut()) {
        let turns = (kk as f64 * x).rem_euclid(1.0);
        let (s, c) = (core::f64::consts::TAU * turns).sin_cos();
        (*r, *i) = (c, -s);
    }
}

/// The direct-sum periodogram on `[-K, K]^2`; the caller has checked the dimension, `K`
/// and the budget. Each row of a block of points reads the deadline of `stop` first (one
/// clock reading per `256 (2K + 1)` multiply-adds).
///
/// # Errors
/// [`crate::Error::OutOfTime`] once the deadline passes.
pub(super) fn direct_sum(points: Points<'_>, k_max: usize, stop: &Stop) -> Result<Spectrum> {
    let n = points.len();
    let side = 2 * k_max + 1;
    // Rows ky = 0 ..= K of the sum S(k) = sum_j exp(-2 pi i k . x_j), as (re, im).
    let mut sums = vec![(0.0f64, 0.0f64); (k_max + 1) * side];
    // Per point of a block: x phases for kx = -K ..= K, y phases for ky = 0 ..= K.
    let (k, half) = (k_max as i64, k_max + 1);
    let (mut xr, mut xi) = (vec![0.0; BLOCK * side], vec![0.0; BLOCK * side]);
    let (mut yr, mut yi) = (vec![0.0; BLOCK * half], vec![0.0; BLOCK * half]);
    for block in points.as_slice().chunks(2 * BLOCK) {
        stop.result()?;
        let m = block.len() / 2;
        for (j, p) in block.chunks_exact(2).enumerate() {
            let at = j * side..(j + 1) * side;
            phases(p[0], -k..=k, &mut xr[at.clone()], &mut xi[at]);
            let at = j * half..(j + 1) * half;
            phases(p[1], 0..=k, &mut yr[at.clone()], &mut yi[at]);
        }
        sums.par_chunks_mut(side).enumerate().for_each(|(ky, row)| {
            if stop.check() {
                return;
            }
            for j in 0..m {
                // exp(-2 pi i ky y_j): entry ky of point j's y phases.
                let (wr, wi) = (yr[j * half + ky], yi[j * half + ky]);
                let at = j * side..(j + 1) * side;
                for ((acc, &ar), &ai) in row.iter_mut().zip(&xr[at.clone()]).zip(&xi[at]) {
                    acc.0 += wr * ar - wi * ai;
                    acc.1 += wr * ai + wi * ar;
                }
            }
        });
    }
    let inv_n = 1.0 / n.max(1) as f64;
    let mut power = vec![0.0f64; side * side];
    for (ky, row) in sums.chunks_exact(side).enumerate() {
        for (kx, &(re, im)) in row.iter().enumerate() {
            let p = (re * re + im * im) * inv_n;
            // (kx - K, ky) and its mirror (K - kx, -ky).
            power[(k_max + ky) * side + kx] = p;
            power[(k_max - ky) * side + (side - 1 - kx)] = p;
        }
    }
    power[k_max * side + k_max] = n as f64; // exact: every phase is 1
    stop.finish(Spectrum {
        k_max,
        points: n,
        power,
    })
}
