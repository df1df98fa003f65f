//! The measuring chain as stages, one instrument each, wired in the rig's order:
//! shaft torque → strain → bridge → carrier modulator → slip rings → demodulator
//! (amplifier output) → anti-alias filter; amplifier output → RMS meter; motor speed →
//! tacho → DVM. Each stage reads channels of the frame and adds its own.

use instruments::{AntiAliasFilter, Block, CarrierDemodulator, CarrierModulator, SlipRing, Tacho};

use super::frame::{Frame, SignalNames};
use crate::scenario::ChainPlan;

/// One instrument working on frames.
pub trait Stage: Send {
    /// Writes the stage's output for `frame` into `out` (the frame's length).
    fn process(&mut self, frame: &Frame, out: &mut [f64]);
}

/// A [`Block`] reading one channel.
struct BlockStage<B> {
    block: B,
    input: usize,
}

impl<B: Block + Send> Stage for BlockStage<B> {
    fn process(&mut self, frame: &Frame, out: &mut [f64]) {
        self.block.process(&frame.channels[self.input], out);
    }
}

/// Slip rings, turning at the mean speed of their shaft over each block.
struct SlipRingStage {
    rings: SlipRing,
    input: usize,
    speed: usize,
}

impl Stage for SlipRingStage {
    fn process(&mut self, frame: &Frame, out: &mut [f64]) {
        let speeds = &frame.channels[self.speed];
        let mean = speeds.iter().sum::<f64>() / speeds.len().max(1) as f64;
        self.rings.set_rotation_hz(mean / std::f64::consts::TAU);
        self.rings.process(&frame.channels[self.input], out);
    }
}

/// A stage with the name of the signal it adds.
pub struct NamedStage {
    /// Output signal name.
    pub output: &'static str,
    /// The instrument.
    pub stage: Box<dyn Stage>,
}

/// Builds the chain's stages for a stream at `rate_hz`; `names` holds the plant's
/// channels on entry and every stage's output on return.
pub fn build_stages(
    plan: &ChainPlan,
    rate_hz: f64,
    names: &mut SignalNames,
) -> anyhow::Result<Vec<NamedStage>> {
    let mut stages = Vec::new();
    let mut add = |names: &mut SignalNames, output: &'static str, stage: Box<dyn Stage>| {
        names.push(output);
        stages.push(NamedStage { output, stage });
    };
    let index = |names: &SignalNames, name: &str| {
        names
            .index(name)
            .ok_or_else(|| anyhow::anyhow!("internal wiring: no signal `{name}`"))
    };
    let torque = index(names, "torque_intermediate_shaft_nm")?;
    add(names, "strain", block(plan.shaft, torque));
    let strain = index(names, "strain")?;
    add(names, "bridge_v", block(plan.bridge, strain));
    let bridge = index(names, "bridge_v")?;
    add(
        names,
        "carrier_v",
        block(CarrierModulator::new(plan.carrier, rate_hz)?, bridge),
    );
    let mut carried = index(names, "carrier_v")?;
    if let Some(settings) = plan.slip_rings {
        let stage = SlipRingStage {
            rings: SlipRing::new(settings, rate_hz, 0.0)?,
            input: carried,
            speed: index(names, "speed3_rad_s")?,
        };
        add(names, "slip_ring_v", Box::new(stage));
        carried = index(names, "slip_ring_v")?;
    }
    add(
        names,
        "amplifier_v",
        block(CarrierDemodulator::new(plan.carrier, rate_hz)?, carried),
    );
    let amplifier = index(names, "amplifier_v")?;
    add(
        names,
        "filter_v",
        block(AntiAliasFilter::new(plan.filter, rate_hz)?, amplifier),
    );
    add(
        names,
        "meter_v",
        block(plan.meter.build(rate_hz)?, amplifier),
    );
    let motor_speed = index(names, "speed1_rad_s")?;
    add(
        names,
        "tacho_v",
        block(Tacho::crompton_parkinson(rate_hz)?, motor_speed),
    );
    let tacho = index(names, "tacho_v")?;
    add(names, "dvm_v", block(plan.dvm.build(rate_hz)?, tacho));
    Ok(stages)
}

fn block<B: Block + Send + 'static>(block: B, input: usize) -> Box<dyn Stage> {
    Box::new(BlockStage { block, input })
}
