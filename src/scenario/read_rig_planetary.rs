//! A rig file's planar parts read into `rig`'s: a `[[planetary]]` stage, a body's or the
//! planets' bearing in the plane, and a shaft to the frame (`between = [body, "frame"]`);
//! every fault at its place with what is allowed.

use rig::{
    MAX_PLANETS, MeshPairs, PlanarBearing, PlanetaryStage, RingSensor, StageFault, StageMesh,
    StageRadii, StageTeeth,
};
use toml::Spanned;

use super::read_faults::checked_stage_fault;
use super::read_rig_mesh::or;
use super::rig_file_toml::{FaultToml, PlanetaryToml, StageMeshToml};
use super::source::ScenarioSource;

/// The reserved body name of the housing: a shaft to it holds a body's rotation.
pub const FRAME: &str = "frame";

/// Pressure angle where a stage leaves it out (degrees): the standard 20°.
const DEFAULT_PRESSURE_ANGLE_DEG: f64 = 20.0;

/// The stage `p`, its sun, ring and carrier named by `body`.
pub(super) fn planetary_stage(
    src: &ScenarioSource,
    p: &PlanetaryToml,
    body: &impl Fn(&Spanned<String>, &str) -> anyhow::Result<usize>,
) -> anyhow::Result<PlanetaryStage> {
    let name = p.name.get_ref();
    let field = |f: &str| format!("planetary `{name}`.{f}");
    let teeth = p.teeth.get_ref();
    let mesh = |m: &Spanned<StageMeshToml>, f: &str| stage_mesh(src, m.get_ref(), &field(f));
    Ok(PlanetaryStage {
        name: name.clone(),
        sun: body(&p.sun, &field("sun"))?,
        ring: body(&p.ring, &field("ring"))?,
        carrier: body(&p.carrier, &field("carrier"))?,
        planet_angles_rad: planet_angles(src, p, &field("planet_angles_deg"))?,
        planet_inertia_kgm2: *p.planet_inertia_kgm2.get_ref(),
        planet_pin_errors_um: pin_errors(src, p, &field("planet_pin_errors_um"))?,
        planet_bearing: planar_bearing(
            src,
            [&p.planet_mass_kg, &p.planet_bearing_stiffness_n_per_m],
            &p.planet_bearing_damping_ns_per_m,
            &field("planet_mass_kg"),
        )?,
        teeth: StageTeeth {
            sun: teeth.sun,
            planet: teeth.planet,
            ring: teeth.ring,
        },
        module_m: *p.module_m.get_ref(),
        pressure_angle_deg: or(&p.pressure_angle_deg, DEFAULT_PRESSURE_ANGLE_DEG),
        base_radii_m: p.base_diameter_m.as_ref().map(|d| {
            let d = d.get_ref();
            StageRadii {
                sun: d.sun / 2.0,
                planet: d.planet / 2.0,
                ring: d.ring / 2.0,
            }
        }),
        carrier_radius_given_m: p.carrier_radius_m.as_ref().map(|r| *r.get_ref()),
        sun_planet: mesh(&p.sun_planet, "sun_planet")?,
        ring_planet: mesh(&p.ring_planet, "ring_planet")?,
        faults: p
            .fault
            .iter()
            .map(|f| stage_fault(src, p, f))
            .collect::<anyhow::Result<_>>()?,
        ring_sensor: p.ring_sensor.as_ref().map(|s| {
            let s = s.get_ref();
            let planets = f64::from(*p.planets.get_ref());
            RingSensor {
                angle_rad: s.angle_deg.to_radians(),
                window_rad: s.window_deg.unwrap_or(360.0 / planets).to_radians(),
            }
        }),
    })
}

/// A stage's mesh table, its `pairs` refused at its place (`field` names the table).
fn stage_mesh(src: &ScenarioSource, m: &StageMeshToml, field: &str) -> anyhow::Result<StageMesh> {
    let pairs = match &m.pairs {
        None => MeshPairs::Single,
        Some(text) => MeshPairs::parse(text.get_ref()).ok_or_else(|| {
            src.error(
                text.span(),
                &format!("{field}.pairs"),
                format!("`{}`: one of {}", text.get_ref(), MeshPairs::NAMES),
            )
        })?,
    };
    Ok(StageMesh {
        stiffness_n_per_m: m.stiffness_n_per_m,
        damping_ns_per_m: m.damping_ns_per_m,
        backlash_mm: m.backlash_mm,
        pairs,
        double_pair_ratio: or(&m.double_pair_ratio, 2.0),
        stiffness_smoothing: or(&m.stiffness_smoothing, 0.0),
    })
}

/// A `[[planetary.fault]]` on the sun, the ring or `planet<k>` of stage `p`.
fn stage_fault(
    src: &ScenarioSource,
    p: &PlanetaryToml,
    f: &FaultToml,
) -> anyhow::Result<StageFault> {
    if let Some(mesh) = &f.mesh {
        return Err(src.error(
            mesh.span(),
            "planetary.fault.mesh",
            "a stage's fault belongs to the [[planetary]] above it: leave out `mesh`",
        ));
    }
    let t = p.teeth.get_ref();
    let teeth = StageTeeth {
        sun: t.sun,
        planet: t.planet,
        ring: t.ring,
    };
    checked_stage_fault(
        src,
        f,
        (teeth, *p.planets.get_ref() as usize),
        "planetary.fault",
    )
}

/// The planets' angles (rad): as given (one per planet), else equally spaced.
fn planet_angles(src: &ScenarioSource, p: &PlanetaryToml, field: &str) -> anyhow::Result<Vec<f64>> {
    let planets = *p.planets.get_ref() as usize;
    if !(1..=MAX_PLANETS).contains(&planets) {
        return Err(src.error(
            p.planets.span(),
            field.replace("planet_angles_deg", "planets").as_str(),
            format!("{planets}: a stage has 1 to {MAX_PLANETS} planets"),
        ));
    }
    let Some(given) = &p.planet_angles_deg else {
        return Ok(PlanetaryStage::equally_spaced_rad(planets));
    };
    if given.get_ref().len() != planets {
        return Err(src.error(
            given.span(),
            field,
            format!(
                "{} angles for {planets} planets: one angle (degrees) per planet",
                given.get_ref().len()
            ),
        ));
    }
    Ok(given.get_ref().iter().map(|d| d.to_radians()).collect())
}

/// The planets' pin errors (µm): one per planet, or none.
fn pin_errors(src: &ScenarioSource, p: &PlanetaryToml, field: &str) -> anyhow::Result<Vec<f64>> {
    let Some(given) = &p.planet_pin_errors_um else {
        return Ok(Vec::new());
    };
    let planets = *p.planets.get_ref() as usize;
    if given.get_ref().len() != planets {
        return Err(src.error(
            given.span(),
            field,
            format!(
                "{} errors for {planets} planets: one pin error (µm) per planet",
                given.get_ref().len()
            ),
        ));
    }
    Ok(given.get_ref().clone())
}

/// A bearing in the plane from its mass and stiffness (both, or neither: `None`) and
/// its damping (0 when left out); `field` names the mass where one is missing.
pub(super) fn planar_bearing(
    src: &ScenarioSource,
    [mass, stiffness]: [&Option<Spanned<f64>>; 2],
    damping: &Option<Spanned<f64>>,
    field: &str,
) -> anyhow::Result<Option<PlanarBearing>> {
    match (mass, stiffness) {
        (None, None) => {
            if let Some(d) = damping {
                return Err(src.error(
                    d.span(),
                    field,
                    "a bearing's damping needs its mass and stiffness: the body moves in the plane only with both",
                ));
            }
            Ok(None)
        }
        (Some(m), Some(k)) => Ok(Some(PlanarBearing {
            mass_kg: *m.get_ref(),
            stiffness_n_per_m: *k.get_ref(),
            damping_ns_per_m: or(damping, 0.0),
        })),
        (Some(given), None) | (None, Some(given)) => Err(src.error(
            given.span(),
            field,
            "a body moves in the plane with its mass (kg) and its bearing's stiffness (N/m) both: give both, or neither for an axis held rigidly",
        )),
    }
}
