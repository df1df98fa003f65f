//! A topology's constants in the form the equations take (SI), and the linear forms A is
//! built from (`system_matrix.rs` builds A of u' = A u in each mode).
//!
//! Each body turns about its own axis (a driven gear of an external pair turns the other
//! way); its angle is kept as x = θ − sΦ, less its share of the set rotation, so that
//! twists keep their precision however far the rig has turned (twists and deflections
//! are the same in x as in θ: the shares s make every shaft and mesh turn rigidly). A
//! body on a bearing in the plane also moves in x and y (share 0), its isotropic bearing
//! a spring-damper to the frame on each (`topology::RigCoordinates::supports`); a mesh
//! between gears that move then deflects along its line of action with their
//! translations too (`RigCoordinates::mesh_form`: the two flanks' lines mirror each
//! other about the centre line), and its force acts on them. A stage's planet on a bearing
//! moves in x and y on its pin, its share r_c s_c e_t (the pin's as the carrier turns);
//! the translations of a stage's members are kept in the carrier's frame, where every
//! line of action and bearing stays put (the frame's gyroscopic and centripetal terms
//! neglected: `docs/planetary.md`). A shaft carries k(θa − θb) + c(ωa − ωb) + T0 from a to b (T0 the
//! torque locked into a loop's shaft, 0 elsewhere). A mesh's deflection along the line of
//! action is δ = r_a θa + r_b θb (both radii negated where the driver turns against the
//! motor, so that δ > 0 always presses its drive flank); on its drive flank (δ > b, b half the free play) it
//! pushes with F = k(δ − b) + c δ', on its back flank (δ < −b) with F = k(δ + b) + c δ'
//! (thesis eq. 5.6: the spring-damper acts on the overlap), −r_a F on the driver and
//! −r_b F on the driven gear (−g F on each coordinate of δ's terms g); two pairs multiply k and c by the mesh's double-pair ratio.
//! A mesh's gear-error torques −C2 cos θ − C3 cos 2θ (θ its driver's share of the set
//! rotation) act on both its gears, each in its own sense of rotation, touching or not.
//! The motor's PI loop on the first-order filtered speed gives kp(Ω − ω_f) + ki z,
//! or its limit, on the motor body; the brake resists with its load and residual drag,
//! its slope about the set speed (the set slope plus the eddy-current characteristic's,
//! linearised at the set point) and the oscillating load; each body has its bearing drag.

use crate::mode::MotorMode;
use crate::topology::{Coupling, RigCoordinates, RigTopology};

use super::drive_model::{BrakeModel, MotorModel};
use super::layout::NetLayout;
use super::mesh_model::MeshModel;
use super::mode::MeshState;

/// Each stage's meshes in the plant's order (`RigTopology::mesh_names`): its sun–planet
/// meshes, then its ring–planet meshes, each drive flank the one the sun turning forward
/// against the carrier presses.
fn stage_meshes(
    rig: &RigTopology,
    coordinates: &RigCoordinates,
    speed_ratio: &[f64],
) -> Vec<MeshModel> {
    let mut out = Vec::new();
    for (i, stage) in rig.planetary.iter().enumerate() {
        let relative = speed_ratio[stage.sun] - speed_ratio[stage.carrier];
        let sense = if relative < 0.0 { -1.0 } else { 1.0 };
        for ring in [false, true] {
            for k in 0..stage.planets() {
                let form = coordinates.stage_mesh_form(i, stage, k, ring);
                let planet = coordinates.planet_rotation(i, k);
                out.push(MeshModel::of_stage(
                    stage,
                    ring,
                    (k, planet),
                    form,
                    sense,
                    speed_ratio,
                ));
            }
        }
    }
    out
}

/// A shaft's constants.
#[derive(Clone, Debug, PartialEq)]
pub struct ShaftModel {
    /// The bodies it joins (from, to).
    pub between: [usize; 2],
    /// Stiffness (N m/rad).
    pub stiffness_nm_per_rad: f64,
    /// Damping (N m s/rad).
    pub damping_nms_per_rad: f64,
    /// Torque it carries untwisted (N m): for a loop's twisted shaft, what makes it
    /// carry the locked-in torque at rest once the rest of the loop has yielded; else 0.
    pub preload_nm: f64,
}

/// What of a stretch of set points enters A: the rates the harmonic pairs and the
/// oscillating load turn at, and the slope of the brake's characteristic there.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SegmentRates {
    /// The motor's set speed the meshes' harmonic pairs turn with (rad/s; 0 where the rig
    /// has none).
    pub harmonic_rad_s: f64,
    /// The oscillating load's angular frequency (rad/s).
    pub oscillating_rad_s: f64,
    /// The eddy-current characteristic's slope at the set point (N m s/rad).
    pub brake_characteristic_nms_per_rad: f64,
}

/// The constants of a whole rig.
#[derive(Clone, Debug, PartialEq)]
pub struct NetworkModel {
    /// Where the states sit.
    pub layout: NetLayout,
    /// Each coordinate's inertia: kg m² for a rotation (body i's is coordinate i), kg for
    /// a translation.
    pub inertia: Vec<f64>,
    /// Each coordinate's drag (N m s/rad on a body's rotation; 0 on a translation).
    pub drag_nms_per_rad: Vec<f64>,
    /// Each coordinate's speed per unit speed of the motor's body (signed; 0 for a
    /// translation).
    pub speed_ratio: Vec<f64>,
    /// The shafts.
    pub shafts: Vec<ShaftModel>,
    /// What holds coordinates to the frame: shafts to the frame on rotations, bearings on
    /// translations, then each stage's planets' bearings on their pins.
    pub supports: Vec<Coupling>,
    /// How many of `supports`, first, are the rig's shafts to the frame (in its order).
    pub frame_shafts: usize,
    /// Where the planets' bearings on their pins begin in `supports` (stage by stage,
    /// planet by planet, x then y).
    pub planet_bearings: usize,
    /// The meshes.
    pub meshes: Vec<MeshModel>,
    /// The motor, if the rig has one.
    pub motor: Option<MotorModel>,
    /// The brake, if the rig has one.
    pub brake: Option<BrakeModel>,
}

impl NetworkModel {
    /// The constants of a checked topology, a loop's shaft untwisted (its preload, which
    /// makes it carry the locked torque at rest, is `equilibrium::assembled`'s business).
    pub fn of(rig: &RigTopology) -> Self {
        let reference = rig.motor.unwrap_or(0);
        let speeds = rig.relative_speeds();
        let base = speeds[reference].unwrap_or(1.0);
        let coordinates = RigCoordinates::of(rig);
        // Translations turn with nothing: their share of the set rotation is 0.
        let mut speed_ratio: Vec<f64> = speeds.iter().map(|s| s.unwrap_or(0.0) / base).collect();
        speed_ratio.resize(coordinates.len(), 0.0);
        // Each planet rolls on its sun (`PlanetaryStage::planet_speed`); one on a bearing
        // rides with its pin, r_c θ_c e_t (its translations kept in the carrier's frame).
        for (i, stage) in rig.planetary.iter().enumerate() {
            let carrier = speed_ratio[stage.carrier];
            let planet = stage.planet_speed(speed_ratio[stage.sun], carrier);
            for k in 0..stage.planets() {
                speed_ratio[coordinates.planet_rotation(i, k)] = planet;
                if let Some(x) = coordinates.planet_translation(i, k) {
                    let (_, et) = stage.axes(k);
                    let pin_m = stage.carrier_radius_m() * carrier;
                    speed_ratio[x] = pin_m * et[0];
                    speed_ratio[x + 1] = pin_m * et[1];
                }
            }
        }
        let inertia = coordinates.masses();
        let mut drag_nms_per_rad: Vec<f64> =
            rig.bodies.iter().map(|b| b.drag_nms_per_rad).collect();
        drag_nms_per_rad.resize(coordinates.len(), 0.0);
        let shafts = rig
            .shafts
            .iter()
            .enumerate()
            .map(|(i, s)| ShaftModel {
                between: s.between,
                stiffness_nm_per_rad: s.stiffness_nm_per_rad,
                damping_nms_per_rad: s.damping_nms_per_rad,
                preload_nm: rig
                    .locked_torque
                    .as_ref()
                    .filter(|l| l.shaft == i)
                    .map_or(0.0, |l| l.torque_nm),
            })
            .collect();
        let mut meshes: Vec<MeshModel> = rig
            .meshes
            .iter()
            .enumerate()
            .map(|(i, m)| MeshModel::of(m, &speed_ratio, coordinates.mesh_form(rig, i)))
            .collect();
        meshes.extend(stage_meshes(rig, &coordinates, &speed_ratio));
        // The speed loop on the rig's inertia seen at the motor, Σ J s² (as the 1983
        // preset's on the sum of its five inertias).
        let seen: f64 = inertia
            .iter()
            .zip(&speed_ratio)
            .map(|(j, s)| j * s * s)
            .sum();
        let d = &rig.drive;
        let wn = 2.0 * std::f64::consts::PI * d.speed_loop_hz;
        let motor = rig.motor.map(|body| MotorModel {
            body,
            kp_nms_per_rad: 2.0 * d.speed_loop_damping_ratio * wn * seen,
            ki_nm_per_rad: seen * wn * wn,
            filter_rad_s: 2.0 * std::f64::consts::PI * d.feedback_filter_hz,
            limit_nm: d.limit_nm(),
        });
        let brake = rig.brake.map(|body| BrakeModel {
            body,
            direction: if speed_ratio[body] < 0.0 { -1.0 } else { 1.0 },
            slope_nms_per_rad: d.brake_slope_nms_per_rad,
            drag_nm: d.brake_drag_nm,
            critical_rad_s: d.brake_critical_speed_rpm * std::f64::consts::PI / 30.0,
            speed_share: speed_ratio[body].abs(),
        });
        let mut supports = coordinates.supports(rig);
        let planet_bearings = supports.len();
        for (i, stage) in rig.planetary.iter().enumerate() {
            supports.extend(coordinates.planet_bearings(i, stage));
        }
        Self {
            layout: NetLayout::new(rig, &coordinates),
            inertia,
            drag_nms_per_rad,
            speed_ratio,
            shafts,
            supports,
            frame_shafts: rig.frame_shafts.len(),
            planet_bearings,
            meshes,
            motor,
            brake,
        }
    }

    /// The fastest harmonic pair (rad/s) at a set speed of `speed_rad_s`.
    pub fn fastest_harmonic_rad_s(&self, speed_rad_s: f64) -> f64 {
        self.layout
            .harmonics()
            .iter()
            .map(|&(_, mesh, harmonic)| (harmonic * self.meshes[mesh].share * speed_rad_s).abs())
            .fold(0.0, f64::max)
    }

    /// The absolute angle θ = x + sΦ (rad) of body `body` at `u`.
    pub fn absolute_angle_rad(&self, body: usize, u: &[f64]) -> f64 {
        let l = &self.layout;
        u[l.angle(body)] + self.speed_ratio[body] * u[l.phase()]
    }

    /// The angle mesh `mesh`'s tooth periods follow (rad of its driver,
    /// `MeshModel::zone_angle`) as terms on the state: Σ c (x_j + s_j Φ) + offset · 1.
    pub fn zone_angle_terms(&self, mesh: usize) -> Vec<(usize, f64)> {
        let l = &self.layout;
        let m = &self.meshes[mesh];
        let mut terms: Vec<(usize, f64)> =
            m.zone_angle.iter().map(|&(j, c)| (l.angle(j), c)).collect();
        terms.push((l.phase(), m.zone_share));
        if m.zone_offset_rad != 0.0 {
            terms.push((l.unit(), m.zone_offset_rad));
        }
        terms
    }

    /// The angle mesh `mesh`'s tooth periods follow (rad of its driver) at `u`.
    pub fn zone_angle_rad(&self, mesh: usize, u: &[f64]) -> f64 {
        self.zone_angle_terms(mesh)
            .iter()
            .map(|&(j, c)| c * u[j])
            .sum()
    }

    /// A mesh's deflection δ (m) on `flank` (+1 drive, −1 back) and its rate (m/s) at
    /// state `u`.
    pub fn deflection(&self, mesh: usize, flank: f64, u: &[f64]) -> (f64, f64) {
        let l = &self.layout;
        let m = &self.meshes[mesh];
        (
            m.terms(flank).map(|(j, c)| c * u[l.angle(j)]).sum(),
            m.terms(flank).map(|(j, c)| c * u[l.speed(j)]).sum(),
        )
    }

    /// The overlap (m) of mesh `mesh`'s `flank` (+1 drive, −1 back) at `u` and its rate
    /// (m/s), the set speed held at `speed_rad_s`: > 0 (drive) or < 0 (back) in contact.
    pub fn overlap(&self, mesh: usize, flank: f64, u: &[f64], speed_rad_s: f64) -> (f64, f64) {
        let l = &self.layout;
        let m = &self.meshes[mesh];
        let (delta, rate) = self.deflection(mesh, flank, u);
        let mut overlap = delta - flank * m.half_backlash_m + m.offset_m;
        let mut overlap_rate = rate;
        let w = m.share * speed_rad_s;
        if let Some(rev) = l.revolution[mesh] {
            let amplitude = m.te_once_m + flank * m.variation_m;
            overlap += amplitude * u[rev];
            overlap_rate -= amplitude * w * u[rev + 1];
        }
        if let Some(tooth) = l.tooth[mesh] {
            overlap += m.te_mesh_m * u[tooth];
            overlap_rate -= m.te_mesh_m * m.teeth * w * u[tooth + 1];
        }
        if let Some(run_out) = l.run_out[mesh] {
            overlap += m.run_out_driven_m * u[run_out];
            overlap_rate -= m.run_out_driven_m * m.driven_turns * w * u[run_out + 1];
        }
        if let Some(spacing) = l.spacing[mesh] {
            overlap += u[spacing];
        }
        (overlap, overlap_rate)
    }

    /// The force (N) a mesh in `state` pushes with at `u`; 0 apart.
    pub fn mesh_force_n(&self, mesh: usize, state: MeshState, u: &[f64], speed_rad_s: f64) -> f64 {
        let Some(flank) = state.pushing_flank() else {
            return 0.0;
        };
        let (k, c) = self.meshes[mesh].spring(state);
        let (overlap, rate) = self.overlap(mesh, flank, u, speed_rad_s);
        k * overlap + c * rate
    }

    /// The motor's torque (N m) in `motor` mode as a linear form of the state (index,
    /// coefficient): the loop's command kp(Ω − ω_f) + ki∫, or the limit it is held at;
    /// none without a motor.
    pub fn motor_torque_terms(&self, motor: MotorMode) -> Vec<(usize, f64)> {
        let Some(m) = &self.motor else {
            return Vec::new();
        };
        let l = &self.layout;
        let limit = m.limit_nm.unwrap_or(f64::INFINITY);
        match motor {
            MotorMode::Linear => vec![
                (l.set_speed(), m.kp_nms_per_rad),
                (l.filtered(), -m.kp_nms_per_rad),
                (l.integral(), m.ki_nm_per_rad),
            ],
            MotorMode::LimitHigh => vec![(l.unit(), limit)],
            MotorMode::LimitLow => vec![(l.unit(), -limit)],
        }
    }

    /// The PI loop's command before any limit (N m).
    pub fn controller_nm(&self, u: &[f64]) -> f64 {
        let l = &self.layout;
        self.motor.as_ref().map_or(0.0, |m| {
            m.kp_nms_per_rad * (u[l.set_speed()] - u[l.filtered()])
                + m.ki_nm_per_rad * u[l.integral()]
        })
    }

    /// The force of a mesh's `flank` (+1 drive, −1 back) in `state` as a linear form
    /// (index, coefficient): k·overlap + c·overlap rate, the harmonic pairs turning at
    /// the driver's share of `speed_rad_s`.
    pub fn force_terms(
        &self,
        mesh: usize,
        state: MeshState,
        flank: f64,
        speed_rad_s: f64,
    ) -> Vec<(usize, f64)> {
        let (k, c) = self.meshes[mesh].spring(state);
        let mut terms: Vec<(usize, f64)> = Vec::new();
        for (index, stiff, damp) in self.overlap_terms(mesh, flank, speed_rad_s) {
            let v = k * stiff + c * damp;
            match terms.iter_mut().find(|(i, _)| *i == index) {
                Some(t) => t.1 += v,
                None => terms.push((index, v)),
            }
        }
        terms.retain(|&(_, v)| v != 0.0);
        terms
    }

    /// The overlap of a mesh's `flank` (+1 drive, −1 back) as terms (state, coefficient
    /// of the overlap, coefficient of its rate): δ + e − f b(1 − C1 cos θ), the harmonic
    /// pairs turning at the driver's share of `speed_rad_s`.
    pub fn overlap_terms(
        &self,
        mesh: usize,
        flank: f64,
        speed_rad_s: f64,
    ) -> Vec<(usize, f64, f64)> {
        let l = &self.layout;
        let m = &self.meshes[mesh];
        let mut terms: Vec<(usize, f64, f64)> = m
            .terms(flank)
            .map(|(j, c)| (l.angle(j), c, 0.0))
            .chain(m.terms(flank).map(|(j, c)| (l.speed(j), 0.0, c)))
            .collect();
        terms.push((l.unit(), -flank * m.half_backlash_m + m.offset_m, 0.0));
        let w = m.share * speed_rad_s;
        if let Some(rev) = l.revolution[mesh] {
            let amplitude = m.te_once_m + flank * m.variation_m;
            terms.push((rev, amplitude, 0.0));
            terms.push((rev + 1, 0.0, -amplitude * w));
        }
        if let Some(tooth) = l.tooth[mesh] {
            terms.push((tooth, m.te_mesh_m, 0.0));
            terms.push((tooth + 1, 0.0, -m.te_mesh_m * m.teeth * w));
        }
        if let Some(run_out) = l.run_out[mesh] {
            terms.push((run_out, m.run_out_driven_m, 0.0));
            terms.push((run_out + 1, 0.0, -m.run_out_driven_m * m.driven_turns * w));
        }
        if let Some(spacing) = l.spacing[mesh] {
            terms.push((spacing, 1.0, 0.0));
        }
        terms
    }
}
