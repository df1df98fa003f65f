//! Rig files built into the binary, by a preset's name: every preset is a rig file
//! (`scenarios/rigs/NAME.toml`, running as the preset does: `tests/rig_file_1983.rs`), so
//! commands that take rig files take a preset's name too.

use super::source::ScenarioSource;

/// Each built-in rig: the preset it stands for, its file and the file's text.
const BUILT_IN: [(&str, &str, &str); 5] = [
    (
        "basmaji-1983",
        "scenarios/rigs/basmaji-1983.toml",
        include_str!("../../scenarios/rigs/basmaji-1983.toml"),
    ),
    (
        "basmaji-1983-calibrated",
        "scenarios/rigs/basmaji-1983-calibrated.toml",
        include_str!("../../scenarios/rigs/basmaji-1983-calibrated.toml"),
    ),
    (
        "basmaji-1983-drive",
        "scenarios/rigs/basmaji-1983-drive.toml",
        include_str!("../../scenarios/rigs/basmaji-1983-drive.toml"),
    ),
    (
        "basmaji-1983-hand",
        "scenarios/rigs/basmaji-1983-hand.toml",
        include_str!("../../scenarios/rigs/basmaji-1983-hand.toml"),
    ),
    (
        "basmaji-1983-rig",
        "scenarios/rigs/basmaji-1983-rig.toml",
        include_str!("../../scenarios/rigs/basmaji-1983-rig.toml"),
    ),
];

/// The rig file of preset `name`, as a source named after the file it was built from.
pub fn preset_rig_source(name: &str) -> anyhow::Result<ScenarioSource> {
    if let Some((_, path, text)) = BUILT_IN.iter().find(|(n, _, _)| *n == name) {
        return Ok(ScenarioSource {
            path: format!("{path} (built in as --preset {name})").into(),
            text: (*text).to_string(),
        });
    }
    let known: Vec<&str> = BUILT_IN.iter().map(|(n, _, _)| *n).collect();
    anyhow::bail!(
        "--preset {name}: no such preset; the presets are {}{}",
        known.join(", "),
        rig::nearest::did_you_mean(name, known.iter().copied())
    )
}

#[cfg(test)]
mod tests {
    use super::{BUILT_IN, preset_rig_source};

    #[test]
    fn every_preset_is_built_in_as_its_rig_file() {
        let built_in: Vec<&str> = BUILT_IN.iter().map(|(n, _, _)| *n).collect();
        assert_eq!(built_in, rig::PRESET_NAMES);
        for (name, path, _) in BUILT_IN {
            let source = preset_rig_source(name).expect("built in");
            let file = std::fs::read_to_string(path).expect("the file it was built from");
            assert_eq!(source.text, file, "{name}");
        }
        let refused = preset_rig_source("basmaji-1983-rgi").expect_err("no such preset");
        assert!(
            refused
                .to_string()
                .contains("did you mean `basmaji-1983-rig`"),
            "{refused}"
        );
    }
}
