//! What makes a rig's planar parts ones the model can take: bodies' masses and bearings,
//! shafts to the frame, and planetary stages (their bodies, planets, teeth, geometry and
//! meshes). Each fault names the item and field, and what is allowed.

use std::f64::consts::PI;

use super::check::{check_tooth_fault, fault, finite, non_negative, positive};
use super::planetary::{MAX_PLANETS, PlanarBearing, PlanetaryStage, StageMember, StageMesh};
use super::rig_topology::{MAX_PLANT_MESHES, RigTopology};
use crate::error::TopologyError;
use crate::options::MeshPairs;

impl RigTopology {
    /// Checks planar bearings, shafts to the frame and planetary stages.
    pub(super) fn check_planar(&self) -> Result<(), TopologyError> {
        for (i, b) in self.bodies.iter().enumerate() {
            if let Some(bearing) = &b.planar {
                check_bearing(bearing, "body", i, ["mass_kg", "bearing_stiffness_n_per_m"])?;
                non_negative(
                    bearing.damping_ns_per_m,
                    ("body", i, "bearing_damping_ns_per_m"),
                )?;
            }
        }
        for (i, s) in self.frame_shafts.iter().enumerate() {
            positive(
                s.stiffness_nm_per_rad,
                ("frame_shaft", i, "stiffness_nm_per_rad"),
            )?;
            non_negative(
                s.damping_nms_per_rad,
                ("frame_shaft", i, "damping_nms_per_rad"),
            )?;
        }
        for (i, m) in self.meshes.iter().enumerate() {
            finite(m.centre_line_deg, ("mesh", i, "centre_line_deg"))?;
        }
        for (i, stage) in self.planetary.iter().enumerate() {
            check_stage(stage, i)?;
            self.check_planet_names(stage, i)?;
        }
        // The speeds once every stage is known sound.
        let speeds = self.relative_speeds();
        for (i, stage) in self.planetary.iter().enumerate() {
            // A held carrier's frame is the housing's: nothing turns there.
            let carrier_turns = speeds[stage.carrier] != Some(0.0);
            for member in [stage.sun, stage.ring, stage.carrier] {
                if carrier_turns && self.bodies[member].planar.is_some() {
                    self.check_member_frame(i, member)?;
                }
            }
        }
        self.check_mesh_count()
    }

    /// A stage's planets' names are not the rig's bodies'.
    fn check_planet_names(&self, stage: &PlanetaryStage, i: usize) -> Result<(), TopologyError> {
        for k in 0..stage.planets() {
            let name = stage.planet_name(k);
            if self.bodies.iter().any(|b| b.name == name) {
                return Err(fault(
                    "planetary",
                    i,
                    "name",
                    format!(
                        "its planet {} is `{name}`, the name of a body: rename the stage or the body",
                        k + 1
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Every mesh, external and of the stages, within [`MAX_PLANT_MESHES`].
    fn check_mesh_count(&self) -> Result<(), TopologyError> {
        let count = self.mesh_names().len();
        if count <= MAX_PLANT_MESHES {
            return Ok(());
        }
        Err(fault(
            "planetary",
            self.planetary.len().saturating_sub(1),
            "planets",
            format!(
                "{count} meshes (the external ones and two per planet): a rig has at most {MAX_PLANT_MESHES}"
            ),
        ))
    }
}

impl RigTopology {
    /// Refuses what the time-domain plant does not step: a motor whose body the frame
    /// holds still.
    pub fn check_steppable(&self) -> Result<(), TopologyError> {
        if let Some(motor) = self.motor
            && self.relative_speeds()[motor] == Some(0.0)
        {
            return Err(fault(
                "motor",
                0,
                "body",
                format!(
                    "the motor's body `{}` is held still by a shaft to the frame: drive a body that turns",
                    self.bodies[motor].name
                ),
            ));
        }
        Ok(())
    }
}

impl RigTopology {
    /// Body `member` of stage `i`, on a bearing, meshes in no other stage and no external
    /// mesh: its translations are kept in the stage's turning carrier's frame
    /// (`plant/model.rs`), where another stage's or an external mesh's line of action
    /// would turn. Refused for every door, `modes` too (whose zero speed would allow it),
    /// so that the file is refused at its line.
    fn check_member_frame(&self, i: usize, member: usize) -> Result<(), TopologyError> {
        let name = &self.bodies[member].name;
        let other_stage = self
            .planetary
            .iter()
            .enumerate()
            .find(|(j, s)| *j != i && [s.sun, s.ring, s.carrier].contains(&member));
        let external = self.meshes.iter().find(|m| m.gears.contains(&member));
        let elsewhere = match (other_stage, external) {
            (Some((_, s)), _) => format!("stage `{}`", s.name),
            (None, Some(m)) => format!("mesh `{}`", m.name),
            (None, None) => return Ok(()),
        };
        Err(fault(
            "body",
            member,
            "mass_kg",
            format!(
                "body `{name}` moves in the plane in stage `{}` and meshes in {elsewhere} too: a stage member's translations are kept in its carrier's frame, where another line of action turns; give `{name}` no bearing (mass_kg), or mesh it in this stage only",
                self.planetary[i].name
            ),
        ))
    }
}

/// A bearing's mass and stiffness, both positive (`fields`: their names in the file).
fn check_bearing(
    bearing: &PlanarBearing,
    table: &'static str,
    i: usize,
    fields: [&'static str; 2],
) -> Result<(), TopologyError> {
    positive(bearing.mass_kg, (table, i, fields[0]))?;
    positive(bearing.stiffness_n_per_m, (table, i, fields[1]))
}

/// One stage: three distinct bodies, 1 to 8 planets that can be assembled where they
/// stand, teeth that fit, positive geometry and meshes.
fn check_stage(s: &PlanetaryStage, i: usize) -> Result<(), TopologyError> {
    let members = [s.sun, s.ring, s.carrier];
    if members[0] == members[1] || members[0] == members[2] || members[1] == members[2] {
        return Err(fault(
            "planetary",
            i,
            "carrier",
            "sun, ring and carrier are one body twice: name three bodies".into(),
        ));
    }
    if !(1..=MAX_PLANETS).contains(&s.planets()) {
        return Err(fault(
            "planetary",
            i,
            "planets",
            format!("{}: a stage has 1 to {MAX_PLANETS} planets", s.planets()),
        ));
    }
    positive(
        s.planet_inertia_kgm2,
        ("planetary", i, "planet_inertia_kgm2"),
    )?;
    for &e in &s.planet_pin_errors_um {
        // Within a tenth of a module: an error of position, not another geometry.
        if !(e.is_finite() && e.abs() <= s.module_m * 1e5) {
            return Err(fault(
                "planetary",
                i,
                "planet_pin_errors_um",
                format!(
                    "{e}: a pin error lies within a tenth of the module, ±{} µm",
                    s.module_m * 1e5
                ),
            ));
        }
    }
    if let Some(bearing) = &s.planet_bearing {
        check_bearing(
            bearing,
            "planetary",
            i,
            ["planet_mass_kg", "planet_bearing_stiffness_n_per_m"],
        )?;
        non_negative(
            bearing.damping_ns_per_m,
            ("planetary", i, "planet_bearing_damping_ns_per_m"),
        )?;
    }
    positive(s.module_m, ("planetary", i, "module_m"))?;
    if !(s.pressure_angle_deg > 0.0 && s.pressure_angle_deg < 45.0) {
        return Err(fault(
            "planetary",
            i,
            "pressure_angle_deg",
            format!(
                "{}: a pressure angle lies in (0, 45) degrees",
                s.pressure_angle_deg
            ),
        ));
    }
    check_teeth(s, i)?;
    if let Some(r) = &s.base_radii_m {
        for value in [r.sun, r.planet, r.ring] {
            positive(value, ("planetary", i, "base_diameter_m"))?;
        }
    }
    if let Some(rc) = s.carrier_radius_given_m {
        positive(rc, ("planetary", i, "carrier_radius_m"))?;
    }
    check_angles(s, i)?;
    check_stage_mesh(&s.sun_planet, s.module_m, i, "sun_planet")?;
    check_stage_mesh(&s.ring_planet, s.module_m, i, "ring_planet")?;
    check_stage_pairs(s, i, false, "sun_planet")?;
    check_stage_pairs(s, i, true, "ring_planet")?;
    check_stage_faults(s, i)?;
    check_ring_sensor(s, i)
}

/// A ring sensor's place finite and its window 0 to 360 degrees wide.
fn check_ring_sensor(s: &PlanetaryStage, i: usize) -> Result<(), TopologyError> {
    let Some(sensor) = &s.ring_sensor else {
        return Ok(());
    };
    finite(sensor.angle_rad, ("planetary", i, "ring_sensor"))?;
    if !(sensor.window_rad > 0.0 && sensor.window_rad <= 2.0 * PI) {
        return Err(fault(
            "planetary",
            i,
            "ring_sensor",
            format!(
                "window_deg {}: a window over the planet's passage, more than 0 and at most 360 degrees wide",
                sensor.window_rad.to_degrees()
            ),
        ));
    }
    Ok(())
}

/// At least 5 teeth each, and a ring of z_s + 2 z_p teeth (standard gears on one centre
/// distance) unless the base diameters are given.
fn check_teeth(s: &PlanetaryStage, i: usize) -> Result<(), TopologyError> {
    let t = s.teeth;
    if [t.sun, t.planet, t.ring].iter().any(|&z| z < 5) {
        return Err(fault(
            "planetary",
            i,
            "teeth",
            format!(
                "sun {}, planet {}, ring {}: each gear needs at least 5 teeth",
                t.sun, t.planet, t.ring
            ),
        ));
    }
    let standard = u64::from(t.sun) + 2 * u64::from(t.planet);
    if s.base_radii_m.is_none() && u64::from(t.ring) != standard {
        return Err(fault(
            "planetary",
            i,
            "teeth",
            format!(
                "ring {}: standard gears on one centre distance need ring = sun + 2 planet = {standard} (or give base_diameter_m, as a published model's numbers)",
                t.ring
            ),
        ));
    }
    Ok(())
}

/// Planet angles in [0°, 360°), distinct, each one the planets can be assembled at
/// ((z_s + z_r) ψ / 360° whole), and no two planets' tips overlapping.
fn check_angles(s: &PlanetaryStage, i: usize) -> Result<(), TopologyError> {
    let field = "planet_angles_deg";
    for (k, &psi) in s.planet_angles_rad.iter().enumerate() {
        if !(0.0..2.0 * PI).contains(&psi) {
            return Err(fault(
                "planetary",
                i,
                field,
                format!(
                    "planet {}: {}°: an angle in [0, 360) degrees",
                    k + 1,
                    psi.to_degrees()
                ),
            ));
        }
    }
    let step_deg = 360.0 / (f64::from(s.teeth.sun) + f64::from(s.teeth.ring));
    let mut sorted = s.planet_angles_rad.clone();
    sorted.sort_by(f64::total_cmp);
    if let Some(w) = sorted.windows(2).find(|w| w[0] == w[1]) {
        return Err(fault(
            "planetary",
            i,
            field,
            format!(
                "two planets at {}°: each planet its own angle",
                w[0].to_degrees()
            ),
        ));
    }
    if let Some((k, deg)) = s.unassemblable() {
        return Err(fault(
            "planetary",
            i,
            field,
            format!(
                "planet {} at {deg:.3}°: planets can be assembled only at multiples of 360°/(z_s + z_r) = {step_deg:.4}° (equally spaced: (z_s + z_r)/N whole)",
                k + 1
            ),
        ));
    }
    if let Some((a, b, apart_mm, least_mm)) = s.overlapping_planets() {
        return Err(fault(
            "planetary",
            i,
            field,
            format!(
                "planets {} and {} are {apart_mm:.1} mm apart, centre to centre; their tips need {least_mm:.1} mm: fewer planets, or a larger carrier",
                a + 1,
                b + 1
            ),
        ));
    }
    Ok(())
}

/// A stage's mesh: positive stiffness, damping ≥ 0, backlash below half the pitch.
fn check_stage_mesh(
    m: &StageMesh,
    module_m: f64,
    i: usize,
    field: &'static str,
) -> Result<(), TopologyError> {
    positive(m.stiffness_n_per_m, ("planetary", i, field))?;
    non_negative(m.damping_ns_per_m, ("planetary", i, field))?;
    positive(m.backlash_mm, ("planetary", i, field))?;
    let half_pitch_mm = PI * module_m * 1e3 / 2.0;
    if m.backlash_mm >= half_pitch_mm {
        return Err(fault(
            "planetary",
            i,
            field,
            format!(
                "backlash {} mm: a gap between teeth, below half the circular pitch (π m / 2 = {half_pitch_mm:.3} mm)",
                m.backlash_mm
            ),
        ));
    }
    Ok(())
}

/// A stage mesh's pairs: two at least as stiff as one, smoothing a share of the pitch
/// (alternating pairs only), and a contact ratio in [1, 2) where pairs alternate.
fn check_stage_pairs(
    s: &PlanetaryStage,
    i: usize,
    ring: bool,
    field: &'static str,
) -> Result<(), TopologyError> {
    let m = if ring { &s.ring_planet } else { &s.sun_planet };
    let alternating = m.pairs == MeshPairs::Alternating;
    let refuse = |why: String| Err(fault("planetary", i, field, why));
    if !(m.double_pair_ratio.is_finite() && m.double_pair_ratio >= 1.0) {
        return refuse(format!(
            "double_pair_ratio {}: two pairs are at least as stiff as one (≥ 1)",
            m.double_pair_ratio
        ));
    }
    if !(0.0..=1.0).contains(&m.stiffness_smoothing) {
        return refuse(format!(
            "stiffness_smoothing {}: a fraction of the tooth pitch, 0 to 1",
            m.stiffness_smoothing
        ));
    }
    if m.stiffness_smoothing > 0.0 && !alternating {
        return refuse(format!(
            "stiffness_smoothing {}: smooths the changes between one and two pairs, which need pairs = \"alternating\"",
            m.stiffness_smoothing
        ));
    }
    let ratio = s.mesh_phase(0, ring).contact_ratio;
    if alternating && !(1.0..2.0).contains(&ratio) {
        return refuse(format!(
            "pairs = \"alternating\" with a contact ratio of {ratio:.3}: one and two pairs alternate for 1 ≤ ε < 2"
        ));
    }
    Ok(())
}

/// A stage's faults: each on a tooth its gear has, of a severity 0 to 1.
fn check_stage_faults(s: &PlanetaryStage, i: usize) -> Result<(), TopologyError> {
    for (k, f) in s.faults.iter().enumerate() {
        let (gear, teeth) = match f.member {
            StageMember::Sun => ("sun".to_string(), s.teeth.sun),
            StageMember::Ring => ("ring".to_string(), s.teeth.ring),
            StageMember::Planet(j) if j < s.planets() => {
                (format!("planet{}", j + 1), s.teeth.planet)
            }
            StageMember::Planet(j) => {
                return Err(fault(
                    "planetary",
                    i,
                    "fault",
                    format!(
                        "fault {}: planet{}, of a stage of {} planets",
                        k + 1,
                        j + 1,
                        s.planets()
                    ),
                ));
            }
        };
        check_tooth_fault(("planetary", i, k), (&gear, teeth), f.tooth, f.severity)?;
    }
    Ok(())
}
