//! Point sets in one line (feature `std`), as SciPy users write
//! `qmc.Sobol(d, scramble=True, seed=s).random(n)`: `n` points of `d` dimensions in a
//! `Vec`, row-major or as `[T; D]` arrays, next to the zero-allocation [`Sampler::fill_as`].
//!
//! ```
//! // 1024 scrambled Sobol' points in 3D as f64, row-major (point i is v[3 i..3 i + 3]).
//! let v = qmckit::collect::sobol_scrambled(1024, 3, 7)?;
//! assert_eq!(v.len(), 3 * 1024);
//! assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
//! // Any sampler, as fixed-size arrays of any coordinate type.
//! let h: Vec<[f32; 2]> = qmckit::collect::arrays(&qmckit::Halton::new(2)?, 16)?;
//! assert_eq!(h[1][0], 0.5);
//! assert!((h[1][1] - 1.0 / 3.0).abs() < 1e-7); // rounded down, never up to 1.0
//! # Ok::<(), qmckit::Error>(())
//! ```
//!
//! Cost: one pass of the sampler's batch fill (its sequential fast path), plus the `Vec`
//! of `n d` values, checked against [`crate::size::MAX_ALLOC_BYTES`].

use std::vec::Vec;

use crate::bits::FromFraction;
use crate::digital::sobol::Sobol;
use crate::error::{Error, Result};
use crate::radical_inverse::halton::Halton;
use crate::randomize::digits::DigitScramble;
use crate::randomize::{FastOwen, Scrambled};
use crate::sampler::Sampler;

/// Points `0 .. n` of `sampler`, row-major (`sampler.dims()` values a point), converted to
/// `T` (`f64`, `f32`, `u32`, ...) as [`Sampler::fill_as`] converts.
///
/// # Errors
/// [`Error::IndexOutOfRange`] past the sampler's end, [`Error::TooLarge`] for a buffer past
/// the allocation limit.
pub fn points<T: FromFraction + Default, S: Sampler>(sampler: &S, n: u64) -> Result<Vec<T>> {
    crate::size::end(0, n, sampler.len())?;
    let mut out = crate::size::vec_zeroed(crate::size::coordinates(n, sampler.dims())?)?;
    sampler.fill_as(0, &mut out)?;
    Ok(out)
}

/// Points `0 .. n` of a `D`-dimensional `sampler` as `[T; D]` arrays.
///
/// # Errors
/// [`Error::BufferLength`] when `D != sampler.dims()`; otherwise as [`points`].
pub fn arrays<const D: usize, T: FromFraction + Default, S: Sampler>(
    sampler: &S,
    n: u64,
) -> Result<Vec<[T; D]>> {
    if D != sampler.dims() {
        return Err(Error::BufferLength {
            expected: sampler.dims(),
            got: D,
        });
    }
    let flat: Vec<T> = points(sampler, n)?;
    Ok(flat
        .chunks_exact(D.max(1))
        .map(|p| core::array::from_fn(|k| p[k]))
        .collect())
}

/// `n` Sobol' points of `d` dimensions with hash-based Owen scrambling ([`FastOwen`],
/// seeded by `seed`), as `f64` in `[0, 1)`, row-major: the randomized Sobol' points of
/// SciPy's `scramble=True`, by a different (nested, hash-based) scramble.
///
/// # Errors
/// As [`Sobol::new`] and [`points`].
pub fn sobol_scrambled(n: u64, d: usize, seed: u64) -> Result<Vec<f64>> {
    points(&Scrambled::new(Sobol::new(d)?, FastOwen::new(seed)), n)
}

/// `n` Halton points of `d` dimensions with random digit permutations (seeded by `seed`),
/// as `f64` in `[0, 1)`, row-major, from index 0 (SciPy's `qmc.Halton(scramble=True)`
/// randomizes by digit permutations too).
///
/// # Errors
/// As [`Halton::with_scramble`] and [`points`].
pub fn halton_scrambled(n: u64, d: usize, seed: u64) -> Result<Vec<f64>> {
    points(
        &Halton::with_scramble(d, DigitScramble::Permutations(seed))?,
        n,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn collected_points_are_the_samplers() {
        let s = Scrambled::new(Sobol::new(3).unwrap(), FastOwen::new(9));
        let v = sobol_scrambled(100, 3, 9).unwrap();
        for i in 0..100 {
            for k in 0..3 {
                let x = crate::bits::to_f64(s.sample(i, k).unwrap());
                assert_eq!(v[i as usize * 3 + k], x);
            }
        }
        let h = Halton::with_scramble(2, DigitScramble::Permutations(4)).unwrap();
        let a: Vec<[u32; 2]> = arrays(&h, 50).unwrap();
        assert_eq!(a[49], [h.sample(49, 0).unwrap(), h.sample(49, 1).unwrap()]);
        assert_eq!(
            halton_scrambled(50, 2, 4).unwrap()[98],
            crate::bits::to_f64(a[49][0])
        );
    }

    #[test]
    fn bad_requests_are_errors() {
        let s = Sobol::new(2).unwrap();
        assert!(points::<f64, _>(&s, (1 << 32) + 1).is_err());
        assert!(arrays::<3, f64, _>(&s, 4).is_err());
        assert!(sobol_scrambled(u64::MAX, 2, 0).is_err());
        assert!(points::<f64, _>(&Sobol::new(64).unwrap(), 1 << 32).is_err()); // 2 TiB
    }
}
