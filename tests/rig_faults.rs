//! Tooth faults on a rig file's mesh (`[[mesh.fault]]`, issue 35): a pitted tooth's pair
//! keeps the unpitted share of its stiffness over its single-contact stretch (the
//! quasi-static mesh deflection there is F / (k (1 − s))), a broken-off share of the face
//! over its whole time in mesh; a tooth broken through leaves its pair as free
//! play, so once a revolution of its gear the teeth part and the next pair strikes as it
//! comes into mesh (then, after a bounce, once more within that tooth period), where the
//! healthy rig runs without an impact; bad faults are refused at their line.

mod common;
mod rig_support;

use rig::{NetworkStart, Schedule};
use rig_support::faulted::{deflection_m, rig_damped, rig_with};
use rig_support::{RATE_HZ, body, plant, run};
use testrig::scenario::read_rig_file;

/// A pit of half the contact width on tooth 7 of the driven gear: over its pair's
/// single-contact stretch (the last 2 − ε of the tooth period) the pair keeps half its
/// stiffness, so the deflection there rises by F/k; as the pair comes into mesh, and on
/// every other pair, nothing changes.
#[test]
fn a_pit_halves_its_pairs_stiffness_over_the_single_contact_stretch() {
    let dir = common::folder("fault-pit");
    let rig = rig_with(
        dir.path(),
        "[[mesh.fault]]\ngear = \"driven\"\ntooth = 7\nkind = \"pit\"\nseverity = 0.5\n",
    );
    // 30 rev/min, 5 N m: a tooth period lasts 66.7 ms, long beside the mesh's ringing.
    let (rpm, load_nm) = (30.0, 5.0);
    let mut p = plant(&rig, Schedule::constant(rpm, load_nm), NetworkStart::Steady);
    let block = run(&mut p, &rig, 4.0);
    let delta = deflection_m(&rig, &block);
    let tooth_s = 60.0 / rpm / 30.0;
    // The single-contact stretch: the last 2 − ε of each tooth period.
    let single_from = rig.meshes[0].contact_ratio() - 1.0;
    // The mean deflection over the middle of pair `pair`'s stretch from..to (tooth
    // periods).
    let mean = |pair: usize, from: f64, to: f64| {
        let margin = 0.2 * (to - from);
        let a = ((pair as f64 + from + margin) * tooth_s * RATE_HZ) as usize;
        let b = ((pair as f64 + to - margin) * tooth_s * RATE_HZ) as usize;
        delta[a..b].iter().sum::<f64>() / (b - a) as f64
    };
    let single = |pair| mean(pair, single_from, 1.0);
    let double = |pair| mean(pair, 0.0, single_from);
    // Pair 6 (the driven gear's tooth 7) in both revolutions, against its neighbours.
    for pair in [6, 36] {
        let r_b = rig.meshes[0].base_radii_m()[0];
        let force_n = block.mesh_force_n[0][((pair as f64 + 0.5) * tooth_s * RATE_HZ) as usize];
        let k = rig.meshes[0].stiffness_n_per_m;
        assert!(
            (force_n * r_b / load_nm - 1.0).abs() < 0.01,
            "the mesh carries the load: {force_n} N"
        );
        // Healthy F/k, pitted F/(k/2) over the single-contact stretch: F/k more there.
        let healthy = 0.5 * (single(pair - 2) + single(pair + 2));
        let rise = single(pair) - healthy;
        assert!(
            (rise / (force_n / k) - 1.0).abs() < 0.02,
            "pair {pair}: the pitted pair deflects {rise:e} m more; F/k = {:e} m",
            force_n / k
        );
        // Before it, as the pair comes into mesh, the pit is not in contact.
        let early = double(pair) - 0.5 * (double(pair - 2) + double(pair + 2));
        assert!(
            early.abs() < 0.02 * force_n / k,
            "pair {pair} coming in: {early:e} m"
        );
        for other in [pair - 3, pair + 3] {
            let same = single(other) - healthy;
            assert!(same.abs() < 0.02 * force_n / k, "pair {other}: {same:e} m");
        }
    }
}

/// The test rig's shaft damping (N m s/rad): the 1983 rig's first torsional mode damped
/// (ζ about 0.1), so that a strike's ringing dies within a revolution and each
/// revolution's impacts are the broken tooth's own.
const DAMPING: f64 = 10.0;
const RPM: f64 = 300.0;
const LOAD: f64 = 5.424;

#[test]
fn a_tooth_broken_through_lets_the_next_pair_strike_as_it_comes_in_every_revolution() {
    let dir = common::folder("fault-broken");
    let damping = Some(DAMPING);
    let healthy = rig_damped(dir.path(), "", damping);
    let broken = rig_damped(
        dir.path(),
        "[[mesh.fault]]\ngear = \"driven\"\ntooth = 7\nkind = \"broken\"\nseverity = 1.0\n",
        damping,
    );
    let (rpm, load_nm, seconds) = (RPM, LOAD, 3.0);
    let schedule = Schedule::constant(rpm, load_nm);
    let mut calm = plant(&healthy, schedule.clone(), NetworkStart::Steady);
    run(&mut calm, &healthy, seconds);
    assert!(
        calm.take_impacts().is_empty(),
        "the healthy pair stays in contact here"
    );
    let mut p = plant(&broken, schedule, NetworkStart::Steady);
    let b = run(&mut p, &broken, seconds);
    let _ = b;
    let impacts = p.take_impacts();
    let revolution_s = 60.0 / rpm;
    let tooth_s = revolution_s / 30.0;
    let revolutions = (seconds / revolution_s).round() as usize;
    // Where each impact falls in its revolution, in tooth periods of the driver from the
    // start of pair 7 (the driven gear's tooth 8, the pair after the broken tooth).
    let after_pair_7 = |t_s: f64| (t_s / tooth_s - 7.0).rem_euclid(30.0);
    for i in &impacts {
        let at = after_pair_7(i.time_s);
        assert!(
            !(1.0..=29.99).contains(&at),
            "an impact {at} tooth periods after pair 7 comes in: {i:?}"
        );
        assert_eq!(i.flank, rig::Contact::Drive);
    }
    // Every revolution: the strike as pair 7 comes in, at the same closing speed.
    let strikes: Vec<&rig::NetworkImpact> = impacts
        .iter()
        .filter(|i| after_pair_7(i.time_s) > 29.99 || after_pair_7(i.time_s) < 0.01)
        .collect();
    assert_eq!(strikes.len(), revolutions, "{impacts:?}");
    for s in &strikes {
        assert_eq!(
            s.teeth,
            [8, 8],
            "the pair after the broken tooth 7 strikes: {s:?}"
        );
    }
    let first = strikes[1].approach_m_s;
    assert!(first > 0.005, "closing at {first} m/s");
    for s in &strikes[1..] {
        assert!((s.approach_m_s / first - 1.0).abs() < 0.01, "{s:?}");
    }
}

#[test]
fn bad_faults_are_refused_at_their_line_and_a_severity_is_set_by_path() {
    let dir = common::folder("fault-bad");
    let path = format!(
        "{}/scenarios/rigs/basmaji-1983.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).expect("rig file");
    for (fault, field, says) in [
        (
            "gear = \"pinion\"\ntooth = 7\nkind = \"pit\"\nseverity = 0.5",
            "mesh.fault.gear",
            "`driver` or `driven`",
        ),
        (
            "gear = \"driven\"\ntooth = 31\nkind = \"pit\"\nseverity = 0.5",
            "mesh.fault.tooth",
            "teeth 1 to 30",
        ),
        (
            "gear = \"driven\"\ntooth = 7\nkind = \"spall\"\nseverity = 0.5",
            "mesh.fault.kind",
            "crack, pit, broken",
        ),
        (
            "gear = \"driven\"\ntooth = 7\nkind = \"pit\"\nseverity = 1.5",
            "mesh.fault.severity",
            "0 to 1",
        ),
    ] {
        let faulted = text.replace("[motor]", &format!("[[mesh.fault]]\n{fault}\n\n[motor]"));
        let file = dir.path().join("bad.toml");
        std::fs::write(&file, &faulted).expect("write");
        let err = format!("{:#}", read_rig_file(&file).expect_err("refused"));
        let key = field.rsplit('.').next().expect("key");
        let line = faulted
            .lines()
            .enumerate()
            .filter(|(_, l)| l.starts_with(&format!("{key} =")))
            .map(|(n, _)| n + 1)
            .last()
            .expect("line");
        assert!(
            err.contains(&format!("bad.toml:{line}:")) && err.contains(field) && err.contains(says),
            "{err}"
        );
    }
    let rig = rig_with(
        dir.path(),
        "[[mesh.fault]]\ngear = \"driver\"\ntooth = 3\nkind = \"broken\"\nseverity = 0.2\n",
    );
    let field = rig
        .fields()
        .into_iter()
        .find(|f| f.path == "mesh.gears.fault1.severity")
        .expect("the fault's severity by path");
    assert_eq!(field.value, 0.2);
    let mut set = rig.clone();
    set.set_field("mesh.gears.fault1.severity", 0.6)
        .expect("set");
    assert_eq!(set.meshes[0].faults[0].severity, 0.6);
    set.set_field("mesh.gears.fault1.severity", 1.5)
        .expect("set");
    assert!(set.check().is_err());
}

/// Alternating pairs follow the driver's absolute angle: over each tooth period two pairs
/// share the load for ε − 1 of it (deflection F / (2k)), then one pair carries it
/// (F / k). With tooth 7 of the driven gear pitted by half, its single-pair stretch
/// deflects F / (k/2) and the double-pair stretches beside it stay at F / (2k); with half
/// its face broken off, the double-pair stretches beside it deflect F / (1.5 k) too.
#[test]
fn alternating_pairs_share_the_load_over_the_contact_ratio_and_a_fault_weakens_its_own() {
    // A pit acts over its pair's single-contact stretch alone; a broken-off share of the
    // face over the pair's whole time in mesh, so the double stretches share its loss.
    for (kind, cases) in [
        ("pit", [(3.0, 2.0, 1.0), (6.0, 2.0, 0.5), (7.0, 2.0, 1.0)]),
        (
            "broken",
            [(3.0, 2.0, 1.0), (6.0, 1.5, 0.5), (7.0, 1.5, 1.0)],
        ),
    ] {
        alternating_pairs_with(kind, &cases);
    }
}

/// The deflection over each zone of the pairs of `cases` (pair, two-pair stiffness,
/// single-pair stiffness, each over one healthy pair's) with tooth 7 of the driven gear
/// faulted by `kind` at severity 0.5, pairs alternating.
fn alternating_pairs_with(kind: &str, cases: &[(f64, f64, f64)]) {
    let dir = common::folder("fault-pairs");
    let fault = format!(
        "[[mesh.fault]]\ngear = \"driven\"\ntooth = 7\nkind = \"{kind}\"\nseverity = 0.5\n"
    );
    let rig = rig_with(dir.path(), &format!("pairs = \"alternating\"\n{fault}"));
    let share = rig.meshes[0].contact_ratio() - 1.0;
    let (rpm, load_nm) = (30.0, 5.0);
    let mut p = plant(&rig, Schedule::constant(rpm, load_nm), NetworkStart::Steady);
    let block = run(&mut p, &rig, 1.0);
    let delta = deflection_m(&rig, &block);
    let tooth_s = 60.0 / rpm / 30.0;
    let mean_over = |from: f64, to: f64| {
        let (a, b) = (
            (from * tooth_s * RATE_HZ) as usize,
            (to * tooth_s * RATE_HZ) as usize,
        );
        delta[a..b].iter().sum::<f64>() / (b - a) as f64
    };
    let k = rig.meshes[0].stiffness_n_per_m;
    let force_n = load_nm / rig.meshes[0].base_radii_m()[1];
    // (zone start, zone end, the stiffness in it over one healthy pair's)
    let zones =
        |p: f64, double: f64, single: f64| [(p, p + share, double), (p + share, p + 1.0, single)];
    for &(pair, double, single) in cases {
        for (from, to, ratio) in zones(pair, double, single) {
            let (a, b) = (from + 0.2 * (to - from), to - 0.2 * (to - from));
            let got = mean_over(a, b) - rig.meshes[0].half_backlash_m();
            let want = force_n / (ratio * k);
            assert!(
                (got / want - 1.0).abs() < 0.03,
                "{kind}: pair {pair}, {from:.2}..{to:.2} tooth periods: {got:e} m, F/({ratio} k) = {want:e} m"
            );
        }
    }
}

/// Run-out of either gear (`run_out_driver_um`, `run_out_driven_um`): a transmission error
/// R cos θ once per revolution of that gear. Quasi-statically the loaded pair keeps its
/// overlap, so the deflection swings by −R cos θ at each gear's own rotation: on a
/// 30:45 pair at 30 rev/min, 30 µm at the driver's 0.5 Hz and 50 µm at the driven gear's
/// 1/3 Hz, within 1 %.
#[test]
fn a_gears_run_out_swings_the_mesh_once_per_its_revolution() {
    let dir = common::folder("fault-run-out");
    let rig = rig_with(
        dir.path(),
        "run_out_driver_um = 30.0\nrun_out_driven_um = 50.0\n",
    );
    let mut rig = rig;
    rig.meshes[0].teeth = [30, 45];
    rig.check().expect("a 30:45 pair");
    let rpm = 30.0;
    let mut p = plant(&rig, Schedule::constant(rpm, 5.0), NetworkStart::Steady);
    let block = run(&mut p, &rig, 6.0);
    let [ra, rb] = rig.meshes[0].base_radii_m();
    let (a, b) = (body(&rig, "input_flywheel"), body(&rig, "driven_gear"));
    let delta: Vec<f64> = (0..block.len())
        .map(|n| ra * block.angle_rad[a][n] - rb * block.angle_rad[b][n])
        .collect();
    for (hz, expected_um) in [(rpm / 60.0, 30.0), (rpm / 60.0 * 30.0 / 45.0, 50.0)] {
        let (cos, sin) = phasor(&block.time_s, &delta, hz);
        let amplitude_um = cos.hypot(sin) * 1e6;
        assert!(
            (amplitude_um / expected_um - 1.0).abs() < 0.01,
            "{hz} Hz: {amplitude_um} µm, the run-out {expected_um} µm"
        );
        assert!(cos < 0.0, "−R cos θ: {cos}, {sin}");
    }
}

/// The in-phase and quadrature amplitudes of `x` at `hz` over whole periods.
fn phasor(t: &[f64], x: &[f64], hz: f64) -> (f64, f64) {
    let w = 2.0 * std::f64::consts::PI * hz;
    let n = t.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    let (mut c, mut s) = (0.0, 0.0);
    for (&ti, &xi) in t.iter().zip(x) {
        c += (xi - mean) * (w * ti).cos();
        s += (xi - mean) * (w * ti).sin();
    }
    (2.0 * c / n, 2.0 * s / n)
}

/// A mesh without `stiffness_n_per_m` takes its stiffness from its face width by the
/// potential-energy method: one pair always, the mean over the tooth period; alternating
/// pairs, one pair's mean over its single stretch and the double stretch's ratio to it.
/// Both or neither given is refused at the mesh.
#[test]
fn a_face_width_gives_the_mesh_stiffness_by_the_potential_energy_method() {
    use rig::mesh_stiffness::PairGeometry;
    let dir = common::folder("fault-pe-stiffness");
    let path = format!(
        "{}/scenarios/rigs/basmaji-1983.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).expect("rig file");
    let stiffness_line = text
        .lines()
        .find(|l| l.starts_with("stiffness_n_per_m"))
        .expect("the stiffness line")
        .to_string();
    let read = |replacement: &str| {
        let file = dir.path().join("pe.toml");
        std::fs::write(&file, text.replace(&stiffness_line, replacement)).expect("write");
        read_rig_file(&file)
    };
    let geometry = PairGeometry {
        teeth: [30, 30],
        module_m: 0.005,
        pressure_angle_rad: 20f64.to_radians(),
        face_width_m: 0.020,
        addendum_coefficient: 1.0,
        youngs_modulus_pa: 206e9,
        poisson_ratio: 0.3,
        bore_diameter_m: None,
    };
    let lumped = geometry.lumped();
    let single = read("face_width_m = 0.020").expect("a face width");
    assert_eq!(
        single.meshes[0].stiffness_n_per_m,
        lumped.cycle_mean_n_per_m
    );
    let alternating = read("face_width_m = 0.020\npairs = \"alternating\"").expect("alternating");
    let m = &alternating.meshes[0];
    assert_eq!(m.stiffness_n_per_m, lumped.single_n_per_m);
    assert_eq!(m.double_pair_ratio, lumped.double_pair_ratio);
    assert!(
        (1.3..2.0).contains(&m.double_pair_ratio),
        "{}",
        m.double_pair_ratio
    );
    // One pair within 15 % of the thesis's K23 / r_b² (2.62e8 N/m, ISO's c' b).
    let k = m.stiffness_n_per_m;
    assert!((k / 2.617e8 - 1.0).abs() < 0.15, "{k}");
    let both = format!(
        "{:#}",
        read(&format!("{stiffness_line}\nface_width_m = 0.02")).expect_err("both")
    );
    assert!(
        both.contains("not both") && both.contains("stiffness_n_per_m"),
        "{both}"
    );
    let neither = format!("{:#}", read("").expect_err("neither"));
    assert!(
        neither.contains("missing") && neither.contains("face_width_m"),
        "{neither}"
    );
}
