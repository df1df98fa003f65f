//! A sweep file checked and expanded into its cases.

use rig::Approach;

use crate::scenario::build::stream_rate_hz;
use crate::scenario::preset_rig::preset_title;
use crate::scenario::read_chain::record_plan;
use crate::scenario::read_chain::{ChainSetting, analyser_plan, chain_plan};
use crate::scenario::read_rig::rig_params;
use crate::scenario::read_stages::read_signal_among;
use crate::scenario::rig_overrides::{checked_at_path, rig_of_file_table};
use crate::scenario::scenario_toml::RecordFile;
use crate::scenario::{AnalyserPlan, ChainPlan, RecordPlan, ScenarioSource};
use crate::vocabulary::limits::check_simulated_s;

use super::case_rig::CaseRig;
use super::knock::knock_rad_s;
use super::sequence::{Direction, Sequence};
use super::sweep_toml::{CaseFile, GridFile, SweepFile};
use crate::rig_roles::plant_signals;
use crate::scenario::rig_chain::rig_chain;
use crate::vocabulary::frame::SignalNames;
use crate::vocabulary::limits::MAX_SWEEP_CASES;
use crate::vocabulary::seeds::{NoiseSource, case_seed};

/// Most knocked repeats of a point.
pub const MAX_REPEATS: u32 = 8;

/// Everything a sweep needs, checked.
#[derive(Clone, Debug)]
pub struct SweepPlan {
    /// Sweep name.
    pub name: String,
    /// Base seed.
    pub seed: u64,
    /// Stream rate (Hz).
    pub rate_hz: f64,
    /// The rig's name: the preset's, or the rig file's `name`.
    pub preset: String,
    /// Settle time per case (s).
    pub settle_s: f64,
    /// Measured time per case (s).
    pub measure_s: f64,
    /// How the points are reached: each from rest, or the lab's run up and down.
    pub sequence: Sequence,
    /// The chain (slip-ring seed replaced per case).
    pub chain: ChainPlan,
    /// The analyser.
    pub analyser: AnalyserPlan,
    /// Line presence threshold (dB above the local floor).
    pub line_db: f64,
    /// Names of the swept parameters, in column order.
    pub swept: Vec<String>,
    /// What each case records over its measured window, if anything.
    pub record: Option<RecordPlan>,
    /// The sweep file's text as run (cited in the recordings' sidecars).
    pub text: String,
    /// The cases, in index order.
    pub cases: Vec<Case>,
}

impl SweepPlan {
    /// Whether a case reads signal `name`: a chain stage's input, the analyser's, or a
    /// recorded signal.
    pub fn reads(&self, name: &str) -> bool {
        self.chain.reads(name)
            || self.analyser.input == name
            || self.record.as_ref().is_some_and(|r| r.records(name))
    }
}
/// One case of the grid.
#[derive(Clone, Debug)]
pub struct Case {
    /// Index in the grid (0-based).
    pub index: usize,
    /// Speed set point (rev/min).
    pub rpm: f64,
    /// Load (N m).
    pub load_nm: f64,
    /// Values of the swept parameters, as text, in `SweepPlan::swept` order.
    pub values: Vec<String>,
    /// The rig of this case.
    pub rig: CaseRig,
    /// The case's seed.
    pub seed: u64,
    /// How the case reaches its operating point.
    pub approach: Approach,
    /// Which way the speed came to it.
    pub direction: Direction,
    /// The series it is run in, in order, on one plant (`None`: on a plant of its own).
    pub series: Option<usize>,
    /// A repeat's knock: the driven gear's speed change before it settles (rad/s); 0 for
    /// every other case.
    pub kick_rad_s: f64,
}

/// Checks `file` (read from `src`) and expands its grid.
pub fn build_sweep(src: &ScenarioSource, file: &SweepFile) -> anyhow::Result<SweepPlan> {
    let rate_hz = stream_rate_hz(src, &file.rate_hz)?;
    let (preset, base) = match &file.rig.file {
        Some(_) => {
            let rig = rig_of_file_table(src, &file.rig)?;
            (rig.name.clone(), CaseRig::File(Box::new(rig)))
        }
        None => {
            let (name, params) = rig_params(src, &file.rig)?;
            let (title, description) =
                preset_title(&name).map_err(|e| src.error(0..0, "rig.preset", format!("{e:#}")))?;
            let rig = CaseRig::Preset {
                name: title,
                description,
                params: Box::new(params),
            };
            (name, rig)
        }
    };
    let analyser = analyser_plan(src, &file.analyser, rate_hz, file.seed)?;
    let band_hz = Some(analyser.settings.fmax_hz);
    // Checked here: the rig (a preset's as converted: a value its parameters take and no
    // rig does is refused at its path), a motor and gauges; each case puts the strain
    // stage on its gauge. Its chain, analyser and recording may read any of the rig's
    // columns beside the standard inputs (`rig_roles`).
    let topology = base.topology();
    checked_at_path(&topology).map_err(|e| src.error(0..0, "rig", format!("{e:#}")))?;
    let plant = plant_signals(&topology);
    let setting = ChainSetting {
        plant: &plant,
        rate_hz,
        seed: file.seed,
        band_hz,
    };
    let chain = chain_plan(src, &file.chain, setting)?;
    rig_chain(src, &topology, &chain)?;
    let names = chain.stages.signal_names_on(&plant);
    let input = file.analyser.input.as_ref();
    read_signal_among(src, &names, input, "analyser.input", &analyser.input)?;
    let (settle_s, measure_s) = case_timing(src, &file.case, &analyser)?;
    let record = file
        .record
        .as_ref()
        .map(|r| sweep_record_plan(src, r, &chain, &names))
        .transpose()?;
    let grid = &file.grid;
    if grid.rpm.is_empty() || grid.load_nm.is_empty() {
        return Err(src.error(0..0, "grid", "rpm and load_nm each need at least one value"));
    }
    let repeats = repeats(src, &file.case)?;
    if matches!(base, CaseRig::File(_)) {
        check_rig_file_sweep(src, file)?;
    }
    check_case_count(src, grid, file.case.sequence, repeats)?;
    let mut swept = Vec::new();
    let mut variants: Vec<(Vec<String>, CaseRig)> = vec![(Vec::new(), base)];
    if !grid.backlash_mm.is_empty() {
        swept.push("backlash_mm".to_string());
        variants = expand(
            variants,
            grid.backlash_mm.iter().map(|b| {
                let value = toml::Value::Float(b.0);
                (b.0.to_string(), move |r: &mut CaseRig| {
                    r.set("backlash_mm", &value)
                })
            }),
        )?;
    }
    for (name, values) in &grid.set {
        swept.push(name.clone());
        let field = format!("grid.set.{name}");
        variants = expand(
            variants,
            values.get_ref().iter().map(|v| {
                // The case's label: a name as written, a number or switch as TOML shows it.
                let label = match v {
                    toml::Value::String(s) => s.clone(),
                    other => other.to_string(),
                };
                let field = field.clone();
                (label, move |r: &mut CaseRig| {
                    r.set(name, v)
                        .map_err(|e| src.error(values.span(), &field, format!("{e:#}")))
                })
            }),
        )?;
    }
    let sequence = file.case.sequence;
    let mut cases = Vec::new();
    for (values, rig) in &variants {
        for load in &grid.load_nm {
            rig.check_load(load.0)
                .map_err(|message| src.error(0..0, "grid.load_nm", message))?;
        }
        let points = match sequence {
            Sequence::Static => own_points(grid, Direction::Static, repeats, 0),
            Sequence::UpAndDown => up_and_down_points(grid),
            Sequence::EveryApproach => [
                up_and_down_points(grid),
                own_points(grid, Direction::Rest, repeats, grid.load_nm.len()),
            ]
            .concat(),
        };
        let series_base = cases
            .iter()
            .filter_map(|c: &Case| c.series)
            .max()
            .map_or(0, |s| s + 1);
        for (rpm, load_nm, direction, series) in points {
            let index = cases.len();
            let seed = case_seed(file.seed, index);
            cases.push(Case {
                index,
                rpm,
                load_nm,
                values: values.clone(),
                rig: rig.clone(),
                seed,
                approach: match direction {
                    Direction::Rest => Approach::Rest,
                    _ => Approach::Static,
                },
                direction,
                series: series.map(|s| series_base + s),
                kick_rad_s: match direction {
                    Direction::Repeat => knock_rad_s(NoiseSource::Knock.case_seed(seed), rpm),
                    _ => 0.0,
                },
            });
        }
    }
    Ok(SweepPlan {
        name: file.name.clone(),
        seed: file.seed,
        rate_hz,
        preset,
        settle_s,
        measure_s,
        sequence,
        chain,
        analyser,
        line_db: file.detect.line_db.0,
        swept,
        record,
        text: src.text.clone(),
        cases,
    })
}

/// The grid's points each on a plant of its own, started as `direction` says: speed
/// outer, load inner, as the file lists them. With repeats each point is a series (numbered
/// from `first_series`): the point, then its knocked repeats.
fn own_points(
    grid: &GridFile,
    direction: Direction,
    repeats: u32,
    first_series: usize,
) -> Vec<(f64, f64, Direction, Option<usize>)> {
    let mut points = Vec::new();
    let mut next_series = first_series;
    for rpm in &grid.rpm {
        for load in &grid.load_nm {
            let series = (repeats > 0).then(|| {
                next_series += 1;
                next_series - 1
            });
            points.push((rpm.0, load.0, direction, series));
            points.extend((0..repeats).map(|_| (rpm.0, load.0, Direction::Repeat, series)));
        }
    }
    points
}

/// `case.repeats`, checked: at most [`MAX_REPEATS`], and only where points start on their
/// own.
fn repeats(src: &ScenarioSource, case: &CaseFile) -> anyhow::Result<u32> {
    let Some(repeats) = &case.repeats else {
        return Ok(0);
    };
    let n = *repeats.get_ref();
    if n > MAX_REPEATS {
        return Err(src.error(
            repeats.span(),
            "case.repeats",
            format!("{n}: at most {MAX_REPEATS} knocked repeats of a point"),
        ));
    }
    if n > 0 && case.sequence == Sequence::UpAndDown {
        return Err(src.error(
            repeats.span(),
            "case.repeats",
            "repeats knock points started on their own: give sequence = \"static\" or \"every-approach\"",
        ));
    }
    Ok(n)
}

/// A sweep on a rig file, checked: the backlash by its mesh's path, and a gauged shaft
/// for the chain's strain.
fn check_rig_file_sweep(src: &ScenarioSource, file: &SweepFile) -> anyhow::Result<()> {
    if !file.grid.backlash_mm.is_empty() {
        return Err(src.error(
            0..0,
            "grid.backlash_mm",
            "a rig file's backlash is its mesh's: give grid.set.\"mesh.NAME.backlash_mm\"",
        ));
    }
    Ok(())
}

/// A sweep's `[record]`, checked as a scenario's: each case records its measured window
/// at the sweep's rate, from its start (no decimation, no `record` command).
fn sweep_record_plan(
    src: &ScenarioSource,
    file: &RecordFile,
    chain: &ChainPlan,
    names: &SignalNames,
) -> anyhow::Result<RecordPlan> {
    if *file.decimate.get_ref() != 1 {
        return Err(src.error(
            file.decimate.span(),
            "record.decimate",
            "a sweep's case records at the sweep's rate_hz: leave out decimate, or lower rate_hz",
        ));
    }
    if !file.from_start {
        return Err(src.error(
            0..0,
            "record.from_start",
            "a sweep's case records its whole measured window: leave out from_start",
        ));
    }
    record_plan(src, file, chain, names)
}

/// The lab's run: one series per load, the speeds up in ascending order, then down from
/// the one below the top (the top is measured once, on the way up).
/// Counts the grid's cases before any is made, and refuses more than
/// [`MAX_SWEEP_CASES`], naming the count and its factors.
fn check_case_count(
    src: &ScenarioSource,
    grid: &GridFile,
    sequence: Sequence,
    repeats: u32,
) -> anyhow::Result<()> {
    let n = grid.rpm.len() as u128;
    let own = n * (1 + u128::from(repeats));
    let speeds = match sequence {
        Sequence::Static => own,
        Sequence::UpAndDown => 2 * n - 1,
        Sequence::EveryApproach => 2 * n - 1 + own,
    };
    let factors = [grid.load_nm.len(), grid.backlash_mm.len().max(1)]
        .into_iter()
        .chain(grid.set.values().map(|v| v.get_ref().len().max(1)));
    let count = factors.fold(speeds, |n, f| n.saturating_mul(f as u128));
    if count > u128::from(MAX_SWEEP_CASES) {
        return Err(src.error(
            0..0,
            "grid",
            format!(
                "{count} cases: more than {MAX_SWEEP_CASES} in one sweep; split the grid into several sweep files (or use --set), each run as its own job"
            ),
        ));
    }
    Ok(())
}

fn up_and_down_points(grid: &GridFile) -> Vec<(f64, f64, Direction, Option<usize>)> {
    let mut speeds: Vec<f64> = grid.rpm.iter().map(|r| r.0).collect();
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    let down: Vec<f64> = speeds.iter().rev().skip(1).copied().collect();
    let mut points = Vec::new();
    for (series, load) in grid.load_nm.iter().enumerate() {
        points.extend(
            speeds
                .iter()
                .map(|&r| (r, load.0, Direction::Up, Some(series))),
        );
        points.extend(
            down.iter()
                .map(|&r| (r, load.0, Direction::Down, Some(series))),
        );
    }
    points
}

/// The settling and measured times (s) of `case`, checked: each a simulated time the
/// program accepts, the measured time at least one of `analyser`'s blocks.
pub fn case_timing(
    src: &ScenarioSource,
    case: &CaseFile,
    analyser: &AnalyserPlan,
) -> anyhow::Result<(f64, f64)> {
    for (value, field) in [
        (&case.settle_s, "case.settle_s"),
        (&case.measure_s, "case.measure_s"),
    ] {
        check_simulated_s(value.get_ref().0, false)
            .map_err(|message| src.error(value.span(), field, message))?;
    }
    let block_s = analyser.settings.block as f64 / analyser.settings.sample_rate_hz();
    if case.measure_s.get_ref().0 < block_s {
        return Err(src.error(
            case.measure_s.span(),
            "case.measure_s",
            format!("shorter than one analyser block ({block_s} s): no spectrum could be taken"),
        ));
    }
    Ok((case.settle_s.get_ref().0, case.measure_s.get_ref().0))
}

/// Every variant so far with every value of one more parameter.
fn expand<F: Fn(&mut CaseRig) -> anyhow::Result<()>>(
    variants: Vec<(Vec<String>, CaseRig)>,
    values: impl Iterator<Item = (String, F)> + Clone,
) -> anyhow::Result<Vec<(Vec<String>, CaseRig)>> {
    let mut out = Vec::new();
    for (texts, params) in variants {
        for (text, apply) in values.clone() {
            let mut p = params.clone();
            apply(&mut p)?;
            let mut t = texts.clone();
            t.push(text);
            out.push((t, p));
        }
    }
    Ok(out)
}
