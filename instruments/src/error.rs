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
