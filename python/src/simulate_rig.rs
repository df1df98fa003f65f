//! `testrig.simulate(rig=…)`: a rig file's rig (a path, or the same tables as a dict) at a
//! steady point, its signals named after its bodies, shafts and meshes as numpy arrays,
//! its impacts and summary: the CLI's `simulate --rig`.

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rig::{column_names, columns};
use testrig::rig_point::{RigPointRun, RigPointSpec, run_rig_point};
use testrig::scenario::{ScenarioSource, source_rig_with_overrides};

use crate::argument_names::ARGUMENT_NAMES;
use crate::errors::TestrigError;
use crate::interrupt::Interrupt;

/// The rig a Python caller names: a path (str or os.PathLike) to a rig file, or a dict
/// of its tables; `overrides` as `PATH=VALUE`.
fn read_rig(rig: &Bound<'_, PyAny>, overrides: &[String]) -> PyResult<rig::RigTopology> {
    let source = if rig.is_instance_of::<PyDict>() {
        let json: String = rig
            .py()
            .import("json")?
            .call_method1("dumps", (rig,))?
            .extract()?;
        let value: serde_json::Value =
            serde_json::from_str(&json).map_err(|e| TestrigError::new_err(e.to_string()))?;
        let text =
            toml::to_string(&value).map_err(|e| TestrigError::new_err(format!("rig dict: {e}")))?;
        ScenarioSource {
            path: "rig dict".into(),
            text,
        }
    } else {
        let path: std::path::PathBuf = rig
            .py()
            .import("os")?
            .call_method1("fspath", (rig,))?
            .extract::<String>()?
            .into();
        ScenarioSource::read(&path).map_err(|e| TestrigError::new_err(format!("{e:#}")))?
    };
    source_rig_with_overrides(&source, overrides)
        .map_err(|e| TestrigError::new_err(format!("{e:#}")))
}

/// Runs a rig file's rig; the dict `simulate` returns.
#[allow(clippy::too_many_arguments)]
pub fn simulate_rig<'py>(
    py: Python<'py>,
    rig: &Bound<'py, PyAny>,
    overrides: &[String],
    rpm: f64,
    load_nm: f64,
    (settle_s, duration_s, rate_hz): (f64, f64, f64),
    signals: bool,
    approach: rig::Approach,
) -> PyResult<Bound<'py, PyDict>> {
    let topology = read_rig(rig, overrides)?;
    let names = column_names(&topology);
    let (kept, run, interrupt) = py.detach(|| {
        let mut kept: Vec<Vec<f64>> = vec![Vec::new(); names.len()];
        let interrupt = std::cell::RefCell::new(Interrupt::new());
        let spec = RigPointSpec {
            rig: &topology,
            rpm,
            load_nm,
            settle_s,
            duration_s,
            rate_hz,
            approach,
        };
        let run = run_rig_point(&spec, ARGUMENT_NAMES, |block| {
            if signals {
                for (column, part) in kept.iter_mut().zip(columns(&topology, block)) {
                    column.extend(part);
                }
            }
            interrupt.borrow_mut().check()
        });
        (kept, run, interrupt.into_inner())
    });
    let run: RigPointRun = interrupt.result(run)?;
    let out = PyDict::new(py);
    let signal_dict = PyDict::new(py);
    if signals {
        for (name, column) in names.iter().zip(kept) {
            signal_dict.set_item(name, column.into_pyarray(py))?;
        }
    }
    let impacts = PyDict::new(py);
    let list = &run.impacts;
    impacts.set_item(
        "time_s",
        list.iter()
            .map(|i| i.time_s)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    impacts.set_item(
        "mesh",
        list.iter()
            .map(|i| topology.meshes[i.mesh].name.clone())
            .collect::<Vec<_>>(),
    )?;
    impacts.set_item(
        "flank",
        list.iter()
            .map(|i| i.flank.sign())
            .collect::<Vec<i8>>()
            .into_pyarray(py),
    )?;
    impacts.set_item(
        "closing_speed_m_s",
        list.iter()
            .map(|i| i.approach_m_s.abs())
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    for (key, gear) in [("driver_tooth", 0), ("driven_tooth", 1)] {
        impacts.set_item(
            key,
            list.iter()
                .map(|i| i.teeth[gear])
                .collect::<Vec<u32>>()
                .into_pyarray(py),
        )?;
    }
    let mut summary =
        serde_json::to_value(&run.summary).map_err(|e| TestrigError::new_err(e.to_string()))?;
    if let Some(map) = summary.as_object_mut() {
        for (key, value) in [
            ("rig", serde_json::json!(topology.name)),
            ("rpm", rpm.into()),
            ("load_nm", load_nm.into()),
            ("settle_s", settle_s.into()),
            ("approach", serde_json::json!(approach)),
            ("simulated_s", run.simulated_s.into()),
            ("wall_s", run.wall_s.into()),
            (
                "realtime_factor",
                (run.simulated_s / run.wall_s.max(1e-9)).into(),
            ),
        ] {
            map.insert(key.to_string(), value);
        }
    }
    let summary = py
        .import("json")?
        .call_method1("loads", (summary.to_string(),))?;
    out.set_item("signals", signal_dict)?;
    out.set_item("impacts", impacts)?;
    out.set_item("summary", summary)?;
    Ok(out)
}
