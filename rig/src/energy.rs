//! Mechanical energy of the rig, for energy balances and blow-up checks.

use crate::geometry::GearGeometry;
use crate::params::RigParams;

/// Kinetic energy ½ Σ J ω² (J) of absolute speeds `speed_rad_s`.
pub fn kinetic_energy_j(params: &RigParams, speed_rad_s: &[f64; 5]) -> f64 {
    params
        .inertias_kgm2()
        .iter()
        .zip(speed_rad_s)
        .map(|(j, w)| 0.5 * j * w * w)
        .sum()
}

/// Strain energy ½ K Δθ² (J) of the three shafts at angles `angle_rad`.
pub fn shaft_energy_j(params: &RigParams, angle_rad: &[f64; 5]) -> f64 {
    let springs = [
        (params.k12_input_shaft_nm_per_rad, 0, 1),
        (params.k34_intermediate_shaft_nm_per_rad, 2, 3),
        (params.k45_final_shaft_nm_per_rad, 3, 4),
    ];
    springs
        .iter()
        .map(|&(k, i, j)| 0.5 * k * (angle_rad[i] - angle_rad[j]).powi(2))
        .sum()
}

/// Strain energy ½ K (|d| − B)² (J) of one tooth pair at relative rotation `d_rad` with
/// constant free play (no backlash variation), zero while apart.
pub fn mesh_energy_j(params: &RigParams, d_rad: f64) -> f64 {
    let b = GearGeometry::of(params).half_backlash_rad;
    let overlap = (d_rad.abs() - b).max(0.0);
    0.5 * params.k23_mesh_nm_per_rad * overlap * overlap
}
