//! What a written spectrum says of how it was measured (`# key: value` lines of its CSV),
//! the same for the run's analyser and for `testrig analyse`: each source gives its own
//! opening lines (scenario and measurement, or file and section), then the analyser's.

use instruments::{AnalyserSettings, Spectrum};

use crate::recording::{ALIAS_COLUMN, Metadata};

/// How a spectrum was measured, beyond the analyser's settings.
pub struct SpectrumFacts<'a> {
    /// The analyser's settings.
    pub settings: &'a AnalyserSettings,
    /// The window's equivalent noise bandwidth (Hz).
    pub enbw_hz: f64,
    /// Spectra averaged into the display.
    pub averages_done: usize,
    /// The anti-alias filter before the ADC, described.
    pub filter: String,
    /// The ADC, described (bits, range, overloads).
    pub adc: String,
    /// Unit of the sampled signal (the power is in unit²).
    pub unit: &'a str,
}

/// `head` (the source's own lines) followed by the analyser's: sampling, block, band,
/// window, averages, overlap, filter, ADC, scaling and the alias column.
pub fn spectrum_metadata(mut head: Metadata, facts: SpectrumFacts) -> Metadata {
    let s = facts.settings;
    head.extend([
        ("fs_hz", s.sample_rate_hz().to_string()),
        ("n", s.block.to_string()),
        ("fmax_hz", s.fmax_hz.to_string()),
        ("sampling", format!("{:?}", s.sampling)),
        ("window", s.window.name().to_string()),
        ("enbw_hz", facts.enbw_hz.to_string()),
        (
            "averages",
            format!(
                "{} of {} requested, linear (sum then divide)",
                facts.averages_done, s.averages
            ),
        ),
        ("overlap_pct", (100.0 * s.overlap).to_string()),
        ("filter", facts.filter),
        ("adc", facts.adc),
        (
            "scaling",
            Spectrum::Power.scaling().replace("unit", facts.unit),
        ),
        ("alias_of_hz", ALIAS_COLUMN.to_string()),
    ]);
    head
}
