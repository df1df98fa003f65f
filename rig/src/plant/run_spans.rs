//! A fast run's products: a mode's step (and stride) with the forcing states that hold
//! still over the run (the unit state, a set speed and a load that do not ramp) folded
//! into one column, the unit state's, and those that stay zero (the rates of set points
//! that hold, an oscillating load that is off) left out. On the 1983 rig, 15 of the
//! state's 22 columns remain in the fused product, and the forcing block shrinks to the
//! states that move (the set rotation and the harmonic pair). A spacing error holds still
//! too, but changes at every tooth zone: it keeps a column of its own, so that the fold
//! outlives it.
//!
//! Which forcing states hold still follows from A's forcing rows (they read only forcing
//! states, the same in every mode) and the state: a state stays zero if it is zero and
//! its rate reads only states that stay zero; it holds still if its rate reads only
//! those. Built for a mode and the values of the still states, kept while they hold.

use std::ops::Range;

use super::layout::NetLayout;
use super::system::{ModeSystem, SpanMatrix};

/// A mode's products over runs whose still forcing states hold the values they were
/// built for.
#[derive(Clone, Debug)]
pub struct RunSpans {
    /// The states the fused products read, in the order of their columns: the mechanical
    /// states, the forcing states that move and the spacing errors where they feed them,
    /// then the unit state (its column carrying the still states' part).
    pub columns: Vec<usize>,
    /// The forcing states that move (the rows of each span's `forcing`).
    pub moving: Vec<usize>,
    /// The states the forcing products read: `moving`, then the unit state.
    pub forcing_columns: Vec<usize>,
    /// Rows of each column of a span's `forcing`: `moving` rounded up to a multiple of 4.
    pub moving_rows: usize,
    /// The step: `fused` with the mode's fused rows over `columns`, `forcing` the moving
    /// states' rows over `forcing_columns`.
    pub step: SpanMatrix,
    /// The stride of the mode, alike, if it has one.
    pub stride: Option<SpanMatrix>,
    /// The mode's output period as one span, alike, if it has one.
    pub period: Option<SpanMatrix>,
    /// The samples inside a recorded stride (`ModeSystem::inside`), alike: `fused` with
    /// the mode's mechanical rows alone.
    pub inside: Vec<SpanMatrix>,
    /// The forcing states that hold (still or zero), each with the bits of its value.
    held: Vec<(usize, u64)>,
}

impl RunSpans {
    /// The products of `system` for runs from the state `u`.
    pub fn new(system: &ModeSystem, layout: &NetLayout, u: &[f64]) -> Self {
        let forcing = layout.mechanical()..layout.len();
        let a = |row: usize, col: usize| system.a.get(row, col);
        let (zero, still) = holding_states(&a, forcing.clone(), u);
        // Spacing errors hold still within a run but change at every tooth zone: read as
        // columns of their own, not folded, so that a fold outlives them.
        let read: Vec<usize> = layout.spacing.iter().flatten().copied().collect();
        let moving: Vec<usize> = forcing
            .clone()
            .filter(|&j| !zero[j - forcing.start] && !still[j - forcing.start])
            .filter(|j| !read.contains(j))
            .collect();
        let held = forcing
            .clone()
            .filter(|j| !moving.contains(j) && !read.contains(j))
            .map(|j| (j, u[j].to_bits()))
            .collect();
        let still: Vec<usize> = forcing
            .clone()
            .filter(|&j| still[j - forcing.start] && !read.contains(&j))
            .collect();
        let unit = layout.unit();
        let feeds = |m: &SpanMatrix, rows: usize, j: usize| {
            m.fused[j * rows..(j + 1) * rows].iter().any(|&x| x != 0.0)
        };
        let fed = |&j: &usize| {
            let spans = std::iter::once(&system.step)
                .chain(system.stride.iter().map(|s| &s.matrix))
                .chain(&system.period);
            spans.into_iter().any(|m| feeds(m, system.fused_rows, j))
                || (system.inside.iter()).any(|m| feeds(m, system.mechanical_rows, j))
        };
        let mut columns: Vec<usize> = (0..layout.mechanical()).collect();
        columns.extend(moving.iter().chain(&read).copied().filter(fed));
        columns.push(unit);
        let mut forcing_columns = moving.clone();
        forcing_columns.push(unit);
        let shape = Shape {
            fused_rows: system.fused_rows,
            forcing_rows: system.forcing_rows,
            first_forcing: forcing.start,
            moving_rows: moving.len().div_ceil(4) * 4,
        };
        let fold = |span: &SpanMatrix| shape.fold(span, &columns, &moving, &still, u);
        let inside_shape = Shape {
            fused_rows: system.mechanical_rows,
            ..shape
        };
        Self {
            step: fold(&system.step),
            stride: system.stride.as_ref().map(|s| fold(&s.matrix)),
            period: system.period.as_ref().map(fold),
            inside: (system.inside.iter())
                .map(|span| inside_shape.fold(span, &columns, &moving, &still, u))
                .collect(),
            moving_rows: shape.moving_rows,
            columns,
            moving,
            forcing_columns,
            held,
        }
    }

    /// Writes the moving forcing states' values `forcing` (in the order of `moving`, as
    /// a span's forcing product gives them) into the state `u`.
    #[inline(always)]
    pub fn set_moving(&self, forcing: &[f64], u: &mut [f64]) {
        for (&i, &x) in self.moving.iter().zip(forcing) {
            u[i] = x;
        }
    }

    /// Whether the forcing states it holds still have, in `u`, the values it was built
    /// for.
    pub fn holds(&self, u: &[f64]) -> bool {
        self.held.iter().all(|&(i, bits)| u[i].to_bits() == bits)
    }
}

/// Per forcing state (from `forcing.start`): whether it stays zero, and whether it holds
/// still (nonzero, its rate reading only states that stay zero), by A's entries `a`.
fn holding_states(
    a: &dyn Fn(usize, usize) -> f64,
    forcing: Range<usize>,
    u: &[f64],
) -> (Vec<bool>, Vec<bool>) {
    let at = |j: usize| j - forcing.start;
    let mut zero: Vec<bool> = forcing.clone().map(|j| u[j] == 0.0).collect();
    // A state whose rate reads one that does not stay zero may leave zero: the largest
    // set of zero states whose rates read only one another.
    loop {
        let leaving: Vec<usize> = forcing
            .clone()
            .filter(|&j| zero[at(j)] && forcing.clone().any(|k| !zero[at(k)] && a(j, k) != 0.0))
            .collect();
        if leaving.is_empty() {
            break;
        }
        for j in leaving {
            zero[at(j)] = false;
        }
    }
    let still = forcing
        .clone()
        .map(|j| !zero[at(j)] && forcing.clone().all(|k| zero[at(k)] || a(j, k) == 0.0))
        .collect();
    (zero, still)
}

/// The sizes a span's folded matrices take.
#[derive(Clone, Copy)]
struct Shape {
    fused_rows: usize,
    forcing_rows: usize,
    first_forcing: usize,
    moving_rows: usize,
}

impl Shape {
    /// `span` over `columns` (fused) and over `moving` then the unit state (forcing), the
    /// `still` states' columns times their values in `u` summed into the unit state's.
    fn fold(
        &self,
        span: &SpanMatrix,
        columns: &[usize],
        moving: &[usize],
        still: &[usize],
        u: &[f64],
    ) -> SpanMatrix {
        let rows = self.fused_rows;
        let fused_column = |j: usize| &span.fused[j * rows..(j + 1) * rows];
        let mut fused = Vec::with_capacity(columns.len() * rows);
        for &j in &columns[..columns.len() - 1] {
            fused.extend_from_slice(fused_column(j));
        }
        fused.extend((0..rows).map(|r| {
            still
                .iter()
                .map(|&j| fused_column(j)[r] * u[j])
                .sum::<f64>()
        }));
        let f = |row: usize, col: usize| {
            let (row, col) = (row - self.first_forcing, col - self.first_forcing);
            span.forcing[col * self.forcing_rows + row]
        };
        let mut forcing = vec![0.0; (moving.len() + 1) * self.moving_rows];
        for (r, &i) in moving.iter().enumerate() {
            for (c, &j) in moving.iter().enumerate() {
                forcing[c * self.moving_rows + r] = f(i, j);
            }
            forcing[moving.len() * self.moving_rows + r] =
                still.iter().map(|&j| f(i, j) * u[j]).sum::<f64>();
        }
        SpanMatrix { fused, forcing }
    }
}
