//! Exact propagation of one linear mode: the step matrix e^{A h} for whole steps, and
//! the Taylor expansion of e^{A τ} for any τ within a step (event location, restarts).

use nalgebra::DMatrix;

use crate::derivative::Derivative;
use crate::events::EventFn;
use crate::jump_response::JumpResponse;
use crate::layout::{Layout, N_MECH, UNIT, V0, VF};
use crate::mode::Mode;
use crate::stride::{Stride, stride_steps};

/// Highest Taylor order kept; with ρ·h ≤ 0.5 the remainder of order 16 is below 1e-17.
pub const TAYLOR_ORDER: usize = 16;

/// Largest ρ·h (spectral radius of A times the internal step) the Taylor expansion is used at.
pub const MAX_RHO_H: f64 = 0.5;

/// Most switching functions of one mode that are not angle events (mesh and motor).
pub const MAX_ROW_EVENTS: usize = 4;

/// Rows of the fused step: the 12 mechanical states, then the values of the mode's row
/// events in four fixed slots and their slopes in four more, all at the end of the step.
pub const FUSED_ROWS: usize = N_MECH + 2 * MAX_ROW_EVENTS;

/// Result of one fused step.
pub type FusedRows = [f64; FUSED_ROWS];

/// Columns of a fused step matrix, one per augmented state (zero beyond the layout's length).
pub type FusedColumns = [[f64; FUSED_ROWS]; Layout::MAX_LEN];

/// 1/k for k = 0..=TAYLOR_ORDER (1/0 taken as 0, never used).
const RECIPROCALS: [f64; TAYLOR_ORDER + 1] = {
    let mut r = [0.0; TAYLOR_ORDER + 1];
    let mut k = 1;
    while k <= TAYLOR_ORDER {
        r[k] = 1.0 / k as f64;
        k += 1;
    }
    r
};

/// Taylor vectors v_k = (A δ)^k u₀ / k!, so that u(s δ) = Σ_k v_k s^k for s ∈ [0, 1]
/// (only those up to the order of the last expansion are valid).
pub type TaylorVectors = [[f64; Layout::MAX_LEN]; TAYLOR_ORDER + 1];

/// Everything needed to advance the plant while it stays in one [`Mode`].
pub struct ModeSystem {
    /// The mode this system belongs to.
    pub mode: Mode,
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
    /// Builds the system for `mode` with matrix `a`, internal step `step_s` and switching functions `events`.
    pub fn new(mode: Mode, a: &DMatrix<f64>, step_s: f64, events: Vec<EventFn>) -> Self {
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
            mode,
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
        let x = self.spectral_radius * delta_s;
        let mut term = x;
        (1..TAYLOR_ORDER)
            .find(|&k| {
                term *= x * RECIPROCALS[k + 1];
                term < 1e-16
            })
            .map_or(TAYLOR_ORDER, |k| k + 1)
            .max(4)
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
        out[..self.len].copy_from_slice(&vectors[order][..self.len]);
        for v in vectors[..order].iter().rev() {
            for (o, &vk) in out[..self.len].iter_mut().zip(&v[..self.len]) {
                *o = o.mul_add(s, vk);
            }
        }
    }
}

/// e^{A k h} for k = 1..=`count`, computed on the balanced matrix D⁻¹AD, whose entries
/// are all of order ρ or less: D = 1 for angles and the controller integral, ρ for speeds,
/// and for each forcing state (unit, load, harmonics) the scale that brings its column's
/// largest entry to ρ. The Padé exponential of the balanced matrix is then accurate to
/// rounding in every entry, not only relative to the largest (K/J·h ≈ 3000 for the mesh),
/// and the constant forcing adds no bias; its powers are taken there too.
pub fn exp_powers(a: &DMatrix<f64>, step_s: f64, rho: f64, count: usize) -> Vec<DMatrix<f64>> {
    let len = a.nrows();
    let rho = rho.max(1.0);
    let mechanical = |i: usize| {
        if (V0..V0 + 5).contains(&i) || i == VF {
            rho
        } else {
            1.0
        }
    };
    let scale: Vec<f64> = (0..len)
        .map(|c| {
            if c < N_MECH {
                return mechanical(c);
            }
            let largest = (0..N_MECH)
                .map(|r| a[(r, c)].abs() / mechanical(r))
                .fold(0.0, f64::max);
            if largest > 0.0 { rho / largest } else { 1.0 }
        })
        .collect();
    let balanced = DMatrix::from_fn(len, len, |r, c| a[(r, c)] * scale[c] / scale[r] * step_s);
    let exp = balanced.exp();
    let mut power = exp.clone();
    let mut powers = Vec::with_capacity(count);
    for k in 1..=count {
        if k > 1 {
            power = &exp * &power;
        }
        powers.push(DMatrix::from_fn(len, len, |r, c| {
            power[(r, c)] * scale[r] / scale[c]
        }));
    }
    powers
}

/// Spectral radius of `a` (rad/s): the fastest rate the Taylor expansion must resolve.
pub fn spectral_radius(a: &DMatrix<f64>) -> f64 {
    a.complex_eigenvalues()
        .iter()
        .map(|l| l.norm())
        .fold(0.0, f64::max)
}

/// The fused matrix of the step matrix `step` (e^{A h} for some h): its mechanical rows,
/// then each row event's value and slope forms times `step`. Row events sit in fixed
/// slots (values at N_MECH + j, slopes at N_MECH + 4 + j); an empty slot's value is −1
/// (the unit state's column) and its slope 0, so it never crosses.
pub fn fused_columns(
    step: &DMatrix<f64>,
    events: &[EventFn],
    row_events: &[usize],
) -> FusedColumns {
    let len = step.nrows();
    let n = row_events.len();
    let form = |terms: &[(usize, f64)], col: usize| -> f64 {
        terms.iter().map(|&(i, c)| c * step[(i, col)]).sum()
    };
    let fused_entry = |row: usize, col: usize| -> f64 {
        let Some(r) = row.checked_sub(N_MECH) else {
            return step[(row, col)];
        };
        let (slot, is_slope) = (r % MAX_ROW_EVENTS, r >= MAX_ROW_EVENTS);
        match (slot < n, is_slope) {
            (true, false) => form(&events[row_events[slot]].value.terms, col),
            (true, true) => form(&events[row_events[slot]].slope.terms, col),
            (false, false) => -step[(UNIT, col)],
            (false, true) => 0.0,
        }
    };
    std::array::from_fn(|col| {
        std::array::from_fn(|row| {
            if col < len {
                fused_entry(row, col)
            } else {
                0.0
            }
        })
    })
}

/// `columns` times `u` over the first `len` columns (16, 18 or 20): a fixed shape for
/// each, which the compiler unrolls into vector multiply-adds, the columns summed in two
/// chains (even and odd) to halve the latency.
#[inline]
pub fn product<const ROWS: usize>(
    columns: &[[f64; ROWS]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
    len: usize,
) -> [f64; ROWS] {
    match len {
        16 => product_of::<ROWS, 16>(columns, u),
        18 => product_of::<ROWS, 18>(columns, u),
        _ => product_of::<ROWS, { Layout::MAX_LEN }>(columns, u),
    }
}

#[inline(always)]
fn product_of<const ROWS: usize, const N: usize>(
    columns: &[[f64; ROWS]; Layout::MAX_LEN],
    u: &[f64; Layout::MAX_LEN],
) -> [f64; ROWS] {
    let (mut even, mut odd) = ([0.0; ROWS], [0.0; ROWS]);
    for (pair, weights) in columns[..N].chunks_exact(2).zip(u[..N].chunks_exact(2)) {
        for ((e, o), (&c0, &c1)) in even
            .iter_mut()
            .zip(odd.iter_mut())
            .zip(pair[0].iter().zip(&pair[1]))
        {
            *e = c0.mul_add(weights[0], *e);
            *o = c1.mul_add(weights[1], *o);
        }
    }
    for (e, o) in even.iter_mut().zip(odd) {
        *e += o;
    }
    even
}
