//! A case's recording: the signals a sweep's `[record]` names, over the case's measured
//! window, written as a run's recording is (`runtime`'s recorder) to
//! `recordings/case-NNNNN.wav` (+ its JSON sidecar), `.csv` and `.uff`.

use std::path::Path;

use anyhow::Context;

use super::grid::{Case, SweepPlan};
use crate::recording::FrameWriter;
use crate::runtime::sinks::recorder::{RecordingSource, recording_writers};
use crate::vocabulary::frame::{Frame, SignalNames};

/// Folder of the cases' recordings inside a sweep's output folder.
pub const RECORDINGS_DIR: &str = "recordings";

/// The recording of one case, frame by frame.
pub struct CaseRecording {
    writers: Vec<Box<dyn FrameWriter>>,
    time: usize,
    channels: Vec<usize>,
    row: Vec<f64>,
}

impl CaseRecording {
    /// Starts the recording of `case` into `sweep_dir/recordings`, its signals found in
    /// `names` (the frames' channels); `None` when the sweep records nothing or runs
    /// without a folder (a calibration).
    pub fn start(
        plan: &SweepPlan,
        case: &Case,
        sweep_dir: Option<&Path>,
        names: &SignalNames,
    ) -> anyhow::Result<Option<Self>> {
        let (Some(record), Some(sweep_dir)) = (&plan.record, sweep_dir) else {
            return Ok(None);
        };
        let index = |name: &str| {
            names
                .index(name)
                .with_context(|| format!("record.signals: `{name}` is not a signal of this case"))
        };
        let channels = record
            .signals
            .iter()
            .map(|s| index(s))
            .collect::<anyhow::Result<_>>()?;
        let dir = sweep_dir.join(RECORDINGS_DIR);
        std::fs::create_dir_all(&dir)
            .with_context(|| format!("{}: cannot create the folder", dir.display()))?;
        let text = format!(
            "{}\n# case {}: {} rev/min, {} N m{}\n",
            plan.text,
            case.index,
            case.rpm,
            case.load_nm,
            case.values
                .iter()
                .zip(&plan.swept)
                .map(|(v, n)| format!(", {n} = {v}"))
                .collect::<String>()
        );
        let source = RecordingSource {
            rate_hz: plan.rate_hz,
            stages: &plan.chain.stages,
            text: &text,
            name: &format!("sweep {} case {}", plan.name, case.index),
        };
        Ok(Some(Self {
            writers: recording_writers(&dir, &case_stem(case.index), &source, record)?,
            time: index("time_s")?,
            channels,
            row: Vec::with_capacity(record.signals.len()),
        }))
    }

    /// Writes every sample of `frame`.
    pub fn write(&mut self, frame: &Frame) -> anyhow::Result<()> {
        for i in 0..frame.len() {
            self.row.clear();
            self.row
                .extend(self.channels.iter().map(|&c| frame.channels[c][i]));
            let time_s = frame.channels[self.time][i];
            for writer in &mut self.writers {
                writer.write_frame(time_s, &self.row)?;
            }
        }
        Ok(())
    }

    /// Completes the files; their paths relative to the sweep's folder.
    pub fn finish(self) -> anyhow::Result<Vec<String>> {
        let mut files = Vec::new();
        for writer in self.writers {
            for path in writer.finish()?.files {
                let name = path.file_name().map_or_else(String::new, |n| {
                    format!("{RECORDINGS_DIR}/{}", n.to_string_lossy())
                });
                files.push(name);
            }
        }
        Ok(files)
    }
}

/// The recordings' file stem of case `index`.
fn case_stem(index: usize) -> String {
    format!("case-{index:05}")
}
