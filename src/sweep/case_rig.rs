//! The rig a case runs on: a preset's parameters (`rig::RigParams`, set by the thesis's
//! names) or a rig file's rig (`rig::RigTopology`, set by path), each with its grid
//! values set; either runs as a rig on the plant of any rig (`rig::NetworkPlant`), a
//! preset's as `rig::preset_rig` converts it.

use std::borrow::Cow;

use rig::{RigParams, RigTopology};

use crate::scenario::rig_overrides::set_rig_value;
use crate::scenario::values::param_value;
use crate::vocabulary::limits::check_load_within;

/// A case's rig.
#[derive(Clone, Debug)]
pub enum CaseRig {
    /// A preset's parameters, its grid values set by the thesis's names.
    Preset {
        /// The rig's name (its built-in file's, or a preset file's stem).
        name: String,
        /// What the rig is, as its file says.
        description: String,
        /// The parameters.
        params: Box<RigParams>,
    },
    /// A rig file's rig.
    File(Box<RigTopology>),
}

impl CaseRig {
    /// The preset's parameters; a rig file's rig is refused, `what` saying what needs them.
    pub fn preset(&self, what: &str) -> anyhow::Result<&RigParams> {
        match self {
            Self::Preset { params, .. } => Ok(params),
            Self::File(rig) => anyhow::bail!(
                "{what} runs on a preset's parameters; rig `{}` is a rig file's",
                rig.name
            ),
        }
    }

    /// The rig the case runs: a rig file's as it is, a preset's converted from its
    /// parameters (`rig::preset_rig`).
    pub fn topology(&self) -> Cow<'_, RigTopology> {
        match self {
            Self::Preset {
                name,
                description,
                params,
            } => Cow::Owned(rig::preset_rig(name, description, params)),
            Self::File(rig) => Cow::Borrowed(rig),
        }
    }

    /// Sets `name` (a preset's parameter, or a rig file's path) to `value`, checked with
    /// the whole rig.
    pub fn set(&mut self, name: &str, value: &toml::Value) -> anyhow::Result<()> {
        match self {
            Self::Preset { params, .. } => {
                let value = param_value(value).map_err(anyhow::Error::msg)?;
                rig::set_param_value(params, name, value)?;
                params.validate()?;
                Ok(self.topology().check()?)
            }
            Self::File(rig) => {
                set_rig_value(rig, name, value)?;
                Ok(rig.check()?)
            }
        }
    }

    /// The value at `name` as text (a preset's parameter, a rig file's number by path or
    /// a fault's kind); `None` where the rig has no such value.
    pub fn value_text(&self, name: &str) -> Option<String> {
        match self {
            Self::Preset { params, .. } => rig::param_spec(name).ok().map(|s| s.value(params)),
            Self::File(rig) => rig
                .fields()
                .into_iter()
                .find(|f| f.path == name)
                .map(|f| f.value.to_string())
                .or_else(|| rig.word(name)),
        }
    }

    /// Whether the rig can hold `load_nm` (the one load check of every rig); the refusal
    /// says why.
    pub fn check_load(&self, load_nm: f64) -> Result<(), String> {
        check_load_within(load_nm, &self.topology()).map_err(|e| e.to_string())
    }

    /// The rig's undamped natural frequencies (Hz) with its meshes in contact, rigid-body
    /// mode left out (`testrig modes`' first table).
    pub fn natural_hz(&self) -> Vec<f64> {
        self.topology().natural_frequencies_hz()
    }
}
