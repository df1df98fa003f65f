//! `sweep.json`: what the table and plots of a sweep folder need besides its cases, so
//! that `merge` can assemble shards without the sweep file.

use std::path::Path;

use anyhow::Context;
use serde::{Deserialize, Serialize};

use crate::recording::PartialFile;

/// What the table and plots need besides the cases (`sweep.json`, so that `merge` can
/// assemble shards without the sweep file).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SweepMeta {
    /// Sweep name.
    pub name: String,
    /// Swept parameter columns.
    pub swept: Vec<String>,
    /// Natural frequencies of the rig (Hz), for the frequency map.
    pub natural_hz: Vec<f64>,
    /// Top of the analysed band (Hz).
    pub fmax_hz: f64,
    /// Number of cases in the whole grid.
    pub cases: usize,
}

/// Writes `dir/sweep.json` whole (under a temporary name until complete).
pub fn write_meta(dir: &Path, meta: &SweepMeta) -> anyhow::Result<()> {
    let file = PartialFile::new(&dir.join("sweep.json"));
    let mut out = file.create()?;
    serde_json::to_writer_pretty(&mut out, meta)?;
    std::io::Write::flush(&mut out)?;
    drop(out);
    file.commit()?;
    Ok(())
}

/// Reads `sweep.json` of a sweep folder.
pub fn read_meta(dir: &Path) -> anyhow::Result<SweepMeta> {
    let path = dir.join("sweep.json");
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("{}: cannot read", path.display()))?;
    serde_json::from_str(&text)
        .with_context(|| format!("{}: not a sweep description", path.display()))
}
