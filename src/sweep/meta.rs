//! `sweep.json`: what the table and plots of a sweep folder need besides its cases, so
//! that `merge` can assemble shards without the sweep file.

use std::path::Path;

use anyhow::Context;
use serde::{Deserialize, Serialize};

use rig::RigTopology;
use sha2::{Digest, Sha256};

use super::case_rig::CaseRig;
use super::grid::SweepPlan;
use crate::recording::PartialFile;
use crate::scenario::ScenarioSource;

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
    /// The rig file's rig the sweep runs on (its `name`); none on a preset, whose cases
    /// are held against the thesis.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rig_file: Option<String>,
    /// The published rig the rig file says it is (`rig::RigTopology::reproduces`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reproduces: Option<String>,
    /// SHA-256 of everything that decides the cases' results ([`fingerprint`]): shards
    /// and resumed runs of one sweep share it; `merge` and `--resume` refuse others.
    #[serde(default)]
    pub fingerprint: String,
}

impl SweepMeta {
    /// Whether its healthy cases are held against the thesis (Basmaji 1983, ch. IV): a
    /// preset's sweep, or a rig file's that reproduces the 1983 rig.
    pub fn held_against_thesis(&self) -> bool {
        self.rig_file.is_none() || self.reproduces.as_deref() == Some(RigTopology::BASMAJI_1983)
    }
}

/// The metadata of the sweep `plan` read from `source`: its name, what it sweeps, the
/// whole rig's natural frequencies (of the first case's parameters), its band, its size
/// and fingerprint.
pub fn sweep_meta(source: &ScenarioSource, plan: &SweepPlan) -> SweepMeta {
    let natural_hz = plan
        .cases
        .first()
        .map(|c| c.rig.natural_hz())
        .unwrap_or_default();
    SweepMeta {
        name: plan.name.clone(),
        swept: plan.swept.clone(),
        natural_hz,
        fmax_hz: plan.analyser.settings.fmax_hz,
        cases: plan.cases.len(),
        rig_file: match plan.cases.first().map(|c| &c.rig) {
            Some(CaseRig::File(rig)) => Some(rig.name.clone()),
            _ => None,
        },
        reproduces: match plan.cases.first().map(|c| &c.rig) {
            Some(CaseRig::File(rig)) => rig.reproduces.clone(),
            _ => None,
        },
        fingerprint: fingerprint(&source.text, plan),
    }
}

/// The fingerprint of a sweep: SHA-256 over the sweep file's text as run (with its
/// `--set` edits: grid, seed, case timing, chain, analyser), the first case's rig
/// parameters (a preset file's values included) and the program's version.
pub fn fingerprint(source_text: &str, plan: &SweepPlan) -> String {
    let base = plan.cases.first().map(|c| match &c.rig {
        CaseRig::Preset { params, .. } => format!("{params:?}"),
        CaseRig::File(rig) => format!("{rig:?}"),
    });
    let mut hasher = Sha256::new();
    hasher.update(source_text.as_bytes());
    hasher.update(base.unwrap_or_default().as_bytes());
    hasher.update(env!("CARGO_PKG_VERSION").as_bytes());
    hasher
        .finalize()
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
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
