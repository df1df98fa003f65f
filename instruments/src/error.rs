//! Errors of the instrument blocks: settings out of range.

/// A setting an instrument cannot take.
#[derive(Debug, thiserror::Error)]
pub enum InstrumentError {
    /// A setting outside its range.
    #[error("{instrument}: `{setting}` = {value}: {allowed}")]
    Setting {
        /// Which instrument.
        instrument: &'static str,
        /// Which setting.
        setting: &'static str,
        /// The value given.
        value: String,
        /// What is allowed.
        allowed: String,
    },
    /// A keyboard program line that cannot be read or run.
    #[error(
        "keyboard program line {line}: `{text}` (commands: LABEL n, CLEAR BLOCK b, ANALOG IN CHANNEL c BLOCK b, FOURIER TRANSFORM, POWER SPECTRUM, COUNT LOOP LABEL n TIMES k, DIVIDE BLOCK b BY k, LOG, DISPLAY, END)"
    )]
    Program {
        /// Line number (1-based).
        line: usize,
        /// The line, or what went wrong there.
        text: String,
    },
}

/// Checks that `value` is finite and > 0; the error names the instrument and setting.
pub fn require_positive(
    instrument: &'static str,
    setting: &'static str,
    value: f64,
) -> Result<(), InstrumentError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(InstrumentError::setting(
            instrument,
            setting,
            value,
            "must be finite and > 0",
        ))
    }
}

impl InstrumentError {
    /// A setting error.
    pub fn setting(
        instrument: &'static str,
        setting: &'static str,
        value: impl ToString,
        allowed: impl Into<String>,
    ) -> Self {
        Self::Setting {
            instrument,
            setting,
            value: value.to_string(),
            allowed: allowed.into(),
        }
    }
}
