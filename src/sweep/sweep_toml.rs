//! The sweep file as written (TOML): a grid of operating points and parameters, each case
//! run at fixed set points through the measuring chain and the analyser.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

use super::sequence::Sequence;
use crate::scenario::scenario_toml::{AnalyserFile, ChainFile, RecordFile, RigFile};
use crate::scenario::values::{LoadNm, Positive, SpeedRpm};

/// The whole file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFile {
    /// Short name, used in titles.
    pub name: String,
    /// What the sweep shows.
    #[serde(default)]
    pub description: String,
    /// Base seed; case i uses a seed derived from it and i.
    #[serde(default)]
    pub seed: u64,
    /// Rate of the true signals and the analogue chain in each case (Hz).
    #[serde(default = "default_rate")]
    pub rate_hz: Spanned<Positive>,
    /// The rig every case starts from.
    #[serde(default)]
    pub rig: RigFile,
    /// The grid.
    pub grid: GridFile,
    /// Each case's timing.
    pub case: CaseFile,
    /// The measuring chain (as in a scenario).
    #[serde(default)]
    pub chain: ChainFile,
    /// The analyser (as in a scenario).
    pub analyser: AnalyserFile,
    /// When a spectral line counts as present.
    #[serde(default)]
    pub detect: DetectFile,
    /// What each case records over its measured window (as a scenario's `[record]`),
    /// into `recordings/case-NNNNN.*`; left out: nothing.
    pub record: Option<RecordFile>,
}

fn default_rate() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(10_240.0))
}

/// `[grid]`: every combination is a case; parameters outermost, then speed, then load.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridFile {
    /// Motor speed set points (rev/min).
    pub rpm: Vec<SpeedRpm>,
    /// Brake loads (N m).
    pub load_nm: Vec<LoadNm>,
    /// Backlash settings (mm), set through the centre distance.
    #[serde(default)]
    pub backlash_mm: Vec<Positive>,
    /// Any parameter by name with the values it takes (`testrig params` lists the names).
    #[serde(default)]
    pub set: BTreeMap<String, Spanned<Vec<toml::Value>>>,
}

/// `[case]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseFile {
    /// Simulated time before measuring (s).
    pub settle_s: Spanned<Positive>,
    /// Simulated time measured (s): the regime window and the analyser's averages.
    pub measure_s: Spanned<Positive>,
    /// `static` (default): every point from the static load; `up-and-down`: the lab's
    /// run, at each load the speeds stepped up and back down on one rig, each point
    /// settling from the state the one before it left; `every-approach`: the run up and
    /// down, and every point from rest.
    #[serde(default)]
    pub sequence: Sequence,
    /// Knocked repeats of each point started on its own (`static` and `every-approach`):
    /// the point's rig continued, its driven gear knocked by a seeded kick, settled and
    /// measured again, as a lab repeats a doubtful test. 0 (default) to 8.
    #[serde(default)]
    pub repeats: Option<Spanned<u32>>,
}

/// `[detect]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DetectFile {
    /// A line is present when it stands this many dB above the median of the lines
    /// around it (±10 lines, its own ±2 left out).
    #[serde(default = "default_line_db")]
    pub line_db: Positive,
}

impl Default for DetectFile {
    fn default() -> Self {
        Self {
            line_db: default_line_db(),
        }
    }
}

fn default_line_db() -> Positive {
    Positive(10.0)
}
