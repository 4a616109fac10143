//! A randomizer whose output keeps only the top `bits` bits of every 0.32 coordinate
//! (SciPy's `bits`: coordinates are multiples of `2^-bits`): `x -> r(x) & mask` with
//! `mask = !0 << (32 - bits)`. The mask is applied inside the scramble loop, so a `f64`
//! fill (`Scrambled::fill_as`) scrambles, masks and converts each cached chunk in one pass
//! of the CPU's widest build, with no second pass over the caller's array.

use qmckit::Base2Digital;
use qmckit::bits::FromFraction;
use qmckit::randomize::{Affine, Randomizer, Randomizes, Scrambler};

/// Most lanes a row-major scramble lays out (`qmckit::randomize::ROW_LANES`).
const MAX_LANES: usize = qmckit::randomize::ROW_LANES;

/// `inner`, then the AND with `mask`.
#[derive(Clone, Copy, Debug)]
pub struct Truncated<R> {
    inner: R,
    mask: u32,
}

impl<R> Truncated<R> {
    /// `inner`, each value ANDed with `mask` (`!0 << (32 - bits)` keeps `bits` bits).
    pub fn new(inner: R, mask: u32) -> Self {
        Truncated { inner, mask }
    }
}

/// [`Truncated`] prepared for one dimension.
#[derive(Clone, Copy, Debug)]
pub struct TruncatedScrambler<S> {
    inner: S,
    mask: u32,
}

impl<S: Scrambler> Scrambler for TruncatedScrambler<S> {
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        self.inner.scramble(x) & self.mask
    }

    #[inline(always)]
    fn scramble_lanes(lanes: &[Self], xs: &mut [u32]) {
        with_inner::<S, false>(lanes, xs);
    }

    const TAKES_REVERSED: bool = S::TAKES_REVERSED;

    #[inline(always)]
    fn scramble_lanes_reversed(lanes: &[Self], xs: &mut [u32]) {
        with_inner::<S, true>(lanes, xs);
    }

    /// One mask on every lane (what `Truncated` lays out): the inner scramblers' own
    /// converting loop, handed the mask, so the scramble, the mask and the conversion stay
    /// one pass. Otherwise the default.
    #[inline(always)]
    fn scramble_lanes_into<T: FromFraction>(
        lanes: &[Self],
        xs: &mut [u32],
        out: &mut [T],
        reversed: bool,
        keep: u32,
    ) {
        if let Some(first) = lanes.first()
            && lanes.len() <= MAX_LANES
            && lanes.iter().all(|s| s.mask == first.mask)
        {
            let mut inner = [first.inner; MAX_LANES];
            for (i, s) in inner.iter_mut().zip(lanes) {
                *i = s.inner;
            }
            let inner = inner.get(..lanes.len()).unwrap_or(&[]);
            S::scramble_lanes_into(inner, xs, out, reversed, keep & first.mask);
            return;
        }
        qmckit::randomize::scramble_into_by_parts(lanes, xs, out, reversed, keep);
    }
}

/// The inner scramblers' own lane loop (their `scramble_lanes`, or with `REVERSED` their
/// `scramble_lanes_reversed`, which may be specialized), then the masks laid over the same
/// lanes: one AND a value on the chunk, still in cache. Called directly (not through a
/// function value), so that all of it is inlined into the caller's CPU-specific build.
#[inline(always)]
fn with_inner<S: Scrambler, const REVERSED: bool>(lanes: &[TruncatedScrambler<S>], xs: &mut [u32]) {
    let Some(first) = lanes.first() else {
        return;
    };
    let width = lanes.len();
    if width > MAX_LANES {
        // Not laid out by qmckit's fills; value by value.
        for chunk in xs.chunks_mut(width) {
            for (x, s) in chunk.iter_mut().zip(lanes) {
                *x = s.scramble(*x);
            }
        }
        return;
    }
    let mut inner = [first.inner; MAX_LANES];
    for (i, s) in inner.iter_mut().zip(lanes) {
        *i = s.inner;
    }
    let inner = inner.get(..width).unwrap_or(&[]);
    if REVERSED {
        S::scramble_lanes_reversed(inner, xs);
    } else {
        S::scramble_lanes(inner, xs);
    }
    if lanes.iter().all(|s| s.mask == first.mask) {
        let mask = first.mask;
        for x in xs.iter_mut() {
            *x &= mask;
        }
    } else {
        for chunk in xs.chunks_mut(width) {
            for (x, s) in chunk.iter_mut().zip(lanes) {
                *x &= s.mask;
            }
        }
    }
}

impl<R: Randomizer> Randomizer for Truncated<R> {
    type Scrambler = TruncatedScrambler<R::Scrambler>;

    #[inline]
    fn scrambler(&self, dim: usize) -> Self::Scrambler {
        TruncatedScrambler {
            inner: self.inner.scrambler(dim),
            mask: self.mask,
        }
    }

    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.inner.apply(x, dim) & self.mask
    }
}

/// Applies where the inner randomizer does, and takes the construction's bit-reversed fill
/// when the inner scrambler works on reversed values (the hash-based Owen scramble). The
/// mask is not an affine bijection, so the folded affine fill is not used.
impl<S: Base2Digital + ?Sized, R: Randomizes<S>> Randomizes<S> for Truncated<R> {
    #[inline]
    fn affine_fill(
        _sampler: &S,
        _start: u32,
        _out: &mut [u32],
        _maps: &dyn Fn(usize) -> Option<Affine>,
    ) -> Option<qmckit::Result<()>> {
        None
    }

    #[inline]
    fn reversed_fill(sampler: &S, start: u32, out: &mut [u32]) -> Option<qmckit::Result<()>> {
        sampler.fill_reversed(start, out)
    }
}
