//! The kinds of a planetary gear's free vibration modes that Lin & Parker (J. Vib.
//! Acoust. 121(3), 1999) prove for equally spaced, identical planets: rotational modes
//! (the central members — every body of the rig — only turn), translational modes (they
//! only translate, in degenerate pairs) and planet modes (they stay still, from four
//! planets on). A mode is classed by where its kinetic energy ½ ω² Σ m_j φ_j² lies:
//! a share below [`STILL_SHARE`] counts as none.

use serde::Serialize;

use super::coordinates::{CoordinateKind, RigCoordinates};
use super::rig_topology::RigTopology;
use crate::modal::NaturalMode;

/// Below this share of a mode's kinetic energy a group of coordinates is still (the
/// eigen-solution's rounding leaves ~1e-16).
pub const STILL_SHARE: f64 = 1e-9;

/// A mode's kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ModeKind {
    /// The central members turn and do not translate.
    Rotational,
    /// The central members translate and do not turn.
    Translational,
    /// The central members stay still; only planets move.
    Planet,
    /// None of these (a torsional rig's modes, or a stage with unequal planets).
    Mixed,
}

impl RigTopology {
    /// The kind of each of `modes`, the rig's flexible modes ([`Self::natural_modes`]),
    /// in the same order.
    pub fn mode_kinds(&self, modes: &[NaturalMode]) -> Vec<ModeKind> {
        let coordinates = RigCoordinates::of(self);
        modes.iter().map(|m| kind_of(&coordinates, m)).collect()
    }
}

/// The kind of mode `mode` over `coordinates`.
fn kind_of(coordinates: &RigCoordinates, mode: &NaturalMode) -> ModeKind {
    if coordinates.is_empty() {
        return ModeKind::Mixed;
    }
    let (mut turning, mut translating, mut total) = (0.0, 0.0, 0.0);
    for (j, (c, &phi)) in coordinates.coordinates.iter().zip(&mode.shape).enumerate() {
        let energy = c.mass * phi * phi;
        total += energy;
        if coordinates.is_planet(j) {
            continue;
        }
        match c.kind {
            CoordinateKind::Rotation => turning += energy,
            CoordinateKind::X | CoordinateKind::Y => translating += energy,
        }
    }
    let still = |e: f64| e <= STILL_SHARE * total;
    match (still(turning), still(translating)) {
        (true, true) => ModeKind::Planet,
        (false, true) if coordinates.translates() => ModeKind::Rotational,
        (true, false) => ModeKind::Translational,
        _ => ModeKind::Mixed,
    }
}
