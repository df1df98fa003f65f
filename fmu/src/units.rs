//! The units the variables use, as FMI's `<UnitDefinitions>` give them: each a product of
//! SI base units (and rad) to powers, times a factor.

/// One unit: its name, the exponents of kg, m, s, A and rad, and its factor to SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnitDefinition {
    /// The name variables give.
    pub name: &'static str,
    /// Exponents of kg, m, s, A, rad.
    pub exponents: [i32; 5],
    /// Value in SI per unit (1 rev/min = π/30 rad/s).
    pub factor: f64,
}

const DEG: f64 = std::f64::consts::PI / 180.0;
const RPM: f64 = std::f64::consts::PI / 30.0;

/// Every unit a variable of any rig may name.
pub const UNITS: [UnitDefinition; 21] = [
    unit("s", [0, 0, 1, 0, 0], 1.0),
    unit("m", [0, 1, 0, 0, 0], 1.0),
    unit("mm", [0, 1, 0, 0, 0], 1e-3),
    unit("um", [0, 1, 0, 0, 0], 1e-6),
    unit("rad", [0, 0, 0, 0, 1], 1.0),
    unit("deg", [0, 0, 0, 0, 1], DEG),
    unit("rev/min", [0, 0, -1, 0, 1], RPM),
    unit("Hz", [0, 0, -1, 0, 0], 1.0),
    unit("kg m^2", [1, 2, 0, 0, 0], 1.0),
    unit("N", [1, 1, -2, 0, 0], 1.0),
    unit("N m", [1, 2, -2, 0, 0], 1.0),
    unit("N/m", [1, 0, -2, 0, 0], 1.0),
    unit("N s/m", [1, 0, -1, 0, 0], 1.0),
    unit("N m/rad", [1, 2, -2, 0, -1], 1.0),
    unit("N m s/rad", [1, 2, -1, 0, -1], 1.0),
    unit("Pa", [1, -1, -2, 0, 0], 1.0),
    unit("ue", [0, 0, 0, 0, 0], 1e-6),
    unit("1", [0, 0, 0, 0, 0], 1.0),
    unit("%", [0, 0, 0, 0, 0], 0.01),
    unit("W", [1, 2, -3, 0, 0], 1.0),
    unit("A", [0, 0, 0, 1, 0], 1.0),
];

const fn unit(name: &'static str, exponents: [i32; 5], factor: f64) -> UnitDefinition {
    UnitDefinition {
        name,
        exponents,
        factor,
    }
}

/// The definition of `name`, if it is one of [`UNITS`].
pub fn unit_definition(name: &str) -> Option<&'static UnitDefinition> {
    UNITS.iter().find(|u| u.name == name)
}
