//! Where each of a stage's meshes stands in its tooth period, and which teeth it brings
//! together: the contact ratios of the sun–planet (external) and ring–planet (internal)
//! pairs, and the phase of every planet's meshes (Parker & Lin, "Mesh phasing
//! relationships in planetary and epicyclic gears", J. Mech. Des. 126(2), 2004).
//!
//! Every stage mesh's teeth pass at one rate: X, the sun's turn against the carrier in
//! sun pitches, counts them (a planet's teeth pass the sun and the ring at that rate, as do
//! the ring's teeth past a planet). Planet k's sun mesh starts a tooth period (a new pair
//! enters at the start of the line of action) where X − z_s ψ_k/2π is whole, ψ_k from the
//! first planet: Parker & Lin's γ_sk. Its ring mesh follows the planet's teeth half a
//! planet's turn on (z_p/2 teeth), from the sun mesh's pitch point (a_s periods after a
//! pair enters there) to the ring's (a_r periods after one enters), less a tooth's
//! thickness at the pitch circle (half a pitch for standard teeth): the planet, an idler,
//! takes the sun's push on one flank of a tooth and pushes the ring with the other, which
//! leads it by that thickness. Its periods start where X − z_s ψ_k/2π − a_s − z_p/2 + ½ +
//! a_r is whole, so that γ_rk ≡ −z_r ψ_k/2π ((z_s + z_r)ψ_k/2π being whole) and the sun
//! and ring meshes of one planet stand apart by the geometry of their teeth and lines of
//! action. The sun's tooth in mesh with planet k in period p is p, the planet's p, the
//! ring's p + (z_s + z_r)ψ_k/2π: the sun's and the planets' numbered from the pair
//! entering the first planet's sun mesh at X = 0, the ring's from the pair entering its
//! ring mesh in that mesh's period 0, each in the order they come into mesh.
//!
//! The geometry is the teeth's: standard addenda m, pitch radii m z/2 (a stage given
//! published base radii keeps its teeth's phasing).

use std::f64::consts::PI;

use crate::tooth_fault::{FaultedGear, ToothFault};

use super::planetary::{PlanetaryStage, StageMember};

/// A planet tooth's thickness at its pitch circle over the circular pitch: ½ for standard
/// teeth (no profile shift), the lead of the flank that pushes the ring over the one the
/// sun pushes.
const TOOTH_THICKNESS_PITCHES: f64 = 0.5;

/// Where a stage mesh's tooth periods stand.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StageMeshPhase {
    /// The mesh's contact ratio ε (teeth, module, pressure angle, standard addenda).
    pub contact_ratio: f64,
    /// X (sun pitches of the sun's turn against the carrier) where the mesh's tooth
    /// period 0 starts.
    pub start_periods: f64,
    /// The tooth of the driver and of the driven gear in mesh in period 0, less one.
    pub tooth_offsets: [i64; 2],
}

/// A pair's stretch of the line of action on either side of the pitch point, in base
/// pitches: (approach: from the pair's entry to the pitch point, recess: on to its exit).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Stretches {
    approach: f64,
    recess: f64,
}

impl PlanetaryStage {
    /// Where planet `k`'s sun mesh (`ring` false) or ring mesh stands.
    pub fn mesh_phase(&self, k: usize, ring: bool) -> StageMeshPhase {
        let turns = (self.planet_angles_rad[k] - self.planet_angles_rad[0]) / (2.0 * PI);
        let (zs, zp, zr) = (
            f64::from(self.teeth.sun),
            f64::from(self.teeth.planet),
            f64::from(self.teeth.ring),
        );
        let sun = self.stretches(false);
        let sun_start = zs * turns;
        if !ring {
            return StageMeshPhase {
                contact_ratio: sun.approach + sun.recess,
                start_periods: sun_start,
                tooth_offsets: [0, 0],
            };
        }
        let ring_stretch = self.stretches(true);
        StageMeshPhase {
            contact_ratio: ring_stretch.approach + ring_stretch.recess,
            start_periods: sun_start + sun.approach + zp / 2.0
                - TOOTH_THICKNESS_PITCHES
                - ring_stretch.approach,
            tooth_offsets: [0, ((zs + zr) * turns).round() as i64],
        }
    }

    /// The stage's faults on the teeth planet `k`'s sun mesh (`ring` false) or ring mesh
    /// brings together, as that mesh's driver's or driven gear's (a ring tooth's crack
    /// as an external gear's of z_r teeth: the potential-energy method is an external
    /// tooth's).
    pub fn mesh_faults(&self, k: usize, ring: bool) -> Vec<ToothFault> {
        self.faults
            .iter()
            .filter_map(|f| {
                let gear = match (f.member, ring) {
                    (StageMember::Sun, false) => FaultedGear::Driver,
                    (StageMember::Planet(j), false) if j == k => FaultedGear::Driven,
                    (StageMember::Planet(j), true) if j == k => FaultedGear::Driver,
                    (StageMember::Ring, true) => FaultedGear::Driven,
                    _ => return None,
                };
                Some(ToothFault {
                    gear,
                    tooth: f.tooth,
                    kind: f.kind,
                    severity: f.severity,
                })
            })
            .collect()
    }

    /// The sun–planet pair's stretches (the sun driving: the pair enters at the planet's
    /// tip), or the ring–planet pair's (the planet driving: it enters at the ring's tip).
    fn stretches(&self, ring: bool) -> Stretches {
        let m = self.module_m;
        let (sin, cos) = self.pressure_angle_deg.to_radians().sin_cos();
        let base_pitch = PI * m * cos;
        // Along the line of action from a gear's base tangent point to where its tip
        // circle (radius `tip`) cuts it, less the stretch to the pitch point.
        let past_pitch = |z: u32, tip: f64| {
            let pitch = m * f64::from(z) / 2.0;
            (tip.powi(2) - (pitch * cos).powi(2)).sqrt() - pitch * sin
        };
        let planet_tip = past_pitch(
            self.teeth.planet,
            m * f64::from(self.teeth.planet) / 2.0 + m,
        );
        if ring {
            let ring_tip = -past_pitch(self.teeth.ring, m * f64::from(self.teeth.ring) / 2.0 - m);
            Stretches {
                approach: ring_tip / base_pitch,
                recess: planet_tip / base_pitch,
            }
        } else {
            let sun_tip = past_pitch(self.teeth.sun, m * f64::from(self.teeth.sun) / 2.0 + m);
            Stretches {
                approach: planet_tip / base_pitch,
                recess: sun_tip / base_pitch,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stage(teeth: [u32; 3], planets: usize) -> PlanetaryStage {
        crate::topology::planetary::example_stage(teeth, planets)
    }

    /// The contact ratios are the textbook's (√(ra₁² − rb₁²) ± √(ra₂² − rb₂²) ∓ a sin α)/p_b,
    /// with a = r_s + r_p for the external pair and a = r_r − r_p for the internal one,
    /// worked out here for 24/36/96 at 3 mm, 20°.
    #[test]
    fn contact_ratios() {
        let s = stage([24, 36, 96], 3);
        let (sin, cos) = 20f64.to_radians().sin_cos();
        let (rs, rp, rr, m) = (0.036, 0.054, 0.144, 0.003);
        let reach = |r: f64, tip: f64| (tip.powi(2) - (r * cos).powi(2)).sqrt();
        let base_pitch = PI * m * cos;
        let external = (reach(rs, rs + m) + reach(rp, rp + m) - (rs + rp) * sin) / base_pitch;
        let internal = (reach(rp, rp + m) - reach(rr, rr - m) + (rr - rp) * sin) / base_pitch;
        assert!((s.mesh_phase(0, false).contact_ratio - external).abs() < 1e-12);
        assert!((s.mesh_phase(0, true).contact_ratio - internal).abs() < 1e-12);
        assert!((1.6..1.7).contains(&external), "{external}");
        assert!((1.9..2.0).contains(&internal), "{internal}");
    }

    /// Parker & Lin's phases: the sun meshes stand z_s ψ_k/2π apart, the ring meshes
    /// −z_r ψ_k/2π, both whole (in phase) where z_s/N is whole and spread over the
    /// period where it is not; the ring's tooth offsets are (z_s + z_r)ψ_k/2π.
    #[test]
    fn planets_phase_as_parker_and_lin() {
        for (teeth, in_phase) in [([24, 36, 96], true), ([25, 35, 95], false)] {
            let s = stage(teeth, 3);
            for k in 0..3 {
                let turns = k as f64 / 3.0;
                let sun =
                    s.mesh_phase(k, false).start_periods - s.mesh_phase(0, false).start_periods;
                let ring =
                    s.mesh_phase(k, true).start_periods - s.mesh_phase(0, true).start_periods;
                let gamma_s = f64::from(teeth[0]) * turns;
                let gamma_r = -f64::from(teeth[2]) * turns;
                assert!((sun - gamma_s).abs() < 1e-12);
                assert!(((ring - gamma_r) - (ring - gamma_r).round()).abs() < 1e-12);
                assert_eq!(
                    (sun - sun.round()).abs() < 1e-12,
                    in_phase || k == 0,
                    "{teeth:?} planet {k}: {sun}"
                );
                let offset = s.mesh_phase(k, true).tooth_offsets[1];
                assert_eq!(
                    offset,
                    (f64::from(teeth[0] + teeth[2]) * turns).round() as i64
                );
            }
        }
    }
}
