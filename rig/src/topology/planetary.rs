//! A planetary stage: a sun, a ring and a carrier (bodies of the rig) and N planets on the
//! carrier's pins, each planet in mesh with the sun (an external pair) and the ring (an
//! internal pair). The geometry the planar model needs (Lin & Parker, J. Vib. Acoust.
//! 121(3), 1999): base radii, the carrier's radius to the planet centres, the planets'
//! angles ψ_k, the pressure angle α, and each mesh's line of action. Speeds by rolling on
//! the base circles, r_s ω_s + r_r ω_r = 2 r_c cos α ω_c: Willis's equation
//! ω_s − ω_c = −(z_r/z_s)(ω_r − ω_c) for standard gears. Planets are named `<stage>_planet<k>`,
//! k from 1.

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

use crate::options::MeshPairs;
use crate::tooth_fault::FaultKind;

/// Most planets a stage may have.
pub const MAX_PLANETS: usize = 8;

/// A body's translation on isotropic bearings to the frame (or, for a planet, to its pin
/// on the carrier): with it the body moves in the plane, x and y beside its rotation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanarBearing {
    /// The body's mass (kg).
    pub mass_kg: f64,
    /// The bearing's stiffness in every radial direction (N/m).
    pub stiffness_n_per_m: f64,
    /// The bearing's damping in every radial direction (N s/m).
    pub damping_ns_per_m: f64,
}

/// One of a stage's two kinds of mesh (sun–planet, ring–planet), the same for every
/// planet: a spring-damper along its line of action, apart within the backlash.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StageMesh {
    /// Stiffness along the line of action (N/m).
    pub stiffness_n_per_m: f64,
    /// Damping along the line of action (N s/m).
    pub damping_ns_per_m: f64,
    /// Total circular backlash at the pitch circles (mm).
    pub backlash_mm: f64,
    /// One pair always, or one and two pairs as the contact ratio gives them.
    #[serde(default)]
    pub pairs: MeshPairs,
    /// Stiffness and damping of two pairs over one pair's (with `pairs` alternating).
    #[serde(default = "two")]
    pub double_pair_ratio: f64,
    /// Width of each change between one and two pairs as a fraction of the tooth pitch
    /// (0: sharp), as an external mesh's.
    #[serde(default)]
    pub stiffness_smoothing: f64,
}

/// The default double-pair ratio, 2.
fn two() -> f64 {
    2.0
}

/// A transducer on the ring (an accelerometer on the housing over it, or a strain gauge
/// on the ring gear): each ring–planet mesh force reaches it weighted by a window over
/// the planet's passage (McFadden & Smith 1985; Inalpolat & Kahraman 2009).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RingSensor {
    /// Its place on the ring (rad, from the first planet's place with the carrier at 0,
    /// measured as the planets' angles are).
    pub angle_rad: f64,
    /// The window's full width (rad): a planet further than half of it from the sensor
    /// is not seen.
    pub window_rad: f64,
}

/// A stage's gear: the sun, the ring or planet k (from 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum StageMember {
    /// The sun.
    Sun,
    /// The ring.
    Ring,
    /// Planet k, from 0 (`<stage>_planet<k + 1>`).
    Planet(usize),
}

impl StageMember {
    /// Its name as rig files write it: `sun`, `ring`, `planet<k>` (k from 1).
    pub fn name(self) -> String {
        match self {
            Self::Sun => "sun".into(),
            Self::Ring => "ring".into(),
            Self::Planet(k) => format!("planet{}", k + 1),
        }
    }

    /// The gear named `name` of a stage of `planets` planets.
    pub fn parse(name: &str, planets: usize) -> Option<Self> {
        match name {
            "sun" => Some(Self::Sun),
            "ring" => Some(Self::Ring),
            _ => name
                .strip_prefix("planet")
                .and_then(|k| k.parse::<usize>().ok())
                .filter(|k| (1..=planets).contains(k))
                .map(|k| Self::Planet(k - 1)),
        }
    }
}

/// A fault on one tooth of a stage's sun, ring or planet, acting in every mesh that
/// tooth enters (a sun tooth meets each planet in turn, a planet tooth the sun and the
/// ring, a ring tooth each planet).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StageFault {
    /// The gear whose tooth it is.
    pub member: StageMember,
    /// The tooth, 1..=z of that gear: tooth 1 of the sun and of each planet is in the pair
    /// entering the first planet's sun mesh at the start, tooth 1 of the ring in the pair
    /// entering its ring mesh in that mesh's first period (`StageMeshPhase`); the others
    /// numbered in the order they come into mesh.
    pub tooth: u32,
    /// What it is.
    pub kind: FaultKind,
    /// How bad, 0..=1 (the share the kind names, as a mesh's fault).
    pub severity: f64,
}

/// Teeth of a stage's sun, planets and ring.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct StageTeeth {
    /// Sun's teeth z_s.
    pub sun: u32,
    /// Each planet's teeth z_p.
    pub planet: u32,
    /// Ring's teeth z_r.
    pub ring: u32,
}

/// Base radii of a stage's sun, planets and ring (m).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct StageRadii {
    /// Sun's base radius (m).
    pub sun: f64,
    /// Each planet's base radius (m).
    pub planet: f64,
    /// Ring's base radius (m).
    pub ring: f64,
}

/// A planetary stage.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanetaryStage {
    /// Its name, unique in the rig; its planets are `<name>_planet<k>`.
    pub name: String,
    /// The sun's body (index into the rig's bodies).
    pub sun: usize,
    /// The ring's body.
    pub ring: usize,
    /// The carrier's body.
    pub carrier: usize,
    /// Each planet's angle ψ_k on the carrier (rad).
    pub planet_angles_rad: Vec<f64>,
    /// Each planet's moment of inertia about its pin (kg m²).
    pub planet_inertia_kgm2: f64,
    /// Each planet's pin position error (µm, tangential: positive ahead of its place in
    /// the carrier's turning sense); empty: none.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub planet_pin_errors_um: Vec<f64>,
    /// Each planet's translation on its pin's bearing; `None`: planets held rigidly on
    /// their pins (they move with the carrier).
    pub planet_bearing: Option<PlanarBearing>,
    /// Teeth.
    pub teeth: StageTeeth,
    /// Module (m).
    pub module_m: f64,
    /// Pressure angle of both meshes (degrees).
    pub pressure_angle_deg: f64,
    /// Base radii as a publication gives them; `None`: m z cos α / 2.
    pub base_radii_m: Option<StageRadii>,
    /// Radius of the planets' centres (m); `None`: the centre distance m(z_s + z_p)/2.
    pub carrier_radius_given_m: Option<f64>,
    /// The sun–planet meshes.
    pub sun_planet: StageMesh,
    /// The ring–planet meshes.
    pub ring_planet: StageMesh,
    /// Faults seeded on single teeth.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub faults: Vec<StageFault>,
    /// A transducer on the ring, if the stage has one (its signal `sensor_<stage>_n`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ring_sensor: Option<RingSensor>,
}

/// A mesh's line of action in the plane: the unit vector `n` a positive force pushes
/// the second gear along (the first gear is pushed along −n).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineOfAction {
    /// Its direction (x, y).
    pub n: [f64; 2],
}

impl PlanetaryStage {
    /// Number of planets N.
    pub fn planets(&self) -> usize {
        self.planet_angles_rad.len()
    }

    /// The name of planet `k` (from 0): `<stage>_planet<k + 1>`.
    pub fn planet_name(&self, k: usize) -> String {
        format!("{}_planet{}", self.name, k + 1)
    }

    /// Base radii (m): as given, else m z cos α / 2.
    pub fn radii_m(&self) -> StageRadii {
        self.base_radii_m.unwrap_or_else(|| {
            let cos = self.pressure_angle_deg.to_radians().cos();
            let r = |z: u32| self.module_m * f64::from(z) * cos / 2.0;
            StageRadii {
                sun: r(self.teeth.sun),
                planet: r(self.teeth.planet),
                ring: r(self.teeth.ring),
            }
        })
    }

    /// Radius of the planets' centres (m): as given, else m(z_s + z_p)/2.
    pub fn carrier_radius_m(&self) -> f64 {
        self.carrier_radius_given_m.unwrap_or_else(|| {
            self.module_m * (f64::from(self.teeth.sun) + f64::from(self.teeth.planet)) / 2.0
        })
    }

    /// Equally spaced planet angles 2π k/N (rad).
    pub fn equally_spaced_rad(planets: usize) -> Vec<f64> {
        (0..planets)
            .map(|k| 2.0 * PI * k as f64 / planets as f64)
            .collect()
    }

    /// The sun–planet mesh of planet `k`: the sun, turning positive, pushes the planet
    /// along n = cos α e_t + sin α e_r (e_r, e_t radial and tangential at ψ_k), a line
    /// tangent to both base circles between the centres.
    pub fn sun_line(&self, k: usize) -> LineOfAction {
        let (er, et) = self.axes(k);
        let (s, c) = self.pressure_angle_deg.to_radians().sin_cos();
        LineOfAction {
            n: [c * et[0] + s * er[0], c * et[1] + s * er[1]],
        }
    }

    /// The ring–planet mesh of planet `k`: the planet pushes the ring along
    /// n = −cos α e_t + sin α e_r, tangent to both base circles on the planet's outer side.
    pub fn ring_line(&self, k: usize) -> LineOfAction {
        let (er, et) = self.axes(k);
        let (s, c) = self.pressure_angle_deg.to_radians().sin_cos();
        LineOfAction {
            n: [-c * et[0] + s * er[0], -c * et[1] + s * er[1]],
        }
    }

    /// The radial and tangential unit vectors at planet `k`.
    pub fn axes(&self, k: usize) -> ([f64; 2], [f64; 2]) {
        let (s, c) = self.planet_angles_rad[k].sin_cos();
        ([c, s], [-s, c])
    }

    /// The carrier's speed per unit speed of the sun with the ring held.
    pub fn carrier_per_sun(&self) -> f64 {
        let r = self.radii_m();
        r.sun / self.rolling_m()
    }

    /// 2 r_c cos α (m): the planets roll on the sun's and the ring's base circles, so
    /// that r_s ω_s + r_r ω_r = 2 r_c cos α ω_c (Willis's equation: for standard gears
    /// 2 r_c cos α = r_s + r_r, and ω_s − ω_c = −(z_r/z_s)(ω_r − ω_c)). From the radii,
    /// so that a published model's numbers turn its meshes rigidly too.
    fn rolling_m(&self) -> f64 {
        2.0 * self.carrier_radius_m() * self.pressure_angle_deg.to_radians().cos()
    }

    /// The third of sun, ring and carrier speeds from two (rad/s), by rolling
    /// (Willis's equation, `Self::rolling_m`); `None` where fewer than two are known.
    pub fn willis(
        &self,
        sun: Option<f64>,
        ring: Option<f64>,
        carrier: Option<f64>,
    ) -> Option<[f64; 3]> {
        let r = self.radii_m();
        let (a, b, c) = (r.sun, r.ring, self.rolling_m());
        match (sun, ring, carrier) {
            (Some(s), Some(r), Some(w)) => Some([s, r, w]),
            (Some(s), Some(r), None) => Some([s, r, (a * s + b * r) / c]),
            (Some(s), None, Some(w)) => Some([s, (c * w - a * s) / b, w]),
            (None, Some(r), Some(w)) => Some([(c * w - b * r) / a, r, w]),
            _ => None,
        }
    }

    /// A planet's absolute speed (rad/s) from the sun's and the carrier's: it rolls on
    /// the sun, r_s ω_s + r_p ω_p = r_c cos α ω_c.
    pub fn planet_speed(&self, sun: f64, carrier: f64) -> f64 {
        let r = self.radii_m();
        let rc = self.carrier_radius_m() * self.pressure_angle_deg.to_radians().cos();
        (rc * carrier - r.sun * sun) / r.planet
    }

    /// The planet angle (degrees, from the first) nearest to which planet `k` cannot be
    /// assembled, if it cannot: equal tooth phasing needs (z_s + z_r) ψ_k / 2π whole
    /// (Parker & Lin 2004), within 1e-6 of a tooth.
    pub fn unassemblable(&self) -> Option<(usize, f64)> {
        let teeth = f64::from(self.teeth.sun) + f64::from(self.teeth.ring);
        let first = *self.planet_angles_rad.first()?;
        self.planet_angles_rad
            .iter()
            .enumerate()
            .find_map(|(k, &psi)| {
                let phase = teeth * (psi - first) / (2.0 * PI);
                ((phase - phase.round()).abs() > 1e-6).then_some((k, psi.to_degrees()))
            })
    }

    /// Two neighbouring planets (from 0) whose tips would overlap, with the distance of
    /// their centres and the least it may be, 2 (r_p + m) (mm), if any: the planets' pitch
    /// radius m z_p / 2 plus a standard addendum m. Only for a stage of real geometry (no
    /// base radii given: a published lumped model's numbers are taken as given).
    pub fn overlapping_planets(&self) -> Option<(usize, usize, f64, f64)> {
        if self.base_radii_m.is_some() || self.planets() < 2 {
            return None;
        }
        let least = self.module_m * (f64::from(self.teeth.planet) + 2.0);
        let mut order: Vec<usize> = (0..self.planets()).collect();
        order.sort_by(|&a, &b| self.planet_angles_rad[a].total_cmp(&self.planet_angles_rad[b]));
        let rc = self.carrier_radius_m();
        (0..order.len()).find_map(|i| {
            let (a, b) = (order[i], order[(i + 1) % order.len()]);
            let gap = (self.planet_angles_rad[b] - self.planet_angles_rad[a]).rem_euclid(2.0 * PI);
            let distance = 2.0 * rc * (gap / 2.0).sin();
            (distance < least).then_some((a, b, distance * 1e3, least * 1e3))
        })
    }
}

/// A stage of these teeth (sun, planet, ring) and equally spaced planets at 3 mm, 20°,
/// single pairs of 5e8 N/m, 0.1 mm backlash: the unit tests' example.
#[cfg(test)]
pub(crate) fn example_stage(teeth: [u32; 3], planets: usize) -> PlanetaryStage {
    let mesh = StageMesh {
        stiffness_n_per_m: 5e8,
        damping_ns_per_m: 0.0,
        backlash_mm: 0.1,
        pairs: MeshPairs::Single,
        double_pair_ratio: 2.0,
        stiffness_smoothing: 0.0,
    };
    PlanetaryStage {
        name: "epi".into(),
        sun: 0,
        ring: 1,
        carrier: 2,
        planet_angles_rad: PlanetaryStage::equally_spaced_rad(planets),
        planet_inertia_kgm2: 1e-3,
        planet_pin_errors_um: Vec::new(),
        planet_bearing: None,
        teeth: StageTeeth {
            sun: teeth[0],
            planet: teeth[1],
            ring: teeth[2],
        },
        module_m: 0.003,
        pressure_angle_deg: 20.0,
        base_radii_m: None,
        carrier_radius_given_m: None,
        sun_planet: mesh.clone(),
        ring_planet: mesh,
        faults: Vec::new(),
        ring_sensor: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stage(planets: usize) -> PlanetaryStage {
        example_stage([24, 36, 96], planets)
    }

    /// Willis: the carrier turns at z_s/(z_s + z_r) of the sun with the ring held, the
    /// sun and the ring at opposite speeds hold the carrier at (z_s − z_r)/(z_s + z_r)…
    /// each form of the equation agrees with the others.
    #[test]
    fn willis_forms_agree() {
        let s = stage(3);
        let [_, _, carrier] = s.willis(Some(1.0), Some(0.0), None).unwrap();
        assert!((carrier - 24.0 / 120.0).abs() < 1e-15);
        assert!((s.carrier_per_sun() - carrier).abs() < 1e-15);
        let [sun, _, _] = s.willis(None, Some(0.0), Some(carrier)).unwrap();
        assert!((sun - 1.0).abs() < 1e-14);
        let [_, ring, _] = s.willis(Some(1.0), None, Some(carrier)).unwrap();
        assert!(ring.abs() < 1e-14);
        // Rigid rotation: all three at one speed.
        assert!((s.willis(Some(2.0), Some(2.0), None).unwrap()[2] - 2.0).abs() < 1e-15);
    }

    /// With the ring held a planet rolls on it: its pitch point on the ring is still,
    /// ω_c (r_s + r_p) + ω_p r_p = 0 at the ring's pitch circle (standard gears).
    #[test]
    fn planet_rolls_on_a_held_ring() {
        let s = stage(3);
        let carrier = s.carrier_per_sun();
        let planet = s.planet_speed(1.0, carrier);
        let (rs, rp) = (0.036, 0.054);
        let ring_pitch_speed = carrier * (rs + rp) + planet * rp;
        assert!(ring_pitch_speed.abs() < 1e-15, "{ring_pitch_speed}");
    }

    /// Lines of action are unit vectors at α from the tangent; the sun–planet one pushes
    /// the planet outwards, the ring's pushes the ring outwards.
    #[test]
    fn lines_of_action() {
        let s = stage(4);
        for k in 0..4 {
            let (er, et) = s.axes(k);
            for line in [s.sun_line(k), s.ring_line(k)] {
                let [x, y] = line.n;
                assert!((x.hypot(y) - 1.0).abs() < 1e-15);
                let radial = x * er[0] + y * er[1];
                assert!((radial - 20f64.to_radians().sin()).abs() < 1e-15);
            }
            let tangential = |l: LineOfAction| l.n[0] * et[0] + l.n[1] * et[1];
            assert!(tangential(s.sun_line(k)) > 0.0);
            assert!(tangential(s.ring_line(k)) < 0.0);
        }
    }

    /// Equal spacing assembles where (z_s + z_r)/N is whole (120/N: 3, 4, 5 and 8
    /// planets), not for 7; and an angle off a tooth is found.
    #[test]
    fn assembly() {
        for n in [3, 4, 5, 8] {
            assert_eq!(stage(n).unassemblable(), None, "{n} planets");
        }
        // Planets of 36 teeth on a 90 mm carrier radius: 4 fit (127 mm apart, tips
        // 114 mm across), 5 do not (106 mm).
        assert_eq!(stage(4).overlapping_planets(), None);
        let (_, _, apart_mm, least_mm) = stage(5).overlapping_planets().expect("overlap");
        assert!((apart_mm - 180.0 * 36f64.to_radians().sin()).abs() < 1e-9);
        assert!((least_mm - 114.0).abs() < 1e-9);
        assert_eq!(stage(7).unassemblable().map(|(k, _)| k), Some(1));
        let mut s = stage(3);
        s.planet_angles_rad[2] = 241f64.to_radians();
        assert_eq!(s.unassemblable().map(|(k, _)| k), Some(2));
        // Turned as a whole, a good arrangement stays good.
        s.planet_angles_rad = [10.0, 130.0, 250.0].map(f64::to_radians).to_vec();
        assert_eq!(s.unassemblable(), None);
    }
}
