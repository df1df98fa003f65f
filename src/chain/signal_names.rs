//! Names of the signals the standard chain reads and produces, so that no file spells
//! them by hand.

/// Torque in the intermediate (output) shaft, under the gauges (N m); a plant signal.
pub const SHAFT_TORQUE_NM: &str = "torque_intermediate_shaft_nm";
/// Motor speed (rad/s), what the tacho turns with; a plant signal.
pub const MOTOR_SPEED_RAD_S: &str = "speed1_rad_s";
/// Speed of the gauged shaft's slip rings (rad/s); a plant signal.
pub const SLIP_RING_SPEED_RAD_S: &str = "speed3_rad_s";
/// Surface shear strain at ±45° (strain).
pub const STRAIN: &str = "strain";
/// Bridge output (V).
pub const BRIDGE_V: &str = "bridge_v";
/// Carrier-modulated bridge output (V).
pub const CARRIER_V: &str = "carrier_v";
/// The carrier after the slip rings (V).
pub const SLIP_RING_V: &str = "slip_ring_v";
/// Carrier amplifier output, demodulated (V).
pub const AMPLIFIER_V: &str = "amplifier_v";
/// Anti-alias filter output (V), the analyser's input by default.
pub const FILTER_V: &str = "filter_v";
/// RMS voltmeter reading (V).
pub const METER_V: &str = "meter_v";
/// Tacho generator output (V).
pub const TACHO_V: &str = "tacho_v";
/// Digital voltmeter reading of the tacho (V).
pub const DVM_V: &str = "dvm_v";
