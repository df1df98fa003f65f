//! Strides: several internal steps taken as one by a settling run's fast path
//! (`plant/fast.rs`), in modes whose fastest motion is slow against the step (teeth
//! apart: the rig's own modes below 100 Hz); for a run that writes samples, an output
//! period of several steps taken as one where the mode allows, and a stride of at least
//! [`MIN_RECORDED_STRIDE`] output periods with its inside samples each from its first
//! state (`plant/record_stride.rs`).
//!
//! A stride of m steps is one fused product with e^{A m h} (state and row events at its
//! end, for the switch checks over the whole stride). Where the check over a stride says a function may cross, the fast path takes that
//! stretch in single steps (and the exact path locates the crossing on a step of ρh ≤
//! [`crate::taylor::MAX_RHO_H`], as ever), so a stride only needs its check to be
//! sound: m is whole output periods, a power of two of them, up to [`MAX_STRIDE`] steps
//! with ρ·m·h ≤ [`MAX_RHO_STRIDE`].

/// Most internal steps one stride takes.
pub const MAX_STRIDE: usize = 8;

/// Largest ρ·m·h (rad of the fastest motion) a stride spans. The check fits a cubic
/// through each function's values and slopes at the stride's ends and asks whether any
/// interior maximum comes within a quarter of those values and slopes of the target
/// ([`crate::roots::may_cross_span`]); over 1.75 rad it missed none of the sampled functions
/// of up to three motions that peaked above the target (its test), over 2 rad one in
/// three thousand. 1.75 rad lets the planetary bench's stiffest modes (ρT ≈ 1.59 at
/// 51.2 kHz) take each output period in one product. Measured against single steps
/// (the 1983 rig gives the same impacts at 1.5 and 1.75 rad): docs/plant-numerics.md.
pub const MAX_RHO_STRIDE: f64 = 1.75;

/// Fewest output samples a stride of a run that writes samples takes
/// (`plant/record_stride.rs`). Its check over several steps costs about twice a step's,
/// and its first state is kept: over two samples that cost more than the one product of
/// fused rows it saves (measured on the two-stage rig at 51.2 kHz: 7 % more instructions
/// than a step a sample), over four and eight it pays (the 1983 rig: 17 % fewer).
pub const MIN_RECORDED_STRIDE: u32 = 4;

/// Whether a run that writes samples may take an output period of `substeps` internal
/// steps of `step_s` (s) as one span in a mode of spectral radius `rho` (rad/s): more than
/// one step, and ρ·T ≤ [`MAX_RHO_STRIDE`], so that the check over the period is as sound
/// as a stride's (a sample at the period's end, none inside it).
pub fn takes_whole_periods(rho: f64, step_s: f64, substeps: u32) -> bool {
    substeps > 1 && rho * f64::from(substeps) * step_s <= MAX_RHO_STRIDE
}

/// The steps a stride of a mode takes: whole output periods of `substeps` internal steps
/// each, their number a power of two, as many as keep ρ·m·h ≤ [`MAX_RHO_STRIDE`] and m
/// within [`MAX_STRIDE`], for spectral radius `rho` (rad/s) and internal step `step_s`
/// (s); 1 (no stride) where not even one period qualifies, a period is longer than
/// [`MAX_STRIDE`] or is one step that cannot double. At 51.2 kHz (one step a sample) that
/// is up to 8 steps; at 10.24 kHz (3 steps a sample for the 1983 rig) 3 or 6, so a
/// settling run strides at a sweep's rate too.
pub fn stride_steps(rho: f64, step_s: f64, substeps: u32) -> usize {
    let period = substeps.max(1) as usize;
    let fits = |steps: usize| rho * steps as f64 * step_s <= MAX_RHO_STRIDE;
    if period > MAX_STRIDE || !fits(period) {
        return 1;
    }
    let mut steps = period;
    while 2 * steps <= MAX_STRIDE && fits(2 * steps) {
        steps *= 2;
    }
    steps
}

#[cfg(test)]
mod tests {
    use super::{stride_steps, takes_whole_periods};

    #[test]
    fn a_stride_is_whole_output_periods_within_its_bounds() {
        let h = 1e-5;
        // One step a sample: powers of two up to 8, as far as ρ·m·h ≤ 1.75 allows.
        assert_eq!(stride_steps(1.0, h, 1), 8);
        assert_eq!(stride_steps(0.3 / h, h, 1), 4);
        assert_eq!(stride_steps(0.6 / h, h, 1), 2);
        assert_eq!(stride_steps(0.9 / h, h, 1), 1);
        // Three steps a sample: 3 or 6, never a count that splits a period.
        assert_eq!(stride_steps(1.0, h, 3), 6);
        assert_eq!(stride_steps(0.2 / h, h, 3), 6);
        assert_eq!(stride_steps(0.4 / h, h, 3), 3);
        assert_eq!(stride_steps(0.6 / h, h, 3), 1);
        // A period longer than the longest stride, or no period at all: no stride.
        assert_eq!(stride_steps(1.0, h, 9), 1);
        assert_eq!(stride_steps(1.0, h, 0), 8);
    }

    #[test]
    fn a_recorded_run_takes_a_period_whole_where_its_check_is_a_strides() {
        let h = 1e-5;
        // Four steps a sample: ρ·4h = 1.2 and 1.8 rad.
        assert!(takes_whole_periods(0.3 / h, h, 4));
        assert!(!takes_whole_periods(0.45 / h, h, 4));
        // One step a sample is a step already.
        assert!(!takes_whole_periods(1.0, h, 1));
    }
}
