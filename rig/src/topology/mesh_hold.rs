//! The natural modes of a rig with its meshes held one of three ways, as the thesis's
//! App. C takes its rig: in contact on their springs (`modes.rs`), rigid (each mesh's
//! gears turn as one coordinate in the ratio of their base radii, so an external pair's
//! r_b1 θ1 + r_b2 θ2 stays 0), or apart (the rig falls into the parts its shafts join,
//! each with its own rigid-body mode left out). App. C's "whole rig" is the rigid form
//! with the driven gear's inertia left out; here every inertia counts. Rigid and apart
//! are forms of a torsional rig: a rig with planetary stages or bodies that move in the
//! plane has its modes in contact only.

use nalgebra::DMatrix;

use super::coordinates::RigCoordinates;
use super::modes::add_coupling;
use super::rig_topology::RigTopology;
use crate::modal::{NaturalMode, free_modes};

/// How a modal analysis holds the meshes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshHold {
    /// Every mesh in contact on its spring.
    Contact,
    /// Every mesh rigid: its gears turn together in the ratio of their base radii.
    Rigid,
    /// Every mesh apart: each part the shafts join moves on its own.
    Apart,
}

/// The flexible modes of bodies that move together.
#[derive(Clone, Debug, PartialEq)]
pub struct ModalPart {
    /// Each coordinate's bodies (names): one body (`<body>.x`, `<body>.y` for its
    /// translations in the plane), or the gears a rigid mesh joins and the bodies on them.
    pub coordinates: Vec<Vec<String>>,
    /// The flexible modes, ascending; each shape gives the coordinates' amplitudes
    /// (rad per rad of the coordinate's first body), the largest scaled to 1.
    pub modes: Vec<NaturalMode>,
}

/// Each body's coordinate and its angle per unit of that coordinate, and the part it
/// moves in.
struct Coordinates {
    of_body: Vec<(usize, f64)>,
    count: usize,
    part_of: Vec<usize>,
    parts: usize,
}

impl RigTopology {
    /// Whether the rig turns about fixed axes alone: no planetary stage, no body on a
    /// bearing in the plane.
    pub fn is_torsional(&self) -> bool {
        self.planetary.is_empty() && self.bodies.iter().all(|b| b.planar.is_none())
    }

    /// The rig's flexible modes with its meshes held as `hold` says: one part in contact
    /// or rigid (a checked rig is connected), the parts the shafts join when apart (a
    /// part of one body is left out: it has no flexible mode, or held to the frame only
    /// its own on that shaft). Rigid and apart give no
    /// part for a rig that is not torsional ([`Self::is_torsional`]).
    pub fn modal_parts(&self, hold: MeshHold) -> Vec<ModalPart> {
        if hold != MeshHold::Contact && !self.is_torsional() {
            return Vec::new();
        }
        match hold {
            MeshHold::Contact => vec![ModalPart {
                coordinates: RigCoordinates::of(self)
                    .coordinates
                    .iter()
                    .map(|c| vec![c.name()])
                    .collect(),
                modes: self.natural_modes(),
            }],
            MeshHold::Rigid => vec![self.part(&self.rigid_coordinates(), 0)],
            MeshHold::Apart => {
                let apart = self.shaft_parts();
                (0..apart.parts)
                    .map(|p| self.part(&apart, p))
                    .filter(|part| part.coordinates.len() > 1)
                    .collect()
            }
        }
    }

    /// The modes over `coordinates` of the bodies of part `part`, with the shafts as
    /// springs (the meshes rigid or apart).
    fn part(&self, coordinates: &Coordinates, part: usize) -> ModalPart {
        let in_part = |body: usize| coordinates.part_of[body] == part;
        // Renumber the coordinates this part holds, in the order of their first body.
        let mut index = vec![usize::MAX; coordinates.count];
        let mut names: Vec<Vec<String>> = Vec::new();
        let mut inertia: Vec<f64> = Vec::new();
        for (body, &(c, ratio)) in coordinates.of_body.iter().enumerate() {
            if !in_part(body) {
                continue;
            }
            if index[c] == usize::MAX {
                index[c] = names.len();
                names.push(Vec::new());
                inertia.push(0.0);
            }
            names[index[c]].push(self.bodies[body].name.clone());
            inertia[index[c]] += self.bodies[body].inertia_kgm2 * ratio * ratio;
        }
        let mut k = DMatrix::zeros(names.len(), names.len());
        for s in self.shafts.iter().filter(|s| in_part(s.between[0])) {
            let [(ca, ra), (cb, rb)] = s.between.map(|b| coordinates.of_body[b]);
            add_coupling(
                &mut k,
                &[(index[ca], ra), (index[cb], -rb)],
                s.stiffness_nm_per_rad,
            );
        }
        let mut held = false;
        for s in self.frame_shafts.iter().filter(|s| in_part(s.body)) {
            let (c, ratio) = coordinates.of_body[s.body];
            add_coupling(&mut k, &[(index[c], ratio)], s.stiffness_nm_per_rad);
            held = true;
        }
        ModalPart {
            // A part turns freely unless a shaft holds it to the frame.
            modes: free_modes(&k, &inertia, usize::from(!held)),
            coordinates: names,
        }
    }

    /// The coordinates with every mesh rigid: each group of gears the meshes join is one
    /// coordinate, the angle of its first body; another gear turns at −r_b1/r_b2 of the
    /// gear it meshes with.
    fn rigid_coordinates(&self) -> Coordinates {
        let links = self.meshes.iter().map(|m| {
            let [ra, rb] = m.base_radii_m();
            (m.gears, -ra / rb)
        });
        let (of_body, count) = groups(self.bodies.len(), links.collect());
        Coordinates {
            part_of: vec![0; of_body.len()],
            of_body,
            count,
            parts: 1,
        }
    }

    /// The parts the shafts join with every mesh apart, each body its own coordinate.
    fn shaft_parts(&self) -> Coordinates {
        let n = self.bodies.len();
        let (part_of, parts) = groups(n, self.shafts.iter().map(|s| (s.between, 1.0)).collect());
        Coordinates {
            of_body: (0..n).map(|body| (body, 1.0)).collect(),
            count: n,
            part_of: part_of.into_iter().map(|(part, _)| part).collect(),
            parts,
        }
    }
}

/// The groups `links` join among `n` bodies, numbered in the order of their first body,
/// and each body's angle per unit angle of that first body: a link ([a, b], ratio) turns
/// b at `ratio` times a (and a at 1/`ratio` times b). Also how many groups there are.
fn groups(n: usize, links: Vec<([usize; 2], f64)>) -> (Vec<(usize, f64)>, usize) {
    let mut of_body: Vec<Option<(usize, f64)>> = vec![None; n];
    let mut count = 0;
    for first in 0..n {
        if of_body[first].is_some() {
            continue;
        }
        of_body[first] = Some((count, 1.0));
        let mut stack = vec![first];
        while let Some(body) = stack.pop() {
            let (_, ratio) = of_body[body].expect("placed");
            for &([a, b], link) in &links {
                let next = if a == body {
                    (b, ratio * link)
                } else if b == body {
                    (a, ratio / link)
                } else {
                    continue;
                };
                if of_body[next.0].is_none() {
                    of_body[next.0] = Some((count, next.1));
                    stack.push(next.0);
                }
            }
        }
        count += 1;
    }
    (
        of_body.into_iter().map(|c| c.expect("placed")).collect(),
        count,
    )
}
