//! Every bound an input is checked against, in one place: speed and load set points,
//! simulated times, the analyser's averages. The scenario reader, the command line, the
//! live panel and the sweeps all check here, so each refuses the same values with the
//! same words.

/// Highest motor speed set point a scenario accepts (rev/min), the plant's own limit.
pub const MAX_SPEED_RPM: f64 = rig::schedule::MAX_SPEED_RPM;

/// The live ceiling of a live rig (the panel, Python's `testrig.Rig`) whose scenario has
/// no `[live]`: speeds up to 3000 rev/min, an oscillating load up to 200 Hz.
pub const DEFAULT_LIVE_CEILING: rig::LiveCeiling = rig::LiveCeiling {
    speed_rpm: 3000.0,
    oscillating_load_hz: 200.0,
};

/// Longest simulated time a run, a simulation or a sweep case accepts (s): 10⁶ s, about
/// 11.6 days (half an hour unpaced); beyond it the sample count loses meaning.
pub const MAX_SIMULATED_S: f64 = 1.0e6;

/// A simulated length (s) as an input accepts it: finite, > 0 (or ≥ 0 where `zero_ok`),
/// at most [`MAX_SIMULATED_S`].
pub fn check_simulated_s(value: f64, zero_ok: bool) -> Result<f64, LimitError> {
    let low_ok = if zero_ok { value >= 0.0 } else { value > 0.0 };
    if value.is_finite() && low_ok && value <= MAX_SIMULATED_S {
        Ok(value)
    } else {
        let low = if zero_ok { "≥ 0" } else { "> 0" };
        Err(LimitError::SimulatedTime { value, low })
    }
}

/// A brake load (N m) as an input accepts it: finite and ≥ 0 (an eddy-current brake only
/// resists the rotation); the error says why not.
pub fn check_load_nm(value: f64) -> Result<f64, LimitError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(LimitError::Load { value })
    }
}

/// The one load check of every rig: a brake load (N m) `rig` can run against, at most
/// [`max_load_nm`], and none where it has no brake. Beyond it the motor cannot hold any
/// speed, and the model's constant-torque brake would then drive the rig backwards, which
/// an eddy-current brake cannot (its torque falls to zero with the speed).
pub fn check_load_within(load_nm: f64, rig: &rig::RigTopology) -> Result<(), LimitError> {
    let (max_nm, has_brake) = (max_load_nm(rig), rig.brake.is_some());
    let rig = format!("rig `{}`", rig.name);
    if !has_brake && load_nm != 0.0 {
        Err(LimitError::NoBrake {
            load_nm,
            rig: rig.clone(),
        })
    } else if load_nm <= max_nm || !has_brake {
        Ok(())
    } else {
        Err(LimitError::LoadAboveMotor {
            load_nm,
            max_nm,
            rig: rig.clone(),
        })
    }
}

/// The largest brake load (N m) the motor of `rig` holds at its brake (the one load limit
/// of every rig): its
/// torque limit over the brake's speed per unit motor speed, less the brake's residual
/// drag (infinite where the file gives no limit, 0 without a motor or brake).
pub fn max_load_nm(rig: &rig::RigTopology) -> f64 {
    let (Some(motor), Some(brake)) = (rig.motor, rig.brake) else {
        return 0.0;
    };
    let Some(limit_nm) = rig.drive.limit_nm() else {
        return f64::INFINITY;
    };
    let speeds = rig.relative_speeds();
    match (speeds[motor], speeds[brake]) {
        (Some(m), Some(b)) if b != 0.0 => limit_nm * (m / b).abs() - rig.drive.brake_drag_nm,
        _ => f64::INFINITY,
    }
}

/// A motor speed set point (rev/min) as an input accepts it: finite, in [0, 10 000].
pub fn check_speed_rpm(value: f64) -> Result<f64, LimitError> {
    if value.is_subnormal() {
        Err(LimitError::SpeedSubnormal { value })
    } else if value.is_finite() && (0.0..=MAX_SPEED_RPM).contains(&value) {
        Ok(value)
    } else {
        Err(LimitError::Speed { value })
    }
}

/// Most cases one sweep file may hold: a plan of about 350 MB and, at about 0.2 s of
/// one core a case, some 2½ core-days of work; a larger campaign is several sweep files
/// (or `--set` on one), each run as its own job.
pub const MAX_SWEEP_CASES: u64 = 1_000_000;

/// Largest analyser block (samples): twice the HP 5451C's largest transform (the thesis
/// used 1024). Beyond it one block and its alias truth take the memory and the time of
/// a whole run (a block of 2²⁰ at 51.2 kHz took 3 GB and made the plant 1.2 s late).
pub const MAX_BLOCK: usize = 16_384;

/// An analyser's block size, at most [`MAX_BLOCK`] (its power of two is the analyser's
/// own check).
pub fn check_block(block: usize) -> Result<usize, LimitError> {
    if block <= MAX_BLOCK {
        Ok(block)
    } else {
        Err(LimitError::Block { block })
    }
}

/// Most spectra an average takes: the ground truth keeps the analogue signal behind a
/// whole average (at 51.2 kHz and the thesis's 2.56 s blocks, 1000 averages hold 1 GiB).
pub const MAX_AVERAGES: usize = 1000;

/// An analyser's number of averages, 1 to [`MAX_AVERAGES`].
pub fn check_averages(averages: usize) -> Result<usize, LimitError> {
    if (1..=MAX_AVERAGES).contains(&averages) {
        Ok(averages)
    } else {
        Err(LimitError::Averages { averages })
    }
}

/// A value outside the bounds an input is checked against; each says what is allowed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LimitError {
    /// A simulated time out of range.
    #[error("{value} s is not allowed: a simulated time {low} and at most {MAX_SIMULATED_S} s")]
    SimulatedTime {
        /// The time given (s).
        value: f64,
        /// The lower bound as words ("> 0" or "≥ 0").
        low: &'static str,
    },
    /// A brake load that is negative or not finite.
    #[error(
        "{value} N m is not allowed: an eddy-current brake's load is a finite torque ≥ 0 (it resists the rotation, it cannot drive it)"
    )]
    Load {
        /// The load given (N m).
        value: f64,
    },
    /// A brake load beyond what the motor holds at the brake.
    #[error(
        "{load_nm} N m is more than the motor can hold at the brake of {rig} ({max_nm:.3} N m: its torque limit through its gears less the brake's residual drag, a preset's brake_drag_nm or a rig file's [brake] drag_nm): the rig would stop, and an eddy-current brake cannot drive it backwards"
    )]
    LoadAboveMotor {
        /// The load given (N m).
        load_nm: f64,
        /// The most the rig holds (N m).
        max_nm: f64,
        /// The rig, as the message names it (rig `NAME`).
        rig: String,
    },
    /// A brake load on a rig file's rig without a brake.
    #[error("{load_nm} N m: {rig} has no [brake] to load; give 0")]
    NoBrake {
        /// The load given (N m).
        load_nm: f64,
        /// The rig, as the message names it (rig `NAME`).
        rig: String,
    },
    /// A speed set point out of range.
    #[error(
        "{value} rev/min is not allowed: a speed set point lies in [0, {MAX_SPEED_RPM}] rev/min"
    )]
    Speed {
        /// The speed given (rev/min).
        value: f64,
    },
    /// A speed set point too close to 0 to be a speed (a subnormal number).
    #[error(
        "{value:e} rev/min is not allowed: a speed set point is 0 or at least 2.2e-308 rev/min (a smaller one is no speed a number can hold exactly)"
    )]
    SpeedSubnormal {
        /// The speed given (rev/min).
        value: f64,
    },
    /// A block larger than [`MAX_BLOCK`].
    #[error("block {block}: at most {MAX_BLOCK} samples")]
    Block {
        /// The block given.
        block: usize,
    },
    /// A number of averages out of range.
    #[error("{averages} averages: from 1 to {MAX_AVERAGES}")]
    Averages {
        /// The averages given.
        averages: usize,
    },
}

#[cfg(test)]
mod tests {
    use super::{MAX_SPEED_RPM, check_speed_rpm};

    #[test]
    fn a_speed_refusal_names_the_bound_it_broke_and_only_that() {
        let beyond = check_speed_rpm(2.0 * MAX_SPEED_RPM)
            .expect_err("too fast")
            .to_string();
        assert!(
            beyond.contains(&format!("[0, {MAX_SPEED_RPM}]")),
            "{beyond}"
        );
        assert!(!beyond.contains("2.2e-308"), "{beyond}");
        let tiny = check_speed_rpm(5e-324).expect_err("subnormal").to_string();
        assert!(tiny.contains("2.2e-308"), "{tiny}");
        assert_eq!(check_speed_rpm(0.0), Ok(0.0));
    }
}
