//! The one plant, of any rig a rig file describes ([`crate::RigTopology`]): bodies (turning,
//! or also moving in the plane on bearings), shafts, external meshes and planetary stages
//! with backlash (up to 20 meshes; a stage's translations kept in its carrier's frame,
//! `model.rs`), a speed-controlled motor, a brake, a locked-in loop torque; advanced
//! exactly between the switches of every mesh and of the motor's limit, each switch
//! found on the exact solution. `ring_sensor.rs` a stage's ring transducer as a column.
//!
//! `layout.rs` the state: absolute angles and speeds, the speed loop, then forcing states
//! (unit, set speed and its ramp rate, brake load and its rate, the oscillating load's
//! pair, the set rotation, the meshes' harmonic pairs and spacing errors). `mode.rs` the
//! discrete state (each mesh apart / drive / back, clipped under the no-pull law, its
//! pairs one, two or a step of a smoothed change; the motor linear or at a limit).
//! `model.rs` the constants of a topology (the gear errors included) and its forms,
//! `system_matrix.rs` A of u' = A u per mode, `drive_model.rs` the motor's and the brake's (drag, characteristic), `mesh_model.rs` a mesh's constants (its pair zones,
//! its faulted teeth's factors). `events.rs` the switching functions of a mode.
//! `system.rs` per mode the fused step (e^{A h}'s mechanical rows with the fixed-target
//! functions' values and rates) and the events, `span_ends.rs` where each function's end
//! comes from (a row, or an angle the set rotation's functions share), `system_cache.rs`
//! them built on first use and kept; `run_spans.rs` them folded for a fast run, the forcing states that hold
//! still in one column.
//! `equilibrium.rs` the steady state at a set speed and load (and at rest, a loop's
//! locked torque carried), and the model assembled with a loop's preload.
//! `block.rs` the samples and impacts a run gives, `output.rs` the samples held by
//! state and turned into signals a chunk at a time, `columns.rs` them as named columns.
//! `run_up.rs` how long the drive takes to run the rig up from rest.
//! `network_plant.rs` the plant (`NetworkPlant`: the name it had beside the retired thesis plant), `teeth.rs` its pair zones and tooth passes, `segment.rs` its set
//! points over time, `fast.rs` its runs of samples in one mode, `record_stride.rs` the
//! strides of a run that writes samples,
//! `stepping.rs` its exact steps and switches, `span_gaps.rs` a function's gaps to its
//! target over a span as the checks judge them, `products.rs` the
//! matrix–state products they take.

mod block;
mod columns;
mod drive_model;
mod equilibrium;
mod events;
mod fast;
mod layout;
mod mesh_model;
mod mode;
mod model;
mod network_plant;
mod output;
mod products;
mod record_stride;
mod ring_sensor;
mod run_spans;
mod run_up;
mod segment;
mod span_ends;
mod span_gaps;
mod sparse_rows;
mod stepping;
mod system;
mod system_cache;
mod system_matrix;
mod teeth;

pub use block::{NetworkBlock, NetworkImpact};
pub use columns::{Column, column, column_names, column_specs, columns, shaft_torque_column};
pub use mode::Contact;
pub use network_plant::{NetworkPlant, NetworkStart, SKIP_STRETCH};
pub use ring_sensor::{passage_window, ring_sensor_n};
