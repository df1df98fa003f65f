//! The physical plant of testrig: F. Basmaji's 1983 geared rig (five inertias on a line,
//! a 1:1 spur pair with backlash, speed-controlled DC motor, eddy-current brake), and any
//! rig a rig file describes (`network/`), each advanced exactly between contact switches.
//! See `ARCHITECTURE.md` at the project root.
//!
//! Modules. One concept per file; `lib.rs` only declares and re-exports.
//!
//! `params.rs` the parameter set (SI, units in names) and its validation; `param_table.rs`
//! access by name (`--set`), with unit and meaning; `presets.rs` named sets
//! (`basmaji-1983`, the thesis's numbers; `basmaji-1983-calibrated`, the second search's
//! best, and `basmaji-1983-hand`, the calibration before the searches; see
//! `docs/calibration.md`); `preset_rig.rs` a preset's parameters as the rig of any
//! topology they describe (each shipped preset file is its conversion); `output_rate.rs`
//! the output rates a plant takes; `options.rs` contact law, tooth pairs. The model options beyond
//! the thesis (bearing drag, the eddy-current brake's characteristic, the transmission
//! error as a displacement once per revolution and at mesh frequency, smoothed mesh
//! stiffness) are parameters, 0 in `basmaji-1983`.
//!
//! `geometry.rs` pitch radius, backlash from the centre-distance shift, contact ratio.
//! `eddy_current.rs` the brake's characteristic and its slope at a set point, for both
//! plants.
//!
//! `layout.rs` the augmented state: X1..X5, V1..V5 relative to the set rotation φ(t), the
//! controller's filtered speed Vf and integral z, then forcing states: unit, load, (cos φ,
//! sin φ), optionally (cos 2φ, sin 2φ), the oscillating load pair and (cos zφ, sin zφ) for
//! the profile error at mesh frequency (z the teeth), and the spacing error of the tooth
//! pair in mesh (set at each tooth pass; `spacing.rs` draws the seeded errors).
//!
//! `mode.rs` the discrete state (mesh: apart / drive / back / clipped; mesh stiffness
//! level: one pair, two, or a step between; motor linear or at its limit). `model.rs`
//! builds the matrix A of u' = A u per mode (with the brake's characteristic linearised at
//! the set point, the bearing drag and the transmission error's forcing). `pair_zones.rs`
//! the stiffness zones of a tooth period (sharp, or each change a staircase).
//!
//! `events.rs` the switching functions of each mode (gap, contact force, pair-zone and
//! tooth-pass angles, motor limit, revolution marker); `roots.rs` where a polynomial first
//! crosses zero on a step, and whether a Hermite cubic between steps may cross;
//! `run_up_time.rs` how long a drive at its limit takes to run a rig up from rest.
//!
//! `propagator.rs` per mode: e^{A h} for whole steps, the Taylor expansion of e^{A τ} for
//! any τ inside a step; `derivative.rs` A·u for the expansion; `jump_response.rs` e^{A s h}
//! applied to a jump of the gear angles (tooth passes); `stride.rs` several steps at once
//! where the mode is slow. `system_cache.rs` builds them on first use. Below them, shared
//! by all: `column_product.rs` (the fixed-shape matrix–state product), `fused_step.rs` (a
//! step's mechanical rows with the row events' values and slopes), `matrix_exp.rs`
//! (balanced Padé e^{A h}, spectral radius), `taylor.rs` (order, coefficients, vectors).
//!
//! `plant/` the plant: `state.rs` (the struct, construction, steady initial state,
//! accessors), `fast.rs` (runs of strides and steps in one mode), `chunk.rs` (their states
//! column-wise and the true signals from them), `stepping.rs` (one step at a time, the
//! switch checks, the exact path), `switches.rs` (what each switch does: impacts,
//! separations, tooth shifting, pair zones, motor limits, revolution samples),
//! `segment_start.rs` (set-point segments, phase, harmonic states), `output.rs` (samples,
//! bounds); below them `segment.rs` (one stretch of set points) and `mesh_position.rs`
//! (flank overlap, tooth in mesh).
//!
//! Layers: no module imports one that imports it (`rig/tests/module_layers.rs` reads the
//! source and fails on a cycle). Only the model's interface is public (`params`,
//! `param_table`, `presets`, `geometry`, `options`, `schedule`, `approach`, `signals`, `records`,
//! `regime`, `judge`, `steady`, `modal`, `energy`, and `Plant`); the numerics are private
//! to the crate.
//!
//! `mesh_stiffness.rs` a spur pair's stiffness by the potential-energy method (checked
//! against ISO 6336-1). `schedule.rs` set points over time; `approach.rs` how a run reaches its point (static,
//! from rest, a slow ramp from below or above) as a schedule. `signals.rs` the true-signal block. `records.rs`
//! impacts and revolution samples. `regime.rs` period-k classification of the Poincaré
//! samples (the old classifier, kept for the regime map and the panel). `judge/` the
//! physics judge of a settled motion from the output-shaft torque: `spread.rs` (scatter of
//! samples every k revolutions), `order_lines.rs` (Hann spectrum in orders: power on the
//! period-k lines, a subharmonic's height over the broadband floor), `zero_one.rs` (the 0-1
//! test for chaos), `verdict.rs` (period-k / quasi-periodic / chaotic / no vibration, thresholds
//! and their reasons; see `docs/physics.md`). `steady.rs` settle-then-measure runs
//! (`SteadyWindow` keeps the window's torque for the judge and the motor's mean speed
//! against the set speed; its `regime()` is the cheap part a paced thread uses). `modal.rs`
//! natural frequencies and shapes. `energy.rs` energy terms for tests. `nearest.rs` the
//! known names nearest a mistyped one, for refusals.
//!
//! `network/` the plant of any rig a rig file describes (`RigTopology`): any number of
//! bodies, shafts and up to four meshes, loops with a locked-in torque, the same exact
//! stepping (per mode e^{A h}, switches on the Taylor expansion); `topology/` the rig
//! itself as data, its checks, its numbers by path and natural modes.
//!
//! `fma.rs` the fused multiply-add path chosen at run time: the inner loops
//! (`column_product.rs`, `propagator.rs`, `jump_response.rs`) run compiled for AVX2 and FMA
//! where the CPU has them, for baseline x86-64 elsewhere, with the same bytes.
//!
//! ```
//! use rig::{Plant, PlantConfig, RigChains, Schedule, SignalBlock, preset};
//!
//! // The thesis's numbers reproduce its App. C fundamental.
//! let params = preset("basmaji-1983")?;
//! let fundamental = RigChains::of(&params).whole_rig.modes()[0].frequency_hz;
//! assert!((fundamental - 17.84).abs() < 0.01);
//!
//! // 200 rev/min with 2.712 N m on the brake: one revolution (0.3 s) of true signals.
//! let mut plant = Plant::new(params, Schedule::constant(200.0, 2.712), PlantConfig::default())?;
//! let mut block = SignalBlock::default();
//! plant.run(15_360, &mut block)?;
//! let torque = &block.shaft_torque_nm[rig::INTERMEDIATE_SHAFT];
//! let mean = torque.iter().sum::<f64>() / torque.len() as f64;
//! assert!((mean - 2.712).abs() < 0.05, "the output shaft carries the load: {mean}");
//! # Ok::<(), rig::RigError>(())
//! ```

pub mod approach;
mod column_product;
mod derivative;
mod eddy_current;
pub mod energy;
pub mod error;
mod events;
mod fma;
mod fused_step;
pub mod geometry;
pub mod judge;
mod jump_response;
mod layout;
mod matrix_exp;
pub mod mesh_stiffness;
pub mod modal;
mod mode;
mod model;
pub mod nearest;
pub mod network;
pub mod options;
pub mod output_rate;
mod pair_zones;
pub mod param_table;
pub mod params;
mod plant;
pub mod preset_rig;
pub mod presets;
mod propagator;
pub mod records;
pub mod regime;
mod roots;
mod run_up_time;
pub mod schedule;
pub mod signals;
pub mod spacing;
pub mod steady;
mod stride;
mod system_cache;
mod taylor;
pub mod tooth_fault;
pub mod topology;

#[cfg(test)]
mod jump_response_tests;

pub use approach::Approach;
pub use error::RigError;
pub use error::{TopologyError, TopologyPlace};
pub use geometry::GearGeometry;
pub use judge::{JudgeInput, Judgement, Motion, judge};
pub use modal::{Chain, NaturalMode, RigChains};
pub use mode::{MeshMode, Mode, MotorMode, PairZone};
pub use network::{
    Column, Contact, NetworkBlock, NetworkImpact, NetworkPlant, NetworkStart, column, column_names,
    column_specs, columns,
};
pub use options::{ContactLaw, MeshPairs};
pub use output_rate::{MAX_OUTPUT_RATE_HZ, MIN_OUTPUT_RATE_HZ, takes_output_rate};
pub use param_table::{
    DERIVED_SPECS, PARAM_SPECS, ParamSpec, ParamValue, param_spec, set_param, set_param_value,
};
pub use params::RigParams;
pub use plant::{Plant, PlantConfig};
pub use preset_rig::preset_rig;
pub use presets::{DEFAULT_PRESET, PRESET_NAMES, preset};
pub use records::{Flank, Impact, RevolutionSample};
pub use regime::{Regime, RegimeCriteria, classify, classify_scaled, impacts_per_tooth};
pub use schedule::{LiveCeiling, MAX_SPEED_RPM, Schedule, SetPoints, Track};
pub use signals::{COLUMN_NAMES, COLUMN_UNITS, DRIVEN_GEAR, INTERMEDIATE_SHAFT, SignalBlock};
pub use steady::{SteadySummary, SteadyWindow, run_steady};
pub use tooth_fault::{FaultKind, FaultedGear, ToothFault};
pub use topology::TopologyField;
pub use topology::{
    Body, DriveRatings, DriveSettings, Gauge, LockedTorque, MAX_BODIES, MAX_MESHES, Mesh,
    RigTopology, Shaft,
};
pub use topology::{MeshHold, ModalPart};
