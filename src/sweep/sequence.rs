//! How a sweep reaches its points ([`Sequence`]: each on its own, or as the lab ran them,
//! up and down) and which way the speed came to a case ([`Direction`]).

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
    /// plant of its own from the static load. Where motions coexist, each approach
    /// shows the one it reaches.
    EveryApproach,
}

/// Which way the speed came to a case.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Direction {
    /// Started at its own set points.
    #[default]
    Static,
    /// Stepped up from the speed below.
    Up,
    /// Stepped down from the speed above.
    Down,
}

impl std::fmt::Display for Direction {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Static => "static",
            Self::Up => "up",
            Self::Down => "down",
        })
    }
}
