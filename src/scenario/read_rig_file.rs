//! A rig file read into a checked `rig::RigTopology`: names resolved to bodies and
//! shafts, defaults filled in, the topology checked (`RigTopology::check`); every fault
//! at file:line:column with its field and what is allowed.

use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;

use rig::{
    Body, DriveRatings, DriveSettings, FrameShaft, Gauge, LockedTorque, Mesh, RigTopology, Shaft,
    TopologyPlace,
};
use toml::Spanned;

use super::read_rig_mesh::{mesh, or};
use super::read_rig_planetary::{FRAME, planar_bearing, planetary_stage};
use super::rig_file_toml::{
    BrakeToml, KeyphasorToml, MotorToml, PlanetaryToml, RigFileToml, ShaftToml,
};
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

/// The field a check's fault names, as the file writes it (`shaft `input`.stiffness…`).
fn field_name(rig: &RigTopology, place: &TopologyPlace) -> String {
    // A shaft to the frame is a `[[shaft]]` in the file.
    let table = match place.table {
        "frame_shaft" => "shaft",
        table => table,
    };
    match place_item(rig, place) {
        Some(name) => format!("{table} `{name}`.{}", place.field),
        None => format!("{table}.{}", place.field),
    }
}

/// Where in a `[[planetary]]` table a check's fault on `field` lies.
fn planetary_span(p: &PlanetaryToml, field: &str) -> Range<usize> {
    let given = |v: &Option<Spanned<f64>>| v.as_ref().map(Spanned::span);
    match field {
        "sun" => Some(p.sun.span()),
        "ring" => Some(p.ring.span()),
        "carrier" => Some(p.carrier.span()),
        "planets" => Some(p.planets.span()),
        "planet_angles_deg" => p
            .planet_angles_deg
            .as_ref()
            .map_or(Some(p.planets.span()), |a| Some(a.span())),
        "planet_inertia_kgm2" => Some(p.planet_inertia_kgm2.span()),
        "planet_pin_errors_um" => p.planet_pin_errors_um.as_ref().map(Spanned::span),
        "planet_mass_kg" => given(&p.planet_mass_kg),
        "planet_bearing_stiffness_n_per_m" => given(&p.planet_bearing_stiffness_n_per_m),
        "planet_bearing_damping_ns_per_m" => given(&p.planet_bearing_damping_ns_per_m),
        "teeth" => Some(p.teeth.span()),
        "module_m" => Some(p.module_m.span()),
        "pressure_angle_deg" => given(&p.pressure_angle_deg),
        "base_diameter_m" => p.base_diameter_m.as_ref().map(Spanned::span),
        "carrier_radius_m" => given(&p.carrier_radius_m),
        "sun_planet" => Some(p.sun_planet.span()),
        "ring_planet" => Some(p.ring_planet.span()),
        _ => None,
    }
    .unwrap_or(p.name.span())
}

/// The name of the body, shaft or mesh a check's fault lies in, if it lies in one.
pub(super) fn place_item<'a>(rig: &'a RigTopology, place: &TopologyPlace) -> Option<&'a str> {
    match place.table {
        "body" => rig.bodies.get(place.index).map(|b| b.name.as_str()),
        "shaft" => rig.shafts.get(place.index).map(|s| s.name.as_str()),
        "mesh" => rig.meshes.get(place.index).map(|m| m.name.as_str()),
        "frame_shaft" => rig.frame_shafts.get(place.index).map(|s| s.name.as_str()),
        "planetary" => rig.planetary.get(place.index).map(|s| s.name.as_str()),
        _ => None,
    }
}

/// Where in the file a check's fault lies (0..0, no line, where the file has no such value).
fn span_of(file: &RigFileToml, place: &TopologyPlace) -> Range<usize> {
    let i = place.index;
    let span = match (place.table, place.field) {
        ("body", "inertia_kgm2") => file.bodies.get(i).map(|b| b.inertia_kgm2.span()),
        ("body", "mass_kg") => file
            .bodies
            .get(i)
            .and_then(|b| b.mass_kg.as_ref().map(Spanned::span)),
        ("body", "bearing_stiffness_n_per_m") => file
            .bodies
            .get(i)
            .and_then(|b| b.bearing_stiffness_n_per_m.as_ref().map(Spanned::span)),
        ("body", "bearing_damping_ns_per_m") => file
            .bodies
            .get(i)
            .and_then(|b| b.bearing_damping_ns_per_m.as_ref().map(Spanned::span)),
        ("body", "drag_nms_per_rad") => file
            .bodies
            .get(i)
            .and_then(|b| b.drag_nms_per_rad.as_ref().map(Spanned::span)),
        ("body", _) => file.bodies.get(i).map(|b| b.name.span()),
        ("shaft", "stiffness_nm_per_rad") => {
            file.shafts.get(i).map(|s| s.stiffness_nm_per_rad.span())
        }
        ("shaft", "damping_nms_per_rad") => file
            .shafts
            .get(i)
            .and_then(|s| s.damping_nms_per_rad.as_ref().map(Spanned::span)),
        ("shaft", _) => file.shafts.get(i).map(|s| s.between.span()),
        ("mesh", field) => file.meshes.get(i).and_then(|m| match field {
            "teeth" => Some(m.teeth.span()),
            "module_m" => Some(m.module_m.span()),
            "backlash_mm" => Some(m.backlash_mm.span()),
            "centre_distance_shift_mm" => m.centre_distance_shift_mm.as_ref().map(Spanned::span),
            "stiffness_n_per_m" => m.stiffness_n_per_m.as_ref().map(Spanned::span),
            "damping_ns_per_m" => m.damping_ns_per_m.as_ref().map(Spanned::span),
            "pressure_angle_deg" => m.pressure_angle_deg.as_ref().map(Spanned::span),
            "driven" => Some(m.driven.span()),
            "pairs" => m.pairs.as_ref().map(Spanned::span),
            "double_pair_ratio" => m.double_pair_ratio.as_ref().map(Spanned::span),
            "addendum_coefficient" => m.addendum_coefficient.as_ref().map(Spanned::span),
            "stiffness_smoothing" => m.stiffness_smoothing.as_ref().map(Spanned::span),
            "backlash_variation" => m.backlash_variation.as_ref().map(Spanned::span),
            "te_once_per_rev_um" => m.te_once_per_rev_um.as_ref().map(Spanned::span),
            "te_mesh_frequency_um" => m.te_mesh_frequency_um.as_ref().map(Spanned::span),
            "fault" => m.fault.first().map(|f| f.tooth.span()),
            "run_out_driver_um" => m.run_out_driver_um.as_ref().map(Spanned::span),
            "run_out_driven_um" => m.run_out_driven_um.as_ref().map(Spanned::span),
            "tooth_spacing_error_um" => m.tooth_spacing_error_um.as_ref().map(Spanned::span),
            "gear_error_c2_nm" => m.gear_error_c2_nm.as_ref().map(Spanned::span),
            "gear_error_c3_nm" => m.gear_error_c3_nm.as_ref().map(Spanned::span),
            _ => Some(m.name.span()),
        }),
        ("frame_shaft", field) => file
            .shafts
            .iter()
            .filter(|s| s.between.get_ref().iter().any(|b| b.get_ref() == FRAME))
            .nth(i)
            .map(|s| match field {
                "stiffness_nm_per_rad" => s.stiffness_nm_per_rad.span(),
                "damping_nms_per_rad" => s
                    .damping_nms_per_rad
                    .as_ref()
                    .map_or(s.between.span(), Spanned::span),
                _ => s.between.span(),
            }),
        ("planetary", field) => file.planetary.get(i).map(|p| planetary_span(p, field)),
        ("locked_torque", _) => file.locked_torque.as_ref().map(|l| l.torque_nm.span()),
        ("motor", field) => file.motor.as_ref().and_then(|m| match field {
            "torque_limit_nm" => m.torque_limit_nm.as_ref().map(Spanned::span),
            "speed_loop_hz" => m.speed_loop_hz.as_ref().map(Spanned::span),
            "speed_loop_damping_ratio" => m.speed_loop_damping_ratio.as_ref().map(Spanned::span),
            "feedback_filter_hz" => m.feedback_filter_hz.as_ref().map(Spanned::span),
            "rated_power_w" => m.rated_power_w.as_ref().map(Spanned::span),
            "rated_speed_rpm" => m.rated_speed_rpm.as_ref().map(Spanned::span),
            "full_load_current_a" => m.full_load_current_a.as_ref().map(Spanned::span),
            "current_limit_pct" => m.current_limit_pct.as_ref().map(Spanned::span),
            _ => Some(m.body.span()),
        }),
        ("gauge", field) => file.gauge.as_ref().map(|g| match field {
            "shear_modulus_pa" => g
                .shear_modulus_pa
                .as_ref()
                .map_or(g.shaft.span(), Spanned::span),
            _ => g.diameter_m.span(),
        }),
        ("brake", field) => file.brake.as_ref().map(|b| {
            let value = match field {
                "drag_nm" => &b.drag_nm,
                "critical_speed_rpm" => &b.critical_speed_rpm,
                _ => &b.slope_nms_per_rad,
            };
            value.as_ref().map_or(b.body.span(), Spanned::span)
        }),
        _ => None,
    };
    span.unwrap_or(0..0)
}
