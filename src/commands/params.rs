//! `testrig params`: every parameter with value, unit and meaning.

use rig::{DERIVED_SPECS, GearGeometry, PARAM_SPECS, ParamSpec};
use serde_json::json;

use crate::cli::ParamsArgs;
use testrig::scenario::preset_with_overrides;

pub fn run(args: &ParamsArgs) -> anyhow::Result<()> {
    let params = preset_with_overrides(&args.rig.preset, &args.rig.overrides)?;
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
            json!({"preset": args.rig.preset, "parameters": as_json(PARAM_SPECS), "derived_settable": as_json(DERIVED_SPECS), "derived": derived})
        );
        return Ok(());
    }
    println!("preset {}", args.rig.preset);
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
