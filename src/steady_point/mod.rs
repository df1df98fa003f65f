//! One steady operating point of a rig alone, unpaced (`testrig simulate`, Python's
//! `testrig.simulate`; a preset's rig or a rig file's): the plant of any topology (`rig::NetworkPlant`) brought to the set speed and
//! load by its approach (`rig::Approach`), settled, then measured with every block handed to the caller;
//! its signals named after the rig's bodies, shafts and meshes.
//!
//! The motion is judged, as for the 1983 rig (`docs/physics.md`), on the gauged shaft's
//! torque (the last shaft where the file has no `[gauge]`) in revolutions of the motor's
//! body.
//!
//! `point.rs` the point run (its spec, its settling, its window handed on), `window.rs`
//! the measuring window summed block by block and judged, `summary.rs` what it reports.

mod point;
mod summary;
mod window;

pub use point::{
    RigPointRun, RigPointSpec, motor_of, run_rig_point, settled_rig_plant, skip_rig_samples,
};
pub use summary::{BodySummary, MeshSummary, RigPointSummary, ShaftSummary, regime_of};
pub use window::{RigWindow, judged_shaft};
