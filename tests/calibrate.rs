//! `testrig calibrate`: a short search that improves its objective, resumes from its log,
//! writes a preset every command takes, and refuses bad files at their line.

mod common;

use std::path::{Path, PathBuf};

use common::{folder, testrig, testrig_ok};

/// Two points of the campaign's chain: unloaded at 1300 rev/min the thesis saw the half
/// order, at 500 rev/min not. The campaign's rig starts with an intermediate shaft six
/// times stiffer than the thesis's: its subharmonic band lies higher and 1300 rev/min
/// shows no line; the search may soften the shaft.
fn calibration(campaign: &Path, budget: usize) -> String {
    format!(
        r#"name = "short"
campaign = "{}"
seed = 11

[case]
settle_s = 8
measure_s = 6

[search]
budget = {budget}
population = 4
sigma = 0.3
approaches = ["from-below"]

[[target]]
rpm = [1300]
load_nm = [0.0]
half_order = "present"

[[target]]
rpm = [500]
load_nm = [0.0]
half_order = "absent"

[[free]]
name = "k34_intermediate_shaft_nm_per_rad"
min = 1000
max = 20000
scale = "log"
"#,
        campaign.display()
    )
}

/// The campaign with a stiff intermediate shaft (15 000 N m/rad): the search starts there.
fn campaign(dir: &Path) -> PathBuf {
    stiff_campaign(dir, "thesis-campaign.toml")
}

/// The shipped campaign `name` with a stiff intermediate shaft (15 000 N m/rad), written
/// into `dir`.
fn stiff_campaign(dir: &Path, name: &str) -> PathBuf {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenarios")
            .join(name),
    )
    .expect("campaign")
    .replace(
        "backlash_mm = 0.73",
        "backlash_mm = 0.73\nset = { k34_intermediate_shaft_nm_per_rad = 15000 }",
    )
    // The rig the searches below were written on (the lab campaign's preset before its
    // drive as built): stiff, it is not period 2 at 1300 rev/min unloaded.
    .replace(
        "preset = \"basmaji-1983-drive\"",
        "preset = \"basmaji-1983-rig\" #",
    );
    let path = dir.join("campaign.toml");
    std::fs::write(&path, text).expect("campaign");
    path
}

fn calibrate(file: &Path, out: &Path, extra: &[&str]) -> String {
    let mut args = vec![
        "calibrate",
        file.to_str().expect("utf-8"),
        "--out",
        out.to_str().expect("utf-8"),
    ];
    args.extend(extra);
    testrig_ok(&args)
}

/// The search's `result.json` in `out`.
fn result_of(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("result.json")).expect("result"))
        .expect("json")
}

/// The records of the search's log `evaluations.jsonl` in `out`.
fn log(out: &Path) -> Vec<serde_json::Value> {
    log_named(out, "evaluations.jsonl")
}

/// The records of the log `name` in `out`, one JSON line each.
fn log_named(out: &Path, name: &str) -> Vec<serde_json::Value> {
    std::fs::read_to_string(out.join(name))
        .expect("log")
        .lines()
        .map(|l| serde_json::from_str(l).expect("json line"))
        .collect()
}

#[test]
fn a_short_search_improves_its_objective_resumes_and_writes_a_usable_preset() {
    let dir = folder("calibrate-short");
    let file = dir.join("short.toml");
    std::fs::write(&file, calibration(&campaign(&dir), 12)).expect("file");
    let out = dir.join("out");
    calibrate(&file, &out, &["--budget", "8"]);
    let first = log(&out);
    let objective = |r: &serde_json::Value| r["objective"].as_f64().expect("objective");
    // The first candidate of the search lies near the stiff start: no line at 1300.
    let start = objective(&first[0]);
    let best = first.iter().map(objective).fold(f64::INFINITY, f64::min);
    assert!(
        start > 1.0,
        "the start already meets the targets: {start} dB"
    );
    assert!(best < 0.5 * start, "no improvement: {start} → {best} dB");
    // The search stops early only when every target is met with its margin.
    let met = best <= 0.0;
    assert!(
        first.len() == 8 || (met && first.len().is_multiple_of(4)),
        "{} evaluations",
        first.len()
    );
    // Resumed with a larger budget: the logged evaluations are reused as they were (and
    // nothing more runs if every target was met).
    let n = first.len();
    let more = if met { 0 } else { 4 };
    let said = calibrate(&file, &out, &["--resume"]);
    assert!(
        said.contains(&format!("{more} run now, {n} from the log")),
        "{said}"
    );
    let resumed = log(&out);
    assert_eq!(resumed.len(), n + more);
    assert_eq!(resumed[..n], first[..]);
    // The result and the preset file agree with the best of the log.
    let result = result_of(&out);
    let best = resumed.iter().map(objective).fold(f64::INFINITY, f64::min);
    assert_eq!(result["objective_db"].as_f64(), Some(best));
    let k34: f64 = result["values"]["k34_intermediate_shaft_nm_per_rad"]
        .as_str()
        .expect("value")
        .parse()
        .expect("number");
    let preset = out.join("preset.toml");
    let params = testrig(&[
        "params",
        "--preset",
        preset.to_str().expect("utf-8"),
        "--json",
    ]);
    assert!(
        params.status.success(),
        "{}",
        String::from_utf8_lossy(&params.stderr)
    );
    let listed: serde_json::Value = serde_json::from_slice(&params.stdout).expect("json");
    let listed_k34 = listed["parameters"]
        .as_array()
        .expect("list")
        .iter()
        .find(|p| p["name"] == "k34_intermediate_shaft_nm_per_rad")
        .and_then(|p| p["value"].as_str())
        .and_then(|v| v.parse::<f64>().ok())
        .expect("k34 listed");
    assert_eq!(listed_k34, k34);
    for name in ["report.md", "convergence.png", "convergence.svg"] {
        assert!(out.join(name).is_file(), "{name} missing");
    }
}

#[test]
fn bad_calibration_files_are_refused_at_their_line() {
    let dir = folder("calibrate-bad");
    let campaign = campaign(&dir);
    let good = calibration(&campaign, 4);
    for (from, to, field) in [
        (
            "name = \"k34_intermediate_shaft_nm_per_rad\"",
            "name = \"k34\"",
            "free",
        ),
        (
            "half_order = \"absent\"",
            "half_order = \"gone\"",
            "target.half_order",
        ),
        (
            "approaches = [\"from-below\"]",
            "approaches = [\"sideways\"]",
            "search.approaches",
        ),
        ("min = 1000", "min = -1", "free"),
        ("population = 4", "population = 2", "search.population"),
    ] {
        let file = dir.join("bad.toml");
        std::fs::write(&file, good.replace(from, to)).expect("file");
        let output = testrig(&[
            "calibrate",
            file.to_str().expect("utf-8"),
            "--out",
            dir.join("out").to_str().expect("utf-8"),
        ]);
        let said = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success(), "{to}: accepted");
        assert!(
            said.contains("bad.toml:") && said.contains(field),
            "{to}: {said}"
        );
        let line = said
            .split("bad.toml:")
            .nth(1)
            .and_then(|s| s.split(':').next())
            .and_then(|l| l.parse::<usize>().ok());
        assert!(line.is_some_and(|l| l > 1), "{to}: no line in {said}");
    }
}

#[test]
fn a_preset_file_is_refused_at_its_line() {
    let dir = folder("preset-bad");
    let file = dir.join("preset.toml");
    std::fs::write(
        &file,
        "base = \"basmaji-1983\"\n[set]\nbrake_drag_nm = -1\n",
    )
    .expect("file");
    let output = testrig(&["params", "--preset", file.to_str().expect("utf-8")]);
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success());
    assert!(
        said.contains("preset.toml:3:") && said.contains("set.brake_drag_nm"),
        "{said}"
    );
}

#[test]
fn a_natural_frequency_target_finds_the_shaft_stiffness_of_the_measured_fundamental() {
    // The measured fundamental, 13.33 Hz, as a natural frequency of the linear model: the
    // rig's first mode with its teeth in contact on the mesh spring (`testrig modes`'s
    // "teeth locked on the mesh spring K23", as every rig's modes are taken) is 13.33 Hz
    // with the intermediate shaft at 1469.7 N m/rad (found by bisection on `testrig
    // modes`; with the gear pair rigid, the thesis's App. C, it is 1449.5). The search has
    // only the linear model to evaluate. Its loss, one unit per tolerance outside it, is
    // capped at 80: a tolerance of 0.05 Hz leaves it a slope over ±4 Hz (at 0.005 Hz it
    // is flat beyond 0.4 Hz, and the search wanders), and holds K34 to 0.75 %.
    let dir = folder("calibrate-natural");
    let text = calibration(&campaign(&dir), 120)
        .split("[[target]]")
        .next()
        .expect("head")
        .to_string()
        + r#"
[[natural]]
mode = 1
hz = 13.33
tolerance_hz = 0.05

[[free]]
name = "k34_intermediate_shaft_nm_per_rad"
min = 500
max = 5000
scale = "log"
"#;
    let file = dir.join("natural.toml");
    std::fs::write(&file, text).expect("file");
    let out = dir.join("out");
    calibrate(&file, &out, &[]);
    let result = result_of(&out);
    assert_eq!(result["objective_db"].as_f64(), Some(0.0), "{result}");
    let k34: f64 = result["values"]["k34_intermediate_shaft_nm_per_rad"]
        .as_str()
        .and_then(|v| v.parse().ok())
        .expect("k34");
    assert!((k34 / 1469.7 - 1.0).abs() < 0.0075, "K34 = {k34}");
}

#[test]
fn a_cross_validated_search_scores_the_points_it_did_not_see() {
    let dir = folder("calibrate-halves");
    let file = dir.join("halves.toml");
    std::fs::write(&file, calibration(&campaign(&dir), 4)).expect("file");
    let out = dir.join("out");
    let said = calibrate(&file, &out, &["--train-half", "even"]);
    assert!(said.contains("held-out points"), "{said}");
    let result = result_of(&out);
    // Two points: the search sees the first (index 0), the second is held out.
    assert_eq!(result["training_score"][1], 1, "{result}");
    assert_eq!(result["held_out_score"][1], 1, "{result}");
    assert_eq!(result["score"][1], 2, "{result}");
}

#[test]
fn shards_search_independently_and_the_report_takes_the_best_of_all_logs() {
    let dir = folder("calibrate-shards");
    let file = dir.join("shards.toml");
    std::fs::write(&file, calibration(&campaign(&dir), 8)).expect("file");
    let out = dir.join("out");
    for shard in ["0/2", "1/2"] {
        calibrate(&file, &out, &["--shard", shard]);
    }
    let (a, b) = (
        log_named(&out, "evaluations-0-of-2.jsonl"),
        log_named(&out, "evaluations-1-of-2.jsonl"),
    );
    // Each stream has its own seed: the same start, different samples.
    assert!(!a.is_empty() && !b.is_empty());
    assert_ne!(a[0]["x"], b[0]["x"]);
    let result = result_of(&out);
    assert_eq!(
        result["evaluations"].as_u64(),
        Some((a.len() + b.len()) as u64)
    );
    let best = a
        .iter()
        .chain(&b)
        .filter_map(|r| r["objective"].as_f64())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(result["objective_db"].as_f64(), Some(best));
}

#[test]
fn each_file_given_to_the_wrong_command_is_refused_with_the_right_one() {
    let targets = format!(
        "{}/scenarios/thesis-targets.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let campaign = format!(
        "{}/scenarios/thesis-campaign.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let out = folder("calibrate-wrong").join("out");
    let out = out.to_str().expect("utf-8");
    for (args, right) in [
        (vec!["run", &targets, "--out", out], "testrig calibrate"),
        (vec!["sweep", &targets, "--out", out], "testrig calibrate"),
        (vec!["calibrate", &campaign, "--out", out], "testrig sweep"),
    ] {
        let output = testrig(&args);
        let said = String::from_utf8_lossy(&output.stderr);
        assert!(
            !output.status.success() && said.contains(right),
            "{args:?}: {said}"
        );
    }
}

/// Issue 26: the objective scored on the physics judge's motion (`objective = "motion"`).
/// On the lab campaign's rig with a stiff intermediate shaft, 1300 rev/min unloaded is not
/// period 2; a short search softens the shaft until it is, cleanly.
#[test]
fn a_search_on_the_judged_motion_finds_the_half_order_motion() {
    let dir = folder("calibrate-motion");
    let campaign = stiff_campaign(&dir, "thesis-campaign-lab.toml");
    let file = dir.join("motion.toml");
    let search = calibration(&campaign, 12)
        .replace("sigma = 0.3", "sigma = 0.3\nobjective = \"motion\"")
        .replace(
            "rpm = [500]\nload_nm = [0.0]",
            "rpm = [500]\nload_nm = [2.712]",
        );
    std::fs::write(&file, search).expect("file");
    let out = dir.join("out");
    calibrate(&file, &out, &["--budget", "8"]);
    let evaluations = log(&out);
    let objective = |r: &serde_json::Value| r["objective"].as_f64().expect("objective");
    let start = objective(&evaluations[0]);
    let best = evaluations
        .iter()
        .min_by(|a, b| objective(a).total_cmp(&objective(b)))
        .expect("evaluations");
    assert!(
        start > 10.0,
        "the stiff start already moves as expected: {start} dB"
    );
    assert!(
        objective(best) < 0.5 * start,
        "{start} → {} dB",
        objective(best)
    );
    let at_1300 = best["outcomes"]
        .as_array()
        .expect("outcomes")
        .iter()
        .find(|o| o["rpm"] == 1300.0)
        .expect("1300 rev/min");
    assert_eq!(at_1300["regimes"][0], "period-2", "{at_1300}");
    assert_eq!(at_1300["loss_db"], 0.0, "{at_1300}");
    std::fs::remove_dir_all(&dir).ok();
}
