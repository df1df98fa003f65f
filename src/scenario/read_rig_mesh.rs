//! A rig file's `[[mesh]]` read into a `rig::Mesh`: its gears, teeth and geometry, its
//! stiffness (as given, or by the potential-energy method from its face width), its
//! pairs, and its `[[mesh.fault]]`s; every fault at its place with what is allowed.

use rig::mesh_stiffness::PairGeometry;
use rig::{ContactLaw, Mesh, MeshPairs};
use toml::Spanned;

use super::read_faults::tooth_fault;
use super::rig_file_toml::MeshToml;
use super::source::ScenarioSource;

/// Young's modulus where the potential-energy method's mesh leaves it out (Pa): steel's.
const STEEL_YOUNGS_MODULUS_PA: f64 = 206.0e9;

/// Poisson's ratio the potential-energy method takes: steel's.
const STEEL_POISSON_RATIO: f64 = 0.3;

/// Pressure angle where a mesh leaves it out (degrees): the standard 20°.
const DEFAULT_PRESSURE_ANGLE_DEG: f64 = 20.0;

/// The mesh `m`, its driver and driven gear named by `body`.
pub(super) fn mesh(
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
        centre_distance_shift_mm: or(&m.centre_distance_shift_mm, 0.0),
        centre_line_deg: or(&m.centre_line_deg, 0.0),
        stiffness_n_per_m: stiffness.0,
        potential_energy: stiffness.2,
        damping_ns_per_m: or(&m.damping_ns_per_m, 0.0),
        pairs: pairs(src, m)?,
        contact_law: contact_law(src, m)?,
        double_pair_ratio: or(&m.double_pair_ratio, stiffness.1),
        addendum_coefficient: or(&m.addendum_coefficient, 1.0),
        stiffness_smoothing: or(&m.stiffness_smoothing, 0.0),
        backlash_variation: or(&m.backlash_variation, 0.0),
        te_once_per_rev_um: or(&m.te_once_per_rev_um, 0.0),
        te_mesh_frequency_um: or(&m.te_mesh_frequency_um, 0.0),
        run_out_driver_um: or(&m.run_out_driver_um, 0.0),
        run_out_driven_um: or(&m.run_out_driven_um, 0.0),
        tooth_spacing_error_um: or(&m.tooth_spacing_error_um, 0.0),
        tooth_spacing_seed: m.tooth_spacing_seed.unwrap_or(0),
        tooth_shifting: m.tooth_shifting.unwrap_or(false),
        gear_error_c2_nm: or(&m.gear_error_c2_nm, 0.0),
        gear_error_c3_nm: or(&m.gear_error_c3_nm, 0.0),
        faults: m
            .fault
            .iter()
            .map(|f| tooth_fault(src, f, [*z1, *z2]))
            .collect::<anyhow::Result<_>>()?,
    })
}

/// A mesh's stiffness of one pair (N/m), the double-pair ratio where the file leaves it
/// out, and the geometry the stiffness was derived from: as given (ratio 2), or from
/// `face_width_m` by the potential-energy method (`rig::mesh_stiffness`; with one pair
/// always, the mean over the tooth period). Both or neither given is refused, and so is
/// a material or bore without the face width.
fn mesh_stiffness(
    src: &ScenarioSource,
    m: &MeshToml,
    teeth: [u32; 2],
) -> anyhow::Result<(f64, f64, Option<PairGeometry>)> {
    let field = format!("mesh `{}`.stiffness_n_per_m", m.name.get_ref());
    let Some(width) = &m.face_width_m else {
        for (given, name) in [
            (&m.youngs_modulus_pa, "youngs_modulus_pa"),
            (&m.poisson_ratio, "poisson_ratio"),
            (&m.bore_diameter_m, "bore_diameter_m"),
        ] {
            if let Some(v) = given {
                return Err(src.error(
                    v.span(),
                    &format!("mesh.{name}"),
                    "used by the potential-energy method only: give face_width_m (m) instead of stiffness_n_per_m",
                ));
            }
        }
        return match &m.stiffness_n_per_m {
            Some(k) => Ok((*k.get_ref(), 2.0, None)),
            None => Err(src.error(
                m.name.span(),
                &field,
                "missing: give stiffness_n_per_m (N/m, one pair along the line of action), or face_width_m (m) for the potential-energy method",
            )),
        };
    };
    if let Some(k) = &m.stiffness_n_per_m {
        return Err(src.error(
            k.span(),
            &field,
            "give the stiffness or the face width (the potential-energy method then gives the stiffness), not both",
        ));
    }
    let geometry = pair_geometry(src, m, teeth, width)?;
    let lumped = geometry.lumped();
    let alternating = m
        .pairs
        .as_ref()
        .is_some_and(|p| p.get_ref() == "alternating");
    let (k, ratio) = if alternating {
        (lumped.single_n_per_m, lumped.double_pair_ratio)
    } else {
        (lumped.cycle_mean_n_per_m, 2.0)
    };
    Ok((k, ratio, Some(geometry)))
}

/// The pair's geometry and material for the potential-energy method, each number checked
/// at its field: a width and modulus > 0, Poisson's ratio in (0, 0.5), a bore inside each
/// gear's root circle.
fn pair_geometry(
    src: &ScenarioSource,
    m: &MeshToml,
    teeth: [u32; 2],
    width: &Spanned<f64>,
) -> anyhow::Result<PairGeometry> {
    let positive = |v: f64| v.is_finite() && v > 0.0;
    if !positive(*width.get_ref()) {
        return Err(src.error(width.span(), "mesh.face_width_m", "a width > 0 m"));
    }
    let number = |given: &Option<Spanned<f64>>, default: f64| {
        given.as_ref().map_or(default, |v| *v.get_ref())
    };
    let span_of = |given: &Option<Spanned<f64>>| given.as_ref().map_or(width.span(), Spanned::span);
    let youngs = number(&m.youngs_modulus_pa, STEEL_YOUNGS_MODULUS_PA);
    if !positive(youngs) {
        return Err(src.error(
            span_of(&m.youngs_modulus_pa),
            "mesh.youngs_modulus_pa",
            "a modulus > 0 Pa",
        ));
    }
    let poisson = number(&m.poisson_ratio, STEEL_POISSON_RATIO);
    if !(poisson > 0.0 && poisson < 0.5) {
        return Err(src.error(
            span_of(&m.poisson_ratio),
            "mesh.poisson_ratio",
            "a ratio in (0, 0.5)",
        ));
    }
    let alpha = m
        .pressure_angle_deg
        .as_ref()
        .map_or(DEFAULT_PRESSURE_ANGLE_DEG, |a| *a.get_ref());
    let geometry = PairGeometry {
        teeth,
        module_m: *m.module_m.get_ref(),
        pressure_angle_rad: alpha.to_radians(),
        face_width_m: *width.get_ref(),
        addendum_coefficient: or(&m.addendum_coefficient, 1.0),
        youngs_modulus_pa: youngs,
        poisson_ratio: poisson,
        bore_diameter_m: m.bore_diameter_m.as_ref().map(|d| *d.get_ref()),
    };
    if let Some(bore) = &m.bore_diameter_m {
        let root_diameter_m = (0..2)
            .map(|g| 2.0 * geometry.root_radius_m(g))
            .fold(f64::INFINITY, f64::min);
        if !(positive(*bore.get_ref()) && *bore.get_ref() < root_diameter_m) {
            return Err(src.error(
                bore.span(),
                "mesh.bore_diameter_m",
                format!("a diameter > 0 m and inside the smaller gear's root circle ({root_diameter_m:.4} m)"),
            ));
        }
    }
    Ok(geometry)
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

/// A mesh's `contact_law`: the thesis's when left out.
fn contact_law(src: &ScenarioSource, m: &MeshToml) -> anyhow::Result<ContactLaw> {
    let Some(text) = &m.contact_law else {
        return Ok(ContactLaw::Thesis);
    };
    ContactLaw::parse(text.get_ref()).ok_or_else(|| {
        src.error(
            text.span(),
            &format!("mesh `{}`.contact_law", m.name.get_ref()),
            format!("`{}`: one of {}", text.get_ref(), ContactLaw::NAMES),
        )
    })
}

/// An optional number's value, or `default`.
pub(super) fn or(value: &Option<Spanned<f64>>, default: f64) -> f64 {
    value.as_ref().map_or(default, |v| *v.get_ref())
}
