//! What a transducer on a planetary stage's ring sees (McFadden & Smith, "An explanation
//! for the asymmetry of the modulation sidebands about the tooth meshing frequency in
//! epicyclic gear vibration", Proc. IMechE C 199, 1985; Inalpolat & Kahraman, "A
//! theoretical and experimental investigation of modulation sidebands of planetary gear
//! sets", J. Sound Vib. 323, 2009): each ring–planet mesh force reaches it weighted by a
//! window over the planet's passage, a Hann window w(d) = ½(1 + cos 2πd/W) of full width W
//! in the planet's angular distance d from the sensor (0 beyond W/2). The planets travel
//! with the carrier, so the window turns the mesh forces' lines into sidebands at
//! multiples of the planet-pass frequency N f_c. Only the ring meshes' forces reach it
//! (the sun's pass through the planets' bearings and the carrier, not the ring).

use std::f64::consts::PI;

use crate::topology::{PlanetaryStage, RingSensor};

/// The window's weight at angular distance `distance_rad` (wrapped to [−π, π], by the
/// nearest whole turn: a rounding, cheaper than a remainder) for a full width
/// `width_rad`.
pub fn passage_window(distance_rad: f64, width_rad: f64) -> f64 {
    let d = distance_rad - 2.0 * PI * (distance_rad / (2.0 * PI)).round();
    if d.abs() >= width_rad / 2.0 {
        0.0
    } else {
        0.5 * (1.0 + (2.0 * PI * d / width_rad).cos())
    }
}

/// The sensor's signal (N) at each sample: Σ_k w(θ_c + ψ_k − ψ_1 − φ) F_rk, the carrier's
/// angle θ_c (rad, in the direction the planets' angles are measured) and each planet's
/// ring mesh force F_rk (N) per sample.
pub fn ring_sensor_n(
    stage: &PlanetaryStage,
    sensor: &RingSensor,
    carrier_angle_rad: &[f64],
    ring_forces_n: &[&[f64]],
) -> Vec<f64> {
    let first = stage.planet_angles_rad[0];
    (0..carrier_angle_rad.len())
        .map(|n| {
            ring_forces_n
                .iter()
                .zip(&stage.planet_angles_rad)
                .map(|(force, psi)| {
                    let place = carrier_angle_rad[n] + psi - first;
                    passage_window(place - sensor.angle_rad, sensor.window_rad) * force[n]
                })
                .sum()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The window is 1 over the sensor, ½ a quarter width off, 0 from half its width on,
    /// and wraps round the ring.
    #[test]
    fn the_window_over_a_planets_passage() {
        let w = 2.0 * PI / 3.0;
        assert_eq!(passage_window(0.0, w), 1.0);
        assert!((passage_window(w / 4.0, w) - 0.5).abs() < 1e-15);
        assert_eq!(passage_window(w / 2.0, w), 0.0);
        assert!((passage_window(2.0 * PI + w / 4.0, w) - 0.5).abs() < 1e-12);
        assert!((passage_window(-w / 4.0, w) - 0.5).abs() < 1e-15);
    }
}
