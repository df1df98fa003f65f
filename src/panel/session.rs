//! A live session written as a scenario (`session.toml`): the scenario as run, its length,
//! seed and live ceiling set to what the session had, and every accepted command at the
//! virtual time it took effect, so that `testrig run session.toml --pace max` does it again.

use anyhow::Context;
use rig::LiveCeiling;
use serde::Serialize;

use crate::scenario::apply_override;
use crate::vocabulary::command::TimedCommand;

/// What a session ran.
#[derive(Clone, Debug)]
pub struct Session<'a> {
    /// The scenario text as run (after `--set` edits).
    pub scenario_text: &'a str,
    /// Simulated length at the end (s).
    pub duration_s: f64,
    /// Base seed.
    pub seed: u64,
    /// The live ceiling the plant was built for.
    pub ceiling: LiveCeiling,
    /// The accepted commands, in the order they took effect.
    pub commands: &'a [TimedCommand],
}

#[derive(Serialize)]
struct Commands<'a> {
    command: &'a [TimedCommand],
}

impl Session<'_> {
    /// The session as scenario text.
    pub fn to_toml(&self) -> anyhow::Result<String> {
        let mut text = self.scenario_text.to_string();
        for item in [
            format!("duration_s={}", self.duration_s),
            format!("seed={}", self.seed),
            format!("live.max_speed_rpm={}", self.ceiling.speed_rpm),
            format!(
                "live.max_oscillating_load_hz={}",
                self.ceiling.oscillating_load_hz
            ),
        ] {
            text = apply_override(&text, &item)?;
        }
        let commands = toml::to_string(&Commands {
            command: self.commands,
        })
        .context("writing the session's commands as TOML")?;
        text.push_str("\n# The session's commands, at the virtual time each took effect.\n");
        text.push_str(&commands);
        Ok(text)
    }
}
