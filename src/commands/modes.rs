//! `testrig modes`: the natural frequencies and mode shapes of any rig (a preset is its
//! rig file), its meshes held three ways as the thesis's App. C takes its rig: in contact
//! on their springs, rigid, and apart (`rig::MeshHold`).

use rig::{MeshHold, ModalPart, ModeKind, RigTopology};
use serde_json::{Value, json};

use crate::cli::ModesArgs;
use testrig::scenario::command_rig;

pub fn run(args: &ModesArgs) -> anyhow::Result<()> {
    let rig = command_rig(
        args.rig_file.as_deref(),
        &args.rig.preset,
        &args.rig.overrides,
    )?;
    let contact = first_part(&rig, MeshHold::Contact);
    // Lin & Parker's kinds, for a rig that moves in the plane.
    let kinds = (!rig.is_torsional()).then(|| rig.mode_kinds(&contact.modes));
    let rigid = rig.modal_parts(MeshHold::Rigid).into_iter().next();
    let apart = rig.modal_parts(MeshHold::Apart);
    if args.json {
        let bodies: Vec<&str> = rig.bodies.iter().map(|b| b.name.as_str()).collect();
        let value = json!({
            "rig": rig.name,
            "bodies": bodies,
            "coordinates": coordinate_names(&contact),
            "natural_hz": frequencies(&contact),
            "shapes": shapes(&contact),
            "kinds": kinds,
            "rigid_meshes": rigid.as_ref().map(part_json),
            "meshes_apart": apart.iter().map(part_json).collect::<Vec<_>>(),
        });
        println!("{value}");
        return Ok(());
    }
    println!("{}: every mesh in contact, no speed controller", rig.name);
    print_modes(&contact, kinds.as_deref());
    let Some(rigid) = rigid else {
        println!(
            "(meshes rigid or apart: forms of a torsional rig; this one has planetary stages or bodies that move in the plane)"
        );
        return Ok(());
    };
    println!(
        "every mesh rigid, each pair's gears one coordinate (the thesis's App. C \"whole rig\")"
    );
    print_modes(&rigid, None);
    for part in &apart {
        println!("every mesh apart: {}", coordinate_names(part).join(", "));
        print_modes(part, None);
    }
    Ok(())
}

/// The one part a connected rig forms with its meshes held as `hold`.
fn first_part(rig: &RigTopology, hold: MeshHold) -> ModalPart {
    rig.modal_parts(hold).remove(0)
}

/// Each coordinate's name: its body, or the bodies a rigid mesh joins (`a + b`).
fn coordinate_names(part: &ModalPart) -> Vec<String> {
    part.coordinates.iter().map(|c| c.join(" + ")).collect()
}

fn frequencies(part: &ModalPart) -> Vec<f64> {
    part.modes.iter().map(|m| m.frequency_hz).collect()
}

fn shapes(part: &ModalPart) -> Vec<&Vec<f64>> {
    part.modes.iter().map(|m| &m.shape).collect()
}

fn part_json(part: &ModalPart) -> Value {
    json!({
        "coordinates": coordinate_names(part),
        "natural_hz": frequencies(part),
        "shapes": shapes(part),
    })
}

/// A table of `part`'s modes: frequency, each mode's kind where given, then each
/// coordinate's amplitude in a column as wide as its name, right-aligned under it.
fn print_modes(part: &ModalPart, kinds: Option<&[ModeKind]>) {
    let names = coordinate_names(part);
    let widths: Vec<usize> = names.iter().map(|b| b.chars().count().max(7)).collect();
    let head: Vec<String> = names
        .iter()
        .zip(&widths)
        .map(|(b, w)| format!("{b:>w$}"))
        .collect();
    let kind_head = if kinds.is_some() {
        "kind           "
    } else {
        ""
    };
    println!("  {:>10}  {kind_head}{}", "f (Hz)", head.join("  "));
    for (m, mode) in part.modes.iter().enumerate() {
        let kind = kinds.map_or(String::new(), |k| {
            format!("{:<15}", format!("{:?}", k[m]).to_lowercase())
        });
        let shape: Vec<String> = mode
            .shape
            .iter()
            .zip(&widths)
            .map(|(v, w)| format!("{v:>+w$.4}"))
            .collect();
        println!("  {:>10.3}  {kind}{}", mode.frequency_hz, shape.join("  "));
    }
    println!();
}
