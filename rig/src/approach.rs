//! How a run reaches its operating point: started there in steady motion from the static
//! load, started from rest with the speed knob turned to the point, or brought to it by a
//! slow ramp of the speed from below or above, as an experimenter turns the knob. Where
//! the rig has more than one motion at a point, the approach decides which it settles to.

use serde::{Deserialize, Serialize};

use crate::plant::NetworkStart;
use crate::schedule::{Schedule, Track};

/// How a run starts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "start")]
pub enum Approach {
    /// At the set speed from the static load (shafts twisted to carry it, no vibration).
    #[default]
    Static,
    /// At rest at t = 0 (shafts twisted to carry the load at standstill), the speed knob
    /// already at the set speed: the speed loop and the drive's current limit run the rig
    /// up.
    Rest,
    /// From `from_rpm` (static load there), ramped linearly to the set speed over `ramp_s`
    /// (s); settling is counted from the end of the ramp.
    Ramp {
        /// Speed the run starts at (rev/min).
        from_rpm: f64,
        /// Length of the ramp (s).
        ramp_s: f64,
    },
}

/// Lowest speed a ramp starts from (rev/min): the rig must turn.
pub const LOWEST_START_RPM: f64 = 50.0;

/// Where the lab's slow run-up starts (rev/min): the lowest speed of the thesis's
/// campaign, below the first torsional resonance, where the rig has one motion.
pub const LAB_RUN_UP_FROM_RPM: f64 = 250.0;

/// Where the lab's slow run-down starts (rev/min): the 1983 drive's top speed.
pub const LAB_RUN_DOWN_FROM_RPM: f64 = 2000.0;

/// The lab's slow ramp (rev/min per second): slow beside the speed loop (0.5 Hz) and the
/// rig's transients, so the motion follows its branch as the speed changes.
pub const LAB_RAMP_RPM_PER_S: f64 = 10.0;

impl Approach {
    /// A ramp to `rpm` from `delta_rpm` below it (`delta_rpm` < 0: above), over `ramp_s`.
    pub fn ramp_to(rpm: f64, delta_rpm: f64, ramp_s: f64) -> Self {
        Self::Ramp {
            from_rpm: (rpm - delta_rpm).max(LOWEST_START_RPM),
            ramp_s,
        }
    }

    /// The lab's slow run-up to `rpm`: from [`LAB_RUN_UP_FROM_RPM`] (half of `rpm` where
    /// that is lower) at `rate_rpm_per_s`.
    pub fn run_up(rpm: f64, rate_rpm_per_s: f64) -> Self {
        Self::ramp_from(
            LAB_RUN_UP_FROM_RPM.min(rpm / 2.0).max(LOWEST_START_RPM),
            rpm,
            rate_rpm_per_s,
        )
    }

    /// The lab's slow run-down to `rpm`: from [`LAB_RUN_DOWN_FROM_RPM`] (a fifth above
    /// `rpm` where that is higher) at `rate_rpm_per_s`.
    pub fn run_down(rpm: f64, rate_rpm_per_s: f64) -> Self {
        Self::ramp_from(LAB_RUN_DOWN_FROM_RPM.max(1.2 * rpm), rpm, rate_rpm_per_s)
    }

    /// A ramp from `from_rpm` to `rpm` at `rate_rpm_per_s` (> 0).
    pub fn ramp_from(from_rpm: f64, rpm: f64, rate_rpm_per_s: f64) -> Self {
        Self::Ramp {
            from_rpm,
            ramp_s: (rpm - from_rpm).abs() / rate_rpm_per_s,
        }
    }

    /// The schedule of a run at `rpm` and `load_nm`.
    pub fn schedule(self, rpm: f64, load_nm: f64) -> Schedule {
        match self {
            Self::Static | Self::Rest => Schedule::constant(rpm, load_nm),
            Self::Ramp { from_rpm, ramp_s } => Schedule {
                speed_rpm: Track::hold(from_rpm).ramp_to(0.0, ramp_s, rpm),
                ..Schedule::constant(from_rpm, load_nm)
            },
        }
    }

    /// Time before the set speed is reached by the set point (s): the ramp's length.
    pub fn lead_in_s(self) -> f64 {
        match self {
            Self::Static | Self::Rest => 0.0,
            Self::Ramp { ramp_s, .. } => ramp_s,
        }
    }

    /// Where a rig file's plant starts ([`NetworkPlant::new`](crate::NetworkPlant::new)):
    /// at rest, or in steady motion at the schedule's first set points.
    pub fn network_start(self) -> NetworkStart {
        match self {
            Self::Rest => NetworkStart::Rest,
            Self::Static | Self::Ramp { .. } => NetworkStart::Steady,
        }
    }
}

impl std::fmt::Display for Approach {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Static => f.write_str("from the static load"),
            Self::Rest => f.write_str("from rest"),
            Self::Ramp { from_rpm, ramp_s } => {
                write!(f, "ramped from {from_rpm} rev/min over {ramp_s} s")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_run_up_starts_at_the_labs_lowest_speed_and_ends_at_the_point() {
        let a = Approach::run_up(1300.0, 10.0);
        assert_eq!(
            a,
            Approach::Ramp {
                from_rpm: 250.0,
                ramp_s: 105.0
            }
        );
        let s = a.schedule(1300.0, 2.0);
        assert_eq!(s.speed_rpm.value_at(0.0), 250.0);
        assert_eq!(s.speed_rpm.value_at(52.5), 775.0);
        assert_eq!(s.speed_rpm.value_at(a.lead_in_s()), 1300.0);
        assert_eq!(s.load_nm.value_at(0.0), 2.0);
    }

    #[test]
    fn a_run_down_starts_at_the_drives_top_speed_or_above_the_point() {
        let a = Approach::run_down(1500.0, 10.0);
        assert_eq!(a.schedule(1500.0, 0.0).speed_rpm.value_at(0.0), 2000.0);
        assert_eq!(a.lead_in_s(), 50.0);
        let b = Approach::run_down(3000.0, 10.0);
        assert_eq!(b.schedule(3000.0, 0.0).speed_rpm.value_at(0.0), 3600.0);
    }
}
