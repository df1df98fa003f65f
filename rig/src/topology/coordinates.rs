//! The rig's coordinates and every spring on them, in the planar lumped model of Lin &
//! Parker (J. Vib. Acoust. 121(3), 1999) at zero carrier speed. Each body has its rotation
//! θ (rad, absolute); a body with a bearing in the plane has x and y (m) beside it; each
//! planet of a stage has its rotation (absolute) and, on a bearing, x and y. A body or a
//! planet without one keeps its centre where its axis holds it: a body's still, a
//! planet's on its pin, moving with the carrier.
//!
//! A spring acts on a deflection that is a linear form of the coordinates:
//! - a shaft on θ_a − θ_b, a shaft to the frame on θ;
//! - a bearing on x and on y (a planet's on its centre less its pin's,
//!   (x_c, y_c) + r_c θ_c e_t);
//! - a mesh on δ = r_a θ_a + r_b θ_b + (d_a − d_b)·n, d a gear's centre, n the unit
//!   line of action along which the first gear pushes the second; for a stage's planet
//!   k, δ_sp = r_s θ_s + r_p θ_p + (d_s − d_p)·n_s and δ_rp = r_r θ_r − r_p θ_p + (d_p −
//!   d_r)·n_r (`PlanetaryStage::sun_line`, `ring_line`): Lin & Parker's δ_sn, δ_rn with
//!   u = r θ.
//!
//! The coordinates are every body's rotation, in the bodies' order (body i's is
//! coordinate i), then the translations of the bodies that move in the plane, then every
//! stage's planets' rotations, then their translations: a torsional rig's are its bodies' rotations and its meshes'
//! deflections the torsional r_a θ_a + r_b θ_b.

use super::planetary::{PlanarBearing, PlanetaryStage};
use super::rig_topology::RigTopology;

/// What a coordinate measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoordinateKind {
    /// Rotation (rad), absolute.
    Rotation,
    /// Translation along x (m).
    X,
    /// Translation along y (m).
    Y,
}

/// One coordinate of the rig.
#[derive(Clone, Debug, PartialEq)]
pub struct Coordinate {
    /// The body's or the planet's name.
    pub body: String,
    /// What it measures.
    pub kind: CoordinateKind,
    /// Its inertia: kg m² for a rotation, kg for a translation.
    pub mass: f64,
}

impl Coordinate {
    /// Its name: the body's for a rotation, `<body>.x` and `<body>.y` for translations.
    pub fn name(&self) -> String {
        match self.kind {
            CoordinateKind::Rotation => self.body.clone(),
            CoordinateKind::X => format!("{}.x", self.body),
            CoordinateKind::Y => format!("{}.y", self.body),
        }
    }
}

/// A spring-damper on a linear form of the coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Coupling {
    /// The deflection's terms (coordinate, coefficient): rad or m per unit coordinate.
    pub terms: Vec<(usize, f64)>,
    /// Stiffness on the deflection (N m/rad for a rotation's, N/m for a length's).
    pub stiffness: f64,
    /// Damping on its rate (N m s/rad or N s/m).
    pub damping: f64,
}

/// A mesh's deflection δ along its line of action on either flank, as terms of the
/// coordinates: on flank f (+1 drive, −1 back) δ_f = `turning` + f · `radial`. The
/// rotations and the translations along the tangent (cos α e_t) turn the flank's sense
/// with it; the translations along sin α e_r part the gears on either flank (the two
/// flanks' lines of action are mirror images about the centre line, both separating).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct MeshForm {
    /// The part whose sign follows the flank (m per unit coordinate).
    pub turning: Vec<(usize, f64)>,
    /// The part that parts the gears on either flank (m per unit coordinate).
    pub radial: Vec<(usize, f64)>,
}

impl MeshForm {
    /// The turning part times `sense` (−1 where the driver turns against the motor, so
    /// that the drive flank is the one forward motion presses).
    pub fn sensed(&self, sense: f64) -> Vec<(usize, f64)> {
        self.turning.iter().map(|&(j, c)| (j, c * sense)).collect()
    }

    /// δ on the drive flank: `turning` + `radial`, each coordinate once.
    pub fn drive(&self) -> Vec<(usize, f64)> {
        merged(self.turning.iter().chain(&self.radial).copied().collect())
    }
}

/// Where a gear's coordinates sit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Place {
    /// Its rotation.
    rotation: usize,
    /// Its x (y follows), if it moves in the plane.
    translation: Option<usize>,
}

/// The coordinates of a whole rig.
#[derive(Clone, Debug, PartialEq)]
pub struct RigCoordinates {
    /// Every coordinate: each body's, in order, then each stage's planets'.
    pub coordinates: Vec<Coordinate>,
    bodies: Vec<Place>,
    /// Per stage, per planet.
    planets: Vec<Vec<Place>>,
    /// The first planet's first coordinate (the bodies' come before).
    first_planet: usize,
    /// The end of the planets' rotations (their translations follow).
    planets_turning_end: usize,
}

/// A centre's displacement: its x and its y as linear forms.
type Centre = [Vec<(usize, f64)>; 2];

impl RigCoordinates {
    /// The coordinates of `rig`.
    pub fn of(rig: &RigTopology) -> Self {
        let mut coordinates = Vec::new();
        let c = &mut coordinates;
        // Every body's rotation first: body i's is coordinate i, as in a torsional rig.
        let rotations: Vec<usize> = rig
            .bodies
            .iter()
            .map(|b| push(c, &b.name, CoordinateKind::Rotation, b.inertia_kgm2))
            .collect();
        let bodies = rig
            .bodies
            .iter()
            .zip(rotations)
            .map(|(b, rotation)| Place {
                rotation,
                translation: push_translation(c, &b.name, b.planar.as_ref()),
            })
            .collect();
        let first_planet = c.len();
        // Every planet's rotation, then every planet's translation: the turning parts'
        // rotations stay together, ahead of the translations that ride on the carrier.
        let rotations: Vec<Vec<usize>> = rig
            .planetary
            .iter()
            .map(|s| {
                (0..s.planets())
                    .map(|k| {
                        push(
                            c,
                            &s.planet_name(k),
                            CoordinateKind::Rotation,
                            s.planet_inertia_kgm2,
                        )
                    })
                    .collect()
            })
            .collect();
        let planets_turning_end = c.len();
        let planets = rig
            .planetary
            .iter()
            .zip(rotations)
            .map(|(s, rotations)| {
                rotations
                    .into_iter()
                    .enumerate()
                    .map(|(k, rotation)| Place {
                        rotation,
                        translation: push_translation(
                            c,
                            &s.planet_name(k),
                            s.planet_bearing.as_ref(),
                        ),
                    })
                    .collect()
            })
            .collect();
        Self {
            coordinates,
            bodies,
            planets,
            first_planet,
            planets_turning_end,
        }
    }

    /// Whether any body or planet moves in the plane.
    pub fn translates(&self) -> bool {
        self.coordinates
            .iter()
            .any(|c| c.kind != CoordinateKind::Rotation)
    }

    /// How many coordinates of `rig` are translations (x and y each, of the bodies and
    /// planets on bearings), counted from the rig without building its coordinates: the
    /// columns' lookup asks for it for every column of every block.
    pub fn translation_count(rig: &RigTopology) -> usize {
        let bodies = rig.bodies.iter().filter(|b| b.planar.is_some()).count();
        let planets: usize = rig
            .planetary
            .iter()
            .filter(|s| s.planet_bearing.is_some())
            .map(|s| s.planets())
            .sum();
        2 * (bodies + planets)
    }

    /// Whether coordinate `j` is a planet's.
    pub fn is_planet(&self, j: usize) -> bool {
        j >= self.first_planet
    }

    /// Number of coordinates.
    pub fn len(&self) -> usize {
        self.coordinates.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.coordinates.is_empty()
    }

    /// Each coordinate's inertia (kg m² or kg).
    pub fn masses(&self) -> Vec<f64> {
        self.coordinates.iter().map(|c| c.mass).collect()
    }

    /// Every spring of `rig` on these coordinates, meshes in contact on their drive
    /// flanks: shafts, [`Self::supports`], meshes, then each stage's.
    pub fn couplings(&self, rig: &RigTopology) -> Vec<Coupling> {
        let mut out = Vec::new();
        for s in &rig.shafts {
            let [a, b] = s.between.map(|i| self.bodies[i].rotation);
            out.push(coupling(
                vec![(a, 1.0), (b, -1.0)],
                s.stiffness_nm_per_rad,
                s.damping_nms_per_rad,
            ));
        }
        out.extend(self.supports(rig));
        for (i, m) in rig.meshes.iter().enumerate() {
            out.push(coupling(
                self.mesh_form(rig, i).drive(),
                m.stiffness_n_per_m,
                m.damping_ns_per_m,
            ));
        }
        for (i, stage) in rig.planetary.iter().enumerate() {
            self.stage_couplings(i, stage, &mut out);
        }
        out
    }

    /// What holds bodies to the frame: shafts to it on their rotations, bearings on their
    /// translations.
    pub fn supports(&self, rig: &RigTopology) -> Vec<Coupling> {
        let mut out = Vec::new();
        for s in &rig.frame_shafts {
            let theta = self.bodies[s.body].rotation;
            out.push(coupling(
                vec![(theta, 1.0)],
                s.stiffness_nm_per_rad,
                s.damping_nms_per_rad,
            ));
        }
        for (body, place) in rig.bodies.iter().zip(&self.bodies) {
            if let (Some(bearing), Some(x)) = (&body.planar, place.translation) {
                for axis in [x, x + 1] {
                    out.push(coupling(
                        vec![(axis, 1.0)],
                        bearing.stiffness_n_per_m,
                        bearing.damping_ns_per_m,
                    ));
                }
            }
        }
        out
    }

    /// External mesh `i`'s deflection δ = r_a θ_a + r_b θ_b + (d_a − d_b)·n, with
    /// n = cos α e_t + sin α e_r along its centre line on the drive flank (the driver
    /// turning positive pushes the driven gear along it; translations only where a gear
    /// moves in the plane), as a [`MeshForm`].
    pub fn mesh_form(&self, rig: &RigTopology, i: usize) -> MeshForm {
        let m = &rig.meshes[i];
        let [a, b] = m.gears;
        let [ra, rb] = m.base_radii_m();
        let phi = m.centre_line_deg.to_radians();
        let (s, c) = m.pressure_angle_deg.to_radians().sin_cos();
        let (er, et) = ([phi.cos(), phi.sin()], [-phi.sin(), phi.cos()]);
        let (tangent, radial) = ([c * et[0], c * et[1]], [s * er[0], s * er[1]]);
        let mut turning = vec![(self.bodies[a].rotation, ra), (self.bodies[b].rotation, rb)];
        turning.extend(along(&self.body_centre(a), tangent, 1.0));
        turning.extend(along(&self.body_centre(b), tangent, -1.0));
        let mut parting = along(&self.body_centre(a), radial, 1.0);
        parting.extend(along(&self.body_centre(b), radial, -1.0));
        MeshForm {
            turning: merged(turning),
            radial: merged(parting),
        }
    }

    /// A stage's springs: per planet its bearing on the pin (where it moves in the
    /// plane), its sun–planet and its ring–planet mesh.
    fn stage_couplings(&self, i: usize, stage: &PlanetaryStage, out: &mut Vec<Coupling>) {
        out.extend(self.planet_bearings(i, stage));
        for k in 0..self.planets[i].len() {
            for (ring, m) in [(false, &stage.sun_planet), (true, &stage.ring_planet)] {
                out.push(coupling(
                    self.stage_mesh_form(i, stage, k, ring).drive(),
                    m.stiffness_n_per_m,
                    m.damping_ns_per_m,
                ));
            }
        }
    }

    /// Stage `i`'s planets' bearings on their pins, x then y of each planet that moves in
    /// the plane: its centre less its pin's, (x_c, y_c) + r_c θ_c e_t.
    pub fn planet_bearings(&self, i: usize, stage: &PlanetaryStage) -> Vec<Coupling> {
        let mut out = Vec::new();
        for (k, planet) in self.planets[i].iter().enumerate() {
            let (Some(bearing), Some(x)) = (&stage.planet_bearing, planet.translation) else {
                continue;
            };
            let pin = self.pin_centre(stage, k);
            for (axis, pin_axis) in [(x, &pin[0]), (x + 1, &pin[1])] {
                let mut terms = vec![(axis, 1.0)];
                terms.extend(pin_axis.iter().map(|&(j, v)| (j, -v)));
                out.push(coupling(
                    terms,
                    bearing.stiffness_n_per_m,
                    bearing.damping_ns_per_m,
                ));
            }
        }
        out
    }

    /// Stage `i`'s mesh of planet `k` with the sun (`ring` false) or the ring: δ_sp =
    /// r_s θ_s + r_p θ_p + (d_s − d_p)·n_s, or δ_rp = r_r θ_r − r_p θ_p + (d_p − d_r)·n_r,
    /// as a [`MeshForm`] (a pinned planet's centre its pin's, (x_c, y_c) + r_c θ_c e_t).
    pub fn stage_mesh_form(
        &self,
        i: usize,
        stage: &PlanetaryStage,
        k: usize,
        ring: bool,
    ) -> MeshForm {
        let r = stage.radii_m();
        let planet = &self.planets[i][k];
        let centre = self.planet_centre(planet, self.pin_centre(stage, k));
        let n = if ring {
            stage.ring_line(k).n
        } else {
            stage.sun_line(k).n
        };
        let (er, _) = stage.axes(k);
        let s = stage.pressure_angle_deg.to_radians().sin();
        let radial = [s * er[0], s * er[1]];
        let tangent = [n[0] - radial[0], n[1] - radial[1]];
        // The gear that pushes along n, and the one pushed.
        let (pusher, pushed) = if ring {
            (centre, self.body_centre(stage.ring))
        } else {
            (self.body_centre(stage.sun), centre)
        };
        let mut turning = if ring {
            vec![
                (self.bodies[stage.ring].rotation, r.ring),
                (planet.rotation, -r.planet),
            ]
        } else {
            vec![
                (self.bodies[stage.sun].rotation, r.sun),
                (planet.rotation, r.planet),
            ]
        };
        turning.extend(along(&pusher, tangent, 1.0));
        turning.extend(along(&pushed, tangent, -1.0));
        let mut parting = along(&pusher, radial, 1.0);
        parting.extend(along(&pushed, radial, -1.0));
        MeshForm {
            turning: merged(turning),
            radial: merged(parting),
        }
    }

    /// Planet `k` of stage `i`'s rotation coordinate.
    pub fn planet_rotation(&self, i: usize, k: usize) -> usize {
        self.planets[i][k].rotation
    }

    /// Planet `k` of stage `i`'s x coordinate (y follows), if it moves in the plane.
    pub fn planet_translation(&self, i: usize, k: usize) -> Option<usize> {
        self.planets[i][k].translation
    }

    /// The coordinates past the bodies' translations that are the planets' rotations
    /// (their translations follow).
    pub fn planet_rotations(&self) -> std::ops::Range<usize> {
        self.first_planet..self.planets_turning_end
    }

    /// The coordinates past the bodies' rotations that are translations of bodies (the
    /// planets' come after them).
    pub fn body_translations(&self) -> std::ops::Range<usize> {
        self.bodies.len()..self.first_planet
    }

    /// A body's centre: its x and y where it moves in the plane, else still.
    fn body_centre(&self, body: usize) -> Centre {
        match self.bodies[body].translation {
            Some(x) => [vec![(x, 1.0)], vec![(x + 1, 1.0)]],
            None => [Vec::new(), Vec::new()],
        }
    }

    /// Planet `k`'s pin: the carrier's centre plus r_c θ_c e_t.
    fn pin_centre(&self, stage: &PlanetaryStage, k: usize) -> Centre {
        let [mut x, mut y] = self.body_centre(stage.carrier);
        let (_, et) = stage.axes(k);
        let rc = stage.carrier_radius_m();
        let theta = self.bodies[stage.carrier].rotation;
        x.push((theta, rc * et[0]));
        y.push((theta, rc * et[1]));
        [x, y]
    }

    /// A planet's centre: its own x and y on a bearing, else its pin's.
    fn planet_centre(&self, planet: &Place, pin: Centre) -> Centre {
        match planet.translation {
            Some(x) => [vec![(x, 1.0)], vec![(x + 1, 1.0)]],
            None => pin,
        }
    }
}

/// Adds a coordinate of `name`, returning its index.
fn push(c: &mut Vec<Coordinate>, name: &str, kind: CoordinateKind, mass: f64) -> usize {
    c.push(Coordinate {
        body: name.to_string(),
        kind,
        mass,
    });
    c.len() - 1
}

/// Adds x and y of `name` on `bearing`, if it has one, returning x's index.
fn push_translation(
    c: &mut Vec<Coordinate>,
    name: &str,
    bearing: Option<&PlanarBearing>,
) -> Option<usize> {
    let p = bearing?;
    let x = push(c, name, CoordinateKind::X, p.mass_kg);
    push(c, name, CoordinateKind::Y, p.mass_kg);
    Some(x)
}

/// `sign` · d·n as terms, d a centre's displacement.
fn along(centre: &Centre, n: [f64; 2], sign: f64) -> Vec<(usize, f64)> {
    centre[0]
        .iter()
        .map(|&(j, v)| (j, sign * v * n[0]))
        .chain(centre[1].iter().map(|&(j, v)| (j, sign * v * n[1])))
        .filter(|&(_, v)| v != 0.0)
        .collect()
}

/// A coupling on `terms`, those of one coordinate summed.
fn coupling(terms: Vec<(usize, f64)>, stiffness: f64, damping: f64) -> Coupling {
    Coupling {
        terms: merged(terms),
        stiffness,
        damping,
    }
}

/// `terms` with those of one coordinate summed, in the order each first appears.
fn merged(terms: Vec<(usize, f64)>) -> Vec<(usize, f64)> {
    let mut out: Vec<(usize, f64)> = Vec::with_capacity(terms.len());
    for (j, v) in terms {
        match out.iter_mut().find(|(i, _)| *i == j) {
            Some(t) => t.1 += v,
            None => out.push((j, v)),
        }
    }
    out
}
