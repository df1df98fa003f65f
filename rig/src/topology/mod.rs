//! The rig as data, the first stage of the pipeline (the rig → its assembled model and
//! plant in `plant/` → the judge): `rig_topology.rs` a rig of any topology as a rig file
//! describes it (bodies, shafts, meshes, motor, brake, drive); `check.rs` what makes it one
//! the plant can run, each fault at its item and field; `fields.rs` every number by its
//! path, with unit and meaning; `modes.rs` its undamped natural modes;
//! `mesh_hold.rs` those with its meshes in contact, rigid or apart.

mod check;
mod fields;
mod mesh_hold;
mod modes;
mod rig_topology;

pub use fields::TopologyField;
pub use mesh_hold::{MeshHold, ModalPart};
pub(crate) use modes::add_coupling;
pub use rig_topology::{
    Body, DriveRatings, DriveSettings, Gauge, LockedTorque, MAX_BODIES, MAX_MESHES, Mesh,
    RigTopology, Shaft,
};
