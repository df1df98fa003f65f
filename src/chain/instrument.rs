//! Every kind of instrument a chain stage can be, with its settings: what it reads, the
//! unit and full scale of what it writes, and how it is built on a stream.

use instruments::{
    AcCoupling, AntiAliasFilter, CarrierDemodulator, CarrierModulator, CarrierSettings,
    InstrumentError, LowPassSpec, ShaftStrain, SlipRing, SlipRingSettings, StrainBridge, Tacho,
};

use super::microstrain::{MICROSTRAIN_PER_STRAIN, MicrostrainBridge, ShaftMicrostrain};
use super::stage::{Stage, block_stage, slip_ring_stage};
use super::voltmeters::{DvmSettings, MeterSettings};
use crate::vocabulary::signal_names::MICROSTRAIN_UNIT;

/// One instrument and its settings.
#[derive(Clone, Debug)]
pub enum Instrument {
    /// Shaft torque (N m) to surface strain at +45° (µε).
    Strain(ShaftStrain),
    /// Strain gauges in a Wheatstone bridge: strain (µε) to volts.
    Bridge(StrainBridge),
    /// The carrier amplifier's modulator (before the slip rings).
    CarrierModulator(CarrierSettings),
    /// Slip rings: reads the carrier and the shaft speed (rad/s).
    SlipRings(SlipRingSettings),
    /// The carrier amplifier's synchronous demodulator and output filter.
    CarrierDemodulator(CarrierSettings),
    /// A low-pass filter (`None`: a straight wire).
    LowPass(Option<LowPassSpec>),
    /// An RMS voltmeter.
    Meter(MeterSettings),
    /// The AC tacho generator: motor speed (rad/s) to volts.
    Tacho,
    /// The digital voltmeter on the tacho.
    Dvm(DvmSettings),
    /// A first-order AC coupling (high-pass) with its corner (Hz).
    AcCoupling(f64),
}

impl Instrument {
    /// How many input signals it reads (the slip rings also read their shaft's speed).
    pub fn input_count(&self) -> usize {
        match self {
            Self::SlipRings(_) => 2,
            _ => 1,
        }
    }

    /// Whether its output is in its input's unit: a linear filter (a low-pass, an AC
    /// coupling) passes a force in newtons as newtons, and an RMS meter reads it in
    /// newtons. The others write their own ([`Self::unit`]).
    pub fn keeps_unit(&self) -> bool {
        matches!(
            self,
            Self::LowPass(_) | Self::AcCoupling(_) | Self::Meter(_)
        )
    }

    /// Unit of its output, unless it keeps its input's ([`Self::keeps_unit`]).
    pub fn unit(&self) -> &'static str {
        match self {
            Self::Strain(_) => MICROSTRAIN_UNIT,
            _ => "V",
        }
    }

    /// Full scale of its output for integer recordings (in its unit).
    pub fn full_scale(&self) -> f64 {
        match self {
            Self::Strain(_) => 1.0e-3 * MICROSTRAIN_PER_STRAIN,
            _ => 10.0,
        }
    }

    /// A line saying what it is, for metadata and plots.
    pub fn describe(&self) -> String {
        match self {
            Self::LowPass(Some(f)) => {
                format!("{:?} order {} at {} Hz", f.kind, f.order, f.cutoff_hz)
            }
            Self::LowPass(None) => "none".into(),
            Self::Meter(m) => format!("{:?} RMS meter, τ {} s", m.detector, m.tau_s),
            other => format!("{other:?}"),
        }
    }

    /// Gives a seeded instrument the seed `seed` (each sweep case its own).
    pub fn reseed(&mut self, seed: u64) {
        if let Self::SlipRings(s) = self {
            s.seed = seed;
        }
    }

    /// The instrument on a stream at `rate_hz`, reading the channels `inputs`
    /// ([`Self::input_count`] of them).
    pub fn build(&self, rate_hz: f64, inputs: &[usize]) -> Result<Box<dyn Stage>, InstrumentError> {
        let input = inputs[0];
        Ok(match self {
            Self::Strain(s) => block_stage(ShaftMicrostrain(*s), input),
            Self::Bridge(b) => block_stage(MicrostrainBridge(*b), input),
            Self::CarrierModulator(c) => block_stage(CarrierModulator::new(*c, rate_hz)?, input),
            Self::SlipRings(s) => {
                slip_ring_stage(SlipRing::new(*s, rate_hz, 0.0)?, input, inputs[1])
            }
            Self::CarrierDemodulator(c) => {
                block_stage(CarrierDemodulator::new(*c, rate_hz)?, input)
            }
            Self::LowPass(spec) => block_stage(AntiAliasFilter::new(*spec, rate_hz)?, input),
            Self::Meter(m) => block_stage(m.build(rate_hz)?, input),
            Self::Tacho => block_stage(Tacho::crompton_parkinson(rate_hz)?, input),
            Self::Dvm(d) => block_stage(d.build(rate_hz)?, input),
            Self::AcCoupling(corner_hz) => {
                block_stage(AcCoupling::new(*corner_hz, rate_hz)?, input)
            }
        })
    }
}
