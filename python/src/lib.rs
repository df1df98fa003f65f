//! `testrig` in Python: the module `testrig._testrig`, wrapped by the pure-Python package
//! `testrig` beside it (`python/testrig/`). Each function is the same engine as the CLI's
//! command of the same name.

mod analyse;
mod errors;
mod interrupt;
mod simulate;

use pyo3::prelude::*;

/// The compiled part of `testrig`.
#[pymodule]
fn _testrig(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("TestrigError", m.py().get_type::<errors::TestrigError>())?;
    m.add_function(wrap_pyfunction!(simulate::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(analyse::analyse, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
