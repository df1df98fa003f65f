//! The campaign as the lab ran it (`case.sequence = "up-and-down"`): one rig per load
//! stepping its speed up and back down, each point from the state the one before left,
//! judged as physics.

mod common;

use std::path::Path;

use common::{csv_rows, folder, number, sets, testrig};

/// Runs the shipped campaign `name` into `out` with `--set` for each of `items`.
fn campaign(name: &str, out: &Path, items: &[&str]) {
    let file = format!("{}/scenarios/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    let mut args = vec!["sweep", &file, "--out", out.to_str().expect("utf-8")];
    args.extend(sets(items, &[]));
    let output = testrig(&args);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// Issue 26: the campaign as the lab ran it. At one load the speed steps up through the
/// grid and back down on one rig, each point settling from the state the one before it
/// left: the first point is a start from rest (the same numbers as the static campaign's
/// case), and coming back down to 600 rev/min the rig keeps a motion of another size
/// than going up (the thesis's rig at 2.712 N m: 1.5 against 5.0 N m AC RMS, settled 30 s).
#[test]
fn the_lab_run_steps_up_and_back_down_on_one_rig_and_finds_coexisting_motions() {
    let dir = folder("lab-run");
    // The campaign's own 60 s settled and 30 s measured. Which of the two motions the run
    // down keeps after the chaotic 700 and 800 rev/min is decided at rounding
    // (`docs/physics.md`): with single steps in recorded windows it kept the small one
    // here and this test settled 30 s and measured 10 s; with a recorded period taken
    // in one product (`rig/src/stride.rs`) it keeps the large one at the campaign's own
    // times, and at 30 s and 15 s, 40 s and 10 s, 20 s and 10 s (not at 30 s and 10 s).
    let common = [
        "grid.rpm=[600, 700, 800]",
        "grid.load_nm=[2.712]",
        "rig.preset=\"basmaji-1983\"",
    ];
    let lab = dir.join("lab");
    let mut items = common.to_vec();
    items.push("case.sequence=\"up-and-down\"");
    campaign("thesis-campaign", &lab, &items);
    let rest = dir.join("rest");
    campaign("thesis-campaign", &rest, &common);
    let rows = csv_rows(&lab.join("cases.csv"));
    let walk: Vec<(String, String)> = rows
        .iter()
        .map(|r| (r["rpm"].clone(), r["direction"].clone()))
        .collect();
    let expected = [
        ("600", "up"),
        ("700", "up"),
        ("800", "up"),
        ("700", "down"),
        ("600", "down"),
    ];
    assert_eq!(
        walk,
        expected.map(|(r, d)| (r.to_string(), d.to_string())),
        "the speeds up, then down from the one below the top"
    );
    let static_600 = csv_rows(&rest.join("cases.csv"))
        .into_iter()
        .find(|r| r["rpm"] == "600")
        .expect("600 rev/min from rest");
    for column in [
        "torque_ac_rms_nm",
        "motion",
        "impacts_per_rev",
        "spread_1rev",
    ] {
        assert_eq!(rows[0][column], static_600[column], "{column}");
    }
    let (up, down) = (
        number(&rows[0], "torque_ac_rms_nm"),
        number(&rows[4], "torque_ac_rms_nm"),
    );
    assert!(
        down > 2.0 * up,
        "600 rev/min: {up} N m going up, {down} N m coming down"
    );
    let report = std::fs::read_to_string(lab.join("report.md")).expect("report.md");
    let hysteresis = report
        .lines()
        .find(|l| l.starts_with("- Hysteresis"))
        .expect("a hysteresis line");
    assert!(
        hysteresis.contains("600 rev/min, 2.712 N m"),
        "{hysteresis}"
    );
    assert!(lab.join("bifurcation-2.712_N_m.png").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// Issue 26: the rig chosen by its motion (`basmaji-1983-drive` now, the shipped lab campaign)
/// at 2.712 N m, shortened: period 1 at 500 rev/min, period 2 with the half-order line
/// far over the broadband floor at 1200 and 1500 rev/min, going up and coming down, as
/// the thesis saw (Figs 4.34-4.39). The judge reads the true output-shaft torque.
#[test]
fn the_lab_campaign_on_the_rig_preset_moves_as_the_thesis_saw_at_2712_nm() {
    let dir = folder("lab-rig");
    let out = dir.join("out");
    campaign(
        "thesis-campaign-lab",
        &out,
        &[
            "grid.rpm=[500, 1200, 1500]",
            "grid.load_nm=[2.712]",
            "case.settle_s=60",
            "case.measure_s=20",
            "case.repeats=0",
        ],
    );
    // The lab's score counts a point the thesis's motion is reached at by any approach:
    // never fewer than any one approach's, never more than the points.
    let report = std::fs::read_to_string(out.join("report.md")).expect("report");
    let hits = |label: &str| -> (usize, usize) {
        let line = report
            .lines()
            .find(|l| l.starts_with(label))
            .unwrap_or_else(|| panic!("no line {label}"));
        let numbers: Vec<usize> = line
            .split("**")
            .nth(1)
            .expect("bold")
            .split(' ')
            .filter_map(|w| w.parse().ok())
            .collect();
        (numbers[0], numbers[1])
    };
    let (lab, points) = hits("- The lab's score");
    for direction in ["- up:", "- down:", "- rest:"] {
        assert!(
            hits(direction).0 <= lab,
            "{direction} against the lab's {lab}"
        );
    }
    assert!(lab <= points && points == 3, "{lab} of {points}");
    let rows = csv_rows(&out.join("cases.csv"));
    let seen: Vec<(&str, &str, &str)> = rows
        .iter()
        .map(|r| {
            (
                r["rpm"].as_str(),
                r["direction"].as_str(),
                r["motion"].as_str(),
            )
        })
        .collect();
    assert_eq!(
        seen,
        [
            ("500", "up", "period-1"),
            ("1200", "up", "period-2"),
            ("1500", "up", "period-2"),
            ("1200", "down", "period-2"),
            ("500", "down", "period-1"),
            ("500", "rest", "period-1"),
            ("1200", "rest", "period-2"),
            ("1500", "rest", "period-2"),
        ]
    );
    for row in &rows {
        assert_eq!(row["physics_match"], "true", "{row:?}");
        if row["motion"] == "period-2" {
            assert!(number(row, "half_order_floor_db") >= 20.0, "{row:?}");
            assert!(number(row, "spread_2rev") < 0.05, "{row:?}");
        }
    }
    let report = std::fs::read_to_string(out.join("report.md")).expect("report.md");
    assert!(report.contains("- up: **3 of 3 decided points"), "{report}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Issue 26, item 3: the report says where the motor cannot hold the set speed. At
/// 5.424 N m the rig preset's 0.6 N m of drag leaves the 2 hp motor (7.12 N m) its
/// margin: every point held. With a bearing drag of 0.01 N m s/rad on each of the five
/// bodies at 2.712 N m the motor holds 600 rev/min (6.45 N m needed) but not 900
/// (8.02 N m): its speed sags to where its limit meets the load and the drags,
/// (7.12 − 2.712 − 0.6)/(5 × 0.01) rad/s = 727 rev/min, and the report names the point.
#[test]
fn the_report_names_the_points_where_the_motor_cannot_hold_the_set_speed() {
    let dir = folder("lab-motor");
    let holding = |out: &Path| {
        std::fs::read_to_string(out.join("report.md"))
            .expect("report.md")
            .lines()
            .find(|l| l.starts_with("- The motor holds the set speed"))
            .expect("a line on the motor")
            .to_string()
    };
    let held = dir.join("held");
    campaign(
        "thesis-campaign-lab",
        &held,
        &[
            "grid.rpm=[600, 900]",
            "grid.load_nm=[5.424]",
            "case.settle_s=20",
            "case.measure_s=10",
            "case.repeats=0",
        ],
    );
    assert!(
        holding(&held).ends_with("at every point."),
        "{}",
        holding(&held)
    );
    for row in csv_rows(&held.join("cases.csv")) {
        assert!(number(&row, "speed_offset_rpm").abs() < 1.0, "{row:?}");
    }
    let sagged = dir.join("sagged");
    campaign(
        "thesis-campaign-lab",
        &sagged,
        &[
            "grid.rpm=[600, 900]",
            "grid.load_nm=[2.712]",
            "case.settle_s=60",
            "case.measure_s=10",
            "case.repeats=0",
            "rig.set.bearing_drag_nms_per_rad=0.01",
        ],
    );
    let line = holding(&sagged);
    assert!(
        line.contains("not at 2 points")
            && line.contains("900 rev/min, 2.712 N m, up")
            && line.contains("900 rev/min, 2.712 N m, rest"),
        "{line}"
    );
    let p = rig::preset("basmaji-1983-drive").expect("preset");
    let balance_rad_s = (p.motor_torque_limit_nm() - 2.712 - p.brake_drag_nm) / (5.0 * 0.01);
    let expected_rpm = balance_rad_s * 30.0 / std::f64::consts::PI - 900.0;
    for row in csv_rows(&sagged.join("cases.csv")) {
        let offset = number(&row, "speed_offset_rpm");
        if row["rpm"] == "900" {
            assert!(
                (offset - expected_rpm).abs() < 0.05 * expected_rpm.abs(),
                "900 rev/min: {offset} rev/min off, the balance {expected_rpm}"
            );
        } else {
            assert!(offset.abs() < 1.0, "{row:?}");
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Issue 34, item 2: every motion a point can hold. At 1500 rev/min and 5.424 N m the
/// rig run up and the rig started from rest settle to period 2; knocked on the driven
/// gear (a seeded kick of 2-20 % of the speed) and settled again it keeps another
/// motion, period 1 with a smaller torque. The report lists both with the approaches
/// that reached them, the knocks are reproducible, and the diagram is drawn.
#[test]
fn a_knocked_repeat_finds_a_motion_the_run_up_does_not() {
    let dir = folder("lab-knock");
    let items = ["grid.rpm=[1500]", "grid.load_nm=[5.424]", "case.repeats=2"];
    let (first, second) = (dir.join("first"), dir.join("second"));
    campaign("thesis-campaign-lab", &first, &items);
    campaign("thesis-campaign-lab", &second, &items);
    let rows = csv_rows(&first.join("cases.csv"));
    let seen: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r["direction"].as_str(), r["motion"].as_str()))
        .collect();
    assert_eq!(
        seen,
        [
            ("up", "period-2"),
            ("rest", "period-2"),
            ("repeat", "period-1"),
            ("repeat", "period-1")
        ]
    );
    let omega = 1500.0 * std::f64::consts::PI / 30.0;
    for row in &rows {
        let kick = number(row, "kick_rad_s").abs();
        if row["direction"] == "repeat" {
            assert!((0.02 * omega..=0.2 * omega).contains(&kick), "{row:?}");
            assert!(
                number(row, "torque_ac_rms_nm") < 0.8 * number(&rows[1], "torque_ac_rms_nm"),
                "another motion, not the same one: {row:?}"
            );
        } else {
            assert_eq!(kick, 0.0, "{row:?}");
        }
    }
    let report = std::fs::read_to_string(first.join("report.md")).expect("report.md");
    let line = report
        .lines()
        .find(|l| l.starts_with("- Coexisting motions"))
        .expect("a coexisting-motions line");
    assert!(
        line.contains("1500 rev/min, 5.424 N m: period-2 (up, rest), period-1 (repeat ×2)"),
        "{line}"
    );
    assert_eq!(
        std::fs::read(first.join("cases.csv")).expect("csv"),
        std::fs::read(second.join("cases.csv")).expect("csv"),
        "the same seed knocks the same way"
    );
    assert!(first.join("bifurcation-5.424_N_m.png").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// Issue 34: knocked repeats are refused beyond 8 a point, and on the up-and-down run
/// (whose points are never started on their own), each naming the file's line and field.
#[test]
fn repeats_beyond_eight_or_on_the_run_up_and_down_are_refused_at_their_line() {
    let dir = folder("repeats");
    let file = dir.join("repeats.toml");
    let out = dir.join("out");
    for (case, says) in [
        ("repeats = 9", "at most 8"),
        (
            "sequence = \"up-and-down\"\nrepeats = 1",
            "give sequence = \"static\" or \"every-approach\"",
        ),
    ] {
        let text = format!(
            "name = \"repeats\"\n[grid]\nrpm = [600]\nload_nm = [1.0]\n[case]\nsettle_s = 1\nmeasure_s = 3\n{case}\n[analyser]\nfmax_hz = 5\nblock = 16\n"
        );
        std::fs::write(&file, &text).expect("sweep file");
        let done = testrig(&[
            "sweep",
            file.to_str().expect("utf-8"),
            "--out",
            out.to_str().expect("utf-8"),
        ]);
        let stderr = String::from_utf8_lossy(&done.stderr);
        let line = text
            .lines()
            .position(|l| l.starts_with("repeats"))
            .expect("line")
            + 1;
        assert_eq!(done.status.code(), Some(1), "{stderr}");
        assert!(
            stderr.contains(&format!("repeats.toml:{line}:"))
                && stderr.contains("case.repeats")
                && stderr.contains(says),
            "{stderr}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
