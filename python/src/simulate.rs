//! `testrig.simulate`: the plant alone at a steady point, its true signals as numpy
//! arrays (one copy: each column is moved into its array), its impacts and summary.

use std::collections::HashMap;

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rig::{COLUMN_NAMES, Flank, SignalBlock};
use testrig::steady_point::{PointRun, PointSpec, approach_named, run_point};

use crate::argument_names::ARGUMENT_NAMES;
use crate::interrupt::Interrupt;

/// Every true signal of the window, column by column in [`COLUMN_NAMES`]' order.
#[derive(Default)]
struct Columns {
    numbers: Vec<Vec<f64>>,
    contact: Vec<i8>,
    tooth: Vec<u32>,
}

impl Columns {
    /// Room for `samples` of every column.
    fn with_capacity(samples: usize) -> Self {
        Self {
            numbers: (0..COLUMN_NAMES.len() - 2)
                .map(|_| Vec::with_capacity(samples))
                .collect(),
            contact: Vec::with_capacity(samples),
            tooth: Vec::with_capacity(samples),
        }
    }

    /// Appends `block`.
    fn extend(&mut self, b: &SignalBlock) {
        let sources = std::iter::once(&b.time_s)
            .chain(&b.angle_rad)
            .chain(&b.speed_rad_s)
            .chain(&b.shaft_torque_nm)
            .chain([&b.mesh_torque_nm, &b.motor_torque_nm]);
        for (column, source) in self.numbers.iter_mut().zip(sources) {
            column.extend_from_slice(source);
        }
        self.contact.extend_from_slice(&b.contact);
        self.tooth.extend_from_slice(&b.tooth);
    }
}

/// Runs the plant at `rpm` rev/min and `load_nm` N m, reached by `approach` (`"static"`:
/// in steady motion from the static load; `"rest"`: from standstill; `"up"`/`"down"`: the
/// lab's slow ramp from 250 rev/min or from 2000 rev/min at `ramp_rate` rev/min per s, as
/// `testrig simulate --approach`): `settle_s` s settling (from a ramp's end), then
/// `duration_s` s measured at `rate_hz`. Returns a dict: `signals` (name → array,
/// units in the names), `impacts` (time_s, flank +1 drive / −1 back, tooth,
/// closing_speed_rad_s), `summary` (the CLI's `simulate --json`). `set` overrides
/// parameters by name (`testrig params`). `signals=False` keeps no signal (`signals`
/// is then empty): the impacts and the summary alone, as fast as the CLI. `rig` (a rig
/// file's path, or a dict of its tables) runs that rig instead of the preset, as
/// `testrig simulate --rig` does; `set` then takes paths
/// (`mesh.stage1.backlash_mm`).
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
    if let Some(rig) = rig {
        let times = (settle_s, duration_s, rate_hz);
        return crate::simulate_rig::simulate_rig(
            py, &rig, &overrides, rpm, load_nm, times, signals, approach,
        );
    }
    let spec = PointSpec {
        preset,
        overrides: &overrides,
        rpm,
        load_nm,
        settle_s,
        duration_s,
        rate_hz,
        approach,
    };
    let samples = if signals {
        (duration_s.max(0.0) * rate_hz.max(0.0)).min(1e9) as usize + 1
    } else {
        0
    };
    let (columns, run, interrupt) = py.detach(|| {
        let mut columns = Columns::with_capacity(samples);
        let interrupt = std::cell::RefCell::new(Interrupt::new());
        let run = run_point(
            &spec,
            ARGUMENT_NAMES,
            || interrupt.borrow_mut().check(),
            |block| {
                if signals {
                    columns.extend(block);
                }
                interrupt.borrow_mut().check()
            },
        );
        let interrupt = interrupt.into_inner();
        (columns, run, interrupt)
    });
    let run = interrupt.result(run)?;
    result_dict(py, &spec, columns, run)
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

/// The dict `simulate` returns.
fn result_dict<'py>(
    py: Python<'py>,
    spec: &PointSpec,
    columns: Columns,
    run: PointRun,
) -> PyResult<Bound<'py, PyDict>> {
    let signals = PyDict::new(py);
    if columns.numbers.first().is_some_and(|c| !c.is_empty()) {
        let numeric = COLUMN_NAMES.iter().take(columns.numbers.len());
        for (name, column) in numeric.zip(columns.numbers) {
            signals.set_item(*name, column.into_pyarray(py))?;
        }
        signals.set_item("contact", columns.contact.into_pyarray(py))?;
        signals.set_item("tooth", columns.tooth.into_pyarray(py))?;
    }
    let impacts = PyDict::new(py);
    let list = run.plant.impacts();
    let times: Vec<f64> = list.iter().map(|i| i.time_s).collect();
    let flanks: Vec<i8> = list
        .iter()
        .map(|i| match i.flank {
            Flank::Drive => 1,
            Flank::Back => -1,
        })
        .collect();
    let teeth: Vec<u32> = list.iter().map(|i| i.tooth).collect();
    let closing: Vec<f64> = list.iter().map(|i| i.closing_speed_rad_s).collect();
    impacts.set_item("time_s", times.into_pyarray(py))?;
    impacts.set_item("flank", flanks.into_pyarray(py))?;
    impacts.set_item("tooth", teeth.into_pyarray(py))?;
    impacts.set_item("closing_speed_rad_s", closing.into_pyarray(py))?;
    let mut summary = serde_json::to_value(&run.summary)
        .map_err(|e| crate::errors::TestrigError::new_err(e.to_string()))?;
    if let Some(map) = summary.as_object_mut() {
        for (key, value) in [
            ("preset", serde_json::json!(spec.preset)),
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
            (
                "condition",
                run.condition
                    .map_or(serde_json::Value::Null, |c| c.to_json()),
            ),
        ] {
            map.insert(key.to_string(), value);
        }
    }
    let json = py.import("json")?;
    let summary = json.call_method1("loads", (summary.to_string(),))?;
    let result = PyDict::new(py);
    result.set_item("signals", signals)?;
    result.set_item("impacts", impacts)?;
    result.set_item("summary", summary)?;
    Ok(result)
}
