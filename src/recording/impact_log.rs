//! `impacts.csv`: every contact start of a run, a row each, as the plant logs them: time,
//! mesh, flank, closing speed along the line of action (m/s), the teeth struck (driver's,
//! driven's). One writer for `simulate` and `run`.

use std::path::{Path, PathBuf};

use rig::{Contact, NetworkImpact, RigTopology};

use super::csv_stream::CsvRecorder;

/// The columns of `impacts.csv`.
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
    /// The rig's mesh names.
    meshes: Vec<String>,
}

impl ImpactLog {
    /// Starts `path` for the impacts of `rig`'s meshes.
    pub fn of_meshes(path: &Path, rig: &RigTopology) -> anyhow::Result<Self> {
        Ok(Self {
            csv: CsvRecorder::create(path, &MESH_COLUMNS.map(String::from))?,
            meshes: rig.meshes.iter().map(|m| m.name.clone()).collect(),
        })
    }

    /// Appends `impacts`.
    pub fn write(&mut self, impacts: &[NetworkImpact]) -> anyhow::Result<()> {
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

    /// Flushes and gives the file its final name.
    pub fn finish(self) -> anyhow::Result<PathBuf> {
        self.csv.finish()
    }
}
