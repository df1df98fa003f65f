//! The shipped planetary bench run through `testrig simulate`: Willis's speeds, the
//! torque balance and equal load sharing; energy without damping through impacts, on
//! fixed axes and in the plane; a pin error's unequal sharing against the static
//! solution, and its equal sharing with the sun floating; and the carrier-synchronous
//! condition report with the stage's fault lines, a cracked sun tooth's growing; and the
//! shipped planetary fault data set.

mod common;

use common::{
    bench_in_the_plane, csv_rows, folder, json, simulate_rig, single_pair_bench, testrig,
    testrig_ok,
};

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
    simulate_rig(&rig, ("1500", "50"), ("2", "1"), &out, &[]);
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

/// The worst relative energy drift over 1 s at 51.2 kHz of `text`'s stage with every
/// damping removed and no motor or brake, knocked at rest by `kicks` (coordinate, rad/s
/// or m/s), and the impacts it rattled through.
fn free_energy_drift(text: &str, kicks: &[(usize, f64)]) -> (f64, usize) {
    let cut = text.find("[motor]").expect("the motor's table");
    let free = text[..cut]
        .replace("damping_nms_per_rad = 0.2", "damping_nms_per_rad = 0.0")
        .replace("damping_nms_per_rad = 50.0", "damping_nms_per_rad = 0.0")
        .replace("damping_nms_per_rad = 1.0", "damping_nms_per_rad = 0.0")
        .replace("damping_ns_per_m = 2000.0", "damping_ns_per_m = 0.0")
        .replace("damping_ns_per_m = 500.0", "damping_ns_per_m = 0.0")
        .replace("damping_ns_per_m = 200.0", "damping_ns_per_m = 0.0");
    assert!(!free.contains("damping_ns_per_m = 2") && !free.contains("damping_ns_per_m = 5"));
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
    for &(coordinate, delta) in kicks {
        plant.kick(coordinate, delta);
    }
    let e0 = plant.energy_j();
    let mut worst = 0.0_f64;
    for _ in 0..51_200 {
        plant.skip(1).expect("runs");
        worst = worst.max((plant.energy_j() - e0).abs() / e0);
    }
    (worst, plant.take_impacts().len())
}

#[test]
fn a_planetary_stage_conserves_energy_through_impacts_without_damping() {
    // The stage knocked at rest rattles in its backlash: the sun (body 1) and the first
    // planet (the first coordinate after the bodies) knocked.
    let (worst, impacts) = free_energy_drift(&single_pair_bench(), &[(1, 3.0), (5, -1.0)]);
    eprintln!("MEASURED planetary energy drift {worst:e} over {impacts} impacts");
    assert!(impacts > 50, "only {impacts} impacts");
    assert!(worst < 1e-9, "energy drifts by {worst:e}");
    // In the plane, the sun floating and the planets on their pins' bearings: the sun's
    // rotation and x (coordinate 5, after the bodies' rotations) and planet 1's x (10,
    // after the sun's y and the planets' rotations) knocked.
    let planar = bench_in_the_plane("1.0e8", "");
    let (worst, impacts) = free_energy_drift(&planar, &[(1, 3.0), (5, 0.05), (10, -0.05)]);
    eprintln!("MEASURED planar planetary energy drift {worst:e} over {impacts} impacts");
    assert!(impacts > 50, "only {impacts} impacts in the plane");
    assert!(worst < 1e-9, "energy drifts by {worst:e} in the plane");
}

#[test]
fn a_floating_sun_shares_the_load_equally_despite_a_pin_error() {
    // Planet 1's pin 0.1 µm ahead, the sun on a soft bearing (1e3 N/m against 4e8 N/m
    // meshes): the sun's balance in the plane, Σ F_k n_k = −k_b d with three lines 120°
    // apart, leaves only equal forces, whatever the pin error. The sun moves to close
    // each planet's path by 2 cos α (e_k − ē) along its line, |d| = (2/3)|Σ 2 cos α
    // (e_k − ē) n_k| = (4/3) e cos α. A stiff sun bearing (1e10 N/m) keeps the unequal
    // sharing of a sun on a fixed axis.
    // (The known result for three planets: Kahraman, Mech. Mach. Theory 29(8), 1994.)
    let dir = folder("planetary-floating-sun");
    let error = "planet_pin_errors_um = [0.1, 0.0, 0.0]\n";
    let forces = |bearing: &str| {
        let out = dir.join(format!("out-{bearing}"));
        let rig = written(
            &dir,
            &format!("float-{bearing}"),
            &bench_in_the_plane(bearing, error),
        );
        simulate_rig(&rig, ("1500", "50"), ("2", "0.1"), &out, &[]);
        let at = last_sample(&out);
        let f: Vec<f64> = (1..=3)
            .map(|k| at(&format!("force_epi_sun_planet{k}_n")))
            .collect();
        (f, at("x_sun_m").hypot(at("y_sun_m")))
    };
    let (floating, moved_m) = forces("1.0e3");
    let spread = floating
        .iter()
        .fold(0.0_f64, |m, f| m.max((f - floating[0]).abs()));
    let expected_m = 4.0 / 3.0 * 0.1e-6 * 20f64.to_radians().cos();
    eprintln!(
        "MEASURED floating sun: forces {floating:?} N, moved {moved_m:e} m (expected {expected_m:e})"
    );
    assert!(spread < 1e-5 * floating[0], "floating sun: {floating:?} N");
    assert!(
        (moved_m - expected_m).abs() < 1e-3 * expected_m,
        "the sun moved {moved_m:e} m"
    );
    // Held, the planet ahead carries less (95.4 N against 100.1 N, measured: softer than
    // on fixed pins, its own bearing in the path).
    let (held, _) = forces("1.0e10");
    assert!(
        held[1] - held[0] > 1.0,
        "a held sun shares unequally: {held:?} N"
    );
}

#[test]
fn a_pin_error_shares_the_load_unequally_as_the_static_solution_says() {
    // Planet 1's pin 0.1 µm ahead: both its meshes relax by e cos α. The central members
    // are rigid rotations, so every planet's two meshes in series (k_sp k_rp/(k_sp +
    // k_rp)) close the same gap less their own 2 e cos α: F_k = T_s/(N r_s) − 2 k_path
    // cos α (e_k − ē), the sum still T_s / r_s. The sun meshes' stiffness is set by path
    // to twice the file's.
    let text = single_pair_bench().replacen(
        "planet_inertia_kgm2 = 0.0015\n",
        "planet_inertia_kgm2 = 0.0015\nplanet_pin_errors_um = [0.1, 0.0, 0.0]\n",
        1,
    );
    let dir = folder("planetary-pin-error");
    let out = dir.join("out");
    simulate_rig(
        &written(&dir, "pin", &text),
        ("1500", "50"),
        ("2", "0.5"),
        &out,
        &["--set", "planetary.epi.sun_planet.stiffness_n_per_m=8.0e8"],
    );
    let at = last_sample(&out);
    let cos = 20f64.to_radians().cos();
    let rs = 0.003 * 24.0 * cos / 2.0;
    let path = 8.0e8 * 4.5e8 / (8.0e8 + 4.5e8);
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
    // The planet ahead carries less: about 36 N of the 98.5 N share (26 N with the
    // file's stiffness: the path set stiffer).
    let first = at("force_epi_sun_planet1_n");
    assert!(first < 65.0 && first > 60.0, "{first}");
}

#[test]
fn the_condition_report_averages_the_ring_sensor_over_the_carrier_and_reads_the_fault_lines() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/rigs/planetary-bench.toml"
    );
    let shipped = std::fs::read_to_string(path).expect("shipped bench");
    let dir = folder("planetary-condition");
    let cracked = shipped.replacen(
        "\n[motor]",
        "\n[[planetary.fault]]\ngear = \"sun\"\ntooth = 5\nkind = \"crack\"\nseverity = 0.4\n\n[motor]",
        1,
    );
    let report = |name: &str, text: &str| {
        let rig = written(&dir, name, text);
        let args = [
            "simulate",
            "--rig",
            &rig,
            "--rpm",
            "1500",
            "--load",
            "50",
            "--settle",
            "1",
            "--duration",
            "2",
            "--json",
        ];
        json(&testrig(&args))["condition"].clone()
    };
    let (healthy, crack) = (report("healthy", &shipped), report("cracked", &cracked));
    assert_eq!(healthy["gear"], "carrier");
    assert_eq!(healthy["teeth"], 96);
    assert_eq!(healthy["signal"], "sensor_epi_n");
    // Ten carrier turns in 2 s at 5 Hz: whole ones between the first and last pulse.
    assert!(healthy["revolutions_averaged"].as_u64().expect("a count") >= 8);
    let line = |c: &serde_json::Value, name: &str| {
        let l = &c["planetary"][0]["lines"][name];
        (
            l["hz"].as_f64().expect("hz"),
            l["amplitude"].as_f64().expect("amplitude"),
        )
    };
    // 1500 rev/min, the ring held: carrier 5 Hz, the sun 20 Hz against it.
    let expected = [
        ("mesh", 480.0),
        ("planet_pass", 15.0),
        ("sun_fault", 60.0),
        ("planet_fault", 96.0 / 36.0 * 5.0),
        ("ring_fault", 15.0),
    ];
    for (name, hz) in expected {
        assert!((line(&healthy, name).0 - hz).abs() < 1e-9, "{name}");
    }
    let (before, after) = (line(&healthy, "sun_fault").1, line(&crack, "sun_fault").1);
    eprintln!(
        "MEASURED ring sensor at the sun's fault line, 60 Hz: healthy {before:.3e} N, cracked 0.4 {after:.3e} N"
    );
    assert!(after > 100.0 * before, "{before:e} -> {after:e} N");
}

/// The shipped data set (`scenarios/planetary-fault-dataset.toml`, 36 cases) labels every
/// case of gear × severity × speed × load once, severity 0 as healthy, names the stage
/// and the gear of each fault, records every case, and at every point the ring sensor's
/// carrier-synchronous residual (the truth columns average it) grows with each step of
/// the sun's crack.
#[test]
fn the_planetary_fault_dataset_labels_every_case_and_the_sun_crack_lifts_the_residual() {
    let dir = folder("planetary-fault-dataset");
    let out = dir.join("out");
    testrig_ok(&[
        "sweep",
        &common::scenario("planetary-fault-dataset"),
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    let labels = csv_rows(&out.join("labels.csv"));
    assert_eq!(labels.len(), 36);
    let (gear, severity) = ("planetary.epi.fault1.gear", "planetary.epi.fault1.severity");
    let mut seen: Vec<String> = labels
        .iter()
        .map(|r| {
            [gear, severity, "rpm", "load_nm"]
                .map(|k| r[k].clone())
                .join(" ")
        })
        .collect();
    seen.sort();
    seen.dedup();
    assert_eq!(seen.len(), 36, "every combination once");
    for r in &labels {
        if r[severity] == "0.0" {
            assert_eq!(r["fault_kind"], "healthy", "{r:?}");
        } else {
            assert_eq!(r["fault_mesh"], "epi");
            assert_eq!(r["fault_gear"], r[gear]);
            assert_eq!(r["fault_kind"], "crack");
        }
        for file in r["recordings"].split(' ') {
            assert!(out.join(file).is_file(), "{file}");
        }
    }
    for (rpm, load) in [
        ("1000", "25"),
        ("1000", "50"),
        ("1500", "25"),
        ("1500", "50"),
    ] {
        let residual: Vec<f64> = ["0.0", "0.25", "0.5"]
            .iter()
            .map(|s| {
                let r = labels
                    .iter()
                    .find(|r| {
                        r[gear] == "sun"
                            && r[severity] == *s
                            && r["rpm"] == rpm
                            && r["load_nm"] == load
                    })
                    .expect("the case");
                r["residual_rms_nm"].parse().expect("a number")
            })
            .collect();
        eprintln!(
            "MEASURED planetary data set {rpm} rev/min {load} N m: the ring sensor's residual RMS by sun crack 0, 0.25, 0.5: {residual:?} N"
        );
        assert!(
            residual[0] < residual[1] && residual[1] < residual[2],
            "{rpm} rev/min, {load} N m: {residual:?}"
        );
    }
}
