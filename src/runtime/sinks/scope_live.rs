//! The scope operated live: a second scope sweeping as the panel sets it (auto or
//! single), its latest trace published on the panel. The storage scope (`scope.rs`)
//! owns it and routes the panel's scope commands to it.

use std::sync::Arc;

use instruments::{Block, InstrumentError, Scope, ScopeSettings, SweepMode};

use crate::runtime::status::SharedStatus;
use crate::vocabulary::LiveTrace;
use crate::vocabulary::command::ScopeMode;

/// Most points of a trace sent to the panel (every k-th sample beyond).
const PANEL_POINTS: usize = 2000;

/// A trace the panel asked to save.
pub struct SavedTrace {
    /// Its number among the saves (1, 2, …).
    pub number: usize,
    /// (time from the trigger (s), divisions) of each point.
    pub trace: Vec<(f64, f64)>,
    /// The scope's settings it was taken at.
    pub settings: ScopeSettings,
}

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

impl LiveScope {
    /// A live scope at `settings` on a stream at `rate_hz`, sweeping on every trigger
    /// (auto), publishing to `status`.
    pub fn new(
        settings: ScopeSettings,
        rate_hz: f64,
        status: SharedStatus,
    ) -> Result<Self, InstrumentError> {
        Ok(Self {
            scope: Scope::new(sweep_settings(settings, ScopeMode::Auto), rate_hz)?,
            mode: ScopeMode::Auto,
            seen: 0,
            last: None,
            saved: 0,
            scratch: Vec::new(),
            status,
        })
    }

    /// Feeds the samples `x` of `signal` (in `unit`); a new sweep goes on the panel.
    pub fn watch(&mut self, x: &[f64], (signal, unit): (&str, &str)) {
        self.scratch.resize(x.len(), 0.0);
        self.scope.process(x, &mut self.scratch);
        if self.scope.sweeps() == self.seen {
            return;
        }
        self.seen = self.scope.sweeps();
        self.last = self.scope.trace();
        self.publish(signal, unit);
    }

    /// Re-sets the scope to `settings` in `mode` (its present mode if `None`), on a
    /// stream at `rate_hz`; the present scope stays if the settings are refused.
    pub fn rescale(
        &mut self,
        settings: ScopeSettings,
        mode: Option<ScopeMode>,
        rate_hz: f64,
    ) -> Result<(), InstrumentError> {
        let mode = mode.unwrap_or(self.mode);
        self.scope = Scope::new(sweep_settings(settings, mode), rate_hz)?;
        self.mode = mode;
        self.seen = 0;
        self.rescale_shown(settings);
        Ok(())
    }

    /// The trace on screen redrawn at the new scales at once, as a storage scope does
    /// (its volts kept, its divisions re-counted): the state shows the settings in effect
    /// from the command on, not from the next sweep.
    fn rescale_shown(&self, settings: ScopeSettings) {
        let mode = match self.mode {
            ScopeMode::Auto => "auto",
            ScopeMode::Single => "single",
        };
        self.status.update(|st| {
            if let Some(shown) = &st.trace {
                let ratio = shown.volts_per_div / settings.volts_per_div;
                st.trace = Some(Arc::new(LiveTrace {
                    divisions: shown.divisions.iter().map(|d| d * ratio).collect(),
                    volts_per_div: settings.volts_per_div,
                    seconds_per_div: settings.seconds_per_div,
                    trigger_v: settings.trigger_v,
                    mode: mode.into(),
                    ..(**shown).clone()
                }));
            }
        });
    }

    /// Re-arms the scope (a single sweep starts waiting for its trigger again). The trace
    /// on screen stays until the new sweep is complete, as on a storage scope: the count
    /// of sweeps goes on, so the re-armed scope's empty store is never taken for a sweep.
    pub fn rearm(&mut self) {
        self.scope.reset();
        self.seen = self.scope.sweeps();
    }

    /// The trace on screen to save; `None` (the number still counted) if no sweep has
    /// been shown yet.
    pub fn next_saved(&mut self) -> Option<SavedTrace> {
        self.saved += 1;
        Some(SavedTrace {
            number: self.saved,
            trace: self.last.clone()?,
            settings: self.scope.settings(),
        })
    }

    fn publish(&self, signal: &str, unit: &str) {
        let Some(trace) = &self.last else {
            return;
        };
        let s = self.scope.settings();
        let stride = trace.len().div_ceil(PANEL_POINTS).max(1);
        let shown = LiveTrace {
            time_s: trace.iter().step_by(stride).map(|p| p.0).collect(),
            divisions: trace.iter().step_by(stride).map(|p| p.1).collect(),
            volts_per_div: s.volts_per_div,
            seconds_per_div: s.seconds_per_div,
            trigger_v: s.trigger_v,
            mode: match self.mode {
                ScopeMode::Auto => "auto".into(),
                ScopeMode::Single => "single".into(),
            },
            signal: signal.to_string(),
            unit: unit.to_string(),
        };
        self.status.update(|st| st.trace = Some(Arc::new(shown)));
    }
}

/// `settings` sweeping as `mode` asks: auto repeats, single stops after one sweep.
fn sweep_settings(settings: ScopeSettings, mode: ScopeMode) -> ScopeSettings {
    let sweep_mode = match mode {
        ScopeMode::Auto => SweepMode::Auto,
        ScopeMode::Single => SweepMode::Single,
    };
    ScopeSettings {
        mode: sweep_mode,
        ..settings
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use instruments::Slope;

    /// Re-arming the panel's scope emptied its screen until the next sweep, so "save the
    /// displays" sent just after "arm" saved no trace (a flaky session test). The trace
    /// on screen now stays until the re-armed sweep completes.
    #[test]
    fn a_rearmed_scope_keeps_its_trace_on_screen_until_the_next_sweep() {
        let rate_hz = 51_200.0;
        let settings = ScopeSettings {
            volts_per_div: 0.5,
            seconds_per_div: 0.002,
            trigger_v: 0.0,
            slope: Slope::Rising,
            mode: SweepMode::Single,
        };
        let mut live = LiveScope::new(settings, rate_hz, SharedStatus::default()).expect("valid");
        let sine = |from: usize, n: usize| -> Vec<f64> {
            (from..from + n)
                .map(|k| (std::f64::consts::TAU * 100.0 * k as f64 / rate_hz).sin())
                .collect()
        };
        live.watch(&sine(0, 5_000), ("amplifier_v", "V"));
        live.rearm();
        // A block too short for the re-armed sweep to complete.
        live.watch(&sine(5_000, 100), ("amplifier_v", "V"));
        let saved = live
            .next_saved()
            .expect("the earlier trace is still on screen");
        assert_eq!(saved.number, 1);
        assert_eq!(saved.trace.len(), 1024);
    }
}
