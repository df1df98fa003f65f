//! Values set on a rig by path, after it is read: `--set PATH=VALUE` on a rig file
//! (`rig_with_overrides`), a sweep's or scenario's `[rig] file` with its `[rig.set]` and
//! `[[rig.fault]]`s (`rig_of_file_table`); the result checked, a fault named by its path.

use std::path::Path;

use anyhow::Context;
use rig::RigTopology;
use toml::Spanned;

use super::read_faults::seed_faults;
use super::read_rig_file::{read_rig_file, rig_topology};
use super::rig_fault_place::place_item;
use super::scenario_toml::RigFile;
use super::source::ScenarioSource;

/// Reads the rig file at `path`, sets each `PATH=VALUE` of `overrides` (`--set
/// mesh.stage1.backlash_mm=0.3`), and checks the result; a fault an override brings is
/// named by it.
pub fn rig_with_overrides(path: &Path, overrides: &[String]) -> anyhow::Result<RigTopology> {
    source_rig_with_overrides(&ScenarioSource::read(path)?, overrides)
}

/// Sets each `PATH=VALUE` of `items` on `rig` (`--set mesh.gears.backlash_mm=0.5`: a
/// number by [`RigTopology::set_field`]), in order; the whole rig is checked after.
pub fn set_paths(rig: &mut RigTopology, items: &[String]) -> anyhow::Result<()> {
    for item in items {
        let Some((key, value)) = item.split_once('=') else {
            anyhow::bail!(
                "--set {item}: expected PATH=VALUE (`testrig params --rig` lists the paths)"
            );
        };
        let number: f64 = value
            .trim()
            .parse()
            .map_err(|_| anyhow::anyhow!("--set {item}: `{}` is not a number", value.trim()))?;
        rig.set_field(key.trim(), number)
            .with_context(|| format!("--set {item} (`testrig params --rig` lists the paths)"))?;
    }
    Ok(())
}

/// [`rig_with_overrides`] for a rig file's text (Python's dict of tables, as TOML).
pub fn source_rig_with_overrides(
    src: &ScenarioSource,
    overrides: &[String],
) -> anyhow::Result<RigTopology> {
    let mut rig = rig_topology(src)?;
    set_paths(&mut rig, overrides)?;
    if !overrides.is_empty() {
        checked_at_path(&rig).with_context(|| {
            format!(
                "{} with --set {}",
                src.path.display(),
                overrides.join(" --set ")
            )
        })?;
    }
    Ok(rig)
}

/// The rig of a sweep's `[rig]` table naming a rig file (`file`, relative to the sweep
/// file): its `[rig.set]` paths set (numbers, or a fault's kind by name) and its
/// `[[rig.fault]]`s seeded, checked; a preset or a backlash beside it is refused.
pub fn rig_of_file_table(src: &ScenarioSource, table: &RigFile) -> anyhow::Result<RigTopology> {
    let Some(file) = &table.file else {
        return Err(src.error(0..0, "rig.file", "missing: name the rig file"));
    };
    if let Some(preset) = &table.preset {
        return Err(src.error(
            preset.span(),
            "rig.preset",
            "give either a preset or a rig file, not both",
        ));
    }
    if let Some(backlash) = &table.backlash_mm {
        return Err(src.error(
            backlash.span(),
            "rig.backlash_mm",
            "a rig file's backlash is its mesh's: give rig.set.\"mesh.NAME.backlash_mm\"",
        ));
    }
    let dir = src.path.parent().unwrap_or(Path::new("."));
    let path = dir.join(file.get_ref());
    let mut rig =
        read_rig_file(&path).map_err(|e| src.error(file.span(), "rig.file", format!("{e:#}")))?;
    seed_faults(src, &mut rig, &table.fault)?;
    set_table_paths(src, &mut rig, table.set.iter())?;
    rig.check()
        .map_err(|e| src.error(file.span(), "rig", format!("{}: {e}", path.display())))?;
    Ok(rig)
}

/// Sets each `[rig.set]` entry of `entries` (a rig path and its value) on `rig`, a refusal
/// named at its entry; not checked with the whole rig.
pub fn set_table_paths<'a>(
    src: &ScenarioSource,
    rig: &mut RigTopology,
    entries: impl Iterator<Item = (&'a String, &'a Spanned<toml::Value>)>,
) -> anyhow::Result<()> {
    for (key, value) in entries {
        set_rig_value(rig, key, value.get_ref())
            .map_err(|e| src.error(value.span(), &format!("rig.set.{key}"), e))?;
    }
    Ok(())
}

/// Sets `path` of `rig` to `value`: a number by [`RigTopology::set_field`], a fault's kind
/// by [`RigTopology::set_word`]; not checked with the whole rig.
pub fn set_rig_value(rig: &mut RigTopology, path: &str, value: &toml::Value) -> anyhow::Result<()> {
    match value {
        toml::Value::Float(x) => rig.set_field(path, *x)?,
        toml::Value::Integer(i) => rig.set_field(path, *i as f64)?,
        toml::Value::String(word) => rig.set_word(path, word)?,
        other => anyhow::bail!(
            "{other}: a number, or a tooth fault's kind (`testrig params --rig` lists the paths)"
        ),
    }
    Ok(())
}

/// Checks `rig`, a fault named by its path (`motor.speed_loop_hz`,
/// `mesh.gears.backlash_mm`), as `--set` names it.
pub fn checked_at_path(rig: &RigTopology) -> anyhow::Result<()> {
    rig.check().map_err(|e| {
        let place = &e.place;
        let path = match place_item(rig, place) {
            Some(name) => format!("{}.{name}.{}", place.table, place.field),
            None => format!("{}.{}", place.table, place.field),
        };
        anyhow::anyhow!("{path} {e}")
    })
}
