//! Numbers a scenario file may hold, checked as they are read so that a bad value is
//! reported at its own line and column.

use serde::Deserialize;

use crate::vocabulary::limits::{LimitError, check_load_nm, check_speed_rpm};

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

/// A number a file's field does not allow; each says what is allowed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NumberError {
    /// Not finite.
    #[error("{0} is not allowed: a finite number is")]
    Infinite(f64),
    /// Negative or not finite.
    #[error("{0} is not allowed: a finite number ≥ 0 is")]
    Negative(f64),
    /// Zero, negative or not finite.
    #[error("{0} is not allowed: a finite number > 0 is")]
    NotAboveZero(f64),
}

impl TryFrom<f64> for Finite {
    type Error = NumberError;
    fn try_from(value: f64) -> Result<Self, NumberError> {
        if value.is_finite() {
            Ok(Self(value))
        } else {
            Err(NumberError::Infinite(value))
        }
    }
}

impl TryFrom<f64> for NonNegative {
    type Error = NumberError;
    fn try_from(value: f64) -> Result<Self, NumberError> {
        if value.is_finite() && value >= 0.0 {
            Ok(Self(value))
        } else {
            Err(NumberError::Negative(value))
        }
    }
}

impl TryFrom<f64> for Positive {
    type Error = NumberError;
    fn try_from(value: f64) -> Result<Self, NumberError> {
        if value.is_finite() && value > 0.0 {
            Ok(Self(value))
        } else {
            Err(NumberError::NotAboveZero(value))
        }
    }
}

impl TryFrom<f64> for LoadNm {
    type Error = LimitError;
    fn try_from(value: f64) -> Result<Self, LimitError> {
        check_load_nm(value).map(Self)
    }
}

impl TryFrom<f64> for SpeedRpm {
    type Error = LimitError;
    fn try_from(value: f64) -> Result<Self, LimitError> {
        check_speed_rpm(value).map(Self)
    }
}

/// A rig parameter's value as a TOML file holds it (a number, a switch or a name),
/// handed to `rig::set_param_value` as it is, without a trip through text; arrays and
/// tables are refused.
pub fn param_value(value: &toml::Value) -> Result<rig::ParamValue<'_>, String> {
    match value {
        toml::Value::Float(x) => Ok(rig::ParamValue::Number(*x)),
        toml::Value::Integer(n) => Ok(rig::ParamValue::Number(*n as f64)),
        toml::Value::Boolean(b) => Ok(rig::ParamValue::Switch(*b)),
        toml::Value::String(s) => Ok(rig::ParamValue::Text(s)),
        other => Err(format!(
            "{other} is not one value (a number, true/false or a name)"
        )),
    }
}
