//! Per mode: A, e^{A h} and the switching functions, built when the mode is first met
//! and kept until the set points' rates (`SegmentRates`) change.

use std::collections::HashMap;

use nalgebra::DMatrix;

use crate::matrix_exp::{exp_powers_balanced, forcing_scales, spectral_radius};

use super::events::{EventForm, event_forms};
use super::mode::NetMode;
use super::model::{NetworkModel, SegmentRates};
use super::output::OutputForms;
use super::products;

/// One mode's linear system.
#[derive(Clone, Debug)]
pub struct ModeSystem {
    /// A of u' = A u, column-major, each column padded to the layout's padded length.
    pub a_columns: Vec<f64>,
    /// The fused step, column-major with `fused_rows` rows a column: the mechanical rows
    /// of e^{A h}, then the value and then the rate of each row event (a switching
    /// function of fixed target) after the step.
    pub fused: Vec<f64>,
    /// Rows of each column of `fused` (a multiple of 4).
    pub fused_rows: usize,
    /// Per switching function, its slot among the row events (its value at row
    /// mechanical + slot of the fused step, its rate `row_events` rows further), or
    /// `None` for a function of the set rotation (its target moves: evaluated apart).
    pub row_slot: Vec<Option<usize>>,
    /// Number of row events.
    pub row_events: usize,
    /// The forcing block of e^{A h} (rows and columns of the forcing states), column-major
    /// with `forcing_rows` rows a column. The forcing states evolve by themselves, the
    /// same in every mode.
    pub forcing_step: Vec<f64>,
    /// Rows of each column of `forcing_step` (the forcing states, rounded up to a
    /// multiple of 4).
    pub forcing_rows: usize,
    /// The switching functions.
    pub events: Vec<EventForm>,
    /// The signals a sample writes, as linear forms of the state.
    pub outputs: OutputForms,
}

impl ModeSystem {
    /// The forcing states at the step's end, from `u` at its start, into `next` (`out`
    /// a scratch of at least `forcing_rows`).
    #[inline]
    pub fn advance_forcing(&self, mechanical: usize, u: &[f64], next: &mut [f64], out: &mut [f64]) {
        let forcing = next.len().min(mechanical + self.forcing_rows) - mechanical;
        products::rows(&self.forcing_step, self.forcing_rows, &u[mechanical..], out);
        next[mechanical..mechanical + forcing].copy_from_slice(&out[..forcing]);
    }
}

/// The modes met so far.
#[derive(Clone, Debug)]
pub struct SystemCache {
    /// Where each mode's system sits in `built`.
    systems: HashMap<NetMode, usize>,
    built: Vec<ModeSystem>,
    /// The mode asked for last and where its system sits (most steps stay in one mode).
    last: Option<(NetMode, usize)>,
    step_s: f64,
    rho: f64,
    /// The rates of the set points the systems were built for.
    rates: SegmentRates,
}

impl SystemCache {
    /// An empty cache for steps of `step_s`, ρ the fastest rate of any mode (rad/s).
    pub fn new(step_s: f64, rho: f64) -> Self {
        Self {
            systems: HashMap::new(),
            built: Vec::new(),
            last: None,
            step_s,
            rho,
            rates: SegmentRates::default(),
        }
    }

    /// Sets the rates of the set points the systems are built for; a change empties the
    /// cache.
    pub fn set_rates(&mut self, rates: SegmentRates) {
        if rates != self.rates {
            self.systems.clear();
            self.built.clear();
            self.last = None;
            self.rates = rates;
        }
    }

    /// The system of `mode`, built if new.
    pub fn get(&mut self, model: &NetworkModel, mode: &NetMode) -> &ModeSystem {
        let index = match self.last {
            Some((last, index)) if last == *mode => index,
            _ => {
                let index = self.index_of(model, mode);
                self.last = Some((*mode, index));
                index
            }
        };
        &self.built[index]
    }

    /// Where the system of `mode` sits, built if new.
    fn index_of(&mut self, model: &NetworkModel, mode: &NetMode) -> usize {
        if let Some(&index) = self.systems.get(mode) {
            return index;
        }
        let a = model.system_matrix(mode, &self.rates);
        let padded = model.layout.padded();
        let step = exp_step(model, &a, self.step_s, self.rho);
        let events = event_forms(model, mode, &a, self.rates.harmonic_rad_s);
        let a_columns = padded_columns(&a, padded);
        let outputs = OutputForms::of(model, mode, self.rates.harmonic_rad_s);
        self.built
            .push(fused_system(model, a_columns, &step, events, outputs));
        self.systems.insert(*mode, self.built.len() - 1);
        self.built.len() - 1
    }
}

/// The system of a mode from its A (`a_columns`), e^{A h} (`step`), switching functions
/// and signals.
fn fused_system(
    model: &NetworkModel,
    a_columns: Vec<f64>,
    step: &DMatrix<f64>,
    events: Vec<EventForm>,
    outputs: OutputForms,
) -> ModeSystem {
    let l = &model.layout;
    let mechanical = l.mechanical();
    let mut row_slot = Vec::with_capacity(events.len());
    let mut forms: Vec<&EventForm> = Vec::new();
    for form in &events {
        let moving = form.terms.iter().any(|&(i, _)| i == l.phase());
        row_slot.push((!moving).then_some(forms.len()));
        if !moving {
            forms.push(form);
        }
    }
    let row_events = forms.len();
    let fused_rows = (mechanical + 2 * row_events).div_ceil(4) * 4;
    let mut fused = vec![0.0; fused_rows * l.padded()];
    let times_step = |terms: &[(usize, f64)], col: usize| -> f64 {
        terms.iter().map(|&(i, c)| c * step[(i, col)]).sum()
    };
    for col in 0..step.ncols() {
        let column = &mut fused[col * fused_rows..(col + 1) * fused_rows];
        for (row, entry) in column[..mechanical].iter_mut().enumerate() {
            *entry = step[(row, col)];
        }
        for (j, form) in forms.iter().enumerate() {
            column[mechanical + j] = times_step(&form.terms, col);
            column[mechanical + row_events + j] = times_step(&form.slope, col);
        }
    }
    let forcing = step.nrows() - mechanical;
    let forcing_rows = forcing.div_ceil(4) * 4;
    let mut forcing_step = vec![0.0; forcing_rows * forcing];
    for col in 0..forcing {
        for row in 0..forcing {
            forcing_step[col * forcing_rows + row] = step[(mechanical + row, mechanical + col)];
        }
    }
    ModeSystem {
        a_columns,
        fused,
        fused_rows,
        row_slot,
        row_events,
        forcing_step,
        forcing_rows,
        events,
        outputs,
    }
}

/// `m`'s columns, each padded with zeros to `padded` rows.
fn padded_columns(m: &DMatrix<f64>, padded: usize) -> Vec<f64> {
    let mut out = vec![0.0; m.ncols() * padded];
    for (c, column) in m.column_iter().enumerate() {
        out[c * padded..c * padded + m.nrows()].copy_from_slice(column.as_slice());
    }
    out
}

/// e^{A h}, balanced as the 1983 plant's: angles and the integral at 1,
/// speeds and the filtered speed at ρ, forcing states scaled to ρ, the two states of
/// each harmonic pair alike.
fn exp_step(model: &NetworkModel, a: &DMatrix<f64>, step_s: f64, rho: f64) -> DMatrix<f64> {
    let l = &model.layout;
    let rho = rho.max(1.0);
    let mechanical: Vec<f64> = (0..l.mechanical())
        .map(|i| {
            if (l.speed(0)..l.speed(0) + l.bodies).contains(&i) || i == l.filtered() {
                rho
            } else {
                1.0
            }
        })
        .collect();
    let mut scale = forcing_scales(a, &mechanical, rho);
    // Each harmonic pair turns one state into the other: one scale for both, else the
    // balanced rotation's entries would be as large as their ratio.
    let pairs = l.harmonics();
    let starts = std::iter::once(l.oscillating()).chain(pairs.iter().map(|p| p.0));
    for pair in starts {
        let shared = scale[pair].max(scale[pair + 1]);
        scale[pair] = shared;
        scale[pair + 1] = shared;
    }
    exp_powers_balanced(a, step_s, &scale, 1).remove(0)
}

/// The fastest rate (rad/s) of `model`: A's spectral radius with every mesh on its drive
/// flank with two pairs where pairs alternate (the stiffest mode).
pub fn fastest_rate(model: &NetworkModel) -> f64 {
    let mut mode = NetMode::apart();
    for (state, m) in mode.meshes.iter_mut().zip(&model.meshes) {
        state.contact = super::mode::Contact::Drive;
        state.level = if m.alternating {
            crate::mode::PairZone::TWO
        } else {
            crate::mode::PairZone::ONE
        };
    }
    let a = model.system_matrix(&mode, &SegmentRates::default());
    if a.iter().all(|x| x.is_finite()) {
        spectral_radius(&a)
    } else {
        f64::INFINITY
    }
}
