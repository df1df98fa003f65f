//! An approach by name, as `simulate --approach`, Python's `approach=` and a sweep's
//! `approach` take it: `static`, `rest`, `up` or `down` (`rig::Approach`), its ramp
//! checked.

use anyhow::bail;
use rig::Approach;

use crate::vocabulary::check_simulated_s;

/// The approaches by name, as `simulate --approach` and Python's `approach=` take them.
pub const APPROACH_NAMES: [&str; 4] = ["static", "rest", "up", "down"];

/// The approach named `name` (one of [`APPROACH_NAMES`], or `steady` for `static`) to
/// `rpm`, its ramp at `ramp_rpm_per_s`; refused where the rate is not a positive number
/// or the ramp longer than a run may be.
pub fn approach_named(name: &str, rpm: f64, ramp_rpm_per_s: f64) -> anyhow::Result<Approach> {
    let ramp_ok = ramp_rpm_per_s.is_finite() && ramp_rpm_per_s > 0.0;
    let approach = match name {
        "static" | "steady" => Approach::Static,
        "rest" => Approach::Rest,
        "up" | "down" if !ramp_ok => bail!(
            "ramp rate {ramp_rpm_per_s}: a ramp's rate must be a positive number of rev/min per second"
        ),
        "up" => Approach::run_up(rpm, ramp_rpm_per_s),
        "down" => Approach::run_down(rpm, ramp_rpm_per_s),
        other => bail!("approach `{other}`: one of {}", APPROACH_NAMES.join(", ")),
    };
    check_simulated_s(approach.lead_in_s(), true).map_err(|e| {
        anyhow::anyhow!("ramp rate {ramp_rpm_per_s} rev/min per s to {rpm} rev/min: the ramp's {e}")
    })?;
    Ok(approach)
}
