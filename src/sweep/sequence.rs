//! How a sweep reaches its points ([`Sequence`]: each on its own, or as the lab ran them,
//! up and down, from rest and knocked) and how a case came to its point ([`Direction`]).

use serde::{Deserialize, Serialize};

/// How the grid's points are reached.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Sequence {
    /// Each point on a plant of its own, started at its set points from the static load.
    #[default]
    Static,
    /// At each load (and parameter variant) one plant runs the speeds up in grid order,
    /// then back down: every point starts from the state the one before it left.
    UpAndDown,
    /// Every way the lab reached a point: the run up, the run down, and each point on a
    /// plant of its own from rest, then knocked and measured again `case.repeats` times
    /// (a lab's doubtful repeat). Where motions coexist, each approach shows the one it
    /// reaches.
    EveryApproach,
}

/// Which way the speed came to a case.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Direction {
    /// Started at its own set points from the static load.
    #[default]
    Static,
    /// Started at standstill, the knob at the set speed; settled once the drive has run
    /// the rig up.
    Rest,
    /// The case before it (from rest, or the repeat before) continued: the driven gear
    /// knocked by the case's seeded kick, settled again, measured again.
    Repeat,
    /// Stepped up from the speed below.
    Up,
    /// Stepped down from the speed above.
    Down,
}

impl Direction {
    /// Whether a case so reached starts on a plant of its own (from the static load or
    /// from rest).
    pub fn is_own_start(self) -> bool {
        matches!(self, Self::Static | Self::Rest)
    }
}

impl std::fmt::Display for Direction {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Static => "static",
            Self::Rest => "rest",
            Self::Repeat => "repeat",
            Self::Up => "up",
            Self::Down => "down",
        })
    }
}
