//! `qmckit._qmckit`: the native layer of the Python package. Point generators fill
//! preallocated NumPy arrays in place (module `samplers`); discrepancies run over qmckit's
//! analysis (module `discrepancy`). The Python package (`qmckit`) wraps them in SciPy's
//! `QMCEngine` interface.

use pyo3::prelude::*;

mod discrepancy;
mod error;
mod fill;
mod poisson;
mod samplers;
mod scipy_halton;
mod sobol_owen;
mod truncate;

#[pymodule]
fn _qmckit(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("SOBOL_MAX_DIMS", qmckit::SOBOL_MAX_DIMS)?;
    m.add("HALTON_MAX_DIMS", qmckit::HALTON_MAX_DIMS)?;
    m.add_class::<samplers::NativeSampler>()?;
    m.add_function(wrap_pyfunction!(samplers::sobol, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::halton, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::halton_scipy, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::lattice, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::kronecker, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::faure, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::latin_hypercube, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::pmj02, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::pmj02bn, m)?)?;
    m.add_function(wrap_pyfunction!(samplers::catalog_set, m)?)?;
    m.add_function(wrap_pyfunction!(poisson::poisson_disk, m)?)?;
    m.add_function(wrap_pyfunction!(discrepancy::discrepancy, m)?)?;
    Ok(())
}
