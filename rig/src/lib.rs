//! The physical plant of testrig: any geared rig a rig file describes (`RigTopology`:
//! bodies, shafts, spur meshes with backlash, a speed-controlled motor, a brake), F.
//! Basmaji's 1983 rig among them, advanced exactly between contact switches by one
//! engine. See `ARCHITECTURE.md` at the project root.
//!
//! Modules. One concept per file; `lib.rs` only declares and re-exports. The folders
//! follow the pipeline: the rig as data (`topology/`) → the assembled model and the plant
//! that steps it (`plant/`) → the judge of its motion (`judge/`).
//!
//! `topology/` the rig itself as data: its fields by path, its checks, its natural modes
//! (`mesh_hold.rs` which meshes hold, for `modes`). `params.rs` the 1983 rig's parameter
//! set in the thesis's names (SI, units in names) and its validation; `param_table.rs`
//! access by name (`--set`), with unit and meaning; `presets.rs` named sets
//! (`basmaji-1983`, the thesis's numbers; `basmaji-1983-calibrated`, the second search's
//! best; `basmaji-1983-hand`, the calibration before the searches; see
//! `docs/calibration.md`); `preset_rig.rs` a preset's parameters as the rig they describe
//! (each shipped preset file is its conversion). `options.rs` contact law, tooth pairs;
//! `geometry.rs` pitch radius, backlash from the centre-distance shift, contact ratio;
//! `mesh_stiffness.rs` a spur pair's stiffness by the potential-energy method (checked
//! against ISO 6336-1); `eddy_current.rs` the brake's characteristic and its slope at a
//! set point; `spacing.rs` the seeded tooth-pair spacing errors; `tooth_fault.rs` seeded
//! tooth faults; `pair_zones.rs` the stiffness zones of a tooth period (sharp, or each
//! change a staircase); `mode.rs` a mesh's stiffness level and the motor's mode;
//! `modal.rs` natural frequencies and shapes of chains (App. C's reference).
//!
//! `plant/` the plant: the augmented state's layout, the model (A of u' = A u per mode,
//! the drive and the brake linearised at the set point), the switching functions, the
//! exact step (e^{A h}, switches located on the Taylor expansion), the fast path's runs
//! and strides, the samples and the true signals. Below it, shared: `matrix_exp.rs`
//! (balanced Padé e^{A h}, spectral radius), `taylor.rs` (order, coefficients),
//! `roots.rs` (where a polynomial first crosses zero on a step, and whether a Hermite
//! cubic between steps may), `stride.rs` (how many steps a stride takes),
//! `run_up_time.rs` (how long a drive at its limit takes to run a rig up from rest),
//! `fma.rs` (the inner loops compiled for AVX2 and FMA where the CPU has them, for
//! baseline x86-64 elsewhere, with the same bytes).
//!
//! `schedule.rs` set points over time; `approach.rs` how a run reaches its point (static,
//! from rest, a slow ramp from below or above) as a schedule and a start; `output_rate.rs`
//! the output rates a plant takes. `judge/` the physics judge of a settled motion from a
//! shaft's torque: `spread.rs` (scatter of samples every k revolutions),
//! `order_lines.rs` (Hann spectrum in orders: power on the period-k lines, a
//! subharmonic's height over the broadband floor), `zero_one.rs` (the 0-1 test for
//! chaos), `verdict.rs` (period-k / quasi-periodic / chaotic / no vibration, thresholds
//! and their reasons; see `docs/physics.md`). `regime.rs` the repetition a run reports,
//! and impacts per tooth; `steady.rs` the summary of a settled point. `nearest.rs` the
//! known names nearest a mistyped one, for refusals.
//!
//! Layers: no module imports one that imports it (`rig/tests/module_layers.rs` reads the
//! source and fails on a cycle).
//!
//! ```
//! use rig::{NetworkPlant, NetworkStart, RigChains, Schedule, preset, preset_rig};
//!
//! // The thesis's numbers reproduce its App. C fundamental.
//! let params = preset("basmaji-1983")?;
//! let fundamental = RigChains::of(&params).whole_rig.modes()[0].frequency_hz;
//! assert!((fundamental - 17.84).abs() < 0.01);
//!
//! // The 1983 rig at 200 rev/min with 2.712 N m on the brake: one revolution (0.3 s) of
//! // true signals at 51.2 kHz.
//! let rig = preset_rig("basmaji-1983", "the thesis's rig", &params);
//! let schedule = Schedule::constant(200.0, 2.712);
//! let mut plant = NetworkPlant::new(&rig, schedule, 51_200.0, NetworkStart::Steady)?;
//! let mut block = plant.block();
//! plant.run(15_360, &mut block)?;
//! let torque = &block.shaft_torque_nm[1]; // the intermediate shaft
//! let mean = torque.iter().sum::<f64>() / torque.len() as f64;
//! assert!((mean - 2.712).abs() < 0.05, "the output shaft carries the load: {mean}");
//! # Ok::<(), rig::RigError>(())
//! ```

pub mod approach;
mod eddy_current;
pub mod error;
mod fma;
pub mod geometry;
pub mod judge;
mod matrix_exp;
pub mod mesh_stiffness;
pub mod modal;
mod mode;
pub mod nearest;
pub mod options;
pub mod output_rate;
mod pair_zones;
pub mod param_table;
pub mod params;
pub mod plant;
pub mod preset_rig;
pub mod presets;
pub mod regime;
mod roots;
mod run_up_time;
pub mod schedule;
pub mod spacing;
pub mod steady;
mod stride;
mod taylor;
pub mod tooth_fault;
pub mod topology;

pub use approach::Approach;
pub use error::RigError;
pub use error::{TopologyError, TopologyPlace};
pub use geometry::GearGeometry;
pub use judge::{JudgeInput, Judgement, Motion, judge};
pub use modal::{Chain, NaturalMode, RigChains};
pub use mode::{MotorMode, PairZone};
pub use options::{ContactLaw, MeshPairs};
pub use output_rate::{MAX_OUTPUT_RATE_HZ, MIN_OUTPUT_RATE_HZ, takes_output_rate};
pub use param_table::{
    DERIVED_SPECS, PARAM_SPECS, ParamSpec, ParamValue, param_spec, set_param, set_param_value,
};
pub use params::RigParams;
pub use plant::{
    Column, Contact, NetworkBlock, NetworkImpact, NetworkPlant, NetworkStart, column, column_names,
    column_specs, columns, shaft_torque_column,
};
pub use preset_rig::preset_rig;
pub use presets::{DEFAULT_PRESET, PRESET_NAMES, preset};
pub use regime::{Regime, impacts_per_tooth};
pub use schedule::{LiveCeiling, MAX_SPEED_RPM, Schedule, SetPoints, Track};
pub use steady::SteadySummary;
pub use tooth_fault::{FaultKind, FaultedGear, ToothFault};
pub use topology::TopologyField;
pub use topology::{
    Body, DriveRatings, DriveSettings, FrameShaft, Gauge, LockedTorque, MAX_BODIES,
    MAX_PLANT_MESHES, Mesh, RigTopology, Shaft,
};
pub use topology::{Coordinate, CoordinateKind, Coupling, MeshForm, RigCoordinates};
pub use topology::{
    LineOfAction, MAX_PLANETS, PlanarBearing, PlanetaryStage, RingSensor, StageFault, StageMember,
    StageMesh, StageMeshPhase, StageRadii, StageTeeth,
};
pub use topology::{MeshHold, ModalPart, ModeKind, STILL_SHARE};
