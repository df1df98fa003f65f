//! The recorder: chosen signals to WAV (with sidecar), CSV and UFF58 as they come, and
//! the impact log to `impacts.csv`.

use std::path::{Path, PathBuf};

use instruments::{AntiAliasFilter, FilterKind, LowPassSpec};

use super::{Sink, SinkReport};
use crate::chain::ChainStages;
use crate::recording::{
    ChannelInfo, CsvFrames, FrameWriter, ImpactLog, Uff58Channel, Uff58Recorder, WavRecorder,
    WavSamples, Written,
};
use crate::runtime::status::SharedStatus;
use crate::scenario::{Plan, RecordPlan};
use crate::vocabulary::Refusal;
use crate::vocabulary::RigCommand;
use crate::vocabulary::choices::WavFormat;
use crate::vocabulary::frame::{Frame, SignalNames};
use crate::vocabulary::signal_names::{STRAIN, TIME_S};

/// Order of the Butterworth low-pass a decimated recording passes each signal through.
const DECIMATION_FILTER_ORDER: usize = 8;
/// Its cut-off as a share of the kept rate's Nyquist frequency (as scipy's `decimate`).
const DECIMATION_CUTOFF_OF_NYQUIST: f64 = 0.8;
/// Whether signal `name` is a state or a time, kept sample by sample when decimating (a
/// low-pass of a contact state means nothing): time, and each mesh's `contact_<mesh>`.
fn is_state(name: &str) -> bool {
    name == TIME_S || name.starts_with("contact_")
}

/// Writes every recorded frame.
pub struct RecorderSink {
    indices: Vec<usize>,
    decimate: u64,
    /// Per recorded signal, the decimation's anti-alias filter (`None`: kept as sampled).
    decimators: Vec<Option<AntiAliasFilter>>,
    writers: Vec<Box<dyn FrameWriter>>,
    impacts: ImpactLog,
    row: Vec<f64>,
    rate_hz: f64,
    expected_seq: u64,
    gaps: u64,
    /// For recordings started by command: the plan, and how many were started.
    plan: Option<Box<Plan>>,
    recordings: usize,
    /// Recordings stopped by command, complete.
    finished: Vec<Written>,
    status: Option<SharedStatus>,
    dir: PathBuf,
}

impl RecorderSink {
    /// Opens the files in `dir` for `plan`'s recording, over channels named by `names`.
    pub fn create(dir: &Path, plan: &Plan, names: &SignalNames) -> anyhow::Result<Self> {
        let path = dir.join("impacts.csv");
        let impacts = ImpactLog::of_meshes(&path, &plan.rig.topology)?;
        let mut sink = Self {
            indices: Vec::new(),
            decimate: 1,
            decimators: Vec::new(),
            writers: Vec::new(),
            impacts,
            row: Vec::new(),
            rate_hz: plan.rate_hz,
            expected_seq: 0,
            gaps: 0,
            plan: None,
            recordings: 0,
            finished: Vec::new(),
            status: None,
            dir: dir.to_path_buf(),
        };
        let Some(record) = &plan.record else {
            return Ok(sink);
        };
        sink.indices = record
            .signals
            .iter()
            .map(|s| {
                names
                    .index(s)
                    .ok_or_else(|| anyhow::anyhow!("internal wiring: no `{s}`"))
            })
            .collect::<anyhow::Result<_>>()?;
        sink.decimate = record.decimate as u64;
        sink.decimators = record
            .signals
            .iter()
            .map(|name| decimation_filter(name, plan.rate_hz, record.decimate))
            .collect::<anyhow::Result<_>>()?;
        sink.plan = Some(Box::new(plan.clone()));
        if record.from_start {
            sink.start_recording(dir)?;
        }
        Ok(sink)
    }

    /// Reports whether it records on the live panel's status.
    pub fn go_live(&mut self, status: SharedStatus) {
        let recording = !self.writers.is_empty();
        status.update(|s| s.recording = recording);
        self.status = Some(status);
    }

    /// Opens the files of a new recording in `dir`: `recording.*`, then `recording-02.*` …
    fn start_recording(&mut self, dir: &Path) -> anyhow::Result<()> {
        let Some(plan) = &self.plan else {
            anyhow::bail!("this run records nothing ([record] is left out)");
        };
        let Some(record) = &plan.record else {
            anyhow::bail!("this run records nothing ([record] is left out)");
        };
        self.recordings += 1;
        let stem = match self.recordings {
            1 => "recording".to_string(),
            n => format!("recording-{n:02}"),
        };
        let source = RecordingSource {
            rate_hz: plan.rate_hz,
            stages: &plan.chain.stages,
            text: &plan.text,
            name: &format!("scenario {}", plan.name),
        };
        self.writers = recording_writers(dir, &stem, &source, record)?;
        self.set_recording(true);
        Ok(())
    }

    fn stop_recording(&mut self) -> anyhow::Result<()> {
        for writer in std::mem::take(&mut self.writers) {
            self.finished.push(writer.finish()?);
        }
        self.set_recording(false);
        Ok(())
    }

    fn set_recording(&self, on: bool) {
        if let Some(status) = &self.status {
            status.update(|s| s.recording = on);
        }
    }
}

/// The anti-alias filter that keeps signal `name`, sampled at `rate_hz`, free of aliases
/// when every `decimate`-th sample is kept: a Butterworth low-pass of order
/// [`DECIMATION_FILTER_ORDER`] at [`DECIMATION_CUTOFF_OF_NYQUIST`] of the kept rate's
/// Nyquist frequency. None without decimation and for states and counts.
fn decimation_filter(
    name: &str,
    rate_hz: f64,
    decimate: usize,
) -> anyhow::Result<Option<AntiAliasFilter>> {
    if decimate <= 1 || is_state(name) {
        return Ok(None);
    }
    let spec = decimation_spec(rate_hz, decimate);
    Ok(Some(AntiAliasFilter::new(Some(spec), rate_hz)?))
}

/// The decimation filter's design for a stream at `rate_hz` kept every `decimate`-th sample.
pub fn decimation_spec(rate_hz: f64, decimate: usize) -> LowPassSpec {
    LowPassSpec {
        kind: FilterKind::Butterworth,
        order: DECIMATION_FILTER_ORDER,
        cutoff_hz: DECIMATION_CUTOFF_OF_NYQUIST * rate_hz / decimate as f64 / 2.0,
    }
}

/// What a recording is made of: the stream's rate, the stages that name the signals'
/// units, and the text and name its files cite.
pub struct RecordingSource<'a> {
    /// The stream's rate (Hz).
    pub rate_hz: f64,
    /// The chain's stages (each recorded signal's unit).
    pub stages: &'a ChainStages,
    /// The scenario or sweep file's text, as run (into a WAV's sidecar).
    pub text: &'a str,
    /// What made it (`scenario NAME`, `sweep NAME case K`), into UFF58's headers.
    pub name: &'a str,
}

/// The recording's writers `dir/stem.wav` (+ sidecar), `.csv`, `.uff`, one per format
/// asked for.
pub fn recording_writers(
    dir: &Path,
    stem: &str,
    source: &RecordingSource,
    record: &RecordPlan,
) -> anyhow::Result<Vec<Box<dyn FrameWriter>>> {
    let file = |extension: &str| dir.join(format!("{stem}.{extension}"));
    let rate = source.rate_hz / record.decimate as f64;
    let mut writers: Vec<Box<dyn FrameWriter>> = Vec::new();
    if let Some(format) = record.wav {
        let channels = record
            .signals
            .iter()
            .zip(&record.full_scale)
            .map(|(name, &scale)| ChannelInfo {
                name: name.clone(),
                unit: unit_of(source.stages, name).into(),
                scale: if format == WavFormat::Float32 {
                    1.0
                } else {
                    scale
                },
                full_scale: scale,
            })
            .collect();
        let samples = match format {
            WavFormat::Float32 => WavSamples::Float32,
            WavFormat::Int24 => WavSamples::Int24,
        };
        writers.push(Box::new(WavRecorder::create_as(
            &file("wav"),
            rate.round() as u32,
            channels,
            source.text,
            samples,
        )?));
    }
    if record.csv {
        let path = file("csv");
        writers.push(Box::new(CsvFrames::create(&path, &record.signals)?));
    }
    if record.uff58 {
        let channels = record
            .signals
            .iter()
            .enumerate()
            .map(|(i, s)| uff_channel(source.stages, s, i))
            .collect();
        let source = format!("testrig {}", source.name);
        writers.push(Box::new(Uff58Recorder::create(
            &file("uff"),
            channels,
            &source,
            0.0,
            1.0 / rate,
        )?));
    }
    Ok(writers)
}

/// Unit of a recorded signal (the plan has checked every name).
fn unit_of(stages: &ChainStages, name: &str) -> &'static str {
    stages.unit_of(name).unwrap_or("1")
}

fn uff_channel(stages: &ChainStages, name: &str, index: usize) -> Uff58Channel {
    Uff58Channel {
        description: format!("testrig {name}"),
        response_name: name.chars().take(10).collect(),
        response_node: index as u32 + 1,
        ordinate_type: if name == STRAIN { 3 } else { 0 },
        ordinate_unit: unit_of(stages, name).into(),
    }
}

impl Sink for RecorderSink {
    fn command(&mut self, command: &RigCommand, _frame: &Frame) -> Option<Result<(), Refusal>> {
        let RigCommand::Record { on } = command else {
            return None;
        };
        let dir = self.dir.clone();
        let outcome = match (on, self.writers.is_empty()) {
            (true, true) => self.start_recording(&dir),
            (false, false) => self.stop_recording(),
            (true, false) => Err(anyhow::anyhow!("already recording")),
            (false, true) => Err(anyhow::anyhow!("not recording")),
        };
        Some(outcome.map_err(|e| Refusal::failed(&e)))
    }

    fn consume(&mut self, frame: &Frame) -> anyhow::Result<()> {
        if frame.seq != self.expected_seq {
            self.gaps += frame.seq - self.expected_seq;
        }
        self.expected_seq = frame.seq + 1;
        self.impacts.write(&frame.impacts)?;
        if self.writers.is_empty() {
            return Ok(());
        }
        for i in 0..frame.len() {
            let sample = frame.start_sample + i as u64;
            let keep = sample.is_multiple_of(self.decimate);
            if self.decimators.is_empty() && !keep {
                continue;
            }
            self.row.clear();
            for (&c, filter) in self.indices.iter().zip(&mut self.decimators) {
                let x = frame.channels[c][i];
                self.row.push(filter.as_mut().map_or(x, |f| f.tick(x)));
            }
            if !keep {
                continue;
            }
            let time_s = sample as f64 / self.rate_hz;
            for writer in &mut self.writers {
                writer.write_frame(time_s, &self.row)?;
            }
        }
        Ok(())
    }

    fn finish(self: Box<Self>) -> anyhow::Result<SinkReport> {
        let mut report = SinkReport::default();
        report.files.push(self.impacts.finish()?);
        let mut finished = self.finished;
        for writer in self.writers {
            finished.push(writer.finish()?);
        }
        for written in finished {
            report.files.extend(written.files);
            report.facts.extend(written.facts);
        }
        report
            .facts
            .push(("recording_gaps_blocks", self.gaps.into()));
        if self.decimate > 1 {
            let spec = decimation_spec(self.rate_hz, self.decimate as usize);
            report.facts.push((
                "recording_decimation",
                format!(
                    "every {}th sample kept after a Butterworth low-pass of order {} at {} Hz (states and counts kept as sampled)",
                    self.decimate, spec.order, spec.cutoff_hz
                )
                .into(),
            ));
        }
        Ok(report)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// RMS of every `decimate`-th sample of a `hz` sine at `rate_hz` through the recorder's
    /// decimation filter, after the filter's first second.
    fn kept_rms(hz: f64, rate_hz: f64, decimate: usize) -> f64 {
        let mut filter = decimation_filter("torque_intermediate_shaft_nm", rate_hz, decimate)
            .expect("designed")
            .expect("a continuous signal is filtered");
        let n = (3.0 * rate_hz) as usize;
        let kept: Vec<f64> = (0..n)
            .map(|i| filter.tick((std::f64::consts::TAU * hz * i as f64 / rate_hz).sin()))
            .enumerate()
            .filter(|(i, _)| i % decimate == 0 && *i as f64 >= rate_hz)
            .map(|(_, y)| y)
            .collect();
        (kept.iter().map(|y| y * y).sum::<f64>() / kept.len() as f64).sqrt()
    }

    #[test]
    fn a_decimated_recording_keeps_the_band_and_does_not_fold_what_lies_above_it() {
        // 51.2 kHz kept every 64th sample: 800 Hz, Nyquist 400 Hz, the filter at 320 Hz.
        let unit_sine_rms = std::f64::consts::FRAC_1_SQRT_2;
        let passed = kept_rms(100.0, 51_200.0, 64);
        assert!(
            (passed / unit_sine_rms - 1.0).abs() < 0.01,
            "100 Hz: {passed}"
        );
        // The gears' 650 Hz mesh line would fold to 150 Hz; the filter takes it down by
        // (650/320)^8 ≈ 290 (8th-order Butterworth), about 49 dB.
        let folded = kept_rms(650.0, 51_200.0, 64);
        let expected = unit_sine_rms / (1.0 + (650.0f64 / 320.0).powi(16)).sqrt();
        assert!(
            (folded / expected - 1.0).abs() < 0.05,
            "650 Hz: {folded} against {expected}"
        );
        assert!(folded < 0.005 * unit_sine_rms);
    }

    #[test]
    fn states_and_counts_are_kept_as_sampled_and_no_decimation_filters_nothing() {
        assert!(
            decimation_filter("time_s", 51_200.0, 8)
                .expect("ok")
                .is_none()
        );
        assert!(
            decimation_filter("contact_gears", 51_200.0, 8)
                .expect("ok")
                .is_none()
        );
        assert!(
            decimation_filter("filter_v", 51_200.0, 1)
                .expect("ok")
                .is_none()
        );
    }
}
