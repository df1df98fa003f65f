//! The rig's standard chain as one table: gauges on the intermediate shaft → bridge →
//! carrier modulator → slip rings (when wired) → demodulator (amplifier output) →
//! anti-alias filter; amplifier output → RMS meter; motor speed → tacho → DVM.

use instruments::{CarrierSettings, LowPassSpec, ShaftStrain, SlipRingSettings, StrainBridge};

use super::instrument::Instrument;
use super::stage_plan::StagePlan;
use super::voltmeters::{DvmSettings, MeterSettings};
use crate::vocabulary::signal_names::{
    AMPLIFIER_V, BRIDGE_V, CARRIER_V, DVM_V, FILTER_V, METER_V, MOTOR_SPEED_RAD_S, SHAFT_TORQUE_NM,
    SLIP_RING_SPEED_RAD_S, SLIP_RING_V, STRAIN, TACHO_V,
};

/// The standard stages' settings.
#[derive(Clone, Debug)]
pub struct StandardChain {
    /// Shaft under the gauges.
    pub shaft: ShaftStrain,
    /// Gauges and bridge.
    pub bridge: StrainBridge,
    /// Carrier amplifier (modulator and demodulator share it).
    pub carrier: CarrierSettings,
    /// Slip rings, if wired (left out: the bridge feeds the demodulator directly).
    pub slip_rings: Option<SlipRingSettings>,
    /// Anti-alias filter (`None`: a straight wire).
    pub filter: Option<LowPassSpec>,
    /// The signal the filter reads (`None`: `amplifier_v`).
    pub filter_input: Option<String>,
    /// RMS meter.
    pub meter: MeterSettings,
    /// The signal the meter reads (`None`: `amplifier_v`).
    pub meter_input: Option<String>,
    /// Tacho DVM.
    pub dvm: DvmSettings,
}

impl StandardChain {
    /// Amplifier output (V) per N m of intermediate-shaft torque, static.
    pub fn volts_per_nm(&self) -> f64 {
        self.shaft.strain_per_nm() * self.bridge.output_v(1.0) * self.carrier.gain
    }
}

/// The standard stages in the rig's order, as (output, inputs, instrument) rows.
pub fn standard_stages(c: &StandardChain) -> Vec<StagePlan> {
    let carried = if c.slip_rings.is_some() {
        SLIP_RING_V
    } else {
        CARRIER_V
    };
    let filter_input = c.filter_input.as_deref().unwrap_or(AMPLIFIER_V);
    let meter_input = c.meter_input.as_deref().unwrap_or(AMPLIFIER_V);
    let rows: [(&str, &[&str], Option<Instrument>); 9] = [
        (
            STRAIN,
            &[SHAFT_TORQUE_NM],
            Some(Instrument::Strain(c.shaft)),
        ),
        (BRIDGE_V, &[STRAIN], Some(Instrument::Bridge(c.bridge))),
        (
            CARRIER_V,
            &[BRIDGE_V],
            Some(Instrument::CarrierModulator(c.carrier)),
        ),
        (
            SLIP_RING_V,
            &[CARRIER_V, SLIP_RING_SPEED_RAD_S],
            c.slip_rings.map(Instrument::SlipRings),
        ),
        (
            AMPLIFIER_V,
            &[carried],
            Some(Instrument::CarrierDemodulator(c.carrier)),
        ),
        (
            FILTER_V,
            &[filter_input],
            Some(Instrument::LowPass(c.filter)),
        ),
        (METER_V, &[meter_input], Some(Instrument::Meter(c.meter))),
        (TACHO_V, &[MOTOR_SPEED_RAD_S], Some(Instrument::Tacho)),
        (DVM_V, &[TACHO_V], Some(Instrument::Dvm(c.dvm))),
    ];
    rows.into_iter()
        .filter_map(|(output, inputs, instrument)| {
            Some(StagePlan {
                output: output.to_string(),
                inputs: inputs.iter().map(|i| i.to_string()).collect(),
                instrument: instrument?,
            })
        })
        .collect()
}
