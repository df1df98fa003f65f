//! Rig files (`docs/rig-files.md`): the 1983 rig as a file gives the preset's natural
//! frequencies; rigs nobody tuned (a two-stage reduction, an FZG-type back-to-back loop)
//! give frequencies that are roots of det(K − ω²M) for K and M assembled here from the
//! file's numbers, independently of the application; bad files are refused at their
//! line, naming the field and what is allowed.

mod common;

use nalgebra::DMatrix;

use common::{folder, testrig};

fn rig_file(name: &str) -> String {
    format!("{}/scenarios/rigs/{name}.toml", env!("CARGO_MANIFEST_DIR"))
}

fn json_of(args: &[&str]) -> serde_json::Value {
    let out = testrig(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

fn numbers(value: &serde_json::Value) -> Vec<f64> {
    value
        .as_array()
        .expect("array")
        .iter()
        .map(|v| v.as_f64().expect("number"))
        .collect()
}

#[test]
fn the_1983_rig_file_has_the_presets_natural_frequencies() {
    let from_file = json_of(&["modes", "--rig", &rig_file("basmaji-1983"), "--json"]);
    let preset = json_of(&["modes", "--json"]);
    let (file_hz, preset_hz) = (
        numbers(&from_file["natural_hz"]),
        numbers(&preset["locked_mesh_hz"]),
    );
    assert_eq!(file_hz.len(), 4);
    for (a, b) in file_hz.iter().zip(&preset_hz) {
        assert!(
            (a / b - 1.0).abs() < 1e-4,
            "{file_hz:?} against {preset_hz:?}"
        );
    }
    // App. C's five-inertia rig with the teeth locked: 17.71 Hz fundamental, 1977 Hz mesh.
    assert!((file_hz[0] - 17.71).abs() < 0.01 && (file_hz[3] - 1976.6).abs() < 0.1);
}

/// K and M of a rig file, assembled from its TOML here: shafts k(θa − θb)², meshes
/// k(r_b1 θ1 + r_b2 θ2)² with r_b = m z cos α / 2.
fn matrices(path: &str) -> (DMatrix<f64>, DMatrix<f64>) {
    let text = std::fs::read_to_string(path).expect("rig file");
    let file: toml::Table = toml::from_str(&text).expect("TOML");
    let bodies = file["body"].as_array().expect("bodies");
    let index = |name: &toml::Value| {
        bodies
            .iter()
            .position(|b| b["name"] == *name)
            .expect("a body")
    };
    let n = bodies.len();
    let mass = DMatrix::from_fn(n, n, |r, c| {
        if r == c {
            bodies[r]["inertia_kgm2"].as_float().expect("inertia")
        } else {
            0.0
        }
    });
    let mut k = DMatrix::zeros(n, n);
    for shaft in file["shaft"].as_array().expect("shafts") {
        let between = shaft["between"].as_array().expect("between");
        let (a, b) = (index(&between[0]), index(&between[1]));
        let s = shaft["stiffness_nm_per_rad"].as_float().expect("stiffness");
        k[(a, a)] += s;
        k[(b, b)] += s;
        k[(a, b)] -= s;
        k[(b, a)] -= s;
    }
    for mesh in file["mesh"].as_array().expect("meshes") {
        let (a, b) = (index(&mesh["driver"]), index(&mesh["driven"]));
        let teeth = mesh["teeth"].as_array().expect("teeth");
        let module = mesh["module_m"].as_float().expect("module");
        let cos = mesh["pressure_angle_deg"]
            .as_float()
            .expect("angle")
            .to_radians()
            .cos();
        let radius = |z: &toml::Value| module * z.as_integer().expect("teeth") as f64 * cos / 2.0;
        let (ra, rb) = (radius(&teeth[0]), radius(&teeth[1]));
        let s = mesh["stiffness_n_per_m"].as_float().expect("stiffness");
        k[(a, a)] += s * ra * ra;
        k[(b, b)] += s * rb * rb;
        k[(a, b)] += s * ra * rb;
        k[(b, a)] += s * ra * rb;
    }
    (k, mass)
}

/// det(K − ω²M) at `hz`.
fn characteristic(k: &DMatrix<f64>, m: &DMatrix<f64>, hz: f64) -> f64 {
    let omega = std::f64::consts::TAU * hz;
    (k - m * (omega * omega)).determinant()
}

#[test]
fn rigs_nobody_tuned_have_the_roots_of_their_own_characteristic_equation() {
    for name in ["two-stage", "fzg-back-to-back"] {
        let path = rig_file(name);
        let modes = json_of(&["modes", "--rig", &path, "--json"]);
        let hz = numbers(&modes["natural_hz"]);
        let (k, m) = matrices(&path);
        // One rigid-body mode left out: a connected rig of n bodies has n − 1 others.
        assert_eq!(hz.len(), k.nrows() - 1, "{name}: {hz:?}");
        // Each reported frequency is a root: the determinant changes sign within 0.01 %.
        for &f in &hz {
            let (below, above) = (
                characteristic(&k, &m, f * (1.0 - 1e-4)),
                characteristic(&k, &m, f * (1.0 + 1e-4)),
            );
            assert!(
                below * above < 0.0,
                "{name}: {f} Hz is no root ({below}, {above})"
            );
        }
        // …and there is no other below the highest: between neighbours no sign change
        // is missed (the determinant's sign flips once per root).
        let mut sign = characteristic(&k, &m, hz[0] * 0.5).signum();
        let mut roots = 0;
        let top = hz[hz.len() - 1] * 1.5;
        let steps = 200_000;
        for i in 1..=steps {
            let f = top * i as f64 / steps as f64;
            let s = characteristic(&k, &m, f).signum();
            if f > hz[0] * 0.5 && s != sign {
                roots += 1;
                sign = s;
            }
        }
        assert_eq!(
            roots,
            hz.len(),
            "{name}: {roots} roots up to {top} Hz, {hz:?}"
        );
    }
}

/// Writes `text` as a rig file in `dir` and runs `modes --rig` on it: its stderr.
fn refused(dir: &std::path::Path, name: &str, text: &str) -> String {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).expect("written");
    let out = testrig(&["modes", "--rig", path.to_str().expect("utf-8")]);
    assert!(!out.status.success(), "{name} accepted");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!stderr.contains("panicked"), "{stderr}");
    stderr
}

#[test]
fn bad_rig_files_are_refused_at_their_line_naming_the_field_and_what_is_allowed() {
    let dir = folder("bad-rigs");
    let good = std::fs::read_to_string(rig_file("two-stage")).expect("rig");
    // (name, the line as written, the line as mangled, what the error must say); the
    // error's line is the mangled line's, where the file has one.
    let cases: Vec<(&str, &str, &str, Vec<&str>)> = vec![
        (
            "unknown-body",
            "between = [\"wheel1\", \"pinion2\"]",
            "between = [\"wheel1\", \"pinion9\"]",
            vec![
                "shaft `intermediate`.between",
                "no body `pinion9`",
                "`pinion2`",
            ],
        ),
        (
            "zero-inertia",
            "inertia_kgm2 = 0.012",
            "inertia_kgm2 = 0.0",
            vec![
                "body `wheel1`.inertia_kgm2",
                "must be a number > 0, between 1e-12 and 1e15",
            ],
        ),
        (
            "negative-stiffness",
            "stiffness_nm_per_rad = 5000.0",
            "stiffness_nm_per_rad = -5000.0",
            vec!["shaft `input`.stiffness_nm_per_rad", "> 0"],
        ),
        (
            "backlash-wider-than-a-tooth-gap",
            "backlash_mm = 0.2",
            "backlash_mm = 20.0",
            vec![
                "mesh `stage1`.backlash_mm",
                "half the circular pitch",
                "4.712 mm",
            ],
        ),
        (
            "gauge-on-no-shaft",
            "shaft = \"output\"",
            "shaft = \"outpt\"",
            vec!["gauge.shaft", "no shaft `outpt`"],
        ),
        (
            "teeth-missing",
            "teeth = [20, 60]",
            "teeth = [20]",
            vec![
                "mesh `stage1`.teeth",
                "the teeth of the driver and the driven gear",
            ],
        ),
        (
            "duplicate-name",
            "name = \"coupling\"",
            "name = \"motor\"",
            vec!["body.name", "`motor` names two bodys"],
        ),
        (
            "unknown-key",
            "module_m = 0.003",
            "modul_m = 0.003",
            vec!["unknown field `modul_m`", "module_m"],
        ),
    ];
    for (name, old, new, expected) in cases {
        let at = good.find(old).expect("the line is in the file");
        let line = good[..at].lines().count() + usize::from(good[..at].ends_with('\n'));
        let stderr = refused(&dir, name, &good.replacen(old, new, 1));
        let place = format!("{name}.toml:{line}:");
        assert!(stderr.contains(&place), "{name}: `{place}` not in {stderr}");
        for e in expected {
            assert!(stderr.contains(e), "{name}: `{e}` not in {stderr}");
        }
    }
    // A body joined to nothing (the brake's shaft moved onto another body).
    let stderr = refused(
        &dir,
        "connected-to-nothing",
        &good.replacen(
            "between = [\"flywheel\", \"brake\"]",
            "between = [\"flywheel\", \"wheel2\"]",
            1,
        ),
    );
    assert!(
        stderr.contains("body `brake`.name") && stderr.contains("connected to nothing"),
        "{stderr}"
    );
    // A back-to-back loop whose two gearboxes differ does not turn as one.
    let loop_rig = std::fs::read_to_string(rig_file("fzg-back-to-back")).expect("rig");
    let stderr = refused(
        &dir,
        "unequal-loop",
        &loop_rig.replacen("teeth = [24, 16]", "teeth = [25, 16]", 1),
    );
    // Which joint of the loop is named depends on the order the speeds were found in:
    // any of them closes the loop wrongly.
    assert!(
        stderr.contains("unequal-loop.toml:")
            && stderr.contains("ratios do not close")
            && stderr.contains("two gearboxes of equal ratio"),
        "{stderr}"
    );
    // Too many bodies, too many meshes.
    let mut many = String::from("name = \"many\"\n");
    for i in 0..33 {
        many.push_str(&format!("[[body]]\nname = \"b{i}\"\ninertia_kgm2 = 1.0\n"));
    }
    let stderr = refused(&dir, "too-many-bodies", &many);
    assert!(
        stderr.contains("33 bodies: a rig has 2 to 32 bodies"),
        "{stderr}"
    );
    let mut meshes = good.clone();
    for i in 0..3 {
        meshes.push_str(&format!(
            "[[mesh]]\nname = \"extra{i}\"\ndriver = \"pinion1\"\ndriven = \"wheel1\"\nteeth = [20, 60]\nmodule_m = 0.003\nbacklash_mm = 0.2\nstiffness_n_per_m = 2.8e8\n"
        ));
    }
    let stderr = refused(&dir, "too-many-meshes", &meshes);
    assert!(stderr.contains("5 meshes: a rig has at most 4"), "{stderr}");
}

#[test]
fn params_of_a_rig_file_list_every_field_by_path_and_the_speed_ratios() {
    let two = json_of(&["params", "--rig", &rig_file("two-stage"), "--json"]);
    let value = |rows: &serde_json::Value, name: &str| -> String {
        rows.as_array()
            .expect("rows")
            .iter()
            .find(|r| r["name"] == name)
            .unwrap_or_else(|| panic!("no {name}"))["value"]
            .as_str()
            .expect("text")
            .to_string()
    };
    assert_eq!(value(&two["fields"], "mesh.stage1.backlash_mm"), "0.2");
    assert_eq!(
        value(&two["fields"], "shaft.output.stiffness_nm_per_rad"),
        "60000"
    );
    // 20/60 then 18/54: the brake turns at 1/9 of the motor's speed, the same way.
    let brake: f64 = value(&two["derived"], "body.brake.speed_ratio")
        .parse()
        .expect("number");
    assert!((brake - 1.0 / 9.0).abs() < 1e-6, "{brake}");
    let fzg = json_of(&["params", "--rig", &rig_file("fzg-back-to-back"), "--json"]);
    let wheel: f64 = value(&fzg["derived"], "body.test_wheel.speed_ratio")
        .parse()
        .expect("number");
    assert!((wheel + 16.0 / 24.0).abs() < 1e-6, "{wheel}");
    assert_eq!(value(&fzg["fields"], "locked_torque.torque_nm"), "302");
}

#[test]
fn simulate_runs_a_rig_file_naming_its_columns_after_the_rig_and_sets_fields_by_path() {
    let out = folder("simulate-rig-file");
    let dir = out.path().join("run");
    let dir_text = dir.to_str().expect("path");
    let report = json_of(&[
        "simulate",
        "--rig",
        &rig_file("two-stage"),
        "--rpm",
        "1200",
        "--load",
        "45",
        "--settle",
        "1",
        "--duration",
        "0.5",
        "--out",
        dir_text,
        "--json",
    ]);
    // The load goes through both stages: 45 N m at the output, 15 and 5 N m before.
    let shaft = |name: &str| -> f64 {
        report["shafts"]
            .as_array()
            .expect("shafts")
            .iter()
            .find(|s| s["name"] == name)
            .unwrap_or_else(|| panic!("no shaft {name}"))["torque_mean_nm"]
            .as_f64()
            .expect("number")
    };
    assert!((shaft("output") - 45.0).abs() < 1e-3, "{report}");
    assert!((shaft("intermediate") - 15.0).abs() < 1e-3, "{report}");
    assert!((shaft("input") - 5.0).abs() < 1e-3, "{report}");
    let mut csv = csv::Reader::from_path(dir.join("signals.csv")).expect("signals.csv");
    let header: Vec<String> = csv
        .headers()
        .expect("header")
        .iter()
        .map(String::from)
        .collect();
    for column in [
        "time_s",
        "speed_motor_rpm",
        "speed_brake_rpm",
        "angle_wheel1_rad",
        "torque_output_nm",
        "contact_stage1",
        "force_stage2_n",
        "motor_torque_nm",
        "strain_output_ue",
    ] {
        assert!(header.iter().any(|h| h == column), "{column} in {header:?}");
    }
    let rows: Vec<csv::StringRecord> = csv.records().map(|r| r.expect("row")).collect();
    assert_eq!(rows.len(), 25_600, "0.5 s at 51.2 kHz");
    let at = |row: &csv::StringRecord, name: &str| -> f64 {
        let i = header.iter().position(|h| h == name).expect("column");
        row[i].parse().expect("number")
    };
    // 45 N m on the Ø40 mm steel shaft: 8 T / (π d³ G) = 22.4 µε.
    let strain = at(&rows[100], "strain_output_ue");
    let expected = 8.0 * 45.0 / (std::f64::consts::PI * 0.04_f64.powi(3) * 80.0e9) * 1e6;
    assert!(
        (strain / expected - 1.0).abs() < 1e-4,
        "{strain} µε against {expected}"
    );
    assert!((at(&rows[100], "speed_brake_rpm") - 1200.0 / 9.0).abs() < 1e-3);

    // --set by path: drag on the first wheel costs the motor c (1/3)² Ω more; a path
    // that does not exist, or a value the check refuses, is named.
    let dragged = json_of(&[
        "simulate",
        "--rig",
        &rig_file("two-stage"),
        "--rpm",
        "1200",
        "--load",
        "45",
        "--settle",
        "1",
        "--duration",
        "0.5",
        "--set",
        "body.wheel1.drag_nms_per_rad=0.1",
        "--json",
    ]);
    let motor = dragged["motor_torque_mean_nm"]
        .as_f64()
        .expect("motor torque");
    let expected = 45.0 / 9.0 + 0.1 / 9.0 * 1200.0 * std::f64::consts::PI / 30.0;
    assert!(
        (motor - expected).abs() < 1e-3,
        "{motor} N m against {expected}"
    );
    let loop_rig = testrig(&[
        "simulate",
        "--rig",
        &rig_file("fzg-back-to-back"),
        "--rpm",
        "1450",
        "--load",
        "5",
    ]);
    let err = String::from_utf8_lossy(&loop_rig.stderr);
    assert!(
        !loop_rig.status.success() && err.contains("--load 5") && err.contains("no [brake]"),
        "{err}"
    );
    for (set, says) in [
        ("mesh.stage9.backlash_mm=0.4", "mesh.stage9.backlash_mm"),
        ("mesh.stage1.backlash_mm=-1", "backlash_mm"),
    ] {
        let out = testrig(&[
            "simulate",
            "--rig",
            &rig_file("two-stage"),
            "--rpm",
            "600",
            "--load",
            "10",
            "--set",
            set,
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success() && err.contains(says), "{set}: {err}");
    }
}

#[test]
fn simulate_approach_rest_starts_the_rig_at_rest_with_the_motor_at_its_limit() {
    let dir = folder("rig-approach-rest");
    let out = dir.path().join("run");
    let args = [
        "simulate",
        "--rig",
        &rig_file("basmaji-1983"),
        "--rpm",
        "1300",
        "--load",
        "2.712",
        "--approach",
        "rest",
        "--settle",
        "0",
        "--duration",
        "1",
        "--rate",
        "1000",
        "--out",
        out.to_str().expect("path"),
    ];
    let run = testrig(&args);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let rows = common::csv_rows(&out.join("signals.csv"));
    let first = &rows[0];
    for body in [
        "motor",
        "input_flywheel",
        "driven_gear",
        "output_flywheel",
        "brake",
    ] {
        assert_eq!(common::number(first, &format!("speed_{body}_rpm")), 0.0);
    }
    // 1300 rev/min asked of a rig at rest: the speed loop saturates at the 7.12 N m limit,
    // and the rig gains speed at (limit − load) / ΣJ at most.
    let limit = 7.120909241507619;
    assert!((common::number(first, "motor_torque_nm") - limit).abs() < 1e-9);
    let last = &rows[rows.len() - 1];
    let speed_rad_s = common::number(last, "speed_motor_rpm") * std::f64::consts::PI / 30.0;
    let inertia = 0.0163 + 0.355 + 0.00865 + 0.45 + 0.015;
    let most = (limit - 2.712) / inertia * 0.999;
    assert!(
        speed_rad_s > 0.8 * most && speed_rad_s < 1.05 * most,
        "{speed_rad_s} rad/s after 1 s; (limit − load)/ΣJ gives {most}"
    );
    let preset = testrig(&[
        "simulate",
        "--rpm",
        "1300",
        "--load",
        "2.712",
        "--approach",
        "rest",
    ]);
    assert!(!preset.status.success(), "--approach needs --rig");
}
