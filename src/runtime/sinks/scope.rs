//! The storage scope (on the amplifier output unless the scenario says otherwise): armed for one sweep at each measurement;
//! each stored sweep is written as CSV (time, volts) and drawn as PNG and SVG.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use instruments::{AcCoupling, Block, Scope, ScopeSettings};

use super::measure_clock::MeasureClock;
use super::scope_live::LiveScope;
use super::{Sink, SinkReport};
use crate::plots::{ScopeScales, write_scope_plots};
use crate::recording::CsvRecorder;
use crate::runtime::status::SharedStatus;
use crate::scenario::{Measure, Plan, ScopePlan};
use crate::vocabulary::Refusal;
use crate::vocabulary::RigCommand;
use crate::vocabulary::frame::Frame;

/// The scope.
pub struct ScopeSink {
    settings: ScopeSettings,
    rate_hz: f64,
    input: usize,
    signal: String,
    /// The signal's unit, and the strain (µε) one unit stands for where calibrated.
    unit: &'static str,
    microstrain_per_unit: Option<f64>,
    dir: PathBuf,
    scenario: String,
    measures: Vec<Measure>,
    clock: MeasureClock,
    armed: Option<(usize, Scope)>,
    coupling: Option<AcCoupling>,
    scratch: Vec<f64>,
    files: Vec<PathBuf>,
    untriggered: Vec<usize>,
    /// Live runs: the panel's scope, sweeping as set, and its latest trace published.
    live: Option<LiveScope>,
}

impl ScopeSink {
    /// The scope `scope` reading channel `input` (its signal), writing to `dir`, armed
    /// at `measures`.
    pub fn create(
        dir: &Path,
        plan: &Plan,
        scope: &ScopePlan,
        input: usize,
        measures: Vec<Measure>,
    ) -> anyhow::Result<Self> {
        let coupling = if scope.ac_coupling_hz > 0.0 {
            Some(AcCoupling::new(scope.ac_coupling_hz, plan.rate_hz)?)
        } else {
            None
        };
        Ok(Self {
            coupling,
            settings: scope.settings,
            rate_hz: plan.rate_hz,
            input,
            signal: scope.input.clone(),
            unit: plan.chain.stages.unit_of(&scope.input).unwrap_or("V"),
            microstrain_per_unit: plan.chain.microstrain_per_unit(&scope.input),
            dir: dir.to_path_buf(),
            scenario: plan.name.clone(),
            clock: MeasureClock::new(measures.iter().map(|m| m.at_s), plan.rate_hz),
            measures,
            armed: None,
            scratch: Vec::new(),
            files: Vec::new(),
            untriggered: Vec::new(),
            live: None,
        })
    }

    /// Puts a live scope on the panel (sweeping on every trigger).
    pub fn go_live(&mut self, status: SharedStatus) -> anyhow::Result<()> {
        self.live = Some(LiveScope::new(self.settings, self.rate_hz, status)?);
        Ok(())
    }

    /// Carries out `command` (at `frame`'s start) if it is the scope's. Saving the
    /// displays is answered by the analyser; the scope saves its trace beside it.
    fn carry_out(&mut self, command: &RigCommand, frame: &Frame) -> Option<Result<(), Refusal>> {
        match command {
            RigCommand::SetScope { .. } => Some(self.set_scales(command)),
            RigCommand::ArmScope => Some(self.arm_now(frame)),
            RigCommand::SaveDisplays => {
                if let Err(e) = self.save() {
                    eprintln!("testrig: the scope's trace was not saved: {e:#}");
                }
                None
            }
            _ => None,
        }
    }

    fn set_scales(&mut self, command: &RigCommand) -> Result<(), Refusal> {
        let RigCommand::SetScope {
            volts_per_div,
            seconds_per_div,
            trigger_v,
            mode,
        } = command
        else {
            return Err(Refusal::NotFor("not a scope setting".into()));
        };
        let settings = ScopeSettings {
            volts_per_div: volts_per_div.unwrap_or(self.settings.volts_per_div),
            seconds_per_div: seconds_per_div.unwrap_or(self.settings.seconds_per_div),
            trigger_v: trigger_v.unwrap_or(self.settings.trigger_v),
            ..self.settings
        };
        match &mut self.live {
            Some(live) => live.rescale(settings, *mode, self.rate_hz),
            None => Scope::new(settings, self.rate_hz).map(|_| ()),
        }
        .map_err(Refusal::from)?;
        self.settings = settings;
        Ok(())
    }

    /// Arms a stored sweep now (and re-arms the live scope in single mode).
    fn arm_now(&mut self, frame: &Frame) -> Result<(), Refusal> {
        if let Some(live) = &mut self.live {
            live.rearm();
        }
        let index = self.measures.len();
        self.measures.push(Measure {
            at_s: frame.start_sample as f64 / self.rate_hz,
            label: format!("sweep {}", index + 1),
            speed_rpm: frame.set_points.map_or(0.0, |s| s.speed_rpm),
            load_nm: frame.set_points.map_or(0.0, |s| s.load_nm),
        });
        self.arm(index).map_err(|e| Refusal::failed(&e))
    }

    /// Saves the live scope's trace on screen beside the analyser's saved displays.
    fn save(&mut self) -> anyhow::Result<()> {
        let Some(saved) = self.live.as_mut().and_then(LiveScope::next_saved) else {
            return Ok(());
        };
        let base = self.dir.join(format!("saved-{:02}-scope", saved.number));
        self.write_trace(&base, "saved", &saved.trace, saved.settings)
    }

    fn watch(&mut self, x: &[f64]) -> anyhow::Result<()> {
        let Some((index, scope)) = &mut self.armed else {
            return Ok(());
        };
        self.scratch.resize(x.len(), 0.0);
        scope.process(x, &mut self.scratch);
        if let Some(trace) = scope.trace() {
            let index = *index;
            self.armed = None;
            self.write(index, &trace)?;
        }
        Ok(())
    }

    fn arm(&mut self, index: usize) -> anyhow::Result<()> {
        if let Some((previous, _)) = self.armed.take() {
            self.untriggered.push(previous + 1);
        }
        self.armed = Some((index, Scope::new(self.settings, self.rate_hz)?));
        Ok(())
    }

    fn write(&mut self, index: usize, trace: &[(f64, f64)]) -> anyhow::Result<()> {
        let base = self.dir.join(format!("scope-{:02}", index + 1));
        let label = self.measures[index].label.clone();
        self.write_trace(&base, &label, trace, self.settings)
    }

    /// Writes `trace` (at `settings`) as `base` CSV, PNG and SVG, titled with `label`.
    fn write_trace(
        &mut self,
        base: &std::path::Path,
        label: &str,
        trace: &[(f64, f64)],
        settings: ScopeSettings,
    ) -> anyhow::Result<()> {
        let v = settings.volts_per_div;
        let mut csv = CsvRecorder::create(
            &base.with_extension("csv"),
            &["time_from_trigger_s".to_string(), self.signal.clone()],
        )?;
        for &(t, div) in trace {
            csv.write_row(&[t, div * v])?;
        }
        self.files.push(csv.finish()?);
        let title = format!(
            "{}: {label} ({v} {}/div, {} ms/div)",
            self.scenario,
            self.unit,
            settings.seconds_per_div * 1e3
        );
        let scales = ScopeScales {
            seconds_per_div: settings.seconds_per_div,
            units_per_div: v,
            unit: self.unit,
            microstrain_per_unit: self.microstrain_per_unit,
        };
        self.files
            .extend(write_scope_plots(base, &title, trace, scales)?);
        Ok(())
    }
}

impl Sink for ScopeSink {
    fn command(&mut self, command: &RigCommand, frame: &Frame) -> Option<Result<(), Refusal>> {
        self.carry_out(command, frame)
    }

    fn consume(&mut self, frame: &Frame) -> anyhow::Result<()> {
        let raw = &frame.channels[self.input];
        let x: Arc<[f64]> = match &mut self.coupling {
            Some(c) => {
                let mut coupled = vec![0.0; raw.len()];
                c.process(raw, &mut coupled);
                coupled.into()
            }
            None => Arc::clone(raw),
        };
        if let Some(live) = &mut self.live {
            live.watch(&x, (&self.signal, self.unit));
        }
        let mut offset = 0;
        while let Some((at, index)) = self.clock.next_within(frame.start_sample, x.len()) {
            self.watch(&x[offset..at])?;
            self.arm(index)?;
            offset = at;
        }
        self.watch(&x[offset..])
    }

    fn finish(mut self: Box<Self>) -> anyhow::Result<SinkReport> {
        if let Some((index, _)) = self.armed.take() {
            self.untriggered.push(index + 1);
        }
        let label = |index: usize| &self.measures[index].label;
        let mut warnings: Vec<String> = self
            .untriggered
            .iter()
            .map(|n| {
                format!(
                    "measurement {n} ({}): the scope did not trigger; no trace",
                    label(n - 1)
                )
            })
            .collect();
        warnings.extend(self.clock.unreached_warnings(&self.measures, "no trace"));
        Ok(SinkReport {
            files: std::mem::take(&mut self.files),
            facts: vec![(
                "scope_untriggered_measurements",
                self.untriggered.clone().into(),
            )],
            warnings,
        })
    }
}
