//! Building a parameter set from a preset and `--set NAME=VALUE` overrides.

use anyhow::{Context, bail};
use rig::RigParams;

use crate::cli::RigArgs;

/// The preset named in `args` with every override applied, in order.
pub fn params_from(args: &RigArgs) -> anyhow::Result<RigParams> {
    let mut params = rig::preset(&args.preset).context("--preset")?;
    for item in &args.overrides {
        let Some((name, value)) = item.split_once('=') else {
            bail!("--set {item}: expected NAME=VALUE (`testrig params` lists the names)");
        };
        rig::set_param(&mut params, name.trim(), value.trim())
            .with_context(|| format!("--set {item}"))?;
    }
    Ok(params)
}
