//! How a caller names a steady point's inputs in its messages (the command line's flags,
//! a sweep's keys, the Python function's arguments), and the checks of its times that
//! refuse each input under that name.

use anyhow::bail;

use super::limits::check_simulated_s;

/// How the caller names each input in its messages (the command line's flags, or the
/// Python function's arguments).
#[derive(Clone, Copy, Debug)]
pub struct InputNames {
    /// The speed.
    pub rpm: &'static str,
    /// The load.
    pub load: &'static str,
    /// The settling time.
    pub settle: &'static str,
    /// The measuring window.
    pub duration: &'static str,
    /// The output rate.
    pub rate: &'static str,
}

/// The command line's names.
pub const FLAG_NAMES: InputNames = InputNames {
    rpm: "--rpm",
    load: "--load",
    settle: "--settle",
    duration: "--duration",
    rate: "--rate",
};

/// The settling time, the window and the output rate, each refused under its name.
pub fn check_times(
    settle_s: f64,
    duration_s: f64,
    rate_hz: f64,
    names: InputNames,
) -> anyhow::Result<()> {
    if !rig::takes_output_rate(rate_hz) {
        bail!(
            "{} {}: a sample rate from {} Hz to {:e} Hz",
            names.rate,
            rate_hz,
            rig::MIN_OUTPUT_RATE_HZ,
            rig::MAX_OUTPUT_RATE_HZ
        );
    }
    check_simulated_s(duration_s, false)
        .map_err(|e| anyhow::anyhow!("{} {}: {e}", names.duration, duration_s))?;
    check_simulated_s(settle_s, true)
        .map_err(|e| anyhow::anyhow!("{} {}: {e}", names.settle, settle_s))?;
    Ok(())
}
