//! A planetary stage's numbers and words by path: `planetary.NAME.FIELD`,
//! `planetary.NAME.sun_planet.FIELD` (and `ring_planet`), `planetary.NAME.faultK.severity`,
//! and the words `planetary.NAME.faultK.kind` and `.gear` (`fields.rs` lists and sets them
//! with the rest of the rig's).

use super::planetary::StageMember;
use super::rig_topology::RigTopology;
use crate::error::RigError;
use crate::tooth_fault::FaultKind;

/// A planetary stage's numbers settable by path (`planetary.NAME.FIELD`).
pub(super) const STAGE: [(&str, &str, &str); 5] = [
    (
        "planet_inertia_kgm2",
        "kg m^2",
        "each planet's moment of inertia",
    ),
    (
        "planet_mass_kg",
        "kg",
        "each planet's mass on its pin's bearing",
    ),
    (
        "planet_bearing_stiffness_n_per_m",
        "N/m",
        "each pin bearing's radial stiffness",
    ),
    (
        "planet_bearing_damping_ns_per_m",
        "N s/m",
        "each pin bearing's radial damping",
    ),
    ("pressure_angle_deg", "deg", "both meshes' pressure angle"),
];

/// A stage mesh's numbers settable by path (`planetary.NAME.sun_planet.FIELD`).
pub(super) const STAGE_MESH: [(&str, &str, &str); 5] = [
    (
        "stiffness_n_per_m",
        "N/m",
        "one pair's stiffness along the line of action",
    ),
    (
        "damping_ns_per_m",
        "N s/m",
        "damping along the line of action",
    ),
    (
        "backlash_mm",
        "mm",
        "total circular backlash at the pitch circles",
    ),
    (
        "double_pair_ratio",
        "1",
        "two pairs' stiffness over one pair's",
    ),
    (
        "stiffness_smoothing",
        "1",
        "width of each change between one and two pairs over the pitch",
    ),
];

impl RigTopology {
    /// Sets a stage fault's kind or gear (`sun`, `ring`, `planet<k>`) at `path`.
    pub(super) fn set_stage_word(
        &mut self,
        path: &str,
        (name, fault, field): (&str, &str, &str),
        word: &str,
    ) -> Result<(), RigError> {
        let unknown = self.unknown_path(path);
        let found = self
            .planetary
            .iter_mut()
            .find(|s| s.name == name)
            .and_then(|s| {
                let k = fault.strip_prefix("fault")?.parse::<usize>().ok()?;
                let planets = s.planets();
                let f = s.faults.get_mut(k.checked_sub(1)?)?;
                Some((f, planets))
            });
        let Some((f, planets)) = found else {
            return Err(unknown);
        };
        let invalid = |allowed: String| RigError::InvalidParameter {
            name: path.to_string(),
            value: word.to_string(),
            allowed,
        };
        if field == "kind" {
            f.kind = FaultKind::parse(word)
                .ok_or_else(|| invalid(format!("the kinds are {}", FaultKind::NAMES.join(", "))))?;
        } else {
            f.member = StageMember::parse(word, planets)
                .ok_or_else(|| invalid(format!("sun, ring or planet1 to planet{planets}")))?;
        }
        Ok(())
    }

    /// The stage number at `parts` (`["planetary", NAME, …]`), if the rig has it.
    pub(super) fn stage_slot(&mut self, parts: &[&str]) -> Option<&mut f64> {
        match parts {
            ["planetary", name, field] => {
                let s = self.planetary.iter_mut().find(|s| s.name == *name)?;
                match *field {
                    "planet_inertia_kgm2" => Some(&mut s.planet_inertia_kgm2),
                    "planet_mass_kg" => s.planet_bearing.as_mut().map(|b| &mut b.mass_kg),
                    "planet_bearing_stiffness_n_per_m" => {
                        s.planet_bearing.as_mut().map(|b| &mut b.stiffness_n_per_m)
                    }
                    "planet_bearing_damping_ns_per_m" => {
                        s.planet_bearing.as_mut().map(|b| &mut b.damping_ns_per_m)
                    }
                    "pressure_angle_deg" => Some(&mut s.pressure_angle_deg),
                    _ => None,
                }
            }
            [
                "planetary",
                name,
                mesh @ ("sun_planet" | "ring_planet"),
                field,
            ] => {
                let s = self.planetary.iter_mut().find(|s| s.name == *name)?;
                let m = if *mesh == "sun_planet" {
                    &mut s.sun_planet
                } else {
                    &mut s.ring_planet
                };
                match *field {
                    "stiffness_n_per_m" => Some(&mut m.stiffness_n_per_m),
                    "damping_ns_per_m" => Some(&mut m.damping_ns_per_m),
                    "backlash_mm" => Some(&mut m.backlash_mm),
                    "double_pair_ratio" => Some(&mut m.double_pair_ratio),
                    "stiffness_smoothing" => Some(&mut m.stiffness_smoothing),
                    _ => None,
                }
            }
            ["planetary", name, fault, "severity"] => {
                let s = self.planetary.iter_mut().find(|s| s.name == *name)?;
                let k: usize = fault.strip_prefix("fault")?.parse().ok()?;
                s.faults.get_mut(k.checked_sub(1)?).map(|f| &mut f.severity)
            }
            _ => None,
        }
    }
}
