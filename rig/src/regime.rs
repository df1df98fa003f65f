//! The motion's repetition as a run reports it (period-k or aperiodic, from the physics
//! judge's verdict), and the impacts counted per tooth.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

/// The motion's repetition; written (and read, in JSON and tables) as `period-k` or
/// `aperiodic`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(into = "String", try_from = "String")]
pub enum Regime {
    /// Repeats every k revolutions (k ≥ 1).
    Periodic(usize),
    /// Does not repeat within the longest period looked for.
    Aperiodic,
}

impl Regime {
    /// k of period-k; `None` when aperiodic.
    pub fn period(self) -> Option<usize> {
        match self {
            Self::Periodic(k) => Some(k),
            Self::Aperiodic => None,
        }
    }
}

impl fmt::Display for Regime {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Periodic(k) => write!(f, "period-{k}"),
            Self::Aperiodic => f.write_str("aperiodic"),
        }
    }
}

impl FromStr for Regime {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        if text == "aperiodic" {
            return Ok(Self::Aperiodic);
        }
        text.strip_prefix("period-")
            .and_then(|k| k.parse().ok())
            .filter(|&k| k >= 1)
            .map(Self::Periodic)
            .ok_or_else(|| format!("`{text}` is not a regime: period-k (k ≥ 1) or aperiodic"))
    }
}

impl From<Regime> for String {
    fn from(regime: Regime) -> Self {
        regime.to_string()
    }
}

impl TryFrom<String> for Regime {
    type Error = String;

    fn try_from(text: String) -> Result<Self, String> {
        text.parse()
    }
}

/// Counts of impacts per tooth of the driving gear.
pub fn impacts_per_tooth(teeth: u32, tooth_of_each_impact: impl Iterator<Item = u32>) -> Vec<u64> {
    let mut counts = vec![0; teeth as usize];
    for tooth in tooth_of_each_impact {
        if let Some(c) = counts.get_mut(tooth as usize) {
            *c += 1;
        }
    }
    counts
}
