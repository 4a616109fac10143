//! The scramblers' loops, compiled once per build of [`crate::dispatch`]: one prepared
//! scrambler down a column, scramblers laid over rows, and the same fused with the
//! conversion to the output type (what [`super::Scrambled`]'s fills run).

use super::Scrambler;
use crate::bits::FromFraction;
use crate::dispatch::{self, Kernel, Level};

/// One prepared scrambler over a column.
struct ScrambleSlice<'a, S> {
    s: S,
    xs: &'a mut [u32],
}

impl<S: Scrambler> Kernel for ScrambleSlice<'_, S> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        for x in self.xs {
            *x = self.s.scramble(*x);
        }
    }
}

/// `x = s.scramble(x)` for every `x` in `xs`: one prepared scrambler over a contiguous
/// column, in the build `want` (or the widest narrower one the CPU runs), so the
/// scrambler's per-value arithmetic is vectorized (16 lanes with AVX-512, 8 with AVX2).
#[inline]
pub(crate) fn scramble_slice_at<S: Scrambler>(want: Level, s: S, xs: &mut [u32]) {
    dispatch::run_at(want, ScrambleSlice { s, xs });
}

/// Scramblers laid over a row-major buffer (of bit-reversed values when `reversed`), then
/// (optionally) converted.
struct ScrambleLanes<'a, S, T> {
    lanes: &'a [S],
    xs: &'a mut [u32],
    out: &'a mut [T],
    reversed: bool,
}

impl<S: Scrambler, T: FromFraction> Kernel for ScrambleLanes<'_, S, T> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        if self.out.is_empty() {
            if self.reversed {
                S::scramble_lanes_reversed(self.lanes, self.xs);
            } else {
                S::scramble_lanes(self.lanes, self.xs);
            }
            return;
        }
        S::scramble_lanes_into(self.lanes, self.xs, self.out, self.reversed, u32::MAX);
    }
}

/// `xs[j] = lanes[j % lanes.len()].scramble(xs[j])`: a row-major buffer whose rows hold one
/// coordinate per lane pattern (`lanes` repeats the dimensions' scramblers a whole number of
/// rows), each chunk of `lanes.len()` values scrambled element-wise, in the build `want` (or
/// the widest narrower one the CPU runs): no gather or scatter. With `reversed`, `xs` holds
/// bit-reversed values ([`Scrambler::scramble_lanes_reversed`]).
#[inline]
pub(crate) fn scramble_lanes_at<S: Scrambler>(
    want: Level,
    lanes: &[S],
    xs: &mut [u32],
    reversed: bool,
) {
    let out: &mut [u32] = &mut [];
    dispatch::run_at(
        want,
        ScrambleLanes {
            lanes,
            xs,
            out,
            reversed,
        },
    );
}

/// [`scramble_lanes_at`], then `out[j] = T::from_fraction(xs[j])` (the shorter length), in
/// one pass of one build: what `Scrambled::fill_as` runs on each buffer it fills.
#[inline]
pub(crate) fn scramble_lanes_into_at<S: Scrambler, T: FromFraction>(
    want: Level,
    lanes: &[S],
    xs: &mut [u32],
    out: &mut [T],
    reversed: bool,
) {
    dispatch::run_at(
        want,
        ScrambleLanes {
            lanes,
            xs,
            out,
            reversed,
        },
    );
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;
    use crate::randomize::OwenHash;

    /// Every build the CPU runs against the one-value path: prepared scramblers over
    /// columns, and laid over rows (lane patterns of 1 to 64, one with mixed hashes, a
    /// buffer that ends mid-pattern), with and without the conversion.
    #[test]
    fn every_build_matches_the_scalar_path() {
        let levels = &dispatch::levels()[..];
        // Prepared scramblers over columns: every build against the one-value path.
        {
            use crate::randomize::{
                CranleyPatterson, DigitalShift, ExactOwen, FastOwen, Lms, Randomizer,
            };
            let xs: Vec<u32> = (0..1000u32).map(|k| k.wrapping_mul(0x9E37_79B9)).collect();
            let check = |name: &str,
                         r: &dyn Fn(usize, u32) -> u32,
                         run: &dyn Fn(Level, usize, &mut [u32])| {
                for &lv in levels {
                    for dim in [0usize, 3] {
                        let mut got = xs.clone();
                        run(lv, dim, &mut got);
                        for (k, (&g, &x)) in got.iter().zip(&xs).enumerate() {
                            assert_eq!(g, r(dim, x), "{name} {lv:?} dim {dim} k {k}");
                        }
                    }
                }
            };
            let fo = FastOwen::with_hash(5, OwenHash::LaineKarras);
            check("fast-owen-lk", &|d, x| fo.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, fo.scrambler(d), v)
            });
            let fo = FastOwen::new(6);
            check("fast-owen", &|d, x| fo.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, fo.scrambler(d), v)
            });
            let ex = ExactOwen::new(7);
            check("exact-owen", &|d, x| ex.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, ex.scrambler(d), v)
            });
            let pair = (Lms::new(8), DigitalShift::new(8));
            check("lms+xor", &|d, x| pair.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, pair.scrambler(d), v)
            });
            let cp = CranleyPatterson::new(9);
            check("rotate", &|d, x| cp.apply(x, d), &|lv, d, v| {
                scramble_slice_at(lv, cp.scrambler(d), v)
            });
        }
        // Scramblers laid over rows (lane patterns of 1 to 64, one with mixed hashes, a
        // buffer that ends mid-pattern): every build against the one-value path.
        {
            use crate::randomize::{ExactOwen, FastOwen, FastOwenScrambler, Lms, Randomizer};
            let xs: Vec<u32> = (0..1003u32).map(|k| k.wrapping_mul(0x85EB_CA6B)).collect();
            fn run<S: Scrambler>(levels: &[Level], name: &str, lanes: &[S], xs: &[u32]) {
                for &lv in levels {
                    // The plain input, and the same values bit-reversed (the reversed form).
                    for reversed in [false, true] {
                        let mut got: Vec<u32> = xs
                            .iter()
                            .map(|&x| if reversed { x.reverse_bits() } else { x })
                            .collect();
                        scramble_lanes_at(lv, lanes, &mut got, reversed);
                        for (j, (&g, &x)) in got.iter().zip(xs).enumerate() {
                            let want = lanes[j % lanes.len()].scramble(x);
                            let w = lanes.len();
                            assert_eq!(g, want, "{name} {lv:?} {reversed} width {w} j {j}");
                        }
                    }
                }
            }
            for width in [1usize, 3, 4, 16, 20, 48, 64] {
                let fo = FastOwen::new(11);
                let lanes: Vec<_> = (0..width).map(|d| fo.scrambler(d % 5)).collect();
                run(levels, "fast-owen", &lanes, &xs);
                let fo = FastOwen::with_hash(12, OwenHash::LaineKarras);
                let lanes: Vec<_> = (0..width).map(|d| fo.scrambler(d)).collect();
                run(levels, "fast-owen-lk", &lanes, &xs);
                let mixed: Vec<_> = (0..width)
                    .map(|d| {
                        let hash = [OwenHash::Vegdahl, OwenHash::LaineKarras][d % 2];
                        FastOwenScrambler::from_key((d as u32).wrapping_mul(0x9E37_79B9), hash)
                    })
                    .collect();
                run(levels, "fast-owen-mixed", &mixed, &xs);
                let ex = ExactOwen::new(13);
                let lanes: Vec<_> = (0..width).map(|d| ex.scrambler(d)).collect();
                run(levels, "exact-owen", &lanes, &xs);
                let lms = Lms::new(14);
                let lanes: Vec<_> = (0..width).map(|d| lms.scrambler(d)).collect();
                run(levels, "lms", &lanes, &xs);
            }
        }
        // Fused with the conversion (f32 and f64, plain and reversed input, outputs starting
        // off a cache-line boundary, the trait's `keep` mask): the scrambled values, masked,
        // converted. Widths 1, 4 and 16 take the fused loop of 16 lanes; 64 the default.
        {
            use crate::bits::{to_f32, to_f64};
            use crate::randomize::{FastOwen, Lms, Randomizer};
            let xs: Vec<u32> = (0..1003u32).map(|k| k.wrapping_mul(0x85EB_CA6B)).collect();
            for width in [1usize, 4, 16, 64] {
                for hash in [OwenHash::Vegdahl, OwenHash::LaineKarras] {
                    let fo = FastOwen::with_hash(15, hash);
                    let lanes: Vec<_> = (0..width).map(|d| fo.scrambler(d % 3)).collect();
                    for &lv in levels {
                        for reversed in [false, true] {
                            let input: Vec<u32> = xs
                                .iter()
                                .map(|&x| if reversed { x.reverse_bits() } else { x })
                                .collect();
                            let want =
                                |j: usize, keep: u32| lanes[j % width].scramble(xs[j]) & keep;
                            let mut got = input.clone();
                            let mut f = vec![0f32; xs.len()];
                            scramble_lanes_into_at(lv, &lanes, &mut got, &mut f, reversed);
                            for (j, y) in f.iter().enumerate() {
                                let w = to_f32(want(j, u32::MAX));
                                assert_eq!(y.to_bits(), w.to_bits(), "{lv:?} {width} {j}");
                            }
                            for offset in [0usize, 1, 3, 7] {
                                let keep = u32::MAX << 3;
                                let mut got = input.clone();
                                let mut buf = vec![0f64; xs.len() + offset];
                                let out = &mut buf[offset..];
                                dispatch::run_at(
                                    lv,
                                    IntoKept {
                                        lanes: &lanes,
                                        xs: &mut got,
                                        out,
                                        reversed,
                                        keep,
                                    },
                                );
                                for (j, y) in buf[offset..].iter().enumerate() {
                                    let w = to_f64(want(j, keep));
                                    assert_eq!(
                                        y.to_bits(),
                                        w.to_bits(),
                                        "{lv:?} {width} {offset} {j}"
                                    );
                                }
                            }
                        }
                    }
                }
                // A scrambler with the default (by parts), with a mask.
                let lms = Lms::new(16);
                let lanes: Vec<_> = (0..width).map(|d| lms.scrambler(d)).collect();
                let mut got = xs.clone();
                let mut out = vec![0f64; xs.len()];
                let keep = u32::MAX << 7;
                dispatch::run(IntoKept {
                    lanes: &lanes,
                    xs: &mut got,
                    out: &mut out,
                    reversed: false,
                    keep,
                });
                for (j, y) in out.iter().enumerate() {
                    let w = to_f64(lanes[j % width].scramble(xs[j]) & keep);
                    assert_eq!(y.to_bits(), w.to_bits(), "lms {width} {j}");
                }
            }
        }
    }

    /// [`Scrambler::scramble_lanes_into`] with a mask, in one build.
    struct IntoKept<'a, S> {
        lanes: &'a [S],
        xs: &'a mut [u32],
        out: &'a mut [f64],
        reversed: bool,
        keep: u32,
    }

    impl<S: Scrambler> Kernel for IntoKept<'_, S> {
        type Output = ();
        #[inline(always)]
        fn run(self) {
            S::scramble_lanes_into(self.lanes, self.xs, self.out, self.reversed, self.keep);
        }
    }
}
