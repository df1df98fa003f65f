//! The potential-energy mesh stiffness as `testrig params --rig` derives it, judged by a
//! peer: ROSS 3.1.0's `GearElementTVMS` (`ross-rotordynamics`), run unmodified from its
//! wheel on ROSS's own test case and on the 1983 gears (`tests/mesh_stiffness/
//! compare_ross.py`).

mod common;

use common::{folder, testrig_ok};

#[test]
fn params_prints_what_the_method_derives_from_a_face_width_and_the_material_it_used() {
    let dir = folder("params-face-width");
    let rig = dir.path().join("pair.toml");
    std::fs::write(
        &rig,
        r#"name = "pair"
description = "the 1983 gears by their face width"
[[body]]
name = "pinion"
inertia_kgm2 = 0.01
[[body]]
name = "wheel"
inertia_kgm2 = 0.01
[[mesh]]
name = "gears"
driver = "pinion"
driven = "wheel"
teeth = [30, 30]
module_m = 0.005
backlash_mm = 0.73
face_width_m = 0.020
poisson_ratio = 0.28
bore_diameter_m = 0.020
"#,
    )
    .expect("rig file");
    let json: serde_json::Value = serde_json::from_str(&testrig_ok(&[
        "params",
        "--rig",
        rig.to_str().expect("path"),
        "--json",
    ]))
    .expect("json");
    let value = |name: &str| -> String {
        json["derived"]
            .as_array()
            .expect("derived")
            .iter()
            .find(|row| row["name"] == name)
            .unwrap_or_else(|| panic!("{name} missing: {json}"))["value"]
            .as_str()
            .expect("text")
            .to_string()
    };
    let number = |name: &str| value(name).parse::<f64>().expect("number");
    // 30/30 teeth, 20°, standard addendum: ε = 1.6535 (the geometry alone).
    assert!((number("mesh.gears.contact_ratio") - 1.6535).abs() < 1e-3);
    let pair = number("mesh.gears.pair_stiffness_n_per_m");
    let mean = number("mesh.gears.mean_mesh_stiffness_n_per_m");
    // Two pairs carry over 0.65 of the period: the mean lies between one pair and two.
    assert!(
        pair > 1e8 && mean > 1.3 * pair && mean < 2.0 * pair,
        "{pair} {mean}"
    );
    assert_eq!(number("mesh.gears.poisson_ratio_used"), 0.28);
    assert_eq!(number("mesh.gears.youngs_modulus_pa_used"), 206e9);
    assert_eq!(
        value("mesh.gears.bore_diameters_m_used"),
        "2.000000e-2/2.000000e-2"
    );
    // The mesh the plant runs on takes the method's mean (one pair always).
    let plant = json["fields"]
        .as_array()
        .expect("fields")
        .iter()
        .find(|row| row["name"] == "mesh.gears.stiffness_n_per_m")
        .expect("the mesh's stiffness")["value"]
        .as_str()
        .expect("text")
        .parse::<f64>()
        .expect("number");
    assert!((plant / mean - 1.0).abs() < 1e-6, "{plant} {mean}");
}

#[test]
fn a_bore_outside_the_root_circle_or_a_material_without_a_face_width_is_refused() {
    let dir = folder("params-bore");
    let rig = |extra: &str, width: &str| {
        let path = dir.path().join("pair.toml");
        std::fs::write(
            &path,
            format!(
                "name = \"pair\"\ndescription = \"x\"\n[[body]]\nname = \"a\"\ninertia_kgm2 = 0.01\n[[body]]\nname = \"b\"\ninertia_kgm2 = 0.01\n[[mesh]]\nname = \"gears\"\ndriver = \"a\"\ndriven = \"b\"\nteeth = [30, 30]\nmodule_m = 0.005\nbacklash_mm = 0.73\n{width}\n{extra}\n"
            ),
        )
        .expect("rig file");
        let out = common::testrig(&["params", "--rig", path.to_str().expect("path")]);
        assert!(!out.status.success(), "{extra}");
        String::from_utf8_lossy(&out.stderr).to_string()
    };
    let wide = rig("bore_diameter_m = 0.2", "face_width_m = 0.02");
    assert!(
        wide.contains("pair.toml:17")
            && wide.contains("mesh.bore_diameter_m")
            && wide.contains("root circle"),
        "{wide}"
    );
    let without = rig("poisson_ratio = 0.3", "stiffness_n_per_m = 2.6e8");
    assert!(
        without.contains("mesh.poisson_ratio") && without.contains("face_width_m"),
        "{without}"
    );
}

#[test]
#[ignore = "needs Python modules (python3 -m pip install -r tests/requirements.txt) and ROSS's wheel from PyPI; run by .ci/run"]
fn the_mesh_stiffness_agrees_with_ross() {
    common::run_python_check(
        "mesh_stiffness/compare_ross.py",
        "ross-compare",
        &["numpy", "scipy", "pint", "toml"],
    );
}
