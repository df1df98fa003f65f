//! The plant's true signals as a run records them: units and full scales. The chain's
//! signals are described by their stages (`chain::Instrument`).

/// Unit of plant signal `name` (from the suffix of its name); `None` if the plant has
/// no such signal.
pub fn plant_unit(name: &str) -> Option<&'static str> {
    if !rig::COLUMN_NAMES.contains(&name) {
        return None;
    }
    let units = [
        ("_rad_s", "rad/s"),
        ("_rad", "rad"),
        ("_nm", "N m"),
        ("_s", "s"),
    ];
    Some(
        units
            .iter()
            .find(|(suffix, _)| name.ends_with(suffix))
            .map_or("1", |&(_, unit)| unit),
    )
}

/// Full scale of a plant signal of unit `unit`, for integer recordings (in that unit).
pub fn plant_full_scale(unit: &str) -> f64 {
    match unit {
        "rad/s" => 1_000.0,
        "rad" => 1.0e6,
        "N m" => 100.0,
        "s" => 1.0e5,
        _ => 100.0,
    }
}
