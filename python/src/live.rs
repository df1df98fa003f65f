//! `testrig.Rig`: a live rig paced in real time (or a factor), driven from Python through
//! the panel's own control core: the same commands (`docs/api.md`), the same state, and
//! the latest block of every signal read as numpy arrays. A context manager: leaving the
//! `with` block (normally, by an exception or by Ctrl-C) stops the rig and writes its
//! manifest.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use testrig::panel::{PanelState, ScpiServer, scpi_rack};
use testrig::runtime::{Pace, RunOptions, SharedStatus, run_into_folder_with_status};
use testrig::scenario::{CommandLine, build};
use testrig::vocabulary::{ControlHandle, DEFAULT_LIVE_CEILING, MAX_SIMULATED_S, RigCommand};

use crate::errors::{TestrigError, to_py};
use crate::scenario_arg::scenario_source;

/// A live rig on a thread of its own.
#[pyclass(module = "testrig._testrig")]
pub struct Rig {
    control: ControlHandle,
    status: SharedStatus,
    stop: Arc<AtomicBool>,
    rate_hz: f64,
    out: PathBuf,
    thread: Option<JoinHandle<anyhow::Result<()>>>,
    scpi: Option<ScpiServer>,
}

#[pymethods]
impl Rig {
    /// Starts `scenario` (a path or a dict) live into `out`, paced at `pace` (1: real
    /// time), `set` changing scenario keys, with a SCPI server on `scpi` ("host:port")
    /// if given. It runs until `close()`.
    #[new]
    #[pyo3(signature = (scenario, out, pace=1.0, set=None, scpi=None))]
    fn start(
        scenario: &Bound<'_, PyAny>,
        out: PathBuf,
        pace: f64,
        set: Option<HashMap<String, Bound<'_, PyAny>>>,
        scpi: Option<String>,
    ) -> PyResult<Self> {
        if !(pace.is_finite() && (1e-3..=1e6).contains(&pace)) {
            return Err(TestrigError::new_err(format!(
                "pace {pace}: 1 for real time, or a factor from 0.001 to 1e6"
            )));
        }
        let (path, source) = scenario_source(scenario, set)?;
        let mut plan = build(&source, CommandLine::default()).map_err(to_py)?;
        let ceiling = *plan.live_ceiling.get_or_insert(DEFAULT_LIVE_CEILING);
        plan.duration_s = MAX_SIMULATED_S;
        let (control, requests) = ControlHandle::new();
        let status = SharedStatus::default();
        let scpi = match scpi {
            Some(address) => {
                let address: std::net::SocketAddr = address.parse().map_err(|e| {
                    TestrigError::new_err(format!("scpi {address}: not host:port ({e})"))
                })?;
                let rack = scpi_rack(&plan, ceiling, control.clone(), status.clone());
                Some(ScpiServer::start(address, rack).map_err(to_py)?)
            }
            None => None,
        };
        let stop = Arc::new(AtomicBool::new(false));
        let options = RunOptions {
            pace: Pace::Factor(pace),
            out: out.clone(),
            stop: Arc::clone(&stop),
            console: false,
            control: Some(requests),
            replace: false,
        };
        let rate_hz = plan.rate_hz;
        let shared = status.clone();
        let thread = std::thread::Builder::new()
            .name("testrig-rig".into())
            .spawn(move || run_into_folder_with_status(&path, &plan, &options, shared).map(|_| ()))
            .map_err(|e| to_py(anyhow::anyhow!("cannot start the rig: {e}")))?;
        Ok(Self {
            control,
            status,
            stop,
            rate_hz,
            out,
            thread: Some(thread),
            scpi,
        })
    }

    /// The SCPI server's VISA address (`TCPIP::127.0.0.1::5025::SOCKET`), if it has one.
    #[getter]
    fn scpi_address(&self) -> Option<String> {
        self.scpi
            .as_ref()
            .map(|s| format!("TCPIP::{}::{}::SOCKET", s.address.ip(), s.address.port()))
    }

    /// Sends one command (a dict as the panel's API takes it, e.g. `{"cmd": "set_speed",
    /// "rpm": 1300}`) and waits for the rig to carry it out; returns the reply (`ok`,
    /// `at_s` the virtual time it took effect, `error`). Raises `TestrigError` when refused.
    fn send<'py>(&self, command: &Bound<'py, PyDict>) -> PyResult<Bound<'py, PyDict>> {
        let py = command.py();
        let json: String = py
            .import("json")?
            .call_method1("dumps", (command,))?
            .extract()?;
        let command: RigCommand = serde_json::from_str(&json)
            .map_err(|e| TestrigError::new_err(format!("not a command: {e}")))?;
        let control = self.control.clone();
        let reply = py.detach(move || control.send(command));
        if !reply.ok {
            return Err(TestrigError::new_err(reply.error.unwrap_or_default()));
        }
        let reply =
            serde_json::to_string(&reply).map_err(|e| TestrigError::new_err(e.to_string()))?;
        py.import("json")?
            .call_method1("loads", (reply,))?
            .cast_into::<PyDict>()
            .map_err(|e| TestrigError::new_err(e.to_string()))
    }

    /// The rig's state as the panel shows it (`GET /api/state`): set points, meters,
    /// averages, the analyser's display, the scope's trace, overruns, the judged motion.
    fn state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let state = PanelState::of(&self.status.snapshot(), self.rate_hz);
        let json =
            serde_json::to_string(&state).map_err(|e| TestrigError::new_err(e.to_string()))?;
        py.import("json")?.call_method1("loads", (json,))
    }

    /// The latest block of every signal (plant and chain) as arrays in their units, with
    /// `start_s` (the virtual time of its first sample) and `rate_hz`; None before the
    /// first block.
    fn read<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(latest) = self.status.snapshot().latest else {
            return Ok(None);
        };
        let channels = PyDict::new(py);
        for (name, samples) in latest.names.iter().zip(&latest.channels) {
            channels.set_item(name, samples.to_vec().into_pyarray(py))?;
        }
        let out = PyDict::new(py);
        out.set_item("start_s", latest.start_sample as f64 / self.rate_hz)?;
        out.set_item("rate_hz", self.rate_hz)?;
        out.set_item("channels", channels)?;
        Ok(Some(out))
    }

    /// Stops the rig, closes its files and writes its manifest; returns the output
    /// folder. Calling it again does nothing.
    fn close(&mut self, py: Python<'_>) -> PyResult<PathBuf> {
        if let Some(scpi) = self.scpi.take() {
            py.detach(move || scpi.shut_down());
        }
        self.stop.store(true, Ordering::Relaxed);
        if let Some(thread) = self.thread.take() {
            let joined = py.detach(move || thread.join());
            match joined {
                Ok(result) => result.map_err(to_py)?,
                Err(_) => return Err(to_py(anyhow::anyhow!("the rig's thread panicked"))),
            }
        }
        Ok(self.out.clone())
    }

    fn __enter__(slf: Py<Self>) -> Py<Self> {
        slf
    }

    #[pyo3(signature = (*_args))]
    fn __exit__(
        &mut self,
        py: Python<'_>,
        _args: &Bound<'_, pyo3::types::PyTuple>,
    ) -> PyResult<bool> {
        self.close(py)?;
        Ok(false)
    }
}

impl Drop for Rig {
    /// A rig dropped without `close()` stops all the same.
    fn drop(&mut self) {
        if let Some(scpi) = self.scpi.take() {
            scpi.shut_down();
        }
        self.stop.store(true, Ordering::Relaxed);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}
