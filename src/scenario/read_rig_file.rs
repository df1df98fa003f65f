//! A rig file read into a checked `rig::RigTopology`: names resolved to bodies and
//! shafts, defaults filled in, the topology checked (`RigTopology::check`); every fault
//! at file:line:column with its field and what is allowed.

use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;

use anyhow::Context;

use rig::{
    Body, DriveSettings, FaultKind, FaultedGear, Gauge, LockedTorque, Mesh, MeshPairs, RigTopology,
    Shaft, ToothFault, TopologyPlace,
};
use toml::Spanned;

use super::rig_file_toml::{FaultToml, MeshToml, MotorToml, RigFileToml, ShaftToml};
use super::source::ScenarioSource;

/// Shear modulus where a gauge leaves it out (Pa): steel's.
const STEEL_SHEAR_MODULUS_PA: f64 = 80.0e9;

/// Young's modulus where the potential-energy method's mesh leaves it out (Pa): steel's.
const STEEL_YOUNGS_MODULUS_PA: f64 = 206.0e9;

/// Poisson's ratio the potential-energy method takes: steel's.
const STEEL_POISSON_RATIO: f64 = 0.3;

/// Pressure angle where a mesh leaves it out (degrees): the standard 20°.
const DEFAULT_PRESSURE_ANGLE_DEG: f64 = 20.0;

/// Reads and checks the rig file at `path`.
pub fn read_rig_file(path: &Path) -> anyhow::Result<RigTopology> {
    rig_topology(&ScenarioSource::read(path)?)
}

/// Reads the rig file at `path`, sets each `PATH=VALUE` of `overrides` (`--set
/// mesh.stage1.backlash_mm=0.3`), and checks the result; a fault an override brings is
/// named by it.
pub fn rig_with_overrides(path: &Path, overrides: &[String]) -> anyhow::Result<RigTopology> {
    source_rig_with_overrides(&ScenarioSource::read(path)?, overrides)
}

/// [`rig_with_overrides`] for a rig file's text (Python's dict of tables, as TOML).
pub fn source_rig_with_overrides(
    src: &ScenarioSource,
    overrides: &[String],
) -> anyhow::Result<RigTopology> {
    let mut rig = rig_topology(src)?;
    for item in overrides {
        let Some((key, value)) = item.split_once('=') else {
            anyhow::bail!(
                "--set {item}: expected PATH=VALUE (`testrig params --rig` lists the paths)"
            );
        };
        let number: f64 = value
            .trim()
            .parse()
            .map_err(|_| anyhow::anyhow!("--set {item}: `{}` is not a number", value.trim()))?;
        rig.set_field(key.trim(), number)
            .with_context(|| format!("--set {item} (`testrig params --rig` lists the paths)"))?;
    }
    if !overrides.is_empty() {
        rig.check().with_context(|| {
            format!(
                "{} with --set {}",
                src.path.display(),
                overrides.join(" --set ")
            )
        })?;
    }
    Ok(rig)
}

/// The checked rig of a rig file's text.
pub fn rig_topology(src: &ScenarioSource) -> anyhow::Result<RigTopology> {
    let file: RigFileToml = src.parse_rig_file()?;
    let rig = build(src, &file)?;
    rig.check()
        .map_err(|e| src.error(span_of(&file, &e.place), &field_name(&file, &e.place), &e))?;
    Ok(rig)
}

/// The rig the file describes, its names resolved.
fn build(src: &ScenarioSource, file: &RigFileToml) -> anyhow::Result<RigTopology> {
    let bodies = names(src, "body", file.bodies.iter().map(|b| &b.name))?;
    let shaft_names = names(src, "shaft", file.shafts.iter().map(|s| &s.name))?;
    names(src, "mesh", file.meshes.iter().map(|m| &m.name))?;
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
    let shafts = file
        .shafts
        .iter()
        .map(|s| shaft(src, s, &body))
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
                        listed(file.shafts.iter().map(|s| s.name.get_ref()))
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
                        "no shaft `{}`; the shafts are {}",
                        l.shaft.get_ref(),
                        listed(file.shafts.iter().map(|s| s.name.get_ref()))
                    ),
                )
            })?;
            Some(LockedTorque {
                shaft,
                torque_nm: *l.torque_nm.get_ref(),
            })
        }
    };
    Ok(RigTopology {
        name: file.name.get_ref().clone(),
        description: file.description.clone().unwrap_or_default(),
        bodies: file
            .bodies
            .iter()
            .map(|b| Body {
                name: b.name.get_ref().clone(),
                inertia_kgm2: *b.inertia_kgm2.get_ref(),
                drag_nms_per_rad: or(&b.drag_nms_per_rad, 0.0),
            })
            .collect(),
        shafts,
        meshes,
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
        drive: drive(file),
        gauge,
    })
}

/// The drive settings of `[motor]` and `[brake]`, defaults where they are silent.
fn drive(file: &RigFileToml) -> DriveSettings {
    let d = DriveSettings::default();
    let motor = file.motor.as_ref();
    let motor_field = |f: fn(&MotorToml) -> &Option<Spanned<f64>>, default: f64| {
        motor.map_or(default, |m| or(f(m), default))
    };
    DriveSettings {
        torque_limit_nm: motor.and_then(|m| m.torque_limit_nm.as_ref().map(|t| *t.get_ref())),
        speed_loop_hz: motor_field(|m| &m.speed_loop_hz, d.speed_loop_hz),
        speed_loop_damping_ratio: motor_field(
            |m| &m.speed_loop_damping_ratio,
            d.speed_loop_damping_ratio,
        ),
        feedback_filter_hz: motor_field(|m| &m.feedback_filter_hz, d.feedback_filter_hz),
        brake_slope_nms_per_rad: file.brake.as_ref().map_or(d.brake_slope_nms_per_rad, |b| {
            or(&b.slope_nms_per_rad, d.brake_slope_nms_per_rad)
        }),
    }
}

/// An optional number's value, or `default`.
fn or(value: &Option<Spanned<f64>>, default: f64) -> f64 {
    value.as_ref().map_or(default, |v| *v.get_ref())
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

fn shaft(
    src: &ScenarioSource,
    s: &ShaftToml,
    body: &impl Fn(&Spanned<String>, &str) -> anyhow::Result<usize>,
) -> anyhow::Result<Shaft> {
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
    Ok(Shaft {
        name: s.name.get_ref().clone(),
        between: [body(a, &field)?, body(b, &field)?],
        stiffness_nm_per_rad: *s.stiffness_nm_per_rad.get_ref(),
        damping_nms_per_rad: s.damping_nms_per_rad.as_ref().map_or(0.0, |d| *d.get_ref()),
    })
}

fn mesh(
    src: &ScenarioSource,
    m: &MeshToml,
    body: &impl Fn(&Spanned<String>, &str) -> anyhow::Result<usize>,
) -> anyhow::Result<Mesh> {
    let name = m.name.get_ref();
    let [z1, z2] = m.teeth.get_ref().as_slice() else {
        return Err(src.error(
            m.teeth.span(),
            &format!("mesh `{name}`.teeth"),
            format!(
                "{:?}: the teeth of the driver and the driven gear, e.g. teeth = [20, 60]",
                m.teeth.get_ref()
            ),
        ));
    };
    let stiffness = mesh_stiffness(src, m, [*z1, *z2])?;
    Ok(Mesh {
        name: name.clone(),
        gears: [
            body(&m.driver, &format!("mesh `{name}`.driver"))?,
            body(&m.driven, &format!("mesh `{name}`.driven"))?,
        ],
        teeth: [*z1, *z2],
        module_m: *m.module_m.get_ref(),
        pressure_angle_deg: m
            .pressure_angle_deg
            .as_ref()
            .map_or(DEFAULT_PRESSURE_ANGLE_DEG, |a| *a.get_ref()),
        backlash_mm: *m.backlash_mm.get_ref(),
        stiffness_n_per_m: stiffness.0,
        damping_ns_per_m: or(&m.damping_ns_per_m, 0.0),
        pairs: pairs(src, m)?,
        double_pair_ratio: or(&m.double_pair_ratio, stiffness.1),
        addendum_coefficient: or(&m.addendum_coefficient, 1.0),
        backlash_variation: or(&m.backlash_variation, 0.0),
        te_once_per_rev_um: or(&m.te_once_per_rev_um, 0.0),
        te_mesh_frequency_um: or(&m.te_mesh_frequency_um, 0.0),
        run_out_driver_um: or(&m.run_out_driver_um, 0.0),
        run_out_driven_um: or(&m.run_out_driven_um, 0.0),
        tooth_shifting: m.tooth_shifting.unwrap_or(false),
        faults: m
            .fault
            .iter()
            .map(|f| tooth_fault(src, f, [*z1, *z2]))
            .collect::<anyhow::Result<_>>()?,
    })
}

/// A mesh's stiffness of one pair (N/m) and the double-pair ratio where the file leaves
/// it out: as given (ratio 2), or from `face_width_m` by the potential-energy method
/// (`rig::mesh_stiffness`; with one pair always, the mean over the tooth period). Both or
/// neither given is refused.
fn mesh_stiffness(
    src: &ScenarioSource,
    m: &MeshToml,
    teeth: [u32; 2],
) -> anyhow::Result<(f64, f64)> {
    let field = format!("mesh `{}`.stiffness_n_per_m", m.name.get_ref());
    match (&m.stiffness_n_per_m, &m.face_width_m) {
        (Some(k), None) => Ok((*k.get_ref(), 2.0)),
        (Some(k), Some(_)) => Err(src.error(
            k.span(),
            &field,
            "give the stiffness or the face width (the potential-energy method then gives the stiffness), not both",
        )),
        (None, None) => Err(src.error(
            m.name.span(),
            &field,
            "missing: give stiffness_n_per_m (N/m, one pair along the line of action), or face_width_m (m) for the potential-energy method",
        )),
        (None, Some(width)) => {
            let positive = |v: f64| v.is_finite() && v > 0.0;
            if !positive(*width.get_ref()) {
                return Err(src.error(width.span(), "mesh.face_width_m", "a width > 0 m"));
            }
            let youngs = m.youngs_modulus_pa.as_ref().map_or(STEEL_YOUNGS_MODULUS_PA, |e| *e.get_ref());
            if !positive(youngs) {
                let span = m.youngs_modulus_pa.as_ref().map_or(width.span(), Spanned::span);
                return Err(src.error(span, "mesh.youngs_modulus_pa", "a modulus > 0 Pa"));
            }
            let alpha = m
                .pressure_angle_deg
                .as_ref()
                .map_or(DEFAULT_PRESSURE_ANGLE_DEG, |a| *a.get_ref());
            let geometry = rig::mesh_stiffness::PairGeometry {
                teeth,
                module_m: *m.module_m.get_ref(),
                pressure_angle_rad: alpha.to_radians(),
                face_width_m: *width.get_ref(),
                addendum_coefficient: or(&m.addendum_coefficient, 1.0),
                youngs_modulus_pa: youngs,
                poisson_ratio: STEEL_POISSON_RATIO,
                bore_ratio: 0.5,
            };
            let lumped = geometry.lumped();
            let alternating = m.pairs.as_ref().is_some_and(|p| p.get_ref() == "alternating");
            Ok(if alternating {
                (lumped.single_n_per_m, lumped.double_pair_ratio)
            } else {
                (lumped.cycle_mean_n_per_m, 2.0)
            })
        }
    }
}

/// A `[[mesh.fault]]` read, each field refused at its place with what is allowed.
fn tooth_fault(src: &ScenarioSource, f: &FaultToml, teeth: [u32; 2]) -> anyhow::Result<ToothFault> {
    let (gear, z) = match f.gear.get_ref().as_str() {
        "driver" => (FaultedGear::Driver, teeth[0]),
        "driven" => (FaultedGear::Driven, teeth[1]),
        other => {
            return Err(src.error(
                f.gear.span(),
                "mesh.fault.gear",
                format!("`{other}`: the fault's gear is `driver` or `driven`"),
            ));
        }
    };
    let kind = FaultKind::parse(f.kind.get_ref()).ok_or_else(|| {
        src.error(
            f.kind.span(),
            "mesh.fault.kind",
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
            "mesh.fault.tooth",
            format!("{tooth}: the {} gear has teeth 1 to {z}", f.gear.get_ref()),
        ));
    }
    let severity = *f.severity.get_ref();
    if !(0.0..=1.0).contains(&severity) {
        return Err(src.error(
            f.severity.span(),
            "mesh.fault.severity",
            format!("{severity}: a share of the tooth, 0 to 1"),
        ));
    }
    Ok(ToothFault {
        gear,
        tooth,
        kind,
        severity,
    })
}

/// A mesh's `pairs`: single (the thesis's) when left out.
fn pairs(src: &ScenarioSource, m: &MeshToml) -> anyhow::Result<MeshPairs> {
    let Some(text) = &m.pairs else {
        return Ok(MeshPairs::Single);
    };
    MeshPairs::parse(text.get_ref()).ok_or_else(|| {
        src.error(
            text.span(),
            &format!("mesh `{}`.pairs", m.name.get_ref()),
            format!("`{}`: one of {}", text.get_ref(), MeshPairs::NAMES),
        )
    })
}

/// `names` as "`a`, `b`, `c`".
fn listed<'a>(names: impl Iterator<Item = &'a String>) -> String {
    names
        .map(|n| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The field a check's fault names, as the file writes it (`shaft `input`.stiffness…`).
fn field_name(file: &RigFileToml, place: &TopologyPlace) -> String {
    let item = match place.table {
        "body" => file.bodies.get(place.index).map(|b| b.name.get_ref()),
        "shaft" => file.shafts.get(place.index).map(|s| s.name.get_ref()),
        "mesh" => file.meshes.get(place.index).map(|m| m.name.get_ref()),
        _ => None,
    };
    match item {
        Some(name) => format!("{} `{name}`.{}", place.table, place.field),
        None => format!("{}.{}", place.table, place.field),
    }
}

/// Where in the file a check's fault lies (0..0, no line, where the file has no such value).
fn span_of(file: &RigFileToml, place: &TopologyPlace) -> Range<usize> {
    let i = place.index;
    let span = match (place.table, place.field) {
        ("body", "inertia_kgm2") => file.bodies.get(i).map(|b| b.inertia_kgm2.span()),
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
            "stiffness_n_per_m" => m.stiffness_n_per_m.as_ref().map(Spanned::span),
            "damping_ns_per_m" => m.damping_ns_per_m.as_ref().map(Spanned::span),
            "pressure_angle_deg" => m.pressure_angle_deg.as_ref().map(Spanned::span),
            "driven" => Some(m.driven.span()),
            "pairs" => m.pairs.as_ref().map(Spanned::span),
            "double_pair_ratio" => m.double_pair_ratio.as_ref().map(Spanned::span),
            "addendum_coefficient" => m.addendum_coefficient.as_ref().map(Spanned::span),
            "backlash_variation" => m.backlash_variation.as_ref().map(Spanned::span),
            "te_once_per_rev_um" => m.te_once_per_rev_um.as_ref().map(Spanned::span),
            "te_mesh_frequency_um" => m.te_mesh_frequency_um.as_ref().map(Spanned::span),
            "fault" => m.fault.first().map(|f| f.tooth.span()),
            "run_out_driver_um" => m.run_out_driver_um.as_ref().map(Spanned::span),
            "run_out_driven_um" => m.run_out_driven_um.as_ref().map(Spanned::span),
            _ => Some(m.name.span()),
        }),
        ("locked_torque", _) => file.locked_torque.as_ref().map(|l| l.torque_nm.span()),
        ("motor", field) => file.motor.as_ref().and_then(|m| match field {
            "torque_limit_nm" => m.torque_limit_nm.as_ref().map(Spanned::span),
            "speed_loop_hz" => m.speed_loop_hz.as_ref().map(Spanned::span),
            "speed_loop_damping_ratio" => m.speed_loop_damping_ratio.as_ref().map(Spanned::span),
            "feedback_filter_hz" => m.feedback_filter_hz.as_ref().map(Spanned::span),
            _ => Some(m.body.span()),
        }),
        ("gauge", field) => file.gauge.as_ref().map(|g| match field {
            "shear_modulus_pa" => g
                .shear_modulus_pa
                .as_ref()
                .map_or(g.shaft.span(), Spanned::span),
            _ => g.diameter_m.span(),
        }),
        ("brake", _) => file.brake.as_ref().and_then(|b| {
            b.slope_nms_per_rad
                .as_ref()
                .map_or(Some(b.body.span()), |s| Some(s.span()))
        }),
        _ => None,
    };
    span.unwrap_or(0..0)
}
