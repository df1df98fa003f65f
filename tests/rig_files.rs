//! Rig files (`docs/rig-files.md`): the 1983 rig as a file gives the preset's natural
//! frequencies; rigs nobody tuned (a two-stage reduction, an FZG-type back-to-back loop)
//! give frequencies that are roots of det(K − ω²M) for K and M assembled here from the
//! file's numbers, independently of the application; bad files are refused at their
//! line, naming the field and what is allowed; `params --rig` lists every field.
//! `simulate --rig` is tested in `tests/rig_simulate.rs`.

mod common;

use nalgebra::DMatrix;

use common::{folder, json_of, refused_rig, rig_file};

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
        numbers(&preset["natural_hz"]),
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

/// The meshes held rigid are the limit of stiff meshes, on rigs whose gears are not 1:1
/// (the FZG's 16/24 pairs in a back-to-back loop, the two-stage rig): with every mesh a
/// million times stiffer, the modes in contact below the meshes' own are the rigid
/// modes to 1e-5; and the parts apart are the rig's shafts alone, each part's
/// frequencies the roots of its own chain (here: as many parts as the shafts join).
#[test]
fn rigid_meshes_are_the_limit_of_stiff_ones_on_any_rig() {
    for (name, meshes) in [
        ("fzg-back-to-back", &["test", "slave"][..]),
        ("two-stage", &["stage1", "stage2"][..]),
    ] {
        let path = rig_file(name);
        let modes = json_of(&["modes", "--rig", &path, "--json"]);
        let rigid = numbers(&modes["rigid_meshes"]["natural_hz"]);
        let mut args = vec![
            "modes".to_string(),
            "--rig".into(),
            path.clone(),
            "--json".into(),
        ];
        for mesh in meshes {
            let stiffness = format!("mesh.{mesh}.stiffness_n_per_m");
            let field = modes_field(&path, &stiffness);
            args.push("--set".into());
            args.push(format!("{stiffness}={}", field * 1e6));
        }
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let stiff = numbers(&json_of(&refs)["natural_hz"]);
        for (a, b) in stiff.iter().zip(&rigid) {
            assert!(
                (a / b - 1.0).abs() < 1e-5,
                "{name}: {stiff:?} against {rigid:?}"
            );
        }
        assert!(!modes["meshes_apart"].as_array().expect("parts").is_empty());
    }
}

/// The value of `field` (a path) in the rig file at `path`, as `testrig params --rig`
/// reads it.
fn modes_field(path: &str, field: &str) -> f64 {
    let params = json_of(&["params", "--rig", path, "--json"]);
    params["fields"]
        .as_array()
        .expect("fields")
        .iter()
        .find(|f| f["name"] == field)
        .and_then(|f| f["value"].as_str()?.parse().ok())
        .unwrap_or_else(|| panic!("no {field} in {path}"))
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
            "reproduces-an-unknown-rig",
            "name = \"two-stage\"",
            "reproduces = \"lin-parker-1999\"\nname = \"two-stage\"",
            vec![
                "reproduces",
                "`lin-parker-1999` is no published rig",
                "allowed: basmaji-1983",
            ],
        ),
        (
            "duplicate-name",
            "name = \"coupling\"",
            "name = \"motor\"",
            vec!["body.name", "`motor` names two bodys"],
        ),
        (
            "ratings-and-torque-limit",
            "\n[brake]",
            "torque_limit_nm = 7.0\nrated_power_w = 1491.4\nrated_speed_rpm = 2000.0\n\n[brake]",
            vec!["motor.torque_limit_nm", "not both"],
        ),
        (
            "ratings-without-speed",
            "\n[brake]",
            "current_limit_pct = 150.0\n\n[brake]",
            vec!["motor.rated_power_w", "rated_speed_rpm (rev/min) both"],
        ),
        (
            "negative-brake-drag",
            "\n[gauge]",
            "drag_nm = -0.5\n\n[gauge]",
            vec!["brake.drag_nm", "must be 0 or a number"],
        ),
        (
            "ungauged-shaft-with-the-chains-name",
            "name = \"intermediate\"",
            "name = \"intermediate_shaft\"",
            vec![
                "shaft.name",
                "the measuring chain's name for the gauged shaft",
                "torque_intermediate_shaft_nm",
            ],
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
        let stderr = refused_rig(&dir, name, &good.replacen(old, new, 1));
        let place = format!("{name}.toml:{line}:");
        assert!(stderr.contains(&place), "{name}: `{place}` not in {stderr}");
        for e in expected {
            assert!(stderr.contains(e), "{name}: `{e}` not in {stderr}");
        }
    }
    // A body joined to nothing (the brake's shaft moved onto another body).
    let stderr = refused_rig(
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
    let stderr = refused_rig(
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
    let stderr = refused_rig(&dir, "too-many-bodies", &many);
    assert!(
        stderr.contains("33 bodies: a rig has 2 to 32 bodies"),
        "{stderr}"
    );
    let mut meshes = good.clone();
    for i in 0..19 {
        meshes.push_str(&format!(
            "[[mesh]]\nname = \"extra{i}\"\ndriver = \"pinion1\"\ndriven = \"wheel1\"\nteeth = [20, 60]\nmodule_m = 0.003\nbacklash_mm = 0.2\nstiffness_n_per_m = 2.8e8\n"
        ));
    }
    let stderr = refused_rig(&dir, "too-many-meshes", &meshes);
    assert!(
        stderr.contains("21 meshes: a rig has at most 20"),
        "{stderr}"
    );
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
