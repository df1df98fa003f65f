//! The retired thesis plant's runs of the 1983 rig, kept as a reference for the one
//! plant (issue 45): each case is a rig file (the shipped `basmaji-1983` with an option
//! set, or a shipped preset file) under a schedule from steady running, and the thesis
//! plant's run of the same rig as its preset's parameters (`params`), stored in
//! `tests/reference/thesis-plant-1983.json` by `tests/thesis_reference_gen.rs` (commit
//! `3c19348`, the last with that plant): the intermediate shaft's torque every
//! [`TORQUE_EVERY`] samples at 51.2 kHz, its largest magnitude over every sample, and
//! every impact's time.

use rig::{ContactLaw, DriveRatings, MeshPairs, RigParams, RigTopology, Schedule, Track};
use serde::{Deserialize, Serialize};

use super::shipped;

/// Every how many output samples the reference keeps the torque.
pub const TORQUE_EVERY: usize = 128;

/// The reference file, beside the tests.
pub const REFERENCE_FILE: &str = "tests/reference/thesis-plant-1983.json";

/// One run both plants made.
pub struct Case {
    /// Its key in the reference file.
    pub key: String,
    /// The rig the one plant runs.
    pub rig: RigTopology,
    /// The same rig as the thesis plant's parameters.
    pub params: RigParams,
    /// Set points from steady running.
    pub schedule: Schedule,
    /// Length of the run (s).
    pub seconds: f64,
    /// Whether the thesis plant started from the one plant's steady state (with
    /// alternating pairs its own start deflects the mesh for one pair where two are in
    /// mesh).
    pub from_ours: bool,
}

/// The thesis plant's run of a case.
#[derive(Serialize, Deserialize)]
pub struct Reference {
    /// The intermediate shaft's torque every [`TORQUE_EVERY`] samples from the first (N m).
    pub torque_nm: Vec<f64>,
    /// Its largest magnitude over every sample (N m).
    pub torque_scale_nm: f64,
    /// Each impact's time (s).
    pub impacts_s: Vec<f64>,
}

/// The reference file's contents.
#[derive(Serialize, Deserialize)]
pub struct ReferenceFile {
    /// How and where it was made.
    pub made_by: String,
    /// Each case's run, by key.
    pub cases: std::collections::BTreeMap<String, Reference>,
}

/// Reads the reference file.
pub fn read_reference() -> ReferenceFile {
    let path = format!("{}/{REFERENCE_FILE}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("the reference file");
    serde_json::from_str(&text).expect("the reference file parses")
}

/// 600 rev/min under 0.5 N m with 3 N m oscillating at 25 Hz on the brake: the teeth part
/// and strike.
pub fn rattle() -> Schedule {
    Schedule {
        oscillating_load_nm: Track::hold(3.0),
        oscillating_load_hz: Track::hold(25.0),
        ..Schedule::constant(600.0, 0.5)
    }
}

/// 300 rev/min under 2.712 N m stepped to 1100 rev/min at 0.1 s: the motor runs up at
/// its limit, then its speed loop takes over again.
pub fn step() -> Schedule {
    Schedule {
        speed_rpm: Track::hold(300.0).step_to(0.1, 1100.0),
        ..Schedule::constant(300.0, 2.712)
    }
}

/// Every case, in the groups the tests take them.
pub fn cases() -> Vec<Case> {
    let mut all = base_cases();
    for shifting in [true, false] {
        all.extend(spacing_cases(shifting));
        all.extend(no_pull_cases(shifting, ContactLaw::NoPull));
        all.extend(smoothed_cases(shifting, 0.041));
    }
    all.extend(drive_cases());
    all.extend(preset_cases());
    all
}

/// A case of `rig` and `params` under `schedule` for `seconds`.
fn case(
    key: &str,
    rig: &RigTopology,
    params: &RigParams,
    schedule: Schedule,
    seconds: f64,
) -> Case {
    Case {
        key: key.to_string(),
        rig: rig.clone(),
        params: params.clone(),
        schedule,
        seconds,
        from_ours: false,
    }
}

/// The cases `PREFIX-600` (steady at 600 rev/min under 2.712 N m, 2 s) and
/// `PREFIX-rattle` ([`rattle`] for `rattle_s`) of `rig` and `params`.
fn steady_and_rattling(
    prefix: &str,
    rig: &RigTopology,
    params: &RigParams,
    rattle_s: f64,
) -> Vec<Case> {
    let steady = Schedule::constant(600.0, 2.712);
    vec![
        case(&format!("{prefix}-600"), rig, params, steady, 2.0),
        case(&format!("{prefix}-rattle"), rig, params, rattle(), rattle_s),
    ]
}

/// The shipped 1983 file as it is: steady at 600 and 1300 rev/min under 2.712 N m, and
/// rattling. At 1300 rev/min the rattle is so sensitive that the two plants' rounding
/// differs visibly after about a second, so that point runs 0.6 s.
pub fn base_cases() -> Vec<Case> {
    let rig = shipped("basmaji-1983");
    let params = rig::preset("basmaji-1983").expect("preset");
    vec![
        case(
            "base-600",
            &rig,
            &params,
            Schedule::constant(600.0, 2.712),
            3.0,
        ),
        case(
            "base-1300",
            &rig,
            &params,
            Schedule::constant(1300.0, 2.712),
            0.6,
        ),
        case("base-rattle", &rig, &params, rattle(), 0.3),
    ]
}

/// Seeded spacing errors, 10 µm of arc at the pitch circle (10 cos 20° µm along the line
/// of action), seed 1983, with the thesis's tooth shifting or without.
pub fn spacing_cases(shifting: bool) -> Vec<Case> {
    let mut rig = shipped("basmaji-1983");
    let line_of_action_um = 10.0 * 20.0_f64.to_radians().cos();
    rig.set_field("mesh.gears.tooth_spacing_error_um", line_of_action_um)
        .expect("path");
    rig.meshes[0].tooth_spacing_seed = 1983;
    rig.meshes[0].tooth_shifting = shifting;
    let mut params = rig::preset("basmaji-1983").expect("preset");
    params.tooth_spacing_error_um = 10.0;
    params.tooth_spacing_seed = 1983;
    params.tooth_shifting = shifting;
    steady_and_rattling(&format!("spacing-shifting-{shifting}"), &rig, &params, 0.3)
}

/// The no-pull contact law (`law` on the one plant's rig; the thesis plant's runs have
/// no-pull), with tooth shifting or without.
pub fn no_pull_cases(shifting: bool, law: ContactLaw) -> Vec<Case> {
    let mut rig = shipped("basmaji-1983");
    rig.meshes[0].contact_law = law;
    rig.meshes[0].tooth_shifting = shifting;
    let mut params = rig::preset("basmaji-1983").expect("preset");
    params.contact_law = ContactLaw::NoPull;
    params.tooth_shifting = shifting;
    steady_and_rattling(&format!("no-pull-shifting-{shifting}"), &rig, &params, 0.5)
}

/// Alternating pairs with the stiffness change smoothed over `smoothing` of a tooth
/// period on the one plant's rig (the thesis plant's runs: 0.041, the calibrated
/// preset's), with tooth shifting or without; the thesis plant started from ours.
pub fn smoothed_cases(shifting: bool, smoothing: f64) -> Vec<Case> {
    let mut rig = shipped("basmaji-1983");
    rig.meshes[0].pairs = MeshPairs::Alternating;
    rig.meshes[0].stiffness_smoothing = smoothing;
    rig.meshes[0].tooth_shifting = shifting;
    rig.check().expect("valid");
    let mut params = rig::preset("basmaji-1983").expect("preset");
    params.mesh_pairs = MeshPairs::Alternating;
    params.mesh_stiffness_smoothing = 0.041;
    params.tooth_shifting = shifting;
    let prefix = format!("smoothed-shifting-{shifting}");
    let mut cases = steady_and_rattling(&prefix, &rig, &params, 0.5);
    for c in &mut cases {
        c.from_ours = true;
    }
    cases
}

/// The drive rated at 2 hp and 2000 rev/min with a 150 % current limit, the brake's drag
/// (0.6 N m) and critical speed (3375.7 rev/min), the gear-error torques C2 = 1.98 N m and
/// C3 = 0.5 N m: steady at 600 rev/min, and the step.
pub fn drive_cases() -> Vec<Case> {
    let mut rig = shipped("basmaji-1983");
    rig.drive.torque_limit_nm = None;
    rig.drive.ratings = Some(DriveRatings {
        rated_power_w: 2.0 * 745.699_872,
        rated_speed_rpm: 2000.0,
        full_load_current_a: Some(10.0),
        current_limit_pct: 150.0,
    });
    rig.drive.brake_drag_nm = 0.6;
    rig.drive.brake_critical_speed_rpm = 3375.7;
    rig.meshes[0].gear_error_c2_nm = 1.98;
    rig.meshes[0].gear_error_c3_nm = 0.5;
    rig.check().expect("a valid rig");
    let mut params = rig::preset("basmaji-1983").expect("preset");
    params.drive_current_limit_pct = 150.0;
    params.brake_drag_nm = 0.6;
    params.brake_critical_speed_rpm = 3375.7;
    params.gear_error_c2_nm = 1.98;
    params.gear_error_c3_nm = 0.5;
    vec![
        case(
            "drive-600",
            &rig,
            &params,
            Schedule::constant(600.0, 2.712),
            2.0,
        ),
        case("drive-step", &rig, &params, step(), 1.5),
    ]
}

/// Every preset's shipped file, steady at 600 rev/min and stepped, each over 0.4 s
/// (the calibrated rig, chaotic, over 0.15 s); the thesis plant started from ours.
pub fn preset_cases() -> Vec<Case> {
    let mut cases = Vec::new();
    for name in rig::PRESET_NAMES {
        let rig = shipped(name);
        let params = rig::preset(name).expect("preset");
        let seconds = if *name == "basmaji-1983-calibrated" {
            0.15
        } else {
            0.4
        };
        for (key, schedule) in [("600", Schedule::constant(600.0, 2.712)), ("step", step())] {
            let mut c = case(
                &format!("preset-{name}-{key}"),
                &rig,
                &params,
                schedule,
                seconds,
            );
            c.from_ours = true;
            cases.push(c);
        }
    }
    cases
}
