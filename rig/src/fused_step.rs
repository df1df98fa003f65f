//! The fused step: the mechanical rows of a step matrix and the values and slopes of the
//! mode's row events (mesh and motor switching functions) after the step, in one product.

use nalgebra::DMatrix;

use crate::events::EventFn;
use crate::layout::{Layout, N_MECH, UNIT};

/// Most switching functions of one mode that are not angle events (mesh and motor).
pub const MAX_ROW_EVENTS: usize = 4;

/// Rows of the fused step: the 12 mechanical states, then the values of the mode's row
/// events in four fixed slots and their slopes in four more, all at the end of the step.
pub const FUSED_ROWS: usize = N_MECH + 2 * MAX_ROW_EVENTS;

/// Result of one fused step.
pub type FusedRows = [f64; FUSED_ROWS];

/// Columns of a fused step matrix, one per augmented state (zero beyond the layout's length).
pub type FusedColumns = [[f64; FUSED_ROWS]; Layout::MAX_LEN];

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
