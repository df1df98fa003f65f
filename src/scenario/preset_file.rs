//! Presets from files: a built-in preset and the values that differ from it, as
//! `testrig calibrate` writes them (comments say where they come from). Every command that takes a preset name takes the path
//! of such a file (ending in `.toml`) too.
//!
//! ```toml
//! base = "basmaji-1983"
//! [set]
//! brake_drag_nm = 0.3
//! mesh_pairs = "alternating"
//! ```

use std::collections::BTreeMap;
use std::path::Path;

use anyhow::{Context, bail};
use rig::RigParams;
use serde::Deserialize;
use toml::Spanned;

use super::source::ScenarioSource;

/// The file as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct PresetFile {
    /// A built-in preset the values start from.
    base: Spanned<String>,
    /// Values by `testrig params` name.
    #[serde(default)]
    set: BTreeMap<String, Spanned<toml::Value>>,
}

/// Whether `name` names a preset file rather than a built-in preset.
pub fn is_preset_file(name: &str) -> bool {
    name.ends_with(".toml")
}

/// The parameters of preset `name`: a built-in name, or a file's path (relative to `dir`).
/// Errors name the file, line and field.
pub fn preset_params(name: &str, dir: &Path) -> anyhow::Result<RigParams> {
    if !is_preset_file(name) {
        return Ok(rig::preset(name)?);
    }
    let source = ScenarioSource::read(&dir.join(name))?;
    let file: PresetFile = source.parse_calibration()?;
    let mut params =
        rig::preset(file.base.get_ref()).map_err(|e| source.error(file.base.span(), "base", e))?;
    for (key, value) in &file.set {
        let text = match value.get_ref() {
            toml::Value::String(s) => s.clone(),
            other => other.to_string(),
        };
        rig::set_param(&mut params, key, &text)
            .map_err(|e| source.error(value.span(), &format!("set.{key}"), e))?;
    }
    params
        .validate()
        .map_err(|e| source.error(0..0, "set", e))?;
    Ok(params)
}

/// The parameters of preset `name` (as `preset_params`, relative to the working folder)
/// with every `NAME=VALUE` override applied in order, as `--set` gives them. The names
/// are those of `testrig params` (stored or derived, such as `backlash_mm`), also in the
/// scenario forms `rig.set.NAME` and `rig.NAME`.
pub fn preset_with_overrides(name: &str, overrides: &[String]) -> anyhow::Result<RigParams> {
    let mut params = preset_params(name, Path::new(".")).context("--preset")?;
    for item in overrides {
        let Some((_, value)) = item.split_once('=') else {
            bail!("--set {item}: expected NAME=VALUE (`testrig params` lists the names)");
        };
        rig::set_param(&mut params, param_key(item), value.trim())
            .with_context(|| format!("--set {item}"))?;
    }
    Ok(params)
}

/// The name an override `NAME=VALUE` sets (also written `rig.set.NAME` or `rig.NAME`, as
/// a scenario's keys), trimmed.
pub fn param_key(item: &str) -> &str {
    let key = item.split_once('=').map_or(item, |(key, _)| key).trim();
    key.strip_prefix("rig.set.")
        .or_else(|| key.strip_prefix("rig."))
        .unwrap_or(key)
}
