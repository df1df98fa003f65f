//! Strides: several internal steps taken as one by a settling run's fast path
//! (`plant/fast.rs`), in modes whose fastest motion is slow against the step (teeth
//! apart: the rig's own modes below 100 Hz).
//!
//! A stride of m steps is one fused product with e^{A m h} (state and row events at its
//! end, for the switch checks over the whole stride). Where the check over a stride says a function may cross, the fast path takes that
//! stretch in single steps (and the exact path locates the crossing on a step of ρh ≤
//! [`crate::taylor::MAX_RHO_H`], as ever), so a stride only needs its check to be
//! sound: m is the largest power of two up to [`MAX_STRIDE`] with ρ·m·h ≤
//! [`MAX_RHO_STRIDE`].

/// Most internal steps one stride takes.
pub const MAX_STRIDE: usize = 8;

/// Largest ρ·m·h (rad of the fastest motion) a stride spans. The check fits a cubic
/// through each function's values and slopes at the stride's ends; over ρH ≤ 1 rad a
/// function holds at most one extremum and departs from that cubic by at most
/// (ρH)⁴/384 ≈ 0.3 % of its amplitude, far inside the check's margin (a quarter of the
/// ends' values and slopes).
pub const MAX_RHO_STRIDE: f64 = 1.0;

/// The steps a stride of a mode takes: the largest power of two up to [`MAX_STRIDE`] with
/// ρ·m·h ≤ [`MAX_RHO_STRIDE`] for spectral radius `rho` (rad/s) and internal step `step_s` (s).
pub fn stride_steps(rho: f64, step_s: f64) -> usize {
    let mut steps = 1;
    while steps < MAX_STRIDE && rho * (2 * steps) as f64 * step_s <= MAX_RHO_STRIDE {
        steps *= 2;
    }
    steps
}
