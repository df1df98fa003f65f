//! The rig a scenario runs — a rig file's, or a preset's as its rig file — and what the
//! run asks of it (the most load its motor holds, the gauged shaft's static torque).

use rig::{NetworkBlock, NetworkPlant, NetworkStart, RigError, RigTopology, Schedule};

use crate::steady_point::judged_shaft;
use crate::vocabulary::limits::{LimitError, check_load_within, max_load_nm};

/// The rig a scenario runs on the plant of any rig (`rig::NetworkPlant`), after
/// `[rig.set]` and its seeded faults; it has a motor and strain gauges (checked when the
/// scenario is read).
#[derive(Clone, Debug)]
pub struct PlanRig {
    /// The rig.
    pub topology: Box<RigTopology>,
    /// The preset that named it (`[rig] preset`, or the default), none for `[rig] file`.
    pub preset: Option<String>,
}

impl PlanRig {
    /// The rig's name.
    pub fn name(&self) -> &str {
        &self.topology.name
    }

    /// The largest brake load (N m) the motor can hold: its limit over the brake's speed
    /// per unit motor speed (infinite where the rig gives no limit, 0 without a brake).
    pub fn max_load_nm(&self) -> f64 {
        max_load_nm(&self.topology)
    }

    /// Whether the motor holds a brake load of `load_nm` (N m), as [`Self::max_load_nm`]
    /// says.
    pub fn check_load(&self, load_nm: f64) -> Result<(), LimitError> {
        check_load_within(load_nm, &self.topology)
    }

    /// The gauged shaft's torque (N m) in the steady state at `rpm` (rev/min) and
    /// `load_nm` on the brake, as its steady state gives it (the load through the gears,
    /// a loop's locked torque, bearing and brake drag), sampled at `rate_hz` as the run is.
    pub fn static_torque_nm(&self, rpm: f64, load_nm: f64, rate_hz: f64) -> Result<f64, RigError> {
        let rig = &self.topology;
        let schedule = Schedule::constant(rpm, load_nm);
        let mut plant = NetworkPlant::new(rig, schedule, rate_hz, NetworkStart::Steady)?;
        let mut block = NetworkBlock::new(rig);
        plant.sample_now(&mut block);
        Ok(block.shaft_torque_nm[judged_shaft(rig)][0])
    }
}
