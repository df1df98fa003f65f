//! Removing what an earlier run left in a folder.

use std::path::Path;

use anyhow::Context;

/// Removes every file directly in `dir` whose name ends in `.extension`; returns how many.
pub fn remove_files_with_extension(dir: &Path, extension: &str) -> anyhow::Result<usize> {
    let mut removed = 0;
    for entry in std::fs::read_dir(dir).with_context(|| format!("cannot read {}", dir.display()))? {
        let path = entry?.path();
        if path.extension().is_some_and(|e| e == extension) && path.is_file() {
            std::fs::remove_file(&path)
                .with_context(|| format!("cannot remove {}", path.display()))?;
            removed += 1;
        }
    }
    Ok(removed)
}
