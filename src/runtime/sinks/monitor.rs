//! The rack as the experimenter reads it: the tacho DVM and the RMS meter, shown on the
//! console as the run goes and written to `readings.csv` at each measurement, beside the
//! truth (the shaft torque's mean and RMS over the second before the reading). A survey's
//! readings over two or more loads are also drawn as RMS against load per speed with the
//! static line.

use std::path::{Path, PathBuf};

use anyhow::Context;
use instruments::CROMPTON_PARKINSON_V_PER_RPM;
use serde::Serialize;

use super::measure_clock::MeasureClock;
use super::{Sink, SinkReport};
use crate::plots::{SurveyPoint, write_survey_plots};
use crate::recording::CsvRecorder;
use crate::runtime::status::SharedStatus;
use crate::scenario::{Measure, Plan};
use crate::vocabulary::frame::{Frame, SignalNames};
use crate::vocabulary::signal_names::{DVM_V, METER_V, SHAFT_TORQUE_NM};
use crate::vocabulary::{AwaitingVerdicts, GearIndicators, RowMotion};

/// Length of the truth window before each reading (s).
pub const TRUTH_WINDOW_S: f64 = 1.0;

/// One reading of the rack.
#[derive(Clone, Debug, Serialize)]
struct Reading {
    label: String,
    time_s: f64,
    speed_set_rpm: f64,
    load_set_nm: f64,
    dvm_v: f64,
    dvm_rpm: f64,
    meter_v: f64,
    meter_microstrain: f64,
    true_torque_mean_nm: f64,
    true_torque_ac_rms_nm: f64,
    true_ac_rms_microstrain: f64,
    static_microstrain: f64,
    /// The physics judge's motion over the point's settled window ("unjudged" where the
    /// window did not end; empty where the scenario has no measurements of its own).
    motion: String,
    /// The half-order line's height over the broadband floor in that window (dB).
    half_order_db: Option<f64>,
    /// The driven gear's condition indicators over that window, in the order of
    /// `GearIndicators::COLUMNS` (empty where not judged).
    condition: [Option<f64>; 10],
}

/// Channels the monitor reads.
struct Inputs {
    dvm: usize,
    meter: usize,
    torque: usize,
}

/// The monitor.
pub struct MonitorSink {
    inputs: Inputs,
    measures: Vec<Measure>,
    truth_starts: MeasureClock,
    readings_at: MeasureClock,
    volts_per_microstrain: f64,
    microstrain_per_nm: f64,
    /// The gauged shaft's steady torque at each measurement's set points (N m).
    static_torque_nm: Vec<f64>,
    window: (f64, f64, usize),
    csv: CsvRecorder,
    points: Vec<SurveyPoint>,
    /// Whether the readings are of the scenario's own measurements, each a judged point
    /// (else the one reading at the start is no point, and is written at once).
    judged: bool,
    /// Readings taken, waiting for their points' verdicts.
    waiting: AwaitingVerdicts<Reading>,
    survey_plot: Option<(PathBuf, String)>,
    status: SharedStatus,
}

impl MonitorSink {
    /// A monitor over channels `names`, writing `readings.csv` (and, for a survey, the
    /// survey plot) to `dir`.
    pub fn create(
        dir: &Path,
        plan: &Plan,
        names: &SignalNames,
        measures: Vec<Measure>,
        status: SharedStatus,
    ) -> anyhow::Result<Self> {
        let index = |n: &str| {
            names
                .index(n)
                .ok_or_else(|| anyhow::anyhow!("internal wiring: no `{n}`"))
        };
        let chain = &plan.chain;
        let microstrain_per_nm = chain.strain_per_nm * 1e6;
        let header = [
            "label",
            "time_s",
            "speed_set_rpm",
            "load_set_nm",
            DVM_V,
            "dvm_rpm",
            METER_V,
            "meter_microstrain",
            "true_torque_mean_nm",
            "true_torque_ac_rms_nm",
            "true_ac_rms_microstrain",
            "static_microstrain",
            "motion",
            "half_order_db",
        ]
        .map(String::from)
        .into_iter()
        .chain(GearIndicators::COLUMNS.map(String::from))
        .collect::<Vec<_>>();
        let static_torque_nm = measures
            .iter()
            .map(|m| {
                plan.rig
                    .static_torque_nm(m.speed_rpm, m.load_nm, plan.rate_hz)
            })
            .collect::<Result<Vec<_>, _>>()
            .context("the gauged shaft's static torque at a measurement's set points")?;
        Ok(Self {
            inputs: Inputs {
                dvm: index(DVM_V)?,
                meter: index(METER_V)?,
                torque: index(SHAFT_TORQUE_NM)?,
            },
            truth_starts: MeasureClock::new(
                measures.iter().map(|m| (m.at_s - TRUTH_WINDOW_S).max(0.0)),
                plan.rate_hz,
            ),
            readings_at: MeasureClock::new(measures.iter().map(|m| m.at_s), plan.rate_hz),
            measures,
            volts_per_microstrain: chain.volts_per_nm / microstrain_per_nm,
            microstrain_per_nm,
            static_torque_nm,
            window: (0.0, 0.0, 0),
            csv: CsvRecorder::create(&dir.join("readings.csv"), &header)?,
            points: Vec::new(),
            judged: !plan.measures.is_empty(),
            waiting: AwaitingVerdicts::default(),
            survey_plot: plan
                .is_survey
                .then(|| (dir.join("rms-survey"), plan.name.clone())),
            status,
        })
    }

    fn accumulate(&mut self, torque: &[f64]) {
        for &t in torque {
            self.window.0 += t;
            self.window.1 += t * t;
        }
        self.window.2 += torque.len();
    }

    fn read(&mut self, frame: &Frame, at: usize, index: usize) -> anyhow::Result<()> {
        let sample = at.min(frame.len().saturating_sub(1));
        let dvm_v = frame.channels[self.inputs.dvm][sample];
        let meter_v = frame.channels[self.inputs.meter][sample];
        let n = self.window.2.max(1) as f64;
        let mean = self.window.0 / n;
        let ac_rms = (self.window.1 / n - mean * mean).max(0.0).sqrt();
        let m = &self.measures[index];
        let reading = Reading {
            label: m.label.clone(),
            time_s: m.at_s,
            speed_set_rpm: m.speed_rpm,
            load_set_nm: m.load_nm,
            dvm_v,
            dvm_rpm: dvm_v / CROMPTON_PARKINSON_V_PER_RPM,
            meter_v,
            meter_microstrain: meter_v / self.volts_per_microstrain,
            true_torque_mean_nm: mean,
            true_torque_ac_rms_nm: ac_rms,
            true_ac_rms_microstrain: ac_rms * self.microstrain_per_nm,
            static_microstrain: self.static_torque_nm[index] * self.microstrain_per_nm,
            motion: String::new(),
            half_order_db: None,
            condition: [None; 10],
        };
        self.points.push(SurveyPoint {
            speed_rpm: m.speed_rpm,
            load_nm: m.load_nm,
            rms_microstrain: reading.meter_microstrain,
        });
        self.waiting.push(self.judged.then_some(index), reading);
        self.window = (0.0, 0.0, 0);
        self.write_judged(false)
    }

    /// Writes the readings whose points' verdicts have come, in order; at the run's
    /// `end`, the rest as unjudged.
    fn write_judged(&mut self, end: bool) -> anyhow::Result<()> {
        for (mut reading, motion) in self.waiting.take_ready(end) {
            reading.motion = motion.label();
            if let RowMotion::Judged(verdict) = &motion {
                reading.half_order_db = verdict.summary.motion.half_order_db;
                if let Some(c) = &verdict.condition {
                    reading.condition = c.values().map(Some);
                }
            }
            self.csv.write_row(&reading)?;
        }
        Ok(())
    }
}

impl Sink for MonitorSink {
    fn consume(&mut self, frame: &Frame) -> anyhow::Result<()> {
        self.waiting.add_verdicts(&frame.points);
        self.write_judged(false)?;
        let len = frame.len();
        let torque = frame.channels[self.inputs.torque].clone();
        let mut events: Vec<(usize, bool, usize)> = Vec::new();
        while let Some((at, i)) = self.truth_starts.next_within(frame.start_sample, len) {
            events.push((at, false, i));
        }
        while let Some((at, i)) = self.readings_at.next_within(frame.start_sample, len) {
            events.push((at, true, i));
        }
        events.sort_by_key(|&(at, is_reading, _)| (at, is_reading));
        let mut offset = 0;
        for (at, is_reading, index) in events {
            self.accumulate(&torque[offset..at]);
            offset = at;
            if is_reading {
                self.read(frame, at, index)?;
            } else {
                self.window = (0.0, 0.0, 0);
            }
        }
        self.accumulate(&torque[offset..]);
        if let Some(last) = len.checked_sub(1) {
            let (dvm_v, meter_v) = (
                frame.channels[self.inputs.dvm][last],
                frame.channels[self.inputs.meter][last],
            );
            self.status.update(|s| {
                s.dvm_v = dvm_v;
                s.meter_v = meter_v;
            });
        }
        Ok(())
    }

    fn finish(mut self: Box<Self>) -> anyhow::Result<SinkReport> {
        self.write_judged(true)?;
        let mut files = vec![self.csv.finish()?];
        let mut loads: Vec<f64> = self.points.iter().map(|p| p.load_nm).collect();
        loads.sort_by(f64::total_cmp);
        loads.dedup();
        if let Some((base, name)) = &self.survey_plot
            && loads.len() >= 2
        {
            let title = format!("{name}: RMS meter reading against load");
            files.extend(write_survey_plots(
                base,
                &title,
                &self.points,
                self.microstrain_per_nm,
            )?);
        }
        Ok(SinkReport {
            files,
            facts: vec![("readings", self.points.len().into())],
            warnings: Vec::new(),
        })
    }
}
