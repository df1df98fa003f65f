//! Numbers a scenario file may hold, checked as they are read so that a bad value is
//! reported at its own line and column.

use serde::Deserialize;

use crate::vocabulary::limits::{check_load_nm, check_speed_rpm};

/// A finite number.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, PartialOrd)]
#[serde(try_from = "f64")]
pub struct Finite(pub f64);

/// A finite number ≥ 0.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, PartialOrd)]
#[serde(try_from = "f64")]
pub struct NonNegative(pub f64);

/// A finite number > 0.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, PartialOrd)]
#[serde(try_from = "f64")]
pub struct Positive(pub f64);

/// A brake load set point (N m): finite and ≥ 0, since an eddy-current brake only
/// resists the rotation (it cannot drive the rig).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, PartialOrd)]
#[serde(try_from = "f64")]
pub struct LoadNm(pub f64);

/// A motor speed set point in [0, 10 000] rev/min.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, PartialOrd)]
#[serde(try_from = "f64")]
pub struct SpeedRpm(pub f64);

impl TryFrom<f64> for Finite {
    type Error = String;
    fn try_from(value: f64) -> Result<Self, String> {
        if value.is_finite() {
            Ok(Self(value))
        } else {
            Err(format!("{value} is not allowed: a finite number is"))
        }
    }
}

impl TryFrom<f64> for NonNegative {
    type Error = String;
    fn try_from(value: f64) -> Result<Self, String> {
        if value.is_finite() && value >= 0.0 {
            Ok(Self(value))
        } else {
            Err(format!("{value} is not allowed: a finite number ≥ 0 is"))
        }
    }
}

impl TryFrom<f64> for Positive {
    type Error = String;
    fn try_from(value: f64) -> Result<Self, String> {
        if value.is_finite() && value > 0.0 {
            Ok(Self(value))
        } else {
            Err(format!("{value} is not allowed: a finite number > 0 is"))
        }
    }
}

impl TryFrom<f64> for LoadNm {
    type Error = String;
    fn try_from(value: f64) -> Result<Self, String> {
        check_load_nm(value).map(Self)
    }
}

impl TryFrom<f64> for SpeedRpm {
    type Error = String;
    fn try_from(value: f64) -> Result<Self, String> {
        check_speed_rpm(value).map(Self)
    }
}
