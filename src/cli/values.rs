//! Flags parsed into the types they stand for, so that a bad value is refused by the
//! argument parser with the flag named and the choices listed: the pace, a shard, the
//! window, the sampling convention, the anti-alias filter, the training half.

use clap::ValueEnum;
use instruments::{FilterKind, Window};
use testrig::runtime::Pace;
use testrig::sweep::Shard;
use testrig::vocabulary::SamplingChoice;

/// `--pace`: `1` (real time), a factor from 0.001 to 10⁶, or `max`.
pub fn pace(text: &str) -> Result<Pace, String> {
    Pace::parse(text).ok_or_else(|| "1 (real time), a factor from 0.001 to 1e6, or max".to_string())
}

/// `--shard K/N`.
pub fn shard(text: &str) -> Result<Shard, String> {
    Shard::parse(text).map_err(|e| format!("{e:#}"))
}

/// `--window`: uniform, hanning or flattop.
pub fn window(text: &str) -> Result<Window, String> {
    Window::parse(text).ok_or_else(|| format!("one of {}", Window::NAMES))
}

/// `--sampling`: thesis (fs = 2 Fmax) or 2.56 (fs = 2.56 Fmax).
pub fn sampling(text: &str) -> Result<SamplingChoice, String> {
    SamplingChoice::parse(text)
        .ok_or_else(|| "thesis (fs = 2 Fmax) or 2.56 (fs = 2.56 Fmax)".to_string())
}

/// `--filter`: none, butterworth:ORDER or bessel:ORDER.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FilterArg {
    /// The filter's kind (`None`: no filter).
    pub kind: Option<FilterKind>,
    /// Its order (0 without a filter).
    pub order: usize,
}

/// Parses `--filter`.
pub fn filter(text: &str) -> Result<FilterArg, String> {
    if text == "none" {
        return Ok(FilterArg {
            kind: None,
            order: 0,
        });
    }
    let (kind, order) = text
        .split_once(':')
        .ok_or("none, butterworth:ORDER or bessel:ORDER")?;
    let kind = match kind {
        "butterworth" => FilterKind::Butterworth,
        "bessel" => FilterKind::Bessel,
        other => return Err(format!("`{other}` is not butterworth or bessel")),
    };
    let order = order
        .parse()
        .map_err(|_| "the order must be a whole number".to_string())?;
    Ok(FilterArg {
        kind: Some(kind),
        order,
    })
}

impl std::fmt::Display for FilterArg {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.kind {
            None => f.write_str("none"),
            Some(FilterKind::Butterworth) => write!(f, "butterworth:{}", self.order),
            Some(FilterKind::Bessel) => write!(f, "bessel:{}", self.order),
        }
    }
}

/// `--train-half`: which half of the target points a cross-validating search trains on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum TrainingHalf {
    /// The points at even positions.
    Even,
    /// The points at odd positions.
    Odd,
}

/// `simulate --approach`: how the point is reached.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Approach {
    /// At the set speed in steady motion from the static load (shafts and meshes twisted
    /// to carry it, no vibration).
    #[value(alias = "steady")]
    Static,
    /// From standstill at t = 0, the knob at the set speed.
    Rest,
    /// The lab's slow run-up from below.
    Up,
    /// The lab's slow run-down from above.
    Down,
}

impl Approach {
    /// The plant's approach to `rpm` (a ramp at `ramp_rpm_per_s`), checked.
    pub fn to_rig(self, rpm: f64, ramp_rpm_per_s: f64) -> anyhow::Result<rig::Approach> {
        let name = self.to_possible_value().map(|v| v.get_name().to_string());
        testrig::approach_name::approach_named(&name.unwrap_or_default(), rpm, ramp_rpm_per_s)
    }
}
