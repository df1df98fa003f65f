//! `testrig` in Python: the module `testrig._testrig`, wrapped by the pure-Python package
//! `testrig` beside it (`python/testrig/`). Each function is the same engine as the CLI's
//! command of the same name.

mod analyse;
mod argument_names;
mod errors;
mod interrupt;
mod live;
mod run;
mod scenario_arg;
mod simulate;

use pyo3::prelude::*;

/// The compiled part of `testrig`.
#[pymodule]
fn _testrig(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("TestrigError", m.py().get_type::<errors::TestrigError>())?;
    m.add_function(wrap_pyfunction!(simulate::simulate, m)?)?;
    m.add_class::<live::Rig>()?;
    m.add_function(wrap_pyfunction!(analyse::analyse, m)?)?;
    m.add_function(wrap_pyfunction!(run::run_into, m)?)?;
    m.add_function(wrap_pyfunction!(run::sweep_into, m)?)?;
    m.add_function(wrap_pyfunction!(run::read_recording, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
