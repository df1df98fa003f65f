//! A run into a folder that holds an earlier run: the earlier run's files (those its
//! `manifest.json` lists, the manifest itself, and any `.partial` file a killed run left)
//! are removed first, so old spectra never stand beside new ones. Files the manifest does
//! not list are the user's and stay.

use std::path::Path;

use anyhow::Context;

use crate::recording::remove_files_with_extension;

/// Removes the files of the run recorded in `dir/manifest.json`; returns how many.
/// A folder that does not exist yet holds nothing to remove.
pub fn clear_previous_run(dir: &Path) -> anyhow::Result<usize> {
    let mut removed = 0;
    if !dir.is_dir() {
        return Ok(0);
    }
    let manifest = dir.join("manifest.json");
    if let Ok(text) = std::fs::read_to_string(&manifest) {
        let listed: serde_json::Value = serde_json::from_str(&text).with_context(|| {
            format!(
                "{}: an earlier run's manifest that cannot be read; move it away or choose another --out",
                manifest.display()
            )
        })?;
        let names = listed["files"].as_array().into_iter().flatten();
        for name in names.filter_map(serde_json::Value::as_str) {
            let path = dir.join(name);
            if path.starts_with(dir) && !name.contains("..") && path.is_file() {
                std::fs::remove_file(&path)
                    .with_context(|| format!("cannot remove {}", path.display()))?;
                removed += 1;
            }
        }
    }
    Ok(removed + remove_files_with_extension(dir, "partial")?)
}
