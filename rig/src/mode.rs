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

/// How many tooth pairs carry the mesh torque.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PairZone {
    /// One pair: stiffness K23.
    One,
    /// Two pairs: stiffness K23 × `double_pair_stiffness_ratio`.
    Two,
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
        let pairs = self.pairs as usize;
        let motor = self.motor as usize;
        (mesh * 2 + pairs) * 3 + motor
    }

    /// Number of distinct modes.
    pub const COUNT: usize = 5 * 2 * 3;
}
