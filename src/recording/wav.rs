//! WAV recordings (32-bit float, one channel per signal) with a JSON sidecar giving each
//! channel's name, unit and scale. The file is written under `NAME.wav.partial` and takes
//! its final name only when finished, so no half-written file carries a final name.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use anyhow::Context;
use serde::Serialize;

/// One recorded channel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ChannelInfo {
    /// Signal name.
    pub name: String,
    /// Unit of the physical value.
    pub unit: String,
    /// Physical value at full scale (WAV sample 1.0), in `unit`.
    pub scale: f64,
}

#[derive(Serialize)]
struct Sidecar<'a> {
    sample_rate_hz: u32,
    format: &'static str,
    channels: &'a [ChannelInfo],
    scenario: &'a str,
}

/// A WAV file being written, frame by frame.
pub struct WavRecorder {
    writer: hound::WavWriter<BufWriter<File>>,
    channels: Vec<ChannelInfo>,
    partial: PathBuf,
    path: PathBuf,
    frames: u64,
}

impl WavRecorder {
    /// Starts `path` (its sidecar is `path` + `.json`) at `rate_hz` with `channels`;
    /// `scenario` (text, e.g. the scenario file) goes into the sidecar.
    pub fn create(
        path: &Path,
        rate_hz: u32,
        channels: Vec<ChannelInfo>,
        scenario: &str,
    ) -> anyhow::Result<Self> {
        let partial = path.with_extension("wav.partial");
        let spec = hound::WavSpec {
            channels: u16::try_from(channels.len()).context("too many channels for a WAV file")?,
            sample_rate: rate_hz,
            bits_per_sample: 32,
            sample_format: hound::SampleFormat::Float,
        };
        let writer = hound::WavWriter::create(&partial, spec)
            .with_context(|| format!("cannot write {}", partial.display()))?;
        let sidecar = Sidecar {
            sample_rate_hz: rate_hz,
            format: "32-bit float; physical value = sample × scale",
            channels: &channels,
            scenario,
        };
        let json_path = PathBuf::from(format!("{}.json", path.display()));
        std::fs::write(&json_path, serde_json::to_string_pretty(&sidecar)?)
            .with_context(|| format!("cannot write {}", json_path.display()))?;
        Ok(Self {
            writer,
            channels,
            partial,
            path: path.to_path_buf(),
            frames: 0,
        })
    }

    /// Appends one frame: one physical value per channel, in channel order.
    pub fn write_frame(&mut self, values: &[f64]) -> anyhow::Result<()> {
        for (value, channel) in values.iter().zip(&self.channels) {
            self.writer
                .write_sample((value / channel.scale) as f32)
                .context("writing a WAV sample")?;
        }
        self.frames += 1;
        Ok(())
    }

    /// Frames written so far.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// Closes the file and gives it its final name.
    pub fn finish(self) -> anyhow::Result<PathBuf> {
        self.writer.finalize().context("closing the WAV file")?;
        std::fs::rename(&self.partial, &self.path)
            .with_context(|| format!("naming {}", self.path.display()))?;
        Ok(self.path)
    }
}
