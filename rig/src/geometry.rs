//! Gear geometry: pitch radius, backlash from the centre-distance shift (and the shift
//! for a backlash), contact ratio.

use std::f64::consts::PI;

use crate::params::RigParams;

/// Quantities derived from the gear data of a [`RigParams`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GearGeometry {
    /// Pitch radius r = m z / 2 (m).
    pub pitch_radius_m: f64,
    /// Angular pitch, one tooth: 2π / z (rad).
    pub tooth_pitch_rad: f64,
    /// Total circular backlash at the pitch circle 2B₁ = 2 ΔC tan α (m).
    pub circular_backlash_m: f64,
    /// Free play B each side of centre, as relative rotation: B₁ / r (rad).
    pub half_backlash_rad: f64,
    /// Transverse contact ratio at the operating centre distance (dimensionless).
    pub contact_ratio: f64,
}

impl GearGeometry {
    /// Derives the geometry of the 1:1 pair of `params`.
    ///
    /// Contact ratio of two equal external spur gears at the operating centre distance
    /// a = 2r + ΔC (operating pressure angle cos α_w = 2 r_b / a):
    /// ε = [2 √(r_a² − r_b²) − a sin α_w] / (π m cos α), r_a = r + h_a m, r_b = r cos α.
    pub fn of(params: &RigParams) -> Self {
        let z = f64::from(params.teeth);
        let m = params.module_m;
        let alpha = params.pressure_angle_deg.to_radians();
        let r = m * z / 2.0;
        let r_base = r * alpha.cos();
        let r_tip = r + params.addendum_coefficient * m;
        let centre = 2.0 * r + params.centre_distance_shift_m;
        let alpha_w = (2.0 * r_base / centre).acos();
        let path = 2.0 * (r_tip * r_tip - r_base * r_base).sqrt() - centre * alpha_w.sin();
        let base_pitch = PI * m * alpha.cos();
        let circular_backlash_m = 2.0 * params.centre_distance_shift_m * alpha.tan();
        Self {
            pitch_radius_m: r,
            tooth_pitch_rad: 2.0 * PI / z,
            circular_backlash_m,
            half_backlash_rad: circular_backlash_m / 2.0 / r,
            contact_ratio: path / base_pitch,
        }
    }

    /// Fraction of each tooth period with two pairs in contact: ε − 1, clamped to [0, 1].
    pub fn double_pair_fraction(&self) -> f64 {
        (self.contact_ratio - 1.0).clamp(0.0, 1.0)
    }
}

/// Centre-distance shift ΔC (m) that gives a total circular backlash of
/// `circular_backlash_m` (m) at the pitch circle of `params`' gears: 2B₁ = 2 ΔC tan α
/// (rig-spec §1), the inverse of [`GearGeometry::circular_backlash_m`].
pub fn centre_distance_shift_m(params: &RigParams, circular_backlash_m: f64) -> f64 {
    circular_backlash_m / (2.0 * params.pressure_angle_deg.to_radians().tan())
}
