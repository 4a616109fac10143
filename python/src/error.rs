//! qmckit's errors as Python exceptions: every refusal is a `ValueError` carrying qmckit's
//! one-line message.

use pyo3::PyErr;
use pyo3::exceptions::PyValueError;

/// `qmckit::Error` -> `ValueError(message)`.
pub fn to_py(e: qmckit::Error) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// A `ValueError` with `message`.
pub fn value_error(message: impl Into<String>) -> PyErr {
    PyValueError::new_err(message.into())
}
