//! A gear's condition indicators as a row: what a sweep case and a run's judged point
//! carry (`sweep`'s `cases.csv` and `labels.csv`, `testrig run`'s `readings.csv` and
//! manifest), with their column names in one place.

use serde::{Deserialize, Serialize};

/// A gear's condition indicators over a window (Lebold et al. 2000;
/// `instruments::condition_indicators`, `chain::GearCondition`): a sweep case's, a run's
/// point's. A number the signal leaves undefined (a constant torque's FM4) is NaN, null in
/// JSON.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct GearIndicators {
    /// Revolutions averaged.
    pub revolutions: usize,
    /// FM0.
    #[serde(deserialize_with = "null_as_nan")]
    pub fm0: f64,
    /// FM4.
    #[serde(deserialize_with = "null_as_nan")]
    pub fm4: f64,
    /// M6A.
    #[serde(deserialize_with = "null_as_nan")]
    pub m6a: f64,
    /// M8A.
    #[serde(deserialize_with = "null_as_nan")]
    pub m8a: f64,
    /// NA4.
    #[serde(deserialize_with = "null_as_nan")]
    pub na4: f64,
    /// First sidebands of the first mesh harmonic over the average's RMS.
    #[serde(deserialize_with = "null_as_nan")]
    pub sideband_level: f64,
    /// RMS of the average about its mean (N m).
    #[serde(deserialize_with = "null_as_nan")]
    pub rms_nm: f64,
    /// Crest factor of the average.
    #[serde(deserialize_with = "null_as_nan")]
    pub crest_factor: f64,
    /// Kurtosis of the average.
    #[serde(deserialize_with = "null_as_nan")]
    pub kurtosis: f64,
    /// RMS of the residual signal (N m).
    #[serde(deserialize_with = "null_as_nan")]
    pub residual_rms_nm: f64,
}

impl GearIndicators {
    /// The column names, in the order of [`GearIndicators::values`].
    pub const COLUMNS: [&'static str; 10] = [
        "fm0",
        "fm4",
        "m6a",
        "m8a",
        "na4",
        "sideband_level",
        "crest_factor",
        "kurtosis",
        "residual_rms_nm",
        "revolutions_averaged",
    ];

    /// The values in the order of [`GearIndicators::COLUMNS`] (the count of revolutions
    /// last).
    pub fn values(&self) -> [f64; 10] {
        [
            self.fm0,
            self.fm4,
            self.m6a,
            self.m8a,
            self.na4,
            self.sideband_level,
            self.crest_factor,
            self.kurtosis,
            self.residual_rms_nm,
            self.revolutions as f64,
        ]
    }
}

/// Reads a number that JSON holds as null (serde_json writes NaN so) back as NaN.
pub(crate) fn null_as_nan<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Option::<f64>::deserialize(d).map(|v| v.unwrap_or(f64::NAN))
}
