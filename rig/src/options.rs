//! The mesh model's switchable options: contact law and number of tooth pairs.

use serde::{Deserialize, Serialize};

/// How the mesh torque behaves while the teeth overlap.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ContactLaw {
    /// Thesis eq. (5.6) as written: spring and damper act whenever |d| ≥ B, so the
    /// damper can pull the teeth together while they separate.
    #[default]
    Thesis,
    /// The contact torque is clipped at zero (it never pulls), as Modelica's
    /// `ElastoBacklash` does: contact ends when spring + damper torque reaches zero.
    NoPull,
}

/// How many tooth pairs share the load while the teeth are in contact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MeshPairs {
    /// One pair always (the thesis: contact ratio taken as 1).
    #[default]
    Single,
    /// One or two pairs alternating within each tooth period as the contact ratio
    /// computed from the gear geometry says (thesis recommendation 4).
    Alternating,
}

impl ContactLaw {
    /// Every accepted spelling, for error messages.
    pub const NAMES: &'static str = "thesis, no-pull";

    /// Parses `thesis` or `no-pull`.
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "thesis" => Some(Self::Thesis),
            "no-pull" => Some(Self::NoPull),
            _ => None,
        }
    }

    /// The name `parse` accepts.
    pub fn name(self) -> &'static str {
        match self {
            Self::Thesis => "thesis",
            Self::NoPull => "no-pull",
        }
    }
}

impl MeshPairs {
    /// Every accepted spelling, for error messages.
    pub const NAMES: &'static str = "single, alternating";

    /// Parses `single` or `alternating`.
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "single" => Some(Self::Single),
            "alternating" => Some(Self::Alternating),
            _ => None,
        }
    }

    /// The name `parse` accepts.
    pub fn name(self) -> &'static str {
        match self {
            Self::Single => "single",
            Self::Alternating => "alternating",
        }
    }
}
