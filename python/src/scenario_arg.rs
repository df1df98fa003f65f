//! A scenario as Python hands it: a path (str or `os.PathLike`), or a dict shaped like
//! the TOML file (turned into TOML text, its path `<dict>` in messages).

use std::collections::HashMap;
use std::path::PathBuf;

use pyo3::prelude::*;
use pyo3::types::PyDict;
use testrig::scenario::{ScenarioSource, apply_override};

use crate::errors::{TestrigError, to_py};

/// The scenario's path (for messages and the manifest) and its text with `set` applied.
pub fn scenario_source(
    scenario: &Bound<'_, PyAny>,
    set: Option<HashMap<String, Bound<'_, PyAny>>>,
) -> PyResult<(PathBuf, ScenarioSource)> {
    let py = scenario.py();
    let (path, mut source) = if let Ok(dict) = scenario.cast::<PyDict>() {
        let json: String = py
            .import("json")?
            .call_method1("dumps", (dict,))?
            .extract()?;
        let value: serde_json::Value = serde_json::from_str(&json)
            .map_err(|e| TestrigError::new_err(format!("scenario dict: {e}")))?;
        let text = toml::to_string(&value)
            .map_err(|e| TestrigError::new_err(format!("scenario dict as TOML: {e}")))?;
        let path = PathBuf::from("<dict>");
        (path.clone(), ScenarioSource { path, text })
    } else {
        let path: PathBuf = py
            .import("os")?
            .call_method1("fspath", (scenario,))?
            .extract()?;
        let source = ScenarioSource::read(&path).map_err(to_py)?;
        (path, source)
    };
    let mut items: Vec<String> = Vec::new();
    for (name, value) in set.unwrap_or_default() {
        items.push(format!("{name}={}", toml_value(&value)?));
    }
    items.sort();
    for item in items {
        source.text = apply_override(&source.text, &item).map_err(to_py)?;
    }
    Ok((path, source))
}

/// A Python value as a TOML value in an override (`KEY=VALUE`).
fn toml_value(value: &Bound<'_, PyAny>) -> PyResult<String> {
    let json: String = value
        .py()
        .import("json")?
        .call_method1("dumps", (value,))?
        .extract()?;
    // A JSON scalar or array is TOML already, but for `null`.
    if json == "null" {
        return Err(TestrigError::new_err("set: None is not a TOML value"));
    }
    Ok(json)
}
