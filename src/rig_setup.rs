//! Building a parameter set from a preset and `--set NAME=VALUE` overrides.

use anyhow::{Context, bail};
use rig::RigParams;
use rig::geometry::centre_distance_shift_m;

use std::path::Path;

use testrig::scenario::preset_file::preset_params;

use crate::cli::RigArgs;

/// The preset named in `args` with every override applied, in order. The names are those
/// of `testrig params` and of a scenario's `[rig]`: `backlash_mm` (through the centre
/// distance, as a scenario's `backlash_mm`), and the scenario forms `rig.set.NAME` and
/// `rig.backlash_mm`.
pub fn params_from(args: &RigArgs) -> anyhow::Result<RigParams> {
    let mut params = preset_params(&args.preset, Path::new(".")).context("--preset")?;
    for item in &args.overrides {
        let Some((name, value)) = item.split_once('=') else {
            bail!("--set {item}: expected NAME=VALUE (`testrig params` lists the names)");
        };
        let name = name.trim();
        let name = name
            .strip_prefix("rig.set.")
            .or_else(|| name.strip_prefix("rig."))
            .unwrap_or(name);
        set_one(&mut params, name, value.trim()).with_context(|| format!("--set {item}"))?;
    }
    Ok(params)
}

fn set_one(params: &mut RigParams, name: &str, value: &str) -> anyhow::Result<()> {
    if name != "backlash_mm" {
        return Ok(rig::set_param(params, name, value)?);
    }
    let backlash_mm: f64 = value
        .parse()
        .ok()
        .filter(|b: &f64| b.is_finite() && *b > 0.0)
        .with_context(|| format!("`{value}`: a circular backlash > 0 (mm)"))?;
    let mut changed = params.clone();
    changed.centre_distance_shift_m = centre_distance_shift_m(&changed, backlash_mm * 1e-3);
    changed.validate()?;
    *params = changed;
    Ok(())
}
