//! `testrig modes`: natural frequencies and mode shapes.

use rig::{Chain, RigChains};
use serde_json::json;

use crate::cli::ModesArgs;
use testrig::scenario::preset_with_overrides;

pub fn run(args: &ModesArgs) -> anyhow::Result<()> {
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
        // Each body's column as wide as its name, the shape's entries right-aligned under it.
        let widths: Vec<usize> = chain
            .bodies
            .iter()
            .map(|b| b.chars().count().max(7))
            .collect();
        let head: Vec<String> = chain
            .bodies
            .iter()
            .zip(&widths)
            .map(|(b, w)| format!("{b:>w$}"))
            .collect();
        println!("  {:>10}  {}", "f (Hz)", head.join("  "));
        for mode in chain.modes() {
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
    Ok(())
}

fn frequencies(chain: &Chain) -> Vec<f64> {
    chain.modes().iter().map(|m| m.frequency_hz).collect()
}
