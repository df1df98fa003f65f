//! A free parameter: its range, mapped to the search's unit interval.

use crate::sweep::CaseRig;

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
    /// Its `testrig params` name, or a rig file's path (`testrig params --rig`).
    pub name: String,
    /// Its range.
    pub range: FreeRange,
}

impl FreeParam {
    /// The value at coordinate `x` ∈ [0, 1]: a number, or one of the choices (a number
    /// or a switch where it reads as one, else a word).
    pub fn value(&self, x: f64) -> toml::Value {
        let x = x.clamp(0.0, 1.0);
        match &self.range {
            FreeRange::Linear { min, max } => toml::Value::Float(min + x * (max - min)),
            FreeRange::Log { min, max } => toml::Value::Float(min * (max / min).powf(x)),
            FreeRange::Choice(values) => {
                let i = ((x * values.len() as f64) as usize).min(values.len() - 1);
                let text = &values[i];
                text.parse::<f64>()
                    .map(toml::Value::Float)
                    .or_else(|_| text.parse::<bool>().map(toml::Value::Boolean))
                    .unwrap_or_else(|_| toml::Value::String(text.clone()))
            }
        }
    }

    /// The value at coordinate `x` as text (a number as Rust prints it, a choice as
    /// written).
    pub fn value_text(&self, x: f64) -> String {
        match self.value(x) {
            toml::Value::String(text) => text,
            toml::Value::Float(v) => format!("{v}"),
            other => other.to_string(),
        }
    }

    /// The coordinate of the value `rig` holds, if it lies in the range.
    pub fn coordinate_of(&self, rig: &CaseRig) -> Option<f64> {
        let text = rig.value_text(&self.name)?;
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
pub fn params_at(base: &CaseRig, free: &[FreeParam], x: &[f64]) -> anyhow::Result<CaseRig> {
    let mut rig = base.clone();
    for (p, &xi) in free.iter().zip(x) {
        rig.set(&p.name, &p.value(xi))
            .map_err(|e| anyhow::anyhow!("{}: {e:#}", p.name))?;
    }
    Ok(rig)
}
