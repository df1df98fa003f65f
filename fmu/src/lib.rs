//! A rig file's plant as an FMI 3.0 co-simulation FMU. The shared library this crate
//! builds (`libtestrig_fmu.so`) is the FMU's binary; `testrig fmu` packs it with the
//! model description this crate writes and the rig as `resources/rig.json`.
//!
//! `variables.rs` the variables of a rig, numbered; `units.rs` their units;
//! `model_description.rs` the XML, the model identifier and the instantiation token;
//! `instance.rs` one instance in safe Rust (the state machine, the plant started at rest
//! and advanced over each communication step with the inputs held); `ffi.rs` the C
//! functions offered (`ffi_values.rs` the typed getters and setters, `ffi_state.rs` the
//! FMU state), `ffi_unoffered.rs` the rest of the interface; `error.rs` the one
//! error. `docs/fmu.md` is the user's page.

#![deny(unsafe_op_in_unsafe_fn)]

mod error;
pub mod ffi;
pub mod ffi_state;
pub mod ffi_unoffered;
pub mod ffi_values;
mod instance;
mod model_description;
mod units;
mod variables;

pub use error::FmuError;
pub use instance::{Instance, Phase};
pub use model_description::{
    RIG_RESOURCE, instantiation_token, model_description, model_identifier,
};
pub use units::{UNITS, UnitDefinition, unit_definition};
pub use variables::{
    Causality, DEFAULT_SPEED_CEILING_RPM, Kind, MAX_OSCILLATING_HZ, Role, SAMPLE_RATE_HZ, SetPoint,
    Variable, variables,
};
