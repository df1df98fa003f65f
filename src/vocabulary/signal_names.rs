//! The signals' names and units, in one place: the signals the plant hands the chain
//! (`crate::rig_roles` fills them from any rig) and the names of the signals the standard
//! chain reads and produces, so that no file spells them by hand. The chain's own units come from its stages
//! (`chain::Instrument`).

/// Torque in the intermediate (output) shaft, under the gauges (N m); a plant signal.
pub const SHAFT_TORQUE_NM: &str = "torque_intermediate_shaft_nm";
/// Motor speed (rad/s), what the tacho turns with; a plant signal.
pub const MOTOR_SPEED_RAD_S: &str = "speed1_rad_s";
/// Speed of the gauged shaft's slip rings (rad/s); a plant signal.
pub const SLIP_RING_SPEED_RAD_S: &str = "speed3_rad_s";
/// The watched gear's once-per-revolution pulse (V); a plant signal.
pub const KEYPHASOR_V: &str = "keyphasor_v";
/// Time (s); a plant signal.
pub const TIME_S: &str = "time_s";

/// The signals the plant hands the chain, in frame order.
pub const PLANT_SIGNALS: [&str; 5] = [
    TIME_S,
    SHAFT_TORQUE_NM,
    MOTOR_SPEED_RAD_S,
    SLIP_RING_SPEED_RAD_S,
    KEYPHASOR_V,
];

/// Surface strain at +45° on the gauged shaft (µε).
pub const STRAIN: &str = "strain";
/// Unit of the chain's strain signal ([`STRAIN`]).
pub const MICROSTRAIN_UNIT: &str = "µε";
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

/// Unit of plant signal `name`; `None` if the plant has no such signal. A rig's own
/// columns (`rig::column_names`) carry their unit in their name: `_rpm`, `_rad`, `_nm`,
/// `_n`, `_ue`, `_m` (a centre's displacement in the plane); `contact_<mesh>` is a state
/// (+1, −1, 0).
pub fn plant_unit(name: &str) -> Option<&'static str> {
    match name {
        TIME_S => Some("s"),
        SHAFT_TORQUE_NM => Some("N m"),
        MOTOR_SPEED_RAD_S | SLIP_RING_SPEED_RAD_S => Some("rad/s"),
        KEYPHASOR_V => Some("V"),
        _ if name.starts_with("contact_") => Some("1"),
        _ => [
            ("_rpm", "rev/min"),
            ("_rad", "rad"),
            ("_nm", "N m"),
            ("_n", "N"),
            ("_ue", MICROSTRAIN_UNIT),
            ("_m", "m"),
        ]
        .into_iter()
        .find(|(suffix, _)| name.ends_with(suffix))
        .map(|(_, unit)| unit),
    }
}

/// Full scale of a plant signal of unit `unit`, for integer recordings (in that unit).
pub fn plant_full_scale(unit: &str) -> f64 {
    match unit {
        "rad/s" => 1_000.0,
        "rev/min" => 10_000.0,
        "rad" => 1.0e6,
        "N" => 1.0e5,
        MICROSTRAIN_UNIT => 1_000.0,
        "1" => 1.0,
        "N m" => 100.0,
        "s" => 1.0e5,
        "V" => 10.0,
        // A bearing's deflection: micrometres, a millimetre at most.
        "m" => 1.0e-3,
        _ => 100.0,
    }
}
