//! The rig a scenario runs: a preset of the thesis's plant or a rig file's rig, and what
//! the run asks of either (the most load its motor holds, the gauged shaft's static
//! torque).

use rig::{NetworkBlock, NetworkPlant, NetworkStart, RigError, RigParams, RigTopology, Schedule};

use crate::rig_point::judged_shaft;
use crate::rig_roles::RIG_SIGNALS;
use crate::vocabulary::frame::SignalNames;
use crate::vocabulary::limits::{LimitError, check_load_within_motor};

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
            Self::File(rig) => file_max_load_nm(rig),
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
        match self {
            Self::Preset { params, .. } => check_load_within_motor(load_nm, params),
            Self::File(rig) => check_rig_file_load(rig, load_nm),
        }
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

/// Whether the motor of a rig file's `rig` holds a brake load of `load_nm` (N m), as
/// [`PlanRig::max_load_nm`] says.
pub fn check_rig_file_load(rig: &RigTopology, load_nm: f64) -> Result<(), LimitError> {
    let max_nm = file_max_load_nm(rig);
    if load_nm <= max_nm {
        Ok(())
    } else if rig.brake.is_none() {
        Err(LimitError::NoBrake {
            load_nm,
            rig: rig.name.clone(),
        })
    } else {
        Err(LimitError::LoadAboveRigMotor {
            load_nm,
            max_nm,
            rig: rig.name.clone(),
        })
    }
}

/// [`PlanRig::max_load_nm`] of a rig file's rig.
fn file_max_load_nm(rig: &RigTopology) -> f64 {
    let (Some(motor), Some(brake)) = (rig.motor, rig.brake) else {
        return 0.0;
    };
    let Some(limit_nm) = rig.drive.limit_nm() else {
        return f64::INFINITY;
    };
    let speeds = rig.relative_speeds();
    match (speeds[motor], speeds[brake]) {
        (Some(m), Some(b)) if b != 0.0 => limit_nm * (m / b).abs() - rig.drive.brake_drag_nm,
        _ => f64::INFINITY,
    }
}
