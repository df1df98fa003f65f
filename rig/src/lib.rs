//! The physical plant of testrig: F. Basmaji's 1983 geared rig (five inertias on a line,
//! a 1:1 spur pair with backlash, speed-controlled DC motor, eddy-current brake), advanced
//! exactly between contact switches. See `ARCHITECTURE.md` at the project root.
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

mod column_product;
mod derivative;
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
pub mod modal;
mod mode;
mod model;
pub mod options;
mod pair_zones;
pub mod param_table;
pub mod params;
mod plant;
pub mod presets;
mod propagator;
pub mod records;
pub mod regime;
mod roots;
pub mod schedule;
pub mod signals;
pub mod spacing;
pub mod steady;
mod stride;
mod system_cache;
mod taylor;

#[cfg(test)]
mod jump_response_tests;

pub use error::RigError;
pub use geometry::GearGeometry;
pub use judge::{JudgeInput, Judgement, Motion, judge};
pub use modal::{Chain, NaturalMode, RigChains};
pub use mode::{MeshMode, Mode, MotorMode, PairZone};
pub use options::{ContactLaw, MeshPairs};
pub use param_table::{
    DERIVED_SPECS, PARAM_SPECS, ParamSpec, ParamValue, param_spec, set_param, set_param_value,
};
pub use params::RigParams;
pub use plant::{CHECK_EVERY, Plant, PlantConfig};
pub use presets::{DEFAULT_PRESET, PRESET_NAMES, preset};
pub use records::{Flank, Impact, RevolutionSample};
pub use regime::{Regime, RegimeCriteria, classify, classify_scaled};
pub use schedule::{LiveCeiling, Schedule, SetPoints, Track};
pub use signals::{COLUMN_NAMES, COLUMN_UNITS, INTERMEDIATE_SHAFT, SignalBlock};
pub use steady::{SteadySummary, SteadyWindow, run_steady};
