//! The documents' snippets run as written: a newcomer copies them. The rig-file page's
//! scenario runs through `testrig run`; the SCPI page's pyvisa lines run against the
//! README's `testrig panel --scpi 127.0.0.1:5025` in `tests/docs/scpi_snippet.py`.

mod common;

use std::path::Path;

use common::{folder, testrig};

/// The first fenced block of `language` after the heading line `heading` in `doc`.
fn snippet(doc: &str, heading: &str, language: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(doc);
    let text = std::fs::read_to_string(&path).expect("the document");
    let after = text
        .split_once(&format!("\n{heading}\n"))
        .unwrap_or_else(|| panic!("{doc} has no heading `{heading}`"))
        .1;
    let body = after
        .split_once(&format!("```{language}\n"))
        .unwrap_or_else(|| panic!("no ```{language} block after `{heading}` in {doc}"))
        .1;
    body.split_once("```")
        .expect("the block is closed")
        .0
        .to_string()
}

#[test]
fn the_rig_file_pages_scenario_runs_as_written() {
    let toml = snippet("docs/rig-files.md", "### In a scenario", "toml");
    // As the page says, the rig file lies relative to the scenario: `rigs/` beside it.
    let dir = folder("doc-rig-scenario");
    std::fs::create_dir(dir.path().join("rigs")).expect("rigs/");
    std::fs::copy(
        common::rig_file("two-stage"),
        dir.path().join("rigs/two-stage.toml"),
    )
    .expect("the rig file");
    let scenario = dir.path().join("snippet.toml");
    std::fs::write(&scenario, toml).expect("scenario");
    let out = dir.path().join("out");
    let run = testrig(&[
        "run",
        scenario.to_str().expect("path"),
        "--pace",
        "max",
        "--set",
        "duration_s=4",
        "--out",
        out.to_str().expect("path"),
    ]);
    assert!(
        run.status.success(),
        "the snippet as written: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let manifest: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(out.join("manifest.json")).expect("manifest"),
    )
    .expect("json");
    assert_eq!(manifest["ending"], "completed", "{manifest}");
    assert!(
        out.join("recording.wav").is_file(),
        "[record] writes a WAV by default"
    );
}

#[test]
#[ignore = "needs Python modules (python3 -m pip install -r tests/requirements.txt) and 40 s at pace 1; run by .ci/run"]
fn the_scpi_pages_pyvisa_lines_run_as_written() {
    common::run_python_check(
        "docs/scpi_snippet.py",
        "doc-scpi-snippet",
        &["pyvisa", "numpy"],
    );
}
