//! Poisson-disk sets from qmckit's Bridson sampler (`qmckit::blue_noise::PoissonDisk`):
//! points of the unit cube at least `radius` apart, returned as a new NumPy array (the
//! set's buffer handed to NumPy, not copied).

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use qmckit::blue_noise::PoissonDisk;
use qmckit::work::Budget;

use crate::error::to_py;

/// The Poisson-disk set of `seed` in `[0, 1)^d` (1 <= d <= 8): Bridson's algorithm with
/// `candidates` trials a point (on the sphere of radius `1.001 radius` when `surface`,
/// else in the shell `radius .. 2 radius`), run until no active point remains. `(n, d)`
/// float64.
#[pyfunction]
#[pyo3(signature = (d, radius, candidates = 30, seed = 0, surface = false))]
pub fn poisson_disk<'py>(
    py: Python<'py>,
    d: usize,
    radius: f64,
    candidates: u32,
    seed: u64,
    surface: bool,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let builder = PoissonDisk::new(d, radius)
        .and_then(|p| p.candidates(candidates))
        .map_err(to_py)?
        .seed(seed)
        .surface(surface);
    let set = py
        .detach(move || builder.generate(&Budget::DEFAULT))
        .map_err(to_py)?;
    let n = set.count();
    PyArray1::from_vec(py, set.to_f64()).reshape([n, d])
}
