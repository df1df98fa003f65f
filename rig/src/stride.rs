//! Strides: several internal steps taken as one by the fast path, in modes whose fastest
//! motion is slow against the step (teeth apart: the rig's own modes below 100 Hz).
//!
//! A stride of m steps is one fused product with e^{A m h} (state and row events at its
//! end, for the switch checks over the whole stride) and, when samples are recorded, one
//! product with the mechanical rows of e^{A k h} for each sample k = 1..m−1 inside it.
//! Where the check over a stride says a function may cross, the fast path takes that
//! stretch in single steps (and the exact path locates the crossing on a step of ρh ≤
//! [`crate::taylor::MAX_RHO_H`], as ever), so a stride only needs its check to be
//! sound: m is the largest power of two up to [`MAX_STRIDE`] with ρ·m·h ≤
//! [`MAX_RHO_STRIDE`].

use nalgebra::DMatrix;

use crate::column_product::product;
use crate::events::EventFn;
use crate::fused_step::{FusedColumns, FusedRows, fused_columns};
use crate::layout::{Layout, N_MECH};

/// Most internal steps one stride takes.
pub const MAX_STRIDE: usize = 8;

/// Largest ρ·m·h (rad of the fastest motion) a stride spans. The check fits a cubic
/// through each function's values and slopes at the stride's ends; over ρH ≤ 1 rad a
/// function holds at most one extremum and departs from that cubic by at most
/// (ρH)⁴/384 ≈ 0.3 % of its amplitude, far inside the check's margin (a quarter of the
/// ends' values and slopes).
pub const MAX_RHO_STRIDE: f64 = 1.0;

/// Mechanical rows of e^{A k h}, one column per augmented state.
type MechColumns = [[f64; N_MECH]; Layout::MAX_LEN];

/// The steps a stride of a mode takes: the largest power of two up to [`MAX_STRIDE`] with
/// ρ·m·h ≤ [`MAX_RHO_STRIDE`] for spectral radius `rho` (rad/s) and internal step `step_s` (s).
pub fn stride_steps(rho: f64, step_s: f64) -> usize {
    let mut steps = 1;
    while steps < MAX_STRIDE && rho * (2 * steps) as f64 * step_s <= MAX_RHO_STRIDE {
        steps *= 2;
    }
    steps
}

/// A mode's stride: its length and the matrices that take it.
pub struct Stride {
    /// Internal steps a stride takes (1: the mode takes single steps only).
    pub steps: usize,
    /// Fused columns of e^{A m h}: the state and the row events at the stride's end.
    end_columns: Box<FusedColumns>,
    /// Mechanical rows of e^{A k h} for k = 1..m−1: the samples inside the stride.
    sample_columns: Vec<MechColumns>,
    len: usize,
}

impl Stride {
    /// The stride over `powers` = [e^{A h}, e^{A 2h}, …, e^{A m h}] with the mode's events.
    pub fn new(powers: &[DMatrix<f64>], events: &[EventFn], row_events: &[usize]) -> Self {
        let steps = powers.len();
        let len = powers[0].nrows();
        let sample_columns = powers[..steps - 1]
            .iter()
            .map(|power| {
                std::array::from_fn(|col| {
                    std::array::from_fn(|row| if col < len { power[(row, col)] } else { 0.0 })
                })
            })
            .collect();
        Self {
            steps,
            end_columns: Box::new(fused_columns(&powers[steps - 1], events, row_events)),
            sample_columns,
            len,
        }
    }

    /// The mechanical states and row events at the end of a stride from `u`.
    #[inline]
    pub fn end(&self, u: &[f64; Layout::MAX_LEN]) -> FusedRows {
        product(&self.end_columns, u, self.len)
    }

    /// The mechanical states `k` steps (1 ≤ k < m) into a stride from `u` (always inlined:
    /// called per sample in the fast path's innermost loop).
    #[inline(always)]
    pub fn sample(&self, k: usize, u: &[f64; Layout::MAX_LEN]) -> [f64; N_MECH] {
        product(&self.sample_columns[k - 1], u, self.len)
    }
}
