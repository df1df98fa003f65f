//! The rig `--preset NAME --set …` names: every preset is a rig file, so a preset's name
//! is a short name for its built-in file (`builtin_rigs.rs`), and a preset file (a base
//! and the values a calibration set, `preset_file.rs`) is the rig its parameters
//! describe (`rig::preset_rig`). An override is a rig path (`testrig params --rig`) or
//! one of the thesis's names (`testrig params`, also as `rig.set.NAME`): those are set on
//! the preset's parameters and the rig converted from them, then the paths set on it.

use anyhow::Context;

use rig::RigTopology;

use super::builtin_rigs::preset_rig_source;
use super::preset_file::{is_preset_file, param_key, preset_with_overrides};
use super::read_rig_file::rig_topology;
use super::rig_file_toml::RigFileToml;
use super::rig_overrides::{checked_at_path, rig_with_overrides, set_paths};

/// The checked rig of preset `name` (a built-in name, or a preset file's path) with every
/// `NAME=VALUE` or `PATH=VALUE` of `overrides` set, in order within each kind: the
/// thesis's names first, then the rig paths (where a name and a path change the same
/// number, the path's value holds, whatever their order). A value the rig of any topology cannot take is refused
/// at its path (the thesis's plant took a speed loop of 0 Hz as none, negative dampings
/// and a backlash of 0; a rig file takes none of them).
pub fn preset_rig_with_overrides(name: &str, overrides: &[String]) -> anyhow::Result<RigTopology> {
    let (named, paths): (Vec<String>, Vec<String>) = overrides
        .iter()
        .cloned()
        .partition(|item| is_thesis_name(item));
    let mut rig = if is_preset_file(name) || !named.is_empty() {
        preset_topology(name, &preset_with_overrides(name, &named)?)?
    } else {
        rig_topology(&preset_rig_source(name)?)?
    };
    set_paths(&mut rig, &paths)?;
    if !overrides.is_empty() {
        checked_at_path(&rig)
            .with_context(|| format!("--preset {name} with --set {}", overrides.join(" --set ")))?;
    }
    Ok(rig)
}

/// The rig a command names: `--rig FILE` with its `--set PATH=VALUE`s, else `--preset
/// NAME` (a built-in name or a preset file) with its names and paths set.
pub fn command_rig(
    rig_file: Option<&std::path::Path>,
    preset: &str,
    overrides: &[String],
) -> anyhow::Result<RigTopology> {
    match rig_file {
        Some(path) => rig_with_overrides(path, overrides),
        None => preset_rig_with_overrides(preset, overrides),
    }
}

/// Whether `item` (`KEY=VALUE`) sets one of the thesis's parameters by name (as `NAME`,
/// `rig.set.NAME` or `rig.NAME`) rather than a rig path: a rig path has a dot
/// (`mesh.gears.backlash_mm`), a name none, so a mistyped name is refused with the names
/// near it.
pub fn is_thesis_name(item: &str) -> bool {
    !param_key(item).contains('.')
}

/// The rig preset `name`'s parameters `params` describe (`rig::preset_rig`), named and
/// described as [`preset_title`] says.
pub(crate) fn preset_topology(name: &str, params: &rig::RigParams) -> anyhow::Result<RigTopology> {
    let (title, description) = preset_title(name)?;
    Ok(rig::preset_rig(&title, &description, params))
}

/// The name and description of the rig converted from preset `name`: a built-in preset's
/// its file's; a preset file's its stem and path.
pub(crate) fn preset_title(name: &str) -> anyhow::Result<(String, String)> {
    if is_preset_file(name) {
        let stem = std::path::Path::new(name)
            .file_stem()
            .map_or_else(|| name.to_string(), |s| s.to_string_lossy().into_owned());
        return Ok((stem, format!("the preset file {name}")));
    }
    // The file's text alone: the rig itself is built from the parameters.
    let file: RigFileToml = preset_rig_source(name)?.parse_rig_file()?;
    Ok((file.name.into_inner(), file.description.unwrap_or_default()))
}
