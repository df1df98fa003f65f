//! A run into a folder that holds an earlier run: the earlier run's files are removed
//! first, so old spectra never stand beside new ones: those its `manifest.json` lists
//! (a run that ended), those its journal of finished files names (a run killed before its
//! manifest, `recording::journal`), and any half-written file. Files neither lists are
//! the user's and stay. A folder holding another scenario's run is refused unless the
//! caller says to replace it (`--replace`): a rerun of the same scenario replaces its own.

use std::path::{Path, PathBuf};

use anyhow::Context;

use crate::recording::{JOURNAL_NAME, journaled_files, journaled_scenario, remove_partial_files};

/// The file that marks a sweep's folder (`testrig sweep`, `merge`, `calibrate`'s cases).
const SWEEP_MARKER: &str = "sweep.json";

/// Removes the files of the run recorded in `dir` (its manifest and its journal) before a
/// run of scenario `scenario`; returns how many. A folder that does not exist yet holds
/// nothing to remove; one holding another scenario's run is refused unless `replace`.
pub fn clear_previous_run(dir: &Path, scenario: &str, replace: bool) -> anyhow::Result<usize> {
    if !dir.is_dir() {
        return Ok(0);
    }
    if let Ok(text) = std::fs::read_to_string(dir.join(SWEEP_MARKER)) {
        let name = serde_json::from_str::<serde_json::Value>(&text)
            .ok()
            .and_then(|v| v["name"].as_str().map(str::to_string))
            .unwrap_or_default();
        anyhow::bail!(
            "--out {}: holds a sweep's cases (`{name}`, its {SWEEP_MARKER}); a sweep lists no files to replace: choose another folder",
            dir.display()
        );
    }
    let (listed, earlier) = manifest_files(dir)?;
    let earlier = earlier.or_else(|| journaled_scenario(dir));
    if let Some(earlier) = earlier.filter(|e| e != scenario && !replace) {
        anyhow::bail!(
            "--out {}: holds the files of another run (scenario `{earlier}`); pass --replace to remove them (only the files its manifest or journal lists), or choose another folder",
            dir.display()
        );
    }
    let mut doomed = listed;
    doomed.extend(journaled_files(dir));
    doomed.push(dir.join(JOURNAL_NAME));
    let mut removed = 0;
    for path in doomed {
        if path.is_file() {
            std::fs::remove_file(&path)
                .with_context(|| format!("cannot remove {}", path.display()))?;
            removed += 1;
        }
    }
    Ok(removed + remove_partial_files(dir)?)
}

/// The scenario (or command) of the run whose manifest is in `dir`, if one is.
pub fn manifest_scenario(dir: &Path) -> Option<String> {
    manifest_files(dir).ok()?.1
}

/// The files `dir/manifest.json` lists, as paths in `dir`, and the scenario it ran
/// (nothing without a manifest).
fn manifest_files(dir: &Path) -> anyhow::Result<(Vec<PathBuf>, Option<String>)> {
    let manifest = dir.join("manifest.json");
    let Ok(text) = std::fs::read_to_string(&manifest) else {
        return Ok((Vec::new(), None));
    };
    let listed: serde_json::Value = serde_json::from_str(&text).with_context(|| {
        format!(
            "{}: an earlier run's manifest that cannot be read; move it away or choose another --out",
            manifest.display()
        )
    })?;
    let files = listed["files"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(serde_json::Value::as_str)
        .filter(|name| !name.contains(".."))
        .map(|name| dir.join(name))
        .filter(|path| path.starts_with(dir))
        .collect();
    let scenario = listed["scenario"].as_str().map(str::to_string);
    Ok((files, scenario))
}
