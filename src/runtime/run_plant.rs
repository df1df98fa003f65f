//! The plant as a scenario's run drives it (`rig::NetworkPlant`, any rig): it advances
//! block by block under set points that commands change, hands the chain the signals
//! `crate::rig_roles` names (and the rig's own columns the run reads), logs each mesh's
//! impacts, and its windows are judged on the gauged shaft's torque as `testrig simulate`
//! judges its point.

use std::sync::Arc;

use rig::{
    LiveCeiling, NetworkBlock, NetworkImpact, NetworkPlant, NetworkStart, RigError, RigTopology,
    Schedule, SetPoints, SteadySummary,
};

use crate::rig_roles::RoleColumns;
use crate::steady_point::motor_of;
use crate::steady_point::{RigWindow, regime_of};
use crate::vocabulary::GearIndicators;
use crate::vocabulary::frame::Frame;
use crate::vocabulary::limits::LimitError;
use crate::vocabulary::limits::check_load_within;

/// The plant of a run, with what it needs to frame and judge its blocks.
pub struct RunPlant {
    plant: NetworkPlant,
    rig: Arc<RigTopology>,
    roles: RoleColumns,
    /// The rig's columns (`rig::columns`) each frame carries after the standard inputs.
    rig_columns: Vec<usize>,
    rate_hz: f64,
}

impl RunPlant {
    /// `rig`'s plant in steady motion at `schedule`'s first set points, sampled at
    /// `rate_hz`; for live commands, its step sized for set speeds up to `ceiling`'s
    /// beside the schedule's own, and set points above `ceiling` refused. Its frames carry
    /// the standard inputs, then `rig_columns` of `rig::columns`. A rig without a motor is
    /// refused.
    pub fn new(
        rig: &RigTopology,
        schedule: Schedule,
        rate_hz: f64,
        ceiling: Option<LiveCeiling>,
        rig_columns: Vec<usize>,
    ) -> anyhow::Result<Self> {
        motor_of(rig)?;
        let start = NetworkStart::Steady;
        let plant = match ceiling {
            Some(ceiling) => NetworkPlant::live(rig, schedule, rate_hz, start, ceiling)?,
            None => NetworkPlant::new(rig, schedule, rate_hz, start)?,
        };
        Ok(Self {
            plant,
            rig: Arc::new(rig.clone()),
            roles: RoleColumns::of(rig),
            rig_columns,
            rate_hz,
        })
    }
}

/// One block of the run's plant: its signals, impacts and revolutions.
pub struct RunBlock {
    signals: NetworkBlock,
    impacts: Vec<NetworkImpact>,
    revolutions_s: Vec<f64>,
}

impl RunPlant {
    /// Time between output samples (s).
    pub fn output_step_s(&self) -> f64 {
        1.0 / self.rate_hz
    }

    /// Simulated time now (s).
    pub fn time_s(&self) -> f64 {
        self.plant.time_s()
    }

    /// The set points now.
    pub fn set_points(&self) -> SetPoints {
        self.plant.set_points()
    }

    /// Whether the motor holds a brake load of `load_nm` (N m).
    pub fn check_load(&self, load_nm: f64) -> Result<(), LimitError> {
        check_load_within(load_nm, &self.rig)
    }

    /// Holds `set` from the next sample on.
    pub fn hold(&mut self, set: SetPoints) -> Result<(), RigError> {
        self.plant.hold_set_points(set)
    }

    /// An empty block, shaped for the rig's signals.
    pub fn block(&self) -> RunBlock {
        let rig = &self.rig;
        RunBlock {
            signals: NetworkBlock::new(rig),
            impacts: Vec::new(),
            revolutions_s: Vec::new(),
        }
    }

    /// Advances `samples` samples into `block` (cleared first).
    pub fn advance(&mut self, samples: usize, block: &mut RunBlock) -> Result<(), RigError> {
        block.signals.clear();
        self.plant.run(samples, &mut block.signals)?;
        block.impacts = self.plant.take_impacts();
        block.revolutions_s = self.plant.take_revolutions();
        Ok(())
    }

    /// Contacts that started in `block`.
    pub fn impacts_in(block: &RunBlock) -> usize {
        block.impacts.len()
    }

    /// The frame of `block` (sequence `seq`, from sample `start`); its impacts are moved
    /// into the frame.
    pub fn frame(&self, seq: u64, start: u64, block: &mut RunBlock) -> Frame {
        let mut frame = self
            .roles
            .frame(&self.rig, &block.signals, start, &self.rig_columns);
        frame.seq = seq;
        frame.impacts = std::mem::take(&mut block.impacts).into();
        frame
    }

    /// An empty window; with `indicators`, it also averages the watched gear's
    /// revolutions for its condition indicators (a point's window; the live regime's
    /// needs none).
    pub fn window(&self, indicators: bool) -> RunWindow {
        let window = RigWindow::new(&self.rig, self.rate_hz);
        RunWindow {
            window: if indicators {
                window
            } else {
                window.without_condition()
            },
            rig: Arc::clone(&self.rig),
            rpm: None,
            impacts: Vec::new(),
            revolutions_s: Vec::new(),
        }
    }
}

/// A window of the run's plant: its sums, the gauged shaft's torque, the watched
/// gear's average, the window's impacts and the motor body's revolutions.
pub struct RunWindow {
    window: RigWindow,
    rig: Arc<RigTopology>,
    /// The set speed the window was opened under (rev/min).
    rpm: Option<f64>,
    impacts: Vec<NetworkImpact>,
    revolutions_s: Vec<f64>,
}

impl RunWindow {
    /// The window summed up and judged as a steady point.
    fn steady(&self) -> SteadySummary {
        let rpm = self.rpm.unwrap_or(0.0);
        let summary = self
            .window
            .summary(&self.rig, rpm, &self.impacts, &self.revolutions_s);
        summary.steady
    }
    /// Adds a block made under `set`.
    pub fn add(&mut self, block: &RunBlock, set: &SetPoints) {
        self.rpm.get_or_insert(set.speed_rpm);
        self.window.add(&block.signals);
        self.impacts.extend_from_slice(&block.impacts);
        self.revolutions_s.extend_from_slice(&block.revolutions_s);
    }

    /// The window summed up and its motion judged, and the watched gear's indicators
    /// (none under two revolutions).
    pub fn verdict(&self) -> (SteadySummary, Option<GearIndicators>) {
        let report = self.window.condition_report();
        (self.steady(), report.as_ref().map(GearIndicators::from))
    }

    /// The regime and the judged motion (a spectrum of the window: costly).
    pub fn judged(self) -> (String, String) {
        let motion = self.steady().motion.motion;
        (regime_of(motion).to_string(), motion.to_string())
    }
}
