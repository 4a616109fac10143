//! Fixed-capacity point buffers without allocation (feature `heapless`).

use crate::error::{Error, Result};
use crate::sampler::Sampler;

/// Points `start .. start + count` of `sampler` as `[u32; D]` rows in a `heapless::Vec` of
/// capacity `N`: a stack- or static-allocated pattern for firmware.
///
/// # Errors
/// [`Error::BufferLength`] if `D != sampler.dims()` or `count > N`;
/// [`Error::IndexOutOfRange`] past the sampler's end.
///
/// ```
/// use qmckit::{Halton, buffer::points};
/// let pts = points::<_, 2, 64>(&Halton::new(2)?, 0, 16)?;
/// assert_eq!(pts.len(), 16);
/// assert_eq!(pts[1], [0x8000_0000, 0x5555_5555]);
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn points<S: Sampler + ?Sized, const D: usize, const N: usize>(
    sampler: &S,
    start: u32,
    count: usize,
) -> Result<heapless::Vec<[u32; D], N>> {
    if D != sampler.dims() {
        return Err(Error::BufferLength {
            expected: sampler.dims(),
            got: D,
        });
    }
    if count > N {
        return Err(Error::BufferLength {
            expected: count,
            got: N,
        });
    }
    crate::sampler::check_fill(sampler, start, count * D)?;
    let mut out = heapless::Vec::new();
    for k in 0..count {
        let mut row = [0u32; D];
        sampler.point(start + k as u32, &mut row)?;
        // Cannot fail: count <= N was checked above.
        out.push(row).map_err(|_| Error::BufferLength {
            expected: count,
            got: N,
        })?;
    }
    Ok(out)
}
