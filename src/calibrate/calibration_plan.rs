//! A calibration file checked: the campaign's case settings, the target points, the free
//! parameters and the search.

use std::path::Path;

use crate::scenario::ScenarioSource;
use crate::sweep::grid::case_timing;
use crate::sweep::sweep_toml::SweepFile;
use crate::sweep::{CaseRig, SweepPlan, build_sweep};

use super::calibration_toml::{CalibrationFile, FreeFile};
use super::free_param::{FreeParam, FreeRange, params_at};

/// The finding expected at a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expect {
    /// The half-order line stands out.
    Present,
    /// It does not.
    Absent,
}

/// One operating point with its expected finding.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetPoint {
    /// Index among the target points (0-based, in file order).
    pub index: usize,
    /// Speed (rev/min).
    pub rpm: f64,
    /// Load (N m).
    pub load_nm: f64,
    /// The half-order line expected.
    pub expect: Expect,
    /// Weight in the objective.
    pub weight: f64,
}

/// A natural frequency expected of the linear model.
#[derive(Clone, Debug, PartialEq)]
pub struct NaturalTarget {
    /// Mode number (1 = fundamental).
    pub mode: usize,
    /// Expected (Hz).
    pub hz: f64,
    /// Tolerance (Hz).
    pub tolerance_hz: f64,
    /// dB of objective per tolerance outside it.
    pub weight: f64,
}

/// What each point is scored on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scoring {
    /// The half-order line's height in the chain's averaged spectrum.
    Line,
    /// The physics judge's motion from the true output-shaft torque.
    Motion,
}

/// Which approaches each point is run from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ApproachKind {
    /// From the static load at the set speed.
    Static,
    /// Ramped up from below.
    FromBelow,
    /// Ramped down from above.
    FromAbove,
}

/// Everything a calibration needs, checked.
#[derive(Clone, Debug)]
pub struct CalibrationPlan {
    /// Its name.
    pub name: String,
    /// Search seed.
    pub seed: u64,
    /// The campaign's case settings (its cases are not used).
    pub sweep: SweepPlan,
    /// The rig the free parameters change: a preset's, or a rig file's.
    pub base: CaseRig,
    /// The target points.
    pub points: Vec<TargetPoint>,
    /// Natural-frequency targets.
    pub natural: Vec<NaturalTarget>,
    /// The free parameters, in coordinate order.
    pub free: Vec<FreeParam>,
    /// Evaluations in all.
    pub budget: usize,
    /// First population (`None`: the default).
    pub population: Option<usize>,
    /// Initial step (box fraction).
    pub sigma: f64,
    /// Margin (dB) either side of the line threshold.
    pub margin_db: f64,
    /// Approaches each point is run from.
    pub approaches: Vec<ApproachKind>,
    /// Start offset of a ramped approach (rev/min).
    pub approach_rpm: f64,
    /// Ramp length (s).
    pub ramp_s: f64,
    /// What each point is scored on.
    pub scoring: Scoring,
}

/// Checks `file`, read from `src`; the campaign is read relative to it.
pub fn build_calibration(
    src: &ScenarioSource,
    file: &CalibrationFile,
) -> anyhow::Result<CalibrationPlan> {
    let sweep = campaign_plan(src, file)?;
    let base = sweep
        .cases
        .first()
        .ok_or_else(|| src.error(file.campaign.span(), "campaign", "its grid has no case"))?
        .rig
        .clone();
    let free = free_params(src, file, &base)?;
    let points = target_points(src, file)?;
    let natural = file
        .natural
        .iter()
        .map(|n| {
            let v = n.get_ref();
            if *v.mode.get_ref() == 0 {
                return Err(src.error(v.mode.span(), "natural.mode", "modes count from 1"));
            }
            Ok(NaturalTarget {
                mode: *v.mode.get_ref(),
                hz: v.hz.0,
                tolerance_hz: v.tolerance_hz.0,
                weight: v.weight.0,
            })
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    if points.is_empty() && natural.is_empty() {
        return Err(src.error(0..0, "target", "no targets: give [[target]] or [[natural]]"));
    }
    let search = &file.search;
    if *search.budget.get_ref() == 0 {
        return Err(src.error(
            search.budget.span(),
            "search.budget",
            "at least one evaluation",
        ));
    }
    if let Some(p) = &search.population
        && !(4..=1000).contains(p.get_ref())
    {
        return Err(src.error(p.span(), "search.population", "4 to 1000 candidates"));
    }
    if search.sigma.get_ref().0 > 1.0 {
        return Err(src.error(
            search.sigma.span(),
            "search.sigma",
            "a fraction of the range, ≤ 1",
        ));
    }
    let approaches = approaches(src, file)?;
    let scoring = match search.objective.get_ref().as_str() {
        "line" => Scoring::Line,
        "motion" => Scoring::Motion,
        other => {
            return Err(src.error(
                search.objective.span(),
                "search.objective",
                format!("`{other}`: `line` or `motion`"),
            ));
        }
    };
    Ok(CalibrationPlan {
        name: file.name.clone(),
        seed: file.seed,
        sweep,
        base,
        points,
        natural,
        free,
        budget: *search.budget.get_ref(),
        population: search.population.as_ref().map(|p| *p.get_ref()),
        sigma: search.sigma.get_ref().0,
        margin_db: search.margin_db.get_ref().0,
        approaches,
        approach_rpm: search.approach_rpm.get_ref().0,
        ramp_s: search.ramp_s.get_ref().0,
        scoring,
    })
}

/// The campaign's sweep plan, with the calibration's case timing if it gives one.
fn campaign_plan(src: &ScenarioSource, file: &CalibrationFile) -> anyhow::Result<SweepPlan> {
    let dir = src.path.parent().unwrap_or(Path::new("."));
    let path = dir.join(file.campaign.get_ref());
    let campaign =
        ScenarioSource::read(&path).map_err(|e| src.error(file.campaign.span(), "campaign", e))?;
    let sweep_file: SweepFile = campaign.parse_sweep()?;
    let mut sweep = build_sweep(&campaign, &sweep_file)?;
    if let Some(timing) = &file.case {
        (sweep.settle_s, sweep.measure_s) = case_timing(src, timing, &sweep.analyser)?;
    }
    Ok(sweep)
}

fn target_points(src: &ScenarioSource, file: &CalibrationFile) -> anyhow::Result<Vec<TargetPoint>> {
    let mut points = Vec::new();
    for target in &file.target {
        let t = target.get_ref();
        let expect = match t.half_order.get_ref().as_str() {
            "present" => Expect::Present,
            "absent" => Expect::Absent,
            other => {
                return Err(src.error(
                    t.half_order.span(),
                    "target.half_order",
                    format!("`{other}`: `present` or `absent`"),
                ));
            }
        };
        if t.rpm.is_empty() || t.load_nm.is_empty() {
            return Err(src.error(target.span(), "target", "rpm and load_nm each need a value"));
        }
        for load in &t.load_nm {
            for rpm in &t.rpm {
                points.push(TargetPoint {
                    index: points.len(),
                    rpm: rpm.0,
                    load_nm: load.0,
                    expect,
                    weight: t.weight.0,
                });
            }
        }
    }
    Ok(points)
}

fn free_params(
    src: &ScenarioSource,
    file: &CalibrationFile,
    base: &CaseRig,
) -> anyhow::Result<Vec<FreeParam>> {
    let mut free = Vec::new();
    for entry in &file.free {
        let param = free_param(entry.get_ref(), matches!(base, CaseRig::Preset { .. }))
            .map_err(|message| src.error(entry.span(), "free", message))?;
        if free.iter().any(|p: &FreeParam| p.name == param.name) {
            return Err(src.error(entry.get_ref().name.span(), "free.name", "given twice"));
        }
        for x in [0.0, 1.0] {
            params_at(base, std::slice::from_ref(&param), &[x])
                .map_err(|e| src.error(entry.span(), "free", format!("at the bound: {e:#}")))?;
        }
        free.push(param);
    }
    if free.is_empty() {
        return Err(src.error(0..0, "free", "no free parameter: give [[free]]"));
    }
    Ok(free)
}

/// Why a `[[free]]` entry is not a parameter the search can vary.
#[derive(Debug, thiserror::Error)]
enum FreeParamError {
    /// Not a parameter of `testrig params`.
    #[error("{0}")]
    Unknown(#[from] rig::RigError),
    /// A range that is not one.
    #[error("{0}")]
    Range(&'static str),
    /// A scale other than linear or log.
    #[error("scale `{0}`: `linear` or `log`")]
    Scale(String),
}

/// A `[[free]]` entry read; a preset's parameter is checked by name here, a rig file's
/// path by setting it at the bounds.
fn free_param(f: &FreeFile, preset: bool) -> Result<FreeParam, FreeParamError> {
    let name = f.name.get_ref().clone();
    if preset {
        rig::param_spec(&name)?;
    }
    let scale = f.scale.as_ref().map(|s| s.get_ref().as_str());
    let range = match (&f.choices[..], f.min, f.max, scale) {
        ([_, _, ..], None, None, None) => FreeRange::Choice(f.choices.clone()),
        ([_], ..) => return Err(FreeParamError::Range("a choice needs two values or more")),
        ([], Some(min), Some(max), scale) if min.is_finite() && max.is_finite() && min < max => {
            match scale {
                None | Some("linear") => FreeRange::Linear { min, max },
                Some("log") if min > 0.0 => FreeRange::Log { min, max },
                Some("log") => return Err(FreeParamError::Range("a log scale needs min > 0")),
                Some(other) => return Err(FreeParamError::Scale(other.to_string())),
            }
        }
        ([], Some(_), Some(_), _) => {
            return Err(FreeParamError::Range("min must be below max, both finite"));
        }
        _ => {
            return Err(FreeParamError::Range(
                "give min and max (and scale), or choices",
            ));
        }
    };
    Ok(FreeParam { name, range })
}

fn approaches(src: &ScenarioSource, file: &CalibrationFile) -> anyhow::Result<Vec<ApproachKind>> {
    let list = &file.search.approaches;
    let mut out = Vec::new();
    for name in list.get_ref() {
        let kind = match name.as_str() {
            "static" => ApproachKind::Static,
            "from-below" => ApproachKind::FromBelow,
            "from-above" => ApproachKind::FromAbove,
            other => {
                return Err(src.error(
                    list.span(),
                    "search.approaches",
                    format!("`{other}`: static, from-below or from-above"),
                ));
            }
        };
        if !out.contains(&kind) {
            out.push(kind);
        }
    }
    if out.is_empty() {
        return Err(src.error(list.span(), "search.approaches", "at least one"));
    }
    Ok(out)
}
