//! The rig, the schedule and the measurements of a scenario.

use rig::{DEFAULT_PRESET, ParamValue, RigParams, Schedule, Track};
use toml::Spanned;

use super::preset_file::preset_params;
use super::preset_rig::preset_topology;
use super::read_faults::seed_faults;
use super::rig_overrides::{checked_at_path, rig_of_file_table, set_table_paths};
use super::run_plan::{Measure, PlanRig};
use super::scenario_toml::{ChangeFile, RigFile, ScenarioFile, ScheduleFile, SurveyFile};
use super::source::ScenarioSource;
use super::values::param_value;

/// The rig of a scenario's `[rig]` table: a rig file's (`file`, relative to the
/// scenario, with its `[rig.set]` and `[[rig.fault]]`), else a preset's rig: its
/// parameters with the backlash and the `[rig.set]` names without a dot set, as a rig
/// (`rig::preset_rig`), then the keys with a dot set as rig paths and its faults seeded.
pub fn plan_rig(src: &ScenarioSource, table: &RigFile) -> anyhow::Result<PlanRig> {
    if table.file.is_some() {
        let topology = Box::new(rig_of_file_table(src, table)?);
        return Ok(PlanRig {
            topology,
            preset: None,
        });
    }
    let (name, params) = thesis_params(src, table, |key| !key.contains('.'))?;
    let mut rig = preset_topology(&name, &params)?;
    seed_faults(src, &mut rig, &table.fault)?;
    let paths = table.set.iter().filter(|(key, _)| key.contains('.'));
    set_table_paths(src, &mut rig, paths)?;
    checked_at_path(&rig).map_err(|e| src.error(0..0, "rig", format!("preset {name}: {e:#}")))?;
    Ok(PlanRig {
        topology: Box::new(rig),
        preset: Some(name),
    })
}

/// The preset with the backlash setting and every `[rig.set]` override applied (a
/// `[rig]` table without `file`).
pub fn rig_params(src: &ScenarioSource, rig: &RigFile) -> anyhow::Result<(String, RigParams)> {
    if let Some(f) = rig.fault.first() {
        return Err(src.error(
            f.gear.span(),
            "rig.fault",
            "faults are seeded on a rig file's meshes: give rig.file",
        ));
    }
    thesis_params(src, rig, |_| true)
}

/// The preset of `rig` (`[rig] preset`, else the default) with its backlash setting and
/// the `[rig.set]` keys `names` picks set, checked.
fn thesis_params(
    src: &ScenarioSource,
    rig: &RigFile,
    names: impl Fn(&str) -> bool,
) -> anyhow::Result<(String, RigParams)> {
    let (name, span) = match &rig.preset {
        Some(p) => (p.get_ref().clone(), p.span()),
        None => (DEFAULT_PRESET.to_string(), 0..0),
    };
    let dir = src.path.parent().unwrap_or(std::path::Path::new("."));
    let mut params =
        preset_params(&name, dir).map_err(|e| src.error(span, "rig.preset", format!("{e:#}")))?;
    if let Some(backlash) = &rig.backlash_mm {
        let value = ParamValue::Number(backlash.get_ref().0);
        rig::set_param_value(&mut params, "backlash_mm", value)
            .map_err(|e| src.error(backlash.span(), "rig.backlash_mm", e))?;
    }
    for (key, value) in rig.set.iter().filter(|(key, _)| names(key)) {
        let field = format!("rig.set.{key}");
        let checked =
            param_value(value.get_ref()).map_err(|e| src.error(value.span(), &field, e))?;
        rig::set_param_value(&mut params, key, checked)
            .map_err(|e| src.error(value.span(), &field, e))?;
    }
    params.validate().map_err(|e| src.error(0..0, "rig", e))?;
    Ok((name, params))
}

/// The schedule and the measurements, from `[schedule]` + `[[measure]]` or from `[survey]`;
/// also the survey's length (s), if any.
pub fn schedule_and_measures(
    src: &ScenarioSource,
    file: &ScenarioFile,
) -> anyhow::Result<(Schedule, Vec<Measure>, Option<f64>)> {
    match (&file.schedule, &file.survey) {
        (Some(schedule), None) => {
            let built = schedule_of(src, schedule)?;
            let measures = measures_of(src, file, &built)?;
            Ok((built, measures, None))
        }
        (None, Some(survey)) => {
            if let Some(m) = file.measure.first() {
                return Err(src.error(
                    m.span(),
                    "measure",
                    "a survey takes its own measurements: leave out [[measure]] or [survey]",
                ));
            }
            survey_of(src, survey)
        }
        (Some(schedule), Some(_)) => Err(src.error(
            schedule.span(),
            "schedule",
            "give either [schedule] or [survey], not both",
        )),
        (None, None) => Err(src.error(
            0..0,
            "schedule",
            "missing: give [schedule] (speed_rpm, load_nm, changes) or [survey]",
        )),
    }
}

fn schedule_of(src: &ScenarioSource, file: &Spanned<ScheduleFile>) -> anyhow::Result<Schedule> {
    let s = file.get_ref();
    let mut schedule = Schedule::constant(s.speed_rpm.0, s.load_nm.0);
    let mut free_from = 0.0;
    for change in &s.change {
        let c: &ChangeFile = change.get_ref();
        if c.at_s.0 < free_from {
            return Err(src.error(
                change.span(),
                "schedule.change.at_s",
                format!(
                    "{} s starts before the change before it has finished ({free_from} s): list changes in time order",
                    c.at_s.0
                ),
            ));
        }
        if c.speed_rpm.is_none() && c.load_nm.is_none() {
            return Err(src.error(
                change.span(),
                "schedule.change",
                "changes nothing: give speed_rpm, load_nm or both",
            ));
        }
        let ramp = c.ramp_s.map_or(0.0, |r| r.0);
        schedule.speed_rpm = apply(schedule.speed_rpm, c.at_s.0, ramp, c.speed_rpm.map(|v| v.0));
        schedule.load_nm = apply(schedule.load_nm, c.at_s.0, ramp, c.load_nm.map(|v| v.0));
        free_from = c.at_s.0 + ramp;
    }
    if let Some(fg) = &s.function_generator {
        let torque = oscillating_torque_nm(fg);
        schedule.oscillating_load_nm = Track::hold(torque);
        schedule.oscillating_load_hz = Track::hold(fg.frequency_hz.0);
    }
    schedule
        .validate()
        .map_err(|e| src.error(file.span(), "schedule", e))?;
    Ok(schedule)
}

/// Brake torque amplitude (N m) from the generator's current amplitude through the coil's
/// first-order lag at the set frequency (the steady state; the coil's transient is left out).
fn oscillating_torque_nm(fg: &super::scenario_toml::FunctionGeneratorFile) -> f64 {
    let omega_tau = std::f64::consts::TAU * fg.frequency_hz.0 * fg.coil_time_constant_s.0;
    fg.amplitude_a.0 * fg.torque_per_amp.0 / (1.0 + omega_tau * omega_tau).sqrt()
}

fn apply(track: Track, at_s: f64, ramp_s: f64, value: Option<f64>) -> Track {
    match value {
        None => track,
        Some(v) if ramp_s > 0.0 => track.ramp_to(at_s, at_s + ramp_s, v),
        Some(v) => track.step_to(at_s, v),
    }
}

fn measures_of(
    src: &ScenarioSource,
    file: &ScenarioFile,
    schedule: &Schedule,
) -> anyhow::Result<Vec<Measure>> {
    let mut measures: Vec<Measure> = Vec::with_capacity(file.measure.len());
    for m in &file.measure {
        let at_s = m.get_ref().at_s.0;
        if measures.last().is_some_and(|last| last.at_s > at_s) {
            return Err(src.error(
                m.span(),
                "measure.at_s",
                "measurements must be listed in time order",
            ));
        }
        measures.push(Measure {
            at_s,
            label: m.get_ref().label.clone(),
            speed_rpm: schedule.speed_rpm.value_at(at_s),
            load_nm: schedule.load_nm.value_at(at_s),
        });
    }
    Ok(measures)
}

fn survey_of(
    src: &ScenarioSource,
    survey: &Spanned<SurveyFile>,
) -> anyhow::Result<(Schedule, Vec<Measure>, Option<f64>)> {
    let s = survey.get_ref();
    if s.speeds_rpm.is_empty() || s.loads_nm.is_empty() {
        return Err(src.error(
            survey.span(),
            "survey",
            "speeds_rpm and loads_nm each need at least one value",
        ));
    }
    let hold = s.settle_s.0 + s.measure_s.0;
    let mut speed = Track::hold(s.speeds_rpm[0].0);
    let mut load = Track::hold(s.loads_nm[0].0);
    let mut measures = Vec::new();
    let mut t = 0.0;
    for rpm in &s.speeds_rpm {
        for load_nm in &s.loads_nm {
            speed = speed.step_to(t, rpm.0);
            load = load.step_to(t, load_nm.0);
            measures.push(Measure {
                at_s: t + s.settle_s.0,
                label: format!("{} rev/min, {} N m", rpm.0, load_nm.0),
                speed_rpm: rpm.0,
                load_nm: load_nm.0,
            });
            t += hold;
        }
    }
    let schedule = Schedule {
        speed_rpm: speed,
        load_nm: load,
        ..Schedule::constant(0.0, 0.0)
    };
    Ok((schedule, measures, Some(t)))
}
