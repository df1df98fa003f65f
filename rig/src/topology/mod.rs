//! The rig as data, the first stage of the pipeline (the rig → its assembled model and
//! plant in `plant/` → the judge): `rig_topology.rs` a rig of any topology as a rig file
//! describes it (bodies, shafts, meshes, motor, brake, drive); `check.rs` what makes it one
//! the plant can run, each fault at its item and field (`check_planar.rs` for bearings,
//! shafts to the frame and planetary stages); `fields.rs` every number by its
//! path, with unit and meaning; `planetary.rs` a planetary stage's geometry and speeds; `speeds.rs` each body's share
//! of the motor's speed;
//! `coordinates.rs` the rig's coordinates in the plane and its stiffness on them;
//! `modes.rs` its undamped natural modes, `mode_kind.rs` their kinds in a planetary stage; `mesh_hold.rs` those with its meshes in
//! contact, rigid or apart; `stage_phasing.rs` a stage mesh's pair zones and phase by
//! its planet's place (Parker & Lin 2004); `stage_fields.rs` a stage's paths.

mod check;
mod check_planar;
mod coordinates;
mod fields;
mod mesh_hold;
mod mode_kind;
mod modes;
mod planetary;
mod rig_topology;
mod speeds;
mod stage_fields;
mod stage_phasing;

pub use coordinates::{Coordinate, CoordinateKind, Coupling, MeshForm, RigCoordinates};
pub use fields::TopologyField;
pub use mesh_hold::{MeshHold, ModalPart};
pub use mode_kind::{ModeKind, STILL_SHARE};
pub(crate) use modes::add_coupling;
pub use planetary::{
    LineOfAction, MAX_PLANETS, PlanarBearing, PlanetaryStage, RingSensor, StageFault, StageMember,
    StageMesh, StageRadii, StageTeeth,
};
pub use rig_topology::{
    Body, DriveRatings, DriveSettings, FrameShaft, Gauge, LockedTorque, MAX_BODIES,
    MAX_PLANT_MESHES, Mesh, RigTopology, Shaft,
};
pub use stage_phasing::StageMeshPhase;
