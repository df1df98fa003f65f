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
    println!("{:<36} {:>14} {:<10} meaning", "name", "value", "unit");
    let print_rows = |specs: &[ParamSpec]| {
        for spec in specs {
            let value = spec.value(&params);
            println!(
                "{:<36} {value:>14} {:<10} {}",
                spec.name, spec.unit, spec.meaning
            );
        }
    };
    print_rows(PARAM_SPECS);
    println!("\nderived, settable by name");
    print_rows(DERIVED_SPECS);
    println!("\nderived");
    for (name, value, unit, meaning) in derived {
        println!("{name:<36} {value:>14.6e} {unit:<10} {meaning}");
    }
    Ok(())
}
