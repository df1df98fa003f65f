//! Labels tell the truth (issue 24): what a plot title, a CSV header and the manifest say
//! of the settings is what the run used, `--set` included.

mod common;

use common::{run_ok, scenario};

/// `--set analyser.window=flattop` on the aliasing study (a uniform window in its file):
/// the plot's title, the spectrum's metadata and the manifest's analyser all say flat-top.
#[test]
fn a_set_override_reaches_the_titles_the_headers_and_the_manifest() {
    let (out, manifest) = run_ok(
        "labels-flattop",
        &scenario("aliasing-windowing"),
        &["--duration", "12", "--set", "analyser.window=flattop"],
    );
    let svg = std::fs::read_to_string(out.join("spectrum-01.svg")).expect("svg");
    assert!(
        svg.contains("flattop window"),
        "the title does not say flattop"
    );
    assert!(!svg.contains("uniform"), "the title still says uniform");
    let csv = std::fs::read_to_string(out.join("spectrum-01.csv")).expect("csv");
    assert!(csv.lines().any(|l| l == "# window: flattop"), "{csv:.600}");
    assert!(
        csv.lines().any(|l| l.starts_with("# filter: none")),
        "{csv:.600}"
    );
    assert_eq!(manifest["analyser"]["window"], "flattop", "{manifest}");
    std::fs::remove_dir_all(&out).ok();
}
