//! Planetary stages and planar bodies in a rig file, through the `testrig` binary: bad
//! stages refused at their line naming the field and what is allowed; the speeds Willis's
//! equation gives (`params --rig`); the modes' kinds in `modes --json`; and the plant's
//! refusal, until it steps them, naming the stage.

mod common;

use common::{folder, json, refused_rig, testrig};

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
    // then their translations, then the planets'.
    assert_eq!(coordinates.len(), 18);
    assert_eq!(
        &coordinates[..5],
        ["sun", "ring", "carrier", "sun.x", "sun.y"]
    );
    assert_eq!(
        &coordinates[15..],
        ["epi_planet3", "epi_planet3.x", "epi_planet3.y"]
    );
    let kinds = value["kinds"].as_array().expect("kinds");
    let count = |k: &str| kinds.iter().filter(|v| v.as_str() == Some(k)).count();
    assert_eq!((count("rotational"), count("translational")), (5, 12));
    assert!(value["rigid_meshes"].is_null());
}

#[test]
fn the_plant_refuses_a_stage_that_moves_in_the_plane_naming_it() {
    let text = lin_parker() + "\n[motor]\nbody = \"sun\"\n\n[brake]\nbody = \"carrier\"\n";
    let dir = folder("planetary-run");
    let path = dir.join("driven.toml");
    std::fs::write(&path, text).expect("written");
    let out = testrig(&[
        "simulate",
        "--rig",
        path.to_str().expect("utf-8"),
        "--rpm",
        "1000",
        "--load",
        "1",
    ]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("planetary stage `epi` moves in the plane")
            && stderr.contains("steps stages turning about fixed axes")
            && stderr.matches("moves in the plane").count() == 1
            && !stderr.contains("panicked"),
        "{stderr}"
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

/// Runs `simulate --rig rig` at `rpm` and `load` N m, settled `settle` s, for `seconds`,
/// its signals into `out` (fails with its stderr if refused).
fn simulate(
    rig: &str,
    (rpm, load): (&str, &str),
    (settle, seconds): (&str, &str),
    out: &std::path::Path,
) {
    let run = testrig(&[
        "simulate",
        "--rig",
        rig,
        "--rpm",
        rpm,
        "--load",
        load,
        "--settle",
        settle,
        "--duration",
        seconds,
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
}

/// The shipped bench with one pair always in each mesh (its static solutions and its
/// energy need a stiffness that does not change in contact).
fn single_pair_bench() -> String {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/rigs/planetary-bench.toml"
    );
    let text = std::fs::read_to_string(path).expect("shipped bench");
    assert!(text.contains(", pairs = \"alternating\""));
    text.replace(", pairs = \"alternating\"", "")
}

/// `text` written as `name`.toml in `dir`: its path.
fn written(dir: &std::path::Path, name: &str, text: &str) -> String {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).expect("written");
    path.to_str().expect("utf-8").to_string()
}

/// The last sample of `signals.csv` in `dir`, by column name.
fn last_sample(dir: &std::path::Path) -> impl Fn(&str) -> f64 {
    let csv = std::fs::read_to_string(dir.join("signals.csv")).expect("signals");
    let mut lines = csv.lines();
    let head: Vec<String> = lines
        .next()
        .expect("header")
        .split(',')
        .map(String::from)
        .collect();
    let last: Vec<f64> = lines
        .last()
        .expect("a sample")
        .split(',')
        .map(|v| v.parse().expect("number"))
        .collect();
    move |name| last[head.iter().position(|h| h == name).expect(name)]
}

#[test]
fn a_planetary_bench_turns_by_willis_balances_its_torques_and_shares_its_load_equally() {
    let dir = folder("planetary-bench");
    let out = dir.join("out");
    let rig = written(&dir, "bench", &single_pair_bench());
    simulate(&rig, ("1500", "50"), ("2", "1"), &out);
    let at = last_sample(&out);
    // Willis with the ring held: the carrier at z_s/(z_s + z_r) = 1/5 of the sun, each
    // planet at r_s/(2 r_p) = 1/3 of it the other way (in its own sense, positive).
    assert!((at("speed_carrier_rpm") - 300.0).abs() < 1e-6);
    assert!(at("speed_ring_rpm").abs() < 1e-6);
    for k in 1..=3 {
        assert!((at(&format!("speed_epi_planet{k}_rpm")) - 500.0).abs() < 1e-6);
    }
    // Torques: the carrier carries (1 + z_r/z_s) = 5 times the sun's in steady motion.
    let (input, output) = (at("torque_input_nm"), at("torque_output_nm"));
    assert!((output - 50.0).abs() < 1e-6 && (input - 10.0).abs() < 1e-6);
    // Equal sharing: each planet's sun and ring mesh carries T_s / (N r_s).
    let rs = 0.003 * 24.0 * 20f64.to_radians().cos() / 2.0;
    let share = input / (3.0 * rs);
    for kind in ["sun", "ring"] {
        for k in 1..=3 {
            let force = at(&format!("force_epi_{kind}_planet{k}_n"));
            assert!(
                (force - share).abs() < 1e-9 * share,
                "{kind} mesh of planet {k}: {force} N against {share} N"
            );
        }
    }
}

#[test]
fn a_planetary_stage_conserves_energy_through_impacts_without_damping() {
    let text = single_pair_bench();
    // No damping, no motor, no brake: the stage knocked at rest rattles in its backlash.
    let cut = text.find("[motor]").expect("the motor's table");
    let free = text[..cut]
        .replace("damping_nms_per_rad = 0.2", "damping_nms_per_rad = 0.0")
        .replace("damping_nms_per_rad = 50.0", "damping_nms_per_rad = 0.0")
        .replace("damping_nms_per_rad = 1.0", "damping_nms_per_rad = 0.0")
        .replace("damping_ns_per_m = 2000.0", "damping_ns_per_m = 0.0");
    let source = testrig::scenario::ScenarioSource {
        path: std::path::PathBuf::from("free-bench.toml"),
        text: free,
    };
    let rig = testrig::scenario::rig_topology(&source).expect("the free bench reads");
    let mut plant = rig::NetworkPlant::new(
        &rig,
        rig::Schedule::constant(0.0, 0.0),
        51_200.0,
        rig::NetworkStart::Steady,
    )
    .expect("valid plant");
    // The sun (body 1) and the first planet (the first coordinate after the bodies)
    // knocked.
    plant.kick(1, 3.0);
    plant.kick(5, -1.0);
    let e0 = plant.energy_j();
    let mut worst = 0.0_f64;
    for _ in 0..51_200 {
        plant.skip(1).expect("runs");
        worst = worst.max((plant.energy_j() - e0).abs() / e0);
    }
    let impacts = plant.take_impacts().len();
    eprintln!("MEASURED planetary energy drift {worst:e} of {e0} J over {impacts} impacts");
    assert!(impacts > 50, "only {impacts} impacts");
    assert!(worst < 1e-9, "energy drifts by {worst:e}");
}

#[test]
fn a_pin_error_shares_the_load_unequally_as_the_static_solution_says() {
    // Planet 1's pin 0.1 µm ahead: both its meshes relax by e cos α. The central members
    // are rigid rotations, so every planet's two meshes in series (k_sp k_rp/(k_sp +
    // k_rp)) close the same gap less their own 2 e cos α: F_k = T_s/(N r_s) − 2 k_path
    // cos α (e_k − ē), the sum still T_s / r_s.
    let text = single_pair_bench().replacen(
        "planet_inertia_kgm2 = 0.0015\n",
        "planet_inertia_kgm2 = 0.0015\nplanet_pin_errors_um = [0.1, 0.0, 0.0]\n",
        1,
    );
    let dir = folder("planetary-pin-error");
    let out = dir.join("out");
    simulate(
        &written(&dir, "pin", &text),
        ("1500", "50"),
        ("2", "0.5"),
        &out,
    );
    let at = last_sample(&out);
    let cos = 20f64.to_radians().cos();
    let rs = 0.003 * 24.0 * cos / 2.0;
    let path = 4.0e8 * 4.5e8 / (4.0e8 + 4.5e8);
    let errors = [0.1e-6, 0.0, 0.0];
    let mean = errors.iter().sum::<f64>() / 3.0;
    let input = at("torque_input_nm");
    for (k, e) in errors.iter().enumerate() {
        let expected = input / (3.0 * rs) - 2.0 * path * cos * (e - mean);
        for kind in ["sun", "ring"] {
            let force = at(&format!("force_epi_{kind}_planet{}_n", k + 1));
            assert!(
                (force - expected).abs() < 1e-9 * expected,
                "{kind} mesh of planet {}: {force} N, the static solution {expected} N",
                k + 1
            );
        }
    }
    // The planet ahead carries less: about 26 N of the 98.5 N share.
    let first = at("force_epi_sun_planet1_n");
    assert!(first < 75.0 && first > 70.0, "{first}");
}
