//! The measuring chain of testrig: each instrument of the 1983 rig as a block that turns
//! a sampled input into a sampled output (see `ARCHITECTURE.md` at the project root).
//!
//! This first part holds the block trait; shaft strain, the strain-gauge bridge, the
//! RMS voltmeters, the tacho and its digital voltmeter; the anti-alias low-pass filter
//! (Butterworth and Bessel as cascaded second-order sections); the ADC; and the
//! analyser's windows and spectrum scalings (Heinzel, Rüdiger & Schilling 2002).
//!
//! Blocks. Every block implements `Block` (`reset`, `process(&input, &mut output)` without
//! allocating, `response(hz)`, `latency`) and keeps its state across buffers. `strain.rs`
//! (torque → ±45° strain), `bridge.rs` (full/half/quarter Wheatstone), `carrier.rs` (3C66
//! as modulator before and synchronous demodulator after the slip rings, sharing one
//! carrier), `slip_ring.rs` (contact resistance fluctuation and contact noise, seeded),
//! `voltmeter.rs` (HP 400E and true RMS), `tacho.rs` (AC tacho and its DVM), `lowpass.rs`
//! with `analog.rs` and `biquad.rs` (Butterworth/Bessel as second-order sections by the
//! bilinear transform), `adc.rs` (samples the stream at its own rate: every M-th sample, or
//! Kaiser-windowed sinc between samples; bits, range, clipping, TPDF dither), `window.rs`
//! and `spectrum.rs` (scalings after Heinzel et al.), `analyser.rs` (5451C: conventions,
//! averaging, overlap), `truth.rs` (which displayed lines are aliases, from the analogue
//! signal), `keyboard_program.rs` (the App. E program from text), `scope.rs`,
//! `brake_drive.rs` (function generator, coil lag, brake torque), `noise.rs` (seeded
//! Gaussian), `phase.rs` (a running phase kept within its period), `ac_coupling.rs` (the
//! AC input of the 400E and the scope); `block.rs` the trait, `error.rs` the errors.
//!
//! ```
//! use instruments::{AntiAliasFilter, Block, FilterKind, LowPassSpec};
//!
//! // The thesis's 2 kHz setting on the 51.2 kHz stream: an 8th-order Butterworth.
//! let spec = LowPassSpec { kind: FilterKind::Butterworth, order: 8, cutoff_hz: 2_000.0 };
//! let filter = AntiAliasFilter::new(Some(spec), 51_200.0)?;
//! let at = |hz: f64| 20.0 * filter.response(hz).unwrap().norm().log10();
//! assert!((at(2_000.0) + 3.01).abs() < 0.01);
//! // A 2.2 kHz line that would alias to 1.8 kHz at 4 kHz sampling is cut by about 6.6 dB.
//! assert!(at(2_200.0) < -6.0);
//! # Ok::<(), instruments::InstrumentError>(())
//! ```

mod ac_coupling;
mod adc;
mod analog;
mod analyser;
mod biquad;
mod block;
mod brake_drive;
mod bridge;
mod carrier;
mod condition_indicators;
mod error;
mod keyboard_program;
mod lowpass;
mod noise;
mod phase;
mod scope;
mod slip_ring;
mod spectrum;
mod strain;
mod synchronous_average;
mod tacho;
mod truth;
mod voltmeter;
mod window;

pub use ac_coupling::AcCoupling;
pub use adc::{Adc, AdcSettings};
pub use analyser::{Analyser, AnalyserSettings, Averaging, Line, Sampling};
pub use block::Block;
pub use brake_drive::{BrakeDrive, BrakeDriveSettings};
pub use bridge::{BridgeArrangement, StrainBridge};
pub use carrier::{CarrierDemodulator, CarrierModulator, CarrierSettings};
pub use condition_indicators::{
    ConditionIndicators, GearSignals, SHAFT_ORDERS, central_moment, condition_indicators,
    gear_signals, normalised_moment,
};
pub use error::InstrumentError;
pub use keyboard_program::{KeyboardProgram, ProgramStep};
pub use lowpass::{AntiAliasFilter, FilterKind, LowPassSpec};
pub use noise::GaussianSource;
pub use scope::{Scope, ScopeSettings, Slope, SweepMode};
pub use slip_ring::{SlipRing, SlipRingSettings};
pub use spectrum::{Spectrum, SpectrumEstimator};
pub use strain::ShaftStrain;
pub use synchronous_average::synchronous_average;
pub use tacho::{CROMPTON_PARKINSON_V_PER_RPM, DigitalVoltmeter, Tacho};
pub use truth::AliasTruth;
pub use voltmeter::{Detector, Voltmeter};
pub use window::Window;
