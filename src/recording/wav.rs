//! WAV recordings (32-bit float or 24-bit integer, one channel per signal) with a JSON
//! sidecar giving each channel's name, unit and scale. The file is written under
//! `NAME.wav.partial` and takes its final name only when finished.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use anyhow::Context;
use serde::Serialize;

use super::frame_writer::{FrameWriter, Written};
use super::partial::PartialFile;

/// One recorded channel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ChannelInfo {
    /// Signal name.
    pub name: String,
    /// Unit of the physical value.
    pub unit: String,
    /// Physical value of WAV sample 1.0, in `unit` (the full scale for integer files,
    /// 1 for float files, whose samples are the physical values).
    pub scale: f64,
    /// The recording's full scale in `unit` (what `testrig analyse` takes as the ADC's
    /// range by default).
    pub full_scale: f64,
}

/// How samples are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WavSamples {
    /// IEEE float: sample = value / scale (values beyond the scale are kept).
    Float32,
    /// Signed 24-bit: sample = round(value / scale · (2²³ − 1)), clipped at full scale.
    Int24,
}

/// Largest 24-bit sample.
const INT24_FULL: f64 = 8_388_607.0;

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
    samples: WavSamples,
    file: PartialFile,
    frames: u64,
    clipped: u64,
}

impl WavRecorder {
    /// Starts `path` (its sidecar is `path` + `.json`) at `rate_hz` with `channels` as
    /// 32-bit float; `scenario` (text, e.g. the scenario file) goes into the sidecar.
    pub fn create(
        path: &Path,
        rate_hz: u32,
        channels: Vec<ChannelInfo>,
        scenario: &str,
    ) -> anyhow::Result<Self> {
        Self::create_as(path, rate_hz, channels, scenario, WavSamples::Float32)
    }

    /// As [`WavRecorder::create`], storing samples as `samples`.
    pub fn create_as(
        path: &Path,
        rate_hz: u32,
        channels: Vec<ChannelInfo>,
        scenario: &str,
        samples: WavSamples,
    ) -> anyhow::Result<Self> {
        let (bits_per_sample, sample_format, format) = match samples {
            WavSamples::Float32 => (
                32,
                hound::SampleFormat::Float,
                "32-bit float; physical value = sample × scale",
            ),
            WavSamples::Int24 => (
                24,
                hound::SampleFormat::Int,
                "24-bit integer; physical value = sample / 8388607 × scale",
            ),
        };
        let spec = hound::WavSpec {
            channels: u16::try_from(channels.len()).context("too many channels for a WAV file")?,
            sample_rate: rate_hz,
            bits_per_sample,
            sample_format,
        };
        let file = PartialFile::new(path);
        let writer = hound::WavWriter::new(file.create()?, spec)
            .with_context(|| format!("cannot write {}", file.partial_path().display()))?;
        let sidecar = Sidecar {
            sample_rate_hz: rate_hz,
            format,
            channels: &channels,
            scenario,
        };
        let json_path = PathBuf::from(format!("{}.json", path.display()));
        PartialFile::write_whole(&json_path, serde_json::to_string_pretty(&sidecar)?)?;
        Ok(Self {
            writer,
            channels,
            samples,
            file,
            frames: 0,
            clipped: 0,
        })
    }

    /// Appends one frame: one physical value per channel, in channel order.
    pub fn write_frame(&mut self, values: &[f64]) -> anyhow::Result<()> {
        for (value, channel) in values.iter().zip(&self.channels) {
            let relative = value / channel.scale;
            let written = match self.samples {
                WavSamples::Float32 => self.writer.write_sample(relative as f32),
                WavSamples::Int24 => {
                    if relative.abs() > 1.0 {
                        self.clipped += 1;
                    }
                    let sample = (relative.clamp(-1.0, 1.0) * INT24_FULL).round() as i32;
                    self.writer.write_sample(sample)
                }
            };
            written.with_context(|| format!("writing {}", self.file.path().display()))?;
        }
        self.frames += 1;
        Ok(())
    }

    /// Frames written so far.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// Samples clipped at full scale (24-bit only).
    pub fn clipped(&self) -> u64 {
        self.clipped
    }

    /// Closes the file and gives it its final name.
    pub fn finish(self) -> anyhow::Result<PathBuf> {
        let path = self.file.path().display().to_string();
        self.writer
            .finalize()
            .with_context(|| format!("closing {path}"))?;
        self.file.commit()
    }
}

impl FrameWriter for WavRecorder {
    fn write_frame(&mut self, _time_s: f64, values: &[f64]) -> anyhow::Result<()> {
        WavRecorder::write_frame(self, values)
    }

    /// The WAV file and its sidecar; facts `wav_frames` and `wav_clipped_samples`.
    fn finish(self: Box<Self>) -> anyhow::Result<Written> {
        let facts = vec![
            ("wav_frames", self.frames().into()),
            ("wav_clipped_samples", self.clipped().into()),
        ];
        let wav = WavRecorder::finish(*self)?;
        let mut sidecar = wav.clone().into_os_string();
        sidecar.push(".json");
        Ok(Written {
            files: vec![wav, sidecar.into()],
            facts,
        })
    }
}
