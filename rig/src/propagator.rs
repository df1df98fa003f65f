//! Exact propagation of one linear mode: the step matrix e^{A h} for whole steps, and
//! the Taylor expansion of e^{A τ} for any τ within a step (event location, restarts).

use nalgebra::DMatrix;

use crate::column_product::product;
use crate::derivative::Derivative;
use crate::events::EventFn;
use crate::fused_step::{FusedColumns, FusedRows, MAX_ROW_EVENTS, fused_columns};
use crate::jump_response::JumpResponse;
use crate::layout::Layout;
use crate::matrix_exp::{exp_powers, spectral_radius};
use crate::stride::{Stride, stride_steps};
use crate::taylor::{TaylorVectors, taylor_order};

/// Everything needed to advance the plant while it stays in one [`Mode`].
pub struct ModeSystem {
    /// Switching functions active in this mode.
    pub events: Vec<EventFn>,
    /// Columns of the fused step matrix: the mechanical rows of e^{A h}, then each row
    /// event's value and slope forms times e^{A h}; one per augmented state (zero beyond `len`).
    step_columns: FusedColumns,
    /// Strides of several steps at once, for the fast path.
    pub stride: Stride,
    /// Indices in `events` of the events whose rows the fused step computes.
    pub row_events: Vec<usize>,
    /// Indices in `events` of the angle events (checked from θ2 directly).
    pub angle_events: Vec<usize>,
    /// A·u for the Taylor expansion.
    derivative: Derivative,
    /// e^{A s h} applied to a jump of the gear angles (tooth passes).
    pub jump_response: JumpResponse,
    /// Spectral radius of A (rad/s).
    spectral_radius: f64,
    len: usize,
}

impl ModeSystem {
    /// Builds the system of a mode with matrix `a`, internal step `step_s` and switching
    /// functions `events`.
    pub fn new(a: &DMatrix<f64>, step_s: f64, events: Vec<EventFn>) -> Self {
        let len = a.nrows();
        let rho = spectral_radius(a);
        let powers = exp_powers(a, step_s, rho, stride_steps(rho, step_s));
        let (angle_events, row_events): (Vec<usize>, Vec<usize>) =
            (0..events.len()).partition(|&k| events[k].angle_sign != 0.0);
        assert!(
            row_events.len() <= MAX_ROW_EVENTS,
            "a mode has at most {MAX_ROW_EVENTS} mesh and motor switching functions"
        );
        let step_columns = fused_columns(&powers[0], &events, &row_events);
        let stride = Stride::new(&powers, &events, &row_events);
        let derivative = Derivative::of(a);
        let jump_response = JumpResponse::new(&derivative, step_s);
        Self {
            events,
            step_columns,
            stride,
            row_events,
            angle_events,
            derivative,
            jump_response,
            spectral_radius: rho,
            len,
        }
    }

    /// The fast path for a whole step: the mechanical part of u(t + h) = e^{A h} u(t)
    /// (rows 0..12) and the row events' values and slopes there (rows 12..).
    #[inline]
    pub fn step(&self, u: &[f64; Layout::MAX_LEN]) -> FusedRows {
        product(&self.step_columns, u, self.len)
    }

    /// Values (slots 0..4) and slopes (slots 4..8) of the row events at `u`; an empty
    /// slot holds value −1 and slope 0.
    pub fn row_event_values(&self, u: &[f64; Layout::MAX_LEN]) -> [f64; 2 * MAX_ROW_EVENTS] {
        let mut rows = [0.0; 2 * MAX_ROW_EVENTS];
        rows[..MAX_ROW_EVENTS].fill(-1.0);
        for (j, &k) in self.row_events.iter().enumerate() {
            rows[j] = self.events[k].value.dot(u);
            rows[MAX_ROW_EVENTS + j] = self.events[k].slope.dot(u);
        }
        rows
    }

    /// Taylor order whose remainder (ρδ)^(K+1)/(K+1)! is below 1e-16 (the rounding of the
    /// state itself) for a step of `delta_s`.
    pub fn taylor_order(&self, delta_s: f64) -> usize {
        taylor_order(self.spectral_radius * delta_s)
    }

    /// Fills `vectors` with v_k = (A δ)^k u₀ / k! for k = 0..=order and returns the order
    /// (the vectors above it are left as they were).
    pub fn taylor(&self, u0: &[f64], delta_s: f64, vectors: &mut TaylorVectors) -> usize {
        let order = self.taylor_order(delta_s);
        vectors[0][..self.len].copy_from_slice(&u0[..self.len]);
        for k in 1..=order {
            let (done, rest) = vectors.split_at_mut(k);
            self.derivative
                .scaled(&done[k - 1], delta_s / k as f64, &mut rest[0]);
        }
        order
    }

    /// u(s δ) = Σ_k v_k s^k from Taylor vectors of the given order (Horner in s).
    pub fn taylor_state(&self, vectors: &TaylorVectors, order: usize, s: f64, out: &mut [f64]) {
        #[cfg(target_arch = "x86_64")]
        if crate::fma::available() {
            // SAFETY: the CPU has AVX2 and FMA, checked at run time.
            return unsafe { self.taylor_state_v3(vectors, order, s, out) };
        }
        self.taylor_state_any(vectors, order, s, out);
    }

    /// [`Self::taylor_state`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn taylor_state_v3(&self, vectors: &TaylorVectors, order: usize, s: f64, out: &mut [f64]) {
        self.taylor_state_any(vectors, order, s, out);
    }

    #[inline(always)]
    fn taylor_state_any(&self, vectors: &TaylorVectors, order: usize, s: f64, out: &mut [f64]) {
        out[..self.len].copy_from_slice(&vectors[order][..self.len]);
        for v in vectors[..order].iter().rev() {
            for (o, &vk) in out[..self.len].iter_mut().zip(&v[..self.len]) {
                *o = o.mul_add(s, vk);
            }
        }
    }
}
