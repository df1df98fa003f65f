//! The Fourier analyser at the end of the chain: at each measurement it starts a fresh
//! average of ADC blocks of the filtered amplifier output; each finished average is written
//! as a spectrum (CSV in the `testrig analyse` format, PNG and SVG, UFF58 when asked), with
//! the ground truth of which lines are aliases.

use std::path::{Path, PathBuf};

use super::measure_clock::MeasureClock;
use super::{Sink, SinkReport};
use crate::chain::analyser_setup::{AdcChoice, AnalyserWords};
use crate::chain::spectrum_metadata::{SpectrumFacts, spectrum_metadata};
use crate::chain::{Measurement, Truth};
use crate::plots::{SpectrumPlot, write_spectrum_plots};
use crate::recording::{
    Metadata, PartialFile, Uff58Abscissa, Uff58Record, write_spectrum_csv, write_uff58,
};
use crate::runtime::status::SharedStatus;
use crate::scenario::{AnalyserPlan, Measure, Plan};
use crate::vocabulary::frame::Frame;
use crate::vocabulary::{AwaitingVerdicts, Refusal, RigCommand, RowMotion};

/// The analyser with its ADC and the alias truth.
pub struct AnalyserSink {
    pub(super) plan: AnalyserPlan,
    input: usize,
    pub(super) dir: PathBuf,
    scenario: String,
    filter: String,
    /// The input's unit (`V` through the chain; a sensor's own read directly): the
    /// spectra's powers are in it squared.
    pub(super) unit: &'static str,
    uff: bool,
    pub(super) measures: Vec<Measure>,
    /// For each of `measures`, the scenario's measurement whose judged motion it takes (a
    /// measurement restarted by a command keeps its point's; one started by a command,
    /// and the run's start where the scenario has no measurements, are no point: `None`).
    pub(super) points_of: Vec<Option<usize>>,
    clock: MeasureClock,
    /// The analyser, its ADC and the alias truth at work.
    pub(super) measurement: Measurement,
    pub(super) active: Option<usize>,
    /// ADC overloads of the measurements before the one under way.
    pub(super) overloads: u64,
    files: Vec<PathBuf>,
    incomplete: Vec<String>,
    pub(super) status: SharedStatus,
    /// Live runs: the display is published after every block, with its alias truth.
    pub(super) live: bool,
    /// Displays saved on command so far.
    pub(super) saved: usize,
    /// The stream rate (Hz).
    pub(super) rate_hz: f64,
    /// Averages in the display last published.
    pub(super) published: Option<usize>,
    /// Finished spectra, waiting for their points' judged motion.
    waiting: AwaitingVerdicts<FinishedSpectrum>,
}

/// A finished average, ready to be written once its point's motion is judged.
struct FinishedSpectrum {
    base: PathBuf,
    index: usize,
    count: usize,
    lines: Vec<instruments::Line>,
    alias_of: Vec<Option<f64>>,
    metadata: Metadata,
}

impl AnalyserSink {
    /// An analyser reading channel `input`, writing to `dir`, started at `measures`.
    pub fn create(
        dir: &Path,
        plan: &Plan,
        analyser: AnalyserPlan,
        input: usize,
        measures: Vec<Measure>,
        status: SharedStatus,
    ) -> anyhow::Result<Self> {
        let setup = AnalyserWords::of(&analyser.settings, AdcChoice::of(&analyser.adc))
            .set_up(plan.rate_hz)?;
        let filter = plan
            .chain
            .stages
            .producing(&analyser.input)
            .map_or("none".into(), |s| s.instrument.describe());
        let unit = plan.chain.stages.unit_of(&analyser.input).unwrap_or("V");
        Ok(Self {
            plan: analyser,
            input,
            dir: dir.to_path_buf(),
            scenario: plan.name.clone(),
            filter,
            unit,
            uff: plan.record.as_ref().is_some_and(|r| r.uff58),
            clock: MeasureClock::new(measures.iter().map(|m| m.at_s), plan.rate_hz),
            points_of: (0..measures.len())
                .map(|i| (!plan.measures.is_empty()).then_some(i))
                .collect(),
            measures,
            measurement: Measurement::new(setup, Truth::Kept),
            active: None,
            overloads: 0,
            files: Vec::new(),
            incomplete: Vec::new(),
            status,
            live: false,
            saved: 0,
            rate_hz: plan.rate_hz,
            published: None,
            waiting: AwaitingVerdicts::default(),
        })
    }

    pub(super) fn start(&mut self, index: usize) -> anyhow::Result<()> {
        self.close_measurement()?;
        self.overloads += self.measurement.overloads();
        self.measurement.restart();
        self.active = Some(index);
        Ok(())
    }

    fn feed(&mut self, analogue: &[f64]) -> anyhow::Result<()> {
        if self.active.is_none() || analogue.is_empty() {
            return Ok(());
        }
        self.measurement.push(analogue);
        let (n, of) = (
            self.measurement.average_count(),
            self.plan.settings.averages,
        );
        let overloads = self.overloads + self.measurement.overloads();
        self.status.update(|s| {
            s.averages = (n, of);
            s.adc_overloads = overloads;
        });
        if self.live {
            self.publish();
        }
        if self.measurement.is_complete() {
            self.close_measurement()?;
        }
        Ok(())
    }

    /// Writes the measurement under way (if any spectrum was averaged) and ends it; a
    /// spectrum of fewer averages than set is noted. One restarted before its first
    /// average (a setting changed, as a replayed session does) wrote nothing and is not.
    pub(super) fn close_measurement(&mut self) -> anyhow::Result<()> {
        let Some(index) = self.active.take() else {
            return Ok(());
        };
        let count = self.measurement.average_count();
        if count > 0 && count < self.plan.settings.averages {
            self.incomplete.push(format!(
                "measurement {} ({}): spectrum of {count} of {} averages",
                index + 1,
                self.measures[index].label,
                self.plan.settings.averages
            ));
        }
        if count == 0 {
            return Ok(());
        }
        let base = self.dir.join(format!("spectrum-{:02}", index + 1));
        let finished = self.finish_display(base, index, count);
        self.waiting.push(self.points_of[index], finished);
        self.write_judged(false)?;
        if self.live {
            self.published = None;
            self.publish();
        }
        Ok(())
    }

    /// The display of measurement `index` after `count` averages, to be written as `base`.
    fn finish_display(&mut self, base: PathBuf, index: usize, count: usize) -> FinishedSpectrum {
        let (lines, alias_of) = self.measurement.lines_and_truth();
        let metadata = self.metadata(&self.measures[index], count);
        FinishedSpectrum {
            base,
            index,
            count,
            lines,
            alias_of,
            metadata,
        }
    }

    /// Writes the waiting spectra, in order, as far as their points' verdicts have come;
    /// at the run's `end`, the rest as unjudged.
    fn write_judged(&mut self, end: bool) -> anyhow::Result<()> {
        for (mut finished, motion) in self.waiting.take_ready(end) {
            finished.metadata.extend(motion_metadata(&motion));
            self.write_finished(&finished, &motion)?;
        }
        Ok(())
    }

    /// Writes the display as `base` (CSV, PNG, SVG, UFF58 when asked), of measurement
    /// `index` after `count` averages, at once (the panel's saved displays).
    pub(super) fn write_spectrum(
        &mut self,
        base: &Path,
        index: usize,
        count: usize,
    ) -> anyhow::Result<()> {
        let finished = self.finish_display(base.to_path_buf(), index, count);
        self.write_finished(&finished, &RowMotion::NoPoint)
    }

    /// Writes `finished`, its plot titled with the point's judged `motion` where it has one.
    fn write_finished(
        &mut self,
        finished: &FinishedSpectrum,
        motion: &RowMotion,
    ) -> anyhow::Result<()> {
        let FinishedSpectrum {
            base,
            index,
            count,
            lines,
            alias_of,
            metadata,
        } = finished;
        let (index, count) = (*index, *count);
        let measure = &self.measures[index];
        let csv = base.with_extension("csv");
        write_spectrum_csv(&csv, metadata, lines, alias_of)?;
        self.files.push(csv);
        let s = &self.plan.settings;
        // The settings in effect (after any --set), never the scenario's words for them.
        let filter = match self.filter.as_str() {
            "none" => "no filter",
            described => described,
        };
        let judged = match motion {
            RowMotion::NoPoint => String::new(),
            point => format!(" ({})", point.label()),
        };
        let title = format!(
            "{}: {}{judged}; {count} av., {} window, {filter}, N = {}",
            self.scenario,
            measure.label,
            s.window.name(),
            s.block
        );
        let plot = SpectrumPlot {
            title: &title,
            unit: self.unit,
            lines,
            alias_of,
            running_hz: Some(measure.speed_rpm / 60.0),
        };
        self.files.extend(write_spectrum_plots(base, &plot)?);
        if self.uff {
            self.files
                .push(write_spectrum_uff(base, (&title, self.unit), lines)?);
        }
        Ok(())
    }

    fn metadata(&self, measure: &Measure, count: usize) -> Metadata {
        let adc = &self.plan.adc;
        let head = vec![
            ("scenario", self.scenario.clone()),
            ("measurement", measure.label.clone()),
            ("started_s", measure.at_s.to_string()),
            ("speed_set_rpm", measure.speed_rpm.to_string()),
            ("load_set_nm", measure.load_nm.to_string()),
            (
                "signal",
                format!("{} (after {})", self.plan.input, self.filter),
            ),
        ];
        spectrum_metadata(
            head,
            SpectrumFacts {
                settings: &self.plan.settings,
                enbw_hz: self.measurement.setup.analyser.enbw_hz(),
                averages_done: count,
                filter: self.filter.clone(),
                adc: format!(
                    "{} bits over +-{} {}, {} overloads",
                    adc.bits,
                    adc.range_v,
                    self.unit,
                    self.measurement.overloads()
                ),
                unit: self.unit,
            },
        )
    }
}

/// The point's judged motion as a spectrum's metadata lines (none for no point).
fn motion_metadata(motion: &RowMotion) -> Metadata {
    let number = |v: Option<f64>| v.map_or(String::new(), |v| v.to_string());
    let v = match motion {
        RowMotion::NoPoint => return Vec::new(),
        RowMotion::Unjudged => return vec![("motion", motion.label())],
        RowMotion::Judged(v) => v,
    };
    let m = &v.summary.motion;
    vec![
        ("motion", m.motion.to_string()),
        ("motion_judged_from_s", v.from_s.to_string()),
        ("motion_judged_over_s", v.summary.measured_s.to_string()),
        ("half_order_over_floor_db", number(m.half_order_db)),
        ("chaos_k", number(m.chaos_k)),
    ]
}

/// The spectrum `lines` (powers in `unit` squared) as a UFF58 file beside `base`.
fn write_spectrum_uff(
    base: &Path,
    (title, unit): (&str, &str),
    lines: &[instruments::Line],
) -> anyhow::Result<PathBuf> {
    let ordinate_unit = format!("{unit}^2");
    let source = format!("testrig analyser (power spectrum, {ordinate_unit} rms)");
    let values: Vec<f64> = lines.iter().map(|l| l.value).collect();
    let step_hz = lines.get(1).map_or(1.0, |l| l.frequency_hz);
    let record = Uff58Record {
        description: title,
        source: &source,
        function_type: 12,
        response_name: "amplifier",
        response_node: 1,
        ordinate_type: 0,
        ordinate_unit: &ordinate_unit,
        abscissa: Uff58Abscissa::Frequency {
            start_hz: 0.0,
            step_hz,
        },
        values: &values,
    };
    let file = PartialFile::new(&base.with_extension("uff"));
    let mut out = file.create()?;
    write_uff58(&mut out, &record)?;
    std::io::Write::flush(&mut out)?;
    drop(out);
    file.commit()
}

impl Sink for AnalyserSink {
    fn command(&mut self, command: &RigCommand, frame: &Frame) -> Option<Result<(), Refusal>> {
        self.carry_out(command, frame)
    }

    fn consume(&mut self, frame: &Frame) -> anyhow::Result<()> {
        self.waiting.add_verdicts(&frame.points);
        self.write_judged(false)?;
        let x = frame.channels[self.input].clone();
        let mut offset = 0;
        while let Some((at, index)) = self.clock.next_within(frame.start_sample, x.len()) {
            self.feed(&x[offset..at])?;
            self.start(index)?;
            offset = at;
        }
        self.feed(&x[offset..])
    }

    fn finish(mut self: Box<Self>) -> anyhow::Result<SinkReport> {
        self.close_measurement()?;
        self.write_judged(true)?;
        self.overloads += self.measurement.overloads();
        let mut warnings = std::mem::take(&mut self.incomplete);
        warnings.extend(self.clock.unreached_warnings(&self.measures, "no spectrum"));
        if self.overloads > 0 {
            warnings.push(format!(
                "the ADC overloaded on {} samples (range ±{} V): raise analyser.range_v",
                self.overloads, self.plan.adc.range_v
            ));
        }
        Ok(SinkReport {
            files: std::mem::take(&mut self.files),
            facts: vec![("adc_overloads", self.overloads.into())],
            warnings,
        })
    }
}
