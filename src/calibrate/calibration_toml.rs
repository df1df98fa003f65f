//! The calibration file as written (TOML): the campaign whose case settings it borrows,
//! the targets, the free parameters and the search's settings.

use serde::Deserialize;
use toml::Spanned;

use crate::scenario::values::{LoadNm, Positive, SpeedRpm};
use crate::sweep::sweep_toml::CaseFile;

/// The whole file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CalibrationFile {
    /// Short name, used in titles.
    pub name: String,
    /// What the calibration is for.
    #[serde(default)]
    pub description: String,
    /// The sweep file (relative to this file) whose rig, chain, analyser, detection and
    /// case timing each evaluation uses; its grid is not used.
    pub campaign: Spanned<String>,
    /// Seed of the search (the cases keep the campaign's seeds).
    #[serde(default)]
    pub seed: u64,
    /// The evaluations' case timing, instead of the campaign's.
    #[serde(default)]
    pub case: Option<CaseFile>,
    /// The search.
    #[serde(default)]
    pub search: SearchFile,
    /// Operating points with the finding expected there.
    #[serde(default)]
    pub target: Vec<Spanned<TargetFile>>,
    /// Natural frequencies of the linear model expected.
    #[serde(default)]
    pub natural: Vec<Spanned<NaturalFile>>,
    /// The parameters the search may change.
    #[serde(default)]
    pub free: Vec<Spanned<FreeFile>>,
}

/// `[search]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SearchFile {
    /// Evaluations (candidate parameter sets) in all, unless `--budget` says otherwise.
    #[serde(default = "default_budget")]
    pub budget: Spanned<usize>,
    /// Candidates per generation of the first run (default 4 + ⌊3 ln n⌋).
    pub population: Option<Spanned<usize>>,
    /// Initial step size as a fraction of each parameter's range.
    #[serde(default = "default_sigma")]
    pub sigma: Spanned<Positive>,
    /// Margin (dB) a line must clear its threshold by, either way, before a point adds
    /// nothing to the objective.
    #[serde(default = "default_margin")]
    pub margin_db: Spanned<Positive>,
    /// How each point is reached: any of `static`, `from-below`, `from-above`. A point
    /// matches only if every approach listed gives the expected finding.
    #[serde(default = "default_approaches")]
    pub approaches: Spanned<Vec<String>>,
    /// How far below or above the set speed a ramped approach starts (rev/min).
    #[serde(default = "default_delta")]
    pub approach_rpm: Spanned<Positive>,
    /// Length of the ramp (s).
    #[serde(default = "default_ramp")]
    pub ramp_s: Spanned<Positive>,
    /// What a point is scored on: `line` (the half-order line's height in the chain's
    /// spectrum) or `motion` (the physics judge's motion: period 2 with a clear half
    /// order where the line is expected, period 1 where it is not).
    #[serde(default = "default_objective")]
    pub objective: Spanned<String>,
}

impl Default for SearchFile {
    fn default() -> Self {
        Self {
            budget: default_budget(),
            population: None,
            sigma: default_sigma(),
            margin_db: default_margin(),
            approaches: default_approaches(),
            approach_rpm: default_delta(),
            ramp_s: default_ramp(),
            objective: default_objective(),
        }
    }
}

fn default_budget() -> Spanned<usize> {
    Spanned::new(0..0, 200)
}
fn default_sigma() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(0.3))
}
fn default_margin() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(3.0))
}
fn default_approaches() -> Spanned<Vec<String>> {
    Spanned::new(0..0, vec!["from-below".into(), "from-above".into()])
}
fn default_delta() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(100.0))
}
fn default_objective() -> Spanned<String> {
    Spanned::new(0..0, "line".into())
}

fn default_ramp() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(5.0))
}

/// `[[target]]`: every speed at every load expects the same finding.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TargetFile {
    /// Speeds (rev/min).
    pub rpm: Vec<SpeedRpm>,
    /// Loads (N m).
    pub load_nm: Vec<LoadNm>,
    /// `present` or `absent`: the half-order line expected.
    pub half_order: Spanned<String>,
    /// Weight of these points in the objective.
    #[serde(default = "default_weight")]
    pub weight: Positive,
}

fn default_weight() -> Positive {
    Positive(1.0)
}

/// `[[natural]]`: a natural frequency of the linear model (all teeth in contact).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NaturalFile {
    /// Mode number, 1 the fundamental (the rigid-body mode is not counted).
    pub mode: Spanned<usize>,
    /// Expected frequency (Hz).
    pub hz: Positive,
    /// Within this it adds nothing (Hz).
    pub tolerance_hz: Positive,
    /// dB of objective per tolerance outside it.
    #[serde(default = "default_weight")]
    pub weight: Positive,
}

/// `[[free]]`: one parameter the search may change.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FreeFile {
    /// A `testrig params` name.
    pub name: Spanned<String>,
    /// Lower bound (numbers).
    pub min: Option<f64>,
    /// Upper bound (numbers).
    pub max: Option<f64>,
    /// `linear` (default) or `log` (both bounds > 0).
    pub scale: Option<Spanned<String>>,
    /// The values of a choice (a model option), instead of bounds.
    #[serde(default)]
    pub choices: Vec<String>,
}
