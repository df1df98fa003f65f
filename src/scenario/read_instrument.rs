//! The settings of single instruments read from their tables, shared by the standard
//! chain (`read_chain.rs`) and further stages (`read_stages.rs`).

use instruments::LowPassSpec;

use super::chain_toml::{DEFAULT_CUTOFF_HZ, FilterFile, MeterFile};
use super::source::ScenarioSource;
use crate::chain::MeterSettings;

/// A low-pass filter's spec (`None`: none), written at `field`; its cut-off defaults to
/// `band_hz` and must lie below the stream's Nyquist frequency.
pub fn filter_spec(
    src: &ScenarioSource,
    f: &FilterFile,
    field: &str,
    rate_hz: f64,
    band_hz: Option<f64>,
) -> anyhow::Result<Option<LowPassSpec>> {
    let Some(kind) = f.kind.kind() else {
        return Ok(None);
    };
    let (cutoff, span, origin) = match &f.cutoff_hz {
        Some(c) => (c.get_ref().0, c.span(), ""),
        None => match band_hz {
            Some(band) => (band, 0..0, " (left out: the analyser's fmax_hz)"),
            None => (DEFAULT_CUTOFF_HZ, 0..0, " (left out: the default)"),
        },
    };
    if cutoff >= rate_hz / 2.0 {
        return Err(src.error(
            span,
            &format!("{field}.cutoff_hz"),
            format!(
                "{cutoff} Hz{origin} is at or above the analogue Nyquist rate {} Hz (half of rate_hz); a cut-off below it is allowed",
                rate_hz / 2.0
            ),
        ));
    }
    Ok(Some(LowPassSpec {
        kind,
        order: *f.order.get_ref(),
        cutoff_hz: cutoff,
    }))
}

/// An RMS meter's settings.
pub fn meter_settings(m: &MeterFile) -> MeterSettings {
    MeterSettings {
        detector: m.detector.into(),
        tau_s: m.tau_s.0,
        ac_coupling_hz: m.ac_coupling_hz.get_ref().0,
    }
}
