//! A rig file read into a checked `rig::RigTopology`: names resolved to bodies and
//! shafts, defaults filled in, the topology checked (`RigTopology::check`); every fault
//! at file:line:column with its field and what is allowed.

use std::collections::HashMap;
use std::path::Path;

use rig::{
    Body, DriveRatings, DriveSettings, FrameShaft, Gauge, LockedTorque, Mesh, RigTopology, Shaft,
};
use toml::Spanned;

use crate::vocabulary::signal_names::SHAFT_TORQUE_NM;

use super::read_rig_mesh::{mesh, or};
use super::read_rig_planetary::{FRAME, planar_bearing, planetary_stage};
use super::rig_fault_place::{field_name, span_of};
use super::rig_file_toml::{BrakeToml, KeyphasorToml, MotorToml, RigFileToml, ShaftToml};
use super::source::ScenarioSource;

/// Shear modulus where a gauge leaves it out (Pa): steel's.
const STEEL_SHEAR_MODULUS_PA: f64 = 80.0e9;

/// Reads and checks the rig file at `path`.
pub fn read_rig_file(path: &Path) -> anyhow::Result<RigTopology> {
    rig_topology(&ScenarioSource::read(path)?)
}

/// The checked rig of a rig file's text.
pub fn rig_topology(src: &ScenarioSource) -> anyhow::Result<RigTopology> {
    let file: RigFileToml = src.parse_rig_file()?;
    let rig = build(src, &file)?;
    rig.check()
        .map_err(|e| src.error(span_of(&file, &e.place), &field_name(&rig, &e.place), &e))?;
    Ok(rig)
}

/// The rig the file describes, its names resolved.
fn build(src: &ScenarioSource, file: &RigFileToml) -> anyhow::Result<RigTopology> {
    let bodies = names(src, "body", file.bodies.iter().map(|b| &b.name))?;
    if let Some(b) = file.bodies.iter().find(|b| b.name.get_ref() == FRAME) {
        return Err(src.error(
            b.name.span(),
            "body.name",
            "`frame` is reserved: the housing, which a shaft between = [body, \"frame\"] holds a body to; name the body otherwise",
        ));
    }
    names(src, "shaft", file.shafts.iter().map(|s| &s.name))?;
    names(src, "mesh", file.meshes.iter().map(|m| &m.name))?;
    names(src, "planetary", file.planetary.iter().map(|p| &p.name))?;
    let body = |name: &Spanned<String>, field: &str| -> anyhow::Result<usize> {
        bodies.get(name.get_ref().as_str()).copied().ok_or_else(|| {
            src.error(
                name.span(),
                field,
                format!(
                    "no body `{}`; the bodies are {}",
                    name.get_ref(),
                    listed(file.bodies.iter().map(|b| b.name.get_ref()))
                ),
            )
        })
    };
    let mut shafts = Vec::new();
    let mut frame_shafts = Vec::new();
    for s in &file.shafts {
        match shaft(src, s, &body)? {
            ReadShaft::Between(shaft) => shafts.push(shaft),
            ReadShaft::Frame(shaft) => frame_shafts.push(shaft),
        }
    }
    // Gauges and locked torques name shafts between two bodies.
    let shaft_names: HashMap<&str, usize> = shafts
        .iter()
        .enumerate()
        .map(|(i, s)| (s.name.as_str(), i))
        .collect();
    let planetary = file
        .planetary
        .iter()
        .map(|p| planetary_stage(src, p, &body))
        .collect::<anyhow::Result<Vec<_>>>()?;
    let meshes = file
        .meshes
        .iter()
        .map(|m| mesh(src, m, &body))
        .collect::<anyhow::Result<Vec<_>>>()?;
    let shaft_index = |name: &Spanned<String>, field: &str| -> anyhow::Result<usize> {
        shaft_names
            .get(name.get_ref().as_str())
            .copied()
            .ok_or_else(|| {
                src.error(
                    name.span(),
                    field,
                    format!(
                        "no shaft `{}`; the shafts are {}",
                        name.get_ref(),
                        listed(shafts.iter().map(|s| &s.name))
                    ),
                )
            })
    };
    let gauge = match &file.gauge {
        None => None,
        Some(g) => Some(Gauge {
            shaft: shaft_index(&g.shaft, "gauge.shaft")?,
            diameter_m: *g.diameter_m.get_ref(),
            shear_modulus_pa: or(&g.shear_modulus_pa, STEEL_SHEAR_MODULUS_PA),
        }),
    };
    refuse_shadowed_torque(src, file, &shafts, gauge.as_ref())?;
    let locked_torque = match &file.locked_torque {
        None => None,
        Some(l) => {
            let shaft = *shaft_names.get(l.shaft.get_ref().as_str()).ok_or_else(|| {
                src.error(
                    l.shaft.span(),
                    "locked_torque.shaft",
                    format!(
                        "no shaft `{}` between two bodies; those shafts are {}",
                        l.shaft.get_ref(),
                        listed(shafts.iter().map(|s| &s.name))
                    ),
                )
            })?;
            Some(LockedTorque {
                shaft,
                torque_nm: *l.torque_nm.get_ref(),
            })
        }
    };
    let keyphasor = file
        .keyphasor
        .as_ref()
        .map(|k| keyphasor_gear(src, file, &meshes, body(&k.gear, "keyphasor.gear")?, k))
        .transpose()?;
    Ok(RigTopology {
        name: file.name.get_ref().clone(),
        description: file.description.clone().unwrap_or_default(),
        reproduces: reproduces(src, file)?,
        bodies: file
            .bodies
            .iter()
            .map(|b| {
                Ok(Body {
                    name: b.name.get_ref().clone(),
                    inertia_kgm2: *b.inertia_kgm2.get_ref(),
                    drag_nms_per_rad: or(&b.drag_nms_per_rad, 0.0),
                    planar: planar_bearing(
                        src,
                        [&b.mass_kg, &b.bearing_stiffness_n_per_m],
                        &b.bearing_damping_ns_per_m,
                        &format!("body `{}`.mass_kg", b.name.get_ref()),
                    )?,
                })
            })
            .collect::<anyhow::Result<Vec<_>>>()?,
        shafts,
        meshes,
        frame_shafts,
        planetary,
        motor: file
            .motor
            .as_ref()
            .map(|m| body(&m.body, "motor.body"))
            .transpose()?,
        brake: file
            .brake
            .as_ref()
            .map(|b| body(&b.body, "brake.body"))
            .transpose()?,
        locked_torque,
        drive: drive(src, file)?,
        gauge,
        tacho: file
            .tacho
            .as_ref()
            .map(|t| body(&t.body, "tacho.body"))
            .transpose()?,
        keyphasor,
    })
}

/// Refuses, on a gauged rig, a shaft (between two bodies or to the frame) other than the
/// gauged one whose torque column is named [`SHAFT_TORQUE_NM`], the measuring chain's
/// input for the gauged shaft's torque: a chain, analyser or recording reading it by name
/// would get the gauged shaft's instead. A rig without gauges hands no chain a torque, so
/// nothing is shadowed.
fn refuse_shadowed_torque(
    src: &ScenarioSource,
    file: &RigFileToml,
    shafts: &[Shaft],
    gauge: Option<&Gauge>,
) -> anyhow::Result<()> {
    let Some(gauge) = gauge else {
        return Ok(());
    };
    let gauged = &shafts[gauge.shaft].name;
    let shadowed = file.shafts.iter().find(|s| {
        s.name.get_ref() != gauged && rig::shaft_torque_column(s.name.get_ref()) == SHAFT_TORQUE_NM
    });
    let Some(toml) = shadowed else {
        return Ok(());
    };
    Err(src.error(
        toml.name.span(),
        "shaft.name",
        format!(
            "`{}` is the measuring chain's name for the gauged shaft (`{SHAFT_TORQUE_NM}` is \
             the strain stage's input), and this shaft is not under the [gauge]; name it \
             otherwise, or gauge it",
            toml.name.get_ref()
        ),
    ))
}

/// The keyphasor's gear, body `gear`: refused unless it is some mesh's gear (the
/// indicators it starts need its teeth).
fn keyphasor_gear(
    src: &ScenarioSource,
    file: &RigFileToml,
    meshes: &[Mesh],
    gear: usize,
    table: &KeyphasorToml,
) -> anyhow::Result<usize> {
    if meshes.iter().any(|m| m.gears.contains(&gear)) {
        return Ok(gear);
    }
    let gears = meshes
        .iter()
        .flat_map(|m| m.gears)
        .map(|g| file.bodies[g].name.get_ref());
    Err(src.error(
        table.gear.span(),
        "keyphasor.gear",
        format!(
            "body `{}` is no mesh's gear; the gears are {}",
            table.gear.get_ref(),
            listed(gears)
        ),
    ))
}

/// The drive settings of `[motor]` and `[brake]`, defaults where they are silent.
fn drive(src: &ScenarioSource, file: &RigFileToml) -> anyhow::Result<DriveSettings> {
    let d = DriveSettings::default();
    let motor = file.motor.as_ref();
    let motor_field = |f: fn(&MotorToml) -> &Option<Spanned<f64>>, default: f64| {
        motor.map_or(default, |m| or(f(m), default))
    };
    let brake_field = |f: fn(&BrakeToml) -> &Option<Spanned<f64>>| {
        file.brake.as_ref().map_or(0.0, |b| or(f(b), 0.0))
    };
    Ok(DriveSettings {
        torque_limit_nm: motor.and_then(|m| m.torque_limit_nm.as_ref().map(|t| *t.get_ref())),
        ratings: motor.map(|m| ratings(src, m)).transpose()?.flatten(),
        speed_loop_hz: motor_field(|m| &m.speed_loop_hz, d.speed_loop_hz),
        speed_loop_damping_ratio: motor_field(
            |m| &m.speed_loop_damping_ratio,
            d.speed_loop_damping_ratio,
        ),
        feedback_filter_hz: motor_field(|m| &m.feedback_filter_hz, d.feedback_filter_hz),
        brake_slope_nms_per_rad: brake_field(|b| &b.slope_nms_per_rad),
        brake_drag_nm: brake_field(|b| &b.drag_nm),
        brake_critical_speed_rpm: brake_field(|b| &b.critical_speed_rpm),
    })
}

/// The drive's ratings of `[motor]`, if it gives any: rated power and speed both, the
/// current limit 100 % of full-load current where left out.
fn ratings(src: &ScenarioSource, m: &MotorToml) -> anyhow::Result<Option<DriveRatings>> {
    let given = [
        &m.rated_power_w,
        &m.rated_speed_rpm,
        &m.full_load_current_a,
        &m.current_limit_pct,
    ];
    let Some(first) = given.iter().find_map(|v| v.as_ref()) else {
        return Ok(None);
    };
    let (Some(power), Some(speed)) = (&m.rated_power_w, &m.rated_speed_rpm) else {
        return Err(src.error(
            first.span(),
            "motor.rated_power_w",
            "the drive's ratings need rated_power_w (W) and rated_speed_rpm (rev/min) both; current_limit_pct (%, 100 when left out) sets the torque limit from them",
        ));
    };
    Ok(Some(DriveRatings {
        rated_power_w: *power.get_ref(),
        rated_speed_rpm: *speed.get_ref(),
        full_load_current_a: m.full_load_current_a.as_ref().map(|c| *c.get_ref()),
        current_limit_pct: or(&m.current_limit_pct, 100.0),
    }))
}

/// The published rig the file says it is, one of [`RigTopology::REPRODUCIBLE`].
fn reproduces(src: &ScenarioSource, file: &RigFileToml) -> anyhow::Result<Option<String>> {
    let Some(named) = &file.reproduces else {
        return Ok(None);
    };
    if !RigTopology::REPRODUCIBLE.contains(&named.get_ref().as_str()) {
        return Err(src.error(
            named.span(),
            "reproduces",
            format!(
                "`{}` is no published rig testrig holds sweeps against; allowed: {}",
                named.get_ref(),
                RigTopology::REPRODUCIBLE.join(", ")
            ),
        ));
    }
    Ok(Some(named.get_ref().clone()))
}

/// Each name of a `table`'s items to its index; a repeated name is refused at its place.
fn names<'a>(
    src: &ScenarioSource,
    table: &str,
    items: impl Iterator<Item = &'a Spanned<String>>,
) -> anyhow::Result<HashMap<&'a str, usize>> {
    let mut map = HashMap::new();
    for (i, name) in items.enumerate() {
        if map.insert(name.get_ref().as_str(), i).is_some() {
            return Err(src.error(
                name.span(),
                &format!("{table}.name"),
                format!(
                    "`{}` names two {table}s: each needs its own name",
                    name.get_ref()
                ),
            ));
        }
    }
    Ok(map)
}

/// A `[[shaft]]` as read: between two bodies, or from one to the frame.
enum ReadShaft {
    Between(Shaft),
    Frame(FrameShaft),
}

fn shaft(
    src: &ScenarioSource,
    s: &ShaftToml,
    body: &impl Fn(&Spanned<String>, &str) -> anyhow::Result<usize>,
) -> anyhow::Result<ReadShaft> {
    let field = format!("shaft `{}`.between", s.name.get_ref());
    let [a, b] = s.between.get_ref().as_slice() else {
        return Err(src.error(
            s.between.span(),
            &field,
            format!(
                "{} bodies: a shaft joins two, e.g. between = [\"motor\", \"pinion\"]",
                s.between.get_ref().len()
            ),
        ));
    };
    let name = s.name.get_ref().clone();
    let stiffness_nm_per_rad = *s.stiffness_nm_per_rad.get_ref();
    let damping_nms_per_rad = or(&s.damping_nms_per_rad, 0.0);
    let held = match (a.get_ref() == FRAME, b.get_ref() == FRAME) {
        (true, true) => {
            return Err(src.error(
                s.between.span(),
                &field,
                "joins the frame to itself: name a body and \"frame\"",
            ));
        }
        (false, true) => Some(a),
        (true, false) => Some(b),
        (false, false) => None,
    };
    if let Some(held) = held {
        return Ok(ReadShaft::Frame(FrameShaft {
            name,
            body: body(held, &field)?,
            stiffness_nm_per_rad,
            damping_nms_per_rad,
        }));
    }
    Ok(ReadShaft::Between(Shaft {
        name,
        between: [body(a, &field)?, body(b, &field)?],
        stiffness_nm_per_rad,
        damping_nms_per_rad,
    }))
}

/// `names` as "`a`, `b`, `c`".
fn listed<'a>(names: impl Iterator<Item = &'a String>) -> String {
    names
        .map(|n| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ")
}
