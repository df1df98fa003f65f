//! Every signal a run can record: the plant's true signals and each chain stage's output,
//! with units and a default full scale for integer recordings.

/// Outputs of the measuring chain, in the order the stages produce them.
pub const CHAIN_SIGNALS: [&str; 9] = [
    "strain",
    "bridge_v",
    "carrier_v",
    "slip_ring_v",
    "amplifier_v",
    "filter_v",
    "meter_v",
    "tacho_v",
    "dvm_v",
];

/// Whether `name` is a signal a run produces (slip_ring_v only with slip rings wired).
pub fn is_known(name: &str) -> bool {
    rig::COLUMN_NAMES.contains(&name) || CHAIN_SIGNALS.contains(&name)
}

/// All names, comma-separated, for error messages.
pub fn all_names() -> String {
    rig::COLUMN_NAMES
        .iter()
        .chain(CHAIN_SIGNALS.iter())
        .copied()
        .collect::<Vec<_>>()
        .join(", ")
}

/// Unit of a signal, from the suffix of its name.
pub fn unit_of(name: &str) -> &'static str {
    let units = [
        ("_rad_s", "rad/s"),
        ("_rad", "rad"),
        ("_nm", "N m"),
        ("_v", "V"),
        ("_s", "s"),
    ];
    units
        .iter()
        .find(|(suffix, _)| name.ends_with(suffix))
        .map_or("1", |&(_, unit)| unit)
}

/// Full scale for 24-bit recordings when the scenario gives none (in the signal's unit).
pub fn default_full_scale(name: &str) -> f64 {
    match unit_of(name) {
        "rad/s" => 1_000.0,
        "rad" => 1.0e6,
        "N m" => 100.0,
        "V" => 10.0,
        "s" => 1.0e5,
        _ if name == "strain" => 1.0e-3,
        _ => 100.0,
    }
}
