//! The analyser's one way in: the user's words for it (band, block, window, averages,
//! overlap, sampling, and the ADC's resolution, range and dither) on a stream of a given
//! rate become a checked set-up (analyser, ADC and alias truth built once, as they will
//! run), or a typed error naming the setting at fault. The scenario reader, the live
//! panel, the sweeps, `testrig analyse` and Python's `analyse` all come through here:
//! each front end only parses its own words into [`AnalyserWords`].

use instruments::{
    Adc, AdcSettings, AliasTruth, Analyser, AnalyserSettings, Averaging, InstrumentError, Sampling,
    Spectrum, Window,
};

use crate::vocabulary::limits::{LimitError, check_averages, check_block};

/// The analyser's settings a user chooses, by name in their own words: a scenario's
/// `analyser.*` keys, the panel's fields, `analyse`'s flags.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnalyserSetting {
    /// The block size N.
    Block,
    /// The top of the band (Hz).
    FmaxHz,
    /// The number of averages.
    Averages,
    /// The overlap of successive blocks (%).
    OverlapPct,
    /// The ADC's resolution (bits) and range.
    Adc,
}

/// Why an analyser cannot run as asked.
#[derive(Debug, thiserror::Error)]
pub enum AnalyserSetupError {
    /// The band's top is not a frequency above 0.
    #[error("the top of the band, a frequency > 0 Hz")]
    Band {
        /// The band asked for (Hz).
        fmax_hz: f64,
    },
    /// The averages are out of range.
    #[error("{0}")]
    Averages(LimitError),
    /// The overlap is not a fraction in [0, 1).
    #[error("must lie in [0, 100)")]
    Overlap {
        /// The overlap asked for (%).
        pct: f64,
    },
    /// The block is larger than the rig allows.
    #[error("{0}")]
    Block(LimitError),
    /// The analyser refuses its settings (block size, band).
    #[error("{0}")]
    Analyser(InstrumentError),
    /// The ADC would sample faster than the stream it reads.
    #[error("needs an ADC rate of {adc_hz} Hz, above the stream rate {stream_hz} Hz")]
    AdcAboveStream {
        /// The ADC's rate the band needs (Hz).
        adc_hz: f64,
        /// The stream's rate (Hz).
        stream_hz: f64,
    },
    /// The ADC refuses its settings (bits, range).
    #[error("{0}")]
    Adc(InstrumentError),
    /// The alias truth cannot follow this ADC on this stream.
    #[error("{0}")]
    Truth(InstrumentError),
}

impl AnalyserSetupError {
    /// The setting at fault.
    pub fn setting(&self) -> AnalyserSetting {
        match self {
            Self::Averages(_) => AnalyserSetting::Averages,
            Self::Overlap { .. } => AnalyserSetting::OverlapPct,
            Self::Analyser(_) | Self::Block(_) => AnalyserSetting::Block,
            Self::Band { .. } | Self::AdcAboveStream { .. } | Self::Truth(_) => {
                AnalyserSetting::FmaxHz
            }
            Self::Adc(_) => AnalyserSetting::Adc,
        }
    }
}

/// The ADC as a user sets it; its ratio to the stream follows from the analyser's band.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdcChoice {
    /// Resolution (bits).
    pub bits: u32,
    /// ± full scale, in the unit of the sampled signal.
    pub range_v: f64,
    /// Seed of the TPDF dither (`None`: no dither).
    pub dither_seed: Option<u64>,
}

/// A checked analyser on a stream: its settings, the ADC's, and the three working parts
/// built from them.
pub struct AnalyserSetup {
    /// The analyser's settings.
    pub settings: AnalyserSettings,
    /// The ADC's settings (its ratio from the stream rate).
    pub adc_settings: AdcSettings,
    /// The analyser.
    pub analyser: Analyser,
    /// The ADC.
    pub adc: Adc,
    /// Which displayed lines are aliases, from the analogue signal.
    pub truth: AliasTruth,
}

/// The analyser and its ADC in a user's words, before any check.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnalyserWords {
    /// Top of the band (Hz).
    pub fmax_hz: f64,
    /// Block size N (ADC samples).
    pub block: usize,
    /// Window.
    pub window: Window,
    /// Number of linear averages.
    pub averages: usize,
    /// Overlap of successive blocks, as a share of a block in [0, 1) (a front end that
    /// takes per cent divides by 100 once).
    pub overlap: f64,
    /// How the ADC's rate follows the band.
    pub sampling: Sampling,
    /// The ADC.
    pub adc: AdcChoice,
}

impl AnalyserWords {
    /// The words of settings in effect (to change one of them and check again).
    pub fn of(settings: &AnalyserSettings, adc: AdcChoice) -> Self {
        Self {
            fmax_hz: settings.fmax_hz,
            block: settings.block,
            window: settings.window,
            averages: settings.averages,
            overlap: settings.overlap,
            sampling: settings.sampling,
            adc,
        }
    }

    /// The analyser's settings these words ask for: a power spectrum, linearly averaged
    /// (the thesis's keyboard program), unchecked.
    fn settings(&self) -> AnalyserSettings {
        AnalyserSettings {
            block: self.block,
            fmax_hz: self.fmax_hz,
            sampling: self.sampling,
            window: self.window,
            spectrum: Spectrum::Power,
            averaging: Averaging::Linear,
            averages: self.averages,
            overlap: self.overlap,
        }
    }

    /// Checks the words on a stream at `stream_hz` and builds what runs them.
    pub fn set_up(&self, stream_hz: f64) -> Result<AnalyserSetup, AnalyserSetupError> {
        if !(self.fmax_hz.is_finite() && self.fmax_hz > 0.0) {
            return Err(AnalyserSetupError::Band {
                fmax_hz: self.fmax_hz,
            });
        }
        set_up_analyser(self.settings(), self.adc, stream_hz)
    }
}

/// Checks `settings` and `adc` on a stream at `stream_hz` and builds what runs them.
fn set_up_analyser(
    settings: AnalyserSettings,
    adc: AdcChoice,
    stream_hz: f64,
) -> Result<AnalyserSetup, AnalyserSetupError> {
    check_averages(settings.averages).map_err(AnalyserSetupError::Averages)?;
    check_block(settings.block).map_err(AnalyserSetupError::Block)?;
    if !(0.0..1.0).contains(&settings.overlap) {
        return Err(AnalyserSetupError::Overlap {
            pct: 100.0 * settings.overlap,
        });
    }
    let analyser = Analyser::new(settings).map_err(AnalyserSetupError::Analyser)?;
    let ratio = stream_hz / settings.sample_rate_hz();
    if ratio < 1.0 {
        return Err(AnalyserSetupError::AdcAboveStream {
            adc_hz: settings.sample_rate_hz(),
            stream_hz,
        });
    }
    let adc_settings = AdcSettings {
        ratio,
        bits: adc.bits,
        range_v: adc.range_v,
        dither_seed: adc.dither_seed,
    };
    let built_adc = Adc::new(adc_settings).map_err(AnalyserSetupError::Adc)?;
    let truth = AliasTruth::new(settings.block, ratio, stream_hz, settings.window)
        .map_err(AnalyserSetupError::Truth)?;
    Ok(AnalyserSetup {
        settings,
        adc_settings,
        analyser,
        adc: built_adc,
        truth,
    })
}

impl AdcChoice {
    /// The choice behind ADC settings (their ratio left out).
    pub fn of(adc: &AdcSettings) -> Self {
        Self {
            bits: adc.bits,
            range_v: adc.range_v,
            dither_seed: adc.dither_seed,
        }
    }
}
