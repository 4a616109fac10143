//! Checked sizes: every count, product and allocation derived from input goes through here.
//!
//! A request such as "`n` points of `d` coordinates starting at index `start`" involves a sum
//! (`start + n`), a product (`n d` coordinates) and a byte count (`4 n d`), any of which can
//! overflow or ask for more memory than exists. These helpers compute them exactly and
//! return [`Error::TooLarge`] instead of wrapping, truncating or panicking, so a caller never
//! has to remember which of the three can go wrong. All are `const fn` and `O(1)`.
//!
//! With the `std` feature, [`vec_zeroed`] allocates a buffer after checking it against
//! [`MAX_ALLOC_BYTES`] and reports a failed allocation as an error instead of aborting.
//!
//! ```
//! use qmckit::size;
//! assert_eq!(size::coordinates(1000, 3)?, 3000);
//! assert!(size::coordinates(u64::MAX, 2).is_err()); // overflows: an error, not a wrap
//! assert_eq!(size::end(5, 10, 1 << 32)?, 15);
//! assert!(size::end(1, u64::MAX, 1 << 32).is_err());
//! # Ok::<(), qmckit::Error>(())
//! ```

use crate::error::{Error, Result};

/// The largest single allocation the crate's `std` helpers make: 1 GiB. Computations that
/// need more refuse with [`Error::TooLarge`] (they would exhaust a typical machine or be
/// killed first); streaming paths work in pieces far below it.
pub const MAX_ALLOC_BYTES: u64 = 1 << 30;

/// `n * dims` as a `usize` (the number of coordinates of `n` points).
///
/// # Errors
/// [`Error::TooLarge`] (`what: "coordinates"`) when the product overflows `usize`.
pub const fn coordinates(n: u64, dims: usize) -> Result<usize> {
    product("coordinates", n, dims as u64)
}

/// `n` when it is a valid point count for a construction that takes at most `max` points:
/// the one check of every builder's `new`.
///
/// # Errors
/// [`Error::ZeroPoints`] for `n = 0`, [`Error::TooManyPoints`] (`requested: n, max`) for
/// `n > max`.
///
/// ```
/// use qmckit::{size, Error};
/// assert_eq!(size::points(5, 8)?, 5);
/// assert_eq!(size::points(0, 8), Err(Error::ZeroPoints));
/// assert_eq!(size::points(9, 8), Err(Error::TooManyPoints { requested: 9, max: 8 }));
/// # Ok::<(), qmckit::Error>(())
/// ```
pub const fn points(n: u64, max: u64) -> Result<u64> {
    if n == 0 {
        return Err(Error::ZeroPoints);
    }
    if n > max {
        return Err(Error::TooManyPoints { requested: n, max });
    }
    Ok(n)
}

/// `a * b` as a `usize`, for the count named `what`.
///
/// # Errors
/// [`Error::TooLarge`] when the product overflows `u64` or does not fit `usize`.
pub const fn product(what: &'static str, a: u64, b: u64) -> Result<usize> {
    let max = usize::MAX as u64;
    match a.checked_mul(b) {
        Some(p) if p <= max => Ok(p as usize),
        Some(p) => Err(Error::TooLarge {
            what,
            requested: p,
            max,
        }),
        None => Err(Error::TooLarge {
            what,
            requested: u64::MAX,
            max,
        }),
    }
}

/// The end `start + n` of the index range `start .. start + n`, checked against the
/// construction's length `len` (2^32 for a sequence).
///
/// # Errors
/// [`Error::IndexOutOfRange`] (naming the last index asked for) when the range passes
/// `len`; [`Error::TooLarge`] (`what: "points"`) when `start + n` overflows `u64`.
pub const fn end(start: u64, n: u64, len: u64) -> Result<u64> {
    match start.checked_add(n) {
        Some(end) if end <= len => Ok(end),
        Some(end) => Err(Error::IndexOutOfRange {
            index: end - 1,
            len,
        }),
        None => Err(Error::TooLarge {
            what: "points",
            requested: u64::MAX,
            max: len,
        }),
    }
}

/// The bytes of `count` values of `elem` bytes each, checked against [`MAX_ALLOC_BYTES`].
///
/// # Errors
/// [`Error::TooLarge`] (`what: "bytes"`) past [`MAX_ALLOC_BYTES`] or on overflow.
pub const fn bytes(count: usize, elem: usize) -> Result<usize> {
    match (count as u64).checked_mul(elem as u64) {
        Some(b) if b <= MAX_ALLOC_BYTES => Ok(b as usize),
        Some(b) => Err(Error::TooLarge {
            what: "bytes",
            requested: b,
            max: MAX_ALLOC_BYTES,
        }),
        None => Err(Error::TooLarge {
            what: "bytes",
            requested: u64::MAX,
            max: MAX_ALLOC_BYTES,
        }),
    }
}

/// How many whole rows of `row_len` values of `elem` bytes fit in `max_bytes` (at least
/// one): the batch size of streaming paths, bounded in bytes rather than in rows.
pub const fn rows_within(max_bytes: usize, row_len: usize, elem: usize) -> usize {
    let row = row_len.saturating_mul(elem);
    if row == 0 {
        return 1;
    }
    let rows = max_bytes / row;
    if rows == 0 { 1 } else { rows }
}

/// A zeroed `Vec` of `len` values, checked against [`MAX_ALLOC_BYTES`]; an allocation the
/// system refuses is an error too (no abort).
///
/// # Errors
/// [`Error::TooLarge`] (`what: "bytes"`).
///
/// ```
/// let v: Vec<u32> = qmckit::size::vec_zeroed(1000)?;
/// assert_eq!(v.len(), 1000);
/// assert!(qmckit::size::vec_zeroed::<u64>(usize::MAX).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
#[cfg(feature = "std")]
pub fn vec_zeroed<T: Default + Clone>(len: usize) -> Result<std::vec::Vec<T>> {
    let mut v = vec_with_capacity(len)?;
    v.resize(len, T::default());
    Ok(v)
}

/// An empty `Vec` with room for `capacity` values, checked against [`MAX_ALLOC_BYTES`]; an
/// allocation the system refuses is an error too (no abort). The checked counterpart of
/// `Vec::with_capacity` for capacities derived from input.
///
/// # Errors
/// [`Error::TooLarge`] (`what: "bytes"`).
///
/// ```
/// let v: Vec<f64> = qmckit::size::vec_with_capacity(1000)?;
/// assert!(v.capacity() >= 1000 && v.is_empty());
/// assert!(qmckit::size::vec_with_capacity::<f64>(1 << 40).is_err());
/// # Ok::<(), qmckit::Error>(())
/// ```
#[cfg(feature = "std")]
pub fn vec_with_capacity<T>(capacity: usize) -> Result<std::vec::Vec<T>> {
    let bytes = bytes(capacity, core::mem::size_of::<T>())?;
    let mut v = std::vec::Vec::new();
    v.try_reserve_exact(capacity).map_err(|_| Error::TooLarge {
        what: "bytes",
        requested: bytes as u64,
        max: MAX_ALLOC_BYTES,
    })?;
    Ok(v)
}

/// Reserves room for `additional` more values in `v`, checked so that the whole buffer stays
/// within [`MAX_ALLOC_BYTES`]; the checked counterpart of `Vec::reserve` for growth driven
/// by input (parsers, accumulating loops).
///
/// # Errors
/// [`Error::TooLarge`] (`what: "bytes"`).
#[cfg(feature = "std")]
pub fn reserve<T>(v: &mut std::vec::Vec<T>, additional: usize) -> Result<()> {
    let total = v.len().checked_add(additional).ok_or(Error::TooLarge {
        what: "bytes",
        requested: u64::MAX,
        max: MAX_ALLOC_BYTES,
    })?;
    let bytes = bytes(total, core::mem::size_of::<T>())?;
    v.try_reserve(additional).map_err(|_| Error::TooLarge {
        what: "bytes",
        requested: bytes as u64,
        max: MAX_ALLOC_BYTES,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_and_ends_are_exact_or_refused() {
        assert_eq!(coordinates(0, 5), Ok(0));
        assert_eq!(
            coordinates(1 << 63, 2),
            Err(Error::TooLarge {
                what: "coordinates",
                requested: u64::MAX,
                max: usize::MAX as u64
            })
        );
        assert_eq!(end(0, 1 << 32, 1 << 32), Ok(1 << 32));
        assert_eq!(
            end(1, 1 << 32, 1 << 32),
            Err(Error::IndexOutOfRange {
                index: 1 << 32,
                len: 1 << 32
            })
        );
        assert!(matches!(
            end(u64::MAX, 1, u64::MAX),
            Err(Error::TooLarge { .. })
        ));
    }

    #[test]
    fn byte_counts_stop_at_the_limit() {
        assert_eq!(bytes(1 << 28, 4), Ok(1 << 30));
        assert!(bytes((1 << 28) + 1, 4).is_err());
        assert!(bytes(usize::MAX, 8).is_err());
        assert_eq!(rows_within(1 << 20, 100_000, 4), 2);
        assert_eq!(rows_within(16, 100_000, 4), 1);
        assert_eq!(rows_within(16, 0, 4), 1);
    }
}
