//! 64-bit IEEE float WAV files (scipy's default for float64 arrays), which hound does not
//! read: the RIFF chunks are walked by hand, the `fmt ` chunk checked and the `data` chunk
//! read as little-endian f64.

use std::path::Path;

use anyhow::{Context, bail};

/// Interleaved samples, channel count and sample rate (Hz) of a 64-bit float WAV file;
/// `None` when the file is a WAV of another sample format.
pub struct Float64Wav {
    /// Interleaved samples as stored.
    pub samples: Vec<f64>,
    /// Channels per frame.
    pub channels: usize,
    /// Frames per second (Hz).
    pub rate_hz: f64,
    /// When the file is cut short: the `data` chunk's declared and held bytes (the
    /// whole frames held are read).
    pub cut_short: Option<(usize, usize)>,
}

/// WAVE_FORMAT_IEEE_FLOAT.
const IEEE_FLOAT: u16 = 3;
/// WAVE_FORMAT_EXTENSIBLE: the real format tag opens the sub-format GUID.
const EXTENSIBLE: u16 = 0xFFFE;

/// Reads `path` when it is a 64-bit float WAV file; `Ok(None)` when it is a WAV file of
/// another format; an error when it is no WAV file or is damaged.
pub fn read_float64(path: &Path) -> anyhow::Result<Option<Float64Wav>> {
    let bytes = std::fs::read(path).with_context(|| format!("{}: cannot read", path.display()))?;
    if bytes.len() < 12 || &bytes[0..4] != b"RIFF" || &bytes[8..12] != b"WAVE" {
        bail!("{}: not a RIFF/WAVE file", path.display());
    }
    let mut format = None;
    let mut at = 12;
    while at + 8 <= bytes.len() {
        let id = &bytes[at..at + 4];
        let size = u32::from_le_bytes([bytes[at + 4], bytes[at + 5], bytes[at + 6], bytes[at + 7]])
            as usize;
        let body = bytes
            .get(at + 8..at + 8 + size)
            .or_else(|| (id == b"data").then(|| &bytes[at + 8..]))
            .with_context(|| format!("{}: chunk `{}` cut short", path.display(), text(id)))?;
        match id {
            b"fmt " => format = Some(parse_format(path, body)?),
            b"data" => {
                let Some((tag, channels, rate_hz, bits)) = format else {
                    bail!("{}: `data` before `fmt `", path.display());
                };
                if tag != IEEE_FLOAT || bits != 64 {
                    return Ok(None);
                }
                let whole = body.len() / (8 * channels) * (8 * channels);
                let samples = body[..whole]
                    .chunks_exact(8)
                    .map(|b| f64::from_le_bytes(b.try_into().unwrap_or([0; 8])))
                    .collect();
                return Ok(Some(Float64Wav {
                    samples,
                    channels,
                    rate_hz,
                    cut_short: (body.len() < size).then_some((size, body.len())),
                }));
            }
            _ => {}
        }
        at += 8 + size + (size & 1);
    }
    bail!("{}: no `data` chunk", path.display())
}

/// (format tag, channels, rate in Hz, bits per sample) of a `fmt ` chunk.
fn parse_format(path: &Path, body: &[u8]) -> anyhow::Result<(u16, usize, f64, u16)> {
    if body.len() < 16 {
        bail!("{}: `fmt ` chunk of {} bytes", path.display(), body.len());
    }
    let u16_at = |i: usize| u16::from_le_bytes([body[i], body[i + 1]]);
    let mut tag = u16_at(0);
    if tag == EXTENSIBLE && body.len() >= 26 {
        tag = u16_at(24);
    }
    let channels = usize::from(u16_at(2));
    let rate = u32::from_le_bytes([body[4], body[5], body[6], body[7]]);
    if channels == 0 || rate == 0 {
        bail!(
            "{}: {channels} channels at {rate} Hz in the `fmt ` chunk",
            path.display()
        );
    }
    Ok((tag, channels, f64::from(rate), u16_at(14)))
}

fn text(id: &[u8]) -> String {
    String::from_utf8_lossy(id).into_owned()
}
