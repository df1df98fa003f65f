//! The discrete state of a rig: each mesh apart or touching one flank with one or two
//! pairs, and the motor linear or held at a torque limit.

use crate::mode::MotorMode;
use crate::topology::MAX_MESHES;

/// How a mesh's teeth meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Contact {
    /// Apart, within the backlash.
    Apart,
    /// The driver's drive flank pushes the driven gear.
    Drive,
    /// The back flanks touch.
    Back,
}

impl Contact {
    /// +1 drive, −1 back, 0 apart (the recordings' contact columns).
    pub fn sign(self) -> i8 {
        match self {
            Self::Apart => 0,
            Self::Drive => 1,
            Self::Back => -1,
        }
    }
}

/// One mesh's discrete state.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MeshState {
    /// Which flank, if any.
    pub contact: Contact,
    /// Two pairs share the load (alternating pairs only).
    pub two_pairs: bool,
}

/// The discrete state of the whole rig.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NetMode {
    /// Each mesh's state (the first `meshes` are used).
    pub meshes: [MeshState; MAX_MESHES],
    /// The motor.
    pub motor: MotorMode,
}

impl NetMode {
    /// Every mesh apart with one pair, the motor linear.
    pub fn apart() -> Self {
        Self {
            meshes: [MeshState {
                contact: Contact::Apart,
                two_pairs: false,
            }; MAX_MESHES],
            motor: MotorMode::Linear,
        }
    }
}
