//! The verdict: period-k, quasi-periodic, chaotic or no vibration, from the numbers.
//!
//! Thresholds and why (issue 26 asks for no looser than 10 %, 90 % and 20 dB):
//! - period k: the once-per-revolution samples of the output-shaft torque taken every k
//!   revolutions scatter by at most [`SPREAD_MAX`] (5 %) of the torque's AC RMS, and at
//!   least [`LINE_FRACTION_MIN`] (95 %) of the band's power lies on the lines at multiples
//!   of the running speed / k. A settled periodic motion of the plant gives spreads
//!   below 0.1 % and fractions above 99.9 %, so the margin is for slow transients, not for
//!   near-chaos; the smallest k (1..=[`MAX_PERIOD`]) that passes both is the period.
//!   One rule more, for every speed: no subharmonic line at 1/m of the running speed with
//!   m not dividing k stands clear (below). A half-order line clear of the floor is a
//!   subharmonic on the 5451C's log display even when it holds 2 % of the power and the
//!   once-per-revolution samples differ by under 5 % (or meet it where it crosses zero):
//!   such a motion repeats every 2 revolutions, not every one.
//! - chaotic: not periodic, and the 0-1 test's K at least [`CHAOS_K_MIN`] (0.5: the test
//!   gives K → 1 for chaos and K → 0 for regular motion, Gottwald & Melbourne 2009).
//! - quasi-periodic: not periodic, K below that (regular but not repeating within
//!   [`MAX_PERIOD`] revolutions: a torus, a long period, or a transient still decaying).
//! - no vibration: the torque's AC RMS below [`NO_VIBRATION_AC_RMS_NM`] (1e-4 N m, 0.0004 µε at
//!   the gauges, far under any noise of the measuring chain): the shafts turn steadily
//!   (named so, not "at rest", because they do turn).
//! - undecided: too few revolutions for the 0-1 test and no period found.
//!
//! A subharmonic "stands clear" when its height over the broadband floor reaches
//! [`SUBHARMONIC_CLEAR_DB`] (20 dB) and it carries at least [`SUBHARMONIC_VISIBLE_SHARE`]
//! (1e-6, 60 dB under the band's power) of the band's power: the report, the period
//! label and the campaign's facts all use this one rule ([`stands_clear`]). The second
//! half matters for an exact plant: its broadband floor is rounding, and a line 110 dB
//! under the running-speed lines (a share of 1e-11) still stands 120 dB over it, where no
//! analyser shows anything.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use super::order_lines::{OrderSpectrum, subharmonic_height_db, subharmonic_share};
use super::spread::section_spread;
use super::zero_one::zero_one_k;

/// Longest period looked for (revolutions).
pub const MAX_PERIOD: usize = 8;
/// Largest scatter of every-k-revolution samples for period k (fraction of AC RMS).
pub const SPREAD_MAX: f64 = 0.05;
/// Smallest share of the band's power on the lines of period k.
pub const LINE_FRACTION_MIN: f64 = 0.95;
/// Smallest K of the 0-1 test called chaos.
pub const CHAOS_K_MIN: f64 = 0.5;
/// Largest AC RMS of the output-shaft torque called no vibration (N m).
pub const NO_VIBRATION_AC_RMS_NM: f64 = 1e-4;
/// Height over the floor (dB) at which a subharmonic line stands clear.
pub const SUBHARMONIC_CLEAR_DB: f64 = 20.0;
/// Smallest share of the band's power a subharmonic line carries to stand clear: 60 dB
/// under the band's power, within the 72 dB a 12-bit ADC spans (the chain's ADC, as the
/// 5451C's), so that the analyser's log display shows it.
pub const SUBHARMONIC_VISIBLE_SHARE: f64 = 1e-6;
/// Scatter of once-per-revolution samples (fraction of the AC RMS) below which the section
/// is a fixed point and K is 0 without testing.
const FIXED_POINT_SPREAD: f64 = 1e-3;
/// The spectrum's band, in orders of the running speed (the mesh frequency, 30 orders,
/// and its first sidebands lie inside).
const BAND_ORDERS: f64 = 40.0;

/// What the judge reads: the output (intermediate) shaft's torque over a settled window.
#[derive(Clone, Copy, Debug)]
pub struct JudgeInput<'a> {
    /// The torque sampled evenly over the window (N m).
    pub torque_nm: &'a [f64],
    /// Its sample rate (Hz).
    pub rate_hz: f64,
    /// Running speed of the gears (rev/s).
    pub running_hz: f64,
    /// The torque sampled once per revolution of the driving gear (N m).
    pub revolution_torque_nm: &'a [f64],
}

/// The kind of motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Motion {
    /// The torque does not vibrate: the shafts turn steadily.
    NoVibration,
    /// Repeats every k revolutions, cleanly.
    Periodic(usize),
    /// Regular but not repeating within [`MAX_PERIOD`] revolutions.
    QuasiPeriodic,
    /// Chaotic by the 0-1 test.
    Chaotic,
    /// Too short a window to tell.
    Undecided,
}

impl Motion {
    /// k of period-k; `None` otherwise.
    pub fn period(self) -> Option<usize> {
        match self {
            Self::Periodic(k) => Some(k),
            _ => None,
        }
    }
}

impl fmt::Display for Motion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoVibration => f.write_str("no-vibration"),
            Self::Periodic(k) => write!(f, "period-{k}"),
            Self::QuasiPeriodic => f.write_str("quasi-periodic"),
            Self::Chaotic => f.write_str("chaotic"),
            Self::Undecided => f.write_str("undecided"),
        }
    }
}

impl FromStr for Motion {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        match text {
            "no-vibration" => Ok(Self::NoVibration),
            "quasi-periodic" => Ok(Self::QuasiPeriodic),
            "chaotic" => Ok(Self::Chaotic),
            "undecided" => Ok(Self::Undecided),
            _ => text
                .strip_prefix("period-")
                .and_then(|k| k.parse().ok())
                .filter(|&k| k >= 1)
                .map(Self::Periodic)
                .ok_or_else(|| {
                    format!(
                        "`{text}` is not a motion: period-k (k ≥ 1), quasi-periodic, chaotic, no-vibration or undecided"
                    )
                }),
        }
    }
}

impl Serialize for Motion {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for Motion {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        String::deserialize(d)?
            .parse()
            .map_err(serde::de::Error::custom)
    }
}

/// The verdict with the numbers behind it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Judgement {
    /// The kind of motion.
    pub motion: Motion,
    /// AC RMS of the output-shaft torque over the window (N m).
    pub ac_rms_nm: f64,
    /// For k = 1..=8: the scatter of samples taken every k revolutions, as a fraction of
    /// the AC RMS (`None`: too few revolutions).
    pub spread: Vec<Option<f64>>,
    /// For k = 1..=8: the share of the band's power on the lines of period k (`None`:
    /// lines too close to resolve in the window).
    pub line_fraction: Vec<Option<f64>>,
    /// Height of the half-order line over the floor between the half-order lines (dB).
    pub half_order_db: Option<f64>,
    /// Height of the 1/3-order line over the floor between the third-order lines (dB).
    pub third_order_db: Option<f64>,
    /// Share of the band's power on the half-order line.
    pub half_order_share: Option<f64>,
    /// Share of the band's power on the 1/3-order line.
    pub third_order_share: Option<f64>,
    /// K of the 0-1 test on the once-per-revolution torque (0 regular, 1 chaotic).
    pub chaos_k: Option<f64>,
}

impl Judgement {
    /// Whether the half-order line stands clear ([`stands_clear`]).
    pub fn half_order_clear(&self) -> bool {
        stands_clear(self.half_order_db, self.half_order_share)
    }

    /// Whether the 1/3-order line stands clear ([`stands_clear`]).
    pub fn third_order_clear(&self) -> bool {
        stands_clear(self.third_order_db, self.third_order_share)
    }
}

/// The one rule for a subharmonic line: [`SUBHARMONIC_CLEAR_DB`] over its floor and at
/// least [`SUBHARMONIC_VISIBLE_SHARE`] of the band's power.
pub fn stands_clear(height_db: Option<f64>, share: Option<f64>) -> bool {
    height_db.is_some_and(|h| h >= SUBHARMONIC_CLEAR_DB)
        && share.is_some_and(|s| s >= SUBHARMONIC_VISIBLE_SHARE)
}

/// Fewest torque samples judged: below it the verdict is undecided.
const MIN_SAMPLES: usize = 64;

/// Judges the motion in `input`.
pub fn judge(input: &JudgeInput) -> Judgement {
    let ac_rms_nm = ac_rms(input.torque_nm);
    if input.torque_nm.len() < MIN_SAMPLES || input.running_hz.is_nan() || input.running_hz <= 0.0 {
        return Judgement {
            motion: Motion::Undecided,
            ac_rms_nm,
            spread: vec![None; MAX_PERIOD],
            line_fraction: vec![None; MAX_PERIOD],
            half_order_db: None,
            third_order_db: None,
            half_order_share: None,
            third_order_share: None,
            chaos_k: None,
        };
    }
    let spectrum = OrderSpectrum::new(
        input.torque_nm,
        input.rate_hz,
        input.running_hz,
        BAND_ORDERS,
    );
    let relative = |v: Option<f64>| v.map(|s| s / ac_rms_nm.max(f64::MIN_POSITIVE));
    let spread: Vec<Option<f64>> = (1..=MAX_PERIOD)
        .map(|k| relative(section_spread(input.revolution_torque_nm, k)))
        .collect();
    let line_fraction: Vec<Option<f64>> = (1..=MAX_PERIOD)
        .map(|k| spectrum.line_fraction(k))
        .collect();
    // A section that does not move (a fixed point of the once-per-revolution map) is
    // regular by definition: the 0-1 test on its rounding and its last transient says
    // nothing.
    let chaos_k = if spread[0].is_some_and(|s| s < FIXED_POINT_SPREAD) {
        Some(0.0)
    } else {
        zero_one_k(input.revolution_torque_nm)
    };
    let period = (1..=MAX_PERIOD).find(|&k| {
        spread[k - 1].is_some_and(|s| s <= SPREAD_MAX)
            && line_fraction[k - 1].is_some_and(|f| f >= LINE_FRACTION_MIN)
            && !foreign_subharmonic_clear(&spectrum, k)
    });
    let motion = if ac_rms_nm < NO_VIBRATION_AC_RMS_NM {
        Motion::NoVibration
    } else if let Some(k) = period {
        Motion::Periodic(k)
    } else {
        match chaos_k {
            Some(k) if k >= CHAOS_K_MIN => Motion::Chaotic,
            Some(_) => Motion::QuasiPeriodic,
            None => Motion::Undecided,
        }
    };
    Judgement {
        motion,
        ac_rms_nm,
        spread,
        line_fraction,
        half_order_db: subharmonic_height_db(&spectrum, 2),
        third_order_db: subharmonic_height_db(&spectrum, 3),
        half_order_share: subharmonic_share(&spectrum, 2),
        third_order_share: subharmonic_share(&spectrum, 3),
        chaos_k,
    }
}

/// Whether a subharmonic line at 1/m of the running speed, for some m (2..=[`MAX_PERIOD`])
/// that does not divide `k`, stands clear ([`stands_clear`]): a line period k cannot have.
fn foreign_subharmonic_clear(spectrum: &OrderSpectrum, k: usize) -> bool {
    (2..=MAX_PERIOD).filter(|m| !k.is_multiple_of(*m)).any(|m| {
        stands_clear(
            subharmonic_height_db(spectrum, m),
            subharmonic_share(spectrum, m),
        )
    })
}

fn ac_rms(values: &[f64]) -> f64 {
    let n = values.len().max(1) as f64;
    let mean = values.iter().sum::<f64>() / n;
    (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt()
}
