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
        let mut text = session_head(self.scenario_text, self.seed, self.ceiling)?;
        text = apply_override(&text, &format!("duration_s={}", self.duration_s))?;
        text.push_str(&commands_toml(self.commands)?);
        Ok(text)
    }
}

/// What `session.toml` holds while the session runs: the scenario as run with its seed and
/// live ceiling, then each command appended as it takes effect ([`commands_toml`]). A
/// session killed before its end leaves this file, replayable with `--duration`.
pub fn session_head(
    scenario_text: &str,
    seed: u64,
    ceiling: LiveCeiling,
) -> anyhow::Result<String> {
    let mut text = scenario_text.to_string();
    for item in [
        format!("seed={seed}"),
        format!("live.max_speed_rpm={}", ceiling.speed_rpm),
        format!(
            "live.max_oscillating_load_hz={}",
            ceiling.oscillating_load_hz
        ),
    ] {
        text = apply_override(&text, &item)?;
    }
    text.push_str("\n# The session's commands, at the virtual time each took effect.\n");
    Ok(text)
}

/// `commands` as `[[command]]` tables, to follow [`session_head`].
pub fn commands_toml(commands: &[TimedCommand]) -> anyhow::Result<String> {
    toml::to_string(&Commands { command: commands })
        .context("writing the session's commands as TOML")
}
