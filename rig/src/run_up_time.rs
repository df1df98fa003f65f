//! The time a drive at its torque limit takes to run a rig up from rest, the same rule
//! for every rig (`RigParams::run_up_from_rest_s`, `NetworkModel::run_up_from_rest_s`).

/// Time (s) a torque of `spare_nm` takes to bring an inertia of `inertia_kgm2` under a
/// drag of `drag_nms_per_rad` from rest to `omega_rad_s`: J dω/dt = spare − c ω rises
/// towards ω∞ = spare / c with time constant J / c; where ω∞ lies at or below the set
/// speed, the time of 99 % of the way to ω∞.
pub fn run_up_time_s(
    inertia_kgm2: f64,
    drag_nms_per_rad: f64,
    spare_nm: f64,
    omega_rad_s: f64,
) -> f64 {
    if drag_nms_per_rad == 0.0 {
        return inertia_kgm2 * omega_rad_s / spare_nm;
    }
    let share = omega_rad_s * drag_nms_per_rad / spare_nm;
    let decays = if share < 0.99 {
        -(1.0 - share).ln()
    } else {
        100f64.ln()
    };
    inertia_kgm2 / drag_nms_per_rad * decays
}
