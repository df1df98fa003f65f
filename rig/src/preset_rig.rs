//! A preset's parameters (`RigParams`, the thesis's names: M1..M5, K12..K45, C23 …) as
//! the rig of any topology they describe: the five bodies of the 1983 rig, its three
//! shafts, its one mesh, the motor, the brake and the gauges. Each preset's shipped file
//! (`scenarios/rigs/NAME.toml`) is this rig, held so by a test; the application builds
//! it from parameters where the thesis's names are set (`--set k23_mesh_nm_per_rad=…`, a
//! calibration's preset file).
//!
//! The conversions (docs/rig-files.md): the mesh's torsional K23 and C23 act along the
//! line of action as k = K23 / r_b², c = C23 / r_b² (r_b = m z cos α / 2); the backlash
//! is 2 ΔC tan α at the pitch circle; the transmission errors and spacing errors, given
//! as arcs at the pitch circle, are displacements along the line of action times cos α.

use crate::geometry::GearGeometry;
use crate::params::RigParams;
use crate::topology::{Body, DriveRatings, DriveSettings, Gauge, Mesh, RigTopology, Shaft};

/// Diameter of the gauged intermediate shaft (m): rig-spec §1, 20 mm.
const GAUGED_SHAFT_DIAMETER_M: f64 = 0.020;
/// Shear modulus of the shafts' steel (Pa): EN1A, as the thesis's stiffnesses imply.
const SHAFT_SHEAR_MODULUS_PA: f64 = 82.7e9;

/// The bodies' names, M1..M5.
const BODIES: [&str; 5] = [
    "motor",
    "input_flywheel",
    "driven_gear",
    "output_flywheel",
    "brake",
];

/// The rig `params` describe, named `name` and described by `description`, held against
/// the thesis (`reproduces = "basmaji-1983"`).
pub fn preset_rig(name: &str, description: &str, params: &RigParams) -> RigTopology {
    let bodies = BODIES
        .iter()
        .zip(params.inertias_kgm2())
        .map(|(body, inertia_kgm2)| Body {
            name: (*body).to_string(),
            inertia_kgm2,
            drag_nms_per_rad: params.bearing_drag_nms_per_rad,
            planar: None,
        })
        .collect();
    let shaft = |name: &str, between, k, c| Shaft {
        name: name.to_string(),
        between,
        stiffness_nm_per_rad: k,
        damping_nms_per_rad: c,
    };
    let shafts = vec![
        shaft(
            "input",
            [0, 1],
            params.k12_input_shaft_nm_per_rad,
            params.c12_input_shaft_nms_per_rad,
        ),
        shaft(
            "intermediate",
            [2, 3],
            params.k34_intermediate_shaft_nm_per_rad,
            params.c34_intermediate_shaft_nms_per_rad,
        ),
        shaft(
            "final",
            [3, 4],
            params.k45_final_shaft_nm_per_rad,
            params.c45_final_shaft_nms_per_rad,
        ),
    ];
    RigTopology {
        name: name.to_string(),
        description: description.to_string(),
        reproduces: Some(RigTopology::BASMAJI_1983.to_string()),
        bodies,
        shafts,
        meshes: vec![mesh(params)],
        frame_shafts: Vec::new(),
        planetary: Vec::new(),
        motor: Some(0),
        brake: Some(4),
        locked_torque: None,
        drive: drive(params),
        gauge: Some(Gauge {
            shaft: 1,
            diameter_m: GAUGED_SHAFT_DIAMETER_M,
            shear_modulus_pa: SHAFT_SHEAR_MODULUS_PA,
        }),
        tacho: None,
        keyphasor: None,
    }
}

/// The 1:1 pair between M2 and M3, its torsional values along the line of action.
fn mesh(params: &RigParams) -> Mesh {
    let geometry = GearGeometry::of(params);
    let cos = params.pressure_angle_deg.to_radians().cos();
    let base_radius_m = geometry.pitch_radius_m * cos;
    let along = base_radius_m * base_radius_m;
    Mesh {
        name: "gears".to_string(),
        gears: [1, 2],
        teeth: [params.teeth; 2],
        module_m: params.module_m,
        pressure_angle_deg: params.pressure_angle_deg,
        backlash_mm: geometry.circular_backlash_m * 1e3,
        centre_distance_shift_mm: params.centre_distance_shift_m * 1e3,
        centre_line_deg: 0.0,
        stiffness_n_per_m: params.k23_mesh_nm_per_rad / along,
        damping_ns_per_m: params.c23_mesh_nms_per_rad / along,
        pairs: params.mesh_pairs,
        contact_law: params.contact_law,
        double_pair_ratio: params.double_pair_stiffness_ratio,
        stiffness_smoothing: params.mesh_stiffness_smoothing,
        addendum_coefficient: params.addendum_coefficient,
        backlash_variation: params.backlash_variation_c1,
        te_once_per_rev_um: params.te_once_per_rev_um * cos,
        te_mesh_frequency_um: params.te_mesh_frequency_um * cos,
        tooth_shifting: params.tooth_shifting,
        run_out_driver_um: 0.0,
        run_out_driven_um: 0.0,
        tooth_spacing_error_um: params.tooth_spacing_error_um * cos,
        tooth_spacing_seed: params.tooth_spacing_seed,
        gear_error_c2_nm: params.gear_error_c2_nm,
        gear_error_c3_nm: params.gear_error_c3_nm,
        faults: Vec::new(),
        potential_energy: None,
    }
}

/// The drive's speed loop and ratings, the brake's characteristic and drag.
fn drive(params: &RigParams) -> DriveSettings {
    DriveSettings {
        torque_limit_nm: None,
        ratings: Some(DriveRatings {
            rated_power_w: params.drive_rated_power_w,
            rated_speed_rpm: params.drive_rated_speed_rpm,
            full_load_current_a: Some(params.drive_full_load_current_a),
            current_limit_pct: params.drive_current_limit_pct,
        }),
        speed_loop_hz: params.speed_loop_hz,
        speed_loop_damping_ratio: params.speed_loop_damping_ratio,
        feedback_filter_hz: params.speed_feedback_filter_hz,
        brake_slope_nms_per_rad: params.brake_speed_slope_nms_per_rad,
        brake_drag_nm: params.brake_drag_nm,
        brake_critical_speed_rpm: params.brake_critical_speed_rpm,
    }
}
