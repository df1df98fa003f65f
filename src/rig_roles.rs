//! What the plant hands the measuring chain (`PLANT_SIGNALS`), in a sweep's case and in
//! a scenario's run alike, from any rig: the chain's standard stages read the rig under the standard
//! chain's input names — the gauged shaft's torque as `torque_intermediate_shaft_nm` (the
//! strain stage takes the gauge's diameter and shear modulus), the speed of the tacho's
//! body (`[tacho]`, else the motor's) as `speed1_rad_s`, and the speed of the gauged
//! shaft's first body as `speed3_rad_s` (the slip rings turn with it) — and the watched
//! gear's (`[keyphasor]`) once-per-revolution pulse as `keyphasor_v`. Beside them a run
//! or a case hands on the rig's own columns its chain, analyser or recording reads (a
//! planetary stage's ring sensor `sensor_<stage>_n`, a mesh force, a body's speed), by
//! their names in `testrig simulate`'s signals.

use instruments::ShaftStrain;
use rig::{Gauge, NetworkBlock, RigTopology};

use crate::chain::ChainStages;
use crate::chain::{watched_gear, whole_turns};
use crate::steady_point::judged_shaft;
use crate::vocabulary::frame::{Frame, SignalNames};

/// The keyphasor's high level (V): [`crate::vocabulary::signal_names::KEYPHASOR_V`] is this over the first
/// 1/[`KEYPHASOR_MARK_SHARE`] of each turn of the watched gear (a reflective mark under an
/// optical probe), 0 V otherwise; its rising edges are the revolutions a synchronous
/// average starts from.
const KEYPHASOR_HIGH_V: f64 = 5.0;

/// Revolutions per keyphasor mark width: the mark spans 1/64 of a turn.
const KEYPHASOR_MARK_SHARE: f64 = 64.0;

/// The rig's strain gauges: sweeps and scenarios measure the strain of a gauged shaft.
pub fn gauge_of(rig: &RigTopology) -> anyhow::Result<&Gauge> {
    rig.gauge.as_ref().ok_or_else(|| {
        anyhow::anyhow!(
            "rig `{}` has no [gauge]: sweeps and scenarios measure the strain of a gauged shaft",
            rig.name
        )
    })
}

/// The shaft under `rig`'s gauges, as the chain's strain stage sees it.
pub fn gauged_shaft_strain(rig: &RigTopology) -> anyhow::Result<ShaftStrain> {
    let gauge = gauge_of(rig)?;
    Ok(ShaftStrain::new(gauge.diameter_m, gauge.shear_modulus_pa)?)
}

/// The chain's stages for `rig`: the strain stage on its gauged shaft.
pub fn gauged_stages(stages: &ChainStages, rig: &RigTopology) -> anyhow::Result<ChainStages> {
    Ok(stages.with_gauged_shaft(gauged_shaft_strain(rig)?))
}

/// The rig's columns a run or a case may hand on beside the standard inputs: every
/// column of `rig::column_names` but time and a name a standard input has already.
pub fn rig_columns(rig: &RigTopology) -> Vec<usize> {
    let standard = SignalNames::plant();
    rig::column_names(rig)
        .iter()
        .enumerate()
        .filter(|(_, name)| standard.index(name).is_none())
        .map(|(k, _)| k)
        .collect()
}

/// The standard inputs, then `rig`'s columns `columns` (of `rig::column_names`): the
/// names of the channels of [`RoleColumns::frame`].
pub fn signals_with(rig: &RigTopology, columns: &[usize]) -> SignalNames {
    let mut names = SignalNames::plant();
    let all = rig::column_names(rig);
    for &k in columns {
        names.push(&all[k]);
    }
    names
}

/// Every signal `rig`'s plant can hand a chain: the standard inputs, then all of
/// [`rig_columns`].
pub fn plant_signals(rig: &RigTopology) -> SignalNames {
    signals_with(rig, &rig_columns(rig))
}

/// Of [`rig_columns`], those whose names `reads` says are read.
pub fn rig_columns_read(rig: &RigTopology, reads: impl Fn(&str) -> bool) -> Vec<usize> {
    let names = rig::column_names(rig);
    rig_columns(rig)
        .into_iter()
        .filter(|&k| reads(&names[k]))
        .collect()
}

/// Where the standard chain's inputs sit in a rig's block.
#[derive(Clone, Copy, Debug)]
pub struct RoleColumns {
    /// The gauged (judged) shaft.
    pub gauged_shaft: usize,
    /// The body the tacho turns with: the `[tacho]`'s, else the motor's.
    pub tacho: usize,
    /// The body the slip rings turn with: the gauged shaft's first.
    pub slip_ring_body: usize,
    /// The body whose revolutions the keyphasor marks.
    pub watched_gear: usize,
    /// The watched gear's teeth (none without a mesh: no indicators then).
    pub watched_teeth: Option<u32>,
}

/// The first body of the gauged shaft (a rig without meshes has no watched gear).
fn gauged_shaft_body(rig: &RigTopology) -> usize {
    rig.shafts[judged_shaft(rig)].between[0]
}

impl RoleColumns {
    /// The roles' places in `rig`.
    pub fn of(rig: &RigTopology) -> Self {
        let gauged_shaft = judged_shaft(rig);
        let watched = watched_gear(rig);
        Self {
            gauged_shaft,
            tacho: rig.tacho.or(rig.motor).unwrap_or(0),
            slip_ring_body: gauged_shaft_body(rig),
            watched_gear: watched.map_or(gauged_shaft_body(rig), |(g, _)| g),
            watched_teeth: watched.map(|(_, teeth)| teeth),
        }
    }

    /// The frame of the plant's signals
    /// (`crate::vocabulary::signal_names::PLANT_SIGNALS`) of `block`, starting at sample
    /// `start`, then `rig`'s columns `columns` ([`signals_with`] names them).
    pub fn frame(
        &self,
        rig: &RigTopology,
        block: &NetworkBlock,
        start: u64,
        columns: &[usize],
    ) -> Frame {
        // Each channel copied once, into the frame's own Arc.
        let mut frame = Frame::of_channels(vec![
            block.time_s.as_slice().into(),
            block.shaft_torque_nm[self.gauged_shaft].as_slice().into(),
            block.speed_rad_s[self.tacho].as_slice().into(),
            block.speed_rad_s[self.slip_ring_body].as_slice().into(),
            block.angle_rad[self.watched_gear]
                .iter()
                .map(|&angle| keyphasor_v(angle))
                .collect(),
        ]);
        for &k in columns {
            // The indices are the rig's own (`rig_columns`), each a column.
            let column = rig::column(rig, block, k).expect("a column of the rig");
            frame.channels.push(column.into());
        }
        frame.start_sample = start;
        frame
    }
}

/// The keyphasor's output (V) with the watched gear at `angle_rad`.
fn keyphasor_v(angle_rad: f64) -> f64 {
    // The turn's fraction as `rem_euclid(1.0)` gives it, bit for bit (both round the
    // same exact t − ⌊t⌋ once), without its `fmod` (2 % of the campaign's time).
    let turns = angle_rad / std::f64::consts::TAU;
    let turn = turns - whole_turns(turns);
    if turn < 1.0 / KEYPHASOR_MARK_SHARE {
        KEYPHASOR_HIGH_V
    } else {
        0.0
    }
}
