//! Named parameter sets.

use crate::error::RigError;
use crate::geometry::centre_distance_shift_m;
use crate::options::{ContactLaw, MeshPairs};
use crate::params::RigParams;

/// Names of every preset, in the order `testrig params` lists them.
pub const PRESET_NAMES: &[&str] = &[
    "basmaji-1983",
    "basmaji-1983-calibrated",
    "basmaji-1983-drive",
    "basmaji-1983-hand",
    "basmaji-1983-rig",
];

/// The preset every front door uses where none is named (the CLI's `--preset`, a
/// scenario without `[rig] preset`, Python's `preset=`): the thesis's own numbers.
pub const DEFAULT_PRESET: &str = "basmaji-1983";

/// 2 hp (W).
const TWO_HP_W: f64 = 2.0 * 745.699_872;
/// Top of the rig's speed range (rev/min), taken as the motor's base speed.
const BASE_SPEED_RPM: f64 = 2000.0;
/// The motor's full-load current (A), from its nameplate (rig-spec §1: F.L.C. 10.0 A).
const FULL_LOAD_CURRENT_A: f64 = 10.0;

/// Looks a preset up by name.
pub fn preset(name: &str) -> Result<RigParams, RigError> {
    match name {
        "basmaji-1983" => Ok(basmaji_1983()),
        "basmaji-1983-calibrated" => Ok(basmaji_1983_calibrated()),
        "basmaji-1983-hand" => Ok(basmaji_1983_hand()),
        "basmaji-1983-rig" => Ok(basmaji_1983_rig()),
        "basmaji-1983-drive" => Ok(basmaji_1983_drive()),
        _ => Err(RigError::UnknownPreset {
            name: name.to_string(),
            known: PRESET_NAMES.join(", "),
        }),
    }
}

/// The thesis's own numbers (rig-spec §1–2; Basmaji 1983, App. B, App. C, §5.4.3, §6.5.1).
///
/// Choices where the thesis is silent: addendum 1.0 m (standard teeth); C2 = C3 = 0 (not
/// given); the speed loop (0.5 Hz, ζ 0.7, 2 Hz feedback filter) is slow enough that the
/// motor acts as the thesis's constant torque F1 at the rig's natural frequencies while
/// still holding the mean speed; the torque limit is 2 hp at 2000 rev/min; the brake torque
/// does not depend on speed, as the thesis's F1.
pub fn basmaji_1983() -> RigParams {
    RigParams {
        j1_motor_kgm2: 0.0163,
        j2_input_flywheel_kgm2: 0.355,
        j3_driven_gear_kgm2: 0.00865,
        j4_output_flywheel_kgm2: 0.45,
        j5_brake_kgm2: 0.015,
        k12_input_shaft_nm_per_rad: 5196.2,
        k23_mesh_nm_per_rad: 1.3e6,
        k34_intermediate_shaft_nm_per_rad: 2598.1,
        k45_final_shaft_nm_per_rad: 4330.2,
        c12_input_shaft_nms_per_rad: 0.1473,
        c23_mesh_nms_per_rad: 135.8,
        c34_intermediate_shaft_nms_per_rad: 0.0946,
        c45_final_shaft_nms_per_rad: 0.1589,
        teeth: 30,
        module_m: 5.0e-3,
        pressure_angle_deg: 20.0,
        addendum_coefficient: 1.0,
        centre_distance_shift_m: 1.0e-3,
        contact_law: ContactLaw::Thesis,
        tooth_shifting: true,
        backlash_variation_c1: 0.38,
        gear_error_c2_nm: 0.0,
        gear_error_c3_nm: 0.0,
        mesh_pairs: MeshPairs::Single,
        double_pair_stiffness_ratio: 2.0,
        mesh_stiffness_smoothing: 0.0,
        speed_loop_hz: 0.5,
        speed_loop_damping_ratio: 0.7,
        speed_feedback_filter_hz: 2.0,
        drive_rated_power_w: TWO_HP_W,
        drive_rated_speed_rpm: BASE_SPEED_RPM,
        drive_full_load_current_a: FULL_LOAD_CURRENT_A,
        drive_current_limit_pct: 100.0,
        brake_speed_slope_nms_per_rad: 0.0,
        brake_drag_nm: 0.0,
        bearing_drag_nms_per_rad: 0.0,
        brake_critical_speed_rpm: 0.0,
        te_once_per_rev_um: 0.0,
        te_mesh_frequency_um: 0.0,
        tooth_spacing_error_um: 0.0,
        tooth_spacing_seed: 1983,
    }
}

/// The thesis's rig with what the thesis does not give chosen against its findings by
/// `testrig calibrate` (docs/calibration.md): the best of the second search, 165
/// evaluations of CMA-ES over twelve parameters started from a scan of the profile error
/// at mesh frequency, as the search wrote them (the verdicts at the campaign's chaotic
/// points change with the last digits). Its inertias and shaft stiffnesses stay the
/// thesis's; the search chose a mesh stiffness of 2.0e6 N m/rad (the thesis 1.3e6; ISO
/// 6336-1 gives 1.6e6 for one pair of these gears), a low mesh damping, two tooth pairs
/// alternating with the contact ratio, a larger backlash variation, a once-per-revolution
/// error as a torque (C2) and as a transmission error, a 5.5 µm profile error at mesh
/// frequency, a residual and speed-proportional drag, and an eddy-current brake whose
/// torque peaks at 3376 rev/min. Tooth shifting stays as in the thesis.
///
/// Its backlash is the experiments' 0.73 mm exactly (the thesis's 1.0 mm centre-distance
/// setting gives 0.728 mm), so that it is the rig of the campaign's scenarios, which set
/// `backlash_mm = 0.73`: at the campaign's chaotic points a 0.3 % change of backlash
/// changes which motion the rig settles to.
pub fn basmaji_1983_calibrated() -> RigParams {
    let thesis = basmaji_1983();
    RigParams {
        k23_mesh_nm_per_rad: 2010263.9471880835,
        c23_mesh_nms_per_rad: 12.355688409564184,
        backlash_variation_c1: 0.5079671754037532,
        gear_error_c2_nm: 1.9786607525027597,
        mesh_pairs: MeshPairs::Alternating,
        mesh_stiffness_smoothing: 0.041031409888747754,
        brake_drag_nm: 0.6223084084948766,
        bearing_drag_nms_per_rad: 0.0007643615115723883,
        brake_critical_speed_rpm: 3375.6991064508375,
        te_once_per_rev_um: 23.790484486731927,
        te_mesh_frequency_um: 5.5160248759352495,
        centre_distance_shift_m: centre_distance_shift_m(&thesis, EXPERIMENT_BACKLASH_M),
        ..thesis
    }
}

/// Total circular backlash of the experiments (m): rig-spec §4, 0.73 mm.
pub const EXPERIMENT_BACKLASH_M: f64 = 0.73e-3;

/// The calibration chosen by hand before the search (docs/calibration.md, "Before the
/// search"): the thesis's rig with a residual drag at the brake (0.3 N m) and a
/// once-per-revolution gear error torque (C2 = 0.5 N m). With it the rig's
/// once-per-revolution resonance falls at the measured fundamental's running speed
/// (≈ 780 rev/min), which the searched preset, not asked for it, does not keep.
pub fn basmaji_1983_hand() -> RigParams {
    let thesis = basmaji_1983();
    RigParams {
        brake_drag_nm: 0.3,
        gear_error_c2_nm: 0.5,
        centre_distance_shift_m: centre_distance_shift_m(&thesis, EXPERIMENT_BACKLASH_M),
        ..thesis
    }
}

/// The thesis's rig chosen by its motion (`docs/physics.md`): the thesis's inertias,
/// stiffnesses, mesh and backlash variation, with three changes each chosen by physical
/// reasoning and checked on the lab's run of the campaign by the physics judge, one at a
/// time, before any search:
/// - no numerical tooth shifting: handing a pair's deflection back at every tooth pass is
///   the thesis's numerical device (§5.4.5), not something the gears do;
/// - a residual drag of 0.6 N m at the brake (bearings, seals, slip rings, windage and
///   the brake's remanence at a dial of 0 lbf ft), so that the teeth stay on the drive
///   flank at "0 N m" as on a real rig;
/// - joint damping in the shafts' keyed hubs: 0.6 N m s/rad in the input shaft and
///   1.0 N m s/rad in the intermediate shaft (the fundamental's damping ratio 2.1 %
///   instead of the thesis's 0.2 %, within the 1-5 % usual for assembled drive lines).
///
/// It keeps the calculated fundamental of 17.84 Hz: with the backlash its once-per-
/// revolution resonance falls at 750-850 rev/min, the rig's "measured fundamental" of
/// 13.33 Hz; shafts softened to put the linear fundamental at 13.33 Hz move the
/// half-order band down to 750-1500 rev/min (`docs/physics.md`).
pub fn basmaji_1983_rig() -> RigParams {
    let thesis = basmaji_1983();
    RigParams {
        tooth_shifting: false,
        brake_drag_nm: 0.6,
        c12_input_shaft_nms_per_rad: 0.6,
        c34_intermediate_shaft_nms_per_rad: 1.0,
        centre_distance_shift_m: centre_distance_shift_m(&thesis, EXPERIMENT_BACKLASH_M),
        ..thesis
    }
}

/// The rig chosen by its motion (`basmaji-1983-rig`) with its drive as built and the
/// residual drag and backlash variation that drive can carry (issue 34, `docs/physics.md`,
/// "The drive as built"): the armature current limit at 150 % of full-load current
/// (10.68 N m; a 1983 thyristor drive's usual setting for intermittent duty, where the
/// nameplate's 100 % had bounded the torque at 7.12 N m), a residual drag of 4.0 N m,
/// and C1 = 0.6. Chosen by scanning the current limit (100, 150, 200 %), the drag (0.6 …
/// 5 N m) and C1 (0.38 … 0.6) on the lab campaign's every approach: the best scan point,
/// so its scores are fitted on the same 75 points they are counted on.
pub fn basmaji_1983_drive() -> RigParams {
    RigParams {
        drive_current_limit_pct: 150.0,
        brake_drag_nm: 4.0,
        backlash_variation_c1: 0.6,
        ..basmaji_1983_rig()
    }
}
