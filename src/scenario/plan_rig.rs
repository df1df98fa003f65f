//! The rig a scenario runs: a preset of the thesis's plant or a rig file's rig, and what
//! the run asks of either (the most load its motor holds, the gauged shaft's static
//! torque).

use rig::{NetworkBlock, NetworkPlant, NetworkStart, RigError, RigParams, RigTopology, Schedule};

use crate::rig_roles::RIG_SIGNALS;
use crate::steady_point::judged_shaft;
use crate::vocabulary::frame::SignalNames;
use crate::vocabulary::limits::{LimitError, check_load_within, rig_max_load_nm};

/// The rig a scenario runs.
#[derive(Clone, Debug)]
pub enum PlanRig {
    /// A preset of the thesis's five-inertia plant (`rig::Plant`), after its overrides.
    Preset {
        /// The preset's name.
        name: String,
        /// Its parameters after `[rig.set]` and the backlash.
        params: Box<RigParams>,
    },
    /// A rig file's rig (`rig::NetworkPlant`), after `[rig.set]` and its seeded faults;
    /// it has a motor and strain gauges (checked when the scenario is read).
    File(Box<RigTopology>),
}

impl PlanRig {
    /// The preset's or the rig file's name.
    pub fn name(&self) -> &str {
        match self {
            Self::Preset { name, .. } => name,
            Self::File(rig) => &rig.name,
        }
    }

    /// The largest brake load (N m) the motor can hold: a preset's torque limit less its
    /// residual drag; a rig file's motor limit over the brake's speed per unit motor speed
    /// (infinite where the file gives no limit, 0 without a brake).
    pub fn max_load_nm(&self) -> f64 {
        match self {
            Self::Preset { params, .. } => crate::vocabulary::max_load_nm(params),
            Self::File(rig) => rig_max_load_nm(rig),
        }
    }

    /// The signals its plant hands the chain: the thesis's plant's columns, or what a rig
    /// file's plant offers (`crate::rig_roles`).
    pub fn plant_signals(&self) -> SignalNames {
        match self {
            Self::Preset { .. } => SignalNames::plant(),
            Self::File(_) => SignalNames::of(&RIG_SIGNALS),
        }
    }

    /// Whether the motor holds a brake load of `load_nm` (N m), as [`Self::max_load_nm`]
    /// says.
    pub fn check_load(&self, load_nm: f64) -> Result<(), LimitError> {
        let (name, has_brake) = match self {
            Self::Preset { name, .. } => (format!("preset `{name}`"), true),
            Self::File(rig) => (format!("rig `{}`", rig.name), rig.brake.is_some()),
        };
        check_load_within(load_nm, self.max_load_nm(), &name, has_brake)
    }

    /// The gauged shaft's torque (N m) in the steady state at `rpm` (rev/min) and
    /// `load_nm` on the brake: a preset's intermediate shaft carries the brake's load; a
    /// rig file's shaft what its steady state gives it (the load through the gears, a
    /// loop's locked torque, bearing drag), sampled at `rate_hz` as the run is.
    pub fn static_torque_nm(&self, rpm: f64, load_nm: f64, rate_hz: f64) -> Result<f64, RigError> {
        let Self::File(rig) = self else {
            return Ok(load_nm);
        };
        let schedule = Schedule::constant(rpm, load_nm);
        let mut plant = NetworkPlant::new(rig, schedule, rate_hz, NetworkStart::Steady)?;
        let mut block = NetworkBlock::new(rig.bodies.len(), rig.shafts.len(), rig.meshes.len());
        plant.sample_now(&mut block);
        Ok(block.shaft_torque_nm[judged_shaft(rig)][0])
    }
}
