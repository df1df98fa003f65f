//! The analyser operated live: commands (start, hold, settings, ADC range, save) and the
//! display published for the front panel after every block averaged.

use std::sync::Arc;

use instruments::{Adc, AdcSettings};

use super::analyser::AnalyserSink;
use crate::chain::analyser_setup::{AdcChoice, AnalyserSetting, AnalyserSetupError, AnalyserWords};
use crate::chain::{Measurement, Truth};
use crate::scenario::Measure;
use crate::vocabulary::Refusal;
use crate::vocabulary::frame::Frame;
use crate::vocabulary::{LiveSpectrum, RigCommand};

impl AnalyserSink {
    /// Publishes the display on the panel after every block averaged, and at once (its
    /// settings, no averages yet): a client asking before the first block sees them.
    pub fn go_live(&mut self) {
        self.live = true;
        self.publish();
    }

    /// Carries out `command` (at `frame`'s start) if it is the analyser's.
    pub(super) fn carry_out(
        &mut self,
        command: &RigCommand,
        frame: &Frame,
    ) -> Option<Result<(), Refusal>> {
        let outcome = match command {
            RigCommand::StartAverage => self.start_now(frame),
            RigCommand::HoldAverage => self.close_measurement().map_err(|e| Refusal::failed(&e)),
            RigCommand::SetAdcRange { range_v } => self.set_adc(AdcSettings {
                range_v: *range_v,
                ..self.plan.adc
            }),
            RigCommand::SetAnalyser { .. } => self.set_analyser(command),
            RigCommand::SaveDisplays => self.save().map_err(|e| Refusal::failed(&e)),
            _ => return None,
        };
        if outcome.is_ok() && self.live {
            self.published = None;
            self.publish();
        }
        Some(outcome)
    }

    /// A fresh average from `frame`'s start, as a measurement of the session.
    fn start_now(&mut self, frame: &Frame) -> Result<(), Refusal> {
        let set = frame.set_points.unwrap_or(rig::SetPoints {
            speed_rpm: 0.0,
            load_nm: 0.0,
            oscillating_load_nm: 0.0,
            oscillating_load_hz: 0.0,
        });
        let index = self.measures.len();
        self.measures.push(Measure {
            at_s: frame.start_sample as f64 / self.rate_hz,
            label: format!("average {}", index + 1),
            speed_rpm: set.speed_rpm,
            load_nm: set.load_nm,
        });
        self.points_of.push(None);
        self.start(index).map_err(|e| Refusal::failed(&e))
    }

    fn set_adc(&mut self, settings: AdcSettings) -> Result<(), Refusal> {
        let adc = Adc::new(settings).map_err(Refusal::from)?;
        self.replace_adc(adc, settings);
        Ok(())
    }

    /// Puts `adc` (built from `settings`) in place, its predecessor's overloads counted.
    fn replace_adc(&mut self, adc: Adc, settings: AdcSettings) {
        self.overloads += self.measurement.overloads();
        self.measurement.setup.adc = adc;
        self.measurement.setup.adc_settings = settings;
        self.plan.adc = settings;
    }

    /// New analyser settings; the average under way is written and a fresh one started.
    fn set_analyser(&mut self, command: &RigCommand) -> Result<(), Refusal> {
        let RigCommand::SetAnalyser {
            fmax_hz,
            block,
            window,
            averages,
            overlap_pct,
        } = command
        else {
            return Err(Refusal::NotFor("not an analyser setting".into()));
        };
        let mut words = AnalyserWords::of(&self.plan.settings, AdcChoice::of(&self.plan.adc));
        words.fmax_hz = fmax_hz.unwrap_or(words.fmax_hz);
        words.block = block.unwrap_or(words.block);
        words.window = window.map_or(words.window, |w| w.0);
        words.averages = averages.unwrap_or(words.averages);
        words.overlap = overlap_pct.map_or(words.overlap, |pct| pct / 100.0);
        let setup = words
            .set_up(self.rate_hz)
            .map_err(|e| live_refusal(&e, &words))?;
        let restart = self.active;
        self.close_measurement().map_err(|e| Refusal::failed(&e))?;
        self.overloads += self.measurement.overloads();
        self.plan.settings = setup.settings;
        self.plan.adc = setup.adc_settings;
        self.measurement = Measurement::new(setup, Truth::Kept);
        if let Some(index) = restart {
            let measure = self.measures[index].clone();
            self.measures.push(measure);
            self.points_of.push(self.points_of[index]);
            self.start(self.measures.len() - 1)
                .map_err(|e| Refusal::failed(&e))?;
        }
        Ok(())
    }

    /// Writes the display as it stands as `saved-NN-spectrum`.
    fn save(&mut self) -> anyhow::Result<()> {
        self.saved += 1;
        let count = self.measurement.average_count();
        let Some(index) = self.active.or(self.measures.len().checked_sub(1)) else {
            anyhow::bail!("no average has been started");
        };
        let base = self.dir.join(format!("saved-{:02}-spectrum", self.saved));
        self.write_spectrum(&base, index, count)
    }

    /// Puts the display (and the truth of the blocks averaged so far) on the panel.
    pub(super) fn publish(&mut self) {
        let count = self.measurement.average_count();
        if self.published == Some(count) {
            return;
        }
        self.published = Some(count);
        let s = self.plan.settings;
        let (lines, flags) = self.measurement.lines_and_truth();
        let alias_of_hz = if count > 0 {
            flags
        } else {
            vec![None; lines.len()]
        };
        let running_hz = self
            .active
            .or(self.measures.len().checked_sub(1))
            .map_or(0.0, |i| self.measures[i].speed_rpm / 60.0);
        // Shown down to the chain's own noise floor, never at the −300 dB of a silent
        // stream's round-off.
        let floor_v2 = self.measurement.floor();
        let spectrum = LiveSpectrum {
            frequency_hz: lines.iter().map(|l| l.frequency_hz).collect(),
            power_v2: lines.iter().map(|l| l.value.max(floor_v2)).collect(),
            floor_v2,
            alias_of_hz,
            averages: count,
            averages_set: s.averages,
            complete: self.active.is_none(),
            running_hz,
            signal: self.plan.input.clone(),
            unit: self.unit.to_string(),
            window: s.window.name().to_string(),
            fmax_hz: s.fmax_hz,
            block: s.block,
            overlap_pct: 100.0 * s.overlap,
            adc_range_v: self.plan.adc.range_v,
        };
        self.status
            .update(|st| st.spectrum = Some(Arc::new(spectrum)));
    }
}

/// The panel's words for a refused analyser setting: the field and value at fault, then
/// why.
fn live_refusal(e: &AnalyserSetupError, words: &AnalyserWords) -> Refusal {
    Refusal::Setting(match e.setting() {
        AnalyserSetting::FmaxHz => format!("fmax_hz {}: {e}", words.fmax_hz),
        AnalyserSetting::OverlapPct => format!("overlap_pct {}: {e}", 100.0 * words.overlap),
        AnalyserSetting::Averages | AnalyserSetting::Block | AnalyserSetting::Adc => e.to_string(),
    })
}
