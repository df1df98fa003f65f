//! What one case of a sweep shows (`CaseResult`, with its rig's faults as `labels.csv`
//! names them), and what measuring a case takes (`case_run.rs` runs it): its timing, its
//! instruments, its result from the judge's summary and the analyser's display.

use instruments::Line;
use rig::{Judgement, Regime, RigTopology, SteadySummary};
use serde::{Deserialize, Serialize};

use super::grid::{Case, SweepPlan};
use super::lines::{OrderLine, order_line, peaks};
use super::sequence::Direction;
use crate::chain::{AdcChoice, AnalyserWords, ChainStages, InlineChain, Measurement, Truth};
use crate::vocabulary::GearIndicators;
use crate::vocabulary::frame::SignalNames;
use crate::vocabulary::gear_indicators::null_as_nan;
use crate::vocabulary::seeds::NoiseSource;

/// Chain time run before the analyser starts, so the filters have settled (s).
const CHAIN_LEAD_S: f64 = 1.0;
/// Once-per-revolution torque samples a case keeps (the last of its window), for the
/// bifurcation diagram.
pub(crate) const KEPT_REVOLUTIONS: usize = 64;

/// What one case shows.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaseResult {
    /// Index in the grid.
    pub index: usize,
    /// Speed set point (rev/min).
    pub rpm: f64,
    /// Load (N m).
    pub load_nm: f64,
    /// Swept parameter values, in the sweep's column order.
    pub values: Vec<String>,
    /// The case's seed.
    pub seed: u64,
    /// How the case was reached: from the static load, from rest, the speed stepped up or
    /// down from the case before it, or knocked after the case before it.
    #[serde(default)]
    pub direction: Direction,
    /// A repeat's knock on the driven gear before it settled (rad/s); 0 otherwise.
    #[serde(default)]
    pub kick_rad_s: f64,
    /// Period-k or aperiodic (`period-k` or `aperiodic` in JSON).
    pub regime: Regime,
    /// The physics judge's verdict on the output-shaft torque over the window.
    pub motion: Judgement,
    /// The output-shaft torque once per revolution of the driving gear, the last of the
    /// window (N m).
    pub revolution_torque_nm: Vec<f64>,
    /// Power of the half-order line (V² rms at the amplifier output).
    #[serde(deserialize_with = "null_as_nan")]
    pub half_order: f64,
    /// Power of the first-order line.
    #[serde(deserialize_with = "null_as_nan")]
    pub first_order: f64,
    /// Power of the second-order line.
    #[serde(deserialize_with = "null_as_nan")]
    pub second_order: f64,
    /// Height of the half-order line above the lines around it (dB).
    #[serde(deserialize_with = "null_as_nan")]
    pub half_order_db: f64,
    /// Whether the half-order line stands out (by the sweep's `line_db`).
    pub half_order_present: bool,
    /// Contact starts per revolution of the driving gear.
    pub impacts_per_rev: f64,
    /// Contact starts on each tooth of the driving gear per revolution.
    pub impacts_per_tooth_per_rev: Vec<f64>,
    /// Whether the teeth ever separate.
    pub separates: bool,
    /// Share of the time apart.
    pub apart_fraction: f64,
    /// Mean output-shaft torque (N m).
    pub torque_mean_nm: f64,
    /// RMS of the output-shaft torque about its mean (N m).
    pub torque_ac_rms_nm: f64,
    /// Mean motor speed over the window less the set speed (rev/min); 0 in case files
    /// written before it was kept.
    #[serde(default)]
    pub speed_offset_rpm: f64,
    /// The driven gear's condition indicators: the true output-shaft torque averaged
    /// synchronously over its revolutions in the window (`None` under two revolutions, or
    /// in case files written before they were kept).
    #[serde(default)]
    pub condition: Option<GearIndicators>,
    /// The same gear's indicators as the chain measures them: the analyser's input read
    /// as torque by the chain's static calibration, noise and all (`None` where that
    /// input has no calibration, or in case files written before they were kept).
    #[serde(default)]
    pub measured_condition: Option<GearIndicators>,
    /// The rig's tooth faults (a rig file's; none on a preset's plant).
    #[serde(default)]
    pub faults: Vec<FaultLabel>,
    /// The case's recordings, relative to the sweep's folder (where it records).
    #[serde(default)]
    pub recordings: Vec<String>,
    /// Analyser averages taken.
    pub averages: usize,
    /// The displayed spectrum: (Hz, V² rms) per line.
    pub spectrum: Vec<(f64, f64)>,
    /// The lines that stand out: (Hz, V² rms).
    pub peaks: Vec<(f64, f64)>,
}

/// One tooth fault of a case's rig, as `labels.csv` names it.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct FaultLabel {
    /// The mesh's name, or the planetary stage's.
    pub mesh: String,
    /// `driver` or `driven`; a stage's `sun`, `ring` or `planet<k>`.
    pub gear: String,
    /// The tooth, 1..=z of that gear.
    pub tooth: u32,
    /// `crack`, `pit` or `broken`.
    pub kind: String,
    /// Its severity, 0..=1 (0: the tooth is healthy).
    pub severity: f64,
}

impl CaseResult {
    /// Whether no tooth fault of the case has a severity above 0 (the rig the thesis saw).
    pub fn is_healthy(&self) -> bool {
        self.faults.iter().all(|f| f.severity <= 0.0)
    }
}

/// Chain time run before the measured window (s): the filters settle over it.
pub fn chain_lead_s(plan: &SweepPlan) -> f64 {
    CHAIN_LEAD_S.min(plan.settle_s)
}

/// Samples [`measure_case`] advances the plant by: the chain's lead and the window.
pub fn measured_samples(plan: &SweepPlan) -> usize {
    (chain_lead_s(plan) * plan.rate_hz).round() as usize
        + (plan.measure_s * plan.rate_hz).round() as usize
}

/// Longest run-up from rest a case waits for before it settles (s).
const MAX_RUN_UP_S: f64 = 600.0;

/// How long a case from rest waits for the drive to run the rig up before it settles (s):
/// the run-up's time, `run_up_s` (`None` where the drive has no limit or no torque to
/// spare: no wait), at most [`MAX_RUN_UP_S`]. The same for a preset's plant and any rig's.
pub(super) fn run_up_wait_s(run_up_s: Option<f64>) -> f64 {
    run_up_s.map_or(0.0, |s| s.min(MAX_RUN_UP_S))
}

/// A case's measuring chain, the analyser's input channel and its measurement.
pub(crate) struct CaseInstruments {
    /// The chain, stage after stage.
    pub chain: InlineChain,
    /// The analyser's input among the frames' channels.
    pub input: usize,
    /// The ADC and analyser.
    pub measurement: Measurement,
}

/// The instruments of `case`: `stages` built on the plant's signals `names` (each stage's
/// output added), their noise and the ADC's dither seeded for the case.
pub(crate) fn case_instruments(
    plan: &SweepPlan,
    case: &Case,
    mut stages: ChainStages,
    names: &mut SignalNames,
) -> anyhow::Result<CaseInstruments> {
    stages.reseed(NoiseSource::SlipRings.case_seed(case.seed));
    let chain = InlineChain::new(stages.build(plan.rate_hz, names)?);
    let input = names
        .index(&plan.analyser.input)
        .ok_or_else(|| anyhow::anyhow!("analyser.input: no {}", plan.analyser.input))?;
    let mut adc = AdcChoice::of(&plan.analyser.adc);
    adc.dither_seed = adc
        .dither_seed
        .map(|_| NoiseSource::AdcDither.case_seed(case.seed));
    let setup = AnalyserWords::of(&plan.analyser.settings, adc).set_up(plan.rate_hz)?;
    // A case reads the heights of lines, never which are aliases: no truth kept.
    Ok(CaseInstruments {
        chain,
        input,
        measurement: Measurement::new(setup, Truth::NotKept),
    })
}

/// A case's result from its window's summary and the analyser's display; the kept
/// revolutions, condition, faults and recordings left for the caller.
pub(crate) fn case_result(
    plan: &SweepPlan,
    case: &Case,
    s: &SteadySummary,
    lines: &[Line],
    averages: usize,
) -> CaseResult {
    let running_hz = case.rpm / 60.0;
    let order = |k: f64| {
        order_line(lines, k * running_hz).unwrap_or(OrderLine {
            power: f64::NAN,
            above_floor_db: f64::NAN,
        })
    };
    let half = order(0.5);
    let revolutions = s.revolutions.max(1) as f64;
    CaseResult {
        index: case.index,
        rpm: case.rpm,
        load_nm: case.load_nm,
        values: case.values.clone(),
        seed: case.seed,
        direction: case.direction,
        kick_rad_s: case.kick_rad_s,
        regime: s.regime,
        motion: s.motion.clone(),
        revolution_torque_nm: Vec::new(),
        half_order: half.power,
        first_order: order(1.0).power,
        second_order: order(2.0).power,
        half_order_db: half.above_floor_db,
        half_order_present: half.above_floor_db >= plan.line_db,
        impacts_per_rev: s.impacts_per_rev,
        impacts_per_tooth_per_rev: s
            .impacts_per_tooth
            .iter()
            .map(|&n| n as f64 / revolutions)
            .collect(),
        separates: s.separates,
        apart_fraction: s.apart_fraction,
        torque_mean_nm: s.torque_mean_nm,
        torque_ac_rms_nm: s.torque_ac_rms_nm,
        speed_offset_rpm: s.speed_offset_rpm,
        condition: None,
        measured_condition: None,
        faults: Vec::new(),
        recordings: Vec::new(),
        averages,
        spectrum: lines.iter().map(|l| (l.frequency_hz, l.value)).collect(),
        peaks: peaks(lines, plan.line_db),
    }
}

/// The tooth faults of `rig` (a case's rig as it runs), as `labels.csv` names them.
pub fn fault_labels(rig: &RigTopology) -> Vec<FaultLabel> {
    rig.meshes
        .iter()
        .flat_map(|m| {
            m.faults.iter().map(|f| FaultLabel {
                mesh: m.name.clone(),
                gear: f.gear.name().into(),
                tooth: f.tooth,
                kind: f.kind.name().into(),
                severity: f.severity,
            })
        })
        .chain(rig.planetary.iter().flat_map(|s| {
            s.faults.iter().map(|f| FaultLabel {
                mesh: s.name.clone(),
                gear: f.member.name(),
                tooth: f.tooth,
                kind: f.kind.name().into(),
                severity: f.severity,
            })
        }))
        .collect()
}
