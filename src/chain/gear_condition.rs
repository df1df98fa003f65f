//! A gear's condition from a steady window: its once-per-revolution pulses (its absolute
//! angle crossing whole turns, as a marker on its shaft gives them), a shaft's torque
//! averaged synchronously over those revolutions, and the condition indicators of that
//! average (`instruments::condition_indicators`, Lebold et al. 2000). The 1983 rig's:
//! the driven gear and the output-shaft torque; a rig file's: the gear and shaft its
//! caller names.

use instruments::{ConditionIndicators, condition_indicators, gear_signals, synchronous_average};
use serde_json::{Value, json};

use super::phasor::Phasor;
use crate::vocabulary::GearIndicators;

/// Points per averaged revolution: 1 024 resolve the mesh harmonics of up to 512 orders.
pub const POINTS_PER_REVOLUTION: usize = 1024;
/// Most torque samples kept (the latest): 2^22, 32 MiB.
const KEPT_SAMPLES_MAX: usize = 1 << 22;

/// A window's torque and the driven gear's pulses, block by block.
#[derive(Clone, Debug)]
pub struct GearCondition {
    rate_hz: f64,
    start_s: Option<f64>,
    torque_nm: Vec<f64>,
    pulses_s: Vec<f64>,
    previous: Option<Previous>,
}

/// ⌊turns⌋ for |turns| < 2⁵²: by truncation to an integer, an instruction on any x86-64,
/// where `f64::floor` is a call into libm without SSE4.1 (one a sample, hoisted out of
/// its branch by the compiler, was 3 % of the lab campaign's time). Unlike `floor` it
/// gives +0 for −0.
pub(crate) fn whole_turns(turns: f64) -> f64 {
    let truncated = turns as i64 as f64;
    if truncated > turns {
        truncated - 1.0
    } else {
        truncated
    }
}

/// The last sample taken: its time (s), the gear's turns and their whole part.
#[derive(Clone, Copy, Debug)]
struct Previous {
    time_s: f64,
    turns: f64,
    whole: f64,
}

impl Previous {
    fn at(time_s: f64, turns: f64, whole: f64) -> Self {
        Self {
            time_s,
            turns,
            whole,
        }
    }
}

/// What a window's synchronous average shows.
#[derive(Clone, Debug, PartialEq)]
pub struct GearConditionReport {
    /// Whole revolutions averaged.
    pub revolutions: usize,
    /// The indicators of the averaged revolution of the torque.
    pub indicators: ConditionIndicators,
    /// RMS of the residual signal (the average less its shaft orders and mesh
    /// harmonics; N m).
    pub residual_rms_nm: f64,
    /// The averaged revolution (N m), `POINTS_PER_REVOLUTION` points from the pulse.
    pub average_nm: Vec<f64>,
}

impl GearCondition {
    /// An empty window of a stream at `rate_hz`.
    pub fn new(rate_hz: f64) -> Self {
        Self {
            rate_hz,
            start_s: None,
            torque_nm: Vec::new(),
            pulses_s: Vec::new(),
            previous: None,
        }
    }

    /// Room for `samples` more torque samples (as many as are kept), so that a window of
    /// known length is stored without growing: growing a vector of millions of samples
    /// copied it and touched fresh pages at each doubling (7 % of the campaign's time in
    /// page faults and copies, measured).
    pub fn reserve(&mut self, samples: usize) {
        self.torque_nm.reserve(samples.min(2 * KEPT_SAMPLES_MAX));
    }

    /// Adds samples at `time_s` of the watched gear's absolute angle (rad, in its sense
    /// of rotation) and of the averaged torque (N m).
    pub fn add_samples(&mut self, time_s: &[f64], gear_angle_rad: &[f64], torque_nm: &[f64]) {
        for (&t, &angle) in time_s.iter().zip(gear_angle_rad) {
            let turns = angle / std::f64::consts::TAU;
            let Some(previous) = self.previous else {
                self.previous = Some(Previous::at(t, turns, whole_turns(turns)));
                continue;
            };
            // ⌊turns⌋, taken only where it may differ from the last sample's (a whole turn
            // crossed or gone back).
            let whole = if turns >= previous.whole + 1.0 || turns < previous.whole {
                whole_turns(turns)
            } else {
                previous.whole
            };
            if whole > previous.whole {
                // The crossing of the whole turn between the two samples, linearly.
                let (t0, turns0) = (previous.time_s, previous.turns);
                self.pulses_s
                    .push(t0 + (t - t0) * (whole - turns0) / (turns - turns0));
            }
            self.previous = Some(Previous::at(t, turns, whole));
        }
        self.start_s
            .get_or_insert(time_s.first().copied().unwrap_or(0.0));
        self.torque_nm.extend_from_slice(torque_nm);
        if self.torque_nm.len() > 2 * KEPT_SAMPLES_MAX {
            let drop = self.torque_nm.len() - KEPT_SAMPLES_MAX;
            self.torque_nm.drain(..drop);
            if let Some(start_s) = &mut self.start_s {
                *start_s += drop as f64 / self.rate_hz;
            }
        }
    }

    /// The amplitude of the kept signal's line at `hz` (Hann-windowed, the window's gain
    /// taken out; 0 without samples), the window's and the line's phases by rotation
    /// (`Phasor`).
    pub fn line_amplitude(&self, hz: f64) -> f64 {
        let x = &self.torque_nm;
        let n = x.len() as f64;
        if x.is_empty() {
            return 0.0;
        }
        let mean = x.iter().sum::<f64>() / n;
        let mut window = Phasor::new(std::f64::consts::TAU / n);
        let mut line = Phasor::new(std::f64::consts::TAU * hz / self.rate_hz);
        let (mut re, mut im, mut gain) = (0.0, 0.0, 0.0);
        for v in x {
            let w = 0.5 - 0.5 * window.next_value().0;
            let (cos, sin) = line.next_value();
            re += w * (v - mean) * cos;
            im -= w * (v - mean) * sin;
            gain += w;
        }
        2.0 * re.hypot(im) / gain
    }

    /// The indicators of the window's average revolution for a gear of `teeth` teeth;
    /// `None` with fewer than two whole revolutions kept.
    pub fn report(&self, teeth: usize) -> Option<GearConditionReport> {
        let start_s = self.start_s?;
        let pulses: Vec<f64> = self
            .pulses_s
            .iter()
            .map(|t| t - start_s)
            .filter(|t| *t >= 0.0)
            .collect();
        let last_s = self.torque_nm.len().saturating_sub(1) as f64 / self.rate_hz;
        let revolutions = pulses.windows(2).filter(|p| p[1] <= last_s).count();
        if revolutions < 2 {
            return None;
        }
        let average = synchronous_average(
            &self.torque_nm,
            self.rate_hz,
            &pulses,
            POINTS_PER_REVOLUTION,
        )
        .ok()?;
        let residual = gear_signals(&average, teeth).residual;
        let residual_rms_nm =
            (residual.iter().map(|r| r * r).sum::<f64>() / residual.len() as f64).sqrt();
        Some(GearConditionReport {
            revolutions,
            indicators: condition_indicators(&average, teeth, &[]),
            residual_rms_nm,
            average_nm: average,
        })
    }
}

impl From<&GearConditionReport> for GearIndicators {
    fn from(report: &GearConditionReport) -> Self {
        let i = &report.indicators;
        Self {
            revolutions: report.revolutions,
            fm0: i.fm0,
            fm4: i.fm4,
            m6a: i.m6a,
            m8a: i.m8a,
            na4: i.na4,
            sideband_level: i.sideband_level,
            rms_nm: i.rms,
            crest_factor: i.crest_factor,
            kurtosis: i.kurtosis,
            residual_rms_nm: report.residual_rms_nm,
        }
    }
}

impl GearConditionReport {
    /// As JSON, every indicator by name.
    pub fn to_json(&self) -> Value {
        let i = &self.indicators;
        json!({
            "revolutions_averaged": self.revolutions,
            "points_per_revolution": POINTS_PER_REVOLUTION,
            "fm0": i.fm0, "fm4": i.fm4, "m6a": i.m6a, "m8a": i.m8a, "na4": i.na4,
            "sideband_level": i.sideband_level, "rms_nm": i.rms,
            "crest_factor": i.crest_factor, "kurtosis": i.kurtosis,
            "residual_rms_nm": self.residual_rms_nm,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{GearCondition, whole_turns};

    #[test]
    fn whole_turns_is_the_floor() {
        let near_whole = [-3.0, -1.0, 0.0, 1.0, 2.0, 1e6]
            .into_iter()
            .flat_map(|w: f64| [w, w.next_down(), w.next_up(), w + 0.5, w - 0.5]);
        let spread = (-2000..2000).map(|k| f64::from(k) * 0.013_7);
        for turns in near_whole.chain(spread) {
            assert_eq!(whole_turns(turns), turns.floor(), "{turns:e}");
        }
    }

    /// A line's amplitude read back: 2.5 N m at 13.333 Hz (not a whole number of cycles
    /// in the 10 s kept) beside 0.4 N m at 60 Hz and an offset, sampled at 51.2 kHz.
    #[test]
    fn a_lines_amplitude_is_read_back_beside_another_line() {
        let rate_hz = 51_200.0;
        let mut condition = GearCondition::new(rate_hz);
        let time_s: Vec<f64> = (0..512_000).map(|k| k as f64 / rate_hz).collect();
        let angle_rad: Vec<f64> = time_s.iter().map(|t| std::f64::consts::TAU * t).collect();
        let torque_nm: Vec<f64> = time_s
            .iter()
            .map(|t| {
                let phase = |hz: f64| std::f64::consts::TAU * hz * t;
                7.0 + 2.5 * (phase(13.333) + 0.3).cos() + 0.4 * phase(60.0).sin()
            })
            .collect();
        condition.add_samples(&time_s, &angle_rad, &torque_nm);
        let read = [13.333, 60.0, 31.0].map(|hz| condition.line_amplitude(hz));
        assert!((read[0] - 2.5).abs() < 1e-6, "{read:?}");
        assert!((read[1] - 0.4).abs() < 1e-6, "{read:?}");
        assert!(read[2] < 1e-6, "no line at 31 Hz: {read:?}");
    }
}
