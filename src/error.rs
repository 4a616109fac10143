//! The one error type of the crate.
//!
//! Every fallible constructor and every request that can be out of range returns
//! `Result<_, Error>`; nothing in the core panics on bad input. The type is `Copy`, carries
//! the offending values, and implements [`core::fmt::Display`] (and `defmt::Format` under the
//! `defmt` feature) so firmware can log it without allocation.

use core::fmt;

/// An invalid parameter or out-of-range request.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Error {
    /// A point set was asked to hold zero points.
    ZeroPoints,
    /// A point set was asked for more points than its construction allows.
    TooManyPoints {
        /// Points requested.
        requested: u64,
        /// Largest allowed.
        max: u64,
    },
    /// A sampler was asked for zero dimensions.
    ZeroDimensions,
    /// A dimension past what the sampler (or its compiled-in table) provides.
    DimensionOutOfRange {
        /// Dimension requested (0-based).
        dim: usize,
        /// Number of dimensions available.
        dims: usize,
    },
    /// A point index past the end of a finite point set.
    IndexOutOfRange {
        /// Index requested.
        index: u64,
        /// Number of points in the set.
        len: u64,
    },
    /// A radical-inverse base below 2.
    BaseTooSmall {
        /// Base requested.
        base: u32,
    },
    /// A net size exponent `m` (N = b^m) past what 32-bit indices and outputs hold.
    MTooLarge {
        /// Exponent requested.
        m: u32,
        /// Largest allowed.
        max: u32,
    },
    /// A point count that the construction needs to be a power of two.
    NotPowerOfTwo {
        /// Count given.
        n: u64,
    },
    /// A stratum count of zero in a stratified sampler.
    ZeroStrata {
        /// The dimension with zero strata.
        dim: usize,
    },
    /// An output buffer whose length does not fit the request.
    BufferLength {
        /// Length the call needs (or a multiple of it).
        expected: usize,
        /// Length given.
        got: usize,
    },
    /// A combination the crate does not provide (e.g. an option that does not apply).
    Unsupported {
        /// What was asked for.
        what: &'static str,
    },
    /// An inverse radical inverse asked for more digits than fit in 32 bits.
    TooManyDigits {
        /// Digits requested.
        digits: u32,
        /// Largest allowed for this base.
        max: u32,
    },
    /// A point coordinate outside the closed unit interval `[0, 1]`, or not a number.
    CoordinateOutOfRange {
        /// Point (0-based).
        point: usize,
        /// Coordinate (0-based).
        dim: usize,
    },
    /// A flat coordinate buffer whose length is not a multiple of the dimension.
    RaggedPoints {
        /// Number of coordinates given.
        len: usize,
        /// Dimension of a point.
        dims: usize,
    },
    /// A count, product or allocation derived from the input that is larger than the crate
    /// admits (it would overflow, or exceed a memory limit); see [`crate::size`].
    TooLarge {
        /// What was counted (`"coordinates"`, `"bytes"`, ...).
        what: &'static str,
        /// The size asked for (saturated at `u64::MAX` when it overflows).
        requested: u64,
        /// The largest admitted.
        max: u64,
    },
    /// A computation whose estimated running time exceeds its time budget (see
    /// [`crate::work`]).
    OverBudget {
        /// The computation.
        what: &'static str,
        /// Estimated running time, in milliseconds (saturated).
        estimated_ms: u64,
        /// The budget, in milliseconds.
        budget_ms: u64,
    },
    /// A computation that was admitted by its estimate but ran past its deadline (see
    /// [`crate::work`]): stopped, with nothing returned.
    OutOfTime {
        /// The computation.
        what: &'static str,
        /// The budget, in milliseconds.
        budget_ms: u64,
    },
    /// A result that exists mathematically but is not representable in `f64` (it would
    /// overflow or underflow to zero), reported instead of a wrong number.
    NotRepresentable {
        /// What could not be represented.
        what: &'static str,
    },
    /// A geometric or numeric parameter that is not finite, or outside the range where the
    /// computation is defined (e.g. a degenerate triangle, edges that are not perpendicular).
    InvalidParameter {
        /// What is wrong, as a short phrase.
        what: &'static str,
    },
}

/// Shorthand for `core::result::Result<T, qmckit::Error>`.
pub type Result<T> = core::result::Result<T, Error>;

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::ZeroPoints => write!(f, "the number of points must be at least 1"),
            Error::TooManyPoints { requested, max } => {
                write!(f, "{requested} points requested, at most {max} allowed")
            }
            Error::ZeroDimensions => write!(f, "the number of dimensions must be at least 1"),
            Error::DimensionOutOfRange { dim, dims } => write!(
                f,
                "dimension {dim} is out of range: {dims} dimension(s) available (0-based)"
            ),
            Error::IndexOutOfRange { index, len } => {
                write!(f, "index {index} is out of range for a set of {len} points")
            }
            Error::BaseTooSmall { base } => write!(f, "base {base} is invalid: it must be >= 2"),
            Error::MTooLarge { m, max } => write!(f, "m = {m} is too large: at most {max}"),
            Error::NotPowerOfTwo { n } => write!(f, "{n} points: this set needs a power of two"),
            Error::ZeroStrata { dim } => {
                write!(
                    f,
                    "dimension {dim} has zero strata: every count must be >= 1"
                )
            }
            Error::BufferLength { expected, got } => {
                write!(
                    f,
                    "buffer of length {got} given, {expected} (or a multiple) needed"
                )
            }
            Error::Unsupported { what } => write!(f, "not supported: {what}"),
            Error::TooManyDigits { digits, max } => {
                write!(f, "{digits} digits requested, at most {max} fit in 32 bits")
            }
            Error::CoordinateOutOfRange { point, dim } => write!(
                f,
                "point {point}, coordinate {dim}: not a number in [0, 1] (0-based)"
            ),
            Error::RaggedPoints { len, dims } => write!(
                f,
                "{len} coordinates do not make whole points of {dims} dimension(s)"
            ),
            Error::TooLarge {
                what,
                requested,
                max,
            } => {
                if requested == u64::MAX {
                    write!(f, "too many {what}: the count overflows (at most {max})")
                } else {
                    write!(f, "too many {what}: {requested} requested, at most {max}")
                }
            }
            Error::OverBudget {
                what,
                estimated_ms,
                budget_ms,
            } => {
                write!(f, "{what}: estimated ")?;
                write_seconds(f, estimated_ms)?;
                write!(f, ", more than the time budget of ")?;
                write_seconds(f, budget_ms)
            }
            Error::OutOfTime { what, budget_ms } => {
                write!(f, "{what}: stopped, running past the time budget of ")?;
                write_seconds(f, budget_ms)
            }
            Error::NotRepresentable { what } => {
                write!(f, "{what} is not representable as an f64")
            }
            Error::InvalidParameter { what } => write!(f, "invalid parameter: {what}"),
        }
    }
}

/// `ms` milliseconds as seconds: with one decimal from a second up (`12.3 s`), to the
/// millisecond below (`0.308 s`), or `more than 10^15 s`.
fn write_seconds(f: &mut fmt::Formatter<'_>, ms: u64) -> fmt::Result {
    if ms == u64::MAX {
        write!(f, "more than 10^15 s")
    } else if ms < 1000 {
        write!(f, "0.{ms:03} s")
    } else {
        write!(f, "{}.{} s", ms / 1000, (ms % 1000) / 100)
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Error {}
