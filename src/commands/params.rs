//! `testrig params`: every parameter with value, unit and meaning.

use rig::{DERIVED_SPECS, GearGeometry, PARAM_SPECS, ParamSpec};
use serde_json::json;

use crate::cli::ParamsArgs;
use testrig::scenario::{
    is_thesis_name, preset_rig_with_overrides, preset_with_overrides, read_rig_file,
};

/// A table's rows: (name, value, unit, meaning).
type Rows = Vec<[String; 4]>;

pub fn run(args: &ParamsArgs) -> anyhow::Result<()> {
    if let Some(path) = &args.rig_file {
        return rig_file_params(path, args.json);
    }
    // A preset is its rig: the thesis's names it is set by, then the rig it runs as, by
    // path, as `params --rig` prints a rig file.
    let named: Vec<String> = (args.rig.overrides.iter())
        .filter(|item| is_thesis_name(item))
        .cloned()
        .collect();
    let params = preset_with_overrides(&args.rig.preset, &named)?;
    let rig = preset_rig_with_overrides(&args.rig.preset, &args.rig.overrides)?;
    let (rig_fields, rig_derived) = rig_rows(&rig);
    let geometry = GearGeometry::of(&params);
    let (kp, ki) = params.speed_loop_gains();
    let derived = [
        (
            "pitch_radius_m",
            geometry.pitch_radius_m,
            "m",
            "r = m z / 2",
        ),
        (
            "circular_backlash_m",
            geometry.circular_backlash_m,
            "m",
            "total backlash at the pitch circle 2B1 = 2 dC tan(alpha)",
        ),
        (
            "half_backlash_rad",
            geometry.half_backlash_rad,
            "rad",
            "free play B each side of centre, B1 / r",
        ),
        (
            "contact_ratio",
            geometry.contact_ratio,
            "1",
            "transverse contact ratio at the operating centre distance",
        ),
        (
            "speed_loop_kp_nms_per_rad",
            kp,
            "N m s/rad",
            "speed loop proportional gain 2 zeta w_n J",
        ),
        (
            "speed_loop_ki_nm_per_rad",
            ki,
            "N m/rad",
            "speed loop integral gain J w_n^2",
        ),
    ];
    if args.json {
        let as_json = |specs: &[ParamSpec]| -> Vec<_> {
            specs
                .iter()
                .map(|s| json!({"name": s.name, "value": s.value(&params), "unit": s.unit, "meaning": s.meaning}))
                .collect()
        };
        let derived: Vec<_> = derived
            .iter()
            .map(|(n, v, u, m)| json!({"name": n, "value": v, "unit": u, "meaning": m}))
            .collect();
        println!(
            "{}",
            json!({"preset": args.rig.preset, "parameters": as_json(PARAM_SPECS), "derived_settable": as_json(DERIVED_SPECS), "derived": derived, "rig": rig.name, "fields": rows_json(&rig_fields), "rig_derived": rows_json(&rig_derived)})
        );
        return Ok(());
    }
    println!(
        "preset {}, by the thesis's names (a rig path set with --set changes only the rig \
         below, which is what runs)",
        args.rig.preset
    );
    let rows = |specs: &[ParamSpec]| -> Vec<[String; 4]> {
        specs
            .iter()
            .map(|s| {
                let value = s.value(&params).to_string();
                [
                    s.name.to_string(),
                    value,
                    s.unit.to_string(),
                    s.meaning.to_string(),
                ]
            })
            .collect()
    };
    let derived: Vec<[String; 4]> = derived
        .iter()
        .map(|(n, v, u, m)| {
            [
                n.to_string(),
                format!("{v:.6e}"),
                u.to_string(),
                m.to_string(),
            ]
        })
        .collect();
    let sections = [
        ("", rows(PARAM_SPECS)),
        ("derived, settable by name", rows(DERIVED_SPECS)),
        ("derived", derived),
    ];
    print_table(&sections);
    println!("\nthe rig it runs as: {} ({})", rig.name, rig.description);
    print_table(&[("", rig_fields), ("derived", rig_derived)]);
    Ok(())
}

/// Prints titled sections of (name, value, unit, meaning) rows, each column as wide as its
/// widest entry in any section, so that every row lines up whatever its values.
fn print_table(sections: &[(&str, Vec<[String; 4]>)]) {
    let all = sections.iter().flat_map(|(_, rows)| rows);
    let width = |k: usize, head: &str| {
        all.clone()
            .map(|r| r[k].chars().count())
            .chain([head.len()])
            .max()
            .unwrap_or(0)
    };
    let (name_w, value_w, unit_w) = (width(0, "name"), width(1, "value"), width(2, "unit"));
    println!(
        "{:<name_w$} {:>value_w$} {:<unit_w$} meaning",
        "name", "value", "unit"
    );
    for (title, rows) in sections {
        if !title.is_empty() {
            println!("\n{title}");
        }
        for [name, value, unit, meaning] in rows {
            println!("{name:<name_w$} {value:>value_w$} {unit:<unit_w$} {meaning}");
        }
    }
}

/// Every field of the rig file at `path` by its path, with unit and meaning, then what
/// follows from them.
fn rig_file_params(path: &std::path::Path, as_json: bool) -> anyhow::Result<()> {
    let rig = read_rig_file(path)?;
    let (fields, derived) = rig_rows(&rig);
    if as_json {
        println!(
            "{}",
            json!({"rig": rig.name, "fields": rows_json(&fields), "derived": rows_json(&derived)})
        );
        return Ok(());
    }
    println!("rig {} ({})", rig.name, rig.description);
    print_table(&[("", fields), ("derived", derived)]);
    Ok(())
}

/// Rows as JSON objects with `name`, `value`, `unit` and `meaning`.
fn rows_json(rows: &[[String; 4]]) -> Vec<serde_json::Value> {
    rows.iter()
        .map(|[n, v, u, m]| json!({"name": n, "value": v, "unit": u, "meaning": m}))
        .collect()
}

/// Every field of `rig` by its path, with unit and meaning, and what follows from them
/// (base radii, the potential-energy method's numbers, each body's speed per unit motor
/// speed): (fields, derived).
fn rig_rows(rig: &rig::RigTopology) -> (Rows, Rows) {
    let row = |name: String, value: String, unit: &str, meaning: &str| {
        [name, value, unit.to_string(), meaning.to_string()]
    };
    let mut fields: Rows = rig
        .fields()
        .into_iter()
        .map(|f| row(f.path, f.value.to_string(), f.unit, f.meaning))
        .collect();
    let mut derived = Vec::new();
    for m in &rig.meshes {
        let gears = format!(
            "{} drives {}",
            rig.bodies[m.gears[0]].name, rig.bodies[m.gears[1]].name
        );
        let p = |field: &str| format!("mesh.{}.{field}", m.name);
        fields.push(row(
            p("teeth"),
            format!("{}/{}", m.teeth[0], m.teeth[1]),
            "1",
            &gears,
        ));
        let [ra, rb] = m.base_radii_m();
        derived.push(row(
            p("base_radii_m"),
            format!("{ra:.6e}/{rb:.6e}"),
            "m",
            "r_b = m z cos(alpha) / 2",
        ));
        if let Some(g) = &m.potential_energy {
            derived.extend(
                potential_energy_rows(g)
                    .map(|(field, value, unit, meaning)| row(p(field), value, unit, meaning)),
            );
        }
    }
    let speeds = rig.relative_speeds();
    let reference = rig.motor.and_then(|m| speeds[m]).unwrap_or(1.0);
    for (b, speed) in rig.bodies.iter().zip(&speeds) {
        let ratio = speed.map_or(f64::NAN, |s| s / reference);
        derived.push(row(
            format!("body.{}.speed_ratio", b.name),
            format!("{ratio:.6}"),
            "1",
            "speed per unit speed of the motor's body (negative: turns the other way)",
        ));
    }
    (fields, derived)
}

/// What the potential-energy method derives for a mesh given by its face width, with the
/// material and bore it used: (field, value, unit, meaning).
fn potential_energy_rows(
    g: &rig::mesh_stiffness::PairGeometry,
) -> [(&'static str, String, &'static str, &'static str); 7] {
    let lumped = g.lumped();
    let e = |v: f64| format!("{v:.6e}");
    [
        (
            "contact_ratio",
            format!("{:.6}", g.contact_ratio()),
            "1",
            "transverse contact ratio at the standard centre distance (potential-energy method)",
        ),
        (
            "pair_stiffness_n_per_m",
            e(lumped.single_n_per_m),
            "N/m",
            "one pair's stiffness, its mean over the stretch it carries alone (potential-energy method)",
        ),
        (
            "mean_mesh_stiffness_n_per_m",
            e(lumped.cycle_mean_n_per_m),
            "N/m",
            "the mesh's stiffness averaged over a tooth period, one and two pairs in turn (potential-energy method)",
        ),
        (
            "double_pair_ratio_derived",
            format!("{:.6}", lumped.double_pair_ratio),
            "1",
            "two pairs' mean stiffness over one pair's (potential-energy method)",
        ),
        (
            "youngs_modulus_pa_used",
            e(g.youngs_modulus_pa),
            "Pa",
            "Young's modulus the method used",
        ),
        (
            "poisson_ratio_used",
            format!("{}", g.poisson_ratio),
            "1",
            "Poisson's ratio the method used",
        ),
        (
            "bore_diameters_m_used",
            format!(
                "{:.6e}/{:.6e}",
                2.0 * g.bore_radius_m(0),
                2.0 * g.bore_radius_m(1)
            ),
            "m",
            "each gear's bore diameter the fillet foundation used (bore_diameter_m, else the base radius)",
        ),
    ]
}
