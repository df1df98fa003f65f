//! Parts of the plant's discrete state (`plant/mode.rs`): a mesh's stiffness level
//! and the drive's speed controller.

/// How stiff the mesh is: one pair (level 0), two pairs (level [`PairZone::TWO`]), or a
/// step of a smoothed change between them (levels 1 … 4, `mesh_stiffness_smoothing`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PairZone(pub u8);

/// Steps of each smoothed change between one and two pairs.
pub const TRANSITION_STEPS: u8 = 4;

impl PairZone {
    /// One pair: stiffness K23.
    pub const ONE: Self = Self(0);
    /// Two pairs: stiffness K23 × `double_pair_stiffness_ratio`.
    pub const TWO: Self = Self(TRANSITION_STEPS + 1);

    /// Where the level lies from one pair (0) to two (1): step l of a change at (l − ½)/steps.
    pub fn share_of_second_pair(self) -> f64 {
        match self.0 {
            0 => 0.0,
            l if l >= Self::TWO.0 => 1.0,
            l => (f64::from(l) - 0.5) / f64::from(TRANSITION_STEPS),
        }
    }
}

/// State of the drive's speed controller.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MotorMode {
    /// PI output within the torque limit.
    Linear,
    /// At +limit; the integrator tracks so that the command stays at the limit.
    LimitHigh,
    /// At −limit; the integrator tracks likewise.
    LimitLow,
}
