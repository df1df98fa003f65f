//! The search's log: one JSON line per evaluation, appended as each generation finishes,
//! so a search interrupted at any point resumes from it.

use std::collections::BTreeMap;
use std::io::{BufRead, Write};
use std::path::{Path, PathBuf};

use anyhow::Context;
use serde::{Deserialize, Serialize};

use super::evaluate::Evaluation;

/// One evaluation as logged.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EvaluationRecord {
    /// Evaluation number within its search (from 0).
    pub evaluation: usize,
    /// Restart (0 is the first run).
    pub restart: usize,
    /// Generation within the restart.
    pub generation: usize,
    /// Coordinates in the unit box.
    pub x: Vec<f64>,
    /// The free parameters' values, by name.
    pub values: BTreeMap<String, String>,
    /// What the evaluation gave.
    #[serde(flatten)]
    pub result: Evaluation,
}

/// The log of shard `index` of `count` in `dir`.
pub fn log_path(dir: &Path, index: usize, count: usize) -> PathBuf {
    if count == 1 {
        dir.join("evaluations.jsonl")
    } else {
        dir.join(format!("evaluations-{index}-of-{count}.jsonl"))
    }
}

/// Every complete record of the log at `path` (none if there is no log). A last line cut
/// short by an interruption is dropped.
pub fn read_log(path: &Path) -> anyhow::Result<Vec<EvaluationRecord>> {
    let file = match std::fs::File::open(path) {
        Ok(f) => f,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(e).with_context(|| format!("{}: cannot read", path.display())),
    };
    let lines: Vec<String> = std::io::BufReader::new(file)
        .lines()
        .collect::<Result<_, _>>()
        .with_context(|| format!("{}: cannot read", path.display()))?;
    let mut records = Vec::with_capacity(lines.len());
    for (i, line) in lines.iter().enumerate() {
        match serde_json::from_str::<EvaluationRecord>(line) {
            Ok(r) => records.push(r),
            Err(_) if i + 1 == lines.len() => break,
            Err(e) => anyhow::bail!(
                "{}:{}: not an evaluation record: {e}",
                path.display(),
                i + 1
            ),
        }
    }
    Ok(records)
}

/// Every log in `dir` (all shards), read.
pub fn read_all_logs(dir: &Path) -> anyhow::Result<Vec<EvaluationRecord>> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .with_context(|| format!("{}: cannot list", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("evaluations") && n.ends_with(".jsonl"))
        })
        .collect();
    paths.sort();
    let mut all = Vec::new();
    for p in paths {
        all.extend(read_log(&p)?);
    }
    Ok(all)
}

/// Rewrites the log at `path` with `records` (dropping a cut-short line), ready to append.
pub fn start_log(path: &Path, records: &[EvaluationRecord]) -> anyhow::Result<std::fs::File> {
    let mut file =
        std::fs::File::create(path).with_context(|| format!("{}: cannot write", path.display()))?;
    append(&mut file, records).with_context(|| format!("{}: cannot write", path.display()))?;
    Ok(file)
}

/// Appends `records`, one line each, and flushes.
pub fn append(file: &mut std::fs::File, records: &[EvaluationRecord]) -> std::io::Result<()> {
    let mut text = String::new();
    for r in records {
        text.push_str(&serde_json::to_string(r).map_err(std::io::Error::other)?);
        text.push('\n');
    }
    file.write_all(text.as_bytes())?;
    file.sync_data()
}
