//! What makes a rig file's rig one the plant can run: positive, finite numbers, bodies
//! that exist and are all joined into one rig, gears with teeth, loops whose gear ratios
//! close, and the limits on size. Each fault names the item and field, and what is
//! allowed.

use super::rig_topology::{MAX_BODIES, MAX_PLANT_MESHES, RigTopology};
use crate::error::{TopologyError, TopologyPlace};

pub(super) fn fault(
    table: &'static str,
    index: usize,
    field: &'static str,
    message: String,
) -> TopologyError {
    TopologyError {
        place: TopologyPlace {
            table,
            index,
            field,
        },
        message,
    }
}

/// Refuses a number that is not finite (NaN or infinite).
pub(super) fn finite(
    value: f64,
    (table, index, field): (&'static str, usize, &'static str),
) -> Result<(), TopologyError> {
    if value.is_finite() && value.abs() <= LARGEST {
        return Ok(());
    }
    Err(fault(
        table,
        index,
        field,
        format!("{value}: must be a number between -{LARGEST:e} and {LARGEST:e}"),
    ))
}

/// Smallest positive number a rig takes in its units (kg m², N m/rad, m, …): far
/// below any real part, far above the subnormal numbers that would overflow A.
const SMALLEST: f64 = 1e-12;
/// Largest number a rig takes in its units.
const LARGEST: f64 = 1e15;

/// `value` as a positive finite number, or the fault at its place.
pub(super) fn positive(
    value: f64,
    (table, index, field): (&'static str, usize, &'static str),
) -> Result<(), TopologyError> {
    if (SMALLEST..=LARGEST).contains(&value) {
        return Ok(());
    }
    Err(fault(
        table,
        index,
        field,
        format!("{value}: must be a number > 0, between {SMALLEST:e} and {LARGEST:e}"),
    ))
}

/// `value` as a finite number ≥ 0, or the fault at its place.
pub(super) fn non_negative(
    value: f64,
    (table, index, field): (&'static str, usize, &'static str),
) -> Result<(), TopologyError> {
    if value == 0.0 || (SMALLEST..=LARGEST).contains(&value) {
        return Ok(());
    }
    Err(fault(
        table,
        index,
        field,
        format!("{value}: must be 0 or a number between {SMALLEST:e} and {LARGEST:e}"),
    ))
}

impl RigTopology {
    /// Checks the rig: every number, every connection, the loops, the limits.
    pub fn check(&self) -> Result<(), TopologyError> {
        self.check_sizes()?;
        self.check_numbers()?;
        self.check_planar()?;
        self.check_connected()?;
        self.check_loops_close()?;
        if let Some(locked) = &self.locked_torque
            && !locked.torque_nm.is_finite()
        {
            return Err(fault(
                "locked_torque",
                0,
                "torque_nm",
                format!("{}: must be a finite number", locked.torque_nm),
            ));
        }
        Ok(())
    }

    fn check_sizes(&self) -> Result<(), TopologyError> {
        if self.bodies.len() < 2 || self.bodies.len() > MAX_BODIES {
            return Err(fault(
                "body",
                self.bodies.len().saturating_sub(1),
                "name",
                format!(
                    "{} bodies: a rig has 2 to {MAX_BODIES} bodies",
                    self.bodies.len()
                ),
            ));
        }
        if self.meshes.len() > MAX_PLANT_MESHES {
            return Err(fault(
                "mesh",
                MAX_PLANT_MESHES,
                "name",
                format!(
                    "{} meshes: a rig has at most {MAX_PLANT_MESHES} (the external ones and two per planet)",
                    self.meshes.len()
                ),
            ));
        }
        Ok(())
    }

    fn check_numbers(&self) -> Result<(), TopologyError> {
        for (i, b) in self.bodies.iter().enumerate() {
            positive(b.inertia_kgm2, ("body", i, "inertia_kgm2"))?;
            non_negative(b.drag_nms_per_rad, ("body", i, "drag_nms_per_rad"))?;
        }
        for (i, s) in self.shafts.iter().enumerate() {
            positive(s.stiffness_nm_per_rad, ("shaft", i, "stiffness_nm_per_rad"))?;
            non_negative(s.damping_nms_per_rad, ("shaft", i, "damping_nms_per_rad"))?;
            if s.between[0] == s.between[1] {
                return Err(fault(
                    "shaft",
                    i,
                    "between",
                    "joins a body to itself: name two bodies".into(),
                ));
            }
        }
        for (i, m) in self.meshes.iter().enumerate() {
            if m.teeth.iter().any(|&z| z < 5) {
                return Err(fault(
                    "mesh",
                    i,
                    "teeth",
                    format!("{:?}: each gear needs at least 5 teeth", m.teeth),
                ));
            }
            if m.gears[0] == m.gears[1] {
                return Err(fault(
                    "mesh",
                    i,
                    "driven",
                    "the driven gear is the driver: name two bodies".into(),
                ));
            }
            positive(m.module_m, ("mesh", i, "module_m"))?;
            positive(m.backlash_mm, ("mesh", i, "backlash_mm"))?;
            let half_pitch_mm = std::f64::consts::PI * m.module_m * 1e3 / 2.0;
            if m.backlash_mm >= half_pitch_mm {
                return Err(fault(
                    "mesh",
                    i,
                    "backlash_mm",
                    format!(
                        "{}: backlash is a gap between teeth, below half the circular pitch (π m / 2 = {half_pitch_mm:.3} mm)",
                        m.backlash_mm
                    ),
                ));
            }
            positive(m.stiffness_n_per_m, ("mesh", i, "stiffness_n_per_m"))?;
            non_negative(m.damping_ns_per_m, ("mesh", i, "damping_ns_per_m"))?;
            if !(m.pressure_angle_deg > 0.0 && m.pressure_angle_deg < 45.0) {
                return Err(fault(
                    "mesh",
                    i,
                    "pressure_angle_deg",
                    format!(
                        "{}: a pressure angle lies in (0, 45) degrees",
                        m.pressure_angle_deg
                    ),
                ));
            }
            self.check_pairs(i)?;
        }
        self.check_drive()
    }

    /// A mesh's pair settings: two pairs at least as stiff as one, an addendum, and with
    /// alternating pairs a contact ratio between 1 and 2.
    fn check_pairs(&self, i: usize) -> Result<(), TopologyError> {
        let m = &self.meshes[i];
        positive(m.addendum_coefficient, ("mesh", i, "addendum_coefficient"))?;
        if !(0.0..1.0).contains(&m.backlash_variation) {
            return Err(fault(
                "mesh",
                i,
                "backlash_variation",
                format!(
                    "{}: the free play b(1 − C1 cos θ) needs 0 ≤ C1 < 1",
                    m.backlash_variation
                ),
            ));
        }
        non_negative(m.te_once_per_rev_um, ("mesh", i, "te_once_per_rev_um"))?;
        non_negative(m.run_out_driver_um, ("mesh", i, "run_out_driver_um"))?;
        non_negative(m.run_out_driven_um, ("mesh", i, "run_out_driven_um"))?;
        non_negative(m.te_mesh_frequency_um, ("mesh", i, "te_mesh_frequency_um"))?;
        finite(m.gear_error_c2_nm, ("mesh", i, "gear_error_c2_nm"))?;
        finite(m.gear_error_c3_nm, ("mesh", i, "gear_error_c3_nm"))?;
        non_negative(
            m.tooth_spacing_error_um,
            ("mesh", i, "tooth_spacing_error_um"),
        )?;
        if !(m.double_pair_ratio.is_finite() && m.double_pair_ratio >= 1.0) {
            return Err(fault(
                "mesh",
                i,
                "double_pair_ratio",
                format!(
                    "{}: two pairs are at least as stiff as one (≥ 1)",
                    m.double_pair_ratio
                ),
            ));
        }
        self.check_faults(i)?;
        if !(0.0..=m.module_m * 1e3).contains(&m.centre_distance_shift_mm) {
            return Err(fault(
                "mesh",
                i,
                "centre_distance_shift_mm",
                format!(
                    "{}: 0 to one module ({} mm): the teeth must still reach each other",
                    m.centre_distance_shift_mm,
                    m.module_m * 1e3
                ),
            ));
        }
        if !(0.0..=1.0).contains(&m.stiffness_smoothing) {
            return Err(fault(
                "mesh",
                i,
                "stiffness_smoothing",
                format!(
                    "{}: a fraction of the tooth pitch, 0 to 1",
                    m.stiffness_smoothing
                ),
            ));
        }
        if m.stiffness_smoothing > 0.0 && m.pairs != crate::options::MeshPairs::Alternating {
            return Err(fault(
                "mesh",
                i,
                "stiffness_smoothing",
                format!(
                    "{}: smooths the changes between one and two pairs, which need pairs = \"alternating\"",
                    m.stiffness_smoothing
                ),
            ));
        }
        let ratio = m.contact_ratio();
        if m.pairs == crate::options::MeshPairs::Alternating && !(1.0..2.0).contains(&ratio) {
            return Err(fault(
                "mesh",
                i,
                "pairs",
                format!(
                    "alternating pairs need a contact ratio in [1, 2); these gears have {ratio:.3}"
                ),
            ));
        }
        Ok(())
    }

    /// A mesh's tooth faults: each on a tooth its gear has, its severity in [0, 1].
    fn check_faults(&self, i: usize) -> Result<(), TopologyError> {
        let m = &self.meshes[i];
        for (k, f) in m.faults.iter().enumerate() {
            let (gear, teeth) = match f.gear {
                crate::tooth_fault::FaultedGear::Driver => ("driver gear", m.teeth[0]),
                crate::tooth_fault::FaultedGear::Driven => ("driven gear", m.teeth[1]),
            };
            check_tooth_fault(("mesh", i, k), (gear, teeth), f.tooth, f.severity)?;
        }
        Ok(())
    }

    /// The motor's speed loop and limit, the brake's slope.
    fn check_drive(&self) -> Result<(), TopologyError> {
        let d = &self.drive;
        positive(d.speed_loop_hz, ("motor", 0, "speed_loop_hz"))?;
        positive(
            d.speed_loop_damping_ratio,
            ("motor", 0, "speed_loop_damping_ratio"),
        )?;
        positive(d.feedback_filter_hz, ("motor", 0, "feedback_filter_hz"))?;
        if let Some(limit) = d.torque_limit_nm {
            positive(limit, ("motor", 0, "torque_limit_nm"))?;
            if d.ratings.is_some() {
                return Err(fault(
                    "motor",
                    0,
                    "torque_limit_nm",
                    format!(
                        "{limit}: give the torque limit or the drive's ratings (rated_power_w, rated_speed_rpm, current_limit_pct), not both"
                    ),
                ));
            }
        }
        if let Some(r) = &d.ratings {
            positive(r.rated_power_w, ("motor", 0, "rated_power_w"))?;
            positive(r.rated_speed_rpm, ("motor", 0, "rated_speed_rpm"))?;
            positive(r.current_limit_pct, ("motor", 0, "current_limit_pct"))?;
            if let Some(current) = r.full_load_current_a {
                positive(current, ("motor", 0, "full_load_current_a"))?;
            }
        }
        non_negative(d.brake_slope_nms_per_rad, ("brake", 0, "slope_nms_per_rad"))?;
        non_negative(d.brake_drag_nm, ("brake", 0, "drag_nm"))?;
        non_negative(
            d.brake_critical_speed_rpm,
            ("brake", 0, "critical_speed_rpm"),
        )?;
        if let Some(g) = &self.gauge {
            positive(g.diameter_m, ("gauge", 0, "diameter_m"))?;
            positive(g.shear_modulus_pa, ("gauge", 0, "shear_modulus_pa"))?;
        }
        Ok(())
    }

    /// Every body joined to the first by shafts and meshes.
    fn check_connected(&self) -> Result<(), TopologyError> {
        let speeds = self.relative_speeds();
        match speeds.iter().position(Option::is_none) {
            None => Ok(()),
            Some(i) if let Some(k) = self.stage_of(i) => Err(fault(
                "planetary",
                k,
                "ring",
                format!(
                    "the speeds of `{}`'s sun, ring and carrier are not set by the rest of the rig: it turns as a differential; hold one of the three by a shaft to the frame (between = [\"{}\", \"frame\"]) or join two of them to the rest of the rig",
                    self.planetary[k].name, self.bodies[self.planetary[k].ring].name
                ),
            )),
            Some(i) => Err(fault(
                "body",
                i,
                "name",
                format!(
                    "`{}` is connected to nothing: join it by a shaft or a mesh to the rest of the rig",
                    self.bodies[i].name
                ),
            )),
        }
    }

    /// The planetary stage body `body` is the sun, ring or carrier of, if any.
    fn stage_of(&self, body: usize) -> Option<usize> {
        self.planetary
            .iter()
            .position(|s| [s.sun, s.ring, s.carrier].contains(&body))
    }

    /// A closed loop turns as one only if the ratios around it multiply to 1: each joint
    /// must agree with the speeds the others give its two bodies.
    fn check_loops_close(&self) -> Result<(), TopologyError> {
        let speeds = self.relative_speeds();
        let shafts = self.shafts.len();
        for (k, (a, b, ratio)) in self.joints().enumerate() {
            let (Some(x), Some(y)) = (speeds[a], speeds[b]) else {
                continue;
            };
            if (y - x * ratio).abs() > 1e-9 * x.abs().max(y.abs()) {
                let (table, index, field) = if k < shafts {
                    ("shaft", k, "between")
                } else {
                    ("mesh", k - shafts, "teeth")
                };
                return Err(fault(
                    table,
                    index,
                    field,
                    format!(
                        "closes a loop whose ratios do not close: the rest of the rig turns `{}` at {:.6} times the speed of `{}`, this joint at {ratio:.6}; a back-to-back rig needs two gearboxes of equal ratio",
                        self.bodies[b].name,
                        y / x,
                        self.bodies[a].name
                    ),
                ));
            }
        }
        self.check_stages_close(&speeds)
    }

    /// A stage whose sun, ring and carrier the rest of the rig turns must turn them as
    /// Willis's equation says.
    fn check_stages_close(&self, speeds: &[Option<f64>]) -> Result<(), TopologyError> {
        for (k, stage) in self.planetary.iter().enumerate() {
            let [Some(s), Some(r), Some(c)] =
                [stage.sun, stage.ring, stage.carrier].map(|b| speeds[b])
            else {
                continue;
            };
            let Some([_, _, willis]) = stage.willis(Some(s), Some(r), None) else {
                continue;
            };
            if (willis - c).abs() > 1e-9 * s.abs().max(r.abs()).max(c.abs()) {
                return Err(fault(
                    "planetary",
                    k,
                    "carrier",
                    format!(
                        "the rest of the rig turns sun, ring and carrier at {s:.6}, {r:.6} and {c:.6}; the stage's teeth need the carrier at {willis:.6}"
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// Fault `k` of item `i` of `table`: on a tooth 1..=`teeth` of `gear`, its severity in
/// [0, 1].
pub(super) fn check_tooth_fault(
    (table, i, k): (&'static str, usize, usize),
    (gear, teeth): (&str, u32),
    tooth: u32,
    severity: f64,
) -> Result<(), TopologyError> {
    if !(1..=teeth).contains(&tooth) {
        return Err(fault(
            table,
            i,
            "fault",
            format!(
                "fault {}: tooth {tooth} of the {gear}, which has teeth 1 to {teeth}",
                k + 1
            ),
        ));
    }
    if !(0.0..=1.0).contains(&severity) {
        return Err(fault(
            table,
            i,
            "fault",
            format!(
                "fault {}: severity {severity}: a share of the tooth, 0 to 1",
                k + 1
            ),
        ));
    }
    Ok(())
}
