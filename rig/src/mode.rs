//! The plant's discrete state: which linear system holds between two switches.

/// State of the mesh between two switches.
///
/// `d = X3 − X2` is the relative rotation of the gears, B(t) the free play each side.
/// The thesis's "left" contact (d ≤ −B) is the drive flank: it carries a positive load.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MeshMode {
    /// |d| < B: no mesh torque.
    Apart,
    /// d ≤ −B, mesh torque acting (thesis "left" contact).
    Drive,
    /// d ≥ B, mesh torque acting (thesis "right" contact).
    Back,
    /// d ≤ −B but the no-pull law has clipped the torque to zero (teeth separating).
    DriveClipped,
    /// d ≥ B, torque clipped to zero.
    BackClipped,
}

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
    /// Number of levels.
    pub const LEVELS: usize = Self::TWO.0 as usize + 1;

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

/// The complete discrete state.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Mode {
    /// Mesh contact state.
    pub mesh: MeshMode,
    /// Tooth pairs in contact (only matters while the mesh acts).
    pub pairs: PairZone,
    /// Speed controller state.
    pub motor: MotorMode,
}

/// Which flank the mesh spring acts on, for building the equations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engagement {
    /// No mesh torque.
    Free,
    /// Spring and damper on the drive flank.
    Drive,
    /// Spring and damper on the back flank.
    Back,
}

impl MeshMode {
    /// Which spring acts.
    pub fn engagement(self) -> Engagement {
        match self {
            Self::Drive => Engagement::Drive,
            Self::Back => Engagement::Back,
            Self::Apart | Self::DriveClipped | Self::BackClipped => Engagement::Free,
        }
    }

    /// Contact indicator of the true signals: +1 drive flank, −1 back flank, 0 no torque.
    pub fn contact_code(self) -> i8 {
        match self.engagement() {
            Engagement::Drive => 1,
            Engagement::Back => -1,
            Engagement::Free => 0,
        }
    }

    /// Whether the teeth overlap geometrically (|d| ≥ B), torque or not.
    pub fn overlapping(self) -> bool {
        !matches!(self, Self::Apart)
    }
}

impl Mode {
    /// Index in 0..[`Mode::COUNT`], for caches.
    pub fn index(self) -> usize {
        let mesh = self.mesh as usize;
        let pairs = usize::from(self.pairs.0);
        let motor = self.motor as usize;
        (mesh * PairZone::LEVELS + pairs) * 3 + motor
    }

    /// Number of distinct modes.
    pub const COUNT: usize = 5 * PairZone::LEVELS * 3;
}
