//! Reading one channel of a WAV file as the analogue signal.

use std::path::Path;

use anyhow::{Context, bail};

/// One channel of a WAV file.
pub struct WavChannel {
    /// Samples: float files as stored, integer files scaled to ±1 full scale.
    pub samples: Vec<f64>,
    /// Sample rate (Hz).
    pub rate_hz: f64,
}

/// Reads channel `channel` of the WAV file at `path`.
pub fn read_channel(path: &Path, channel: usize) -> anyhow::Result<WavChannel> {
    let mut reader = hound::WavReader::open(path)
        .with_context(|| format!("{}: cannot read as WAV", path.display()))?;
    let spec = reader.spec();
    let channels = usize::from(spec.channels);
    if channel >= channels {
        bail!(
            "--channel {channel}: {} has {channels} channel(s), numbered from 0",
            path.display()
        );
    }
    let all: Vec<f64> = match spec.sample_format {
        hound::SampleFormat::Float => reader
            .samples::<f32>()
            .map(|s| s.map(f64::from))
            .collect::<Result<_, _>>(),
        hound::SampleFormat::Int => {
            let full_scale = f64::from(1u32 << (spec.bits_per_sample - 1));
            reader
                .samples::<i32>()
                .map(|s| s.map(|v| f64::from(v) / full_scale))
                .collect::<Result<_, _>>()
        }
    }
    .with_context(|| format!("{}: damaged sample data", path.display()))?;
    Ok(WavChannel {
        samples: all
            .iter()
            .skip(channel)
            .step_by(channels)
            .copied()
            .collect(),
        rate_hz: f64::from(spec.sample_rate),
    })
}
