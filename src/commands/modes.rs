//! `testrig modes`: natural frequencies and mode shapes.

use rig::{Chain, NaturalMode, RigChains};
use serde_json::json;

use crate::cli::ModesArgs;
use testrig::scenario::{preset_with_overrides, read_rig_file};

pub fn run(args: &ModesArgs) -> anyhow::Result<()> {
    if let Some(path) = &args.rig_file {
        return rig_file_modes(path, args.json);
    }
    let params = preset_with_overrides(&args.rig.preset, &args.rig.overrides)?;
    let chains = RigChains::of(&params);
    let named = [
        (
            "whole_rig",
            "whole rig, gear pair rigid (thesis App. C)",
            &chains.whole_rig,
        ),
        (
            "locked_mesh",
            "five inertias, teeth locked on the mesh spring K23",
            &chains.locked_mesh,
        ),
        (
            "motor_side",
            "motor side alone (teeth apart)",
            &chains.motor_side,
        ),
        (
            "brake_side",
            "brake side alone (teeth apart)",
            &chains.brake_side,
        ),
    ];
    if args.json {
        let mut object = serde_json::Map::new();
        for (key, _, chain) in named {
            object.insert(format!("{key}_hz"), json!(frequencies(chain)));
            object.insert(
                format!("{key}_shapes"),
                json!(chain.modes().iter().map(|m| &m.shape).collect::<Vec<_>>()),
            );
        }
        println!("{}", serde_json::Value::Object(object));
        return Ok(());
    }
    for (_, title, chain) in named {
        println!("{title}");
        print_modes(&chain.bodies, &chain.modes());
    }
    Ok(())
}

/// A table of `modes`: frequency, then each body's amplitude in a column as wide as its
/// name, right-aligned under it.
fn print_modes(bodies: &[&str], modes: &[NaturalMode]) {
    let widths: Vec<usize> = bodies.iter().map(|b| b.chars().count().max(7)).collect();
    let head: Vec<String> = bodies
        .iter()
        .zip(&widths)
        .map(|(b, w)| format!("{b:>w$}"))
        .collect();
    println!("  {:>10}  {}", "f (Hz)", head.join("  "));
    for mode in modes {
        let shape: Vec<String> = mode
            .shape
            .iter()
            .zip(&widths)
            .map(|(v, w)| format!("{v:>+w$.4}"))
            .collect();
        println!("  {:>10.3}  {}", mode.frequency_hz, shape.join("  "));
    }
    println!();
}

fn frequencies(chain: &Chain) -> Vec<f64> {
    chain.modes().iter().map(|m| m.frequency_hz).collect()
}

/// The natural modes of the rig in the rig file at `path`: every mesh in contact, no
/// speed controller, the rigid-body mode left out.
fn rig_file_modes(path: &std::path::Path, json: bool) -> anyhow::Result<()> {
    let rig = read_rig_file(path)?;
    let modes = rig.natural_modes();
    let bodies: Vec<&str> = rig.bodies.iter().map(|b| b.name.as_str()).collect();
    if json {
        let natural_hz: Vec<f64> = modes.iter().map(|m| m.frequency_hz).collect();
        let shapes: Vec<&Vec<f64>> = modes.iter().map(|m| &m.shape).collect();
        println!(
            "{}",
            json!({"rig": rig.name, "bodies": bodies, "natural_hz": natural_hz, "shapes": shapes})
        );
        return Ok(());
    }
    println!("{}: every mesh in contact, no speed controller", rig.name);
    print_modes(&bodies, &modes);
    Ok(())
}
