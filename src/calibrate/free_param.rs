//! A free parameter: its range, mapped to the search's unit interval.

use rig::{RigError, RigParams};

/// How a coordinate in [0, 1] maps to the parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum FreeRange {
    /// min + x (max − min).
    Linear {
        /// Lower bound.
        min: f64,
        /// Upper bound.
        max: f64,
    },
    /// min (max/min)^x, both > 0.
    Log {
        /// Lower bound.
        min: f64,
        /// Upper bound.
        max: f64,
    },
    /// One of the listed values, the interval cut in equal parts.
    Choice(Vec<String>),
}

/// One free parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeParam {
    /// Its `testrig params` name.
    pub name: String,
    /// Its range.
    pub range: FreeRange,
}

impl FreeParam {
    /// The value at coordinate `x` ∈ [0, 1], as `rig::set_param` takes it.
    pub fn value_text(&self, x: f64) -> String {
        let x = x.clamp(0.0, 1.0);
        match &self.range {
            FreeRange::Linear { min, max } => format!("{}", min + x * (max - min)),
            FreeRange::Log { min, max } => format!("{}", min * (max / min).powf(x)),
            FreeRange::Choice(values) => {
                let i = ((x * values.len() as f64) as usize).min(values.len() - 1);
                values[i].clone()
            }
        }
    }

    /// The coordinate of the value `params` holds, if it lies in the range.
    pub fn coordinate_of(&self, params: &RigParams) -> Option<f64> {
        let spec = rig::param_spec(&self.name).ok()?;
        let text = spec.value(params);
        match &self.range {
            FreeRange::Linear { min, max } => {
                let v: f64 = text.parse().ok()?;
                (v >= *min && v <= *max).then(|| (v - min) / (max - min))
            }
            FreeRange::Log { min, max } => {
                let v: f64 = text.parse().ok()?;
                (v >= *min && v <= *max).then(|| (v / min).ln() / (max / min).ln())
            }
            FreeRange::Choice(values) => {
                let i = values.iter().position(|c| *c == text)?;
                Some((i as f64 + 0.5) / values.len() as f64)
            }
        }
    }
}

/// `base` with every free parameter set at its coordinate in `x`, checked.
pub fn params_at(base: &RigParams, free: &[FreeParam], x: &[f64]) -> Result<RigParams, RigError> {
    let mut params = base.clone();
    for (p, &xi) in free.iter().zip(x) {
        rig::set_param(&mut params, &p.name, &p.value_text(xi))?;
    }
    params.validate()?;
    Ok(params)
}
