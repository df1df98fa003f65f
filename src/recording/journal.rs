//! The journal of a run's finished files: `files.journal` in the output folder, opened
//! when the run starts and given each file's name the moment the file takes its final
//! name ([`super::PartialFile::commit`]), one line each, appended and written through at
//! once. A run that ends writes its manifest and removes the journal; a run killed
//! (`kill -9`, a crash, the machine) leaves it, and the next run into the folder removes
//! exactly the files it names.

use std::io::Write;
use std::path::{Path, PathBuf};

use anyhow::Context;

/// The journal's file name in the output folder.
pub const JOURNAL_NAME: &str = "files.journal";

/// The journal's first line: the scenario whose run keeps it.
const SCENARIO_LINE: &str = "# scenario: ";

/// Opens a journal in `dir` (an existing folder) for a run of scenario `scenario`.
pub fn start_journal(dir: &Path, scenario: &str) -> anyhow::Result<()> {
    let path = dir.join(JOURNAL_NAME);
    std::fs::write(&path, format!("{SCENARIO_LINE}{scenario}\n"))
        .with_context(|| format!("cannot write {}", path.display()))
}

/// The scenario of the run whose journal is in `dir`, if one is.
pub fn journaled_scenario(dir: &Path) -> Option<String> {
    let text = std::fs::read_to_string(dir.join(JOURNAL_NAME)).ok()?;
    Some(
        text.lines()
            .next()
            .and_then(|l| l.strip_prefix(SCENARIO_LINE))
            .unwrap_or("")
            .to_string(),
    )
}

/// Notes `finished` (a file just given its final name) in the journal of its folder, if
/// a run keeps one there. Best effort: a journal that cannot be written loses only the
/// clean-up after a kill, never the file.
pub fn note_finished(finished: &Path) {
    let (Some(dir), Some(name)) = (finished.parent(), finished.file_name()) else {
        return;
    };
    let journal = dir.join(JOURNAL_NAME);
    let Ok(mut file) = std::fs::OpenOptions::new().append(true).open(&journal) else {
        return;
    };
    let _ = writeln!(file, "{}", name.to_string_lossy());
}

/// The files the journal in `dir` names (empty without a journal), as paths in `dir`.
pub fn journaled_files(dir: &Path) -> Vec<PathBuf> {
    std::fs::read_to_string(dir.join(JOURNAL_NAME))
        .unwrap_or_default()
        .lines()
        .filter(|name| {
            !name.is_empty()
                && !name.starts_with('#')
                && !name.contains('/')
                && !name.contains("..")
        })
        .map(|name| dir.join(name))
        .collect()
}

/// Removes the journal of `dir` (its run ended and wrote its manifest).
pub fn end_journal(dir: &Path) -> anyhow::Result<()> {
    let path = dir.join(JOURNAL_NAME);
    match std::fs::remove_file(&path) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
        Err(e) => Err(e).with_context(|| format!("cannot remove {}", path.display())),
    }
}
