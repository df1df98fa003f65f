//! The package's exception: every refusal of the engine, with the CLI's message (the
//! argument named).

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

create_exception!(
    _testrig,
    TestrigError,
    PyException,
    "A value testrig refuses, or a run that failed; the message names the argument."
);

/// An engine error as a [`TestrigError`] with its whole chain of causes.
pub fn to_py(error: anyhow::Error) -> PyErr {
    TestrigError::new_err(format!("{error:#}"))
}
