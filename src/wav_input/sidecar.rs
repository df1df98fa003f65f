//! The JSON sidecar `testrig run` writes beside `recording.wav` (`recording.wav.json`):
//! each channel's name, unit, the scale from WAV sample to physical value, and the
//! recording's full scale.

use std::path::{Path, PathBuf};

use anyhow::Context;
use serde::Deserialize;

/// One channel as the sidecar describes it.
#[derive(Clone, Debug, Deserialize)]
pub struct SidecarChannel {
    /// Signal name.
    pub name: String,
    /// Unit of the physical value.
    pub unit: String,
    /// Physical value of WAV sample 1.0.
    pub scale: f64,
    /// Full scale of the recording (in `unit`); absent in sidecars before it was written.
    #[serde(default)]
    pub full_scale: Option<f64>,
}

#[derive(Debug, Deserialize)]
struct Sidecar {
    channels: Vec<SidecarChannel>,
}

/// The sidecar of `wav` (`wav` + `.json`).
pub fn sidecar_path(wav: &Path) -> PathBuf {
    PathBuf::from(format!("{}.json", wav.display()))
}

/// The channels of the sidecar beside `wav`; `None` when there is none.
pub fn read_sidecar(wav: &Path) -> anyhow::Result<Option<Vec<SidecarChannel>>> {
    let path = sidecar_path(wav);
    let Ok(text) = std::fs::read_to_string(&path) else {
        return Ok(None);
    };
    let sidecar: Sidecar = serde_json::from_str(&text)
        .with_context(|| format!("{}: not a testrig WAV sidecar", path.display()))?;
    Ok(Some(sidecar.channels))
}
