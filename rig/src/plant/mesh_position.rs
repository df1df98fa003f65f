//! Where the mesh stands: the overlap of a flank (with the backlash varying once per
//! revolution) and the tooth in mesh at a gear angle.

use crate::model::ModelConstants;

/// Overlap (rad) and its rate (rad/s) of the flank with `sign` (+1 drive, −1 back), from
/// `mesh` = [X2, X3, V2, V3], `harmonics` = [cos φ, sin φ, cos zφ, sin zφ] and the
/// spacing error `spacing_rad` of the pair in mesh: ∓(X3 − X2 − e) − B with
/// B = B₀(1 − C1 cos φ) and the transmission error e = E cos φ + P cos zφ + s.
#[inline(always)]
pub(super) fn flank_overlap(
    mc: &ModelConstants,
    speed_rad_s: f64,
    sign: f64,
    mesh: [f64; 4],
    harmonics: [f64; 4],
    spacing_rad: f64,
) -> (f64, f64) {
    let [x2, x3, v2, v3] = mesh;
    let [cos, sin, _, _] = harmonics;
    let b0 = mc.half_backlash_rad;
    let c1 = mc.backlash_variation;
    let b = b0 * (1.0 - c1 * cos);
    let b_rate = b0 * c1 * speed_rad_s * sin;
    let (e, e_rate) = mc.transmission_error(speed_rad_s, harmonics);
    let e = e + spacing_rad;
    (
        -sign * (x3 - x2 - e) - b,
        -sign * (v3 - v2 - e_rate) - b_rate,
    )
}

/// Tooth in mesh (0..teeth) at driving-gear angle `theta2` (rad), for a pitch in rad.
#[inline]
pub(super) fn tooth_at(theta2: f64, pitch_rad: f64, teeth: f64) -> u32 {
    tooth_of_pitches((theta2 / pitch_rad).floor(), teeth)
}

/// The tooth after a whole number of pitches (as f64), modulo the teeth, in floating
/// point (exact for any count below 2⁵²).
#[inline]
pub(super) fn tooth_of_pitches(pitches: f64, teeth: f64) -> u32 {
    (pitches - teeth * (pitches / teeth).floor()) as u32
}
