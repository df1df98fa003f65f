//! What every SCPI client of one live rig shares: the control channel and state, the
//! identity, the limits of its set points, the analyser's settings at the start (which
//! `*RST` restores) and the token beyond loopback.

use std::sync::Arc;
use std::sync::atomic::AtomicBool;

use rig::LiveCeiling;

use crate::runtime::status::SharedStatus;
use crate::scenario::Plan;
use crate::vocabulary::choices::WindowChoice;
use crate::vocabulary::command::RigCommand;
use crate::vocabulary::control::ControlHandle;

/// What every client of one rig shares.
#[derive(Clone)]
pub struct Rack {
    /// The control channel of the live rig.
    pub control: ControlHandle,
    /// Its state.
    pub status: SharedStatus,
    /// `*IDN?`'s answer.
    pub identity: String,
    /// Stream rate (Hz).
    pub rate_hz: f64,
    /// Highest speed set point (rev/min).
    pub max_speed_rpm: f64,
    /// Highest brake load (N m).
    pub max_load_nm: f64,
    /// Highest oscillating-load frequency (Hz).
    pub max_oscillating_hz: f64,
    /// The commands that put the analyser back to its settings at the start (`*RST`);
    /// empty without an analyser.
    pub reset: Vec<RigCommand>,
    /// The token protected commands wait for (`None` on loopback).
    pub token: Option<String>,
    /// Whether the scenario has an analyser and a scope (their displays appear in the
    /// state once the run has started).
    pub has_analyser: bool,
    /// See `has_analyser`.
    pub has_scope: bool,
    /// Set when the server stops: a waiting `*OPC?` gives up.
    pub stop: Arc<AtomicBool>,
}

/// The rack of a live run of `plan` with set points up to `ceiling`.
pub fn scpi_rack(
    plan: &Plan,
    ceiling: LiveCeiling,
    control: ControlHandle,
    status: SharedStatus,
) -> Rack {
    let reset = plan.analyser.as_ref().map_or_else(Vec::new, |a| {
        let s = a.settings;
        vec![
            RigCommand::SetAnalyser {
                fmax_hz: Some(s.fmax_hz),
                block: Some(s.block),
                window: Some(WindowChoice(s.window)),
                averages: Some(s.averages),
                overlap_pct: Some(100.0 * s.overlap),
            },
            RigCommand::SetAdcRange {
                range_v: a.adc.range_v,
            },
        ]
    });
    Rack {
        control,
        status,
        identity: format!(
            "testrig,{} (virtual rig; 35670A-style analyser),{},{}",
            plan.name.replace(',', " "),
            plan.seed,
            env!("CARGO_PKG_VERSION")
        ),
        rate_hz: plan.rate_hz,
        max_speed_rpm: ceiling.speed_rpm,
        max_load_nm: plan.rig.max_load_nm(),
        max_oscillating_hz: ceiling.oscillating_load_hz,
        reset,
        has_analyser: plan.analyser.is_some(),
        has_scope: plan.chain.scope.is_some(),
        token: None,
        stop: Arc::new(AtomicBool::new(false)),
    }
}
