//! Strides: several internal steps taken as one by a settling run's fast path
//! (`plant/fast.rs`), in modes whose fastest motion is slow against the step (teeth
//! apart: the rig's own modes below 100 Hz).
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
/// through each function's values and slopes at the stride's ends; over ρH ≤ 1 rad a
/// function holds at most one extremum and departs from that cubic by at most
/// (ρH)⁴/384 ≈ 0.3 % of its amplitude, far inside the check's margin (a quarter of the
/// ends' values and slopes).
pub const MAX_RHO_STRIDE: f64 = 1.0;

/// The steps a stride of a mode takes: whole output periods of `substeps` internal steps
/// each, their number a power of two, as many as keep ρ·m·h ≤ [`MAX_RHO_STRIDE`] and m
/// within [`MAX_STRIDE`] (or one period, where a period is longer), for spectral radius
/// `rho` (rad/s) and internal step `step_s` (s); 1 where not even one period qualifies or
/// a period is one step that cannot double. At 51.2 kHz (one step a sample) that is up
/// to 8 steps; at 10.24 kHz (3 steps a sample for the 1983 rig) 3 or 6, so a settling run
/// strides at a sweep's rate too.
pub fn stride_steps(rho: f64, step_s: f64, substeps: u32) -> usize {
    let period = substeps.max(1) as usize;
    let fits = |steps: usize| rho * steps as f64 * step_s <= MAX_RHO_STRIDE;
    let most = MAX_STRIDE.max(period);
    if !fits(period) {
        return 1;
    }
    let mut steps = period;
    while 2 * steps <= most && fits(2 * steps) {
        steps *= 2;
    }
    steps
}
