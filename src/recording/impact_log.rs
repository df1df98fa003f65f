//! `impacts.csv`: every contact start of a run, a row each, as its plant logs them — the
//! thesis's plant: time, flank, the driving gear's tooth, closing speed (rad/s of relative
//! rotation); a rig file's: time, mesh, flank, closing speed along the line of action
//! (m/s), the teeth struck (driver's, driven's). One writer for `simulate`, `simulate
//! --rig` and `run`.

use std::path::{Path, PathBuf};

use rig::{Contact, Impact, NetworkImpact, RigTopology};

use super::csv_stream::CsvRecorder;
use crate::vocabulary::frame::FrameImpacts;

/// The columns of the thesis's plant's impacts.
const GEAR_COLUMNS: [&str; 4] = ["time_s", "flank", "tooth", "closing_speed_rad_s"];

/// The columns of a rig file's plant's impacts.
const MESH_COLUMNS: [&str; 6] = [
    "time_s",
    "mesh",
    "flank",
    "closing_speed_m_s",
    "driver_tooth",
    "driven_tooth",
];

/// An `impacts.csv` being written.
pub struct ImpactLog {
    csv: CsvRecorder,
    /// The rig file's mesh names (empty for the thesis's plant).
    meshes: Vec<String>,
}

impl ImpactLog {
    /// Starts `path` for the thesis's plant's impacts.
    pub fn of_gears(path: &Path) -> anyhow::Result<Self> {
        Ok(Self {
            csv: CsvRecorder::create(path, &GEAR_COLUMNS.map(String::from))?,
            meshes: Vec::new(),
        })
    }

    /// Starts `path` for the impacts of `rig`'s meshes.
    pub fn of_meshes(path: &Path, rig: &RigTopology) -> anyhow::Result<Self> {
        Ok(Self {
            csv: CsvRecorder::create(path, &MESH_COLUMNS.map(String::from))?,
            meshes: rig.meshes.iter().map(|m| m.name.clone()).collect(),
        })
    }

    /// Appends the thesis's plant's `impacts`.
    pub fn write_gears(&mut self, impacts: &[Impact]) -> anyhow::Result<()> {
        impacts.iter().try_for_each(|i| self.csv.write_row(i))
    }

    /// Appends a rig file's plant's `impacts`.
    pub fn write_meshes(&mut self, impacts: &[NetworkImpact]) -> anyhow::Result<()> {
        for i in impacts {
            let flank = if i.flank == Contact::Drive {
                "drive"
            } else {
                "back"
            };
            let mesh = self.meshes.get(i.mesh).map_or("", String::as_str);
            self.csv.write_row(&[
                i.time_s.to_string(),
                mesh.to_string(),
                flank.to_string(),
                i.approach_m_s.abs().to_string(),
                i.teeth[0].to_string(),
                i.teeth[1].to_string(),
            ])?;
        }
        Ok(())
    }

    /// Appends a frame's impacts.
    pub fn write(&mut self, impacts: &FrameImpacts) -> anyhow::Result<()> {
        match impacts {
            FrameImpacts::Gears(i) => self.write_gears(i),
            FrameImpacts::Meshes(i) => self.write_meshes(i),
        }
    }

    /// Flushes and gives the file its final name.
    pub fn finish(self) -> anyhow::Result<PathBuf> {
        self.csv.finish()
    }
}
