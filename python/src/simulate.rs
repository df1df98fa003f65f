//! `testrig.simulate`: a rig alone at a steady point (a preset's, or a rig file's given
//! as a path or as the same tables in a dict), its signals named after its bodies, shafts
//! and meshes as numpy arrays, its impacts and summary: the CLI's `simulate`.

use std::collections::HashMap;

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rig::{column_names, columns};
use testrig::approach_name::approach_named;
use testrig::scenario::{ScenarioSource, preset_rig_with_overrides, source_rig_with_overrides};
use testrig::steady_point::{RigPointRun, RigPointSpec, run_rig_point};

use crate::argument_names::ARGUMENT_NAMES;
use crate::errors::TestrigError;
use crate::interrupt::Interrupt;

/// Runs the plant at `rpm` rev/min and `load_nm` N m, reached by `approach` (`"static"`:
/// in steady motion from the static load; `"rest"`: from standstill; `"up"`/`"down"`: the
/// lab's slow ramp from 250 rev/min or from 2000 rev/min at `ramp_rate` rev/min per s, as
/// `testrig simulate --approach`): `settle_s` s settling (from a ramp's end), then
/// `duration_s` s measured at `rate_hz`. Returns a dict: `signals` (name → array,
/// named after the rig's bodies, shafts and meshes, units in the names), `impacts`
/// (time_s, mesh, flank +1 drive / −1 back, closing_speed_m_s, driver_tooth,
/// driven_tooth), `summary` (the CLI's `simulate --json`). `set` overrides
/// the rig's numbers by path (`testrig params --rig`, `mesh.gears.backlash_mm`) or, on a
/// preset, by the thesis's names too (`testrig params`). `signals=False` keeps no signal
/// (`signals` is then empty): the impacts and the summary alone, as fast as the CLI.
/// `rig` (a rig file's path, or a dict of its tables) runs that rig instead of the
/// preset, as `testrig simulate --rig` does; a preset is the short name of its rig file,
/// so either gives the same signals, impacts and summary for the same rig.
#[pyfunction]
#[pyo3(signature = (rpm, load_nm, preset=rig::DEFAULT_PRESET, settle_s=60.0, duration_s=10.0, rate_hz=51200.0, set=None, signals=true, rig=None, approach="static", ramp_rate=rig::approach::LAB_RAMP_RPM_PER_S))]
#[allow(clippy::too_many_arguments)]
pub fn simulate<'py>(
    py: Python<'py>,
    rpm: f64,
    load_nm: f64,
    preset: &str,
    settle_s: f64,
    duration_s: f64,
    rate_hz: f64,
    set: Option<HashMap<String, Bound<'py, PyAny>>>,
    signals: bool,
    rig: Option<Bound<'py, PyAny>>,
    approach: &str,
    ramp_rate: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let overrides = overrides(set)?;
    let approach = approach_named(approach, rpm, ramp_rate).map_err(crate::errors::to_py)?;
    let (topology, door) = match rig {
        Some(rig) => {
            let (topology, path) = read_rig(&rig, &overrides)?;
            (topology, path.map(|p| ("rig_file", p)))
        }
        None => (
            preset_rig_with_overrides(preset, &overrides)
                .map_err(|e| TestrigError::new_err(format!("{e:#}")))?,
            Some(("preset", preset.to_string())),
        ),
    };
    let spec = RigPointSpec {
        rig: &topology,
        rpm,
        load_nm,
        settle_s,
        duration_s,
        rate_hz,
        approach,
    };
    let names = column_names(&topology);
    let (kept, run, interrupt) = py.detach(|| {
        // Room for the whole window at once: grown by doubling, the columns were copied
        // over and over.
        let samples = if signals {
            (duration_s.max(0.0) * rate_hz.max(0.0)).min(1e9) as usize + 1
        } else {
            0
        };
        let mut kept: Vec<Vec<f64>> = (0..names.len())
            .map(|_| Vec::with_capacity(samples))
            .collect();
        let interrupt = std::cell::RefCell::new(Interrupt::new());
        let run = run_rig_point(
            &spec,
            ARGUMENT_NAMES,
            || interrupt.borrow_mut().check(),
            |block| {
                if signals {
                    for (column, part) in kept.iter_mut().zip(columns(&topology, block)) {
                        column.extend(part);
                    }
                }
                interrupt.borrow_mut().check()
            },
        );
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
    out.set_item("signals", signal_dict)?;
    out.set_item("impacts", impacts_dict(py, &topology, &run)?)?;
    out.set_item("summary", summary_dict(py, &spec, door, &run)?)?;
    Ok(out)
}

/// `set`'s items as `NAME=VALUE` overrides, each value as Python writes it.
fn overrides(set: Option<HashMap<String, Bound<'_, PyAny>>>) -> PyResult<Vec<String>> {
    let mut items: Vec<String> = Vec::new();
    for (name, value) in set.unwrap_or_default() {
        items.push(format!("{name}={}", value.str()?));
    }
    items.sort();
    Ok(items)
}

/// The rig a Python caller names: a path (str or os.PathLike) to a rig file, or a dict
/// of its tables; `overrides` as `PATH=VALUE`. With the file's path, if it was one.
fn read_rig(
    rig: &Bound<'_, PyAny>,
    overrides: &[String],
) -> PyResult<(rig::RigTopology, Option<String>)> {
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
    let path = (!rig.is_instance_of::<PyDict>()).then(|| source.path.display().to_string());
    let topology = source_rig_with_overrides(&source, overrides)
        .map_err(|e| TestrigError::new_err(format!("{e:#}")))?;
    Ok((topology, path))
}

/// The window's impacts, column by column: time, mesh, flank (+1 drive, −1 back), the
/// closing speed along the line of action and the teeth struck.
fn impacts_dict<'py>(
    py: Python<'py>,
    topology: &rig::RigTopology,
    run: &RigPointRun,
) -> PyResult<Bound<'py, PyDict>> {
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
    Ok(impacts)
}

/// The summary as `simulate --json` gives it, as Python objects: `door` the CLI's key
/// for how the rig was named (`preset`, or `rig_file` for a path; neither for a dict).
fn summary_dict<'py>(
    py: Python<'py>,
    spec: &RigPointSpec,
    door: Option<(&str, String)>,
    run: &RigPointRun,
) -> PyResult<Bound<'py, PyAny>> {
    let mut summary =
        serde_json::to_value(&run.summary).map_err(|e| TestrigError::new_err(e.to_string()))?;
    if let Some(map) = summary.as_object_mut() {
        for (key, value) in [
            ("rig", serde_json::json!(spec.rig.name)),
            ("rpm", spec.rpm.into()),
            ("load_nm", spec.load_nm.into()),
            ("settle_s", spec.settle_s.into()),
            ("approach", serde_json::json!(spec.approach)),
            ("simulated_s", run.simulated_s.into()),
            ("wall_s", run.wall_s.into()),
            (
                "realtime_factor",
                (run.simulated_s / run.wall_s.max(1e-9)).into(),
            ),
        ] {
            map.insert(key.to_string(), value);
        }
        if let Some((key, value)) = door {
            map.insert(key.to_string(), value.into());
        }
    }
    let summary = py
        .import("json")?
        .call_method1("loads", (summary.to_string(),))?;
    Ok(summary)
}
