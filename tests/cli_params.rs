//! End-to-end tests of `testrig params` and of the one vocabulary `--set` takes across
//! commands: the thesis's names, a scenario's keys, a rig's paths.

mod common;

use common::{json, testrig};

#[test]
fn params_lists_every_parameter() {
    let out = json(&testrig(&["params", "--json"]));
    let list = out["parameters"].as_array().expect("array");
    assert_eq!(list.len(), rig::PARAM_SPECS.len());
    assert!(
        list.iter()
            .all(|p| p["unit"].is_string() && p["meaning"].is_string())
    );
}

/// A preset is its rig: `params --preset NAME` lists, beside the thesis's names, every
/// field of the rig it runs as by path, as `params --rig` lists a file. A thesis's name
/// set on the preset reaches the rig converted (K23 = 2.6e6 N m/rad along the line of
/// action: K23 / r_b², r_b = 70.48 mm); a rig path set on it shows there alone.
#[test]
fn params_of_a_preset_lists_its_rig_as_params_of_its_file_does() {
    let file = format!(
        "{}/scenarios/rigs/basmaji-1983.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let shipped = json(&testrig(&["params", "--rig", &file, "--json"]));
    let preset = json(&testrig(&["params", "--json"]));
    assert_eq!(preset["fields"], shipped["fields"]);
    assert_eq!(preset["rig_derived"], shipped["derived"]);
    let named = ["params", "--set", "k23_mesh_nm_per_rad=2.6e6", "--json"];
    let out = json(&testrig(&named));
    let stiffness: f64 = listed(&out, "fields", "mesh.gears.stiffness_n_per_m")
        .as_str()
        .expect("a value")
        .parse()
        .expect("a number");
    let base_radius_m = 0.005 * 30.0 * 20.0_f64.to_radians().cos() / 2.0;
    let expected = 2.6e6 / (base_radius_m * base_radius_m);
    assert!(
        (stiffness - expected).abs() < 1e-9 * expected,
        "{stiffness} N/m against {expected}"
    );
    let set = ["params", "--set", "mesh.gears.backlash_mm=0.3", "--json"];
    let out = json(&testrig(&set));
    let backlash = listed(&out, "fields", "mesh.gears.backlash_mm");
    assert_eq!(backlash, serde_json::json!("0.3"), "{out}");
}

/// The `value` of the entry named `name` in the list `list` of `testrig params --json`.
fn listed(params: &serde_json::Value, list: &str, name: &str) -> serde_json::Value {
    params[list]
        .as_array()
        .expect("a list")
        .iter()
        .find(|entry| entry["name"] == name)
        .unwrap_or_else(|| panic!("{name} in {list}"))["value"]
        .clone()
}

#[test]
fn one_parameter_vocabulary_across_params_simulate_and_run() {
    // backlash_mm (a scenario's [rig] key) works in params (and simulate, which shares it),
    // in both its bare and its scenario form.
    for item in ["backlash_mm=1.46", "rig.backlash_mm=1.46"] {
        let out = json(&testrig(&["params", "--set", item, "--json"]));
        let backlash = listed(&out, "derived", "circular_backlash_m")
            .as_f64()
            .expect("number");
        assert!((backlash - 1.46e-3).abs() < 1e-12, "{item}: {backlash}");
    }
    let out = json(&testrig(&["params", "--set", "rig.set.teeth=31", "--json"]));
    assert_eq!(listed(&out, "parameters", "teeth"), "31");
    // run takes the bare name too; a bad value is blamed on the --set, not on a line.
    let scenario = format!(
        "{}/scenarios/aliasing-windowing.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let out = common::folder("vocabulary");
    let run = |extra: &[&str]| {
        let mut args = vec![
            "run",
            scenario.as_str(),
            "--out",
            out.to_str().expect("utf-8"),
        ];
        args.extend(extra);
        testrig(&args)
    };
    let bad = run(&["--set", "teeth=0"]);
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert!(!bad.status.success());
    assert!(
        stderr.contains("--set teeth=0 (on ") && stderr.contains("rig.set.teeth"),
        "{stderr}"
    );
    let unknown = run(&["--set", "analyser.windw=hanning"]);
    let stderr = String::from_utf8_lossy(&unknown.stderr);
    assert!(
        stderr.contains("--set analyser.windw=hanning (on ") && stderr.contains("windw"),
        "{stderr}"
    );
    let good = run(&[
        "--pace",
        "max",
        "--duration",
        "0.5",
        "--set",
        "teeth=31",
        "--set",
        "backlash_mm=1.46",
    ]);
    assert!(
        good.status.success(),
        "{}",
        String::from_utf8_lossy(&good.stderr)
    );
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn an_unknown_set_name_lists_the_scenario_sections_and_the_nearest_rig_parameters() {
    let scratch = common::folder("unknown-set");
    let scenario = format!(
        "{}/scenarios/subharmonic-2712nm.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let refusal = |set: &str| {
        let out = testrig(&[
            "run",
            &scenario,
            "--set",
            set,
            "--out",
            scratch.to_str().expect("utf-8"),
        ]);
        assert!(!out.status.success());
        String::from_utf8_lossy(&out.stderr).to_string()
    };
    // A typo of a rig parameter: the sections, and the parameter meant, not all 45.
    let typo = refusal("backlsh_mm=1");
    for expected in [
        "--set backlsh_mm=1",
        "`schedule`",
        "`analyser`",
        "did you mean `backlash_mm`?",
    ] {
        assert!(typo.contains(expected), "{expected} missing: {typo}");
    }
    assert!(!typo.contains("k12_input_shaft_nm_per_rad"), "{typo}");
    // Nothing near: the sections, and where the parameters are listed.
    let nonsense = refusal("nonsense=1");
    assert!(
        nonsense.contains("`testrig params` lists them"),
        "{nonsense}"
    );
    assert!(!nonsense.contains("did you mean"), "{nonsense}");
    assert!(
        !scratch.join("manifest.json").exists(),
        "nothing is run on a bad --set"
    );
}
