//! Ctrl-C during a long call: the engine runs without the GIL and looks for a pending
//! signal about four times a second, stopping with Python's own exception.

use std::time::{Duration, Instant};

use pyo3::prelude::*;

/// How often a running call looks for a pending signal.
const CHECK_EVERY: Duration = Duration::from_millis(250);

/// Looks for pending signals now and then.
pub struct Interrupt {
    last: Instant,
    /// The exception a signal handler raised (KeyboardInterrupt), once one has.
    pub raised: Option<PyErr>,
}

impl Interrupt {
    /// Nothing raised yet.
    pub fn new() -> Self {
        Self {
            last: Instant::now(),
            raised: None,
        }
    }

    /// An error when a signal handler has raised (the call should stop), at most every
    /// [`CHECK_EVERY`].
    pub fn check(&mut self) -> anyhow::Result<()> {
        if self.last.elapsed() < CHECK_EVERY {
            return Ok(());
        }
        self.last = Instant::now();
        if let Err(e) = Python::attach(|py| py.check_signals()) {
            self.raised = Some(e);
            anyhow::bail!("interrupted");
        }
        Ok(())
    }

    /// The call's result as Python sees it: the signal's exception first.
    pub fn result<T>(self, result: anyhow::Result<T>) -> PyResult<T> {
        match (self.raised, result) {
            (Some(raised), _) => Err(raised),
            (None, result) => result.map_err(crate::errors::to_py),
        }
    }
}
