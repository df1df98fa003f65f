//! One face for every recording of samples (WAV, CSV, UFF58): a frame in (one value per
//! recorded signal, at a time), files and facts out when finished.

use std::path::{Path, PathBuf};

use super::csv_stream::CsvRecorder;

/// What a finished recording leaves behind.
#[derive(Debug, Default)]
pub struct Written {
    /// Its files, complete.
    pub files: Vec<PathBuf>,
    /// Facts for the manifest, by key (e.g. frames written, samples clipped).
    pub facts: Vec<(&'static str, serde_json::Value)>,
}

/// A recording written frame by frame.
pub trait FrameWriter: Send {
    /// Appends one frame: the value of each recorded signal (in its unit) at `time_s`.
    fn write_frame(&mut self, time_s: f64, values: &[f64]) -> anyhow::Result<()>;
    /// Completes the recording's files under their final names.
    fn finish(self: Box<Self>) -> anyhow::Result<Written>;
}

/// A CSV recording: `time_s`, then one column per signal.
pub struct CsvFrames {
    csv: CsvRecorder,
    row: Vec<f64>,
}

impl CsvFrames {
    /// Starts `path` with columns `time_s` and `signals`.
    pub fn create(path: &Path, signals: &[String]) -> anyhow::Result<Self> {
        let mut header = vec!["time_s".to_string()];
        header.extend(signals.iter().cloned());
        Ok(Self {
            csv: CsvRecorder::create(path, &header)?,
            row: Vec::with_capacity(header.len()),
        })
    }
}

impl FrameWriter for CsvFrames {
    fn write_frame(&mut self, time_s: f64, values: &[f64]) -> anyhow::Result<()> {
        self.row.clear();
        self.row.push(time_s);
        self.row.extend_from_slice(values);
        self.csv.write_row(&self.row)
    }

    fn finish(self: Box<Self>) -> anyhow::Result<Written> {
        Ok(Written {
            files: vec![self.csv.finish()?],
            facts: Vec::new(),
        })
    }
}
