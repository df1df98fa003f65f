//! Every number of a rig by its path, as a rig file names it (`body.motor.inertia_kgm2`,
//! `shaft.input.stiffness_nm_per_rad`, `mesh.stage1.backlash_mm`, `motor.torque_limit_nm`,
//! `locked_torque.torque_nm` …), with unit and meaning: what `testrig params --rig` lists
//! and what `--set`, sweeps and calibration change.

use super::rig_topology::RigTopology;
use super::stage_fields::{STAGE, STAGE_MESH};
use crate::error::RigError;
use crate::nearest::did_you_mean;
use crate::tooth_fault::FaultKind;

/// One number of a rig.
#[derive(Clone, Debug, PartialEq)]
pub struct TopologyField {
    /// Its path, `table.item.field` or `table.field`.
    pub path: String,
    /// Its value (SI or as the unit says).
    pub value: f64,
    /// Its unit.
    pub unit: &'static str,
    /// What it is.
    pub meaning: &'static str,
}

/// The fields of each table: (field, unit, meaning).
const BODY: [(&str, &str, &str); 5] = [
    ("inertia_kgm2", "kg m^2", "moment of inertia"),
    ("drag_nms_per_rad", "N m s/rad", "bearing and windage drag"),
    ("mass_kg", "kg", "mass, moving in the plane on its bearing"),
    (
        "bearing_stiffness_n_per_m",
        "N/m",
        "its bearing's radial stiffness",
    ),
    (
        "bearing_damping_ns_per_m",
        "N s/m",
        "its bearing's radial damping",
    ),
];
const SHAFT: [(&str, &str, &str); 2] = [
    ("stiffness_nm_per_rad", "N m/rad", "torsional stiffness"),
    ("damping_nms_per_rad", "N m s/rad", "torsional damping"),
];
const MESH: [(&str, &str, &str); 18] = [
    ("module_m", "m", "module"),
    ("pressure_angle_deg", "deg", "pressure angle"),
    (
        "backlash_mm",
        "mm",
        "total circular backlash at the pitch circles",
    ),
    (
        "centre_distance_shift_mm",
        "mm",
        "operating centre distance over the standard, for the contact ratio",
    ),
    (
        "centre_line_deg",
        "deg",
        "direction from the driver's centre to the driven gear's",
    ),
    (
        "stiffness_n_per_m",
        "N/m",
        "one tooth pair, along the line of action",
    ),
    ("damping_ns_per_m", "N s/m", "along the line of action"),
    (
        "double_pair_ratio",
        "1",
        "two pairs' stiffness over one pair's",
    ),
    ("addendum_coefficient", "1", "addendum over the module"),
    (
        "stiffness_smoothing",
        "1",
        "width of each one/two-pair change over the pitch (0: sharp)",
    ),
    (
        "backlash_variation",
        "1",
        "C1 of the free play b(1 - C1 cos θ), once per revolution",
    ),
    (
        "te_once_per_rev_um",
        "um",
        "transmission error once per revolution of the driver",
    ),
    (
        "te_mesh_frequency_um",
        "um",
        "transmission error at mesh frequency",
    ),
    (
        "run_out_driver_um",
        "um",
        "run-out of the driving gear, once per its revolution",
    ),
    (
        "run_out_driven_um",
        "um",
        "run-out of the driven gear, once per its revolution",
    ),
    (
        "tooth_spacing_error_um",
        "um",
        "RMS of the tooth-pair spacing errors along the line of action",
    ),
    (
        "gear_error_c2_nm",
        "N m",
        "C2 of the gear-error torque -C2 cos θ on both gears",
    ),
    (
        "gear_error_c3_nm",
        "N m",
        "C3 of the gear-error torque -C3 cos 2θ on both gears",
    ),
];
const MOTOR: [(&str, &str, &str); 8] = [
    (
        "torque_limit_nm",
        "N m",
        "most torque either way (none: no limit)",
    ),
    ("speed_loop_hz", "Hz", "speed-loop natural frequency"),
    ("speed_loop_damping_ratio", "1", "speed-loop damping ratio"),
    ("feedback_filter_hz", "Hz", "speed feedback filter corner"),
    ("rated_power_w", "W", "the drive's rated output"),
    ("rated_speed_rpm", "rev/min", "the drive's rated speed"),
    ("full_load_current_a", "A", "the drive's full-load current"),
    (
        "current_limit_pct",
        "%",
        "armature current limit over full-load current",
    ),
];
const BRAKE: [(&str, &str, &str); 3] = [
    (
        "slope_nms_per_rad",
        "N m s/rad",
        "rise of the brake torque with speed",
    ),
    ("drag_nm", "N m", "residual drag added to the set load"),
    (
        "critical_speed_rpm",
        "rev/min",
        "the eddy-current brake's critical speed (0: off)",
    ),
];

impl RigTopology {
    /// Every number of the rig by its path, in the file's order.
    pub fn fields(&self) -> Vec<TopologyField> {
        let mut paths: Vec<(String, &'static str, &'static str)> = Vec::new();
        let mut add = |prefix: String, table: &[(&'static str, &'static str, &'static str)]| {
            for (field, unit, meaning) in table {
                paths.push((format!("{prefix}.{field}"), unit, meaning));
            }
        };
        for b in &self.bodies {
            add(format!("body.{}", b.name), &BODY);
        }
        for s in &self.shafts {
            add(format!("shaft.{}", s.name), &SHAFT);
        }
        for s in &self.frame_shafts {
            add(format!("shaft.{}", s.name), &SHAFT);
        }
        for m in &self.meshes {
            add(format!("mesh.{}", m.name), &MESH);
            for k in 1..=m.faults.len() {
                add(
                    format!("mesh.{}.fault{k}", m.name),
                    &[(
                        "severity",
                        "1",
                        "the tooth fault's severity (pitted or broken share)",
                    )],
                );
            }
        }
        for s in &self.planetary {
            add(format!("planetary.{}", s.name), &STAGE);
            for mesh in ["sun_planet", "ring_planet"] {
                add(format!("planetary.{}.{mesh}", s.name), &STAGE_MESH);
            }
            for k in 1..=s.faults.len() {
                add(
                    format!("planetary.{}.fault{k}", s.name),
                    &[("severity", "1", "the tooth fault's severity")],
                );
            }
        }
        add("motor".into(), &MOTOR);
        add("brake".into(), &BRAKE);
        if self.gauge.is_some() {
            add(
                "gauge".into(),
                &[
                    ("diameter_m", "m", "the gauged shaft's diameter"),
                    ("shear_modulus_pa", "Pa", "the gauged shaft's shear modulus"),
                ],
            );
        }
        if self.locked_torque.is_some() {
            add(
                "locked_torque".into(),
                &[(
                    "torque_nm",
                    "N m",
                    "torque the loop's shaft carries at rest",
                )],
            );
        }
        let mut copy = self.clone();
        paths
            .into_iter()
            .filter_map(|(path, unit, meaning)| {
                let value = *copy.slot(&path)?;
                Some(TopologyField {
                    path,
                    value,
                    unit,
                    meaning,
                })
            })
            .collect()
    }

    /// The refusal of an unknown `path`, with the rig's nearest paths.
    pub(super) fn unknown_path(&self, path: &str) -> RigError {
        let paths: Vec<String> = self.fields().into_iter().map(|f| f.path).collect();
        RigError::UnknownParameter {
            name: path.to_string(),
            near: did_you_mean(path, paths.iter().map(String::as_str)),
        }
    }

    /// Sets the number at `path` (checked with the whole rig by [`RigTopology::check`]).
    pub fn set_field(&mut self, path: &str, value: f64) -> Result<(), RigError> {
        if path == "motor.torque_limit_nm" {
            self.drive.torque_limit_nm.get_or_insert(value);
        }
        let unknown = self.unknown_path(path);
        let slot = self.slot(path).ok_or(unknown)?;
        *slot = value;
        Ok(())
    }

    /// The word at `path`: a tooth fault's kind by name, `mesh.NAME.faultK.kind` or
    /// `planetary.STAGE.faultK.kind`, or a stage fault's gear, `planetary.STAGE.faultK.gear`.
    pub fn word(&self, path: &str) -> Option<String> {
        let parts: Vec<&str> = path.split('.').collect();
        let fault_index = |fault: &str| -> Option<usize> {
            fault
                .strip_prefix("fault")?
                .parse::<usize>()
                .ok()?
                .checked_sub(1)
        };
        match parts.as_slice() {
            ["mesh", name, fault, "kind"] => {
                let mesh = self.meshes.iter().find(|m| m.name == *name)?;
                let f = mesh.faults.get(fault_index(fault)?)?;
                Some(f.kind.name().to_string())
            }
            ["planetary", name, fault, field @ ("kind" | "gear")] => {
                let stage = self.planetary.iter().find(|s| s.name == *name)?;
                let f = stage.faults.get(fault_index(fault)?)?;
                Some(match *field {
                    "kind" => f.kind.name().to_string(),
                    _ => f.member.name(),
                })
            }
            _ => None,
        }
    }

    /// Sets the word at `path`: a tooth fault's kind, `mesh.NAME.faultK.kind`, one of
    /// [`FaultKind::NAMES`] (a sweep's grid turns a seeded crack into a pit so).
    pub fn set_word(&mut self, path: &str, word: &str) -> Result<(), RigError> {
        let parts: Vec<&str> = path.split('.').collect();
        if let ["planetary", name, fault, field @ ("kind" | "gear")] = parts.as_slice() {
            return self.set_stage_word(path, (name, fault, field), word);
        }
        let found = match parts.as_slice() {
            ["mesh", name, fault, "kind"] => fault
                .strip_prefix("fault")
                .and_then(|k| k.parse::<usize>().ok())
                .and_then(|k| {
                    let m = self.meshes.iter().position(|m| m.name == *name)?;
                    (1..=self.meshes[m].faults.len())
                        .contains(&k)
                        .then_some((m, k - 1))
                }),
            _ => None,
        };
        let Some((m, f)) = found else {
            return Err(self.unknown_path(path));
        };
        self.meshes[m].faults[f].kind =
            FaultKind::parse(word).ok_or_else(|| RigError::InvalidParameter {
                name: path.to_string(),
                value: word.to_string(),
                allowed: format!("the kinds are {}", FaultKind::NAMES.join(", ")),
            })?;
        Ok(())
    }

    /// The number at `path`, if the rig has it (a motor without a torque limit has none).
    fn slot(&mut self, path: &str) -> Option<&mut f64> {
        let parts: Vec<&str> = path.split('.').collect();
        match parts.as_slice() {
            ["body", name, field] => {
                let b = self.bodies.iter_mut().find(|b| b.name == *name)?;
                match *field {
                    "inertia_kgm2" => Some(&mut b.inertia_kgm2),
                    "drag_nms_per_rad" => Some(&mut b.drag_nms_per_rad),
                    "mass_kg" => b.planar.as_mut().map(|p| &mut p.mass_kg),
                    "bearing_stiffness_n_per_m" => {
                        b.planar.as_mut().map(|p| &mut p.stiffness_n_per_m)
                    }
                    "bearing_damping_ns_per_m" => {
                        b.planar.as_mut().map(|p| &mut p.damping_ns_per_m)
                    }
                    _ => None,
                }
            }
            ["shaft", name, field] => {
                if let Some(s) = self.frame_shafts.iter_mut().find(|s| s.name == *name) {
                    return match *field {
                        "stiffness_nm_per_rad" => Some(&mut s.stiffness_nm_per_rad),
                        "damping_nms_per_rad" => Some(&mut s.damping_nms_per_rad),
                        _ => None,
                    };
                }
                let s = self.shafts.iter_mut().find(|s| s.name == *name)?;
                match *field {
                    "stiffness_nm_per_rad" => Some(&mut s.stiffness_nm_per_rad),
                    "damping_nms_per_rad" => Some(&mut s.damping_nms_per_rad),
                    _ => None,
                }
            }
            ["mesh", name, field] => {
                let m = self.meshes.iter_mut().find(|m| m.name == *name)?;
                match *field {
                    "module_m" => Some(&mut m.module_m),
                    "pressure_angle_deg" => Some(&mut m.pressure_angle_deg),
                    "backlash_mm" => Some(&mut m.backlash_mm),
                    "centre_distance_shift_mm" => Some(&mut m.centre_distance_shift_mm),
                    "centre_line_deg" => Some(&mut m.centre_line_deg),
                    "stiffness_n_per_m" => Some(&mut m.stiffness_n_per_m),
                    "damping_ns_per_m" => Some(&mut m.damping_ns_per_m),
                    "double_pair_ratio" => Some(&mut m.double_pair_ratio),
                    "addendum_coefficient" => Some(&mut m.addendum_coefficient),
                    "stiffness_smoothing" => Some(&mut m.stiffness_smoothing),
                    "backlash_variation" => Some(&mut m.backlash_variation),
                    "te_once_per_rev_um" => Some(&mut m.te_once_per_rev_um),
                    "run_out_driver_um" => Some(&mut m.run_out_driver_um),
                    "run_out_driven_um" => Some(&mut m.run_out_driven_um),
                    "tooth_spacing_error_um" => Some(&mut m.tooth_spacing_error_um),
                    "te_mesh_frequency_um" => Some(&mut m.te_mesh_frequency_um),
                    "gear_error_c2_nm" => Some(&mut m.gear_error_c2_nm),
                    "gear_error_c3_nm" => Some(&mut m.gear_error_c3_nm),
                    _ => None,
                }
            }
            ["mesh", name, fault, "severity"] => {
                let m = self.meshes.iter_mut().find(|m| m.name == *name)?;
                let k: usize = fault.strip_prefix("fault")?.parse().ok()?;
                m.faults.get_mut(k.checked_sub(1)?).map(|f| &mut f.severity)
            }
            ["planetary", ..] => self.stage_slot(&parts),
            ["motor", field] => {
                let d = &mut self.drive;
                match *field {
                    "torque_limit_nm" => d.torque_limit_nm.as_mut(),
                    "speed_loop_hz" => Some(&mut d.speed_loop_hz),
                    "speed_loop_damping_ratio" => Some(&mut d.speed_loop_damping_ratio),
                    "feedback_filter_hz" => Some(&mut d.feedback_filter_hz),
                    "rated_power_w" => d.ratings.as_mut().map(|r| &mut r.rated_power_w),
                    "rated_speed_rpm" => d.ratings.as_mut().map(|r| &mut r.rated_speed_rpm),
                    "full_load_current_a" => d
                        .ratings
                        .as_mut()
                        .and_then(|r| r.full_load_current_a.as_mut()),
                    "current_limit_pct" => d.ratings.as_mut().map(|r| &mut r.current_limit_pct),
                    _ => None,
                }
            }
            ["brake", "slope_nms_per_rad"] => Some(&mut self.drive.brake_slope_nms_per_rad),
            ["brake", "drag_nm"] => Some(&mut self.drive.brake_drag_nm),
            ["brake", "critical_speed_rpm"] => Some(&mut self.drive.brake_critical_speed_rpm),
            ["gauge", "diameter_m"] => self.gauge.as_mut().map(|g| &mut g.diameter_m),
            ["gauge", "shear_modulus_pa"] => self.gauge.as_mut().map(|g| &mut g.shear_modulus_pa),
            ["locked_torque", "torque_nm"] => self.locked_torque.as_mut().map(|l| &mut l.torque_nm),
            _ => None,
        }
    }
}
