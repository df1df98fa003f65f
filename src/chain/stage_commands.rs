//! Commands a chain stage carries out: the anti-alias filter's type and cut-off, the
//! carrier amplifier's gain. The stage is rebuilt with the new settings (its state starts
//! afresh, as when a real filter card is switched); refused, it stays as it was.

use instruments::FilterKind;

use crate::chain::{Instrument, LowPassWords, NamedStage};
use crate::vocabulary::command::{RigCommand, Target};
use crate::vocabulary::signal_names::{AMPLIFIER_V, FILTER_V};
use crate::vocabulary::{AppliedChain, AppliedFilter, Refusal};

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
            let words = LowPassWords {
                kind: kind.kind(),
                order: *order,
                cutoff_hz: Some(*cutoff_hz),
            };
            match words.spec(*cutoff_hz, stage.rate_hz) {
                Ok(spec) => Instrument::LowPass(spec),
                Err(e) => {
                    return Some(Err(Refusal::Setting(format!("cutoff_hz {cutoff_hz}: {e}"))));
                }
            }
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

/// Writes what `stage` applies into `chain`, if it is the amplifier or the anti-alias
/// filter (the panel's echo).
pub fn echo_stage(stage: &NamedStage, chain: &mut AppliedChain) {
    match (&stage.plan.instrument, stage.output.as_str()) {
        (Instrument::CarrierDemodulator(settings), AMPLIFIER_V) => {
            chain.amplifier_gain = Some(settings.gain);
        }
        (Instrument::LowPass(spec), FILTER_V) => {
            chain.filter = Some(match spec {
                Some(spec) => AppliedFilter {
                    kind: match spec.kind {
                        FilterKind::Butterworth => "butterworth",
                        FilterKind::Bessel => "bessel",
                    }
                    .into(),
                    order: spec.order,
                    cutoff_hz: spec.cutoff_hz,
                },
                None => AppliedFilter {
                    kind: "none".into(),
                    order: 0,
                    cutoff_hz: 0.0,
                },
            });
        }
        _ => {}
    }
}
