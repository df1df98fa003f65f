//! Bodies that move in the plane on their bearings, in the one plant: a free translation
//! rings at √(k/m) exactly; a loaded pair's bearings carry the mesh force along its line
//! of action, as statics says, and keep it in steady motion; energy is conserved through
//! impacts when the mesh acts on translations too (its force applied as its deflection
//! reads them, or energy would leak).

use rig::{
    Body, DriveSettings, Mesh, MeshPairs, NetworkPlant, NetworkStart, PlanarBearing, RigTopology,
    Schedule, Shaft,
};

const RATE_HZ: f64 = 51_200.0;

fn body(name: &str, inertia_kgm2: f64, planar: Option<(f64, f64)>) -> Body {
    Body {
        name: name.into(),
        inertia_kgm2,
        drag_nms_per_rad: 0.0,
        planar: planar.map(|(mass_kg, stiffness_n_per_m)| PlanarBearing {
            mass_kg,
            stiffness_n_per_m,
            damping_ns_per_m: 0.0,
        }),
    }
}

/// A 20/40 pair of 3 mm module, both gears on bearings, its centre line at 30°.
fn pair(damping_ns_per_m: f64) -> Mesh {
    Mesh {
        name: "pair".into(),
        gears: [1, 2],
        teeth: [20, 40],
        module_m: 0.003,
        pressure_angle_deg: 20.0,
        backlash_mm: 0.2,
        centre_distance_shift_mm: 0.0,
        centre_line_deg: 30.0,
        stiffness_n_per_m: 3.0e8,
        damping_ns_per_m,
        pairs: MeshPairs::Single,
        contact_law: Default::default(),
        double_pair_ratio: 2.0,
        stiffness_smoothing: 0.0,
        addendum_coefficient: 1.0,
        backlash_variation: 0.0,
        te_once_per_rev_um: 0.0,
        te_mesh_frequency_um: 0.0,
        tooth_shifting: false,
        run_out_driver_um: 0.0,
        run_out_driven_um: 0.0,
        tooth_spacing_error_um: 0.0,
        tooth_spacing_seed: 0,
        gear_error_c2_nm: 0.0,
        gear_error_c3_nm: 0.0,
        faults: Vec::new(),
        potential_energy: None,
    }
}

/// Motor — shaft — pinion ═ wheel (brake), pinion and wheel on bearings of
/// `bearing_n_per_m`; with `driven` a motor and a brake, else neither.
fn planar_rig(driven: bool, mesh_damping: f64) -> RigTopology {
    RigTopology {
        name: "planar-pair".into(),
        description: String::new(),
        reproduces: None,
        bodies: vec![
            body("motor", 0.01, None),
            body("pinion", 2e-4, Some((0.8, 2.0e8))),
            body("wheel", 3e-3, Some((2.5, 3.0e8))),
        ],
        shafts: vec![Shaft {
            name: "input".into(),
            between: [0, 1],
            stiffness_nm_per_rad: 2000.0,
            damping_nms_per_rad: if driven { 0.05 } else { 0.0 },
        }],
        meshes: vec![pair(mesh_damping)],
        frame_shafts: Vec::new(),
        planetary: Vec::new(),
        motor: driven.then_some(0),
        brake: driven.then_some(2),
        locked_torque: None,
        drive: DriveSettings::default(),
        gauge: None,
        tacho: None,
        keyphasor: None,
    }
}

/// The plant of `rig` at rest, its meshes touching without force.
fn at_rest(rig: &RigTopology) -> NetworkPlant {
    NetworkPlant::new(
        rig,
        Schedule::constant(0.0, 0.0),
        RATE_HZ,
        NetworkStart::Steady,
    )
    .expect("valid plant")
}

/// The line of action of the pair: cos α e_t + sin α e_r along its 30° centre line.
fn line_of_action() -> [f64; 2] {
    let (phi, alpha) = (30f64.to_radians(), 20f64.to_radians());
    [
        -alpha.cos() * phi.sin() + alpha.sin() * phi.cos(),
        alpha.cos() * phi.cos() + alpha.sin() * phi.sin(),
    ]
}

#[test]
fn a_free_translation_rings_at_the_root_of_stiffness_over_mass() {
    // The rig at rest, the teeth touching without force: the wheel knocked across the
    // line of action leaves the mesh's deflection as it is, and rings on its bearing
    // alone, its displacement v/ω sin ωt along the knock.
    let rig = planar_rig(false, 0.0);
    let mut plant = at_rest(&rig);
    // Coordinates: motor, pinion, wheel rotations; pinion x, y; wheel x, y.
    let (wheel_x, n) = (5, 7);
    let line = line_of_action();
    let across = [-line[1], line[0]];
    let v = 1e-4;
    plant.kick(wheel_x, v * across[0]);
    plant.kick(wheel_x + 1, v * across[1]);
    let omega = (3.0e8_f64 / 2.5).sqrt();
    let mut worst = 0.0_f64;
    for k in 1..=2048 {
        plant.skip(1).expect("runs");
        let t = k as f64 / RATE_HZ;
        let q = plant.state_rad();
        for axis in 0..2 {
            let x = q[wheel_x + axis];
            let expected = across[axis] * v / omega * (omega * t).sin();
            worst = worst.max((x - expected).abs() / (v / omega));
            let rate = q[n + wheel_x + axis];
            worst = worst.max((rate - across[axis] * v * (omega * t).cos()).abs() / v);
        }
    }
    eprintln!("MEASURED free translation: worst {worst:e} of the amplitude");
    assert!(worst < 1e-9, "{worst:e}");
    // The teeth stay touching without force: any touch the rounding of the deflection
    // makes is at no speed.
    for impact in plant.take_impacts() {
        assert!(impact.approach_m_s.abs() < 1e-9 * v, "{impact:?}");
    }
}

#[test]
fn loaded_bearings_carry_the_mesh_force_along_its_line_of_action() {
    let rig = planar_rig(true, 2000.0);
    let load_nm = 12.0;
    let mut plant = NetworkPlant::new(
        &rig,
        Schedule::constant(600.0, load_nm),
        RATE_HZ,
        NetworkStart::Steady,
    )
    .expect("valid plant");
    // The wheel's base radius carries the brake's torque: F = T / r_b2.
    let rb2 = 0.003 * 40.0 * 20f64.to_radians().cos() / 2.0;
    let force_n = load_nm / rb2;
    let n = line_of_action();
    let check = |plant: &NetworkPlant, when: &str| {
        let q = plant.state_rad();
        // The pinion is pushed back along −n, the wheel along +n; each bearing holds it.
        let expected = [
            (3, -force_n * n[0] / 2.0e8),
            (4, -force_n * n[1] / 2.0e8),
            (5, force_n * n[0] / 3.0e8),
            (6, force_n * n[1] / 3.0e8),
        ];
        for (j, x) in expected {
            assert!(
                (q[j] - x).abs() < 1e-9 * force_n / 2.0e8,
                "{when}: coordinate {j} at {} m, statics {x} m",
                q[j]
            );
        }
    };
    check(&plant, "the steady start");
    plant.skip((2.0 * RATE_HZ) as usize).expect("runs");
    check(&plant, "after 2 s of steady motion");
}

#[test]
fn energy_is_conserved_through_impacts_with_the_gears_moving_in_the_plane() {
    let rig = planar_rig(false, 0.0);
    let mut plant = at_rest(&rig);
    // The pinion turned against the wheel and both gears knocked sideways: the teeth
    // rattle, the bearings ring.
    plant.kick(1, 2.0);
    plant.kick(2, -0.5);
    plant.kick(3, 0.02);
    plant.kick(6, -0.01);
    let e0 = plant.energy_j();
    let mut worst = 0.0_f64;
    for _ in 0..(2.0 * RATE_HZ) as usize {
        plant.skip(1).expect("runs");
        worst = worst.max((plant.energy_j() - e0).abs() / e0);
    }
    let impacts = plant.take_impacts().len();
    eprintln!("MEASURED planar energy drift {worst:e} of {e0} J over {impacts} impacts");
    assert!(impacts > 20, "only {impacts} impacts");
    assert!(worst < 1e-9, "energy drifts by {worst:e}");
}
