//! A mode's response to a jump of the gear angles within a step. Between switches the
//! model is linear, so a state that jumps by Δ at τ, the mode unchanged, ends its step at
//! e^{A h} u + e^{A (h − τ)} Δ: a tooth pass (thesis §5.4.5, X2 and X3 move by half the
//! overlap) adds the second term to the step's end already known, and needs no Taylor
//! expansion from the new state unless a switch may follow in the same step.

use crate::derivative::Derivative;
use crate::layout::{Layout, N_MECH, X0};
use crate::taylor::TAYLOR_ORDER;

/// The states a jump may move: the driving and driven gears' angles X2, X3.
pub const GEAR_ANGLES: [usize; 2] = [X0 + 1, X0 + 2];

/// Taylor terms of e^{A s h} applied to one gear angle's unit vector: the mechanical rows
/// of (A h)^k e_j / k! for k = 0..=[`TAYLOR_ORDER`] (the harmonic states never respond).
type JumpSeries = [[f64; N_MECH]; TAYLOR_ORDER + 1];

/// e^{A s h} applied to jumps of the gear angles, for one mode and internal step h.
pub struct JumpResponse {
    /// One series per entry of [`GEAR_ANGLES`].
    series: Box<[JumpSeries; 2]>,
}

impl JumpResponse {
    /// The series of the mode whose A·u is `derivative`, for internal step `step_s` (s).
    pub fn new(derivative: &Derivative, step_s: f64) -> Self {
        let series = GEAR_ANGLES.map(|column| {
            let mut term = [0.0; Layout::MAX_LEN];
            term[column] = 1.0;
            let mut series = [[0.0; N_MECH]; TAYLOR_ORDER + 1];
            for (k, out) in series.iter_mut().enumerate() {
                if k > 0 {
                    let previous = term;
                    derivative.scaled(&previous, step_s / k as f64, &mut term);
                }
                out.copy_from_slice(&term[..N_MECH]);
            }
            series
        });
        Self {
            series: Box::new(series),
        }
    }

    /// Adds e^{A s h} Δ to the mechanical states of `out`, Δ being `jump` (rad) on the
    /// gear angles, from the series up to `order` (the Taylor order for a step of s·h).
    pub fn add_to(&self, jump: [f64; 2], s: f64, order: usize, out: &mut [f64; Layout::MAX_LEN]) {
        #[cfg(target_arch = "x86_64")]
        if crate::fma::available() {
            // SAFETY: the CPU has AVX2 and FMA, checked at run time.
            return unsafe { self.add_to_v3(jump, s, order, out) };
        }
        self.add_to_any(jump, s, order, out);
    }

    /// [`Self::add_to`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn add_to_v3(&self, jump: [f64; 2], s: f64, order: usize, out: &mut [f64; Layout::MAX_LEN]) {
        self.add_to_any(jump, s, order, out);
    }

    #[inline(always)]
    fn add_to_any(&self, jump: [f64; 2], s: f64, order: usize, out: &mut [f64; Layout::MAX_LEN]) {
        let [first, second] = &*self.series;
        let term = |k: usize, row: usize| first[k][row] * jump[0] + second[k][row] * jump[1];
        let mut sum: [f64; N_MECH] = std::array::from_fn(|row| term(order, row));
        for k in (0..order).rev() {
            for (row, value) in sum.iter_mut().enumerate() {
                *value = value.mul_add(s, term(k, row));
            }
        }
        for (o, value) in out[..N_MECH].iter_mut().zip(sum) {
            *o += value;
        }
    }
}
