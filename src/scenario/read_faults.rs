//! A tooth fault read from a rig or sweep file: a `[[mesh.fault]]` on a mesh's driver or
//! driven gear, a `[[planetary.fault]]` on a stage's sun, ring or planet, and a sweep's
//! `[[rig.fault]]` seeded on the mesh or stage it names; each field refused at its place
//! with what is allowed.

use rig::{FaultKind, FaultedGear, RigTopology, StageFault, StageMember, StageTeeth, ToothFault};

use super::rig_file_toml::FaultToml;
use super::source::ScenarioSource;

/// Seeds each of `faults` (a sweep's `[[rig.fault]]`, each naming its mesh, or a
/// planetary stage with `gear` its sun, ring or planet) on the mesh or stage of `rig` it
/// names, after the faults the rig file gives; each refused at its place.
pub(crate) fn seed_faults(
    src: &ScenarioSource,
    rig: &mut RigTopology,
    faults: &[FaultToml],
) -> anyhow::Result<()> {
    for f in faults {
        let Some(name) = &f.mesh else {
            return Err(src.error(
                f.gear.span(),
                "rig.fault.mesh",
                "missing: name the mesh the fault is seeded on",
            ));
        };
        if let Some(stage) = rig.planetary.iter_mut().find(|s| s.name == *name.get_ref()) {
            let shape = (stage.teeth, stage.planets());
            let fault = checked_stage_fault(src, f, shape, "rig.fault")?;
            stage.faults.push(fault);
            continue;
        }
        let known: Vec<&str> = rig
            .meshes
            .iter()
            .map(|m| m.name.as_str())
            .chain(rig.planetary.iter().map(|s| s.name.as_str()))
            .collect();
        let known = known.join(", ");
        let Some(mesh) = rig.meshes.iter_mut().find(|m| m.name == *name.get_ref()) else {
            return Err(src.error(
                name.span(),
                "rig.fault.mesh",
                format!("`{}`: the rig's meshes are {known}", name.get_ref()),
            ));
        };
        let fault = checked_fault(src, f, mesh.teeth, "rig.fault")?;
        mesh.faults.push(fault);
    }
    Ok(())
}

/// A `[[mesh.fault]]` read, each field refused at its place with what is allowed.
pub(super) fn tooth_fault(
    src: &ScenarioSource,
    f: &FaultToml,
    teeth: [u32; 2],
) -> anyhow::Result<ToothFault> {
    if let Some(mesh) = &f.mesh {
        return Err(src.error(
            mesh.span(),
            "mesh.fault.mesh",
            "a rig file's fault belongs to the [[mesh]] above it: leave out `mesh`",
        ));
    }
    checked_fault(src, f, teeth, "mesh.fault")
}

/// A fault's gear, tooth, kind and severity, each refused at its place (`table` names it).
fn checked_fault(
    src: &ScenarioSource,
    f: &FaultToml,
    teeth: [u32; 2],
    table: &str,
) -> anyhow::Result<ToothFault> {
    let gear = |name: &str| match name {
        "driver" => Some((FaultedGear::Driver, teeth[0])),
        "driven" => Some((FaultedGear::Driven, teeth[1])),
        _ => None,
    };
    let (gear, tooth, kind, severity) = fault_fields(src, f, table, gear, "`driver` or `driven`")?;
    Ok(ToothFault {
        gear,
        tooth,
        kind,
        severity,
    })
}

/// A fault's gear (`gear` names it and its teeth, else it is not one of `gears`), tooth,
/// kind and severity, each refused at its place (`table` names it).
pub(super) fn fault_fields<G>(
    src: &ScenarioSource,
    f: &FaultToml,
    table: &str,
    gear: impl Fn(&str) -> Option<(G, u32)>,
    gears: &str,
) -> anyhow::Result<(G, u32, FaultKind, f64)> {
    let Some((gear, z)) = gear(f.gear.get_ref()) else {
        return Err(src.error(
            f.gear.span(),
            &format!("{table}.gear"),
            format!("`{}`: the fault's gear is {gears}", f.gear.get_ref()),
        ));
    };
    let kind = FaultKind::parse(f.kind.get_ref()).ok_or_else(|| {
        src.error(
            f.kind.span(),
            &format!("{table}.kind"),
            format!(
                "`{}`: the kinds are {}",
                f.kind.get_ref(),
                FaultKind::NAMES.join(", ")
            ),
        )
    })?;
    let tooth = *f.tooth.get_ref();
    if !(1..=z).contains(&tooth) {
        return Err(src.error(
            f.tooth.span(),
            &format!("{table}.tooth"),
            format!("{tooth}: the {} gear has teeth 1 to {z}", f.gear.get_ref()),
        ));
    }
    let severity = *f.severity.get_ref();
    if !(0.0..=1.0).contains(&severity) {
        return Err(src.error(
            f.severity.span(),
            &format!("{table}.severity"),
            format!("{severity}: a share of the tooth, 0 to 1"),
        ));
    }
    Ok((gear, tooth, kind, severity))
}

/// A stage fault's gear (`sun`, `ring`, `planet<k>` of a stage of these teeth and
/// planets), tooth, kind and severity, each refused at its place (`table` names it).
pub(super) fn checked_stage_fault(
    src: &ScenarioSource,
    f: &FaultToml,
    (teeth, planets): (StageTeeth, usize),
    table: &str,
) -> anyhow::Result<StageFault> {
    let gear = |name: &str| {
        StageMember::parse(name, planets).map(|member| {
            let z = match member {
                StageMember::Sun => teeth.sun,
                StageMember::Ring => teeth.ring,
                StageMember::Planet(_) => teeth.planet,
            };
            (member, z)
        })
    };
    let gears = format!("`sun`, `ring` or `planet1` to `planet{planets}`");
    let (member, tooth, kind, severity) = fault_fields(src, f, table, gear, &gears)?;
    Ok(StageFault {
        member,
        tooth,
        kind,
        severity,
    })
}
