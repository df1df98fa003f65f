//! The named choices a scenario or sweep file makes (bridge arrangement, filter, meter
//! detector, scope slope, analyser window and sampling, recording formats, WAV format) as typed enums: serde
//! refuses anything else at the value's line with the allowed names, and each maps onto
//! the instrument's own type.

use instruments::{BridgeArrangement, Detector, FilterKind, Sampling, Slope, Window};
use serde::{Deserialize, Serialize};

/// `chain.gauges.arrangement`.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum ArrangementChoice {
    /// Four active gauges (the thesis's).
    #[default]
    Full,
    /// Two active gauges.
    Half,
    /// One active gauge.
    Quarter,
}

impl From<ArrangementChoice> for BridgeArrangement {
    fn from(choice: ArrangementChoice) -> Self {
        match choice {
            ArrangementChoice::Full => Self::Full,
            ArrangementChoice::Half => Self::Half,
            ArrangementChoice::Quarter => Self::Quarter,
        }
    }
}

/// `chain.filter.kind`.
#[derive(Clone, Copy, Debug, Default, Deserialize, Serialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum FilterChoice {
    /// No anti-alias filter.
    None,
    /// Butterworth (the default).
    #[default]
    Butterworth,
    /// Bessel.
    Bessel,
}

impl FilterChoice {
    /// The filter's kind; `None` for no filter.
    pub fn kind(self) -> Option<FilterKind> {
        match self {
            Self::None => None,
            Self::Butterworth => Some(FilterKind::Butterworth),
            Self::Bessel => Some(FilterKind::Bessel),
        }
    }
}

/// `chain.meter.detector`.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum DetectorChoice {
    /// Average-responding, RMS-calibrated for sines (the HP 400E).
    #[default]
    Average,
    /// True RMS.
    TrueRms,
}

impl From<DetectorChoice> for Detector {
    fn from(choice: DetectorChoice) -> Self {
        match choice {
            DetectorChoice::Average => Self::AverageRmsCalibrated,
            DetectorChoice::TrueRms => Self::TrueRms,
        }
    }
}

/// `chain.scope.slope`.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum SlopeChoice {
    /// Trigger on a rising edge.
    #[default]
    Rising,
    /// Trigger on a falling edge.
    Falling,
}

impl From<SlopeChoice> for Slope {
    fn from(choice: SlopeChoice) -> Self {
        match choice {
            SlopeChoice::Rising => Self::Rising,
            SlopeChoice::Falling => Self::Falling,
        }
    }
}

/// `analyser.window`: any name [`Window::parse`] takes (`uniform`, `hanning`, `flattop`
/// and their aliases), so the file and `testrig analyse --window` share one list.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq, Eq)]
#[serde(try_from = "String", into = "String")]
pub struct WindowChoice(pub Window);

impl From<WindowChoice> for String {
    fn from(choice: WindowChoice) -> Self {
        choice.0.name().to_string()
    }
}

impl Default for WindowChoice {
    fn default() -> Self {
        Self(Window::Hanning)
    }
}

/// A named choice that is not one of those allowed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("`{text}` is not one of {allowed}")]
pub struct ChoiceError {
    /// What was written.
    pub text: String,
    /// The choices allowed, listed.
    pub allowed: &'static str,
}

impl TryFrom<String> for WindowChoice {
    type Error = ChoiceError;
    fn try_from(text: String) -> Result<Self, ChoiceError> {
        match Window::parse(&text) {
            Some(window) => Ok(Self(window)),
            None => Err(ChoiceError {
                text,
                allowed: Window::NAMES,
            }),
        }
    }
}

/// `analyser.sampling`: `thesis` (fs = 2 Fmax) or `2.56` (fs = 2.56 Fmax), the latter
/// also written as a number or as `modern`.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(try_from = "TextOrNumber")]
pub enum SamplingChoice {
    /// fs = 2 Fmax, N/2 lines.
    #[default]
    Thesis,
    /// fs = 2.56 Fmax, N/2.56 + 1 lines.
    Modern,
}

/// A choice written as text, or as a number standing for its text (`sampling = 2.56`).
#[derive(Deserialize)]
#[serde(untagged)]
enum TextOrNumber {
    Text(String),
    Number(f64),
}

impl TryFrom<TextOrNumber> for SamplingChoice {
    type Error = ChoiceError;
    fn try_from(value: TextOrNumber) -> Result<Self, ChoiceError> {
        let text = match value {
            TextOrNumber::Text(text) => text,
            TextOrNumber::Number(number) => number.to_string(),
        };
        Self::parse(&text).ok_or(ChoiceError {
            text,
            allowed: "thesis, 2.56",
        })
    }
}

impl SamplingChoice {
    /// `thesis`, `2.56` or `modern`, as the file and `testrig analyse --sampling` take them.
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "thesis" => Some(Self::Thesis),
            "2.56" | "modern" => Some(Self::Modern),
            _ => None,
        }
    }
}

impl From<SamplingChoice> for Sampling {
    fn from(choice: SamplingChoice) -> Self {
        match choice {
            SamplingChoice::Thesis => Self::Thesis,
            SamplingChoice::Modern => Self::Modern,
        }
    }
}

/// `record.wav_format`.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum WavFormatChoice {
    /// 32-bit float, the physical value itself.
    #[default]
    Float32,
    /// 24-bit integer at a full scale per signal.
    Int24,
}

impl From<WavFormatChoice> for WavFormat {
    fn from(choice: WavFormatChoice) -> Self {
        match choice {
            WavFormatChoice::Float32 => Self::Float32,
            WavFormatChoice::Int24 => Self::Int24,
        }
    }
}

/// An entry of `record.formats`.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum RecordFormatChoice {
    /// WAV with a JSON sidecar.
    Wav,
    /// CSV, a column per signal.
    Csv,
    /// UFF58 time histories.
    Uff58,
}

/// How WAV samples are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WavFormat {
    /// 32-bit IEEE float, sample = value / scale.
    Float32,
    /// 24-bit integer, full scale = scale.
    Int24,
}
