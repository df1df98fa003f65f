//! The plant: state, set points and the stepping loop that is exact at every switch.
//!
//! Between switches the equations are linear with constant and harmonic forcing, so a
//! whole internal step is one product with e^{A h} (computed once per mode), and where
//! the mode is slow a stride of several steps is one product too. Every switching
//! function is checked on each step or stride from its values and slopes at both ends;
//! where it may cross, the step is redone on the Taylor expansion of e^{A τ} (exact to
//! rounding for ρh ≤ 0.5), the first crossing is found to within 64 ulps, the mode
//! switches there, and the step continues from that instant.

mod chunk;
mod fast;
mod mesh_position;
mod output;
mod segment;
mod segment_start;
mod state;
mod stepping;
mod switches;

pub(crate) use switches::RELEASE_MARGIN_NM;

pub(crate) use state::SWITCH_LIMIT;
pub use state::{Plant, PlantConfig};
