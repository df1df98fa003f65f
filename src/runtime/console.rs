//! The console while a run goes: a progress bar and, refreshed a few times a second, what
//! the experimenter reads off the rack. Drawn only on a terminal.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use instruments::CROMPTON_PARKINSON_V_PER_RPM;

use super::status::Status;

/// The console display.
pub struct Console {
    bar: ProgressBar,
    rate_hz: f64,
}

impl Console {
    /// A display for `total_samples` at `rate_hz`; hidden when `visible` is false.
    pub fn new(total_samples: u64, rate_hz: f64, visible: bool) -> Self {
        let target = if visible {
            ProgressDrawTarget::stderr_with_hz(4)
        } else {
            ProgressDrawTarget::hidden()
        };
        let bar = ProgressBar::with_draw_target(Some(total_samples), target);
        let style = ProgressStyle::with_template("{bar:24} {percent:>3}% {msg} (eta {eta})")
            .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        Self { bar, rate_hz }
    }

    /// Shows `status`.
    pub fn show(&self, status: &Status) {
        self.bar.set_position(status.simulated_samples);
        let (n, of) = status.averages;
        self.bar.set_message(format!(
            "t {:.1} s | tacho {:.1} V = {:.0} rev/min | meter {:.3} V | analyser {n} of {of} | overloads {} | overruns {}",
            status.simulated_samples as f64 / self.rate_hz,
            status.dvm_v,
            status.dvm_v / CROMPTON_PARKINSON_V_PER_RPM,
            status.meter_v,
            status.adc_overloads,
            status.overruns,
        ));
    }

    /// Removes the bar.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}
