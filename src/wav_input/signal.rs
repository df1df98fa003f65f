//! One channel of a WAV file, picked by number or by name, over a chosen span of time, in
//! physical units when the sidecar gives them.

use std::path::Path;

use anyhow::{Context, bail};

use super::float64::read_float64;
use super::sidecar::{SidecarChannel, read_sidecar, sidecar_path};

/// One channel of a WAV file as an analogue signal.
#[derive(Clone, Debug)]
pub struct WavSignal {
    /// Samples in `unit`: the sidecar's scale applied; without a sidecar float files as
    /// stored and integer files scaled to ±1 at full scale.
    pub samples: Vec<f64>,
    /// Sample rate (Hz).
    pub rate_hz: f64,
    /// Channel index (from 0).
    pub channel: usize,
    /// Signal name from the sidecar.
    pub name: Option<String>,
    /// Unit of `samples` (`WAV unit` without a sidecar).
    pub unit: String,
    /// Full scale of the recording in `unit`, where the file or its sidecar tells it.
    pub full_scale: Option<f64>,
}

/// What the sample formats this reader takes are, for error messages.
const FORMATS: &str = "8-, 16-, 24- and 32-bit integer PCM and 32- and 64-bit IEEE float";

/// Reads channel `channel` (a number from 0, or a signal name from the sidecar) of `path`,
/// from `start_s` for `length_s` seconds (to the end when `None`).
pub fn read_signal(
    path: &Path,
    channel: &str,
    start_s: f64,
    length_s: Option<f64>,
) -> anyhow::Result<WavSignal> {
    let (interleaved, channels, rate_hz, integer) = read_interleaved(path)?;
    let sidecar = read_sidecar(path)?;
    let index = channel_index(path, channel, channels, sidecar.as_deref())?;
    let described: Option<&SidecarChannel> = sidecar.as_deref().and_then(|c| c.get(index));
    let scale = described.map_or(1.0, |c| c.scale);
    let full_scale = described
        .and_then(|c| c.full_scale)
        .or_else(|| integer.then_some(scale));
    let frames = interleaved.len() / channels;
    let (first, count) = span(path, frames, rate_hz, start_s, length_s)?;
    let samples = interleaved
        .iter()
        .skip(index + first * channels)
        .step_by(channels)
        .take(count)
        .map(|s| s * scale)
        .collect();
    Ok(WavSignal {
        samples,
        rate_hz,
        channel: index,
        name: described.map(|c| c.name.clone()),
        unit: described.map_or_else(|| "WAV unit".into(), |c| c.unit.clone()),
        full_scale,
    })
}

/// Interleaved samples, channels, rate (Hz) and whether the samples were integers; a file
/// cut short is read to its last whole frame, with a warning.
fn read_interleaved(path: &Path) -> anyhow::Result<(Vec<f64>, usize, f64, bool)> {
    std::fs::File::open(path).with_context(|| format!("{}: cannot read", path.display()))?;
    let mut reader = match hound::WavReader::open(path) {
        Ok(reader) => reader,
        Err(error) => {
            return match read_float64(path) {
                Ok(Some(wav)) => {
                    if let Some((declared, held)) = wav.cut_short {
                        eprintln!(
                            "warning: {}: the file is cut short: its data chunk declares {declared} bytes and holds {held}; the {} whole frames there are read",
                            path.display(),
                            wav.samples.len() / wav.channels
                        );
                    }
                    Ok((wav.samples, wav.channels, wav.rate_hz, false))
                }
                Ok(None) => bail!("{}: {error}; this reader takes {FORMATS}", path.display()),
                Err(e) => Err(e.context(format!("this reader takes WAV files of {FORMATS}"))),
            };
        }
    };
    let spec = reader.spec();
    let declared = reader.len() as usize;
    let (mut samples, stopped): (Vec<f64>, Option<hound::Error>) = match spec.sample_format {
        hound::SampleFormat::Float => read_until_error(reader.samples::<f32>(), f64::from),
        hound::SampleFormat::Int => {
            let full_scale = f64::from(1u32 << (spec.bits_per_sample - 1));
            read_until_error(reader.samples::<i32>(), |v| f64::from(v) / full_scale)
        }
    };
    if let Some(error) = stopped {
        let channels = usize::from(spec.channels).max(1);
        let frames = samples.len() / channels;
        if frames == 0 {
            bail!(
                "{}: the file is cut short: its data chunk declares {declared} samples and holds none whole ({error})",
                path.display()
            );
        }
        eprintln!(
            "warning: {}: the file is cut short: its data chunk declares {declared} samples and holds {}; the {frames} whole frames there are read",
            path.display(),
            samples.len()
        );
        samples.truncate(frames * channels);
    }
    Ok((
        samples,
        usize::from(spec.channels),
        f64::from(spec.sample_rate),
        spec.sample_format == hound::SampleFormat::Int,
    ))
}

/// The samples `read` yields, each through `convert`, up to the first that cannot be read,
/// and that error.
fn read_until_error<T>(
    read: impl Iterator<Item = Result<T, hound::Error>>,
    convert: impl Fn(T) -> f64,
) -> (Vec<f64>, Option<hound::Error>) {
    let mut samples = Vec::new();
    for sample in read {
        match sample {
            Ok(v) => samples.push(convert(v)),
            Err(e) => return (samples, Some(e)),
        }
    }
    (samples, None)
}

/// The index `channel` names: a number, or a name the sidecar lists.
fn channel_index(
    path: &Path,
    channel: &str,
    channels: usize,
    sidecar: Option<&[SidecarChannel]>,
) -> anyhow::Result<usize> {
    if let Ok(index) = channel.parse::<usize>() {
        if index >= channels {
            bail!(
                "--channel {channel}: {} has {channels} channel(s), numbered from 0",
                path.display()
            );
        }
        return Ok(index);
    }
    let Some(described) = sidecar else {
        bail!(
            "--channel {channel}: a channel by name needs the sidecar {}, which is not there; give a number from 0 to {}",
            sidecar_path(path).display(),
            channels - 1
        );
    };
    described
        .iter()
        .position(|c| c.name == channel)
        .filter(|&i| i < channels)
        .with_context(|| {
            let names: Vec<&str> = described.iter().map(|c| c.name.as_str()).collect();
            format!(
                "--channel {channel}: {} holds {}",
                path.display(),
                names.join(", ")
            )
        })
}

/// First frame and frame count of `[start_s, start_s + length_s)` in a file of `frames`.
fn span(
    path: &Path,
    frames: usize,
    rate_hz: f64,
    start_s: f64,
    length_s: Option<f64>,
) -> anyhow::Result<(usize, usize)> {
    let file_s = frames as f64 / rate_hz;
    if !(start_s.is_finite() && start_s >= 0.0 && start_s < file_s) {
        bail!(
            "--start {start_s}: a time in [0, {file_s}) s, the length of {}",
            path.display()
        );
    }
    let first = (start_s * rate_hz).round() as usize;
    let count = match length_s {
        None => frames - first,
        Some(l) if l.is_finite() && l * rate_hz >= 1.0 => {
            ((l * rate_hz).round() as usize).min(frames - first)
        }
        Some(l) if l.is_finite() && l > 0.0 => {
            bail!("--length {l}: shorter than one sample at {rate_hz} Hz")
        }
        Some(l) => bail!("--length {l}: a duration > 0 s"),
    };
    Ok((first, count))
}
