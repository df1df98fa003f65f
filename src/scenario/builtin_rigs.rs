//! Rig files built into the binary, by a preset's name: where a preset's plant is a rig
//! file's (`basmaji-1983`, the thesis's own numbers, runs as its file does:
//! `tests/rig_file_1983.rs`), commands that take rig files take the preset's name too.
//! The other presets hold what only the thesis's five-inertia plant has (residual drag
//! as a torque, joint damping, the thesis's contact-law variants, spacing errors), and
//! are refused with why.

use super::source::ScenarioSource;

/// Each built-in rig: the preset it stands for and its file's text.
const BUILT_IN: [(&str, &str, &str); 1] = [(
    "basmaji-1983",
    "scenarios/rigs/basmaji-1983.toml",
    include_str!("../../scenarios/rigs/basmaji-1983.toml"),
)];

/// The rig file of preset `name`, as a source named after the file it was built from.
pub fn preset_rig_source(name: &str) -> anyhow::Result<ScenarioSource> {
    if let Some((_, path, text)) = BUILT_IN.iter().find(|(n, _, _)| *n == name) {
        return Ok(ScenarioSource {
            path: format!("{path} (built in as --preset {name})").into(),
            text: (*text).to_string(),
        });
    }
    let as_files: Vec<&str> = BUILT_IN.iter().map(|(n, _, _)| *n).collect();
    if rig::PRESET_NAMES.contains(&name) {
        anyhow::bail!(
            "--preset {name}: its plant holds what only the thesis's five-inertia plant has (see `testrig params --preset {name}`), not a rig file's; presets as rig files: {}; or write a rig file (docs/rig-files.md)",
            as_files.join(", ")
        );
    }
    anyhow::bail!(
        "--preset {name}: no such preset; presets as rig files: {}",
        as_files.join(", ")
    )
}
