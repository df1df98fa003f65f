//! Planetary stages and planar bodies in a rig file, through the `testrig` binary: bad
//! stages refused at their line naming the field and what is allowed; the speeds Willis's
//! equation gives (`params --rig`); the modes' kinds in `modes --json`; the plant's
//! refusal of a stage that moves in the plane, naming it; a pair on bearings through
//! `simulate` (the planetary bench's runs: `planetary_bench.rs`).

mod common;

use common::{
    bench_in_the_plane, csv_rows, folder, json, number, refused_rig, simulate_rig, testrig,
};

fn lin_parker() -> String {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/rigs/lin-parker-1999.toml"
    );
    std::fs::read_to_string(path).expect("shipped rig")
}

/// The line (from 1) of the file's first line that starts with `start`.
fn line_of(text: &str, start: &str) -> usize {
    text.lines()
        .position(|l| l.starts_with(start))
        .expect("line there")
        + 1
}

#[test]
fn bad_stages_are_refused_at_their_line_naming_the_field_and_what_is_allowed() {
    let dir = folder("bad-planetary");
    let good = lin_parker();
    // (name, the text as written, as mangled, the mangled line's start, what the error says)
    let cases: Vec<(&str, &str, &str, &str, Vec<&str>)> = vec![
        (
            "ring-teeth",
            "ring = 96 }\nmodule_m = 0.003\npressure_angle_deg = 24.6\nbase_diameter_m = { sun = 0.0774, planet = 0.1003, ring = 0.275 }\n",
            "ring = 97 }\nmodule_m = 0.003\npressure_angle_deg = 24.6\n",
            "teeth =",
            vec![
                "planetary `epi`.teeth",
                "ring 97: standard gears on one centre distance need ring = sun + 2 planet = 96",
                "base_diameter_m",
            ],
        ),
        (
            "not-assemblable",
            "planets = 3\n",
            "planets = 7\n",
            "planets =",
            vec![
                "planetary `epi`.planet_angles_deg",
                "planet 2",
                "multiples of 360°/(z_s + z_r) = 3.0000°",
            ],
        ),
        (
            "too-many-planets",
            "planets = 3\n",
            "planets = 9\n",
            "planets =",
            vec!["planetary `epi`.planets", "1 to 8 planets"],
        ),
        (
            "angles-for-other-planets",
            "planets = 3\n",
            "planets = 3\nplanet_angles_deg = [0.0, 120.0]\n",
            "planet_angles_deg",
            vec!["2 angles for 3 planets"],
        ),
        (
            "angle-off-a-tooth",
            "planets = 3\n",
            "planets = 3\nplanet_angles_deg = [0.0, 120.0, 241.0]\n",
            "planet_angles_deg",
            vec!["planet 3 at 241.000°"],
        ),
        (
            "mass-without-bearing",
            "planet_bearing_stiffness_n_per_m = 1.0e8\n",
            "",
            "planet_mass_kg",
            vec!["mass (kg) and its bearing's stiffness (N/m) both"],
        ),
        (
            "same-body-twice",
            "carrier = \"carrier\"\n",
            "carrier = \"sun\"\n",
            "carrier =",
            vec!["planetary `epi`.carrier", "name three bodies"],
        ),
        (
            "frame-as-a-body",
            "name = \"carrier\"\n",
            "name = \"frame\"\n",
            "name = \"frame\"",
            vec!["`frame` is reserved"],
        ),
        (
            "zero-mesh-stiffness",
            "ring_planet = { stiffness_n_per_m = 5.0e8",
            "ring_planet = { stiffness_n_per_m = 0.0",
            "ring_planet",
            vec!["planetary `epi`.ring_planet", "> 0"],
        ),
        (
            "fault-on-a-planet-not-there",
            "ring_planet = { stiffness_n_per_m = 5.0e8, backlash_mm = 0.1 }\n",
            "ring_planet = { stiffness_n_per_m = 5.0e8, backlash_mm = 0.1 }\n\n[[planetary.fault]]\ngear = \"planet4\"\ntooth = 1\nkind = \"crack\"\nseverity = 0.2\n",
            "gear = ",
            vec![
                "planetary.fault.gear",
                "`sun`, `ring` or `planet1` to `planet3`",
            ],
        ),
        (
            "fault-past-the-ring-teeth",
            "ring_planet = { stiffness_n_per_m = 5.0e8, backlash_mm = 0.1 }\n",
            "ring_planet = { stiffness_n_per_m = 5.0e8, backlash_mm = 0.1 }\n\n[[planetary.fault]]\ngear = \"ring\"\ntooth = 97\nkind = \"pit\"\nseverity = 0.2\n",
            "tooth = ",
            vec![
                "planetary.fault.tooth",
                "97: the ring gear has teeth 1 to 96",
            ],
        ),
        (
            "pairs-misspelt",
            "sun_planet = { stiffness_n_per_m = 5.0e8, backlash_mm = 0.1 }",
            "sun_planet = { stiffness_n_per_m = 5.0e8, backlash_mm = 0.1, pairs = \"two\" }",
            "sun_planet",
            vec![
                "planetary `epi`.sun_planet.pairs",
                "one of single, alternating",
            ],
        ),
        (
            "member-meshes-outside",
            "[[shaft]]\n",
            "[[body]]\nname = \"pinion\"\ninertia_kgm2 = 0.001\n\n[[mesh]]\nname = \"side\"\ndriver = \"pinion\"\ndriven = \"carrier\"\nteeth = [20, 60]\nmodule_m = 0.003\npressure_angle_deg = 20.0\nbacklash_mm = 0.1\nstiffness_n_per_m = 2.0e8\n\n[[shaft]]\n",
            "mass_kg = 5.43",
            vec![
                "body `carrier`.mass_kg",
                "moves in the plane in stage `epi` and meshes in mesh `side` too",
                "mesh it in this stage only",
            ],
        ),
    ];
    for (name, from, to, line_start, says) in cases {
        assert!(good.contains(from), "{name}: {from:?} not in the file");
        let text = good.replacen(from, to, 1);
        let stderr = refused_rig(&dir, name, &text);
        let line = line_of(&text, line_start);
        assert!(
            stderr.contains(&format!("{name}.toml:{line}:")),
            "{name}: line {line}: {stderr}"
        );
        for s in says {
            assert!(stderr.contains(s), "{name}: {s:?} in {stderr}");
        }
    }
    // Tips that overlap: five planets of 36 teeth, 3 mm module, on a standard carrier.
    let real = good
        .replace(
            "base_diameter_m = { sun = 0.0774, planet = 0.1003, ring = 0.275 }\n",
            "",
        )
        .replace("carrier_radius_m = 0.0884\n", "")
        .replace("planets = 3\n", "planets = 5\n");
    let stderr = refused_rig(&dir, "overlapping-planets", &real);
    assert!(
        stderr.contains("planets 1 and 2 are 105.8 mm apart")
            && stderr.contains("their tips need 114.0 mm"),
        "{stderr}"
    );
    // A stage nothing holds turns as a differential: its speeds are not set.
    let start = good.find("[[shaft]]").expect("the housing");
    let end = good.find("[[planetary]]").expect("the stage");
    let free = format!("{}{}", &good[..start], &good[end..]);
    let stderr = refused_rig(&dir, "differential", &free);
    assert!(
        stderr.contains("planetary `epi`.ring") && stderr.contains("turns as a differential"),
        "{stderr}"
    );
}

#[test]
fn params_give_the_speeds_of_rolling_with_the_ring_held() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/rigs/lin-parker-1999.toml"
    );
    let out = testrig(&["params", "--rig", path]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let ratio = |body: &str| -> f64 {
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("body.{body}.speed_ratio")))
            .expect("speed ratio listed");
        line.split_whitespace()
            .nth(1)
            .expect("value")
            .parse()
            .expect("number")
    };
    // Rolling on the published base radii with the ring held: the carrier at
    // r_s / (2 r_c cos α) of the sun (z_s / (z_s + z_r) for standard gears; the paper's
    // lumped numbers are not quite those).
    let expected = 0.0387 / (2.0 * 0.0884 * 24.6f64.to_radians().cos());
    assert!(
        (ratio("carrier") - expected).abs() < 1e-6,
        "{}",
        ratio("carrier")
    );
    assert!(ratio("ring").abs() < 1e-6);
    assert!((ratio("sun") - 1.0).abs() < 1e-6);
}

#[test]
fn modes_json_names_the_planar_coordinates_and_the_kinds() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/rigs/lin-parker-1999.toml"
    );
    let out = testrig(&["modes", "--rig", path, "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let value = json(&out);
    let coordinates: Vec<&str> = value["coordinates"]
        .as_array()
        .expect("coordinates")
        .iter()
        .map(|c| c.as_str().expect("name"))
        .collect();
    // Three central members and three planets, each θ, x, y: the bodies' rotations first,
    // then their translations, then the planets' rotations, then their translations.
    assert_eq!(coordinates.len(), 18);
    assert_eq!(
        &coordinates[..5],
        ["sun", "ring", "carrier", "sun.x", "sun.y"]
    );
    assert_eq!(
        &coordinates[9..13],
        ["epi_planet1", "epi_planet2", "epi_planet3", "epi_planet1.x"]
    );
    assert_eq!(&coordinates[16..], ["epi_planet3.x", "epi_planet3.y"]);
    let kinds = value["kinds"].as_array().expect("kinds");
    let count = |k: &str| kinds.iter().filter(|v| v.as_str() == Some(k)).count();
    assert_eq!((count("rotational"), count("translational")), (5, 12));
    assert!(value["rigid_meshes"].is_null());
}

#[test]
fn a_stage_in_the_plane_runs_by_willis_with_its_planets_translations_as_signals() {
    // The bench, its sun and planets on bearings: Willis's speeds hold, each planet's two
    // meshes carry one force F (its rotation steady), and its bearing carries their sum:
    // the radial parts (sin α) cancel, the tangential ones add to 2 F cos α, which drive
    // the carrier: N r_c of it is the output's torque.
    let dir = folder("planetary-planar-run");
    let path = dir.join("planar.toml");
    std::fs::write(&path, bench_in_the_plane("1.0e8", "")).expect("written");
    let out = dir.join("out");
    simulate_rig(
        path.to_str().expect("utf-8"),
        ("1500", "50"),
        ("2", "0.1"),
        &out,
        &[],
    );
    let rows = csv_rows(&out.join("signals.csv"));
    let last = rows.last().expect("a sample");
    assert!((number(last, "speed_carrier_rpm") - 300.0).abs() < 1e-6);
    let cos = 20f64.to_radians().cos();
    let mut carried_nm = 0.0;
    for k in 1..=3 {
        let sun = number(last, &format!("force_epi_sun_planet{k}_n"));
        let ring = number(last, &format!("force_epi_ring_planet{k}_n"));
        assert!(
            (sun - ring).abs() < 1e-6 * sun,
            "planet {k}: {sun} against {ring} N"
        );
        let x = number(last, &format!("x_epi_planet{k}_m"));
        let y = number(last, &format!("y_epi_planet{k}_m"));
        let bearing_n = 1.0e8 * x.hypot(y);
        assert!(
            (bearing_n - 2.0 * sun * cos).abs() < 1e-6 * bearing_n,
            "planet {k}: bearing {bearing_n} N against 2 F cos α = {} N",
            2.0 * sun * cos
        );
        carried_nm += 0.090 * bearing_n;
    }
    let output = number(last, "torque_output_nm");
    assert!(
        (carried_nm - output).abs() < 1e-6 * output,
        "the pins carry {carried_nm} N m of {output}"
    );
}

#[test]
fn a_pair_on_bearings_runs_through_simulate_with_its_translations_as_signals() {
    // The two-stage rig with its first pair's gears on bearings, the wheel's set by path.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenarios/rigs/two-stage.toml");
    let text = std::fs::read_to_string(path)
        .expect("shipped rig")
        .replacen(
            "name = \"pinion1\"\n",
            "name = \"pinion1\"\nmass_kg = 1.2\nbearing_stiffness_n_per_m = 2.0e8\n",
            1,
        )
        .replacen(
            "name = \"wheel1\"\n",
            "name = \"wheel1\"\nmass_kg = 6.0\nbearing_stiffness_n_per_m = 1.0e8\n",
            1,
        );
    let dir = folder("planar-simulate");
    let rig = dir.join("planar.toml");
    std::fs::write(&rig, text).expect("written");
    let out = dir.join("out");
    let run = testrig(&[
        "simulate",
        "--rig",
        rig.to_str().expect("utf-8"),
        "--rpm",
        "1500",
        "--load",
        "60",
        "--settle",
        "1",
        "--duration",
        "0.5",
        "--set",
        "body.wheel1.bearing_stiffness_n_per_m=5.0e8",
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let csv = std::fs::read_to_string(out.join("signals.csv")).expect("signals");
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().expect("header").split(',').collect();
    let last: Vec<f64> = lines
        .last()
        .expect("a sample")
        .split(',')
        .map(|v| v.parse().expect("number"))
        .collect();
    let value = |name: &str| last[head.iter().position(|h| *h == name).expect(name)];
    // In steady motion the wheel's bearing carries the first mesh's force: |d| = F/k.
    let force = value("force_stage1_n");
    let displacement = value("x_wheel1_m").hypot(value("y_wheel1_m"));
    assert!(force > 100.0, "the mesh carries {force} N");
    assert!(
        (displacement - force / 5.0e8).abs() < 1e-6 * force / 5.0e8,
        "{displacement} m against F/k = {} m",
        force / 5.0e8
    );
    assert!(head.contains(&"y_pinion1_m"));
}

#[test]
fn two_stages_and_a_pair_in_seventeen_meshes_turn_by_willis_and_share_their_loads() {
    // The shipped two-stage planetary gearbox (4 + 4 planets, a spur pair): 50:1. At
    // 1500 rev/min and 100 N m on the brake every speed follows Willis stage by stage,
    // the motor carries 100/50 N m, and each stage's four planets share its sun's torque
    // equally, T_s/(4 r_s): the first stage's the input shaft's, the second's the middle
    // shaft's, five times as much.
    let dir = folder("planetary-two-stage");
    let out = dir.join("out");
    let rig = common::rig_file("planetary-two-stage");
    simulate_rig(&rig, ("1500", "100"), ("2", "0.1"), &out, &[]);
    let rows = csv_rows(&out.join("signals.csv"));
    let last = rows.last().expect("a sample");
    let forces = last.keys().filter(|k| k.starts_with("force_")).count();
    assert_eq!(forces, 17, "4 + 4 planets' two meshes each and the pair");
    for (body, rpm) in [
        ("carrier1", 300.0),
        ("sun2", 300.0),
        ("carrier2", 60.0),
        ("brake", 30.0),
    ] {
        let speed = number(last, &format!("speed_{body}_rpm"));
        assert!(
            (speed - rpm).abs() < 1e-6,
            "{body} at {speed} rev/min, not {rpm}"
        );
    }
    let motor = number(last, "motor_torque_nm");
    assert!((motor - 2.0).abs() < 1e-6, "the motor carries {motor} N m");
    let rs = 0.003 * 24.0 * 20f64.to_radians().cos() / 2.0;
    for (stage, shaft, sun_nm) in [("first", "input", 2.0), ("second", "middle", 10.0)] {
        let torque = number(last, &format!("torque_{shaft}_nm"));
        assert!(
            (torque - sun_nm).abs() < 1e-6,
            "{shaft} carries {torque} N m"
        );
        for kind in ["sun", "ring"] {
            for k in 1..=4 {
                let force = number(last, &format!("force_{stage}_{kind}_planet{k}_n"));
                let share = sun_nm / (4.0 * rs);
                assert!(
                    (force - share).abs() < 1e-6 * share,
                    "{stage} {kind} mesh of planet {k}: {force} N against {share} N"
                );
            }
        }
    }
}
