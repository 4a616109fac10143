//! [`Scrambled`]: a sampler whose coordinates pass through a randomizer, and its fills (the
//! scramblers prepared once a call, laid over rows or run down columns, fused with the
//! conversion to the output type).

#[cfg(feature = "std")]
use super::Affine;
use super::kernels::{scramble_lanes_at, scramble_lanes_into_at, scramble_slice_at};
use super::{Randomizes, Scrambler};
use crate::bits::FromFraction;
use crate::dispatch::{self, Level};
use crate::error::Result;
use crate::sampler::{Sampler, check_fill};

/// A sampler whose coordinates pass through a randomizer:
/// `sample(i, k) = r.scrambler(k).scramble(s(i, k))`. A [`Sampler`] when `R:`
/// [`Randomizes<S>`].
///
/// `sample` prepares one scrambler a call; `fill` (and so `fill_as`) runs the sampler's own
/// fill, then prepares each dimension's scrambler once: up to [`ROW_LANES`] dimensions, the
/// scramblers are laid over whole rows and applied element-wise (vectorized); above that,
/// down each dimension's column. Scramblers that work on bit-reversed values
/// ([`Scrambler::TAKES_REVERSED`]: the hash-based Owen scramble) take the sampler's
/// reversed fill where it has one ([`Base2Digital::fill_reversed`](crate::sampler::Base2Digital::fill_reversed): Sobol' in up to four
/// dimensions), which saves a reversal a value; the bits are the same.
///
/// ```
/// use qmckit::randomize::{ExactOwen, Scrambled};
/// use qmckit::{Sampler, Sobol};
/// let s = Scrambled::new(Sobol::new(2)?, ExactOwen::new(7));
/// let p = [s.sample(5, 0)?, s.sample(5, 1)?];
/// // Owen scrambling keeps the top bit's stratification: points 0 and 1 of Sobol'
/// // lie in different halves in each dimension, and so do their scrambled images.
/// assert_ne!(s.sample(4, 0)? >> 31, p[0] >> 31);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Scrambled<S, R> {
    sampler: S,
    randomizer: R,
}

impl<S, R> Scrambled<S, R> {
    /// `sampler` randomized by `randomizer`.
    pub const fn new(sampler: S, randomizer: R) -> Self {
        Scrambled {
            sampler,
            randomizer,
        }
    }

    /// The underlying sampler.
    pub const fn sampler(&self) -> &S {
        &self.sampler
    }

    /// The randomizer.
    pub const fn randomizer(&self) -> &R {
        &self.randomizer
    }
}

impl<S: Sampler, R: Randomizes<S>> Scrambled<S, R> {
    /// Lays the dimensions' scramblers over `lanes` (a whole number of rows), each prepared
    /// once; `lanes` starts as dimension 0's scrambler everywhere. In place: the array is
    /// written once and read by the kernel where it is (no copy of it to wait on).
    #[inline(always)]
    fn spread_lanes(&self, lanes: &mut [R::Scrambler]) {
        let dims = self.dims().max(1);
        for dim in 1..dims {
            let s = self.randomizer.scrambler(dim);
            for lane in lanes.iter_mut().skip(dim).step_by(dims) {
                *lane = s;
            }
        }
    }

    /// The fill of points of at most [`ROW_LANES`] dimensions (`rows` validated): the
    /// scramblers laid over `width = lane_width(dims)` lanes, prepared once for the whole
    /// request, and the CPU's build asked once. In place for `u32` (`T = u32` and `out`
    /// the sampler's own buffer), else through a stack buffer of whole lane patterns,
    /// scrambled and converted in one pass.
    #[inline]
    fn fill_rows<const W: usize, T: FromFraction>(
        &self,
        level: Level,
        width: usize,
        start: u32,
        out: &mut [T],
        in_place: Option<&mut [u32]>,
    ) -> Result<()> {
        let mut all = [self.randomizer.scrambler(0); W];
        let lanes = all.get_mut(..width).unwrap_or(&mut []);
        self.spread_lanes(lanes);
        let lanes = &*lanes;
        if let Some(xs) = in_place {
            let reversed = self.fill_source(start, xs)?;
            scramble_lanes_at(level, lanes, xs, reversed);
            return Ok(());
        }
        let dims = self.dims().max(1);
        if out.len() <= SMALL {
            let mut buf = [0u32; SMALL];
            let xs = buf.get_mut(..out.len()).unwrap_or(&mut []);
            let reversed = self.fill_source(start, xs)?;
            scramble_lanes_into_at(level, lanes, xs, out, reversed);
            return Ok(());
        }
        // Whole lane patterns a chunk (width is a multiple of dims, so whole points too).
        let chunk = ROWS_CHUNK / width * width;
        let per = chunk / dims;
        let mut buf = [0u32; ROWS_CHUNK];
        for (c, part) in out.chunks_mut(chunk).enumerate() {
            let xs = buf.get_mut(..part.len()).unwrap_or(&mut []);
            // c * per < rows, so the index is at most the last one the caller validated.
            let reversed = self.fill_source(start + (c * per) as u32, xs)?;
            scramble_lanes_into_at(level, lanes, xs, part, reversed);
        }
        Ok(())
    }

    /// The sampler's values for the scramblers: bit-reversed (`Ok(true)`) when the
    /// scrambler takes reversed input and the sampler produces it
    /// ([`Randomizes::reversed_fill`]), else the plain fill (`Ok(false)`).
    #[inline(always)]
    fn fill_source(&self, start: u32, xs: &mut [u32]) -> Result<bool> {
        if <R::Scrambler as Scrambler>::TAKES_REVERSED
            && let Some(done) = R::reversed_fill(&self.sampler, start, xs)
        {
            return done.map(|()| true);
        }
        self.sampler.fill(start, xs)?;
        Ok(false)
    }

    /// [`fill_rows`](Self::fill_rows) with the lane width of this dimension count;
    /// `dims <= ROW_LANES`.
    #[inline]
    fn fill_low<T: FromFraction>(
        &self,
        start: u32,
        out: &mut [T],
        in_place: Option<&mut [u32]>,
    ) -> Result<()> {
        let level = dispatch::level();
        let width = lane_width(self.dims());
        if width <= 16 {
            self.fill_rows::<16, T>(level, width, start, out, in_place)
        } else {
            self.fill_rows::<ROW_LANES, T>(level, width, start, out, in_place)
        }
    }
}

/// Values a chunk of [`Scrambled::fill_as`]'s long fills: each chunk restarts the
/// sampler's fill (Sobol's sequential fill rebuilds its step table and start point, a few
/// hundred operations a dimension), so 64-bit targets take 16 KiB chunks, which keep that
/// below a tenth of an operation a value and stay in the L1 cache; 32-bit targets keep
/// [`CONVERT_CHUNK`](crate::sampler::CONVERT_CHUNK) (4 KiB of stack).
#[cfg(target_pointer_width = "64")]
const ROWS_CHUNK: usize = 4096;
#[cfg(not(target_pointer_width = "64"))]
const ROWS_CHUNK: usize = crate::sampler::CONVERT_CHUNK;

/// Values [`Scrambled::fill_as`] fills through its small stack buffer (one pixel's 16
/// four-dimensional samples).
const SMALL: usize = 64;

/// A sampler with its dimensions' affine maps prepared (`Scrambled::fill_as`).
#[cfg(feature = "std")]
struct Prepared<'a, S> {
    sampler: &'a S,
    maps: &'a [Affine],
    /// The randomizer's way to the sampler's folded fill ([`Randomizes::affine_fill`]).
    fold: FoldFn<S>,
}

/// [`Randomizes::affine_fill`] of some randomizer.
#[cfg(feature = "std")]
type FoldFn<S> = fn(&S, u32, &mut [u32], &dyn Fn(usize) -> Option<Affine>) -> Option<Result<()>>;

#[cfg(feature = "std")]
impl<S: Sampler> Prepared<'_, S> {
    fn map(&self, dim: usize) -> Affine {
        self.maps.get(dim).copied().unwrap_or(Affine::IDENTITY)
    }
}

#[cfg(feature = "std")]
impl<S: Sampler> Sampler for Prepared<'_, S> {
    fn dims(&self) -> usize {
        self.sampler.dims()
    }

    fn len(&self) -> u64 {
        self.sampler.len()
    }

    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        Ok(self.map(dim).apply(self.sampler.sample(index, dim)?))
    }

    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        if let Some(done) =
            (self.fold)(self.sampler, start, out, &|dim| self.maps.get(dim).copied())
        {
            return done;
        }
        self.sampler.fill(start, out)?;
        let dims = self.dims().max(1);
        for row in out.chunks_exact_mut(dims) {
            for (dim, x) in row.iter_mut().enumerate() {
                *x = self.map(dim).apply(*x);
            }
        }
        Ok(())
    }
}

impl<S: Sampler, R: Randomizes<S>> Sampler for Scrambled<S, R> {
    fn dims(&self) -> usize {
        self.sampler.dims()
    }

    fn len(&self) -> u64 {
        self.sampler.len()
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        let x = self.sampler.sample(index, dim)?;
        Ok(self.randomizer.scrambler(dim).scramble(x))
    }

    /// With `std` and an affine scrambler, the dimensions' maps are prepared once for the
    /// whole request and folded into the sampler's fill where it can. Otherwise, up to
    /// [`ROW_LANES`] dimensions, the scramblers are prepared once for the whole request and
    /// each buffer the sampler fills is scrambled and converted in one pass (one vectorized
    /// loop in the widest build the CPU runs); wider points take the default.
    fn fill_as<T: FromFraction>(&self, start: u32, out: &mut [T]) -> Result<()>
    where
        Self: Sized,
    {
        #[cfg(feature = "std")]
        if <R::Scrambler as Scrambler>::AFFINE {
            let dims = self.dims();
            let mut maps = Vec::new();
            if maps.try_reserve_exact(dims).is_ok() {
                for dim in 0..dims {
                    match self.randomizer.scrambler(dim).affine() {
                        Some(m) => maps.push(m),
                        None => break,
                    }
                }
                if maps.len() == dims {
                    let prepared = Prepared {
                        sampler: &self.sampler,
                        maps: &maps,
                        fold: R::affine_fill,
                    };
                    return crate::sampler::fill_as_by_chunks(&prepared, start, out);
                }
            }
        }
        let dims = self.dims();
        if dims == 0 || dims > ROW_LANES {
            return crate::sampler::fill_as_by_chunks(self, start, out);
        }
        check_fill(self, start, out.len())?;
        self.fill_low(start, out, None)
    }

    /// An affine scrambler (digital shift, LMS, compositions) folded into the sampler's
    /// generator matrices where it has them ([`Base2Digital::fill_affine`](crate::sampler::Base2Digital::fill_affine): Sobol').
    /// Otherwise the sampler's own (sequential) fill, then each dimension's scrambler,
    /// prepared once. Up to [`ROW_LANES`] dimensions the scramblers are repeated over a whole
    /// number of rows and applied element-wise to each chunk of that width; wider points have
    /// each column gathered [`COLUMN`] values at a time into a contiguous buffer, scrambled
    /// there and stored back. Both are vectorized (on x86-64 with `std` in the widest build
    /// the CPU runs).
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        if <R::Scrambler as Scrambler>::AFFINE
            && let Some(done) = R::affine_fill(&self.sampler, start, out, &|dim| {
                self.randomizer.scrambler(dim).affine()
            })
        {
            return done;
        }
        let dims = self.dims();
        if dims == 0 {
            return self.sampler.fill(start, out); // refuses zero dimensions
        }
        if dims == 1 {
            self.sampler.fill(start, out)?;
            scramble_slice_at(dispatch::level(), self.randomizer.scrambler(0), out);
            return Ok(());
        }
        if dims <= ROW_LANES {
            // Low dimensions: the scramblers repeated over whole rows, applied element-wise
            // (one scrambler prepared per dimension, copied down the lanes).
            return self.fill_low::<u32>(start, &mut [], Some(out));
        }
        self.sampler.fill(start, out)?;
        let level = dispatch::level();
        let mut tmp = [0u32; COLUMN];
        for dim in 0..dims {
            let s = self.randomizer.scrambler(dim);
            for rows in out.chunks_mut(COLUMN * dims) {
                let n = rows.len() / dims;
                for (t, row) in tmp.iter_mut().zip(rows.chunks_exact(dims)) {
                    *t = row.get(dim).copied().unwrap_or(0);
                }
                let part = tmp.get_mut(..n).unwrap_or(&mut []);
                scramble_slice_at(level, s, part);
                for (row, t) in rows.chunks_exact_mut(dims).zip(part.iter()) {
                    if let Some(x) = row.get_mut(dim) {
                        *x = *t;
                    }
                }
            }
        }
        Ok(())
    }
}

/// Values of one column [`Scrambled`]'s fill scrambles at a time (256 bytes of stack).
pub const COLUMN: usize = 64;

/// Scramblers [`Scrambled`]'s fill lays over a row-major chunk when points have at most this
/// many dimensions (the dimensions' scramblers repeated a whole number of rows).
pub const ROW_LANES: usize = 64;

/// The row-major chunk width for `dims <= ROW_LANES` dimensions: `lcm(dims, 16)` (whole
/// 16-lane vectors) when that fits in [`ROW_LANES`], else the largest multiple of `dims`
/// that does.
const fn lane_width(dims: usize) -> usize {
    let mut w = dims;
    while !w.is_multiple_of(16) && w + dims <= ROW_LANES {
        w += dims;
    }
    if w.is_multiple_of(16) {
        w
    } else {
        ROW_LANES / dims * dims
    }
}
