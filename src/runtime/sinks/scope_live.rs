//! The scope operated live: a second scope sweeping as the panel sets it (auto or
//! single), its latest trace published; commands change its scales, arm a stored sweep
//! (written as a file, as at a measurement) or save the trace on screen.

use std::sync::Arc;

use instruments::{Block, Scope, ScopeSettings, SweepMode};

use super::scope::ScopeSink;
use crate::live::command::ScopeMode;
use crate::live::{Command, LiveTrace};
use crate::runtime::frame::Frame;
use crate::runtime::status::SharedStatus;
use crate::scenario::Measure;

/// Most points of a trace sent to the panel (every k-th sample beyond).
const PANEL_POINTS: usize = 2000;

/// The panel's scope.
pub struct LiveScope {
    scope: Scope,
    mode: ScopeMode,
    seen: u64,
    last: Option<Vec<(f64, f64)>>,
    saved: usize,
    scratch: Vec<f64>,
    status: SharedStatus,
}

impl ScopeSink {
    /// Puts a live scope on the panel (sweeping on every trigger).
    pub fn go_live(&mut self, status: SharedStatus) -> anyhow::Result<()> {
        let settings = ScopeSettings {
            mode: SweepMode::Repeat,
            ..self.settings
        };
        self.live = Some(LiveScope {
            scope: Scope::new(settings, self.rate_hz)?,
            mode: ScopeMode::Auto,
            seen: 0,
            last: None,
            saved: 0,
            scratch: Vec::new(),
            status,
        });
        Ok(())
    }

    /// Feeds the live scope; a new sweep goes on the panel.
    pub(super) fn watch_live(&mut self, x: &[f64]) {
        let signal = self.signal.clone();
        let Some(live) = &mut self.live else {
            return;
        };
        live.scratch.resize(x.len(), 0.0);
        live.scope.process(x, &mut live.scratch);
        if live.scope.sweeps() == live.seen {
            return;
        }
        live.seen = live.scope.sweeps();
        live.last = live.scope.trace();
        publish(live, signal);
    }

    /// Carries out `command` (at `frame`'s start) if it is the scope's. Saving the
    /// displays is answered by the analyser; the scope saves its trace beside it.
    pub(super) fn carry_out(
        &mut self,
        command: &Command,
        frame: &Frame,
    ) -> Option<Result<(), String>> {
        match command {
            Command::SetScope { .. } => Some(self.set_scales(command)),
            Command::ArmScope => Some(self.arm_now(frame)),
            Command::SaveDisplays => {
                if let Err(e) = self.save() {
                    eprintln!("testrig: the scope's trace was not saved: {e:#}");
                }
                None
            }
            _ => None,
        }
    }

    fn set_scales(&mut self, command: &Command) -> Result<(), String> {
        let Command::SetScope {
            volts_per_div,
            seconds_per_div,
            trigger_v,
            mode,
        } = command
        else {
            return Err("not a scope setting".into());
        };
        let settings = ScopeSettings {
            volts_per_div: volts_per_div.unwrap_or(self.settings.volts_per_div),
            seconds_per_div: seconds_per_div.unwrap_or(self.settings.seconds_per_div),
            trigger_v: trigger_v.unwrap_or(self.settings.trigger_v),
            ..self.settings
        };
        let Some(live) = &mut self.live else {
            Scope::new(settings, self.rate_hz).map_err(|e| e.to_string())?;
            self.settings = settings;
            return Ok(());
        };
        let mode = mode.unwrap_or(live.mode);
        let sweep_mode = match mode {
            ScopeMode::Auto => SweepMode::Repeat,
            ScopeMode::Single => SweepMode::Single,
        };
        let scope = Scope::new(
            ScopeSettings {
                mode: sweep_mode,
                ..settings
            },
            self.rate_hz,
        )
        .map_err(|e| e.to_string())?;
        live.scope = scope;
        live.mode = mode;
        live.seen = 0;
        self.settings = settings;
        Ok(())
    }

    /// Arms a stored sweep now (and re-arms the live scope in single mode).
    fn arm_now(&mut self, frame: &Frame) -> Result<(), String> {
        if let Some(live) = &mut self.live {
            live.scope.reset();
            live.seen = 0;
        }
        let index = self.measures.len();
        self.measures.push(Measure {
            at_s: frame.start_sample as f64 / self.rate_hz,
            label: format!("sweep {}", index + 1),
            speed_rpm: frame.set_points.map_or(0.0, |s| s.speed_rpm),
            load_nm: frame.set_points.map_or(0.0, |s| s.load_nm),
        });
        self.arm(index).map_err(|e| format!("{e:#}"))
    }

    fn save(&mut self) -> anyhow::Result<()> {
        let Some(live) = &mut self.live else {
            return Ok(());
        };
        live.saved += 1;
        let Some(trace) = live.last.clone() else {
            return Ok(());
        };
        let base = self.dir.join(format!("saved-{:02}-scope", live.saved));
        let settings = live.scope.settings();
        self.write_trace(&base, "saved", &trace, settings)
    }
}

fn publish(live: &LiveScope, signal: String) {
    let Some(trace) = &live.last else {
        return;
    };
    let s = live.scope.settings();
    let stride = trace.len().div_ceil(PANEL_POINTS).max(1);
    let shown = LiveTrace {
        time_s: trace.iter().step_by(stride).map(|p| p.0).collect(),
        divisions: trace.iter().step_by(stride).map(|p| p.1).collect(),
        volts_per_div: s.volts_per_div,
        seconds_per_div: s.seconds_per_div,
        trigger_v: s.trigger_v,
        mode: match live.mode {
            ScopeMode::Auto => "auto".into(),
            ScopeMode::Single => "single".into(),
        },
        signal,
    };
    live.status.update(|st| st.trace = Some(Arc::new(shown)));
}
