//! The discrete state of a rig: each mesh apart or touching one flank with one or two
//! pairs (their stiffness scaled where a faulted tooth is in mesh), and the motor linear
//! or held at a torque limit.

use crate::mode::{MotorMode, PairZone};
use crate::topology::MAX_PLANT_MESHES;

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
    /// The pairs in mesh: one, two (alternating pairs only), or a step of a smoothed
    /// change between them.
    pub level: PairZone,
    /// The share of the healthy pairs' stiffness the pairs in mesh keep (a tooth fault;
    /// 1 healthy), as the bits of an f64 so that modes hash.
    pub factor_bits: u64,
    /// Apart because the pair in mesh has no tooth to touch (broken through): no flank
    /// can be touched until the next pair comes into mesh.
    pub toothless: bool,
    /// On its flank, the flanks still overlapping, but the no-pull law has clipped the
    /// force to zero (the damper would pull as the teeth separate): no force until it
    /// pushes again or the overlap ends.
    pub clipped: bool,
}

impl MeshState {
    /// Apart, one pair, healthy.
    pub const APART: Self = Self {
        contact: Contact::Apart,
        level: PairZone::ONE,
        factor_bits: 0x3FF0_0000_0000_0000,
        toothless: false,
        clipped: false,
    };

    /// The share of the healthy pairs' stiffness the pairs in mesh keep.
    pub fn factor(self) -> f64 {
        f64::from_bits(self.factor_bits)
    }

    /// The same state with its force not clipped (the spring as if it pushed).
    pub fn unclipped(self) -> Self {
        Self {
            clipped: false,
            ..self
        }
    }

    /// The flank whose spring pushes (+1 drive, −1 back), if any: none apart or clipped.
    pub fn pushing_flank(self) -> Option<f64> {
        match self.contact {
            _ if self.clipped => None,
            Contact::Apart => None,
            Contact::Drive => Some(1.0),
            Contact::Back => Some(-1.0),
        }
    }
}

/// The discrete state of the whole rig. Equal and hashed by the meshes the rig has (the
/// rest stay apart): a rig of one mesh compares one, not [`MAX_PLANT_MESHES`].
#[derive(Clone, Copy, Debug)]
pub struct NetMode {
    /// Each mesh's state (the first `used` are the rig's).
    pub meshes: [MeshState; MAX_PLANT_MESHES],
    /// How many meshes the rig has.
    used: u8,
    /// The motor.
    pub motor: MotorMode,
}

impl NetMode {
    /// Every one of a rig's `meshes` meshes apart with one pair, the motor linear.
    pub fn apart(meshes: usize) -> Self {
        Self {
            meshes: [MeshState::APART; MAX_PLANT_MESHES],
            used: meshes.min(MAX_PLANT_MESHES) as u8,
            motor: MotorMode::Linear,
        }
    }

    /// The rig's meshes' states.
    pub fn used(&self) -> &[MeshState] {
        &self.meshes[..usize::from(self.used)]
    }
}

impl PartialEq for NetMode {
    fn eq(&self, other: &Self) -> bool {
        self.motor == other.motor && self.used() == other.used()
    }
}

impl Eq for NetMode {}

impl std::hash::Hash for NetMode {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.used().hash(state);
        self.motor.hash(state);
    }
}
