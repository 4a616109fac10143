//! The interface every construction shares: random access by `(index, dimension)`.
//!
//! One integer type per concept across the library's public API: a point (sample) index is
//! a `u32` (the digital constructions are 32-bit, and a pixel's sample index is one too), a
//! dimension is a `usize` (it counts and indexes per-point slices and tables, as `dims()`
//! and `out[dim]` do, so it needs no casts at the call site; [`crate::pixel`]'s dimension
//! counter is a `usize` for the same reason, its hashes reading the low 32 bits as pbrt's
//! `int`), and a seed is a `u64` (the width of the hashes it feeds; below `2^32` the pixel
//! samplers read it as pbrt's `int` seed, bit-identical). An index into an underlying
//! sequence that can pass `2^32` (a pixel sampler's global Sobol' index) is a `u64`.

use crate::bits::FromFraction;
use crate::dispatch::{self, Kernel, Level};
use crate::error::{Error, Result};

/// `u32`s the default [`Sampler::fill_as`] converts a call (4 KiB of stack).
pub const CONVERT_CHUNK: usize = 1024;

/// `u32`s the default [`Sampler::fill_as`] converts a call on 64-bit targets once a request
/// is longer than [`CONVERT_CHUNK`] (16 KiB of stack, within the L1 cache): a sampler whose
/// `fill` restarts per call (Sobol' rebuilds its step table and start point, an affine
/// scramble folds its maps into them, a few thousand operations) pays that a quarter as
/// often. 32-bit targets keep [`CONVERT_CHUNK`].
#[cfg(target_pointer_width = "64")]
const LONG_CHUNK: usize = 4096;
#[cfg(not(target_pointer_width = "64"))]
const LONG_CHUNK: usize = CONVERT_CHUNK;

/// `u32`s of the smaller buffer [`Sampler::fill_as`] uses for requests of at most this many
/// values.
const SMALL_CHUNK: usize = 64;

/// [`Sampler::fill_as`]'s conversion through a stack buffer of `N` `u32`s (`dims <= N`).
fn convert_via<const N: usize, S: Sampler + ?Sized, T: FromFraction>(
    s: &S,
    start: u32,
    out: &mut [T],
    dims: usize,
) -> Result<()> {
    let per = N / dims.max(1); // whole points a call
    let mut buf = [0u32; N];
    for (c, chunk) in out.chunks_mut((per * dims).max(1)).enumerate() {
        let tmp = buf.get_mut(..chunk.len()).unwrap_or(&mut []);
        // c * per < rows, so the index is at most the last one check_fill accepted.
        s.fill(start + (c * per) as u32, tmp)?;
        convert(tmp, chunk);
    }
    Ok(())
}

/// Fractions to coordinates, compiled once per build ([`crate::dispatch::Kernel`]).
struct Convert<'a, T> {
    src: &'a [u32],
    dst: &'a mut [T],
}

impl<T: FromFraction> Kernel for Convert<'_, T> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        // The values before the first cache-line boundary of `dst` one at a time, so that
        // the vector stores after them are aligned (a store across two lines costs two).
        let n = self.src.len().min(self.dst.len());
        let head = self.dst.as_ptr().align_offset(64).min(n);
        let (dst_head, dst) = self.dst.split_at_mut(head);
        let (src_head, src) = self.src.split_at(head.min(self.src.len()));
        for (y, &x) in dst_head.iter_mut().zip(src_head) {
            *y = T::from_fraction(x);
        }
        for (y, &x) in dst.iter_mut().zip(src) {
            *y = T::from_fraction(x);
        }
    }
}

/// `dst[j] = T::from_fraction(src[j])` (the shorter length), in the widest build this CPU
/// runs: what [`Sampler::fill_as`] converts its `u32` buffer with.
#[inline]
pub(crate) fn convert<T: FromFraction>(src: &[u32], dst: &mut [T]) {
    convert_at(dispatch::level(), src, dst);
}

/// [`convert`] with the widest build that is at most `want` and that the CPU runs.
#[inline]
pub(crate) fn convert_at<T: FromFraction>(want: Level, src: &[u32], dst: &mut [T]) {
    dispatch::run_at(want, Convert { src, dst });
}

/// 2^32, the number of `u32` indices.
pub const FULL_RANGE: u64 = 1 << 32;

/// A point set or sequence in `[0, 1)^dims`, answered by random access.
///
/// Coordinates are 0.32 fixed-point fractions (`u32`); see [`crate::bits`] for conversions.
/// `sample` is a pure function of its arguments (randomized samplers carry their seed), so
/// points can be generated in any order, in parallel, or baked at compile time.
///
/// ```
/// use qmckit::{Halton, Sampler};
/// let h = Halton::new(2)?;
/// let mut pts = [0u32; 8]; // 4 points, row-major
/// h.fill(0, &mut pts)?;
/// assert_eq!(pts[2..4], [h.sample(1, 0)?, h.sample(1, 1)?]);
/// # Ok::<(), qmckit::Error>(())
/// ```
// `len` counts valid indices and is never 0 (every constructor refuses empty sets), so
// there is no `is_empty`.
#[allow(clippy::len_without_is_empty)]
pub trait Sampler {
    /// Number of coordinates of each point.
    fn dims(&self) -> usize;

    /// Number of valid indices, at least 1: the size of a finite point set, or 2^32
    /// ([`FULL_RANGE`]) for a sequence.
    fn len(&self) -> u64;

    /// Coordinate `dim` of point `index`.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] or [`Error::DimensionOutOfRange`].
    fn sample(&self, index: u32, dim: usize) -> Result<u32>;

    /// Point `index` into `out`, which must hold exactly `dims()` values.
    ///
    /// # Errors
    /// [`Error::BufferLength`], [`Error::IndexOutOfRange`].
    fn point(&self, index: u32, out: &mut [u32]) -> Result<()> {
        if out.len() != self.dims() {
            return Err(Error::BufferLength {
                expected: self.dims(),
                got: out.len(),
            });
        }
        for (dim, slot) in out.iter_mut().enumerate() {
            *slot = self.sample(index, dim)?;
        }
        Ok(())
    }

    /// Consecutive points `start, start + 1, ...` into `out`, row-major (`dims()` values a
    /// point); `out.len()` must be a multiple of `dims()`. Samplers override this with
    /// sequential fast paths that return the same bits.
    ///
    /// # Errors
    /// [`Error::BufferLength`], [`Error::IndexOutOfRange`].
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        let rows = check_fill(self, start, out.len())?;
        let dims = self.dims();
        if dims == 0 {
            return Ok(()); // unreachable: check_fill refuses zero dimensions
        }
        for (k, row) in out.chunks_exact_mut(dims).enumerate().take(rows) {
            self.point(start + k as u32, row)?;
        }
        Ok(())
    }

    /// [`fill`](Self::fill) into any coordinate type ([`FromFraction`]: `f64`, `f32`,
    /// `u32`, ...): the same values as converting the `u32` fill. The default fills whole
    /// points into a stack buffer of [`CONVERT_CHUNK`] `u32`s a call and converts them (point
    /// by point, through [`sample`](Self::sample), when one point is larger); samplers with
    /// a sequential fast path convert as they store instead ([`crate::Halton`]). Not
    /// available through `dyn Sampler` (it is generic); `&S` and `Box<S>` use the default.
    ///
    /// ```
    /// use qmckit::{Halton, Sampler, bits::to_f64};
    /// let h = Halton::new(3)?;
    /// let mut x = [0f64; 6];
    /// h.fill_as(10, &mut x)?; // points 10 and 11
    /// assert_eq!(x[5], to_f64(h.sample(11, 2)?));
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`fill`](Self::fill).
    fn fill_as<T: FromFraction>(&self, start: u32, out: &mut [T]) -> Result<()>
    where
        Self: Sized,
    {
        fill_as_by_chunks(self, start, out)
    }
}

/// The default [`Sampler::fill_as`]: whole points through [`Sampler::fill`] into a stack
/// buffer of [`CONVERT_CHUNK`] `u32`s, converted (point by point through `sample` when one
/// point is larger). For samplers that override `fill_as` and fall back to it.
///
/// # Errors
/// As [`Sampler::fill`].
pub fn fill_as_by_chunks<S: Sampler + ?Sized, T: FromFraction>(
    s: &S,
    start: u32,
    out: &mut [T],
) -> Result<()> {
    let rows = check_fill(s, start, out.len())?;
    let dims = s.dims();
    if dims > CONVERT_CHUNK {
        for (k, row) in out.chunks_exact_mut(dims).enumerate().take(rows) {
            for (dim, slot) in row.iter_mut().enumerate() {
                *slot = T::from_fraction(s.sample(start + k as u32, dim)?);
            }
        }
        return Ok(());
    }
    // A small buffer for small requests (no 4 KiB to clear for a pixel's samples).
    if out.len() <= SMALL_CHUNK {
        convert_via::<SMALL_CHUNK, _, _>(s, start, out, dims)
    } else if out.len() <= CONVERT_CHUNK {
        convert_via::<CONVERT_CHUNK, _, _>(s, start, out, dims)
    } else {
        convert_via::<LONG_CHUNK, _, _>(s, start, out, dims)
    }
}

/// Validates a [`Sampler::fill`] request of `len` values from index `start` and returns its
/// number of points (for implementors of `fill`).
///
/// # Errors
/// [`Error::BufferLength`] unless `len` is a multiple of `dims()`;
/// [`Error::IndexOutOfRange`] if the last index is `len()` or beyond.
///
/// ```
/// use qmckit::{Sobol, sampler::check_fill};
/// let s = Sobol::new(2)?;
/// assert_eq!(check_fill(&s, 0, 8)?, 4);
/// assert!(check_fill(&s, 0, 7).is_err());
/// assert!(check_fill(&s, u32::MAX, 4).is_err()); // index 2^32 does not exist
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn check_fill<S: Sampler + ?Sized>(s: &S, start: u32, len: usize) -> Result<usize> {
    let dims = s.dims();
    if dims == 0 || !len.is_multiple_of(dims) {
        return Err(Error::BufferLength {
            expected: dims,
            got: len,
        });
    }
    let rows = len / dims;
    let end = start as u64 + rows as u64;
    if end > s.len() {
        return Err(Error::IndexOutOfRange {
            index: end - 1,
            len: s.len(),
        });
    }
    Ok(rows)
}

/// A base-2 digital construction: every coordinate is `C_d i` over GF(2) for a generator
/// matrix `C_d` (Sobol', Larcher–Pillichshammer, van der Corput in base 2 as
/// [`crate::Sobol`]'s dimension 0). The base-2 digital randomizations
/// ([`crate::randomize::DigitalShift`], [`crate::randomize::ExactOwen`],
/// [`crate::randomize::FastOwen`], [`crate::randomize::Lms`]) keep its nets and apply only
/// to these (`Scrambled<S, R>` requires `R: Randomizes<S>`).
pub trait Base2Digital: Sampler {
    /// [`fill`](Sampler::fill) with the affine map `maps(dim)` (`x -> M x ^ c` over GF(2))
    /// applied to every coordinate of dimension `dim`: `Some` from constructions that fold
    /// the maps into their generator matrices so the scramble costs nothing a value
    /// (Sobol'); `None` (the default) when the construction cannot, or when `maps` answers
    /// `None` for a dimension (then `out` may be partly written: the caller fills it
    /// another way). [`crate::randomize::Scrambled`] calls it for affine scramblers
    /// (digital shift, LMS, their compositions).
    ///
    /// # Errors
    /// As [`fill`](Sampler::fill), inside the `Some`.
    fn fill_affine(
        &self,
        start: u32,
        out: &mut [u32],
        maps: &dyn Fn(usize) -> Option<crate::bits::Affine>,
    ) -> Option<Result<()>> {
        let _ = (start, out, maps);
        None
    }

    /// [`fill`](Sampler::fill) with every value bit-reversed: `out[j] = reverse(x_j)`, the
    /// base-2 radical-inverse domain, in which the hash-based Owen scramble works
    /// ([`crate::randomize::FastOwenScrambler::scramble_reversed`]): `reverse` distributes
    /// over XOR, so the reversed point is the GF(2) product of the reversed direction
    /// numbers with the index. `Some` from constructions that produce reversed values
    /// without a reversal a value (Sobol' in up to four dimensions, natural order, on 64-bit
    /// targets: four byte-table reads a point); `None` (the default) otherwise, and `out`
    /// is then untouched. [`crate::randomize::Scrambled`] calls it for scramblers that take
    /// reversed input ([`crate::randomize::Scrambler::TAKES_REVERSED`]).
    ///
    /// # Errors
    /// As [`fill`](Sampler::fill), inside the `Some`.
    fn fill_reversed(&self, start: u32, out: &mut [u32]) -> Option<Result<()>> {
        let _ = (start, out);
        None
    }
}

/// Forwards [`Base2Digital`] through a pointer type.
macro_rules! forward_base2 {
    ($(#[$attr:meta])* $ptr:ty) => {
        $(#[$attr])*
        impl<S: Base2Digital + ?Sized> Base2Digital for $ptr {
            fn fill_affine(
                &self,
                start: u32,
                out: &mut [u32],
                maps: &dyn Fn(usize) -> Option<crate::bits::Affine>,
            ) -> Option<Result<()>> {
                (**self).fill_affine(start, out, maps)
            }
            fn fill_reversed(&self, start: u32, out: &mut [u32]) -> Option<Result<()>> {
                (**self).fill_reversed(start, out)
            }
        }
    };
}

forward_base2!(&S);
forward_base2!(#[cfg(feature = "std")] Box<S>);

/// Validates a finite set's size, `1 <= n <= 2^32`, and its dimension count, `dims >= 1`.
pub(crate) const fn check_set(n: u64, dims: usize) -> Result<()> {
    if let Err(e) = crate::size::points(n, FULL_RANGE) {
        return Err(e);
    }
    if dims == 0 {
        return Err(Error::ZeroDimensions);
    }
    Ok(())
}

/// Validates `index < len` and `dim < dims` for a `sample` call.
#[inline]
pub(crate) const fn check(index: u32, len: u64, dim: usize, dims: usize) -> Result<()> {
    if dim >= dims {
        return Err(Error::DimensionOutOfRange { dim, dims });
    }
    if index as u64 >= len {
        return Err(Error::IndexOutOfRange {
            index: index as u64,
            len,
        });
    }
    Ok(())
}

/// Forwards every [`Sampler`] method through a pointer type.
macro_rules! forward_sampler {
    ($(#[$attr:meta])* $ptr:ty) => {
        $(#[$attr])*
        impl<S: Sampler + ?Sized> Sampler for $ptr {
            fn dims(&self) -> usize {
                (**self).dims()
            }

            fn len(&self) -> u64 {
                (**self).len()
            }

            #[inline]
            fn sample(&self, index: u32, dim: usize) -> Result<u32> {
                (**self).sample(index, dim)
            }

            fn point(&self, index: u32, out: &mut [u32]) -> Result<()> {
                (**self).point(index, out)
            }

            fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
                (**self).fill(start, out)
            }
        }
    };
}

forward_sampler!(
    /// A reference to a sampler is a sampler (so wrappers can borrow, and `&dyn Sampler`
    /// works).
    &S
);
forward_sampler!(
    /// A boxed sampler is a sampler (for run-time choices, as in the command-line tool).
    #[cfg(feature = "std")]
    Box<S>
);

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    /// Every build of the conversion against `from_fraction`, for `f32`, `f64` and `u32`,
    /// on the values where `f32` rounding changes (around powers of two) and a spread.
    #[test]
    fn every_conversion_build_matches_from_fraction() {
        let mut xs: Vec<u32> = (0..32)
            .flat_map(|b| [1u32 << b, (1u32 << b).wrapping_sub(1), (1u32 << b) + 1])
            .collect();
        xs.extend((0..2000u32).map(|k| k.wrapping_mul(0x9E37_79B9)));
        xs.push(u32::MAX);
        for lv in dispatch::levels() {
            let mut f = vec![0f32; xs.len()];
            convert_at(lv, &xs, &mut f);
            let mut d = vec![0f64; xs.len()];
            convert_at(lv, &xs, &mut d);
            let mut u = vec![0u32; xs.len()];
            convert_at(lv, &xs, &mut u);
            for (j, &x) in xs.iter().enumerate() {
                assert_eq!(
                    f[j].to_bits(),
                    crate::bits::to_f32(x).to_bits(),
                    "{lv:?} f32 {x:#x}"
                );
                assert_eq!(
                    d[j].to_bits(),
                    crate::bits::to_f64(x).to_bits(),
                    "{lv:?} f64 {x:#x}"
                );
                assert_eq!(u[j], x, "{lv:?} u32");
            }
        }
    }
}
