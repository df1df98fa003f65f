//! The lab's sequence on a rig file (issue 45): the every-approach sweep (up, down, from
//! rest, knocked) on the 1983 rig as a file against its preset, case by case; a case from
//! rest measured once the drive has run the rig up.

mod common;
mod rig_sweep_support;

use std::path::Path;

use common::{csv_rows, folder, number, rig_file, testrig_ok};
use rig_sweep_support::sweep_file;

/// The lab's every-approach sequence on `rig` (a `[rig]` table's lines) over the speeds
/// `rpm` (a TOML list) at `load_nm`, 30 s settled and 10 s measured, each point from rest
/// knocked `repeats` times, run in `dir`: its `cases.csv` rows and `report.md`.
fn lab_sweep(
    dir: &Path,
    rig: &str,
    rpm: &str,
    load_nm: f64,
    repeats: u32,
) -> (Vec<std::collections::HashMap<String, String>>, String) {
    std::fs::create_dir_all(dir).expect("folder");
    let body = format!(
        "[rig]\n{rig}\n[grid]\nrpm = {rpm}\nload_nm = [{load_nm}]\n[case]\nsettle_s = 30\nmeasure_s = 10\nsequence = \"every-approach\"\nrepeats = {repeats}\n"
    );
    let sweep = sweep_file(dir, &body);
    let out = dir.join("out");
    testrig_ok(&["sweep", &sweep, "--out", out.to_str().expect("utf-8")]);
    let report = std::fs::read_to_string(out.join("report.md")).expect("report.md");
    (csv_rows(&out.join("cases.csv")), report)
}

/// Issue 45: the lab's every-approach sequence (up, down, from rest) and its knocked
/// repeats take a rig file as they take a preset. The 1983 rig as a file and as its
/// preset, stepped 600 → 700 → 800 rev/min and back at 2.712 N m, each point also from
/// rest and knocked once: the same walk of cases; the period-1 cases' torque (up, rest,
/// knocked at 600 rev/min) the preset's to 1e-4 (the file and the preset's conversion,
/// equal to 1e-12 in every number, agree to 1e-6 where the motion does not depend on its
/// history to rounding: 700 and 800 rev/min are chaotic
/// going up and down); from rest and knocked, the same motion at every point (its AC
/// RMS to 1e-3) and the same judged motion at 600 and 800 rev/min. At 700 rev/min from
/// rest (settled 30 s after a 14 s run-up) the rig lies at the edge of period-6 locking:
/// its six-revolution spread (3.1 % on the preset, 5.9 % on the file, measured) lies
/// about the judge's 5 %, and the two rigs, 2e-5 apart in AC RMS, fall on either side
/// (period 6 and quasi-periodic; knocked, both period 6). And at 600
/// rev/min the coexisting motions the preset's lab run finds (`lab_run.rs`): coming down
/// the rig keeps a motion more than twice as large as going up, and the report's
/// hysteresis line names the point, as a preset's report does.
#[test]
fn the_lab_sequence_and_knocked_repeats_run_a_rig_file_as_its_preset() {
    let dir = folder("sweep-rig-lab");
    let run = |name: &str, rig: &str| lab_sweep(&dir.join(name), rig, "[600, 700, 800]", 2.712, 1);
    let (preset, preset_report) = run("preset", "preset = \"basmaji-1983\"");
    let (file, report) = run("file", &format!("file = \"{}\"", rig_file("basmaji-1983")));
    // The file reproduces the 1983 rig: held against the thesis as its preset is, the
    // same thesis's motion at every case and the same scores of the run up and down.
    for (f, p) in file.iter().zip(&preset) {
        assert_eq!(f["thesis_motion"], p["thesis_motion"], "{f:?}");
        assert!(!f["thesis_motion"].is_empty(), "{f:?}");
    }
    let score = |report: &str, approach: &str| -> String {
        report
            .lines()
            .find(|l| l.starts_with(&format!("- {approach}: ")))
            .unwrap_or_else(|| panic!("no {approach} score in {report}"))
            .to_string()
    };
    for approach in ["up", "down"] {
        assert_eq!(score(&report, approach), score(&preset_report, approach));
    }
    let walk = |rows: &[std::collections::HashMap<String, String>]| -> Vec<(String, String)> {
        rows.iter()
            .map(|r| (r["rpm"].clone(), r["direction"].clone()))
            .collect()
    };
    assert_eq!(walk(&file), walk(&preset));
    assert_eq!(file.len(), 11, "5 up and down, 3 from rest, 3 knocked");
    for (f, p) in file.iter().zip(&preset) {
        let own_start = ["rest", "repeat"].contains(&f["direction"].as_str());
        if own_start {
            let (a, b) = (number(f, "torque_ac_rms_nm"), number(p, "torque_ac_rms_nm"));
            assert!((a - b).abs() <= 1e-3 * b, "{f:?}\n{p:?}");
            let locking_edge = f["rpm"] == "700" && f["direction"] == "rest";
            if !locking_edge {
                assert_eq!(f["motion"], p["motion"], "{f:?}\n{p:?}");
            }
        }
        if f["motion"] == "period-1" && p["motion"] == "period-1" {
            let (a, b) = (number(f, "torque_ac_rms_nm"), number(p, "torque_ac_rms_nm"));
            assert!((a - b).abs() <= 1e-4 * b, "{f:?}\n{p:?}");
        }
    }
    let at_600 = |direction: &str| {
        let row = file
            .iter()
            .find(|r| r["rpm"] == "600" && r["direction"] == direction)
            .expect("a case at 600 rev/min");
        number(row, "torque_ac_rms_nm")
    };
    let (up, down) = (at_600("up"), at_600("down"));
    assert!(
        down > 2.0 * up,
        "600 rev/min: {up} N m going up, {down} N m coming down"
    );
    // The rig file's report names it, as a preset's does.
    let hysteresis = report
        .lines()
        .find(|l| l.starts_with("- Hysteresis"))
        .expect("a hysteresis line");
    assert!(
        hysteresis.contains("600 rev/min, 2.712 N m: period-1"),
        "{hysteresis}"
    );
    assert!(report.contains("- The motor holds the set speed (mean within 1 %): at every point."));
    std::fs::remove_dir_all(&dir).ok();
}

/// A case from rest is measured once the drive has run the rig up, on a rig file as on a
/// preset. The 1983 rig with its drive as built (`basmaji-1983-drive`: a 10.68 N m limit
/// against 5.424 N m and 4 N m of drag) takes 140 s to reach 2000 rev/min from rest, more
/// than the case's 30 s of settling: the rig file's case from rest holds the set speed
/// (within 1 rev/min; measured mid-run-up it lagged 934 rev/min) and moves as the
/// preset's does, as do its run up and down.
#[test]
fn a_rig_files_case_from_rest_waits_for_its_run_up_as_a_presets_does() {
    let dir = folder("sweep-rig-run-up");
    let run = |name: &str, rig: &str| lab_sweep(&dir.join(name), rig, "[1600, 2000]", 5.424, 0).0;
    let preset = run(
        "preset",
        "preset = \"basmaji-1983-drive\"\nbacklash_mm = 0.73",
    );
    let file = run(
        "file",
        &format!("file = \"{}\"", rig_file("basmaji-1983-drive")),
    );
    assert_eq!(file.len(), 5, "2 up, 1 down, 2 from rest");
    for (f, p) in file.iter().zip(&preset) {
        assert_eq!((&f["rpm"], &f["direction"]), (&p["rpm"], &p["direction"]));
        let offset = number(f, "speed_offset_rpm");
        assert!(offset.abs() < 1.0, "{f:?}");
        assert_eq!(f["motion"], p["motion"], "{f:?}\n{p:?}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
