//! Regime classification from once-per-revolution samples: period-k or aperiodic.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use crate::records::RevolutionSample;

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

/// How the once-per-revolution samples are compared.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegimeCriteria {
    /// Longest period looked for (revolutions).
    pub max_period: usize,
    /// Samples n and n − k agree when every state differs by less than this fraction of
    /// that state's spread over the window.
    pub relative_tolerance: f64,
    /// Each state's spread is at least this (rad or rad/s), so a still rig is period-1.
    pub spread_floor: f64,
}

impl Default for RegimeCriteria {
    fn default() -> Self {
        Self {
            max_period: 12,
            relative_tolerance: 0.02,
            spread_floor: 1e-9,
        }
    }
}

/// Classifies samples taken once per revolution: the smallest k for which every sample
/// matches the one k revolutions before it. Needs at least 2k + 1 samples for period k.
/// Each state is compared on the scale of its own spread over the samples.
pub fn classify(samples: &[RevolutionSample], criteria: &RegimeCriteria) -> Regime {
    classify_scaled(
        samples,
        &spread_of(samples, criteria.spread_floor),
        criteria,
    )
}

/// As [`classify`], comparing state i on `scale[i]` (rad or rad/s; infinity leaves it out),
/// e.g. the RMS of its vibration over the window: a decaying transient smaller than
/// `relative_tolerance` of the vibration then no longer hides a periodic motion.
pub fn classify_scaled(
    samples: &[RevolutionSample],
    scale: &[f64; 10],
    criteria: &RegimeCriteria,
) -> Regime {
    let spread: [f64; 10] = std::array::from_fn(|i| scale[i].max(criteria.spread_floor));
    (1..=criteria.max_period)
        .take_while(|&k| samples.len() > 2 * k)
        .find(|&k| repeats_every(samples, k, &spread, criteria.relative_tolerance))
        .map_or(Regime::Aperiodic, Regime::Periodic)
}

fn spread_of(samples: &[RevolutionSample], floor: f64) -> [f64; 10] {
    std::array::from_fn(|i| {
        let values = samples.iter().map(|s| s.state[i]);
        let high = values.clone().fold(f64::NEG_INFINITY, f64::max);
        let low = values.fold(f64::INFINITY, f64::min);
        (high - low).max(floor)
    })
}

fn repeats_every(
    samples: &[RevolutionSample],
    k: usize,
    spread: &[f64; 10],
    tolerance: f64,
) -> bool {
    samples.windows(k + 1).all(|w| {
        let (a, b) = (&w[0].state, &w[k].state);
        (0..10).all(|i| (a[i] - b[i]).abs() <= tolerance * spread[i])
    })
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
