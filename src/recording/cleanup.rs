//! Removing what an earlier run left in a folder.

use std::path::Path;

use anyhow::Context;

/// Removes every file directly in `dir` whose name ends in `.extension`; returns how many.
pub fn remove_files_with_extension(dir: &Path, extension: &str) -> anyhow::Result<usize> {
    remove_files_where(dir, |path| path.extension().is_some_and(|e| e == extension))
}

/// Removes every file a killed writer left half-written directly in `dir`: names ending
/// in `.partial`, and drawings named `NAME.partial.png` / `.svg`; returns how many.
pub fn remove_partial_files(dir: &Path) -> anyhow::Result<usize> {
    remove_files_where(dir, |path| {
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        name.ends_with(".partial") || name.contains(".partial.")
    })
}

/// Removes every file directly in `dir` that `doomed` picks; returns how many.
fn remove_files_where(dir: &Path, doomed: impl Fn(&Path) -> bool) -> anyhow::Result<usize> {
    let mut removed = 0;
    for entry in std::fs::read_dir(dir).with_context(|| format!("cannot read {}", dir.display()))? {
        let path = entry?.path();
        if doomed(&path) && path.is_file() {
            std::fs::remove_file(&path)
                .with_context(|| format!("cannot remove {}", path.display()))?;
            removed += 1;
        }
    }
    Ok(removed)
}
