//! `testrig.run` and `testrig.sweep`: a scenario or a sweep run into a folder by the
//! CLI's own engine (the same files, byte for byte), and the recordings read back.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use testrig::runtime::{Pace, RunOptions, run_into_folder};
use testrig::scenario::{CommandLine, build};
use testrig::sweep::{Shard, SweepFile, SweepOptions, build_sweep, run_sweep, sweep_meta};
use testrig::wav_input::read_signal;

use crate::errors::to_py;
use crate::scenario_arg::scenario_source;

/// Runs `scenario` unpaced into `out` (the earlier run's files there removed first; a
/// folder of another scenario's run only with `replace`);
/// returns the manifest as JSON text. Ctrl-C stops the run, keeping its files.
#[pyfunction]
#[pyo3(signature = (scenario, out, set=None, seed=None, duration_s=None, replace=false))]
pub fn run_into(
    py: Python<'_>,
    scenario: &Bound<'_, PyAny>,
    out: PathBuf,
    set: Option<HashMap<String, Bound<'_, PyAny>>>,
    seed: Option<u64>,
    duration_s: Option<f64>,
    replace: bool,
) -> PyResult<String> {
    let (path, source) = scenario_source(scenario, set)?;
    let plan = build(&source, CommandLine { duration_s, seed }).map_err(to_py)?;
    let stop = Arc::new(AtomicBool::new(false));
    let options = RunOptions {
        pace: Pace::Max,
        out: out.clone(),
        stop: Arc::clone(&stop),
        console: false,
        control: None,
        replace,
    };
    let outcome = until_done_or_interrupted(py, &stop, move || {
        run_into_folder(&path, &plan, &options).map(|_| ())
    })?;
    outcome.map_err(to_py)?;
    std::fs::read_to_string(out.join("manifest.json")).map_err(|e| {
        to_py(anyhow::anyhow!(
            "{}: {e}",
            out.join("manifest.json").display()
        ))
    })
}

/// Runs `sweep` (a sweep file or dict) into `out` on `jobs` workers (every core if
/// None), skipping the cases finished there when `resume`; its cases.csv there. Ctrl-C
/// starts no further case and keeps those finished.
#[pyfunction]
#[pyo3(signature = (sweep, out, set=None, jobs=None, resume=false))]
pub fn sweep_into(
    py: Python<'_>,
    sweep: &Bound<'_, PyAny>,
    out: PathBuf,
    set: Option<HashMap<String, Bound<'_, PyAny>>>,
    jobs: Option<usize>,
    resume: bool,
) -> PyResult<()> {
    let (_, source) = scenario_source(sweep, set)?;
    let file: SweepFile = source.parse_sweep().map_err(to_py)?;
    let plan = build_sweep(&source, &file).map_err(to_py)?;
    let meta = sweep_meta(&source, &plan);
    let stop = Arc::new(AtomicBool::new(false));
    let options = SweepOptions {
        jobs,
        shard: Shard { index: 0, count: 1 },
        resume,
        out,
        progress: false,
        stop: Some(Arc::clone(&stop)),
    };
    let outcome = until_done_or_interrupted(py, &stop, move || run_sweep(&plan, &meta, &options))?
        .map_err(to_py)?;
    outcome.failures().map_err(to_py)
}

/// Runs `work` without the GIL on a thread of its own, looking for Ctrl-C on this one
/// four times a second: a signal sets `stop` (the run ends early, its files kept) and is
/// raised once the work has ended.
fn until_done_or_interrupted<T: Send + 'static>(
    py: Python<'_>,
    stop: &Arc<AtomicBool>,
    work: impl FnOnce() -> T + Send + 'static,
) -> PyResult<T> {
    let (send, receive) = crossbeam_channel::bounded(1);
    std::thread::spawn(move || {
        let _ = send.send(work());
    });
    let mut raised = None;
    loop {
        let waited = py.detach(|| receive.recv_timeout(Duration::from_millis(250)));
        match waited {
            Ok(result) => {
                return match raised {
                    Some(e) => Err(e),
                    None => Ok(result),
                };
            }
            Err(crossbeam_channel::RecvTimeoutError::Timeout) => {
                if raised.is_none()
                    && let Err(e) = py.check_signals()
                {
                    stop.store(true, Ordering::Relaxed);
                    raised = Some(e);
                }
            }
            Err(crossbeam_channel::RecvTimeoutError::Disconnected) => {
                return Err(to_py(anyhow::anyhow!(
                    "the run's thread ended without a result"
                )));
            }
        }
    }
}

/// The channels of a WAV recording written by testrig, by name (its sidecar's), as
/// arrays in their units, with `rate_hz` and `units`. The file is read as a WAV first,
/// so a file that is none is refused as such, before its sidecar is looked for.
#[pyfunction]
pub fn read_recording<'py>(py: Python<'py>, path: PathBuf) -> PyResult<Bound<'py, PyDict>> {
    let mut first = Some(read_signal(&path, "0", 0.0, None).map_err(to_py)?);
    let sidecar_path = PathBuf::from(format!("{}.json", path.display()));
    let sidecar: serde_json::Value = std::fs::read_to_string(&sidecar_path)
        .map_err(anyhow::Error::from)
        .and_then(|t| Ok(serde_json::from_str(&t)?))
        .map_err(|e| to_py(e.context(format!("{}", sidecar_path.display()))))?;
    let names: Vec<String> = sidecar["channels"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|c| c["name"].as_str().map(str::to_string))
        .collect();
    let channels = PyDict::new(py);
    let units = PyDict::new(py);
    let mut rate_hz = f64::NAN;
    for (index, name) in names.into_iter().enumerate() {
        let signal = match first.take().filter(|_| index == 0) {
            Some(signal) => signal,
            None => read_signal(&path, &name, 0.0, None).map_err(to_py)?,
        };
        rate_hz = signal.rate_hz;
        units.set_item(&name, &signal.unit)?;
        channels.set_item(&name, signal.samples.into_pyarray(py))?;
    }
    let out = PyDict::new(py);
    out.set_item("rate_hz", rate_hz)?;
    out.set_item("channels", channels)?;
    out.set_item("units", units)?;
    Ok(out)
}
