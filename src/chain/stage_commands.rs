//! Commands a chain stage carries out: the anti-alias filter's type and cut-off, the
//! carrier amplifier's gain. The stage is rebuilt with the new settings (its state starts
//! afresh, as when a real filter card is switched); refused, it stays as it was.

use instruments::LowPassSpec;

use crate::chain::{Instrument, NamedStage};
use crate::vocabulary::Refusal;
use crate::vocabulary::command::{RigCommand, Target};

/// Highest carrier amplifier gain accepted (V/V): far beyond the 3C66's.
const MAX_GAIN: f64 = 1.0e6;

/// Carries out `command` if it is for `stage`: `Some(outcome)`, else `None`.
pub fn apply_to_stage(stage: &mut NamedStage, command: &RigCommand) -> Option<Result<(), Refusal>> {
    match command.target() {
        Target::Stage(output) if output == stage.output => {}
        _ => return None,
    }
    let instrument = match command {
        RigCommand::SetFilter {
            kind,
            order,
            cutoff_hz,
        } => {
            let nyquist_hz = stage.rate_hz / 2.0;
            if !(cutoff_hz.is_finite() && *cutoff_hz > 0.0 && *cutoff_hz < nyquist_hz) {
                return Some(Err(Refusal::Setting(format!(
                    "cutoff_hz {cutoff_hz}: a cut-off lies in (0, {nyquist_hz}) Hz"
                ))));
            }
            Instrument::LowPass(kind.kind().map(|kind| LowPassSpec {
                kind,
                order: *order,
                cutoff_hz: *cutoff_hz,
            }))
        }
        RigCommand::SetAmplifierGain { gain } => {
            let Instrument::CarrierDemodulator(mut settings) = stage.plan.instrument.clone() else {
                return Some(Err(Refusal::Setting(format!(
                    "`{}` is not the carrier amplifier",
                    stage.output
                ))));
            };
            if !(*gain > 0.0 && *gain <= MAX_GAIN) {
                return Some(Err(Refusal::Setting(format!(
                    "gain {gain}: a gain lies in (0, {MAX_GAIN}]"
                ))));
            }
            settings.gain = *gain;
            Instrument::CarrierDemodulator(settings)
        }
        _ => return None,
    };
    Some(stage.rebuild(instrument).map_err(Refusal::from))
}
