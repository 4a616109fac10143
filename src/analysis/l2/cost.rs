//! The cost models of the L2 discrepancies: one per path the measures take.
//!
//! * **The pair sum** (every measure, and the L2-star discrepancy in more than five
//!   dimensions or below the divide and conquer's crossover): `n (n - 1) / 2` pairs at
//!   [`PairCost::seconds_per_pair`] each, measured per measure and per loop (the loops
//!   compiled for one and two dimensions, the loop over the coordinates, the wide path with
//!   tracked exponents), times [`build_factor`] when the CPU runs a narrower build than the
//!   measure asks for; or, when the points' features do not fit in the cache, the time to
//!   stream them ([`STREAM_RATE`]), whichever is longer.
//! * **The divide and conquer** of the L2-star discrepancy ([`l2_star_fast`]): its row
//!   operations ([`tree_rows`]) at [`TREE_RATE`].
//!
//! Both are split over rayon's threads: the estimate is the per-core time over
//! [`CORES`](crate::work::CORES) ([`Cost::parallel`]). The per-core numbers are the least
//! CPU time of repeated one-thread runs on Sobol' points small enough to stay in the caches
//! (`examples/time_costs.rs`: 4000 points in 1D and 2D, 3000 from 3 to 32 dimensions, 120
//! to 1000 points in 1000 dimensions), on an x86-64 CPU with AVX-512 (`docs/budgets.md`
//! lists them against measured times).
//!
//! [`l2_star_fast`]: super::l2_star_fast

use super::{L2Metric, tree};
use crate::dispatch::{FloatBuild, float_build};
use crate::work::{Cost, Rate};

/// Row operations per second and core of the L2-star divide and conquer, in the units of
/// [`tree_rows`]: `7e7`. Measured on one thread (Sobol' points): 7.8e7 to 1.1e8 in 1D
/// (`10^4` to `10^6` points), 7.1e7 to 8.9e7 in 2D, 6.7e7 to 7.8e7 in 3D (`2^12` to `2^18`),
/// 7.4e7 to 8.3e7 in 4D and 8.6e7 in 5D (`196608` points).
pub const TREE_RATE: Rate = Rate::per_second(7e7);

/// Nanoseconds per second: the unit of [`PairCost`].
const NANOS: f64 = 1e9;

/// The size the pair sum's blocked features (`n d F 8` bytes, `F` features a coordinate)
/// may reach and the loop still run at its computing speed: 3 MiB on the calibration
/// machine, whose cores have 2 MiB of level-2 cache each (features of 2.56 MB ran at
/// computing speed, 3.84 MB in 16D at streaming speed).
pub const CACHE_BYTES: f64 = 3.0 * 1024.0 * 1024.0;

/// Bytes per second and core a pair sum streams its features from beyond [`CACHE_BYTES`]:
/// 2.8e10, measured 2.5e10 to 3.2e10 (the centered discrepancy of 10000 points in 32D, 16
/// ns a pair for 512 bytes; the L2-star of 20000 in 32D and the symmetric of 30000 in 16D;
/// the mixture of 1024 points in 500D, 324 ns a pair for 8000 bytes, where the cached loop
/// takes 115).
pub const STREAM_RATE: Rate = Rate::per_second(2.8e10);

/// The per-core cost of one pair `(i, j)` of the pair sum, in nanoseconds, for a measure on
/// the build it asks for (see the module documentation for how it was measured).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairCost {
    /// One dimension (the loop compiled for it).
    pub one: f64,
    /// Two dimensions (the loop compiled for it).
    pub two: f64,
    /// From three dimensions on, per coordinate (the loop over the coordinates; in eight
    /// dimensions the tiled loop of four measures, measured 0.85 to 1 times this).
    pub per_coordinate: f64,
    /// From three dimensions on, per pair (its accumulation).
    pub per_pair: f64,
    /// Above the plain path's dimension limit, per coordinate (tracked exponents).
    pub wide_per_coordinate: f64,
}

impl PairCost {
    /// Seconds of one core per pair in `d` dimensions: `one`, `two`, or
    /// `per_coordinate d + per_pair` (`wide_per_coordinate d + per_pair` on the wide path).
    pub fn seconds_per_pair(&self, d: usize, wide: bool) -> f64 {
        let df = d as f64;
        let ns = match d {
            _ if wide => self.wide_per_coordinate * df + self.per_pair,
            0 | 1 => self.one,
            2 => self.two,
            _ => self.per_coordinate * df + self.per_pair,
        };
        ns / NANOS
    }
}

impl L2Metric {
    /// The per-core cost of one pair of this measure's pair sum (nanoseconds), measured on an
    /// x86-64 CPU with AVX-512 in the build the measure asks for (AVX2 for the L2-star and
    /// generalized L2 discrepancies, AVX-512 for the others).
    pub fn pair_cost(self) -> PairCost {
        let (one, two, per_coordinate, per_pair, wide_per_coordinate) = match self {
            L2Metric::L2Star => (0.12, 0.21, 0.111, 0.11, 0.45),
            L2Metric::Centered => (0.17, 0.31, 0.212, 0.0, 0.83),
            L2Metric::WrapAround => (0.15, 0.28, 0.131, 0.12, 0.37),
            L2Metric::Mixture => (0.45, 0.36, 0.229, 0.0, 0.75),
            L2Metric::Symmetric => (0.125, 0.225, 0.167, 0.0, 0.39),
            L2Metric::Unanchored => (0.165, 0.325, 0.209, 0.0, 0.70),
            L2Metric::Generalized => (0.12, 0.21, 0.112, 0.11, 0.45),
            L2Metric::Diaphony => (0.175, 0.325, 0.207, 0.0, 0.37),
        };
        PairCost {
            one,
            two,
            per_coordinate,
            per_pair,
            wide_per_coordinate,
        }
    }

    /// Features a coordinate of the pair sum stores (`F`): two for the centered, mixture
    /// and unanchored discrepancies, one for the others.
    pub fn features(self) -> usize {
        match self {
            L2Metric::Centered | L2Metric::Mixture | L2Metric::Unanchored => 2,
            _ => 1,
        }
    }

    /// Does the pair sum run in register tiles of four rows in `d` dimensions (8D, plain
    /// path, centered, wrap-around, mixture and unanchored)?
    fn tiled(self, d: usize) -> bool {
        d == 8
            && matches!(
                self,
                L2Metric::Centered
                    | L2Metric::WrapAround
                    | L2Metric::Mixture
                    | L2Metric::Unanchored
            )
    }

    /// Does the pair factor use fused multiply-adds (wrap-around, mixture, diaphony)?
    fn fused(self) -> bool {
        matches!(
            self,
            L2Metric::WrapAround | L2Metric::Mixture | L2Metric::Diaphony
        )
    }

    /// The build this measure's pair sum asks for.
    fn build(self) -> FloatBuild {
        match self {
            L2Metric::L2Star | L2Metric::Generalized => FloatBuild::Avx2,
            _ => FloatBuild::Avx512,
        }
    }
}

/// How much slower the pair sum of `m` runs on this CPU than in the build it asks for: 1
/// there; 1.5 in AVX2 instead of AVX-512 (measured 1.0 to 2.4 times, 1.3 typical); in the
/// portable build 4 (measured 2.2 to 5.4 times) or, on x86-64, 60 for the measures with
/// fused multiply-adds, each then a call of the runtime library's `fma` (measured 17 to 76
/// times on a CPU with FMA; without one the software `fma` is slower still). `O(1)` (the
/// CPU's features are cached).
pub fn build_factor(m: L2Metric) -> f64 {
    let want = m.build();
    match float_build(want) {
        got if got == want => 1.0,
        FloatBuild::Portable if m.fused() && cfg!(target_arch = "x86_64") => 60.0,
        FloatBuild::Portable => 4.0,
        _ => 1.5,
    }
}

/// The row operations of the L2-star divide and conquer on `n` points in `d` dimensions:
/// `n log2 n` in one and two dimensions (one merge sort), `n (log2 n)^(d-1) / (d-1)!` from
/// three (the recursion over the coordinates, Heinrich 1996). `O(d)`.
pub fn tree_rows(n: usize, d: usize) -> f64 {
    let nf = n as f64;
    let lg = nf.max(2.0).log2();
    let mut rows = nf * lg;
    for k in 2..d {
        rows *= lg / k as f64;
    }
    rows
}

/// Seconds of one core a pair of `m`'s pair sum streams its features from beyond the cache:
/// 0 while the `n d F 8` bytes of blocked features fit in [`CACHE_BYTES`], else the pair's
/// `d F 8` bytes (a quarter of it in the 8D tiles, where a loaded block serves four rows) at
/// [`STREAM_RATE`].
fn stream_seconds_per_pair(m: L2Metric, n: usize, d: usize) -> f64 {
    let bytes = (d * m.features() * 8) as f64;
    if n as f64 * bytes <= CACHE_BYTES {
        return 0.0;
    }
    let rows = if m.tiled(d) && d <= m.fast_d() {
        4.0
    } else {
        1.0
    };
    bytes / rows / STREAM_RATE.steps_per_second()
}

/// The estimated time of `m` on `n` points in `d` dimensions on
/// [`CORES`](crate::work::CORES) cores: [`tree_rows`] at [`TREE_RATE`] where the L2-star
/// discrepancy takes the divide and conquer, else `n (n - 1) / 2` pairs, each the longer of
/// its computing, [`PairCost::seconds_per_pair`] (the wide path above the measure's plain
/// dimension limit) times [`build_factor`], and its streaming of features from beyond the
/// cache ([`stream_seconds_per_pair`]). For example the centered discrepancy of 30000
/// points in 8D: `4.5e8` pairs at 1.7 ns, 0.38 s on two cores; the mixture discrepancy of
/// 1024 points in 500D: `5.2e5` pairs of 8000 bytes streamed, 0.15 s. `O(d)`.
pub(super) fn cost(m: L2Metric, n: usize, d: usize) -> Cost {
    if m == L2Metric::L2Star && tree::tree_pays_off(d, n) {
        return Cost::parallel(tree_rows(n, d), TREE_RATE);
    }
    let nf = n as f64;
    let pairs = nf * (nf - 1.0) / 2.0;
    let compute = m.pair_cost().seconds_per_pair(d, d > m.fast_d()) * build_factor(m);
    let per_pair = compute.max(stream_seconds_per_pair(m, n, d));
    // Seconds of one core, as steps of a rate of one a second.
    Cost::parallel(pairs * per_pair, Rate::per_second(1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Seconds of one core by the model, on the calibration machine's builds.
    fn per_core(m: L2Metric, n: usize, d: usize) -> f64 {
        cost(m, n, d).seconds() * crate::work::CORES / build_factor(m)
    }

    /// The model against the least CPU time of one thread (`examples/time_costs.rs`, Sobol'
    /// points, x86-64 with AVX-512, a machine loaded by other work): the loops compiled for
    /// 1D and 2D, the loop over the coordinates, the 8D tiles, features streamed from
    /// memory, the wide path and the L2-star divide and conquer.
    #[test]
    fn the_model_follows_the_measured_times() {
        use L2Metric::*;
        let measured: [(L2Metric, usize, usize, f64); 16] = [
            (Centered, 1, 30000, 0.0665),
            (Mixture, 1, 30000, 0.1732),
            (WrapAround, 2, 20000, 0.0467),
            (Diaphony, 4, 5000, 0.0099),
            (Centered, 8, 30000, 0.788),
            (Unanchored, 8, 10000, 0.0599),
            (L2Star, 8, 30000, 0.3843),
            (Symmetric, 16, 30000, 2.045),
            (Generalized, 16, 20000, 0.3971),
            (Centered, 32, 10000, 0.808),
            (Mixture, 500, 1024, 0.1698),
            (Centered, 600, 300, 0.0138),
            (Unanchored, 1000, 1000, 0.3937),
            (L2Star, 2, 1_000_000, 0.2821),
            (L2Star, 3, 65536, 0.1152),
            (L2Star, 5, 196_608, 9.14),
        ];
        for (m, d, n, seconds) in measured {
            let ratio = seconds / per_core(m, n, d);
            assert!(
                (0.55..1.6).contains(&ratio),
                "{} d {d} n {n}: {ratio}",
                m.name()
            );
        }
    }

    #[test]
    fn each_path_has_its_model() {
        // The L2-star discrepancy takes the divide and conquer from its crossover on.
        let pairs = |n: f64, ns: f64| n * (n - 1.0) / 2.0 * ns * 1e-9 / crate::work::CORES;
        let below = cost(L2Metric::L2Star, 255, 2).seconds();
        assert_eq!(below, pairs(255.0, 0.21) * build_factor(L2Metric::L2Star));
        let above = cost(L2Metric::L2Star, 1 << 20, 2).seconds();
        assert_eq!(above, tree_rows(1 << 20, 2) / 7e7 / crate::work::CORES);
        assert_eq!(tree_rows(1 << 16, 3), 65536.0 * 16.0 * 16.0 / 2.0);
        // Features past the cache are streamed: 1024 points in 500D, two features.
        let m = L2Metric::Mixture;
        let stream = 500.0 * 2.0 * 8.0 / STREAM_RATE.steps_per_second();
        assert_eq!(stream_seconds_per_pair(m, 1024, 500), stream);
        assert_eq!(stream_seconds_per_pair(m, 64, 500), 0.0);
        // The 8D tiles load a block for four rows.
        assert_eq!(
            stream_seconds_per_pair(m, 100_000, 8),
            8.0 * 2.0 * 8.0 / 4.0 / STREAM_RATE.steps_per_second()
        );
        // The wide path above the plain dimension limit.
        let c = L2Metric::Centered.pair_cost();
        assert!(c.seconds_per_pair(513, true) > 3.0 * c.seconds_per_pair(512, false));
        for m in L2Metric::ALL {
            assert!(build_factor(m) >= 1.0);
            let mut last = 0.0;
            for n in [2, 10, 100, 1000, 10_000, 100_000] {
                let s = cost(m, n, 6).seconds();
                assert!(s > last, "{}", m.name());
                last = s;
            }
        }
    }
}
