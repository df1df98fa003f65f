//! How a case reaches its operating point: started there from the static load (the
//! campaign's default), or brought to it in speed from below or above, as an experimenter
//! turns the speed knob. Where the rig has more than one motion at a point, the approach
//! decides which it settles to.

use rig::{Schedule, Track};
use serde::{Deserialize, Serialize};

/// How a case starts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "start")]
pub enum Approach {
    /// At the set speed from the static load (no vibration).
    #[default]
    Static,
    /// From `from_rpm`, ramped linearly to the set speed over `ramp_s` (s); settling is
    /// counted from the end of the ramp.
    Ramp {
        /// Speed the case starts at (rev/min).
        from_rpm: f64,
        /// Length of the ramp (s).
        ramp_s: f64,
    },
}

/// Lowest speed a ramp starts from (rev/min): the rig must turn.
pub const LOWEST_START_RPM: f64 = 50.0;

impl Approach {
    /// A ramp to `rpm` from `delta_rpm` below it (`delta_rpm` < 0: above), over `ramp_s`.
    pub fn ramp_to(rpm: f64, delta_rpm: f64, ramp_s: f64) -> Self {
        Self::Ramp {
            from_rpm: (rpm - delta_rpm).max(LOWEST_START_RPM),
            ramp_s,
        }
    }

    /// The schedule of a case at `rpm` and `load_nm`.
    pub fn schedule(self, rpm: f64, load_nm: f64) -> Schedule {
        match self {
            Self::Static => Schedule::constant(rpm, load_nm),
            Self::Ramp { from_rpm, ramp_s } => Schedule {
                speed_rpm: Track::hold(from_rpm).ramp_to(0.0, ramp_s, rpm),
                ..Schedule::constant(from_rpm, load_nm)
            },
        }
    }

    /// Time before the set speed is reached (s).
    pub fn lead_in_s(self) -> f64 {
        match self {
            Self::Static => 0.0,
            Self::Ramp { ramp_s, .. } => ramp_s,
        }
    }
}
