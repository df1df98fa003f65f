//! The settings of single instruments read from their tables, shared by the standard
//! chain (`read_chain.rs`) and further stages (`read_stages.rs`).

use instruments::LowPassSpec;

use super::chain_toml::{DEFAULT_CUTOFF_HZ, FilterFile, MeterFile};
use super::source::ScenarioSource;
use crate::chain::{LowPassWords, MeterSettings};

/// A low-pass filter's spec (`None`: none), written at `field`; its cut-off defaults to
/// `band_hz` and must lie below the stream's Nyquist frequency.
pub fn filter_spec(
    src: &ScenarioSource,
    f: &FilterFile,
    field: &str,
    rate_hz: f64,
    band_hz: Option<f64>,
) -> anyhow::Result<Option<LowPassSpec>> {
    let words = LowPassWords {
        kind: f.kind.kind(),
        order: *f.order.get_ref(),
        cutoff_hz: f.cutoff_hz.as_ref().map(|c| c.get_ref().0),
    };
    let span = f.cutoff_hz.as_ref().map_or(0..0, |c| c.span());
    words
        .spec(band_hz.unwrap_or(DEFAULT_CUTOFF_HZ), rate_hz)
        .map_err(|e| src.error(span, &format!("{field}.cutoff_hz"), e))
}

/// An RMS meter's settings.
pub fn meter_settings(m: &MeterFile) -> MeterSettings {
    MeterSettings {
        detector: m.detector.into(),
        tau_s: m.tau_s.0,
        ac_coupling_hz: m.ac_coupling_hz.get_ref().0,
    }
}
