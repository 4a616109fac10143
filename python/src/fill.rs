//! Filling caller-owned buffers with consecutive points of a `qmckit::Sampler`, split over
//! threads. Every thread fills whole rows `start + r ..` by random access, so the values do
//! not depend on the number of threads.

use qmckit::Sampler;

/// A sampler shared between fill threads, with its `f64` fill: the sampler's own
/// `fill_as::<f64>` (its batch paths, written straight into the caller's buffer), which a
/// `dyn Sampler` cannot call (it is generic).
pub trait Fill: Sampler + Send + Sync {
    /// `out` (whole rows) with points `start ..` as `f64`, `x / 2^32`.
    ///
    /// # Errors
    /// The sampler's (buffer length, index past its end).
    fn fill_f64(&self, start: u32, out: &mut [f64]) -> qmckit::Result<()>;
}

impl<S: Sampler + Send + Sync> Fill for S {
    fn fill_f64(&self, start: u32, out: &mut [f64]) -> qmckit::Result<()> {
        self.fill_as(start, out)
    }
}

/// A sampler shared between fill threads.
pub type SharedSampler = dyn Fill;

/// Rows below which a fill stays on the calling thread.
const MIN_ROWS_PER_THREAD: usize = 1024;

/// The work on one part of a split fill: `(first_row, rows)`.
pub type Part<'a, T, E> = dyn Fn(usize, &mut [T]) -> Result<(), E> + Sync + 'a;

/// Splits `out` (rows of `dims` values) into at most `workers` contiguous parts of whole
/// rows and runs `part(first_row, slice)` on each, one thread a part. Returns the first
/// error.
pub fn split_rows<T: Send, E: Send>(
    out: &mut [T],
    dims: usize,
    workers: usize,
    part: &Part<'_, T, E>,
) -> Result<(), E> {
    let dims = dims.max(1);
    let rows = out.len() / dims;
    let threads = workers.clamp(1, (rows / MIN_ROWS_PER_THREAD).max(1));
    if threads == 1 {
        return part(0, out);
    }
    let per = rows.div_ceil(threads);
    std::thread::scope(|scope| {
        let mut handles: Vec<std::thread::ScopedJoinHandle<'_, Result<(), E>>> =
            Vec::with_capacity(threads);
        let mut rest = out;
        let mut first = 0;
        while !rest.is_empty() {
            let take = (per * dims).min(rest.len());
            let (head, tail) = rest.split_at_mut(take);
            rest = tail;
            let row = first;
            first += take / dims;
            if rest.is_empty() {
                // The last part runs on this thread.
                let mine = part(row, head);
                let mut result = mine;
                for h in handles {
                    let r: Result<(), E> = match h.join() {
                        Ok(r) => r,
                        Err(p) => std::panic::resume_unwind(p),
                    };
                    if result.is_ok() {
                        result = r;
                    }
                }
                return result;
            }
            handles.push(scope.spawn(move || part(row, head)));
        }
        Ok(())
    })
}

/// Rows `start ..` of `s` into `out` as 0.32 fractions, each value ANDed with `mask`.
///
/// # Errors
/// The sampler's (buffer length, index past its end).
pub fn fill_u32(
    s: &SharedSampler,
    start: u32,
    out: &mut [u32],
    mask: u32,
    workers: usize,
) -> qmckit::Result<()> {
    let dims = s.dims();
    qmckit::sampler::check_fill(s, start, out.len())?;
    split_rows(out, dims, workers, &|row, part: &mut [u32]| {
        // row < rows, so start + row is a valid index (check_fill passed).
        s.fill(start + row as u32, part)?;
        if mask != u32::MAX {
            for x in part.iter_mut() {
                *x &= mask;
            }
        }
        Ok(())
    })
}

/// Rows `start ..` of `s` into `out` as `f64` (`(x & mask) / 2^32`, exact): unmasked, each
/// thread through the sampler's own `f64` fill straight into its rows.
///
/// # Errors
/// The sampler's (buffer length, index past its end).
pub fn fill_f64(
    s: &SharedSampler,
    start: u32,
    out: &mut [f64],
    mask: u32,
    workers: usize,
) -> qmckit::Result<()> {
    let dims = s.dims().max(1);
    qmckit::sampler::check_fill(s, start, out.len())?;
    if mask == u32::MAX {
        return split_rows(out, dims, workers, &|row, part: &mut [f64]| {
            s.fill_f64(start + row as u32, part)
        });
    }
    // Masked: the u32 fill, masked and converted in one pass over a per-thread buffer
    // (one pass over the output instead of two).
    split_rows(out, dims, workers, &|row, part: &mut [f64]| {
        let rows_per_chunk = (CHUNK_VALUES / dims).max(1);
        let mut buf = vec![0u32; (rows_per_chunk * dims).min(part.len())];
        for (c, chunk) in part.chunks_mut(rows_per_chunk * dims).enumerate() {
            let tmp = buf.get_mut(..chunk.len()).unwrap_or(&mut []);
            s.fill(start + (row + c * rows_per_chunk) as u32, tmp)?;
            for (o, &x) in chunk.iter_mut().zip(tmp.iter()) {
                // The bit-pattern conversion (exact, and it vectorizes: no integer to
                // float instruction).
                *o = qmckit::bits::to_f64(x & mask);
            }
        }
        Ok(())
    })
}

/// Values converted per chunk of a masked fill (whole rows; at least one row): 128 KiB
/// of `u32`, in L2, and few enough chunks that a sampler's per-call setup (Sobol's
/// folded affine table: `span` map applications a dimension) does not show.
const CHUNK_VALUES: usize = 1 << 15;
